// verify_outline.hpp - the part of the certificate a polygonal domain adds
// (verify.hpp): every cell the outline may meet, cut by it, lies in its disk.
//
// The pattern is maximal in the polygon when no point of it is uncovered;
// the farthest point from the disks lies at a Voronoi (power) vertex inside
// the polygon (verify.cpp checks those), at an outline vertex, or where the
// outline crosses a cell's edge. The last two are decided, with the cell's
// own vertices, for each cell whose box the outline's grid does not call
// inside, from the points and the mesh alone: in floating point with error
// bounds where that is certain (outline_filter.hpp), else exactly
// (polygon_coverage.hpp).
#ifndef PDS_VERIFY_OUTLINE_HPP
#define PDS_VERIFY_OUTLINE_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/indices.hpp"
#include "domain/polygon.hpp"
#include "mesh/delaunay.hpp"

namespace pds {

class OutlineFilter;

// r: the radius (every vertex's own on a weighted mesh). Returns the first
// vertex whose cut cell is not covered, or kNoVertex.
VertexIndex uncovered_outline_cell(const Delaunay& dt, const Polygon& polygon, double r);

// The same one cell at a time (the loop above; tests compare the filter
// with the exact test through it).
class OutlineJudge {
public:
    enum class Verdict {
        not_cut,            // hidden, outside the box, or inside the outline's clean cells
        covered_by_filter,  // certified in floating point (outline_filter.hpp)
        covered_exactly,    // certified by the exact test (polygon_coverage.hpp)
        uncovered,          // the exact test found a point of the domain outside the disk
    };
    OutlineJudge(const Delaunay& dt, const Polygon& polygon, double r);
    ~OutlineJudge();
    // filter_on false: the exact test alone.
    Verdict judge(VertexIndex v, bool filter_on = true);

private:
    const Delaunay& dt_;
    const Polygon& polygon_;
    double r_;
    std::unique_ptr<OutlineFilter> filter_;
    std::vector<std::uint32_t> edges_;
    std::vector<Point> ring_;
    std::vector<double> radii_;
};

}  // namespace pds

#endif
