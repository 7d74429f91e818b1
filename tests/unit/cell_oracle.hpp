// cell_oracle.hpp - brute-force references for one Voronoi cell, independent
// of the mesh: the cell is the set of domain points at least as close to the
// site as to every other point, found by scanning all points.
#ifndef PDS_TEST_CELL_ORACLE_HPP
#define PDS_TEST_CELL_ORACLE_HPP

#include <cmath>
#include <limits>
#include <vector>

#include "core/point.hpp"

// Distance from the site along direction (ux, uy) to the boundary of its
// clipped cell, over all `others` (which may include the site itself).
inline double cell_reach(const pds::Point& c, double ux, double uy, const std::vector<pds::Point>& others,
                         const pds::Box& box) {
    double t = std::numeric_limits<double>::infinity();
    if (ux > 0) t = std::min(t, (box.x1 - c.x) / ux);
    if (ux < 0) t = std::min(t, (box.x0 - c.x) / ux);
    if (uy > 0) t = std::min(t, (box.y1 - c.y) / uy);
    if (uy < 0) t = std::min(t, (box.y0 - c.y) / uy);
    for (const pds::Point& s : others) {
        const double dx = s.x - c.x, dy = s.y - c.y;
        const double along = ux * dx + uy * dy;
        if (along > 0 && (dx != 0 || dy != 0)) t = std::min(t, (dx * dx + dy * dy) / (2 * along));
    }
    return t;
}

// Free area of the site's cell by polar integration: the integral over angle
// of (reach^2 - R^2)_+ / 2, midpoint rule with `steps` angles.
inline double free_area_by_integration(const pds::Point& c, const std::vector<pds::Point>& others,
                                       const pds::Box& box, double r, int steps) {
    const double pi = 3.14159265358979323846;
    long double sum = 0;
    for (int i = 0; i < steps; ++i) {
        const double phi = (i + 0.5) * 2 * pi / steps;
        const double reach = cell_reach(c, std::cos(phi), std::sin(phi), others, box);
        if (reach > r) sum += 0.5L * ((long double)reach * reach - (long double)r * r);
    }
    return static_cast<double>(sum * (2 * pi / steps));
}

// Is p (in the box) free: at least R from all points, and in c's cell?
inline bool in_free_region_of(const pds::Point& p, const pds::Point& c, const std::vector<pds::Point>& pts,
                              double r) {
    const double dc = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
    if (dc < r * r) return false;
    for (const pds::Point& s : pts) {
        const double d = (p.x - s.x) * (p.x - s.x) + (p.y - s.y) * (p.y - s.y);
        if (d < dc) return false;
    }
    return true;
}

#endif
