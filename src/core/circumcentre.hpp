// circumcentre.hpp - the circumcentre of a Delaunay triangle (a Voronoi
// vertex), defined once, in the forms the library needs.
//
// For the counterclockwise triangle (a, a + b, a + d):
//     centre = a + (nx, ny) / den,  nx = d.y |b|^2 - b.y |d|^2,
//                                   ny = b.x |d|^2 - d.x |b|^2,
//                                   den = 2 (b x d) > 0.
// On the bisector of a and a + b, P(t) = a + b/2 + t perp(b) with
// perp(b) = (-b.y, b.x), the centre sits at t = d . (d - b) / den
// (substitute: perp(b) . (nx, ny) = |b|^2 (|d|^2 - b . d)).
//
//   relative_circumcentre   floating point, relative to a, with a forward
//                           error bound: the free-area pipeline and the
//                           verifier's filter
//   exact_circumcentre      exact numerators and denominator (expansions):
//                           the verifier's exact decision
//   bisector_parameter      t above as an exact rational: the exact coverage
//                           test, which works along Voronoi edges
#ifndef PDS_CIRCUMCENTRE_HPP
#define PDS_CIRCUMCENTRE_HPP

#include <cmath>

#include "core/expansion.hpp"
#include "core/point.hpp"
#include "core/roundoff.hpp"
#include "core/vec.hpp"

namespace pds {

// A circumcentre relative to the triangle's first corner, with a bound on
// the absolute error of x and y, and x^2 + y^2 (both users need it).
struct RelativeCentre {
    double x;
    double y;
    double err;
    double d2;
};

// Throws std::logic_error: a broken mesh invariant.
[[noreturn]] void degenerate_triangle();

// Centre of the counterclockwise triangle (0, b, d). Inline: it runs for
// every neighbour of every cell the sampler looks at.
inline RelativeCentre relative_circumcentre(const Point& b, const Point& d) {
    const double bb = b.x * b.x + b.y * b.y, dd = d.x * d.x + d.y * d.y;
    const double cr = cross(b, d);
    // Delaunay triangles around a site are counterclockwise, and with points
    // at least R apart inside the ghost square their angles stay far from 0.
    if (!(cr > 0.0) || !(cr < 1e300)) degenerate_triangle();
    const double inv = 0.5 / cr;
    const double vx = (d.y * bb - b.y * dd) * inv;
    const double vy = (b.x * dd - d.x * bb) * inv;
    // Forward error: the circumcentre's sensitivity to rounding of b and d and
    // of the arithmetic is below ~(|b|+|d|)^2 / |b x d| ulps of its distance;
    // 256 is a generous constant.
    const double err = 256.0 * kUnitRoundoff * (bb + dd) * inv * (std::fabs(vx) + std::fabs(vy));
    return RelativeCentre{vx, vy, err, vx * vx + vy * vy};
}

// The power centre (a vertex of the power diagram) of the counterclockwise
// triangle (0, b, d) of disks: the point of equal power to the three. wb and
// wd are the site's squared radius minus b's and d's: with them the formula
// is the circumcentre's with |b|^2 + wb and |d|^2 + wd in place of |b|^2
// and |d|^2 (2 v.b = |b|^2 + wb). With zero offsets it is the circumcentre,
// bit for bit. The centre may lie anywhere, even at the site, so its error
// is bounded from the inputs' sizes, not from its distance.
inline RelativeCentre relative_power_centre(const Point& b, const Point& d, double wb, double wd) {
    if (wb == 0.0 && wd == 0.0) return relative_circumcentre(b, d);
    const double bb = b.x * b.x + b.y * b.y, dd = d.x * d.x + d.y * d.y;
    const double cr = cross(b, d);
    if (!(cr > 0.0) || !(cr < 1e300)) degenerate_triangle();
    const double inv = 0.5 / cr;
    const double bw = bb + wb, dw = dd + wd;
    const double vx = (d.y * bw - b.y * dw) * inv;
    const double vy = (b.x * dw - d.x * bw) * inv;
    const double size = std::fabs(b.x) + std::fabs(b.y) + std::fabs(d.x) + std::fabs(d.y);
    const double err = 256.0 * kUnitRoundoff * inv *
                       ((bb + dd) * (std::fabs(vx) + std::fabs(vy)) +
                        size * (bb + dd + std::fabs(wb) + std::fabs(wd)));
    return RelativeCentre{vx, vy, err, vx * vx + vy * vy};
}

// Exact centre of the counterclockwise triangle (a, b, c): a + (nx, ny) / den.
struct ExactCentre {
    Expansion nx;
    Expansion ny;
    Expansion den;  // > 0 for a counterclockwise triangle
};
ExactCentre exact_circumcentre(const Point& a, const Point& b, const Point& c);
// Exact power centre of the counterclockwise disks (a, ra), (b, rb), (c, rc),
// in the same form; with equal radii the circumcentre.
ExactCentre exact_power_centre(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc);

// Exact parameter of the centre of (a, b, c) on the bisector of a and b.
Rational bisector_parameter(const Point& a, const Point& b, const Point& c);

// The power bisector of disks (a, ra) and (b, rb), with e = b - a:
// P(t) = a + s e + t perp(e), s = (|e|^2 + ra^2 - rb^2) / (2 |e|^2); with
// equal radii the bisector above (s = 1/2). Exact parameter of the power
// centre of the disks (a, b, c) on it.
Rational power_bisector_parameter(const Point& a, double ra, const Point& b, double rb, const Point& c,
                                  double rc);

}  // namespace pds

#endif
