// point.hpp - the plain value types every layer shares: a point and an
// axis-aligned box. Coordinates are doubles in the sampler's internal frame
// (the user's frame scaled by a power of two, see sampler.hpp).
#ifndef PDS_POINT_HPP
#define PDS_POINT_HPP

#include <algorithm>
#include <cmath>

namespace pds {

struct Point {
    double x;
    double y;
};

// Closed rectangle [x0, x1] x [y0, y1] with x0 < x1 and y0 < y1.
struct Box {
    double x0;
    double y0;
    double x1;
    double y1;

    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    bool contains(const Point& p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
    // The diagonal: no two points of the box are farther apart.
    double diagonal() const {
        const double w = width(), h = height();
        return std::sqrt(w * w + h * h);  // not hypot: see delaunay.cpp
    }
    // The largest |coordinate| of the box.
    double largest_magnitude() const {
        return std::max(std::max(std::fabs(x0), std::fabs(x1)), std::max(std::fabs(y0), std::fabs(y1)));
    }
};

}  // namespace pds

#endif
