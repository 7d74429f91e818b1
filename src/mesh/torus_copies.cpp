// torus_copies.cpp - margins and the disk invariant (see torus_copies.hpp).
#include "mesh/torus_copies.hpp"

#include <algorithm>
#include <cmath>

#include "core/circumcentre.hpp"
#include "core/roundoff.hpp"
#include "core/vec.hpp"

namespace pds {

namespace {
// The first margin, in radii: after the dart stage the largest empty circle
// is a little over R, so its disk reaches about 2R beyond its site.
constexpr double kFirstMargin = 4.0;
}  // namespace

TorusCopies::TorusCopies(const Torus& t, double r, bool weighted)
    : torus_(t), weighted_(weighted), rmax_(weighted ? r : 0.0) {
    const double diagonal = std::sqrt(t.px * t.px + t.py * t.py);
    // The diagonal always suffices (1.21 diagonals with a variable radius);
    // a little more absorbs the rounding of the test.
    max_margin_ = (weighted ? 1.25 : 1.01) * diagonal;
    margin_ = first_margin_ = std::min(kFirstMargin * r, max_margin_);
    max_i_ = static_cast<int>(std::ceil(max_margin_ / t.px)) + 1;
    max_j_ = static_cast<int>(std::ceil(max_margin_ / t.py)) + 1;
}

double TorusCopies::next_margin() const { return std::min(2.0 * margin_, max_margin_); }

std::size_t TorusCopies::max_copies() const {
    const std::size_t ni = static_cast<std::size_t>(std::ceil(margin_ / torus_.px)) + 1;
    const std::size_t nj = static_cast<std::size_t>(std::ceil(margin_ / torus_.py)) + 1;
    return (2 * ni + 1) * (2 * nj + 1) - 1;
}

double TorusCopies::copies_per_point() const {
    const double a = torus_.px * torus_.py;
    const double e = (torus_.px + 2.0 * margin_) * (torus_.py + 2.0 * margin_);
    return e / a - 1.0;
}

bool TorusCopies::disk_inside(const Point& c, const Point& a, const Point& b, const Box& e) {
    const Point ra{a.x - c.x, a.y - c.y}, rb{b.x - c.x, b.y - c.y};
    // A ghost corner or a sliver: its disk is huge, or unsure; not inside.
    const double cr = cross(ra, rb);
    if (!(cr > 0.0)) return false;
    const RelativeCentre v = relative_circumcentre(ra, rb);
    if (!std::isfinite(v.d2)) return false;
    const double rho = std::sqrt(v.d2);
    // Bounds on the rounding: of the centre (v.err), of the root and of the
    // sums below (relative, generous).
    const double slack = 2.0 * v.err + 16.0 * kUnitRoundoff * (rho + std::fabs(c.x) + std::fabs(c.y) +
                                                                 std::fabs(e.x0) + std::fabs(e.x1) +
                                                                 std::fabs(e.y0) + std::fabs(e.y1));
    const double x = c.x + v.x, y = c.y + v.y, reach = rho + slack;
    return x - reach >= e.x0 && x + reach <= e.x1 && y - reach >= e.y0 && y + reach <= e.y1;
}

bool TorusCopies::conflict_disk_inside(const Point& c, double rc, const Point& a, double ra, const Point& b,
                                       double rb, const Box& e) const {
    const Point pa{a.x - c.x, a.y - c.y}, pb{b.x - c.x, b.y - c.y};
    const double cr = cross(pa, pb);
    if (!(cr > 0.0)) return false;
    const RelativeCentre v = relative_power_centre(pa, pb, (rc - ra) * (rc + ra), (rc - rb) * (rc + rb));
    if (!std::isfinite(v.d2)) return false;
    // rho^2 = pi + rmax^2 = |w - c|^2 - rc^2 + rmax^2 >= 0.
    const double rho2 = v.d2 - rc * rc + rmax_ * rmax_;
    const double rho = std::sqrt(rho2 > 0.0 ? rho2 : 0.0);
    // Rounding: of the centre, carried into rho^2 (and through the root,
    // which can magnify it near 0), and of the sums below.
    const double d = std::sqrt(v.d2);
    const double err2 = 2.0 * d * v.err + v.err * v.err + 8.0 * kUnitRoundoff * (v.d2 + rc * rc + rmax_ * rmax_);
    const double slack = 2.0 * v.err + std::sqrt(err2) +
                         16.0 * kUnitRoundoff * (rho + std::fabs(c.x) + std::fabs(c.y) + std::fabs(e.x0) +
                                                 std::fabs(e.x1) + std::fabs(e.y0) + std::fabs(e.y1));
    const double x = c.x + v.x, y = c.y + v.y, reach = rho + slack;
    return x - reach >= e.x0 && x + reach <= e.x1 && y - reach >= e.y0 && y + reach <= e.y1;
}

double TorusCopies::ring_overshoot(const Delaunay& dt, VertexIndex v) const {
    // The disks' boxes against the fundamental domain, with the same slack
    // as the tests above (a margin of 2x this is used, so generous is fine).
    const Point& c = dt.point(v);
    const double rc = dt.radius(v);
    const double x1 = torus_.x0 + torus_.px, y1 = torus_.y0 + torus_.py;
    double worst = 0.0;
    VertexIndex first = 0, prev = 0;
    int n = 0;
    const auto triangle = [&](VertexIndex a, VertexIndex b) {
        if (Delaunay::is_ghost(a) || Delaunay::is_ghost(b)) {
            worst = INFINITY;
            return;
        }
        const Point pa{dt.point(a).x - c.x, dt.point(a).y - c.y}, pb{dt.point(b).x - c.x, dt.point(b).y - c.y};
        const double ra = dt.radius(a), rb = dt.radius(b);
        const RelativeCentre w = weighted_ ? relative_power_centre(pa, pb, (rc - ra) * (rc + ra), (rc - rb) * (rc + rb))
                                           : relative_circumcentre(pa, pb);
        const double rho2 = weighted_ ? w.d2 - rc * rc + rmax_ * rmax_ : w.d2;
        const double rho = std::sqrt(rho2 > 0.0 ? rho2 : 0.0) * (1.0 + 0x1.0p-30) + 4.0 * w.err + 0x1.0p-40;
        const double x = c.x + w.x, y = c.y + w.y;
        worst = std::max({worst, torus_.x0 - (x - rho), x + rho - x1, torus_.y0 - (y - rho), y + rho - y1});
    };
    dt.for_each_neighbour(v, [&](VertexIndex nb) {
        if (n++ == 0) first = nb;
        else triangle(prev, nb);
        prev = nb;
    });
    if (n >= 2) triangle(prev, first);
    return worst;
}

}  // namespace pds
