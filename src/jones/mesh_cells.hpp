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
#include "mesh/delaunay.hpp"
#include "cells/free_area.hpp"
#include "core/indices.hpp"
#include "core/point.hpp"

namespace pds {

class MeshCells {
public:
    // box and r in the sampler's internal frame.
    MeshCells(const Delaunay& mesh, const Box& box, double r) : mesh_(mesh), box_(box), r_(r) {}

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
    // Never allocates.
    CellMeasure measure(VertexIndex v) const { return measure_cell(query(v), ring(v)); }
    // Exact (cell_coverage.hpp); allocates.
    bool covered_exactly(VertexIndex v) const {
        if (!mesh_.weighted()) return cell_is_covered_exact(mesh_.point(v), ring_points(v), box_, r_);
        std::vector<double> radii;
        mesh_.for_each_neighbour(v, [&](VertexIndex n) { radii.push_back(mesh_.radius(n)); });
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
};

}  // namespace pds

#endif
