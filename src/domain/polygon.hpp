// polygon.hpp - a polygonal domain: the closed region inside an outline of
// rings by the even-odd rule (polygon_rings.hpp), with what the sampler asks
// of a domain (rectangle.hpp lists it): contains, bounds, area, perimeter, a
// count bound, a uniform point, exact scaling.
//
// Edges that cross are split where they cross first (polygon_splits.hpp),
// so each edge has the inside on one side. That side is found by locating
// two points just either side of its middle; the area is the boundary
// integral of the edges so oriented: the even-odd area, rings crossing one
// another or themselves included (a bow tie is two triangles). An outline
// with nothing inside (a
// ring traced twice, say) is refused; beside other rings, copies of one
// segment cancel in pairs, and they and the edges of a ring whose sides the
// probes cannot tell count in the parity only.
#ifndef PDS_POLYGON_HPP
#define PDS_POLYGON_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/expansion.hpp"
#include "core/point.hpp"
#include "core/rng.hpp"
#include "domain/polygon_index.hpp"
#include "domain/polygon_rings.hpp"

namespace pds {

class Polygon {
public:
    // As PolygonRings takes it; throws DomainError.
    Polygon(const double* xy, const std::size_t* ring_ends, std::size_t rings);

    const Box& bounds() const { return rings_->bounds(); }
    bool contains(const Point& p) const { return locator().contains(p); }
    PolygonIndex::Place locate(const Point& p) const { return locator().locate(p); }
    // The closed domain contains the point (X/W, Y/W), W > 0, exactly: a
    // Voronoi vertex, or where a Voronoi edge leaves the bounding box
    // (polygon_exact.cpp). Allocates; for the rare exact decisions.
    bool contains_exact(const Expansion& X, const Expansion& Y, const Expansion& W) const;
    double area() const { return area_; }
    double perimeter() const { return perimeter_; }
    // A bound on the distance between two of its points: the box's diagonal.
    double diameter() const { return bounds().diagonal(); }
    double largest_magnitude() const { return bounds().largest_magnitude(); }
    // A rigorous bound on the points at mutual distance >= r in the domain:
    // their disks of radius r/2 are disjoint and lie within r/2 of it, inside
    // the union of the region and each edge's r/2-neighbourhood.
    double count_bound(double r) const;
    // Uniform in the domain: a cell of the index that is not outside, chosen
    // uniformly, a uniform point of it, kept when the domain contains it.
    Point uniform_point(Rng& rng) const;
    // The area of the outline grid's cells not outside, where uniform_point
    // and the darts draw.
    double candidate_area() const;
    // The same domain times 2^k, exactly.
    Polygon scaled(int k) const;

    // Whether the inside lies to the left of edge i (polygon_rings.hpp's
    // edge from vertex i): its ring's side, so exact for rings that do not
    // cross one another.
    bool inside_left(std::size_t i) const { return inside_left_[i] != 0; }
    // The edges near box b (PolygonIndex::edges_near) that bound the region:
    // without copies of one segment that cancel in pairs, nor the edges of a
    // ring whose sides the probes cannot tell at all (they count for the
    // even-odd rule, but no point of them is the region's).
    void outline_edges_near(const Box& b, std::vector<std::uint32_t>& out) const;

    const PolygonRings& rings() const { return *rings_; }
    const PolygonIndex& index() const { return *index_; }
    // The index that locates points: a finer one when index() is crowded
    // (PolygonIndex::finer_cells_for_location). Locating is exact, so the
    // answers are the same; only index() decides anything else.
    const PolygonIndex& locator() const { return locator_ ? *locator_ : *index_; }

private:
    // Owned through pointers: the index refers to the rings, and a Polygon moves.
    std::unique_ptr<PolygonRings> rings_;
    std::unique_ptr<PolygonIndex> index_;
    std::unique_ptr<PolygonIndex> locator_;  // null: index_ locates
    std::vector<std::size_t> candidate_cells_;
    std::vector<std::uint8_t> inside_left_;  // per edge
    double area_ = 0.0;
    double perimeter_ = 0.0;
};

// The largest and the smallest nonzero finite |c[i]| of c[0..n) (0 and
// HUGE_VAL when there is none).
struct Magnitudes {
    double largest, smallest;
};
Magnitudes magnitudes(const double* c, std::size_t n);

// The power of two e at which to read user coordinates c[0..n) (user =
// read * 2^e), so that the predicates' products on them neither overflow nor
// underflow: 0 when every nonzero finite |c| lies in 2^-500 .. 2^500;
// otherwise the exponent of the largest, or a smaller one that brings the
// largest to at most 2^500 and keeps every nonzero one a normal number, so
// each scales exactly. Throws DomainError when none does (beyond 2^500, a
// nonzero coordinate below about 2^-1522 of the largest).
int reading_exponent(const double* c, std::size_t n);

}  // namespace pds

#endif
