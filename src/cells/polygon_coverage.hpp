// polygon_coverage.hpp - exact decision: does a site's cell, clipped to a
// polygonal domain, lie in the site's disk?
//
// The clipped region is bounded by segments, so it lies in the (convex)
// disk exactly when every vertex of it does. Its vertices are of three
// kinds, each decided with expansions:
//   - the cell's own vertices (clipped to the box) that the domain holds:
//     cell_coverage.hpp, asking Polygon::contains_exact;
//   - the outline's vertices inside the closed cell: at least as close, by
//     power, to the site as to every neighbour;
//   - where an outline edge crosses a cell edge: the edge's ends lie on
//     either side of the neighbour's power bisector, the crossing a + s
//     (b - a) with s = f(a) / (f(a) - f(b)) for the bisector's (linear)
//     power difference f, checked against the other neighbours through the
//     same interpolation of their f.
// Power cells (a variable radius) and Voronoi cells (equal radii) alike.
#ifndef PDS_POLYGON_COVERAGE_HPP
#define PDS_POLYGON_COVERAGE_HPP

#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "domain/polygon.hpp"

namespace pds {

// ring and ring_radii as power_cell_is_covered_exact takes them; edges: the
// outline edges that may meet the cell (at least every one that does).
bool outline_cell_is_covered_exact(const Point& site, double radius, const std::vector<Point>& ring,
                                   const std::vector<double>& ring_radii, const Box& box,
                                   const Polygon& polygon, const std::vector<std::uint32_t>& edges);

}  // namespace pds

#endif
