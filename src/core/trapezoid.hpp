// trapezoid.hpp - a trapezoid between two vertical lines, and a uniform
// point in it: the pieces of a cut cell (cells/region_trapezoids.hpp) and of
// a polygon's slabs (domain/polygon_slabs.hpp).
#ifndef PDS_TRAPEZOID_HPP
#define PDS_TRAPEZOID_HPP

#include <algorithm>
#include <cmath>

#include "core/point.hpp"

namespace pds {

// Between x0 and x1: lower side from lo0 to lo1, upper from hi0 to hi1.
struct Trapezoid {
    double x0, x1, lo0, lo1, hi0, hi1, area;
};

// A uniform point of t from two uniforms in [0, 1): x by the inverse of the
// area's distribution (heights change linearly across), then y uniform.
inline Point point_in_trapezoid(const Trapezoid& t, double u, double v) {
    const double h0 = std::max(0.0, t.hi0 - t.lo0), h1 = std::max(0.0, t.hi1 - t.lo1);
    // s solves h0 s + (h1 - h0) s^2 / 2 = u (h0 + h1) / 2, in the form that
    // never divides by h1 - h0.
    const double root = std::sqrt(h0 * h0 + u * (h1 * h1 - h0 * h0));
    const double s = h0 + root > 0.0 ? u * (h0 + h1) / (h0 + root) : u;
    const double lo = t.lo0 + s * (t.lo1 - t.lo0), hi = t.hi0 + s * (t.hi1 - t.hi0);
    return Point{t.x0 + s * (t.x1 - t.x0), lo + v * (hi - lo)};
}

}  // namespace pds

#endif
