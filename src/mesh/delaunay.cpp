// delaunay.cpp - Guibas-Stolfi insertion with exact predicates (see delaunay.hpp).
#include "mesh/delaunay.hpp"

#include <cmath>
#include <stdexcept>

#include "core/batch.hpp"
#include "core/page_hints.hpp"
#include "core/predicates.hpp"
#include "core/prefetch.hpp"

namespace pds {

namespace {

// Whether m, collinear with a and b, lies strictly between them (exact:
// along a line, a coordinate orders the points).
bool strictly_between(const Point& a, const Point& m, const Point& b) {
    if (a.x != b.x) return (a.x < m.x && m.x < b.x) || (b.x < m.x && m.x < a.x);
    return (a.y < m.y && m.y < b.y) || (b.y < m.y && m.y < a.y);
}

}  // namespace

Delaunay::Delaunay(const Box& domain, bool weighted, double ghost_radius) : weighted_(weighted) {
    const double cx = 0.5 * (domain.x0 + domain.x1);
    const double cy = 0.5 * (domain.y0 + domain.y1);
    // sqrt, not hypot: libm's hypot may differ in the last bit between
    // versions, and the ghosts' coordinates reach the points a seed gives.
    const double w = domain.width(), h = domain.height();
    const double half = 3.0 * std::sqrt(w * w + h * h);
    reserve(kGhosts + 1);
    points_ = {{cx - half, cy - half}, {cx + half, cy - half}, {cx + half, cy + half},
               {cx - half, cy + half}};
    // The square's boundary, counterclockwise, then one diagonal.
    EdgeRef side[kGhosts];
    for (std::uint32_t i = 0; i < kGhosts; ++i) side[i] = mesh_.make_edge(i, (i + 1) % kGhosts);
    for (std::uint32_t i = 0; i < kGhosts; ++i)
        mesh_.splice(QuadEdgeMesh::sym(side[i]), side[(i + 1) % kGhosts]);
    mesh_.connect(side[1], side[0]);  // 2 -> 0
    vertex_edge_.assign(side, side + kGhosts);
    if (weighted_) {
        radii_.assign(kGhosts, ghost_radius);
        hidden_by_.assign(kGhosts, kNoVertex);
    }
}

void Delaunay::reserve(std::size_t vertices) {
    // The arrays may move: never while another thread may read them.
    if (shared_) throw std::logic_error("Delaunay::reserve while the mesh is shared");
    // An insertion adds three edges (four and deletes one when the point lands
    // on an edge), so 3 records per vertex always suffice; build_whole() takes
    // a few more for its parts' arenas.
    mesh_.reserve(3 * vertices + kBuildWholeSlack);
    points_.reserve(vertices);
    vertex_edge_.reserve(vertices);
    if (weighted_) {
        radii_.reserve(vertices);
        hidden_by_.reserve(vertices);
        advise_huge_pages(radii_);
    }
    advise_huge_pages(points_);
    advise_huge_pages(vertex_edge_);
}

void Delaunay::populate_for(std::size_t vertices) const {
    mesh_.populate_for(mesh_.record_count() + 3 * (vertices > points_.size() ? vertices - points_.size() : 0));
    populate_ahead(points_, vertices);
    populate_ahead(vertex_edge_, vertices);
    if (weighted_) {
        populate_ahead(radii_, vertices);
        populate_ahead(hidden_by_, vertices);
    }
}

bool Delaunay::has_room_for_one() const {
    return points_.size() < points_.capacity() && vertex_edge_.size() < vertex_edge_.capacity() &&
           mesh_.spare_records() >= 3 &&
           (!weighted_ || (radii_.size() < radii_.capacity() && hidden_by_.size() < hidden_by_.capacity()));
}

EdgeRef Delaunay::locate(const Point& p, EdgeRef e) const {
    // The walk visits each triangle at most once on a Delaunay mesh; the bound
    // only turns a broken invariant into an error instead of a hang.
    const EdgeRef found = walk(p, e, 4 * mesh_.live_count() + 16, [](EdgeRef) { return true; });
    if (found == kNoEdge) throw std::logic_error("point location did not terminate");
    return found;
}

template <bool kShared>
void Delaunay::prefetch_rings(const std::uint32_t* vertices, std::size_t n) const {
    constexpr int kMaxSteps = 12;  // typical rings have about 6 edges
    EdgeRef edge[kMaxBatch], first[kMaxBatch];
    if (n > kMaxBatch) n = kMaxBatch;
    for (std::size_t k = 0; k < n; ++k) {
        pds::prefetch(&vertex_edge_[vertices[k]]);
        pds::prefetch(&points_[vertices[k]]);
        if (weighted_) pds::prefetch(&radii_[vertices[k]]);
    }
    for (std::size_t k = 0; k < n; ++k) edge[k] = first[k] = load_vertex_edge<kShared>(vertices[k]);
    // One step of every ring per round: the loads of a round are independent.
    // Shared, a ring may be caught mid-change (a deleted record's link is
    // the free list's, possibly kNoEdge): a ref or vertex out of the arrays
    // ends its walk.
    for (int step = 0; step < kMaxSteps; ++step) {
        bool any = false;
        for (std::size_t k = 0; k < n; ++k) {
            if (edge[k] == kNoEdge) continue;
            if constexpr (kShared) {
                if (!mesh_.within(edge[k])) {
                    edge[k] = kNoEdge;
                    continue;
                }
            }
            const std::uint32_t dest = mesh_.load_org<kShared>(QuadEdgeMesh::sym(edge[k]));
            if (!kShared || has_vertex_slot(dest)) {
                pds::prefetch(&points_[dest]);
                if (weighted_) pds::prefetch(&radii_[dest]);
            }
            const EdgeRef next = mesh_.load_onext<kShared>(edge[k]);
            if (!kShared || mesh_.within(next)) pds::prefetch(mesh_.record_address(next));
            edge[k] = next == first[k] ? kNoEdge : next;
            any = true;
        }
        if (!any) break;
    }
}

template <bool kShared>
void Delaunay::prefetch_beyond_rings(const std::uint32_t* vertices, std::size_t n) const {
    constexpr std::size_t kMax = 16 * kMaxBatch;  // rings have about 6 edges: ample
    EdgeRef edge[kMax];
    std::size_t m = 0;
    // Round 1: each ring edge c -> a; its left triangle's third side a -> b
    // (the link edge) is read from the ring edge's own record.
    // Shared, refs and vertices out of the arrays end a walk, as above.
    for (std::size_t k = 0; k < n && m < kMax; ++k) {
        const EdgeRef first = load_vertex_edge<kShared>(vertices[k]);
        if (first == kNoEdge) continue;  // a hidden disk: no ring
        if (kShared && !mesh_.within(first)) continue;
        EdgeRef e = first;
        do {
            const EdgeRef link = mesh_.load_lnext<kShared>(e);
            if (kShared && !mesh_.within(link)) break;
            pds::prefetch(mesh_.record_address(link));
            edge[m++] = link;
            e = mesh_.load_onext<kShared>(e);
        } while (e != first && m < kMax && (!kShared || mesh_.within(e)));
    }
    // Round 2: behind each link edge, the edge to the far corner of the
    // triangle on its other side (what the flip test reads).
    std::size_t kept = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const EdgeRef behind = mesh_.load_oprev<kShared>(edge[i]);
        if (kShared && !mesh_.within(behind)) continue;
        pds::prefetch(mesh_.record_address(behind));
        edge[kept++] = behind;
    }
    // Round 3: the far corners themselves (and their radii).
    for (std::size_t i = 0; i < kept; ++i) {
        const std::uint32_t dest = mesh_.load_org<kShared>(QuadEdgeMesh::sym(edge[i]));
        if (kShared && !has_vertex_slot(dest)) continue;
        pds::prefetch(&points_[dest]);
        if (weighted_) pds::prefetch(&radii_[dest]);
    }
}

template void Delaunay::prefetch_rings<false>(const std::uint32_t*, std::size_t) const;
template void Delaunay::prefetch_rings<true>(const std::uint32_t*, std::size_t) const;
template void Delaunay::prefetch_beyond_rings<false>(const std::uint32_t*, std::size_t) const;
template void Delaunay::prefetch_beyond_rings<true>(const std::uint32_t*, std::size_t) const;

template <bool kShared>
void Delaunay::swap_edge(EdgeRef e) {
    // The endpoints lose e: point their entry edges at edges they keep. Written
    // unconditionally: a store does not wait for the cache, a test would.
    const EdgeRef a = mesh_.oprev(e), b = mesh_.oprev(QuadEdgeMesh::sym(e));
    set_vertex_edge<kShared>(mesh_.org(e), a);
    set_vertex_edge<kShared>(mesh_.dest(e), b);
    mesh_.swap<kShared>(e);
}

template <bool kShared>
void Delaunay::delete_edge(EdgeRef e, QuadEdgeMesh::Arena* arena) {
    const std::uint32_t o = mesh_.org(e), d = mesh_.dest(e);
    if (vertex_edge_[o] == e) set_vertex_edge<kShared>(o, mesh_.onext(e));
    if (vertex_edge_[d] == QuadEdgeMesh::sym(e)) set_vertex_edge<kShared>(d, mesh_.onext(QuadEdgeMesh::sym(e)));
    if (arena)
        mesh_.delete_edge(*arena, e);
    else
        mesh_.delete_edge<kShared>(e);
}

std::uint32_t Delaunay::insert(const Point& p, std::uint32_t near) {
    return shared_ ? insert_as<true>(p, near) : insert_as<false>(p, near);
}

std::uint32_t Delaunay::insert(const Point& p, double r, std::uint32_t near) {
    return shared_ ? insert_as<true>(p, r, near) : insert_as<false>(p, r, near);
}

template <bool kShared>
std::uint32_t Delaunay::insert_as(const Point& p, std::uint32_t near) {
    if (weighted_) throw std::logic_error("Delaunay::insert without a radius on a weighted mesh");
    if (!has_room_for_one()) throw std::logic_error("Delaunay::insert without reserved room");
    const EdgeRef e = locate_new(p, near);
    const std::uint32_t v = static_cast<std::uint32_t>(points_.size());
    points_.push_back(p);
    vertex_edge_.push_back(kNoEdge);
    connect_and_flip<kShared>(p, e, v, nullptr);
    return v;
}

EdgeRef Delaunay::locate_new(const Point& p, VertexIndex near) const {
    const EdgeRef e = locate(p, vertex_edge_[near]);
    if (at_end(p, e)) throw std::logic_error("Delaunay::insert of a duplicate point");
    return e;
}

template <bool kShared>
void Delaunay::connect_and_flip(const Point& p, EdgeRef e, VertexIndex v, QuadEdgeMesh::Arena* arena) {
    const bool on_edge = orient2d(points_[mesh_.org(e)], points_[mesh_.dest(e)], p) == 0;
    const EdgeRef start = connect_spokes<kShared>(e, v, on_edge, &e, arena);

    // Restore the Delaunay property: examine the edges opposite p, flip those
    // whose far corner lies inside the circle through p and the edge.
    for (;;) {
        const EdgeRef t = mesh_.oprev(e);
        const Point& far = points_[mesh_.dest(t)];
        if (right_of(far, e) &&
            incircle(points_[mesh_.org(e)], far, points_[mesh_.dest(e)], p) > 0) {
            swap_edge<kShared>(e);
            e = mesh_.oprev(e);
        } else if (mesh_.onext(e) == start) {
            break;
        } else {
            e = mesh_.lprev(mesh_.onext(e));
        }
    }
}

template void Delaunay::connect_and_flip<false>(const Point&, EdgeRef, VertexIndex, QuadEdgeMesh::Arena*);

template <bool kShared>
EdgeRef Delaunay::connect_spokes(EdgeRef e, VertexIndex v, bool on_edge, EdgeRef* link, QuadEdgeMesh::Arena* arena) {
    if (on_edge) {
        // p lies on e (strictly inside it, since it is in the closed triangle
        // and not a corner): remove e and fill the quadrilateral instead.
        const EdgeRef t = mesh_.oprev(e);
        delete_edge<kShared>(e, arena);
        e = t;
    }
    // Connect p to every corner of the (triangle or quadrilateral) face.
    EdgeRef base = arena ? mesh_.make_edge(*arena, mesh_.org(e), v) : mesh_.make_edge<kShared>(mesh_.org(e), v);
    mesh_.splice<kShared>(base, e);
    const EdgeRef start = base;
    do {
        base = arena ? mesh_.connect(*arena, e, QuadEdgeMesh::sym(base))
                     : mesh_.connect<kShared>(e, QuadEdgeMesh::sym(base));
        e = mesh_.oprev(base);
    } while (mesh_.lnext(e) != start);
    set_vertex_edge<kShared>(v, QuadEdgeMesh::sym(start));
    *link = e;  // a link edge (opposite v, v on its left)
    return start;
}

std::size_t Delaunay::degree(VertexIndex v) const {
    std::size_t n = 0;
    for_each_neighbour(v, [&](VertexIndex) { ++n; });
    return n;
}

template <bool kShared>
void Delaunay::hide_vertex(VertexIndex a, VertexIndex v) {
    // Deleting a's three edges merges its triangles into one.
    while (vertex_edge_[a] != kNoEdge) {
        const EdgeRef e = vertex_edge_[a];
        const EdgeRef next = mesh_.onext(e);
        delete_edge<kShared>(e, nullptr);
        set_vertex_edge<kShared>(a, next == e ? kNoEdge : next);
    }
    hidden_by_[a] = v;
    ++hidden_count_;
}

template <bool kShared>
std::uint32_t Delaunay::insert_as(const Point& p, double r, std::uint32_t near) {
    if (!weighted_) throw std::logic_error("Delaunay::insert with a radius on an unweighted mesh");
    if (!has_room_for_one()) throw std::logic_error("Delaunay::insert without reserved room");
    EdgeRef e = locate(p, vertex_edge_[visible(near)]);
    const VertexIndex a0 = mesh_.org(e), b0 = mesh_.dest(e), c0 = mesh_.dest(mesh_.lnext(e));
    const Point& o = points_[a0];
    const Point& d = points_[b0];
    if (at_end(p, e)) throw std::logic_error("Delaunay::insert of a duplicate point");
    const VertexIndex v = static_cast<VertexIndex>(points_.size());
    points_.push_back(p);
    vertex_edge_.push_back(kNoEdge);
    radii_.push_back(r);
    hidden_by_.push_back(kNoVertex);
    // Hidden at once: the lifted p on or above the plane of the triangle
    // holding it (on an edge, both triangles' planes agree there).
    if (power_test(o, radii_[a0], d, radii_[b0], points_[c0], radii_[c0], p, r) <= 0) {
        hidden_by_[v] = a0;
        ++hidden_count_;
        return v;
    }
    const bool on_edge = orient2d(o, d, p) == 0;
    std::size_t degree_v = on_edge ? 4 : 3;
    connect_spokes<kShared>(e, v, on_edge, &e, nullptr);

    // Edelsbrunner-Shah flips, around v clockwise (e: a link edge a -> b
    // with v on its left, far corner f across it). Every link edge must end
    // regular; while one is not, one of them can be flipped (their Lemma),
    // so the walk goes on until a whole turn finds every link edge regular.
    const std::size_t limit = 64 * (mesh_.live_count() + 16);
    std::size_t quiet = 0;
    for (std::size_t step = 0; quiet < degree_v; ++step) {
        if (step > limit) throw std::logic_error("regular insertion did not terminate");
        const EdgeRef t = mesh_.oprev(e);  // a -> f
        const VertexIndex a = mesh_.org(e), b = mesh_.dest(e), f = mesh_.dest(t);
        const Point& pf = points_[f];
        if (!right_of(pf, e) ||
            power_test(points_[a], radii_[a], pf, radii_[f], points_[b], radii_[b], p, r) <= 0) {
            ++quiet;
            e = mesh_.lprev(mesh_.onext(e));
            continue;
        }
        quiet = 0;
        const int side_a = orient2d(p, pf, points_[a]), side_b = orient2d(p, pf, points_[b]);
        if (side_a < 0 && side_b > 0) {
            // Convex: the 2-2 flip; look at the first of the two new link edges.
            swap_edge<kShared>(e);
            e = mesh_.oprev(e);
            ++degree_v;
        } else if (side_a > 0 && !is_ghost(a) && degree(a) == 3) {
            // a is inside triangle (v, f, b) and only joins them: 3-1.
            const EdgeRef fb = mesh_.lnext(t);
            hide_vertex<kShared>(a, v);
            e = fb;
            --degree_v;
        } else if (side_b < 0 && !is_ghost(b) && degree(b) == 3) {
            // b is inside triangle (v, a, f): 3-1, leaving link edge a -> f.
            hide_vertex<kShared>(b, v);
            e = t;
            --degree_v;
        } else if (side_b == 0 && !is_ghost(b) && degree(b) == 4 && strictly_between(p, points_[b], pf)) {
            // b lies on the segment from v to f, and the link edge's failed
            // test puts lifted b above lifted v f: b is hidden, though no
            // triangle of v holds it. The 3-1 flip of this degenerate case:
            // b's four edges go, and v joins f (b's place as a neighbour).
            hide_vertex<kShared>(b, v);
            mesh_.connect<kShared>(t, mesh_.lprev(t));  // f -> v, in the face a f c v
            e = t;
        } else if (side_a == 0 && !is_ghost(a) && degree(a) == 4 && strictly_between(p, points_[a], pf)) {
            // The same for a on the segment from v to f.
            const EdgeRef fb = mesh_.lnext(t);
            hide_vertex<kShared>(a, v);
            mesh_.connect<kShared>(mesh_.lnext(fb), fb);  // v -> f, in the face f b v c
            e = fb;
        } else {
            // Not flippable now; another link edge is (the Lemma).
            e = mesh_.lprev(mesh_.onext(e));
        }
    }
    return v;
}

}  // namespace pds
