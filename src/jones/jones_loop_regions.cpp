// jones_loop_regions.cpp - the Jones loop's part of the free regions' dart
// process (region_darts.hpp): the epochs drawn from its cells, side by side,
// and their points handed out in order of time.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>

#include "core/space_time_stream.hpp"
#include "core/worker_pool.hpp"
#include "jones/jones_loop.hpp"
#include "jones/plane_space.hpp"
#include "jones/polygon_space.hpp"
#include "jones/radius_rule.hpp"
#include "jones/torus_space.hpp"

namespace pds {

template <class Space, class Rule>
void JonesLoop<Space, Rule>::carry_darts(std::uint64_t salted_seed, std::size_t epoch) {
    // The runs the parallel opening hands over: one radius for every new
    // point (with fixed points, whose clearances are power disks, too), in
    // a rectangle, a polygon or on the torus. Their darts are decided
    // against one another by that radius. A field's, after its dart stage:
    // each accepted dart keeps the later ones out of its own disk.
    const bool one_radius = rule_.new_radius_is(r_);
    // Another salt: these streams share nothing with the opening's.
    Torus torus;
    if constexpr (Space::kPeriodic) torus = space_.copies().torus();
    quiet_helper();
    regions_.start(mix64(salted_seed ^ 0x6A09E667F3BCC909ull), epoch, space_.clip_box(),
                   one_radius ? r_ : rule_.rmax(), torus, !one_radius);
}

template <class Space, class Rule>
const Point* JonesLoop<Space, Rule>::next_region_point() {
    while (!regions_.has_pending()) {
        // The helper reads the darts the next epoch replaces. The epoch's
        // insertions are done: the scan it may have begun stays valid.
        prefetcher_.stop();
        if (regions_.ending() || !draw_region_epoch()) {
            // The loop's own draws go on from here: its tree of bounds.
            active_scan_.drop();
            regions_.stop();
            tree_.rebuild();
            return nullptr;
        }
    }
    // A new epoch's insertions: the helper walks their rings ahead of them
    // and, in the plane, scans the active list for the next epoch meanwhile.
    // By sides, the epoch is in the mesh already.
    if (helper_allowed_ && threads_ > 1 && regions_.next_index() == 0 && !prefetcher_.running() &&
        !inserts_by_sides()) {
        RingPrefetcher::SideJob* job = nullptr;
        if constexpr (Space::kBoundsStayWhileInserting) {
            if (!active_scan_.begun()) active_scan_.begin(regions_.active(), tree_);
            job = &scan_step_;
        }
        prefetcher_.start(dt_, regions_.pending_darts(), regions_.pending_count(), job);
    }
    return &regions_.pending().p;
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::add_region_point() {
    if (!regions_.has_pending()) throw std::logic_error("add_next without next");
    // By sides, the epoch is in the mesh already: its points are only
    // handed out.
    const bool inserted = inserts_by_sides();
    // The next darts' rings, fetched together ahead of their insertions.
    // With the helper too: its walk brings the lines into the shared cache
    // and its own core's, this fetch into this core's, and dropping it was
    // measured to cost (docs/performance.md, 1.15.3).
    if (!inserted && regions_.next_index() % kMaxBatch == 0) {
        prefetcher_.reached(regions_.next_index());
        VertexIndex ahead[kMaxBatch];
        const std::size_t n = regions_.sources_ahead(ahead, kMaxBatch);
        dt_.prefetch_rings(ahead, n);
        dt_.prefetch_beyond_rings(ahead, n);
    }
    const RegionDarts::Dart dart = regions_.pending();
    // A field's value was asked when its dart was accepted.
    const double value = regions_.has_values() ? regions_.pending_value() : rule_.value_at(space_, dart.p);
    if (inserted) hand_out_inserted(value);  // before the pop: a refusal changes nothing
    regions_.pop();
    if (!inserted) space_.insert_point(*this, dart.p, dart.source, value);
    since_batch_.clear();  // the loop's queue is empty while the process runs
}

template <class Space, class Rule>
bool JonesLoop<Space, Rule>::draw_region_epoch() {
    std::vector<SiteIndex>& active = regions_.active();
    const std::size_t sites = dt_.vertex_count() - Delaunay::kGhosts;
    // The listed sites that are covered leave the list, the others' bounds
    // are summed in its order (beside the last insertions, if the helper
    // scanned them); then the sites added since join it (room first: a
    // failure leaves a list a later call scans again alike).
    if (!active_scan_.begun()) active_scan_.begin(active, tree_);
    double total = active_scan_.take();
    active.reserve(active.size() + (sites - regions_.listed()));
    for (std::size_t s = regions_.listed(); s < sites; ++s) {
        const double w = tree_.weight(s);
        if (w > 0.0) {
            active.push_back(static_cast<SiteIndex>(s));
            total += w;
        }
    }
    regions_.set_listed(sites);
    const std::size_t kept = active.size();
    if (kept == 0 || !(total > 0.0)) return false;
    // An epoch's length: about kDartsPerCell darts per cell at its bound.
    const double dt = regions_.darts_per_cell() * static_cast<double>(kept) / total;
    const std::size_t nblocks = (kept + RegionDarts::kBlock - 1) / RegionDarts::kBlock;
    std::vector<RegionDarts::Block>& blocks = regions_.blocks(nblocks);
    // Blocks are taken in turn by whichever worker is free; each writes its
    // own block, so the joined lists do not depend on who drew them.
    WorkerPool pool(nblocks > 1 || inserts_by_sides() ? threads_ : 1);
    // The pages this epoch's insertions will first write (mesh and tree,
    // room for 1.25 times the darts expected), made resident by the last
    // helper before it draws: else the caller's thread faults them in alone.
    const std::size_t ahead = static_cast<std::size_t>(1.25 * regions_.darts_per_cell() * static_cast<double>(kept));
    std::atomic<std::size_t> next_block{0};
    pool.run([&](unsigned w) {
        if (w != 0 && w + 1 == pool.size()) {
            dt_.populate_for(dt_.vertex_count() + ahead);
            tree_.populate_for(tree_.size() + ahead);
        }
        for (std::size_t b; (b = next_block.fetch_add(1, std::memory_order_relaxed)) < nblocks;)
            draw_region_block(cells_of(w), b, dt, blocks[b]);
    });
    // A field's radius at the darts accepted, as the loop's own points get it.
    struct RuleField final : DartField {
        const JonesLoop& loop;
        explicit RuleField(const JonesLoop& l) : loop(l) {}
        double value_at(const Point& p) const override { return loop.rule_.value_at(loop.space_, p); }
        double radius_of(double value) const override { return loop.rule_.radius_of(value); }
    };
    const RuleField field(*this);
    if (inserts_by_sides()) {
        // Room first: on std::bad_alloc the epoch is not decided, and the
        // next call draws it again alike.
        std::size_t drawn = 0;
        for (std::size_t b = 0; b < nblocks; ++b) drawn += blocks[b].darts.size();
        make_room_for_epoch(drawn);
    }
    regions_.decide_and_commit(
        nblocks, [&](SiteIndex site, double w) { tree_.set_leaf_only(site, w); },
        regions_.has_values() ? &field : nullptr);
    if (inserts_by_sides()) insert_epoch_by_sides(pool);
    return true;
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::draw_region_block(const MeshCells& cells, std::size_t block, double dt,
                                               RegionDarts::Block& out) const {
    const std::vector<SiteIndex>& active = regions_.active();
    const std::size_t first = block * RegionDarts::kBlock;
    const std::size_t last = std::min(active.size(), first + RegionDarts::kBlock);
    // The cells that draw darts are found kMaxBatch at a time, then their
    // rings are fetched together (their misses overlap) and drawn from.
    struct Drawer {
        SiteIndex site;
        unsigned darts;
        std::uint64_t seed;
    };
    Drawer drawers[kMaxBatch];
    VertexIndex rings[kMaxBatch];
    std::size_t i = first;
    while (i < last) {
        std::size_t n = 0;
        for (; i < last && n < kMaxBatch; ++i) {
            const SiteIndex site = active[i];
            const double mean = tree_.weight(site) * dt;
            SpaceTimeStream stream(regions_.salted_seed(), site, regions_.epoch());
            // P(at least one dart) = 1 - e^-mean <= mean: most cells stop here.
            const double u = stream.next_double();
            if (u >= mean) continue;
            // The count by inversion of 1 - u (0 iff 1 - u < e^-mean); a
            // larger mean (a bound far above the others') from more draws.
            const unsigned darts = mean <= SpaceTimeStream::kInvertUpTo
                                       ? SpaceTimeStream::poisson_at(1.0 - u, mean, std::exp(-mean))
                                       : stream.poisson_large(mean);
            if (darts == 0) continue;
            rings[n] = vertex_of(site);
            drawers[n++] = Drawer{site, darts, stream.next_u64()};
        }
        dt_.prefetch_rings(rings, n);
        for (std::size_t k = 0; k < n; ++k)
            draw_in_region(cells, drawers[k].site, drawers[k].darts, drawers[k].seed, out);
    }
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::draw_in_region(const MeshCells& cells, SiteIndex site, unsigned darts, std::uint64_t seed,
                                            RegionDarts::Block& out) const {
    const double bound = tree_.weight(site);
    Rng rng(seed);
    const VertexIndex vx = vertex_of(site);
    if (rule_.hidden(dt_, vx)) {
        // A disk whose power cell later, larger ones took: no ring, no area.
        out.bounds.push_back(RegionDarts::Bound{site, 0.0});
        return;
    }
    const CellQuery q = cells.query(vx);
    double weight = bound;
    bool exact = false;  // weight is the cell's exact free area
    for (unsigned d = 0; d < darts; ++d) {
        // Kept iff its target u U falls in the exact free area.
        const double target = rng.next_double() * bound;
        if (exact && !(target < weight)) continue;  // thinned, known without the ring
        const CellSelection sel = cells.select(vx, target);
        if (!sel.found()) {
            if (sel.measure.doubtful && cells.covered_exactly(vx)) {
                weight = 0.0;
                break;
            }
            weight = std::min(weight, sel.measure.area);
            exact = true;
            if (sel.measure.area < bound) continue;  // thinned
            // Free by its vertices, yet no chunk with area: the loop's
            // own draws settle such a cell (and count it) at the end.
            if (!sel.fallback()) continue;
        }
        // A cell the outline cuts is drawn as the loop's own draws draw it
        // (jones_loop.cpp): from its region's trapezoids once the loop has
        // turned to them, kept iff the target falls in the free area; else
        // from its pieces with no retry, a refused draw losing the dart.
        if (region_draws_ && cells.cut()) {
            const CellMeasure m = cells.measure(vx);
            const double free = m.free() > 0.0 ? m.free() : (m.area > 0.0 ? m.floor : 0.0);
            weight = std::min(weight, free);
            exact = true;
            Point p;
            if (target < free && cells.draw_in_cut_cell(vx, free, rng, [&](const Point& x) { return acceptable(x, vx); }, &p))
                out.darts.push_back(RegionDarts::Dart{p, rng.next_double(), vx});
            continue;
        }
        Point chosen{0.0, 0.0};
        const auto accept = [&](const Point& x, const Piece& piece) {
            chosen = space_.snap(x);
            return acceptable(chosen, vx) && cells.counts(vx, chosen, piece);
        };
        Point drawn;
        const double piece_u = rng.next_double();
        const bool retry = rule_.retry_in_piece(dt_, vx) && !cells.cut();
        if (sample_chunk(q, sel.chunk(), piece_u, rng, accept, kMaxDraws, &drawn, retry) == SampleOutcome::placed)
            out.darts.push_back(RegionDarts::Dart{chosen, rng.next_double(), vx});
        // else: a refused draw in a cut cell, or 64 in a healthy piece
        // (never seen); the dart is lost, and the loop's own draws settle
        // a cell that keeps losing them.
    }
    if (weight < bound) out.bounds.push_back(RegionDarts::Bound{site, weight});
}

#define PDS_REGION_MEMBERS(Space, Rule)                                                                        \
    template void JonesLoop<Space, Rule>::carry_darts(std::uint64_t, std::size_t);                             \
    template const Point* JonesLoop<Space, Rule>::next_region_point();                                         \
    template void JonesLoop<Space, Rule>::add_region_point();                                                  \
    template bool JonesLoop<Space, Rule>::draw_region_epoch();                                                 \
    template void JonesLoop<Space, Rule>::draw_region_block(const MeshCells&, std::size_t, double,             \
                                                            RegionDarts::Block&) const;                        \
    template void JonesLoop<Space, Rule>::draw_in_region(const MeshCells&, SiteIndex, unsigned, std::uint64_t, \
                                                         RegionDarts::Block&) const;
PDS_REGION_MEMBERS(PlaneSpace, OneRadius)
PDS_REGION_MEMBERS(PlaneSpace, PowerRule)
PDS_REGION_MEMBERS(TorusSpace, OneRadius)
PDS_REGION_MEMBERS(TorusSpace, PowerRule)
PDS_REGION_MEMBERS(PolygonSpace, OneRadius)
PDS_REGION_MEMBERS(PolygonSpace, PowerRule)

}  // namespace pds
