// torus.hpp - the periodic domain's arithmetic (pds_set_periodic).
//
// On the torus a point stands for itself and its copies shifted by whole
// periods. Every exact decision is taken on those copies as plain doubles, so
// they must be exact: points and periods are kept on a grid of 2^-50 in the
// internal frame (coordinates below 2 in magnitude, copies below 8), where
// every sum of a point and a few periods is a double with room to spare.
#ifndef PDS_TORUS_HPP
#define PDS_TORUS_HPP

#include <cmath>

#include "core/point.hpp"

namespace pds {

struct Torus {
    static constexpr double kQuantum = 0x1.0p-50;
    static constexpr double kInverseQuantum = 0x1.0p50;

    double px = 0.0;  // periods; 0 when the domain is a plain rectangle
    double py = 0.0;
    double x0 = 0.0;  // the fundamental domain is [x0, x0+px) x [y0, y0+py)
    double y0 = 0.0;

    bool on() const { return px > 0.0; }

    // The nearest grid value (exact: scaling by powers of two, integer rounding).
    static double snap(double v) { return std::nearbyint(v * kInverseQuantum) * kQuantum; }
    // The largest grid value <= v.
    static double snap_down(double v) { return std::floor(v * kInverseQuantum) * kQuantum; }

    // A grid point within one period of the fundamental domain, moved into it
    // by whole periods (exact on the grid).
    Point wrap(Point p) const {
        if (p.x < x0) p.x += px;
        else if (p.x - px >= x0) p.x -= px;
        if (p.y < y0) p.y += py;
        else if (p.y - py >= y0) p.y -= py;
        return p;
    }
    // The copy of p shifted by (i, j) periods.
    Point shifted(const Point& p, int i, int j) const { return Point{p.x + i * px, p.y + j * py}; }
};

}  // namespace pds

#endif
