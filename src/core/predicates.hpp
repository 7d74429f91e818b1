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

#include "core/point.hpp"
#include "core/roundoff.hpp"

namespace pds {

namespace predicate_detail {

constexpr double kU = kUnitRoundoff;
constexpr double kOrientBound = (3.0 + 16.0 * kU) * kU;
constexpr double kInCircleBound = (10.0 + 96.0 * kU) * kU;
constexpr double kDistanceBound = 8.0 * kU;
// The weighted forms add the squared radii (one more rounding each, and the
// difference of two) to every lifted coordinate: a looser constant.
constexpr double kPowerTestBound = (24.0 + 256.0 * kU) * kU;
constexpr double kPowerBound = 12.0 * kU;

int orient2d_exact(const Point& a, const Point& b, const Point& c);
int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);
int compare_distance_exact(const Point& p, const Point& q, double r);
int compare_closer_exact(const Point& p, const Point& a, const Point& b);
int power_test_exact(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                     const Point& d, double rd);
int compare_power_exact(const Point& p, const Point& a, double ra, const Point& b, double rb);

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

// The weighted forms (the power diagram of disks, variable radius). A disk
// (x, r) is lifted to (x, |x|^2 - r^2); its power at a point p is
// |p - x|^2 - r^2, and the power diagram is the projection of the lower hull
// of the lifted points (the regular triangulation is its dual). Radii enter
// squared, and exactly in the exact path. Equal radii give the unweighted
// predicates' signs, bit for bit: the weights' differences are then 0.

// +1 if the lifted d lies strictly below the plane through the lifted a, b, c
// (a, b, c counterclockwise): d conflicts with the triangle, as a point
// strictly inside the circumcircle does; -1 if above, 0 if on it.
inline int power_test(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                      const Point& d, double rd) {
    using namespace predicate_detail;
    const double adx = a.x - d.x, ady = a.y - d.y;
    const double bdx = b.x - d.x, bdy = b.y - d.y;
    const double cdx = c.x - d.x, cdy = c.y - d.y;
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double rd2 = rd * rd;
    const double ra2 = ra * ra, rb2 = rb * rb, rc2 = rc * rc;
    const double alift = adx * adx + ady * ady - (ra2 - rd2);
    const double blift = bdx * bdx + bdy * bdy - (rb2 - rd2);
    const double clift = cdx * cdx + cdy * cdy - (rc2 - rd2);
    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double aabs = adx * adx + ady * ady + ra2 + rd2;
    const double babs = bdx * bdx + bdy * bdy + rb2 + rd2;
    const double cabs = cdx * cdx + cdy * cdy + rc2 + rd2;
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * aabs +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * babs +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * cabs;
    const double bound = kPowerTestBound * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    return power_test_exact(a, ra, b, rb, c, rc, d, rd);
}

// Sign of pow_a(p) - pow_b(p) = (|p - a|^2 - ra^2) - (|p - b|^2 - rb^2): -1
// when p is strictly nearer disk a in power (inside a's power cell, not b's).
inline int compare_power(const Point& p, const Point& a, double ra, const Point& b, double rb) {
    using namespace predicate_detail;
    const double ax = p.x - a.x, ay = p.y - a.y;
    const double bx = p.x - b.x, by = p.y - b.y;
    const double da = ax * ax + ay * ay;
    const double db = bx * bx + by * by;
    const double ra2 = ra * ra, rb2 = rb * rb;
    const double diff = (da - db) - (ra2 - rb2);
    const double bound = kPowerBound * (da + db + ra2 + rb2);
    if (diff > bound) return 1;
    if (-diff > bound) return -1;
    return compare_power_exact(p, a, ra, b, rb);
}

}  // namespace pds

#endif
