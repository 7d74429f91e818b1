// polygon_rings.hpp - a polygonal domain's outline as the user gives it,
// checked and cleaned: rings of vertices that combine by the even-odd rule
// (a point is inside when a ray from it crosses the outline an odd number of
// times), so outer boundaries and holes need no labels and either
// orientation works.
//
// Cleaning keeps the region exactly: a vertex equal to the one before it
// (a repeated closing vertex above all) is dropped, collinear runs stay (they
// change no point's parity). Refused, with the ring and vertex named (both
// counted from 0 as given): a coordinate that is not finite, a ring with
// fewer than 3 distinct vertices, a ring whose vertices all lie on one line
// (it encloses nothing).
#ifndef PDS_POLYGON_RINGS_HPP
#define PDS_POLYGON_RINGS_HPP

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/point.hpp"

namespace pds {

// An outline the library cannot take; what() names the ring and the vertex.
class DomainError : public std::invalid_argument {
public:
    explicit DomainError(const std::string& what) : std::invalid_argument(what) {}
};

class PolygonRings {
public:
    // The most vertices an outline may have (edge references are 32 bits).
    static constexpr std::size_t kMaxVertices = std::size_t{1} << 28;

    // xy holds x y interleaved; ring k is vertices [k ? ring_ends[k-1] : 0,
    // ring_ends[k]). Throws DomainError.
    PolygonRings(const double* xy, const std::size_t* ring_ends, std::size_t rings);

    std::size_t rings() const { return ring_begin_.size() - 1; }
    std::size_t vertices() const { return points_.size(); }
    // Ring k's vertices are [ring_begin(k), ring_begin(k + 1)); the edge from
    // the last to the first closes it.
    std::size_t ring_begin(std::size_t k) const { return ring_begin_[k]; }
    const std::vector<Point>& points() const { return points_; }
    // The edge from vertex i to the next vertex of its ring.
    Point edge_start(std::size_t i) const { return points_[i]; }
    Point edge_end(std::size_t i) const { return points_[next_[i]]; }
    // The smallest box holding every vertex.
    const Box& bounds() const { return bounds_; }
    // Total length of the edges.
    double perimeter() const;

private:
    std::vector<Point> points_;
    std::vector<std::uint32_t> next_;  // the next vertex along the ring
    std::vector<std::size_t> ring_begin_;
    Box bounds_{0.0, 0.0, 0.0, 0.0};
};

}  // namespace pds

#endif
