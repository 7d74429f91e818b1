// verify_outline.cpp - see verify_outline.hpp.
#include "verify/verify_outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cells/cell_stream.hpp"
#include "cells/polygon_coverage.hpp"
#include "core/roundoff.hpp"

namespace pds {

namespace {

// Collects the bounding box of a cell streamed by the pipeline (relative to its site).
struct BoxSink {
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL, err = 0.0;
    void vertex(const cell_stream::Vtx& v) {
        x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
        err = std::max(err, v.err);
    }
    void edge(const cell_stream::Vtx&, const cell_stream::Vtx&) {}
    void finish() {}
    bool done() const { return false; }
};

}  // namespace

VertexIndex uncovered_outline_cell(const Delaunay& dt, const Polygon& polygon, double r) {
    const Box& box = polygon.bounds();
    const PolygonIndex& index = polygon.index();
    std::vector<std::uint32_t> edges;
    std::vector<Point> ring;
    std::vector<double> radii;
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
        if (dt.weighted() && dt.is_hidden(v)) continue;
        const Point c = dt.point(v);
        const double rc = dt.weighted() ? dt.radius(v) : r;
        ring.clear();
        radii.clear();
        dt.for_each_neighbour(v, [&](VertexIndex n) {
            ring.push_back(dt.point(n));
            radii.push_back(dt.weighted() ? dt.radius(n) : r);
        });
        BoxSink sink;
        cell_stream::stream_cell(CellQuery{c, box, rc}, [&](const auto& visit) {
            for (std::size_t k = 0; k < ring.size(); ++k) visit(ring[k], (rc - radii[k]) * (rc + radii[k]));
        }, sink);
        if (!(sink.x0 <= sink.x1)) continue;  // nothing of the cell in the box
        const double widen = sink.err + 0x1p-30 * rc +
                             8.0 * kUnitRoundoff * (std::fabs(c.x) + std::fabs(c.y) + std::fabs(sink.x0) +
                                                    std::fabs(sink.x1) + std::fabs(sink.y0) + std::fabs(sink.y1));
        const Box near{c.x + sink.x0 - widen, c.y + sink.y0 - widen, c.x + sink.x1 + widen, c.y + sink.y1 + widen};
        if (index.all_cells(near, PolygonIndex::kInside)) continue;  // the Voronoi vertices decide it
        edges.clear();
        polygon.outline_edges_near(near, edges);
        if (!outline_cell_is_covered_exact(c, rc, ring, radii, box, polygon, edges)) return v;
    }
    return kNoVertex;
}

}  // namespace pds
