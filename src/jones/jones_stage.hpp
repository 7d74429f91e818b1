// jones_stage.hpp - what the sampler and the dart stages ask of the Jones
// stage (the paper's loop, jones_loop.hpp), whatever its mesh and radius.
//
// The stage comes in four types, one per mesh (the plane's, plane_space.hpp;
// the torus's with its copies, torus_space.hpp) and radius rule (one radius
// or a field's power cells, radius_rule.hpp), each compiled on its own:
// make_jones_stage() picks one, once, and no decision on the hot path asks
// which. The virtual calls are those of Stage, one per point, as before.
#ifndef PDS_JONES_STAGE_HPP
#define PDS_JONES_STAGE_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/point.hpp"
#include "core/poll.hpp"
#include "core/torus.hpp"
#include "domain/polygon.hpp"
#include "domain/rectangle.hpp"
#include "jones/mesh_build.hpp"
#include "jones/mesh_cells.hpp"
#include "jones/region_darts.hpp"
#include "jones/stage.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/torus_copies.hpp"
#include "radius/point_radii.hpp"

namespace pds {

// What the stage could not do, for tests and diagnostics.
struct JonesStats {
    std::size_t gave_up_cells = 0;  // cells still free that no draw could reach
    std::size_t corner_points = 0;  // points placed on a corner of the domain those left free
    // Where the loop's work goes (bench/phases.cpp): cells selected from the
    // tree; of those, selections whose target fell in the part of the bound
    // the cell had lost since it was measured; and of those, the ones whose
    // cell had no free area left.
    std::size_t selections = 0;
    std::size_t stale_selections = 0;
    std::size_t stale_at_zero = 0;
    std::size_t region_draws = 0;  // candidates drawn from a cut cell's trapezoids
    // Draws from the fan refused (outside the region) and placed, in all.
    std::size_t refused_draws = 0;
    std::size_t placed_draws = 0;
};

class JonesStage : public Stage {
public:
    // Room for `points` points in all; strong guarantee (std::bad_alloc).
    virtual void reserve(std::size_t points) = 0;
    virtual bool has_room_for(std::size_t points) const = 0;
    // The hand-over: inserts the dart stage's points (point k of `points`
    // is the k-th added) in the order given, measures every cell and builds
    // the tree. A varying radius: values[k] is point k's field value.
    // Requires count() == 0 and room; never allocates. Calls poll every
    // Poll::kEvery points inserted and cells measured.
    virtual void adopt(const std::vector<Point>& points, const std::uint32_t* order,
                       const std::vector<double>* values = nullptr, const Poll& poll = Poll{},
                       MeshBuild build = MeshBuild::insert) = 0;
    // The torus: finishes a widening of the margin that memory interrupted,
    // or that the hand-over left to do (may throw std::bad_alloc).
    virtual void settle() = 0;
    // Continues at a smaller radius: drops drawn candidates (they were drawn
    // for the old free region) and measures every cell again. With a variable
    // radius, radii gives the new scale and the mesh is rebuilt (allocates;
    // on std::bad_alloc nothing has changed).
    virtual void set_radius(double r, const PointRadii* radii = nullptr) = 0;

    // Internals, for the unit tests and bench/phases.cpp.
    virtual const Delaunay& mesh() const = 0;
    virtual MeshCells cells() const = 0;
    // The torus's copies (off for the plane), and whether a vertex is one.
    virtual const TorusCopies& torus_copies() const = 0;
    virtual bool is_copy(VertexIndex v) const = 0;
    virtual const JonesStats& stats() const = 0;
    // Draws the next batches n at a time (1 <= n <= kMaxBatch) until the
    // adaptation changes it: lets a test put several cells in one batch.
    virtual void set_batch_size(std::size_t n) = 0;
    // The first n points adopted are fixed points: verify does not check
    // them against each other, and names the others from n on.
    virtual void set_fixed(std::size_t n) = 0;
    // Threads that measuring every cell (the hand-over, a refine) may use;
    // the measures do not depend on it. A mesh whose cells cannot be
    // measured side by side ignores it.
    virtual void set_threads(unsigned) {}
    // Cut cells drawn from by their regions' trapezoids from the first
    // point, not only once the fan's refusals pile up: lets a test check the
    // law of those draws.
    virtual void draw_cut_cells_by_region() = 0;
    // After the parallel opening's hand-over: carry its dart process on in
    // the cells' free regions (region_darts.hpp), its streams salted_seed's
    // from epoch `epoch` on. Only the one-radius stages of the rectangle
    // and the polygon do; the others ignore it.
    virtual void carry_darts(std::uint64_t /*salted_seed*/, std::size_t /*epoch*/) {}
    // Lets a helper thread run ahead of the free regions' insertions
    // (ring_prefetcher.hpp) while on; off stops it. Sampler::run turns it
    // on for its own duration only, so no thread outlives a call.
    virtual void allow_helper(bool /*on*/) {}
    virtual const RegionDarts::Stats& region_stats() const = 0;
    // Epochs of another mean length (RegionDarts::set_darts_per_cell): lets
    // a test check the law where the darts of an epoch often meet.
    virtual void set_region_darts_per_cell(double mean) = 0;
    // The free regions' epochs go into the mesh on two sides at once
    // (jones_loop_sides.cpp), in the plane with one radius; the other
    // stages ignore it. Other points than with it off, the same for any
    // number of threads. Meanwhile verify, free_area and set_radius refuse
    // a stop inside an epoch (std::logic_error).
    virtual void set_side_insertions(bool /*on*/) {}
    // The most points the pattern can hold, fixed ones included (the
    // sampler's bound): an epoch that outgrows the room reserves at most
    // this much unless its own darts ask for more. Unset, growth is only
    // bounded by what the epochs ask.
    virtual void set_room_cap(std::size_t /*points*/) {}
};

// The domain and r in the internal frame, torus on for a periodic domain;
// radii for a variable radius (r: the largest). May throw std::bad_alloc.
// polygon: a polygonal domain inside the rectangle (polygon_space.hpp).
std::unique_ptr<JonesStage> make_jones_stage(const Rectangle& domain, double r, const Torus& torus = Torus{},
                                             const PointRadii* radii = nullptr,
                                             std::shared_ptr<const Polygon> polygon = nullptr);

}  // namespace pds

#endif
