// mesh_cells.hpp - the per-cell queries on a triangulation of the pattern.
//
// One set of queries serves every triangulation the sampler looks at: the
// Jones stage's own mesh, and the one built on the fly for the dart stage's
// points (pds_free_area, pds_verify). A cell is named by its vertex; the
// ring functor feeds free_area.hpp's pipeline the vertex's Delaunay
// neighbours, counterclockwise, through the mesh's one ring walk.
#ifndef PDS_MESH_CELLS_HPP
#define PDS_MESH_CELLS_HPP

#include <algorithm>
#include <cmath>
#include <vector>

#include "cells/cell_coverage.hpp"
#include "cells/outline_clip.hpp"
#include "cells/piece_ends.hpp"
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
    // Where a free region too thin for the draws may hold a representable
    // point (piece_ends.hpp), relative to v's site.
    PieceEnds piece_ends(VertexIndex v) const {
        const CellQuery q = query(v);
        PieceEnds ends(q.radius);
        if (!clip_) {
            cell_stream::stream_cell(q, ring(v), ends);
        } else {
            OutlineClip::Stage<PieceEnds> cut(*clip_, ends, q.site, q.domain, q.radius);
            cell_stream::stream_cell(q, ring(v), cut);
        }
        return ends;
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
    // A cut cell's free region drawn uniformly, right after measure(v) found
    // `free` of it free: a point uniform in the region (cell and domain, cut
    // into trapezoids, those inside the disk dropped), kept if accept(p) (the exact checks: in the domain,
    // in v's cell, outside every disk). For regions the fan's pieces reach
    // too rarely (a strip far thinner than R that turns inside the cell,
    // where nearly every draw from a piece lands outside the region). About
    // 16 times the expected number of draws, at most kMaxRegionDraws; false
    // if none was kept.
    template <class Accept>
    bool draw_in_cut_cell(VertexIndex v, double free, Rng& rng, const Accept& accept, Point* out) const {
        const std::vector<Trapezoid>& pieces = clip_->region_trapezoids(radius(v));
        std::vector<double>& upto = clip_->trapezoid_sums();  // running sums of the areas
        upto.clear();
        double total = 0.0;
        for (const Trapezoid& t : pieces) upto.push_back(total += t.area);
        if (!(total > 0.0 && free > 0.0)) return false;
        const double draws = std::min(kMaxRegionDraws, std::max(64.0, 16.0 * total / free));
        const Point site = mesh_.point(v);
        for (double i = 0; i < draws; ++i) {
            const double target = rng.next_double() * total;
            const std::size_t k = std::min<std::size_t>(
                pieces.size() - 1, static_cast<std::size_t>(std::upper_bound(upto.begin(), upto.end(), target) - upto.begin()));
            const double u = rng.next_double(), w = rng.next_double();
            const Point d = point_in_trapezoid(pieces[k], u, w);
            const Point p{site.x + d.x, site.y + d.y};
            if (accept(p)) {
                *out = p;
                return true;
            }
        }
        return false;
    }
    static constexpr double kMaxRegionDraws = 65536.0;
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
