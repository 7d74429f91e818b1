// polygon_coverage.cpp - see polygon_coverage.hpp.
#include "cells/polygon_coverage.hpp"

#include <cstddef>

#include "cells/cell_coverage.hpp"
#include "core/expansion.hpp"

namespace pds {

namespace {

using E = Expansion;

E squared_distance(const Point& p, const Point& q) {
    const E dx = E::diff(p.x, q.x), dy = E::diff(p.y, q.y);
    return dx * dx + dy * dy;
}

// The power of x with respect to (c, rc) minus that with respect to (n, rn):
// at most 0 where c's cell may hold x. Linear in x.
E power_difference(const Point& x, const Point& c, double rc, const Point& n, double rn) {
    return (squared_distance(x, c) - E::product(rc, rc)) - (squared_distance(x, n) - E::product(rn, rn));
}

}  // namespace

bool outline_cell_is_covered_exact(const Point& c, double radius, const std::vector<Point>& ring,
                                   const std::vector<double>& ring_radii, const Box& box,
                                   const Polygon& polygon, const std::vector<std::uint32_t>& edges) {
    const E r2 = E::product(radius, radius);
    const std::size_t k = ring.size();
    std::vector<E> fa(k), fb(k);
    const PolygonRings& rings = polygon.rings();
    for (std::uint32_t e : edges) {
        const Point a = rings.edge_start(e), b = rings.edge_end(e);
        for (std::size_t j = 0; j < k; ++j) {
            fa[j] = power_difference(a, c, radius, ring[j], ring_radii[j]);
            fb[j] = power_difference(b, c, radius, ring[j], ring_radii[j]);
        }
        // The edge's first vertex (every vertex starts an edge that meets the
        // cell's box when it lies in the cell).
        bool a_in_cell = true;
        for (std::size_t j = 0; j < k && a_in_cell; ++j) a_in_cell = fa[j].sign() <= 0;
        if (a_in_cell && (squared_distance(a, c) - r2).sign() > 0) return false;
        // Its crossings with the cell's edges.
        for (std::size_t j = 0; j < k; ++j) {
            const int sa = fa[j].sign(), sb = fb[j].sign();
            if (sa * sb >= 0) continue;  // no crossing strictly inside the edge
            const E d = fa[j] - fb[j];   // the sign of fa[j]
            bool in_cell = true;
            for (std::size_t m = 0; m < k && in_cell; ++m)
                if (m != j) in_cell = (fa[j] * fb[m] - fb[j] * fa[m]).sign() * sa <= 0;
            if (!in_cell) continue;
            const E nx = E::diff(a.x, c.x) * d + fa[j] * E::diff(b.x, a.x);
            const E ny = E::diff(a.y, c.y) * d + fa[j] * E::diff(b.y, a.y);
            if ((nx * nx + ny * ny - r2 * d * d).sign() > 0) return false;
        }
    }
    return power_cell_is_covered_exact(c, radius, ring, ring_radii, box, &polygon);
}

}  // namespace pds
