// mesh_checks.hpp - whole-mesh invariant checks for the unit suites: the
// library's own walk (src/mesh_invariants.hpp, also behind pds_verify),
// turned into test assertions, so the tests and the certificate check the
// same invariants.
#ifndef PDS_TEST_MESH_CHECKS_HPP
#define PDS_TEST_MESH_CHECKS_HPP

#include <check.h>

#include <cstddef>

#include "mesh/delaunay.hpp"
#include "mesh/mesh_invariants.hpp"

inline void check_quadedge_algebra(const pds::QuadEdgeMesh& m) {
    const pds::MeshReport rep = pds::check_edge_algebra(m);
    ck_assert_msg(rep.ok, "quad-edge algebra: %s", rep.failure.c_str());
}

// Checks the Delaunay mesh completely; returns the number of triangles.
inline std::size_t check_delaunay_mesh(const pds::Delaunay& dt) {
    const pds::MeshReport rep = pds::check_mesh_invariants(dt);
    ck_assert_msg(rep.ok, "Delaunay mesh: %s", rep.failure.c_str());
    return rep.triangles;
}

#endif
