// roundoff.hpp - the unit roundoff of IEEE-754 double arithmetic, defined once.
//
// Every floating-point error bound in the library (the predicates' filters,
// the free-area pipeline's vertex errors, the verifier's float filter) is a
// small multiple of this u = 2^-53: with round-to-nearest, each basic
// operation's result is the exact result times (1 + d), |d| <= u.
#ifndef PDS_ROUNDOFF_HPP
#define PDS_ROUNDOFF_HPP

#include <cmath>
#include <limits>

namespace pds {

constexpr double kUnitRoundoff = 0x1.0p-53;

// x rounded to the nearest multiple of the spacing of doubles at magnitude
// m (0 stays 0; the result is exact).
inline double on_grid_of(double x, double m) {
    if (!(m > 0.0) || !std::isfinite(m)) return x;
    const double h = std::nextafter(m, std::numeric_limits<double>::infinity()) - m;
    return h > 0.0 && std::isfinite(h) ? std::nearbyint(x / h) * h : x;
}

// The double k representable steps from x (k < 0: downwards).
inline double ulps_from(double x, int k) {
    const double inf = std::numeric_limits<double>::infinity();
    for (; k > 0; --k) x = std::nextafter(x, inf);
    for (; k < 0; ++k) x = std::nextafter(x, -inf);
    return x;
}

}  // namespace pds

#endif
