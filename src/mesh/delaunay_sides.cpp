// delaunay_sides.cpp - insertions side by side (see delaunay.hpp): the
// read-only search that tells whether a point's insertion stays on one side,
// the vertex slots and the insertion into one.
#include <algorithm>
#include <stdexcept>

#include "core/predicates.hpp"
#include "mesh/delaunay.hpp"

namespace pds {

bool Delaunay::can_insert_on_side(const Point& p, VertexIndex near, const Side& side) const {
    return search_on_side(p, near, side) != kNoEdge;
}

bool Delaunay::insert_on_side(const Point& p, VertexIndex near, const Side& side, VertexIndex slot,
                              QuadEdgeMesh::Arena& arena) {
    require_open_slot(slot);
    const EdgeRef e = search_on_side(p, near, side);
    if (e == kNoEdge) return false;
    // The search's walk is locate()'s, so e is the edge insert_in_slot
    // would find: the same records either way.
    points_[slot] = p;
    connect_and_flip<false>(p, e, slot, &arena);
    return true;
}

EdgeRef Delaunay::search_on_side(const Point& p, VertexIndex near, const Side& side) const {
    if (weighted_ || !on_side(near, side)) return kNoEdge;
    // locate()'s walk from near's entry edge, stepping only across edges
    // whose ends are both on the side, so that every triangle read has a
    // vertex of the side. A long walk gives up: the point waits for the
    // serial insertions.
    constexpr std::size_t kMaxSteps = 64;
    const EdgeRef e = walk(p, vertex_edge_[near], kMaxSteps, [&](EdgeRef next) {
        return on_side(mesh_.org(next), side) && on_side(mesh_.dest(next), side);
    });
    if (e == kNoEdge || at_end(p, e)) return kNoEdge;
    // The cavity: the triangles whose circumcircles hold p strictly, found
    // from the one that holds p across the edges between them (they are
    // connected; a point on an edge is strictly inside both triangles'
    // circles). Every corner of a cavity triangle and every far corner of a
    // triangle next to one must be on the side. A triangle is named by the
    // least of its three left-face edges.
    constexpr int kMaxCavity = 32;
    EdgeRef cavity[kMaxCavity], name[kMaxCavity];
    int found = 0;
    const auto name_of = [this](EdgeRef t) {
        const EdgeRef t1 = mesh_.lnext(t), t2 = mesh_.lnext(t1);
        return std::min(t, std::min(t1, t2));
    };
    cavity[found] = e;
    name[found++] = name_of(e);
    for (int i = 0; i < found; ++i) {
        EdgeRef s = cavity[i];
        for (int k = 0; k < 3; ++k, s = mesh_.lnext(s))
            if (!on_side(mesh_.org(s), side)) return kNoEdge;
        for (int k = 0; k < 3; ++k, s = mesh_.lnext(s)) {
            // The triangle across s, left of sym(s): its far corner.
            const EdgeRef across = QuadEdgeMesh::sym(s);
            const VertexIndex far = mesh_.dest(mesh_.lnext(across));
            if (!on_side(far, side)) return kNoEdge;
            if (incircle(points_[mesh_.org(across)], points_[mesh_.dest(across)], points_[far], p) <= 0) continue;
            const EdgeRef n = name_of(across);
            bool seen = false;
            for (int j = 0; j < found && !seen; ++j) seen = name[j] == n;
            if (seen) continue;
            if (found == kMaxCavity) return kNoEdge;
            cavity[found] = across;
            name[found++] = n;
        }
    }
    return e;
}

VertexIndex Delaunay::open_slots(std::size_t n) {
    const std::size_t first = points_.size();
    if (weighted_) throw std::logic_error("Delaunay::open_slots on a weighted mesh");
    if (n > points_.capacity() - first || n > vertex_edge_.capacity() - first)
        throw std::logic_error("Delaunay::open_slots beyond the reserved room");
    points_.resize(first + n, Point{0.0, 0.0});
    vertex_edge_.resize(first + n, kNoEdge);
    return static_cast<VertexIndex>(first);
}

void Delaunay::require_open_slot(VertexIndex slot) const {
    if (weighted_) throw std::logic_error("Delaunay: an insertion into a slot on a weighted mesh");
    if (slot < kGhosts || slot >= points_.size() || vertex_edge_[slot] != kNoEdge)
        throw std::logic_error("Delaunay: an insertion into a slot not open");
    if (shared_) throw std::logic_error("Delaunay: an insertion into a slot while the mesh is shared");
}

void Delaunay::insert_in_slot(const Point& p, VertexIndex near, VertexIndex slot, QuadEdgeMesh::Arena& arena) {
    require_open_slot(slot);
    const EdgeRef e = locate_new(p, near);
    points_[slot] = p;
    connect_and_flip<false>(p, e, slot, &arena);
}

}  // namespace pds
