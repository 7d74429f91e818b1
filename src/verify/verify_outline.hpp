// verify_outline.hpp - the part of the certificate a polygonal domain adds
// (verify.hpp): every cell the outline may meet, cut by it, lies in its disk.
//
// The pattern is maximal in the polygon when no point of it is uncovered;
// the farthest point from the disks lies at a Voronoi (power) vertex inside
// the polygon (verify.cpp checks those), at an outline vertex, or where the
// outline crosses a cell's edge. The last two are decided, with the cell's
// own vertices, exactly for each cell whose box the outline's grid does not
// call inside (polygon_coverage.hpp), from the points and the mesh alone.
#ifndef PDS_VERIFY_OUTLINE_HPP
#define PDS_VERIFY_OUTLINE_HPP

#include <string>

#include "core/indices.hpp"
#include "domain/polygon.hpp"
#include "mesh/delaunay.hpp"

namespace pds {

// r: the radius (every vertex's own on a weighted mesh). Returns the first
// vertex whose cut cell is not covered, or kNoVertex.
VertexIndex uncovered_outline_cell(const Delaunay& dt, const Polygon& polygon, double r);

}  // namespace pds

#endif
