// mesh_cells.hpp - the per-cell queries on a triangulation of the pattern.
//
// One set of queries serves every triangulation the sampler looks at: the
// Jones stage's own mesh, and the one built on the fly for the dart stage's
// points (pds_free_area, pds_verify). A cell is named by its vertex; the
// ring functor feeds free_area.hpp's pipeline the vertex's Delaunay
// neighbours, counterclockwise, through the mesh's one ring walk.
#ifndef PDS_MESH_CELLS_HPP
#define PDS_MESH_CELLS_HPP

#include <vector>

#include "cells/cell_coverage.hpp"
#include "cells/outline_clip.hpp"
#include "cells/polygon_coverage.hpp"
#include "mesh/delaunay.hpp"
#include "cells/free_area.hpp"
#include "core/indices.hpp"
#include "core/point.hpp"

namespace pds {

class MeshCells {
public:
    // box and r in the sampler's internal frame; clip: a polygonal domain's
    // cutter (outline_clip.hpp), or nullptr for the box alone.
    MeshCells(const Delaunay& mesh, const Box& box, double r, OutlineClip* clip = nullptr)
        : mesh_(mesh), box_(box), r_(r), clip_(clip) {}

    CellQuery query(VertexIndex v) const { return CellQuery{mesh_.point(v), box_, radius(v)}; }
    // A site's radius: its own on a weighted mesh, else R.
    double radius(VertexIndex v) const { return mesh_.weighted() ? mesh_.radius(v) : r_; }
    // The ring as free_area.hpp takes it: ring(visit) calls visit(point, w)
    // with w the site's squared radius minus the neighbour's.
    auto ring(VertexIndex v) const {
        return [this, v](const auto& visit) {
            if (!mesh_.weighted()) {
                mesh_.for_each_neighbour(v, [&](VertexIndex n) { visit(mesh_.point(n), 0.0); });
                return;
            }
            const double rc = mesh_.radius(v);
            mesh_.for_each_neighbour(v, [&](VertexIndex n) {
                const double rn = mesh_.radius(n);
                visit(mesh_.point(n), (rc - rn) * (rc + rn));
            });
        };
    }
    std::vector<Point> ring_points(VertexIndex v) const {
        std::vector<Point> ring;
        mesh_.for_each_neighbour(v, [&](VertexIndex n) { ring.push_back(mesh_.point(n)); });
        return ring;
    }
    // Never allocates in a rectangle (a polygon's cutter keeps its scratch).
    CellMeasure measure(VertexIndex v) const {
        if (!clip_) return measure_cell(query(v), ring(v));
        const CellQuery q = query(v);
        cell_stream::CellSink sink(q.radius, -1.0);
        OutlineClip::Stage<cell_stream::CellSink> cut(*clip_, sink, q.site, q.domain, q.radius);
        const bool doubtful = cell_stream::stream_cell(q, ring(v), cut);
        return verdict(sink, doubtful || clip_->doubtful(), q.radius);
    }
    // free_area.hpp's select_in_cell for v's cell.
    CellSelection select(VertexIndex v, double target) const {
        if (!clip_) return select_in_cell(query(v), ring(v), target);
        const CellQuery q = query(v);
        CellSelection s(q.radius, target);
        s.sink.stop_at_target();
        OutlineClip::Stage<cell_stream::CellSink> cut(*clip_, s.sink, q.site, q.domain, q.radius);
        const bool doubtful = cell_stream::stream_cell(q, ring(v), cut);
        s.measure = verdict(s.sink, doubtful || clip_->doubtful(), q.radius);
        return s;
    }
    // After select(v): whether a draw p from piece counts (outline_clip.hpp),
    // and whether a refused draw may be retried in the piece.
    bool counts(VertexIndex v, const Point& p, const Piece& piece) const {
        return !clip_ || clip_->counts(mesh_.point(v), p, piece, radius(v));
    }
    bool cut() const { return clip_ && clip_->cut(); }
    // Exact (cell_coverage.hpp, polygon_coverage.hpp); allocates.
    bool covered_exactly(VertexIndex v) const {
        std::vector<double> radii;
        mesh_.for_each_neighbour(v, [&](VertexIndex n) { radii.push_back(mesh_.weighted() ? mesh_.radius(n) : r_); });
        if (clip_) {
            measure(v);  // finds the outline edges near the cell
            if (clip_->cut())
                return outline_cell_is_covered_exact(mesh_.point(v), radius(v), ring_points(v), radii, box_,
                                                     clip_->polygon(), clip_->edges());
        }
        if (!mesh_.weighted()) return cell_is_covered_exact(mesh_.point(v), ring_points(v), box_, r_);
        return power_cell_is_covered_exact(mesh_.point(v), mesh_.radius(v), ring_points(v), radii, box_);
    }
    // Sum of every real cell's free area, in vertex order.
    double total_free_area() const {
        double sum = 0.0;
        for (VertexIndex v = Delaunay::kGhosts; v < mesh_.vertex_count(); ++v)
            if (!mesh_.weighted() || !mesh_.is_hidden(v)) sum += measure(v).free();
        return sum;
    }

private:
    const Delaunay& mesh_;
    Box box_;
    double r_;
    OutlineClip* clip_;
};

}  // namespace pds

#endif
