// jones_field.cpp - the Jones stage with a variable radius (see
// jones_stage.hpp and point_radii.hpp): the exact test of a candidate in a
// power cell, the test of a site outside its own power cell, and the mesh built anew when a refine changes every radius. The loop itself is in
// jones_stage.cpp; these run only when the stage has a field.
#include <algorithm>
#include <stdexcept>

#include "jones/jones_stage.hpp"
#include "core/predicates.hpp"

namespace pds {

bool JonesStage::in_free_power_cell(const Point& p, VertexIndex v) const {
    // In the site's power cell and outside its disk: outside every disk.
    const Point& c = dt_.point(v);
    const double rc = dt_.radius(v);
    if (compare_distance(p, c, rc) < 0) return false;
    bool ok = true;
    dt_.for_each_neighbour(v, [&](VertexIndex n) {
        if (ok && !Delaunay::is_ghost(n) && compare_power(p, c, rc, dt_.point(n), dt_.radius(n)) > 0) ok = false;
    });
    return ok;
}

bool JonesStage::site_in_own_cell(VertexIndex v) const {
    const Point& c = dt_.point(v);
    const double rc = dt_.radius(v);
    bool inside = true;
    dt_.for_each_neighbour(v, [&](VertexIndex n) {
        if (inside && compare_power(c, c, rc, dt_.point(n), dt_.radius(n)) > 0) inside = false;
    });
    return inside;
}

void JonesStage::rebuild_mesh() {
    // The vertices again in their order, with their new radii: each keeps its
    // number (so the point order and the tree stay), and with equal radii
    // the mesh comes out record for record as before (the scaling changes no
    // decision). Each walk starts at an older neighbour in the old mesh,
    // which is close. Built aside: a failure changes nothing.
    Delaunay fresh(copies_.on() ? copies_.largest_region() : box_, true, radii_->rmax());
    fresh.reserve(std::max<std::size_t>(dt_.vertex_count(), vertices_for(order_.capacity()) + Delaunay::kGhosts));
    std::vector<double> value_of_vertex(dt_.vertex_count(), 0.0);
    for (std::size_t k = 0; k < count(); ++k) value_of_vertex[order_.vertex(k)] = values_[k];
    for (VertexIndex v = Delaunay::kGhosts; v < dt_.vertex_count(); ++v) {
        VertexIndex near = v - 1;
        if (!dt_.is_hidden(v))
            dt_.for_each_neighbour(v, [&](VertexIndex n) {
                if (n < v && !Delaunay::is_ghost(n)) near = n;
            });
        // A copy has its original's radius.
        const VertexIndex o = copies_.on() ? original_[v] : v;
        fresh.insert(dt_.point(v), radii_->radius_of(value_of_vertex[o]), near);
    }
    dt_ = std::move(fresh);
}

}  // namespace pds
