// angle.hpp - a deterministic arctangent.
//
// Sector areas (R^2 * theta / 2) feed the free-area tree, so their last bit
// decides which point a seed produces. libm's atan2 is not guaranteed to give
// the same last bit across versions and platforms, so we compute the angle
// from IEEE-754 basic operations only (+ - * /), which every conforming
// platform rounds identically. Accuracy: a few ulps, far below what the
// sampler needs.
#ifndef PDS_ANGLE_HPP
#define PDS_ANGLE_HPP

namespace pds {

// The angle of the vector (x, y) in [-pi, pi], like atan2(y, x); 0 for (0, 0).
double angle_of(double y, double x);

}  // namespace pds

#endif
