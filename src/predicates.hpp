// predicates.hpp - robust geometric predicates.
//
// Each predicate returns the exact sign of a polynomial in its double inputs.
// A floating-point evaluation with a forward error bound decides almost every
// call; when the bound cannot separate the value from zero, the polynomial is
// evaluated exactly with fixed-capacity expansions (no allocation, so the
// predicates are safe to call while the mesh is half-updated).
//
// The Jones paper used none ("we have not used robust predicates"); a wrong
// orientation or in-circle sign can corrupt the triangulation, and a wrong
// distance comparison can accept a point closer than R, so every decision the
// sampler's guarantees rest on goes through here.
#ifndef PDS_PREDICATES_HPP
#define PDS_PREDICATES_HPP

//
// The floating-point filters are inline, here: they decide nearly every call
// and sit in the innermost loops (location walks, flips, dart tests), where a
// call costs as much as the arithmetic. The exact evaluations are out of line
// in predicates.cpp.
//
// Error bounds: with u = 2^-53 the unit roundoff, each bound is a conservative
// forward bound on |computed - exact| for the floating-point expression it
// guards (Shewchuk 1997, "error bound A" style: a small multiple of u times
// the permanent, the same expression with every term replaced by its absolute
// value). Bounds are rounded up generously; a loose bound only sends a few
// more calls to the exact path.
#include <cmath>

#include "point.hpp"
#include "roundoff.hpp"

namespace pds {

namespace predicate_detail {

constexpr double kU = kUnitRoundoff;
constexpr double kOrientBound = (3.0 + 16.0 * kU) * kU;
constexpr double kInCircleBound = (10.0 + 96.0 * kU) * kU;
constexpr double kDistanceBound = 8.0 * kU;

int orient2d_exact(const Point& a, const Point& b, const Point& c);
int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);
int compare_distance_exact(const Point& p, const Point& q, double r);
int compare_closer_exact(const Point& p, const Point& a, const Point& b);

}  // namespace predicate_detail

// +1 if a, b, c turn counterclockwise, -1 if clockwise, 0 if collinear.
inline int orient2d(const Point& a, const Point& b, const Point& c) {
    using namespace predicate_detail;
    const double left = (a.x - c.x) * (b.y - c.y);
    const double right = (a.y - c.y) * (b.x - c.x);
    const double det = left - right;
    const double bound = kOrientBound * (std::fabs(left) + std::fabs(right));
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return orient2d_exact(a, b, c);
}

// +1 if d lies inside the circle through a, b, c (given counterclockwise),
// -1 if outside, 0 if on it.
inline int incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
    using namespace predicate_detail;
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

// Sign of |p - q|^2 - r*r, with r*r taken exactly (not rounded).
inline int compare_distance(const Point& p, const Point& q, double r) {
    using namespace predicate_detail;
    const double dx = p.x - q.x, dy = p.y - q.y;
    const double d2 = dx * dx + dy * dy;
    const double r2 = r * r;
    const double diff = d2 - r2;
    const double bound = kDistanceBound * (d2 + r2);
    if (diff > bound) return 1;
    if (-diff > bound) return -1;
    return compare_distance_exact(p, q, r);
}

// Sign of |p - a|^2 - |p - b|^2: -1 when p is strictly closer to a than to b.
inline int compare_closer(const Point& p, const Point& a, const Point& b) {
    using namespace predicate_detail;
    const double ax = p.x - a.x, ay = p.y - a.y;
    const double bx = p.x - b.x, by = p.y - b.y;
    const double da = ax * ax + ay * ay;
    const double db = bx * bx + by * by;
    const double diff = da - db;
    const double bound = kDistanceBound * (da + db);
    if (diff > bound) return 1;
    if (-diff > bound) return -1;
    return compare_closer_exact(p, a, b);
}

}  // namespace pds

#endif
