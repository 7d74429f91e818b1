// sampler.hpp - the Jones loop (Jones 2006, figure 1): pick a Voronoi cell with
// probability proportional to its free area, draw a point uniformly in its free
// region, insert it, and account for the areas that changed. Knows nothing of C
// types; the C shim (capi.cpp) validates arguments and maps exceptions to
// error codes.
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
// Batches (memory-level parallelism): the loop is bound by cache misses, each
// cell a chain of dependent loads. Free regions only shrink, so a point drawn
// uniformly from an older free region and kept only if it is still free (at
// least R from the points added since) is exactly uniform over the current
// one. So candidates are drawn in batches from one state of the pattern: the
// tree is descended for all of them level by level and their cells' rings are
// walked in step, so their misses overlap; then each is computed from cache,
// and the queue is consumed in order, dropping candidates the newer points
// cover. The batch size adapts to how many candidates survive; the queue
// persists across calls, so splitting a run does not change its points.
//
// Stages: a run opens with dart throwing on a grid (dart_grid.hpp), which adds
// points with the same law while most of the domain is free, and switches to
// the Jones loop once darts mostly miss: the points so far are inserted into
// the triangulation in grid order, every cell is measured, and the tree is
// built in one pass. Points keep the order they were added in: the dart
// stage's vertices are numbered in grid order for locality, and emitted_ maps
// each of those points to its vertex.
//
// Frame: internally every coordinate is the user's multiplied by 2^k, chosen so
// the domain's largest |coordinate| lies in [1, 2). Scaling by a power of two
// is exact both ways, so every exact decision (distances, orientation) is the
// same in both frames, while products of coordinates can neither overflow nor
// underflow. Points are returned scaled back, bit for bit what was decided on.
//
// Guarantees (with the predicates' exactness):
//   - every accepted point is inside the domain, at least R from its cell's site
//     and inside that cell (so at least R from every point), checked exactly;
//   - each new point is uniform over the free area: the cell is chosen by area
//     (tree), the piece by area, the point by rejection inside the piece;
//   - step() returns false only when every cell is covered: certified in
//     floating point or decided exactly (cell_coverage.hpp).
// Errors: std::bad_alloc before any change of the pattern (room is reserved
// before the mesh is touched); std::logic_error for a broken invariant (a bug).
#ifndef PDS_SAMPLER_HPP
#define PDS_SAMPLER_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "dart_grid.hpp"
#include "delaunay.hpp"
#include "free_area.hpp"
#include "free_area_tree.hpp"
#include "point.hpp"
#include "rng.hpp"
#include "verify.hpp"

namespace pds {

// Why a domain and radius cannot be sampled.
enum class Limit {
    ok,
    too_many_points,        // the count bound exceeds 32-bit indices or the address space
    radius_below_precision, // R under 2^-26 of the coordinates' magnitude
    coordinates_too_small,  // |coordinates| all below 2^-900
};

// What the sampler could not do, for tests and diagnostics.
struct SamplerStats {
    std::size_t gave_up_cells = 0;  // cells still free that no draw could reach
};

class Sampler {
public:
    // The unit square; requires a finite radius > 0 with check_limits() ok.
    Sampler(double radius, std::uint64_t seed);

    static Limit check_limits(const Box& domain, double radius);
    // Rigorous upper bound on the number of points (Oler's inequality).
    static double count_bound(const Box& domain, double radius);
    // Largest number of points the index types allow.
    static std::size_t max_points();

    // Requires count() == 0 and check_limits(domain, radius()) ok.
    void set_domain(const Box& domain);
    // Adds one point (true) or finds the pattern maximal (false).
    bool step();
    // Adds up to max_new points (0: no limit); returns how many. *maximal tells
    // whether the pattern is maximal afterwards (decided exactly, without
    // changing any state). Memory for the whole run is reserved first, so
    // std::bad_alloc means no point was added.
    std::size_t run(std::size_t max_new, bool* maximal);
    // Continues with a smaller radius; requires 0 < radius <= radius() and limits ok.
    void refine(double radius);

    std::size_t count() const {
        return darts_ ? darts_->count() : dt_.vertex_count() - Delaunay::kGhosts;
    }
    std::size_t copy_points(std::size_t first, std::size_t n, double* xy) const;
    double radius() const { return user_radius_; }
    // Exact free area: O(cells not yet known covered), 0 at once when maximal.
    double free_area() const;
    const Box& domain() const { return user_domain_; }
    VerifyReport verify() const;
    const SamplerStats& stats() const { return stats_; }

    // Internals, for the unit tests.
    // Runs the Jones loop from the first point, without the dart stage; requires count() == 0.
    void skip_dart_stage();
    bool in_dart_stage() const { return dart_stage_; }
    // The triangulation (only the ghosts while in the dart stage).
    const Delaunay& mesh() const { return dt_; }
    const Box& internal_domain() const { return box_; }
    double internal_radius() const { return r_; }
    CellMeasure cell_measure(std::size_t site) const;
    CellQuery cell_query(std::size_t site) const;
    std::vector<Point> cell_ring(std::size_t site) const;

private:
    static constexpr int kMaxDraws = 64;  // per piece; a healthy piece accepts > 1/2 of draws
    static constexpr int kFailuresPerGiveUp = 8;
    static constexpr std::size_t kMaxBatch = 64;

    // A point drawn from the free region as it was when its batch was drawn.
    struct Candidate {
        Point p;
        std::uint32_t source;  // the vertex whose cell it was drawn in
    };

    void set_frame(const Box& domain, double radius);
    void ensure_room(std::size_t points);
    bool has_room_for_one() const;
    bool add_one();
    void finish_dart_stage();
    void insert_dart_points(Delaunay& into, std::vector<std::uint32_t>* vertex_of_point) const;
    Delaunay mesh_of_dart_points() const;
    bool dart_pattern_has_room() const;
    void draw_batch(std::size_t n);
    bool still_free(const Point& p) const;
    void drop_queue();
    void insert_point(const Point& p, std::uint32_t near);
    void give_up(std::size_t site);
    // Cell queries on any triangulation of the points: the sampler's own, or
    // one built on the fly for the dart stage's points.
    CellMeasure measure_in(const Delaunay& mesh, std::uint32_t v) const;
    bool covered_exactly_in(const Delaunay& mesh, std::uint32_t v) const;
    bool has_free_region_in(const Delaunay& mesh, std::uint32_t v) const;
    bool covered_exactly(std::size_t site) const { return covered_exactly_in(dt_, vertex_of(site)); }
    const Point& point_at(std::size_t k) const;
    bool has_room() const;
    bool acceptable(const Point& p, std::uint32_t vertex) const;

    static std::uint32_t vertex_of(std::size_t site) {
        return static_cast<std::uint32_t>(site + Delaunay::kGhosts);
    }
    // The ring functor measure_cell and select_in_cell expect.
    static auto ring_of(const Delaunay& mesh, std::uint32_t v) {
        return [&mesh, v](const auto& visit) {
            for_each_neighbour_in(mesh, v, [&](std::uint32_t n) { visit(mesh.point(n)); });
        };
    }
    static std::vector<Point> ring_points(const Delaunay& mesh, std::uint32_t v) {
        std::vector<Point> ring;
        for_each_neighbour_in(mesh, v, [&](std::uint32_t n) { ring.push_back(mesh.point(n)); });
        return ring;
    }
    template <class Visit>
    void for_each_neighbour(std::uint32_t v, const Visit& visit) const {
        for_each_neighbour_in(dt_, v, visit);
    }
    template <class Visit>
    static void for_each_neighbour_in(const Delaunay& dt, std::uint32_t v, const Visit& visit) {
        const QuadEdgeMesh& m = dt.mesh();
        const EdgeRef first = dt.edge_of(v);
        EdgeRef e = first;
        do {
            visit(m.dest(e));
            e = m.onext(e);
        } while (e != first);
    }

    Rng rng_;
    Box user_domain_;
    double user_radius_;
    int scale_exp_ = 0;  // internal = user * 2^scale_exp_
    Box box_;            // internal frame
    double r_ = 0.0;     // internal radius (capped at twice the diagonal)
    bool dart_stage_ = true;
    std::unique_ptr<DartGrid> darts_;       // the dart stage's grid, once it has begun
    std::vector<std::uint32_t> emitted_;    // dart-stage point i is vertex emitted_[i]
    Delaunay dt_;
    FreeAreaTree tree_;  // one leaf per site: an upper bound on its free area
    std::vector<Candidate> queue_;                // the current batch, consumed in order
    std::size_t queue_head_ = 0;
    std::vector<std::uint32_t> since_batch_;      // vertices added since it was drawn
    std::size_t batch_size_ = 1;
    int draw_failures_ = 0;                       // failed chunk samplings since the last point
    SamplerStats stats_;  // counters only: never steer the sampling
};

}  // namespace pds

#endif
