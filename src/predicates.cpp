// predicates.cpp - filtered predicates with exact fallback (see predicates.hpp).
//
// Error bounds: with u = 2^-53 the unit roundoff, each bound below is a
// conservative forward bound on |computed - exact| for the floating-point
// expression right above it (Shewchuk 1997, "error bound A" style: the bound is
// a small multiple of u times the permanent, i.e. the same expression with
// every term replaced by its absolute value). Bounds are rounded up generously;
// a loose bound only sends a few more calls to the exact path.
#include "predicates.hpp"

#include <cmath>

#include "expansion.hpp"

namespace pds {

namespace {

constexpr double kU = 1.1102230246251565e-16;  // 2^-53
constexpr double kOrientBound = (3.0 + 16.0 * kU) * kU;
constexpr double kInCircleBound = (10.0 + 96.0 * kU) * kU;
constexpr double kDistanceBound = 8.0 * kU;

template <std::size_t N>
int sign_of(const FixedExpansion<N>& e) {
    return e.sign();
}

int orient2d_exact(const Point& a, const Point& b, const Point& c) {
    // (a - c) x (b - c), every difference kept exactly.
    const auto acx = exact_diff(a.x, c.x);
    const auto acy = exact_diff(a.y, c.y);
    const auto bcx = exact_diff(b.x, c.x);
    const auto bcy = exact_diff(b.y, c.y);
    return sign_of(acx * bcy - acy * bcx);
}

int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
    const auto adx = exact_diff(a.x, d.x), ady = exact_diff(a.y, d.y);
    const auto bdx = exact_diff(b.x, d.x), bdy = exact_diff(b.y, d.y);
    const auto cdx = exact_diff(c.x, d.x), cdy = exact_diff(c.y, d.y);
    const auto alift = adx * adx + ady * ady;
    const auto blift = bdx * bdx + bdy * bdy;
    const auto clift = cdx * cdx + cdy * cdy;
    const auto bc = bdx * cdy - cdx * bdy;
    const auto ca = cdx * ady - adx * cdy;
    const auto ab = adx * bdy - bdx * ady;
    return sign_of(alift * bc + blift * ca + clift * ab);
}

// |p - q|^2 as an exact expansion.
FixedExpansion<16> squared_distance_exact(const Point& p, const Point& q) {
    const auto dx = exact_diff(p.x, q.x);
    const auto dy = exact_diff(p.y, q.y);
    return dx * dx + dy * dy;
}

}  // namespace

int orient2d(const Point& a, const Point& b, const Point& c) {
    const double left = (a.x - c.x) * (b.y - c.y);
    const double right = (a.y - c.y) * (b.x - c.x);
    const double det = left - right;
    const double bound = kOrientBound * (std::fabs(left) + std::fabs(right));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return orient2d_exact(a, b, c);
}

int incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double adx = a.x - d.x, ady = a.y - d.y;
    const double bdx = b.x - d.x, bdy = b.y - d.y;
    const double cdx = c.x - d.x, cdy = c.y - d.y;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
    const double bound = kInCircleBound * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return incircle_exact(a, b, c, d);
}

int compare_distance(const Point& p, const Point& q, double r) {
    const double dx = p.x - q.x, dy = p.y - q.y;
    const double d2 = dx * dx + dy * dy;
    const double r2 = r * r;
    const double diff = d2 - r2;
    const double bound = kDistanceBound * (d2 + r2);
    if (diff > bound) return 1;
    if (-diff > bound) return -1;
    return sign_of(squared_distance_exact(p, q) - exact_product(r, r));
}

int compare_closer(const Point& p, const Point& a, const Point& b) {
    const double ax = p.x - a.x, ay = p.y - a.y;
    const double bx = p.x - b.x, by = p.y - b.y;
    const double da = ax * ax + ay * ay;
    const double db = bx * bx + by * by;
    const double diff = da - db;
    const double bound = kDistanceBound * (da + db);
    if (diff > bound) return 1;
    if (-diff > bound) return -1;
    return sign_of(squared_distance_exact(p, a) - squared_distance_exact(p, b));
}

}  // namespace pds
