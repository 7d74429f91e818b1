// indices.hpp - the three index spaces of a pattern, and their conversions.
//
//   PointIndex   the user's: the k-th point added, 0-based, what pds_points()
//                and error messages count in. Stable for the sampler's life.
//   VertexIndex  the triangulation's: vertices 0 .. kGhosts-1 are the ghost
//                corners (delaunay.hpp), real sites follow in the order they
//                were inserted into the mesh.
//   SiteIndex    a real vertex counted without the ghosts: the leaf of the
//                free-area tree that holds its cell's weight.
//
// And one number outside the pattern: GridCell, a cell of a dart grid,
// numbered row by row over the padded grid. 64 bits on every target: a grid
// over a wide box (islands far apart) can have more cells than a 32-bit
// size_t counts, and wasm32 must number them as a 64-bit machine does to
// draw the same points.
//
// Site and vertex differ by the ghost count, always: site_of / vertex_of are
// the only conversions. Point and vertex agree (vertex = point + kGhosts)
// except for the points of the dart stage, which enter the mesh in a spatial
// order at the hand-over: JonesStage keeps that map (PointOrder), and it is
// the only place that converts between the user's order and the mesh's.
#ifndef PDS_INDICES_HPP
#define PDS_INDICES_HPP

#include <cstddef>
#include <cstdint>

namespace pds {

using PointIndex = std::size_t;
using VertexIndex = std::uint32_t;
using SiteIndex = std::size_t;
using GridCell = std::uint64_t;

constexpr VertexIndex kGhostVertices = 4;

inline VertexIndex vertex_of(SiteIndex site) { return static_cast<VertexIndex>(site + kGhostVertices); }
inline SiteIndex site_of(VertexIndex v) { return static_cast<SiteIndex>(v - kGhostVertices); }

}  // namespace pds

#endif
