// jones_loop_queries.cpp - what the Jones loop answers about its pattern
// without changing it: the exact free area and the verification
// (pds_free_area, pds_verify), compiled for each mesh and radius rule as
// jones_loop.cpp is.
#include <new>
#include <string>
#include <vector>

#include "jones/jones_loop.hpp"
#include "jones/plane_space.hpp"
#include "jones/polygon_space.hpp"
#include "jones/radius_rule.hpp"
#include "jones/torus_space.hpp"

namespace pds {

template <class Space, class Rule>
double JonesLoop<Space, Rule>::free_area() const {
    require_epoch_handed_out("free_area");
    // Cells are the torus's only once the margin is settled.
    if (space_.pending()) throw std::bad_alloc();
    // The tree holds upper bounds; the exact area is re-measured, cell by cell,
    // in leaf order (so the sum is the same on every call). A cell whose
    // measure rounding leaves open counts only if the exact test finds room
    // in it, as when a draw selects it: a pattern that is maximal has 0,
    // not a residue of rounding (a refine by an ulp leaves such cells).
    const MeshCells cells = this->cells();
    double sum = 0.0;
    tree_.for_each_positive([&](SiteIndex site) {
        const VertexIndex v = vertex_of(site);
        if (rule_.hidden(dt_, v)) return true;
        const CellMeasure m = cells.measure(v);
        if (m.free() > 0.0 && !(m.doubtful && cells.covered_exactly(v))) sum += m.free();
        return true;
    });
    return sum;
}

template <class Space, class Rule>
VerifyReport JonesLoop<Space, Rule>::verify() const {
    require_epoch_handed_out("verify");
    if (space_.pending()) throw std::bad_alloc();
    VerifyReport rep;
    if (Rule::kWeighted) {
        // Each disk is checked against the points after it: their ranks.
        std::vector<std::size_t> rank(dt_.vertex_count(), 0);
        for (std::size_t k = 0; k < count(); ++k) rank[order_.vertex(k)] = k;
        rep = space_.verify(dt_, r_, &rank, fixed_);
    } else {
        rep = space_.verify(dt_, r_, nullptr, fixed_);
    }
    if (rep.vertex != kNoVertex) {
        const PointIndex k = order_.point(rep.vertex);
        if (k < fixed_) rep.failure += " (fixed point " + std::to_string(k) + ")";
        else name_point(rep, k - fixed_);
    }
    if (rep.valid && !rep.maximal && count() > 0 && tree_.total() == 0.0) {
        rep.valid = false;
        rep.failure = "the sampler reported a maximal pattern, but " + rep.failure;
        if (stats_.gave_up_cells > 0)
            rep.failure += " (" + std::to_string(stats_.gave_up_cells) +
                           " free regions were below double-precision resolution)";
    }
    return rep;
}

#define PDS_QUERY_MEMBERS(Space, Rule)                                 \
    template double JonesLoop<Space, Rule>::free_area() const;        \
    template VerifyReport JonesLoop<Space, Rule>::verify() const;
PDS_QUERY_MEMBERS(PlaneSpace, OneRadius)
PDS_QUERY_MEMBERS(PlaneSpace, PowerRule)
PDS_QUERY_MEMBERS(TorusSpace, OneRadius)
PDS_QUERY_MEMBERS(TorusSpace, PowerRule)
PDS_QUERY_MEMBERS(PolygonSpace, OneRadius)
PDS_QUERY_MEMBERS(PolygonSpace, PowerRule)

}  // namespace pds
