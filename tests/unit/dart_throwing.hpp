// dart_throwing.hpp - the reference sampler of the law tests: plain dart
// throwing run to true saturation, after Ebeida et al., "Efficient maximal
// Poisson-disk sampling" (SIGGRAPH 2011), for any pair of
//   a distance rule:  Plane (the closed box), Torus ([x0,x1) x [y0,y1),
//                     distances to the nearest copy), InPolygon (rings by
//                     the even-odd rule) or AroundDisks (the box less open
//                     disks around fixed points), and
//   a radius rule:    ConstantRadius (R everywhere) or FieldRadius (a point
//                     at p carries r(p)).
// A dart is kept when it lies in the domain and outside every earlier disk,
// |p - p_i| >= r_i (the library's rule; with one radius, at least R from
// every point), and then carries its own radius.
//
// Darts are uniform over the union of equal squares that may still hold free
// area (level 0: side rmin / sqrt 2, which one disk covers), so every kept
// dart is uniform over the free region: the exact random-sequential-
// adsorption law. A square is dropped only when one disk (one copy of it on
// the torus) covers it entirely; after a batch of darts the survivors are
// split in four, until none is left: true saturation (a fixed budget of
// misses would stop early and bias the count low). On the torus, squares may
// overhang the far sides: darts there are refused, not wrapped, so no area
// counts twice.
//
// Independent of the library: plain floating point, its own bucket grid
// (cells at least rmax wide; on the torus they divide the periods), and
// nothing from src/ but Point and Box.
#ifndef PDS_TEST_DART_THROWING_HPP
#define PDS_TEST_DART_THROWING_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/point.hpp"
#include "even_odd.hpp"

namespace oracle {

// ---- distance rules ----------------------------------------------------------------

// The closed box; buckets of side `cell` from (x0, y0), one beyond each far side.
struct Plane {
    pds::Box box;

    bool inside(const pds::Point& p) const { return box.contains(p); }
    // A child square with this lower-left corner and side may meet the domain.
    bool meets(double x, double y, double) const { return x <= box.x1 && y <= box.y1; }
    double d2(const pds::Point& a, const pds::Point& b) const {
        return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
    }
    // The copy of q nearest c: q itself.
    pds::Point copy_near(const pds::Point& q, const pds::Point&) const { return q; }
    int cells(double side, double cell) const { return static_cast<int>(std::ceil(side / cell)) + 1; }
    double cell_side(double, double cell, int) const { return cell; }
    // The bucket index i (may be outside [0, n)) as stored, or -1: none there.
    int bucket(int i, int n) const { return i < 0 || i >= n ? -1 : i; }
    int clamp(int i, int n) const { return std::min(n - 1, std::max(0, i)); }
};

// The torus [x0,x1) x [y0,y1); buckets at least `cell` wide dividing the periods.
struct Torus {
    pds::Box box;

    bool inside(const pds::Point& p) const { return p.x >= box.x0 && p.x < box.x1 && p.y >= box.y0 && p.y < box.y1; }
    bool meets(double x, double y, double) const { return x < box.x1 && y < box.y1; }
    static double wrap(double d, double period) {
        d = std::fabs(d);
        return d > 0.5 * period ? period - d : d;
    }
    double d2(const pds::Point& a, const pds::Point& b) const {
        const double dx = wrap(a.x - b.x, box.width()), dy = wrap(a.y - b.y, box.height());
        return dx * dx + dy * dy;
    }
    pds::Point copy_near(const pds::Point& q, const pds::Point& c) const {
        const double w = box.width(), h = box.height();
        return {q.x + w * std::round((c.x - q.x) / w), q.y + h * std::round((c.y - q.y) / h)};
    }
    int cells(double side, double cell) const { return std::max(1, static_cast<int>(side / cell)); }
    double cell_side(double side, double, int n) const { return side / n; }
    int bucket(int i, int n) const { return ((i % n) + n) % n; }
    int clamp(int i, int n) const { return bucket(i, n); }  // overhanging corners wrap
};

// Rings of x y pairs by the even-odd rule (even_odd.hpp), in the plane
// (distances and buckets as Plane's, over the rings' box). A square is kept while its
// centre is inside or an edge of the rings meets it, so squares wholly
// outside are dropped and darts there are refused.
struct InPolygon : Plane {
    std::vector<double> xy;
    std::vector<std::size_t> ends;

    explicit InPolygon(const std::vector<std::vector<double>>& rings) : Plane{{1e300, 1e300, -1e300, -1e300}} {
        for (const auto& ring : rings) {
            xy.insert(xy.end(), ring.begin(), ring.end());
            ends.push_back(xy.size() / 2);
        }
        for (std::size_t k = 0; k + 1 < xy.size(); k += 2) {
            box.x0 = std::min(box.x0, xy[k]);
            box.x1 = std::max(box.x1, xy[k]);
            box.y0 = std::min(box.y0, xy[k + 1]);
            box.y1 = std::max(box.y1, xy[k + 1]);
        }
    }
    bool inside(const pds::Point& p) const { return even_odd_contains(xy.data(), ends.data(), ends.size(), p); }
    // The segment meets the closed square (Liang-Barsky clipping).
    static bool segment_meets(double ax, double ay, double bx, double by, double x, double y, double side) {
        double t0 = 0, t1 = 1;
        const double d[2] = {bx - ax, by - ay}, lo[2] = {x - ax, y - ay}, hi[2] = {x + side - ax, y + side - ay};
        for (int k = 0; k < 2; ++k) {
            if (d[k] == 0) {
                if (lo[k] > 0 || hi[k] < 0) return false;
                continue;
            }
            double ta = lo[k] / d[k], tb = hi[k] / d[k];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
        }
        return t0 <= t1;
    }
    bool meets(double x, double y, double side) const {
        return inside(pds::Point{x + side / 2, y + side / 2}) ||
               any_ring_edge(xy.data(), ends.data(), ends.size(), [&](double ax, double ay, double bx, double by) {
                   return segment_meets(ax, ay, bx, by, x, y, side);
               });
    }
};

// The box less the open disks around fixed points (distances and buckets as
// Plane's): a dart strictly inside a disk is refused, and a square whose
// corners all lie within one disk is dropped.
struct AroundDisks : Plane {
    std::vector<pds::Point> centre;
    std::vector<double> radius;

    bool inside(const pds::Point& p) const {
        if (!box.contains(p)) return false;
        for (std::size_t k = 0; k < centre.size(); ++k)
            if (d2(p, centre[k]) < radius[k] * radius[k]) return false;
        return true;
    }
    bool meets(double x, double y, double side) const {
        if (!Plane::meets(x, y, side)) return false;
        for (std::size_t k = 0; k < centre.size(); ++k) {
            bool all = true;
            for (int c = 0; c < 4 && all; ++c)
                all = d2(pds::Point{x + (c & 1) * side, y + (c >> 1) * side}, centre[k]) <= radius[k] * radius[k];
            if (all) return false;
        }
        return true;
    }
};

// ---- radius rules ------------------------------------------------------------------

struct ConstantRadius {
    double r;
    double at(const pds::Point&) const { return r; }
    double rmin() const { return r; }
    double rmax() const { return r; }
};

// The field's signature is the library's radius function's (user data unused).
using Field = double (*)(void*, double, double);

struct FieldRadius {
    Field field;
    double lo, hi;  // the field's bounds
    double at(const pds::Point& p) const { return field(nullptr, p.x, p.y); }
    double rmin() const { return lo; }
    double rmax() const { return hi; }
};

// ---- the sampler -------------------------------------------------------------------

// A saturated pattern: p[i] carries radius r[i].
struct Pattern {
    std::vector<pds::Point> p;
    std::vector<double> r;
};

template <class Distance, class Radius>
class DartThrowing {
public:
    DartThrowing(const Distance& distance, const Radius& radius) : dist_(distance), radius_(radius) {
        const pds::Box& b = dist_.box;
        gx_ = dist_.cells(b.width(), radius.rmax());
        gy_ = dist_.cells(b.height(), radius.rmax());
        cell_x_ = dist_.cell_side(b.width(), radius.rmax(), gx_);
        cell_y_ = dist_.cell_side(b.height(), radius.rmax(), gy_);
    }

    const Distance& distance() const { return dist_; }

    // A maximal pattern for this seed (std::mt19937_64: the library's
    // generator is not used).
    Pattern run(std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        const pds::Box& box = dist_.box;
        out_ = Pattern{};
        buckets_.assign(static_cast<std::size_t>(gx_) * gy_, {});
        double side = radius_.rmin() / std::sqrt(2.0);
        std::vector<pds::Point> active;  // squares' lower-left corners
        const int nx = static_cast<int>(std::ceil(box.width() / side));
        const int ny = static_cast<int>(std::ceil(box.height() / side));
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < ny; ++j) active.push_back({box.x0 + i * side, box.y0 + j * side});
        // Squares below double resolution after 60 levels: not expected.
        for (int level = 0; !active.empty() && level < 60; ++level) {
            const std::size_t darts = active.size();
            for (std::size_t k = 0; k < darts && !active.empty(); ++k) {
                std::size_t pick = static_cast<std::size_t>(u01(rng) * static_cast<double>(active.size()));
                pick = std::min(pick, active.size() - 1);
                const pds::Point sq = active[pick];
                const pds::Point p{sq.x + u01(rng) * side, sq.y + u01(rng) * side};
                if (dist_.inside(p) && !covered(p)) add(p);
                if (covered_square(sq, side)) {
                    active[pick] = active.back();
                    active.pop_back();
                }
            }
            // Split the survivors; keep children that may meet the domain
            // and are not inside a single disk.
            side *= 0.5;
            std::vector<pds::Point> next;
            for (const pds::Point& sq : active)
                for (int c = 0; c < 4; ++c) {
                    const pds::Point child{sq.x + (c & 1) * side, sq.y + (c >> 1) * side};
                    if (dist_.meets(child.x, child.y, side) && !covered_square(child, side)) next.push_back(child);
                }
            active.swap(next);
        }
        return out_;
    }

private:
    int bucket_x(double x) const { return dist_.clamp(static_cast<int>((x - dist_.box.x0) / cell_x_), gx_); }
    int bucket_y(double y) const { return dist_.clamp(static_cast<int>((y - dist_.box.y0) / cell_y_), gy_); }

    // f(k) for the points k in the buckets within `reach` of (x, y)'s; true
    // as soon as one answers true (a bucket may come twice on a small torus).
    template <class F>
    bool any_near(const pds::Point& c, int reach, const F& f) const {
        const int cx = bucket_x(c.x), cy = bucket_y(c.y);
        for (int i = cx - reach; i <= cx + reach; ++i)
            for (int j = cy - reach; j <= cy + reach; ++j) {
                const int a = dist_.bucket(i, gx_), b = dist_.bucket(j, gy_);
                if (a < 0 || b < 0) continue;
                for (std::size_t k : buckets_[static_cast<std::size_t>(b) * gx_ + a])
                    if (f(k)) return true;
            }
        return false;
    }

    bool covered(const pds::Point& p) const {
        return any_near(p, 1, [&](std::size_t k) { return dist_.d2(p, out_.p[k]) < out_.r[k] * out_.r[k]; });
    }

    // Inside one disk: all four corners within r_k of the same copy of
    // point k, the one nearest the square's centre (a square is far smaller
    // than half a period).
    bool covered_square(const pds::Point& sq, double side) const {
        const pds::Point centre{sq.x + side / 2, sq.y + side / 2};
        return any_near(centre, 2, [&](std::size_t k) {
            const pds::Point q = dist_.copy_near(out_.p[k], centre);
            const double r2 = out_.r[k] * out_.r[k];
            for (int c = 0; c < 4; ++c) {
                const double dx = sq.x + (c & 1) * side - q.x, dy = sq.y + (c >> 1) * side - q.y;
                if (dx * dx + dy * dy > r2) return false;
            }
            return true;
        });
    }

    void add(const pds::Point& p) {
        buckets_[static_cast<std::size_t>(bucket_y(p.y)) * gx_ + bucket_x(p.x)].push_back(out_.p.size());
        out_.p.push_back(p);
        out_.r.push_back(radius_.at(p));
    }

    Distance dist_;
    Radius radius_;
    int gx_ = 1, gy_ = 1;
    double cell_x_ = 0, cell_y_ = 0;
    Pattern out_;
    std::vector<std::vector<std::size_t>> buckets_;
};

template <class Distance, class Radius>
DartThrowing<Distance, Radius> dart_throwing(const Distance& d, const Radius& r) {
    return DartThrowing<Distance, Radius>(d, r);
}

}  // namespace oracle

#endif
