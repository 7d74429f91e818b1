// mesh_invariants.hpp - the one walk that checks a Delaunay mesh whole.
//
// Shared by the verifier (pds_verify) and the unit tests, so the invariants
// the tests prove are the ones a user's certificate re-checks:
//   - quad-edge algebra on every live quarter: rot^4 = sym^2 = id, onext and
//     oprev inverse, lnext and lprev inverse, the duality
//     rot(onext(rot(onext(e)))) == e, links only to live records;
//   - every ring holds one origin, and each vertex's entry edge starts at it;
//   - faces: one quadrilateral outside the ghosts, every other face a
//     counterclockwise triangle, and Euler's formula V - E + F = 2;
//   - every edge between two triangles locally Delaunay (empty circle), which
//     with the above makes the whole mesh Delaunay.
// O(records) time and one byte per quarter of scratch.
#ifndef PDS_MESH_INVARIANTS_HPP
#define PDS_MESH_INVARIANTS_HPP

#include <cstddef>
#include <string>

#include "mesh/delaunay.hpp"

namespace pds {

struct MeshReport {
    bool ok = true;
    std::string failure;        // which invariant failed, when !ok
    std::size_t triangles = 0;  // inner faces, when ok
};

// The quad-edge algebra alone, on any mesh (the first item above).
MeshReport check_edge_algebra(const QuadEdgeMesh& m);
// Everything above.
MeshReport check_mesh_invariants(const Delaunay& dt);

}  // namespace pds

#endif
