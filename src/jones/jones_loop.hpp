// jones_loop.hpp - the Jones loop (Jones 2006, figure 1): pick a Voronoi
// cell with probability proportional to its free area, draw a point
// uniformly in its free region, insert it, and account for the areas that
// changed.
//
// Lazy areas (our change to the paper's step 5): inserting a point only
// shrinks its neighbours' cells, so their old free areas remain upper bounds.
// The tree holds these bounds U >= A instead of exact areas, and neighbours are
// not recomputed at insertion. A cell is selected with probability
// proportional to U, measured exactly in the same pass that picks a piece with
// target u * U, and kept with probability A / U (the target falls inside the
// exact area); otherwise its weight is tightened to A and the selection starts
// over. Every accepted cell is therefore chosen with probability proportional
// to A, as the paper's exact recomputation would give, with a fraction of the
// work; and the loop ends only when every weight has been measured 0.
//
// Batches (memory-level parallelism, batch.hpp): free regions only shrink, so
// a point drawn uniformly from an older free region and kept only if it is
// still free (at least R from the points added since) is exactly uniform over
// the current one. So candidates are drawn in batches from one state of the
// pattern: the tree is descended for all of them level by level and their
// cells' rings are walked in step, so their misses overlap; then each is
// computed from cache, and the queue is consumed in order, dropping
// candidates the newer points cover. The batch size adapts to how many
// candidates survive; the queue persists across calls, so splitting a run
// does not change its points.
//
// Guarantees (with the predicates' exactness):
//   - every accepted point is inside the domain, outside every disk and
//     inside its cell, checked exactly;
//   - each new point is uniform over the free area: the cell is chosen by area
//     (tree), the piece by area, the point by rejection inside the piece;
//   - next() returns nullptr only when every cell is covered: certified in
//     floating point or decided exactly (cell_coverage.hpp).
//
// The loop knows its mesh and radius rule only as types:
//   Space  where the points live: PlaneSpace (the domain's rectangle) or
//          TorusSpace (the plane with copies of the points, torus_space.hpp);
//          it inserts a point, bounds the newer points' reach, verifies.
//   Rule   how far a point keeps others: OneRadius (Voronoi cells) or
//          PowerRule (a field: power cells of a regular triangulation,
//          radius_rule.hpp).
//
// Memory: reserve() makes room for the points beforehand; only the exact
// coverage test allocates while points are drawn. If it runs out, the batch
// being drawn is undone (generator, weights, queue) before std::bad_alloc
// leaves, so the stage is exactly as before the batch and a later call draws
// the same points.
#ifndef PDS_JONES_LOOP_HPP
#define PDS_JONES_LOOP_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/batch.hpp"
#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/rng.hpp"
#include "core/worker_pool.hpp"
#include "jones/active_scan.hpp"
#include "jones/free_area_tree.hpp"
#include "jones/jones_stage.hpp"
#include "jones/point_order.hpp"
#include "jones/region_darts.hpp"
#include "jones/ring_prefetcher.hpp"
#include "mesh/delaunay.hpp"

namespace pds {

template <class Space, class Rule>
class JonesLoop final : public JonesStage {
public:
    JonesLoop(const Rectangle& domain, double r, const Torus& torus, const PointRadii* radii,
              std::shared_ptr<const Polygon> polygon);

    void reserve(std::size_t points) override;
    bool has_room_for(std::size_t points) const override;
    void adopt(const std::vector<Point>& points, const std::uint32_t* order, const std::vector<double>* values,
               const Poll& poll, MeshBuild build) override;
    void settle() override { space_.settle(*this); }
    void set_radius(double r, const PointRadii* radii) override;

    // The points handed out: an epoch inserted by sides is in the mesh
    // before its points are (inserted_ahead_).
    std::size_t count() const override { return space_.count(*this) - inserted_ahead_; }
    const Point& point(PointIndex k) const override { return dt_.point(order_.vertex(k)); }
    void copy_points(PointIndex first, std::size_t n, Point* out) const override {
        // The hand-over put the points in curve order: a copy in the order
        // added reads them at random, so the reads are asked for ahead.
        constexpr std::size_t kAhead = 16;
        for (std::size_t i = 0; i < n; ++i) {
            if (i + kAhead < n) pds::prefetch(&dt_.point(order_.vertex(first + static_cast<PointIndex>(i + kAhead))));
            out[i] = point(first + static_cast<PointIndex>(i));
        }
    }
    double value(PointIndex k) const override { return rule_.value(k); }
    const Point* next(Rng& rng) override;
    void add_next() override;
    double free_area() const override;
    VerifyReport verify() const override;

    const Delaunay& mesh() const override { return dt_; }
    MeshCells cells() const override { return cells_of(0); }
    // The cells as worker w queries them (its own outline cutter).
    MeshCells cells_of(unsigned w) const { return MeshCells(dt_, space_.clip_box(), r_, space_.outline_clip(w)); }
    const TorusCopies& torus_copies() const override { return space_.copies(); }
    bool is_copy(VertexIndex v) const override { return space_.is_copy(v); }
    const JonesStats& stats() const override { return stats_; }
    void set_fixed(std::size_t n) override { fixed_ = n; }
    void set_threads(unsigned n) override {
        space_.set_workers(n < 1 ? 1 : n);  // may throw std::bad_alloc: nothing changed yet
        threads_ = n < 1 ? 1 : n;
    }
    void draw_cut_cells_by_region() override { region_draws_ = true; }
    void set_batch_size(std::size_t n) override { batch_size_ = n < 1 ? 1 : (n > kMaxBatch ? kMaxBatch : n); }
    void carry_darts(std::uint64_t salted_seed, std::size_t epoch) override;
    const RegionDarts::Stats& region_stats() const override { return regions_.stats(); }
    void set_region_darts_per_cell(double mean) override { regions_.set_darts_per_cell(mean); }
    void set_side_insertions(bool on) override;  // jones_loop_sides.cpp
    void set_room_cap(std::size_t points) override { room_cap_ = points; }
    void allow_helper(bool on) override {
        helper_allowed_ = on;
        if (!on) quiet_helper();
    }
    // Stops the helper (joins it): before the darts or the mesh's arrays
    // move, or the mesh changes otherwise than by insertions.
    // A scan of the active list it began ends where it stands.
    void quiet_helper() {
        prefetcher_.stop();
        active_scan_.seal();
    }

private:
    friend Space;
    friend Rule;
    friend class PlaneSpace;  // PolygonSpace's insertion and hand-over are its base's

    static constexpr int kMaxDraws = 64;  // per piece; a healthy piece accepts > 1/2 of draws
    static constexpr int kFailuresPerGiveUp = 8;
    // Refused draws in a row (no point placed) that count as one failure:
    // far beyond what any healthy cell refuses (each keeps a draw with a
    // probability near 1/2 or more).
    static constexpr std::size_t kRejectionsPerFailure = 4096;
    // Refused draws per point placed, in all, past which the cut cells turn
    // to their trapezoids (with kRejectionsPerFailure refusals at least): a
    // strip far thinner than R refuses thousands a point, but places points
    // often enough that none of its runs of refusals reaches a failure; a
    // healthy outline refuses far below one a point.
    static constexpr std::size_t kRefusalsPerPlaced = 16;
    // A candidate is checked exactly only against the newer points within
    // this many radii in x and y (any half-side >= R holds the disk).
    static constexpr double kBoxReach = 1.5;

    // A point drawn from the free region as it was when its batch was drawn.
    struct Candidate {
        Point p;
        VertexIndex source;  // the vertex whose cell it was drawn in
    };
    // A tree weight as it was before the batch being drawn changed it.
    struct WeightUndo {
        SiteIndex site;
        double weight;
    };

    // Every cell's exact free area into the tree: O(N), no allocation. On
    // the torus, false when some real cell is not yet its torus cell.
    bool measure_all_cells(const Poll& poll = Poll{});
    // Sites first..last-1 of them, by worker w; the rings walked a batch ahead.
    bool measure_cells(SiteIndex first, SiteIndex last, unsigned w = 0);
    // Mesh vertices (ghosts aside) that `points` points need, copies included.
    std::size_t vertices_for(std::size_t points) const { return space_.vertices_for(points); }
    void adapt_batch_size();
    void drop_queue();
    // Candidates drawn for a mesh that is gone (a refine, a rebuilt mesh).
    void forget_candidates() {
        drop_queue();
        has_first_ = false;
    }
    bool still_free(const Point& p) const;
    void draw_batch(std::size_t n, Rng& rng);
    void draw_batch_unguarded(std::size_t n, Rng& rng);
    void set_weight(SiteIndex site, double weight);
    void give_up(SiteIndex site);
    // A representable free point of v's cell within two rounding steps of
    // one of its piece ends (piece_ends.hpp), if there is one.
    bool near_piece_end(VertexIndex v, Point* out) const;
    // The free regions' dart process (region_darts.hpp, jones_loop_regions.cpp):
    // the next of its points, or nullptr once it has ended.
    const Point* next_region_point();
    void add_region_point();  // inserts the next of them
    bool draw_region_epoch();
    void draw_region_block(const MeshCells& cells, std::size_t block, double dt,
                           RegionDarts::Block& out) const;
    void draw_in_region(const MeshCells& cells, SiteIndex site, unsigned darts, std::uint64_t seed,
                        RegionDarts::Block& out) const;
    // An epoch's insertions on two sides at once (jones_loop_sides.cpp): in
    // the plane with one radius, when set_side_insertions is on.
    bool inserts_by_sides() const { return side_insertions_; }
    // Room for the epoch's points (at most `darts`), before it is decided.
    void make_room_for_epoch(std::size_t darts);
    void insert_epoch_by_sides(WorkerPool& pool);
    // The next of the points inserted ahead handed out, its value `value`.
    void hand_out_inserted(double value);
    // std::logic_error while some of them are not handed out yet.
    void require_epoch_handed_out(const char* what) const;
    // Exact: inside the domain, outside every disk, inside v's cell.
    bool acceptable(const Point& p, VertexIndex v) const {
        return space_.inside(p) && rule_.acceptable(dt_, p, v, r_);
    }
    // The bookkeeping of a point just inserted as vertex v.
    void record_new_point(VertexIndex v, double value) {
        rule_.push_value(value);
        since_batch_.push_back(v);
        draw_failures_ = 0;
        rejections_ = 0;
    }

    Rule rule_;
    Space space_;
    double r_;
    Delaunay dt_;
    FreeAreaTree tree_;  // one leaf per site: an upper bound on its free area
    PointOrder order_;
    std::vector<Candidate> queue_;            // the current batch, consumed in order
    std::size_t queue_head_ = 0;
    std::vector<VertexIndex> since_batch_;    // vertices added since it was drawn
    std::size_t batch_size_ = 1;
    int draw_failures_ = 0;                   // failed chunk samplings since the last point
    std::size_t rejections_ = 0;              // refused draws since the last point
    // Set for good once refused draws pile up: cut cells are then drawn
    // from their regions' trapezoids (MeshCells::draw_in_cut_cell), not by the fan.
    bool region_draws_ = false;
    Candidate first_{};                       // the first point, drawn over the whole domain
    bool has_first_ = false;
    WeightUndo undo_[2 * kMaxBatch];          // at most two weight changes per candidate
    std::size_t undo_count_ = 0;
    JonesStats stats_;  // counters only: never steer the sampling
    std::size_t fixed_ = 0;  // the first points are fixed (set_fixed)
    unsigned threads_ = 1;   // for measure_all_cells (set_threads)
    RegionDarts regions_;    // on from the parallel opening's hand-over (carry_darts)
    bool side_insertions_ = false;        // set_side_insertions, where it applies
    std::size_t room_cap_ = SIZE_MAX;     // set_room_cap
    std::size_t inserted_ahead_ = 0;      // points of an epoch in the mesh, not yet handed out
    std::vector<std::uint32_t> side_dart_of_;  // an epoch's slot rank -> its dart (by time)
    std::vector<double> side_area_;            // by slot rank: its measured area, -1 while waiting
    // Walks the rings ahead of the regions' insertions, with threads, inside
    // pds_run (allow_helper); stopped before the darts or the mesh may move.
    RingPrefetcher prefetcher_;
    bool helper_allowed_ = false;
    // The next epoch's scan of the active list, by the helper between its
    // walks when the bounds stay (Space::kBoundsStayWhileInserting).
    ActiveScan active_scan_;
    struct ScanStep final : RingPrefetcher::SideJob {
        explicit ScanStep(ActiveScan& s) : scan(s) {}
        bool step() override { return scan.step(); }
        ActiveScan& scan;
    } scan_step_{active_scan_};
};

}  // namespace pds

#endif
