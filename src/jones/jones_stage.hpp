// jones_stage.hpp - the Jones loop (Jones 2006, figure 1): pick a Voronoi
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
//   - every accepted point is inside the domain, at least R from its cell's site
//     and inside that cell (so at least R from every point), checked exactly;
//   - each new point is uniform over the free area: the cell is chosen by area
//     (tree), the piece by area, the point by rejection inside the piece;
//   - next() returns nullptr only when every cell is covered: certified in
//     floating point or decided exactly (cell_coverage.hpp).
// The torus (torus_copies.hpp): the mesh also holds copies of the points
// near the fundamental domain. Copies are vertices with weight 0 in the tree
// (never selected), points are drawn in their real cell (unclipped), snapped
// to the torus grid and moved into the fundamental domain when inserted, and
// a candidate is checked against every copy of the points added since.
//
// A variable radius (point_radii.hpp): the mesh is the regular triangulation
// of the disks and the cells are power cells (free_area.hpp), each new point
// gets its radius from the field as it is added, and a candidate must keep
// out of each newer disk by that disk's radius. A disk can lose its whole
// power cell to later, larger ones (hidden, delaunay.hpp): its weight is
// dropped when it is next selected. A refine changes every radius, and so
// the power diagram: the mesh is rebuilt.
//
// Memory: reserve() makes room for the points beforehand; only the exact
// coverage test allocates while points are drawn. If it runs out, the batch
// being drawn is undone (generator, weights, queue) before std::bad_alloc
// leaves, so the stage is exactly as before the batch and a later call draws
// the same points.
#ifndef PDS_JONES_STAGE_HPP
#define PDS_JONES_STAGE_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/batch.hpp"
#include "mesh/delaunay.hpp"
#include "jones/free_area_tree.hpp"
#include "core/indices.hpp"
#include "jones/mesh_cells.hpp"
#include "core/point.hpp"
#include "core/poll.hpp"
#include "jones/point_order.hpp"
#include "radius/point_radii.hpp"
#include "core/rng.hpp"
#include "jones/stage.hpp"
#include "mesh/torus_copies.hpp"

namespace pds {

// What the stage could not do, for tests and diagnostics.
struct JonesStats {
    std::size_t gave_up_cells = 0;  // cells still free that no draw could reach
    // Where the loop's work goes (bench/phases.cpp): cells selected from the
    // tree; of those, selections whose target fell in the part of the bound
    // the cell had lost since it was measured; and of those, the ones whose
    // cell had no free area left.
    std::size_t selections = 0;
    std::size_t stale_selections = 0;
    std::size_t stale_at_zero = 0;
};

class JonesStage final : public Stage {
public:
    // box and r in the internal frame, torus on for a periodic domain; radii
    // for a variable radius (r: the largest). May throw std::bad_alloc.
    JonesStage(const Box& box, double r, const Torus& torus = Torus{}, const PointRadii* radii = nullptr);

    // Room for `points` points in all; strong guarantee (std::bad_alloc).
    void reserve(std::size_t points);
    bool has_room_for(std::size_t points) const;

    // The hand-over: inserts the dart stage's points (point k of `points`
    // is the k-th added) in the order given, measures every cell and builds
    // the tree. A varying radius: values[k] is point k's field value.
    // Requires count() == 0 and room; never allocates. Calls poll every
    // Poll::kEvery points inserted and cells measured.
    void adopt(const std::vector<Point>& points, const std::uint32_t* order,
               const std::vector<double>* values = nullptr, const Poll& poll = Poll{});
    // The torus: finishes a widening of the margin that memory interrupted,
    // or that the hand-over left to do (may throw std::bad_alloc).
    void settle();
    // Continues at a smaller radius: drops drawn candidates (they were drawn
    // for the old free region) and measures every cell again. With a variable
    // radius, radii gives the new scale and the mesh is rebuilt (allocates;
    // on std::bad_alloc nothing has changed).
    void set_radius(double r, const PointRadii* radii = nullptr);
    double value(PointIndex k) const override { return radii_ ? values_[k] : 0.0; }

    std::size_t count() const override {
        return copies_.on() ? order_.handed_over() : dt_.vertex_count() - Delaunay::kGhosts;
    }
    const Point& point(PointIndex k) const override { return dt_.point(order_.vertex(k)); }
    const Point* next(Rng& rng) override;
    void add_next() override;
    double free_area() const override;
    VerifyReport verify() const override;

    // Internals, for the unit tests.
    const Delaunay& mesh() const { return dt_; }
    MeshCells cells() const { return MeshCells(dt_, copies_.on() ? copies_.clip_box() : box_, r_); }
    bool is_copy(VertexIndex v) const { return copies_.on() && is_copy_[v] != 0; }
    const TorusCopies& torus_copies() const { return copies_; }
    const JonesStats& stats() const { return stats_; }
    // Draws the next batches n at a time (1 <= n <= kMaxBatch) until the
    // adaptation changes it: lets a test put several cells in one batch.
    void set_batch_size(std::size_t n) { batch_size_ = n < 1 ? 1 : (n > kMaxBatch ? kMaxBatch : n); }

private:
    static constexpr int kMaxDraws = 64;  // per piece; a healthy piece accepts > 1/2 of draws
    static constexpr int kFailuresPerGiveUp = 8;
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
    void adapt_batch_size();
    void drop_queue();
    bool still_free(const Point& p) const;
    bool still_free_on_torus(const Point& p) const;
    void draw_batch(std::size_t n, Rng& rng);
    void draw_batch_unguarded(std::size_t n, Rng& rng);
    void set_weight(SiteIndex site, double weight);
    void give_up(SiteIndex site);
    bool acceptable(const Point& p, VertexIndex vertex) const;
    // The field's value at a point about to be added (0 without a field);
    // may throw FieldError, before anything changes.
    // On the torus, at the point moved into the fundamental domain.
    double value_at(const Point& p) const {
        if (!radii_) return 0.0;
        return radii_->value_at(copies_.on() ? copies_.torus().wrap(p) : p);
    }
    void insert_point(const Point& p, VertexIndex near, double value);
    // A variable radius: whether v's site lies in its own power cell (else
    // its fan's pieces reach outside the cell, see free_area.hpp).
    bool site_in_own_cell(VertexIndex v) const;
    // A variable radius: p in v's power cell and outside its disk (exact).
    bool in_free_power_cell(const Point& p, VertexIndex v) const;
    // The torus: the hand-over (adopt) with the points' copies.
    void adopt_on_torus(const std::vector<Point>& points, const std::uint32_t* order, const Poll& poll);
    // The torus: p (drawn in near's cell) wrapped, inserted with its copies.
    void insert_point_on_torus(const Point& p, VertexIndex near, double value);
    // A variable radius: the mesh built anew from the points (refine).
    void rebuild_mesh();
    // The torus: room for one more point and all its copies (may allocate).
    void make_room_for_copies(std::size_t copies);
    // Inserts p (real, wrapped; radius: its radius with a variable one) and
    // its copies; returns p's vertex.
    VertexIndex insert_with_copies(const Point& p, VertexIndex near, double radius);
    // Inserts p with its bookkeeping: a copy of real vertex *copy_of (with
    // its radius), or a real point of radius `radius` when there is none. Its
    // tree leaf is 0 until measured.
    VertexIndex insert_vertex(const Point& p, VertexIndex near, std::optional<VertexIndex> copy_of = std::nullopt,
                              double radius = 0.0);
    // A real point's vertex (not a ghost, not a copy); the torus only.
    bool is_real(VertexIndex v) const { return !Delaunay::is_ghost(v) && original_[v] == v; }
    // Calls f(o) for each neighbour of v that is a copy of real vertex o
    // shifted by exactly (sx, sy) (exact on the grid).
    template <class F>
    void for_each_neighbour_copy(VertexIndex v, double sx, double sy, const F& f) const;
    // Where to start the walk that inserts w, p moved into the domain.
    VertexIndex walk_start(const Point& p, const Point& w, VertexIndex near) const;
    // Where to start the walk that inserts c, the copy of real vertex v
    // shifted by (i, j) periods; hint: the last copy with that offset.
    VertexIndex copy_walk_start(VertexIndex v, const Point& c, int i, int j, VertexIndex hint) const;
    // Whether the triangles around the new vertices [from, vertex_count)
    // keep the torus invariant.
    bool new_rings_valid(VertexIndex from) const;
    // Whether the triangles around real vertex v, measured as m, do.
    bool cell_valid(VertexIndex v, const CellMeasure& m) const;
    // Widens the margin until every real ring is valid, inserting the copies
    // it brings, and measures every cell again.
    void widen_margin();
    // A variable radius on the torus runs the Jones loop from the first
    // point, whose sparse start widens the margin to the whole domain: each
    // time the count doubles, if the cells now need under half the margin,
    // the mesh is rebuilt with the copies of a narrower one (drawn candidates
    // are dropped, as at a refine: a decision that depends on the count
    // only, so the law and the splits' bytes are kept).
    void maybe_narrow_margin();
    void rebuild_with_margin(double margin);
    Point first_point(Rng& rng) const;
    // Mesh vertices (ghosts aside) that `points` points need, copies included.
    std::size_t vertices_for(std::size_t points) const;

    Box box_;
    double r_;
    Delaunay dt_;
    FreeAreaTree tree_;  // one leaf per site: an upper bound on its free area
    PointOrder order_;
    std::vector<Candidate> queue_;            // the current batch, consumed in order
    std::size_t queue_head_ = 0;
    std::vector<VertexIndex> since_batch_;    // vertices added since it was drawn
    std::size_t batch_size_ = 1;
    int draw_failures_ = 0;                   // failed chunk samplings since the last point
    Candidate first_{};                       // the first point, drawn over the whole domain
    bool has_first_ = false;
    WeightUndo undo_[2 * kMaxBatch];          // at most two weight changes per candidate
    std::size_t undo_count_ = 0;
    JonesStats stats_;  // counters only: never steer the sampling
    TorusCopies copies_;                      // off for a plain rectangle
    std::vector<std::uint8_t> is_copy_;       // per vertex, on the torus
    std::vector<VertexIndex> original_;       // per vertex: the real one it copies (itself if real)
    std::vector<VertexIndex> copy_hint_;      // per offset: the last copy inserted
    bool widen_pending_ = false;              // copies may be missing: widen_margin() first
    std::size_t next_narrowing_ = 64;         // the count at which to look at the margin again
    std::optional<PointRadii> radii_;         // a variable radius
    std::vector<double> values_;              // a variable radius: per point, the field's value
};

}  // namespace pds

#endif
