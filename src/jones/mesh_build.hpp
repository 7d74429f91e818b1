// mesh_build.hpp - how the hand-over makes the Jones stage's mesh.
#ifndef PDS_MESH_BUILD_HPP
#define PDS_MESH_BUILD_HPP

namespace pds {

// How the hand-over makes the mesh: by inserting the points one by one in
// the order given, or whole (Delaunay::build_whole, its parts side by side on
// the stage's threads). The same mesh either way, but not the same records,
// so not the same later points: a dart stage keeps to one. The plane builds
// whole without a field, and with fixed points (all other points of one
// radius) the others whole, then the fixed ones inserted; the others insert.
enum class MeshBuild { insert, whole };

}  // namespace pds

#endif
