// cell_coverage.hpp - exact decision: is a site's Voronoi cell, clipped to the
// domain, inside the disk of radius R around the site?
//
// Used when floating point could not certify a cell (free_area.hpp marks it
// "doubtful") and when sampling a cell keeps failing; never while the mesh is
// being changed (it allocates). Exact rational arithmetic on expansions.
//
// Method: each Voronoi edge of site c and neighbour n lies on the bisector
// P(t) = (c + n)/2 + t * perp(n - c). Its ends are the circumcentres of the two
// triangles on the edge, at rational parameters t = d.(q - n) / (2 (n-c) x d)
// with d = q - c for the third corner q. Intersecting that parameter interval
// with the domain's slabs gives the clipped edge; the cell inside the domain is
// covered exactly when both ends of every clipped edge, and every domain corner
// whose nearest site is c, lie within R of c (the clipped cell is the convex
// hull of those points). Power cells: the same with the power bisector
// P(t) = c + s b + t perp(b), s = (|b|^2 + R_c^2 - R_n^2) / (2 |b|^2).
#ifndef PDS_CELL_COVERAGE_HPP
#define PDS_CELL_COVERAGE_HPP

#include <vector>

#include "core/point.hpp"
#include "domain/polygon.hpp"

namespace pds {

// ring: every Delaunay neighbour of site, counterclockwise (ghosts included).
bool cell_is_covered_exact(const Point& site, const std::vector<Point>& ring, const Box& domain,
                           double radius);

// The same for a power cell: the site's disk has `radius`, neighbour k's
// ring_radii[k] (the regular triangulation's ring). Each Voronoi edge is then
// on the power bisector (circumcentre.hpp), and a corner is in the cell when
// no neighbour has a smaller power there. With equal radii the decision is
// the one above.
// outline: a polygonal domain inside the box, or nullptr. With one, only the
// clipped cell's vertices the domain holds count (Polygon::contains_exact);
// the vertices the outline adds are polygon_coverage.hpp's.
bool power_cell_is_covered_exact(const Point& site, double radius, const std::vector<Point>& ring,
                                 const std::vector<double>& ring_radii, const Box& domain,
                                 const Polygon* outline = nullptr);

}  // namespace pds

#endif
