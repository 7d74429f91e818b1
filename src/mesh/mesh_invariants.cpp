// mesh_invariants.cpp - the whole-mesh check (see mesh_invariants.hpp).
#include "mesh/mesh_invariants.hpp"

#include <cstdint>
#include <vector>

#include "core/predicates.hpp"

namespace pds {

namespace {

using Q = QuadEdgeMesh;

bool fail(MeshReport& rep, const char* what) {
    rep.ok = false;
    rep.failure = what;
    return false;
}

bool algebra_holds(const QuadEdgeMesh& m, MeshReport& rep) {
    const std::size_t records = m.record_count();
    for (std::size_t r = 0; r < records; ++r) {
        if (!m.is_live(r)) continue;
        for (std::uint32_t k = 0; k < 4; ++k) {
            const EdgeRef e = static_cast<EdgeRef>(4 * r + k);
            const EdgeRef n = m.onext(e);
            if ((n >> 2) >= records || !m.is_live(n >> 2))
                return fail(rep, "the quad-edge structure links to a dead edge");
            if (Q::rot(Q::rot(Q::rot(Q::rot(e)))) != e || Q::sym(Q::sym(e)) != e ||
                Q::rot(m.onext(Q::rot(n))) != e || m.onext(m.oprev(e)) != e ||
                m.oprev(n) != e || m.lnext(m.lprev(e)) != e)
                return fail(rep, "the quad-edge structure is inconsistent");
        }
        const EdgeRef e = static_cast<EdgeRef>(4 * r);
        if (m.org(m.onext(e)) != m.org(e) || m.org(m.onext(Q::sym(e))) != m.dest(e))
            return fail(rep, "a vertex ring mixes origins");
    }
    return true;
}

bool faces_hold(const Delaunay& dt, MeshReport& rep) {
    const QuadEdgeMesh& m = dt.mesh();
    const std::size_t records = m.record_count();
    std::vector<std::uint8_t> seen(4 * records, 0);
    std::size_t faces = 0, outer = 0, triangles = 0;
    for (std::size_t r = 0; r < records; ++r) {
        if (!m.is_live(r)) continue;
        for (std::uint32_t k = 0; k < 4; k += 2) {
            const EdgeRef start = static_cast<EdgeRef>(4 * r + k);
            if (seen[start]) continue;
            ++faces;
            std::size_t sides = 0;
            EdgeRef e = start;
            do {
                seen[e] = 1;
                e = m.lnext(e);
                ++sides;
            } while (e != start && sides <= 4);
            if (e != start || sides < 3) return fail(rep, "a face of the mesh is not a triangle");
            if (sides == 4) {
                ++outer;
                continue;
            }
            ++triangles;
            const Point& a = dt.point(m.org(start));
            const Point& b = dt.point(m.dest(start));
            const Point& c = dt.point(m.dest(m.lnext(start)));
            if (orient2d(a, b, c) <= 0) return fail(rep, "a triangle of the mesh is not counterclockwise");
            // The neighbour across `start`, if it is a triangle.
            const EdgeRef s = Q::sym(start);
            if (m.lnext(m.lnext(m.lnext(s))) == s) {
                const VertexIndex dv = m.dest(m.lnext(s));
                const Point& d = dt.point(dv);
                if (!dt.weighted() && incircle(a, b, c, d) > 0) return fail(rep, "the mesh is not Delaunay");
                if (dt.weighted() && power_test(a, dt.radius(m.org(start)), b, dt.radius(m.dest(start)), c,
                                                dt.radius(m.dest(m.lnext(start))), d, dt.radius(dv)) > 0)
                    return fail(rep, "the mesh is not regular (an edge fails the power test)");
            }
        }
    }
    if (outer != 1 || dt.vertex_count() - dt.hidden_count() + faces != m.live_count() + 2)
        return fail(rep, "the mesh is not a triangulation of the ghost square");
    rep.triangles = triangles;
    return true;
}

}  // namespace

MeshReport check_edge_algebra(const QuadEdgeMesh& m) {
    MeshReport rep;
    algebra_holds(m, rep);
    return rep;
}

MeshReport check_mesh_invariants(const Delaunay& dt) {
    MeshReport rep;
    if (!algebra_holds(dt.mesh(), rep)) return rep;
    std::size_t hidden = 0;
    for (VertexIndex v = 0; v < dt.vertex_count(); ++v) {
        if (dt.weighted() && dt.is_hidden(v)) {
            // Hidden: its lifted point on or above the lower hull, that is
            // above the plane of the triangle holding it.
            ++hidden;
            const EdgeRef e = dt.locate(dt.point(v), dt.edge_of(dt.visible(v)));
            const VertexIndex a = dt.mesh().org(e), b = dt.mesh().dest(e),
                              c = dt.mesh().dest(dt.mesh().lnext(e));
            if (power_test(dt.point(a), dt.radius(a), dt.point(b), dt.radius(b), dt.point(c), dt.radius(c),
                           dt.point(v), dt.radius(v)) > 0) {
                fail(rep, "a hidden disk has a power cell");
                return rep;
            }
            continue;
        }
        if (dt.edge_of(v) == kNoEdge || (dt.edge_of(v) >> 2) >= dt.mesh().record_count() ||
            !dt.mesh().is_live(dt.edge_of(v) >> 2) || dt.mesh().org(dt.edge_of(v)) != v) {
            fail(rep, "a vertex's entry edge does not start at it");
            return rep;
        }
    }
    if (hidden != dt.hidden_count()) {
        fail(rep, "the mesh miscounts its hidden disks");
        return rep;
    }
    faces_hold(dt, rep);
    return rep;
}

}  // namespace pds
