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

#include "point.hpp"

namespace pds {

// +1 if a, b, c turn counterclockwise, -1 if clockwise, 0 if collinear.
int orient2d(const Point& a, const Point& b, const Point& c);

// +1 if d lies inside the circle through a, b, c (given counterclockwise),
// -1 if outside, 0 if on it.
int incircle(const Point& a, const Point& b, const Point& c, const Point& d);

// Sign of |p - q|^2 - r*r, with r*r taken exactly (not rounded).
int compare_distance(const Point& p, const Point& q, double r);

// Sign of |p - a|^2 - |p - b|^2: -1 when p is strictly closer to a than to b.
int compare_closer(const Point& p, const Point& a, const Point& b);

}  // namespace pds

#endif
