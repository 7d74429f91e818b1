// verify_outline.cpp - see verify_outline.hpp.
#include "verify/verify_outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cells/cell_stream.hpp"
#include "cells/polygon_coverage.hpp"
#include "core/roundoff.hpp"
#include "verify/outline_filter.hpp"

namespace pds {

namespace {

// Collects the bounding box of a cell streamed by the pipeline (relative to
// its site), and hands its vertices to the filter.
struct BoxSink {
    explicit BoxSink(OutlineFilter& f) : filter(f) {}
    OutlineFilter& filter;
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL, err = 0.0;
    void vertex(const cell_stream::Vtx& v) {
        x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
        err = std::max(err, v.err);
        filter.vertex(v);
    }
    void edge(const cell_stream::Vtx&, const cell_stream::Vtx&) {}
    void finish() {}
    bool done() const { return false; }
};

}  // namespace

OutlineJudge::OutlineJudge(const Delaunay& dt, const Polygon& polygon, double r)
    : dt_(dt), polygon_(polygon), r_(r), filter_(new OutlineFilter(polygon)) {}

OutlineJudge::~OutlineJudge() = default;

OutlineJudge::Verdict OutlineJudge::judge(VertexIndex v, bool filter_on) {
    if (dt_.weighted() && dt_.is_hidden(v)) return Verdict::not_cut;
    const Box& box = polygon_.bounds();
    const Point c = dt_.point(v);
    const double rc = dt_.weighted() ? dt_.radius(v) : r_;
    ring_.clear();
    radii_.clear();
    dt_.for_each_neighbour(v, [&](VertexIndex n) {
        ring_.push_back(dt_.point(n));
        radii_.push_back(dt_.weighted() ? dt_.radius(n) : r_);
    });
    OutlineFilter& filter = *filter_;
    filter.begin_cell(c, rc);
    BoxSink sink(filter);
    const bool doubtful = cell_stream::stream_cell(CellQuery{c, box, rc}, [&](const auto& visit) {
        for (std::size_t k = 0; k < ring_.size(); ++k) visit(ring_[k], (rc - radii_[k]) * (rc + radii_[k]));
    }, sink);
    if (!(sink.x0 <= sink.x1)) return Verdict::not_cut;  // nothing of the cell in the box
    const double widen = sink.err + 0x1p-30 * rc +
                         8.0 * kUnitRoundoff * (std::fabs(c.x) + std::fabs(c.y) + std::fabs(sink.x0) +
                                                std::fabs(sink.x1) + std::fabs(sink.y0) + std::fabs(sink.y1));
    const Box near{c.x + sink.x0 - widen, c.y + sink.y0 - widen, c.x + sink.x1 + widen, c.y + sink.y1 + widen};
    // Inside the outline's clean cells: the Voronoi vertices decide it (verify.cpp).
    if (polygon_.index().all_cells(near, PolygonIndex::kInside)) return Verdict::not_cut;
    edges_.clear();
    polygon_.outline_edges_near(near, edges_);
    // Most cells are settled in floating point; the exact test takes the rest.
    if (filter_on && !doubtful && filter.vertices_certain() && filter.edges_certain(ring_, radii_, edges_))
        return Verdict::covered_by_filter;
    return outline_cell_is_covered_exact(c, rc, ring_, radii_, box, polygon_, edges_) ? Verdict::covered_exactly
                                                                                       : Verdict::uncovered;
}

VertexIndex uncovered_outline_cell(const Delaunay& dt, const Polygon& polygon, double r) {
    OutlineJudge judge(dt, polygon, r);
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v)
        if (judge.judge(v) == OutlineJudge::Verdict::uncovered) return v;
    return kNoVertex;
}

}  // namespace pds
