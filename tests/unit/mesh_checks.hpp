// mesh_checks.hpp - whole-mesh invariant checks shared by the unit suites:
// quad-edge algebra, Euler's formula, counterclockwise triangles, and the
// empty-circle property on every edge (locally Delaunay everywhere plus a valid
// triangulation implies globally Delaunay).
#ifndef PDS_TEST_MESH_CHECKS_HPP
#define PDS_TEST_MESH_CHECKS_HPP

#include <check.h>

#include <cstdint>
#include <vector>

#include "delaunay.hpp"
#include "predicates.hpp"

inline void check_quadedge_algebra(const pds::QuadEdgeMesh& m) {
    using Q = pds::QuadEdgeMesh;
    for (std::size_t r = 0; r < m.record_count(); ++r) {
        if (!m.is_live(r)) continue;
        for (std::uint32_t k = 0; k < 4; ++k) {
            const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * r + k);
            ck_assert_uint_eq(Q::rot(Q::rot(Q::rot(Q::rot(e)))), e);
            ck_assert_uint_eq(Q::sym(Q::sym(e)), e);
            ck_assert_uint_eq(Q::rot(m.onext(Q::rot(m.onext(e)))), e);
            ck_assert_uint_eq(m.onext(m.oprev(e)), e);
            ck_assert_uint_eq(m.oprev(m.onext(e)), e);
            ck_assert_uint_eq(m.lnext(m.lprev(e)), e);
            ck_assert(m.is_live(m.onext(e) >> 2));
        }
        const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * r);
        // Every edge of a vertex ring starts at that vertex.
        ck_assert_uint_eq(m.org(m.onext(e)), m.org(e));
        ck_assert_uint_eq(m.org(m.onext(Q::sym(e))), m.dest(e));
    }
}

// Checks the Delaunay mesh completely; returns the number of triangles.
inline std::size_t check_delaunay_mesh(const pds::Delaunay& dt) {
    using Q = pds::QuadEdgeMesh;
    const pds::QuadEdgeMesh& m = dt.mesh();
    check_quadedge_algebra(m);
    const std::size_t v = dt.vertex_count();
    for (std::uint32_t i = 0; i < v; ++i) ck_assert_uint_eq(m.org(dt.edge_of(i)), i);

    // Faces: lnext cycles over primal edges. Exactly one is the outer square
    // (the four ghosts, clockwise from inside); all others are CCW triangles.
    std::vector<char> seen(4 * m.record_count(), 0);
    std::size_t faces = 0, triangles = 0, outer = 0, edges = 0;
    for (std::size_t r = 0; r < m.record_count(); ++r) {
        if (!m.is_live(r)) continue;
        ++edges;
        for (std::uint32_t k = 0; k < 4; k += 2) {
            const pds::EdgeRef start = static_cast<pds::EdgeRef>(4 * r + k);
            if (seen[start]) continue;
            ++faces;
            std::size_t len = 0;
            pds::EdgeRef e = start;
            do {
                seen[e] = 1;
                e = m.lnext(e);
                ++len;
                ck_assert_uint_le(len, 4);
            } while (e != start);
            if (len == 4) {
                ++outer;
                continue;
            }
            ck_assert_uint_eq(len, 3);
            ++triangles;
            const pds::Point& a = dt.point(m.org(start));
            const pds::Point& b = dt.point(m.dest(start));
            const pds::Point& c = dt.point(m.dest(m.lnext(start)));
            ck_assert_int_eq(pds::orient2d(a, b, c), 1);
        }
    }
    ck_assert_uint_eq(outer, 1);
    // Euler: V - E + F == 2 for a connected planar map.
    ck_assert_uint_eq(v + faces, edges + 2);
    ck_assert_uint_eq(edges, m.live_count());

    // Empty circles: for each edge with triangles on both sides, the far corner
    // of one side is not strictly inside the other side's circumcircle.
    for (std::size_t r = 0; r < m.record_count(); ++r) {
        if (!m.is_live(r)) continue;
        const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * r);
        const pds::EdgeRef s = Q::sym(e);
        if (m.lnext(m.lnext(m.lnext(e))) != e || m.lnext(m.lnext(m.lnext(s))) != s) continue;
        const pds::Point& a = dt.point(m.org(e));
        const pds::Point& b = dt.point(m.dest(e));
        const pds::Point& c = dt.point(m.dest(m.lnext(e)));
        const pds::Point& d = dt.point(m.dest(m.lnext(s)));
        ck_assert_int_le(pds::incircle(a, b, c, d), 0);
    }
    return triangles;
}

#endif
