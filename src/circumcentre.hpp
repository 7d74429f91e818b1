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

#include "expansion.hpp"
#include "point.hpp"
#include "roundoff.hpp"
#include "vec.hpp"

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

// Exact centre of the counterclockwise triangle (a, b, c): a + (nx, ny) / den.
struct ExactCentre {
    Expansion nx;
    Expansion ny;
    Expansion den;  // > 0 for a counterclockwise triangle
};
ExactCentre exact_circumcentre(const Point& a, const Point& b, const Point& c);

// Exact parameter of the centre of (a, b, c) on the bisector of a and b.
Rational bisector_parameter(const Point& a, const Point& b, const Point& c);

}  // namespace pds

#endif
