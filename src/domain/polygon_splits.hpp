// polygon_splits.hpp - a polygon's edges split at the vertices that lie on
// them.
//
// The even-odd rule cancels the parts of the outline traced an even number
// of times. Copies of one whole segment are found by their ends
// (polygon.cpp); edges that overlap only in part, such as two squares that
// share part of a side and run the same way round, are split first at the
// vertices lying inside them, so their common parts become copies of one
// segment too. Splitting an edge at a point on it changes no point's parity:
// the region stays exactly the same.
#ifndef PDS_POLYGON_SPLITS_HPP
#define PDS_POLYGON_SPLITS_HPP

#include <cstddef>
#include <vector>

#include "domain/polygon_index.hpp"
#include "domain/polygon_rings.hpp"

namespace pds {

// The rings again, with every vertex that lies strictly inside an edge
// (exactly) inserted into that edge, in order along it: xy (x y
// interleaved) and ring ends as pds_set_polygon takes them. False, and
// nothing written, when no vertex lies inside an edge.
bool split_at_vertices_on_edges(const PolygonRings& rings, const PolygonIndex& index, std::vector<double>& xy,
                                std::vector<std::size_t>& ends);

}  // namespace pds

#endif
