// polygon_splits.hpp - a polygon's edges split where other edges cross them
// and at the vertices that lie on them, and its rings' vertices merged where
// they lie within rounding of each other.
//
// The even-odd rule makes the inside change sides along an edge where
// another edge crosses it (a bow tie's two lobes, a ring across a hole).
// The sampler measures and covers the region edge by edge, each edge with
// the inside on one side, so edges that cross are split at their crossing
// point: the same point, rounded, ends both pieces of each. Rounding moves
// the pieces off the exact edges by an ulp or so at the crossing (the
// region then differs from the exact one by slivers that thin), and can
// make a new crossing where three edges meet at nearly one point, so
// Polygon splits again until none is left (a few rounds at most).
//
// The even-odd rule cancels the parts of the outline traced an even number
// of times. Copies of one whole segment are found by their ends
// (polygon.cpp); edges that overlap only in part, such as two squares that
// share part of a side and run the same way round, are split first at the
// vertices lying inside them, so their common parts become copies of one
// segment too. Splitting an edge at a point on it changes no point's parity:
// the region stays exactly the same.
//
// Two rings may also meet at vertices a few ulps apart (a corner shared by
// two rings, rounded differently in each). The edges from such a pair may
// run as close as the vertices are for their whole length, and no vertex
// lies inside another's edge, so they are merged: one point for both, the
// edges from it then copies, or split where the other's vertices lie (in
// the next round). Merging moves a vertex by no more than twice the
// near-edge reach.
//
// That reach, 2^-44 of the largest |coordinate|, is 16 times the probes'
// first offset (polygon.cpp): slivers between edges that are left are wider
// than the probes' step at their middles, and wide enough for the sampler's
// draws. At 2^-48 (1.7.5), slivers just wider than the reach still took
// wrong sides or were left uncovered (docs/design.md).
#ifndef PDS_POLYGON_SPLITS_HPP
#define PDS_POLYGON_SPLITS_HPP

#include <cstddef>
#include <vector>

#include "domain/polygon_index.hpp"
#include "domain/polygon_rings.hpp"

namespace pds {

// The rings again, with every vertex that lies strictly inside an edge
// inserted into that edge, in order along it: xy (x y interleaved) and ring
// ends as pds_set_polygon takes them. A vertex within kNearEdge of the
// largest |coordinate| of an edge's line counts as on it (when farther than
// that from its ends): the sides of two edges that run that close together
// cannot be told apart by the probes (polygon.cpp), so the stretch they
// share becomes copies of one segment, which cancel. But first, vertices of
// different rings within twice that of each other are moved to one point,
// the least of them (by x, then y: the result does not depend on the rings'
// order), and nothing is split in that call; groups that would move two
// distinct vertices of one ring, span more than twice the merging reach or
// flatten a ring are left as they are. False, and nothing written, when no
// vertex moves and none lies inside an edge.
constexpr double kNearEdge = 0x1p-44;
bool merge_or_split_at_vertices(const PolygonRings& rings, const PolygonIndex& index, std::vector<double>& xy,
                                std::vector<std::size_t>& ends);

// The rings again, with each pair of edges that cross (each passing
// strictly from one side of the other to the other) split at their
// crossing point, rounded, inserted into both. False, and nothing written,
// when no edges cross. Throws DomainError for rings that cross more than
// kMaxCrossingsPerVertex times their vertex count plus kMaxCrossingsBeyond
// (a scribble of n random vertices crosses itself about n^2 / 10 times:
// splitting that would take time and memory far beyond the rings').
constexpr std::size_t kMaxCrossingsPerVertex = 4;
constexpr std::size_t kMaxCrossingsBeyond = 65536;
bool split_at_crossings(const PolygonRings& rings, const PolygonIndex& index, std::vector<double>& xy,
                        std::vector<std::size_t>& ends);

}  // namespace pds

#endif
