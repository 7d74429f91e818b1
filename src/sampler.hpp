// sampler.hpp - the Jones loop (Jones 2006, figure 1): pick a Voronoi cell with
// probability proportional to its free area, draw a point uniformly in its free
// region, insert it, and update the areas of the new site and its neighbours.
// Knows nothing of C types; the C shim (capi.cpp) validates arguments and maps
// exceptions to error codes.
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
#include <vector>

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

// Counters for diagnostics and tests.
struct SamplerStats {
    std::size_t exact_classifications = 0;  // doubtful or stuck cells decided exactly
    std::size_t gave_up_cells = 0;          // cells still free that no draw could reach
    std::size_t failed_draw_rounds = 0;     // sample_cell calls that placed no point
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
    // whether the pattern is maximal afterwards. Memory for the whole run is
    // reserved first, so std::bad_alloc means no point was added.
    std::size_t run(std::size_t max_new, bool* maximal);
    // Continues with a smaller radius; requires 0 < radius <= radius() and limits ok.
    void refine(double radius);

    std::size_t count() const { return dt_.vertex_count() - Delaunay::kGhosts; }
    std::size_t copy_points(std::size_t first, std::size_t n, double* xy) const;
    double radius() const { return user_radius_; }
    double free_area() const;
    const Box& domain() const { return user_domain_; }
    VerifyReport verify() const;
    const SamplerStats& stats() const { return stats_; }
    std::size_t memory_bytes() const;

    // Internals, for the unit tests.
    const Delaunay& mesh() const { return dt_; }
    const Box& internal_domain() const { return box_; }
    double internal_radius() const { return r_; }
    double cell_weight(std::size_t site) const { return tree_.weight(site); }
    bool cell_doubtful(std::size_t site) const { return doubtful_[site] != 0; }
    CellQuery cell_query(std::size_t site) const;
    std::vector<Point> cell_ring(std::size_t site) const;

private:
    static constexpr int kMaxDraws = 64;  // per piece; a healthy piece accepts > 1/2 of draws
    static constexpr int kFailuresPerGiveUp = 8;

    void set_frame(const Box& domain, double radius);
    void ensure_room(std::size_t points);
    bool add_one();
    void insert_point(const Point& p, std::uint32_t near);
    void update_cell(std::uint32_t vertex);
    void resolve_doubtful(std::size_t site);
    void give_up(std::size_t site);
    bool covered_exactly(std::size_t site);
    bool acceptable(const Point& p, std::uint32_t vertex) const;

    static std::uint32_t vertex_of(std::size_t site) {
        return static_cast<std::uint32_t>(site + Delaunay::kGhosts);
    }
    template <class Visit>
    void for_each_neighbour(std::uint32_t v, const Visit& visit) const {
        const QuadEdgeMesh& m = dt_.mesh();
        const EdgeRef first = dt_.edge_of(v);
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
    Delaunay dt_;
    FreeAreaTree tree_;                // one leaf per site, the cell's free area
    std::vector<std::uint8_t> doubtful_;  // per site: area not certified
    std::vector<Point> ring_scratch_;
    SamplerStats stats_;
};

}  // namespace pds

#endif
