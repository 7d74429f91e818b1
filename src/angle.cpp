// angle.cpp - atan2 from basic operations (see angle.hpp).
//
// Reduction: fold the vector into the first octant (t = min/max in [0, 1]),
// then use atan(t) = pi/4 + atan((t - 1)/(t + 1)) for t > tan(pi/8), and
// atan(z) = pi/8 + atan((z - c)/(1 + z c)) with c = tan(pi/8) for
// z > tan(pi/16). The remaining |w| <= tan(pi/16) ~ 0.199 is summed as the
// Taylor series up to w^27, whose truncation error is below 1e-19.
#include "angle.hpp"

namespace pds {

namespace {

constexpr double kPi = 3.141592653589793116;
constexpr double kHalfPi = 1.570796326794896558;
constexpr double kQuarterPi = 0.7853981633974482790;
constexpr double kEighthPi = 0.3926990816987241395;
constexpr double kTanEighthPi = 0.4142135623730950488;
constexpr double kTanSixteenthPi = 0.1989123673796580;

// atan(w) for |w| <= tan(pi/16), Taylor series in Horner form.
double atan_small(double w) {
    const double w2 = w * w;
    double p = -1.0 / 27.0;
    p = p * w2 + 1.0 / 25.0;
    p = p * w2 - 1.0 / 23.0;
    p = p * w2 + 1.0 / 21.0;
    p = p * w2 - 1.0 / 19.0;
    p = p * w2 + 1.0 / 17.0;
    p = p * w2 - 1.0 / 15.0;
    p = p * w2 + 1.0 / 13.0;
    p = p * w2 - 1.0 / 11.0;
    p = p * w2 + 1.0 / 9.0;
    p = p * w2 - 1.0 / 7.0;
    p = p * w2 + 1.0 / 5.0;
    p = p * w2 - 1.0 / 3.0;
    return w + w * (w2 * p);
}

// atan(z) for |z| <= tan(pi/8) (plus rounding).
double atan_eighth(double z) {
    const bool negative = z < 0.0;
    const double a = negative ? -z : z;
    double r;
    if (a > kTanSixteenthPi) {
        r = kEighthPi + atan_small((a - kTanEighthPi) / (1.0 + a * kTanEighthPi));
    } else {
        r = atan_small(a);
    }
    return negative ? -r : r;
}

// atan(t) for t in [0, 1].
double atan_unit(double t) {
    if (t > kTanEighthPi) return kQuarterPi + atan_eighth((t - 1.0) / (t + 1.0));
    return atan_eighth(t);
}

}  // namespace

double angle_of(double y, double x) {
    const double ax = x < 0.0 ? -x : x;
    const double ay = y < 0.0 ? -y : y;
    if (ax == 0.0 && ay == 0.0) return 0.0;
    double a = ay <= ax ? atan_unit(ay / ax) : kHalfPi - atan_unit(ax / ay);
    if (x < 0.0) a = kPi - a;
    return y < 0.0 ? -a : a;
}

}  // namespace pds
