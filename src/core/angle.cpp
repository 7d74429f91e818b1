// angle.cpp - atan2 from basic operations (see angle.hpp).
//
// Reduction: fold the vector into the first octant (t = min/max in [0, 1]),
// take the nearest tabulated b = i/16, and use
//   atan(t) = atan(b) + atan(w),  w = (t - b) / (1 + t b),  |w| <= 1/32,
// where atan(w) is its Taylor series up to w^15 (truncation below 1e-24).
// The table holds atan(i/16) correctly rounded (computed to 40 digits).
#include "core/angle.hpp"

namespace pds {

namespace {

constexpr double kPi = 3.141592653589793116;
constexpr double kHalfPi = 1.570796326794896558;

constexpr double kAtanTable[17] = {
    0.0,                  // atan(0/16)
    0.06241880999595735,  // atan(1/16)
    0.12435499454676144,  // atan(2/16)
    0.18534794999569476,  // atan(3/16)
    0.24497866312686414,  // atan(4/16)
    0.3028848683749714,   // atan(5/16)
    0.35877067027057225,  // atan(6/16)
    0.4124104415973873,   // atan(7/16)
    0.4636476090008061,   // atan(8/16)
    0.5123894603107377,   // atan(9/16)
    0.5585993153435624,   // atan(10/16)
    0.6022873461349642,   // atan(11/16)
    0.6435011087932844,   // atan(12/16)
    0.6823165548747481,   // atan(13/16)
    0.7188299996216245,   // atan(14/16)
    0.7531512809621944,   // atan(15/16)
    0.7853981633974483,   // atan(16/16)
};

// atan(t) for t in [0, 1].
double atan_unit(double t) {
    const int i = static_cast<int>(t * 16.0 + 0.5);
    const double b = i * 0.0625;  // exact
    const double w = (t - b) / (1.0 + t * b);
    const double w2 = w * w;
    double p = -1.0 / 15.0;
    p = p * w2 + 1.0 / 13.0;
    p = p * w2 - 1.0 / 11.0;
    p = p * w2 + 1.0 / 9.0;
    p = p * w2 - 1.0 / 7.0;
    p = p * w2 + 1.0 / 5.0;
    p = p * w2 - 1.0 / 3.0;
    return kAtanTable[i] + (w + w * (w2 * p));
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
