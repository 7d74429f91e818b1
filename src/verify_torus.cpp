// verify_torus.cpp - the periodic certificate (see verify_torus.hpp).
#include "verify_torus.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "hash_map.hpp"
#include "predicates.hpp"

namespace pds {

namespace {

bool point_less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
bool point_equal(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }


bool check_real_points(const Delaunay& dt, const Torus& t, const std::vector<VertexIndex>& real,
                       VerifyReport& rep) {
    for (VertexIndex v : real) {
        const Point& p = dt.point(v);
        const bool inside = p.x >= t.x0 && p.x - t.px < t.x0 && p.y >= t.y0 && p.y - t.py < t.y0;
        const bool on_grid = Torus::snap(p.x) == p.x && Torus::snap(p.y) == p.y;
        if (!inside || !on_grid) {
            rep.failure = inside ? "a point is off the torus grid" : "a point lies outside the fundamental domain";
            rep.vertex = v;
            return false;
        }
    }
    return true;
}

// Buckets at least R (and a little) wide, wrapped: a point closer than R to p,
// in any copy, lies in p's bucket or a neighbour's, whatever the rounding of
// the bucket index. Only occupied buckets are stored (a hash map from bucket to
// its first point, the rest chained), so memory follows the points, not the
// periods over R.
class WrappedBuckets {
public:
    WrappedBuckets(const Delaunay& dt, const Torus& t, const std::vector<VertexIndex>& real, double r)
        : t_(t), nx_(along(t.px, r)), ny_(along(t.py, r)), next_(real.size(), kEnd) {
        heads_.reserve(real.size());
        for (std::size_t i = 0; i < real.size(); ++i) {
            const std::uint64_t k = key(column(dt.point(real[i])), row(dt.point(real[i])));
            const std::uint32_t* head = heads_.find(k);
            next_[i] = head ? *head : kEnd;
            heads_.insert_or_assign(k, static_cast<std::uint32_t>(i));
        }
    }

    // Calls visit(i, sx, sy) for each indexed point i (a position in `real`)
    // whose copy shifted by (sx, sy) periods may lie within R of p.
    template <class Visit>
    void for_each_near(const Point& p, const Visit& visit) const {
        const std::int64_t bx = column(p), by = row(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                // The neighbour bucket, wrapped, and the shift that brings its
                // points next to p.
                const std::int64_t cx = bx + dx, cy = by + dy;
                const int sx = cx < 0 ? -1 : (cx >= nx_ ? 1 : 0);
                const int sy = cy < 0 ? -1 : (cy >= ny_ ? 1 : 0);
                const std::uint32_t* head = heads_.find(key(cx - sx * nx_, cy - sy * ny_));
                for (std::uint32_t i = head ? *head : kEnd; i != kEnd; i = next_[i]) visit(i, sx, sy);
            }
        }
    }

private:
    static constexpr std::uint32_t kEnd = 0xFFFFFFFFu;
    // Buckets per period: whole, at least 1.001 R wide, at most 2^30 (a coarser
    // bucket holds more points: time, not correctness).
    static std::int64_t along(double period, double r) {
        const double n = std::floor(period / (1.001 * r));
        return n < 1.0 ? 1 : static_cast<std::int64_t>(std::min(n, 0x1.0p30));
    }
    static std::int64_t index(double offset, double period, std::int64_t n) {
        const double f = offset / period * static_cast<double>(n);
        return std::min(n - 1, static_cast<std::int64_t>(std::max(0.0, f)));
    }
    std::int64_t column(const Point& p) const { return index(p.x - t_.x0, t_.px, nx_); }
    std::int64_t row(const Point& p) const { return index(p.y - t_.y0, t_.py, ny_); }
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(y) << 32) | static_cast<std::uint64_t>(x);
    }

    const Torus& t_;
    std::int64_t nx_, ny_;
    HashMap heads_;
    std::vector<std::uint32_t> next_;
};

bool check_distances(const Delaunay& dt, const Torus& t, const std::vector<VertexIndex>& real, double r,
                     VerifyReport& rep) {
    const WrappedBuckets buckets(dt, t, real, r);
    for (std::size_t i = 0; i < real.size(); ++i) {
        const Point& p = dt.point(real[i]);
        bool close = false;
        buckets.for_each_near(p, [&](std::uint32_t j, int sx, int sy) {
            if (close || (j == i && sx == 0 && sy == 0)) return;
            close = compare_distance(p, t.shifted(dt.point(real[j]), sx, sy), r) < 0;
        });
        if (close) {
            rep.failure = "two points are closer than the radius on the torus";
            rep.vertex = real[i];
            return false;
        }
    }
    return true;
}

bool check_copies(const Delaunay& dt, const TorusCopies& copies, const std::vector<std::uint8_t>& is_copy,
                  const std::vector<VertexIndex>& real, VerifyReport& rep) {
    std::vector<Point> expected, present;
    for (VertexIndex v : real)
        copies.for_each_copy(dt.point(v), copies.margin(), -1.0,
                             [&](const Point& c, int, int) { expected.push_back(c); });
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v)
        if (is_copy[v] != 0) present.push_back(dt.point(v));
    std::sort(expected.begin(), expected.end(), point_less);
    std::sort(present.begin(), present.end(), point_less);
    if (expected.size() != present.size() ||
        !std::equal(expected.begin(), expected.end(), present.begin(), point_equal)) {
        rep.failure = "the mesh's copies are not the copies of the points within the margin";
        return false;
    }
    return true;
}

}  // namespace

VerifyReport verify_torus(const Delaunay& dt, const TorusCopies& copies, const std::vector<std::uint8_t>& is_copy,
                          double radius) {
    VerifyReport rep;
    const Torus& t = copies.torus();
    std::vector<VertexIndex> real;
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v)
        if (is_copy[v] == 0) real.push_back(v);
    const auto is_real = [&](VertexIndex v) { return !Delaunay::is_ghost(v) && is_copy[v] == 0; };
    if (!check_real_points(dt, t, real, rep) || !check_distances(dt, t, real, radius, rep) ||
        !check_copies(dt, copies, is_copy, real, rep) || !mesh_consistent(dt, rep)) {
        rep.valid = false;
        return rep;
    }
    for (VertexIndex v : real) {
        if (!copies.ring_valid(dt, v, is_real)) {
            rep.valid = false;
            rep.failure = "a triangle around a point reaches beyond the copies in the mesh";
            rep.vertex = v;
            return rep;
        }
    }
    rep.maximal = !real.empty();
    const Box everywhere = copies.clip_box();
    for (VertexIndex v : real) {
        if (!rep.maximal) break;
        const Point& c = dt.point(v);
        VertexIndex first = 0, prev = 0;
        int n = 0;
        const auto triangle = [&](VertexIndex a, VertexIndex b) {
            if (rep.maximal && voronoi_vertex_uncovered(c, dt.point(a), dt.point(b), everywhere, radius))
                rep.maximal = false;
        };
        dt.for_each_neighbour(v, [&](VertexIndex nb) {
            if (n++ == 0) first = nb;
            else triangle(prev, nb);
            prev = nb;
        });
        if (n >= 2) triangle(prev, first);
    }
    if (!rep.maximal)
        rep.failure = real.empty() ? "no points yet" : "a Voronoi vertex is farther than R from its site";
    return rep;
}

}  // namespace pds
