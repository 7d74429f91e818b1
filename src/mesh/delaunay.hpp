// delaunay.hpp - incremental Delaunay triangulation on the quad-edge mesh.
//
// Insertion is Guibas & Stolfi's InsertSite (1985, section 9): locate the
// triangle by a walk, connect the new site to its corners, then flip edges
// that fail the in-circle test. All decisions use the exact predicates, so the
// mesh is exactly Delaunay (ties on a circle are left unflipped).
//
// Jones 2006 (section 3, step 3) notes that the walk can start at the Voronoi
// site whose cell the new point was drawn in; the point's nearest site is then
// at most a few triangles away, so location is O(1) in practice.
//
// Ghosts: vertices 0..3 are the corners of a square centred on the domain with
// half-side 3 * diagonal. Every point of the domain is then more than 3
// diagonals from a ghost but within one diagonal of any real site, so the
// Voronoi cells of real sites inside the domain are exactly those of the real
// sites alone; and every triangle with a corner in the domain has a bounded
// circumcircle (a huge circle would swallow a ghost). The ghosts only bound the
// mesh; callers skip them when they enumerate sites.
//
// Weighted (a variable radius): each vertex is a disk (point, radius), and
// the mesh is the regular triangulation, dual of the power diagram; the
// flip test is the power test (predicates.hpp) and the insertion is
// Edelsbrunner & Shah's (1996): the point's spokes, then 2-2 flips of link
// edges that fail the test where the quadrilateral is convex, and 3-1 flips
// that remove a reflex vertex of degree 3; in the degenerate case of a
// vertex of degree 4 on the segment from the new point to the far corner
// (disks on one line), it is removed and the segment drawn. A disk whose
// power cell is empty is "hidden": it is not in the mesh, keeps its point
// and radius, and names the vertex that hid it (a walk starting there
// begins nearby). A disk is hidden when its lifted point lies on or above
// the lower hull: a cell of zero area counts as empty. With equal radii
// every decision is the unweighted one, so the mesh is the same, edge for
// edge.
#ifndef PDS_DELAUNAY_HPP
#define PDS_DELAUNAY_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/predicates.hpp"
#include "core/prefetch.hpp"
#include "core/relaxed.hpp"
#include "mesh/quadedge.hpp"

namespace pds {

class Delaunay {
public:
    static constexpr VertexIndex kGhosts = kGhostVertices;

    // Weighted: the ghosts get ghost_radius. Given the largest radius, every
    // decision with equal radii is the unweighted one; and radii up to twice
    // the diagonal (the frame's cap) keep the ghosts' cells out of the domain
    // (a site's power there is under diagonal^2, a ghost's over 9 diagonal^2
    // - (2 diagonal)^2).
    explicit Delaunay(const Box& domain, bool weighted = false, double ghost_radius = 0.0);

    // Makes room for `vertices` vertices in all (ghosts included) and their
    // edges; strong guarantee (std::bad_alloc and nothing changed).
    void reserve(std::size_t vertices);
    // True when insert() can run without allocating.
    bool has_room_for_one() const;
    // Makes resident the pages that insertions up to `vertices` vertices in
    // all will first write (core/page_hints.hpp), within the room
    // reserved. Changes nothing the mesh holds: another thread may read the
    // mesh meanwhile, none may insert.
    void populate_for(std::size_t vertices) const;
    // True when the mesh has room for `vertices` vertices in all (ghosts
    // included) without allocating, as reserve(vertices) makes.
    bool has_room_for(std::size_t vertices) const {
        return points_.capacity() >= vertices && vertex_edge_.capacity() >= vertices &&
               mesh_.record_count() + mesh_.spare_records() >= 3 * vertices &&
               (!weighted_ || (radii_.capacity() >= vertices && hidden_by_.capacity() >= vertices));
    }

    // Inserts p, which must be strictly inside the ghost square and distinct
    // from every vertex; `near` is where the walk starts. Returns p's vertex.
    std::uint32_t insert(const Point& p, std::uint32_t near);
    // The same for the disk (p, r) on a weighted mesh; the vertex may be
    // hidden at once, and others may become hidden.
    std::uint32_t insert(const Point& p, double r, std::uint32_t near);
    // While on, the insertions write the links and the entry edges by
    // relaxed atomic stores, so that a thread started after set_shared(true)
    // may run prefetch_rings and prefetch_beyond_rings meanwhile; off (the
    // default) they write plainly, which the compiler optimizes better.
    // Changing the mesh in any other way needs it off and that thread gone
    // (reserve() refuses with std::logic_error while it is on).
    void set_shared(bool on) { shared_ = on; }
    bool shared() const { return shared_; }

    // Inserts points[order[0]], points[order[1]], ... (n of them), each walk
    // starting at the vertex inserted before it: a neighbour when the order
    // is spatial (the dart stage's hand-over order). Calls inserted(k, v)
    // for point k landing on vertex v. Requires room for all n. A weighted
    // mesh gives point k the radius radius_of(k).
    template <class Inserted>
    void insert_in_order(const std::vector<Point>& points, const std::uint32_t* order, std::size_t n,
                         const Inserted& inserted) {
        insert_in_order(points, order, n, [](std::uint32_t) { return 0.0; }, inserted);
    }
    template <class RadiusOf, class Inserted>
    void insert_in_order(const std::vector<Point>& points, const std::uint32_t* order, std::size_t n,
                         const RadiusOf& radius_of, const Inserted& inserted) {
        // The points are stored in the order they were drawn, so reading them
        // in spatial order is a cache miss each: ask for them well ahead.
        constexpr std::size_t kAhead = 16;
        for (std::size_t i = 0; i < n && i < kAhead; ++i) pds::prefetch(&points[order[i]]);
        VertexIndex previous = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (i + kAhead < n) pds::prefetch(&points[order[i + kAhead]]);
            const std::uint32_t k = order[i];
            previous = weighted_ ? insert(points[k], radius_of(k), previous) : insert(points[k], previous);
            inserted(k, previous);
        }
    }

    // The same mesh built whole from points[order[0]], ... (n of them, vertex
    // 4 + i for order[i]), by Guibas and Stolfi's divide and conquer
    // (delaunay_build.cpp): its parts are built and merged side by side on up
    // to `threads` threads. Only on a mesh holding its ghosts alone, with the
    // room reserve(4 + n) makes; does not allocate; a weighted mesh gives
    // every point the ghosts' radius (the caller's to check: the regular
    // mesh is then the Delaunay one). The records and entry edges depend on
    // n and the points alone, never on the threads. False, and nothing
    // changed, when it does not apply (few points, no room): the caller
    // inserts them instead.
    template <class Inserted>
    bool build_whole(const std::vector<Point>& points, const std::uint32_t* order, std::size_t n,
                     unsigned threads, const Inserted& inserted) {
        if (!build_whole(points, order, n, threads)) return false;
        for (std::size_t i = 0; i < n; ++i) inserted(order[i], static_cast<VertexIndex>(kGhosts + i));
        return true;
    }
    bool build_whole(const std::vector<Point>& points, const std::uint32_t* order, std::size_t n,
                     unsigned threads);
    // Fewer points than this are inserted one by one (build_whole declines).
    static constexpr std::size_t kBuildWholeFrom = 4096;
    // The records build_whole() needs beyond 3 per vertex (its arenas' slack).
    static constexpr std::size_t kBuildWholeSlack = 8 * 64;

    // ---- Insertions side by side (delaunay_sides.cpp) ----
    // Threads may insert at once into one unweighted mesh, each on its side
    // of a vertical line, when each point's insertion reads and writes only
    // triangles whose vertices are all real vertices of its side: the
    // triangles whose circumcircles hold it strictly (those its flips
    // remove) and the triangles next to them. A thread then writes only
    // records whose two faces are such triangles, and reads only triangles
    // with a vertex of its side, which the other never writes; so they
    // share nothing. The points go into vertex slots opened beforehand and
    // their records come from arenas laid out beforehand, so the mesh's
    // records do not depend on the threads, only on what each side
    // inserts, in which order.
    struct Side {
        double mid;  // the line x = mid
        bool left;   // the side x < mid; else x >= mid
    };
    bool on_side(VertexIndex v, const Side& side) const {
        return !is_ghost(v) && ((points_[v].x < side.mid) == side.left);
    }
    // Whether p can be inserted so, walking from `near` (a vertex of the
    // side): read-only; it steps only across edges whose ends are both on
    // the side. False also when p is a vertex or the walk is long.
    bool can_insert_on_side(const Point& p, VertexIndex near, const Side& side) const;
    // Opens n empty vertex slots after the last vertex (within the room
    // reserved, std::logic_error beyond it); returns the first. Every slot
    // must be filled by insert_in_slot before the mesh is used otherwise.
    VertexIndex open_slots(std::size_t n);
    // The records n insertions take (within the room reserved), and their
    // return once the insertions are done.
    QuadEdgeMesh::Arena edge_arena(std::size_t insertions) { return mesh_.append_arena(3 * insertions); }
    // Whether edge_arena can take n insertions' records without a reserve:
    // an arena comes after every record, free ones too, so has_room_for
    // may say yes when it does not fit.
    bool can_append_edges(std::size_t insertions) const { return mesh_.appendable_records() >= 3 * insertions; }
    // The vertices in all (ghosts included) whose reserve makes it so.
    std::size_t vertices_to_append_edges(std::size_t insertions) const {
        return (mesh_.record_count() + 3 * insertions + 2) / 3;
    }
    void close_edge_arena(const QuadEdgeMesh::Arena& arena) { mesh_.close_appended(arena); }
    // Inserts p into the open slot, walking from `near`, its records from
    // `arena`; std::logic_error on a weighted mesh, a slot not open and
    // empty, or a duplicate point.
    void insert_in_slot(const Point& p, VertexIndex near, VertexIndex slot, QuadEdgeMesh::Arena& arena);
    // can_insert_on_side, then if so insert_in_slot from the edge the search
    // found (no second walk); false, and nothing changed, if not.
    bool insert_on_side(const Point& p, VertexIndex near, const Side& side, VertexIndex slot,
                        QuadEdgeMesh::Arena& arena);

    bool weighted() const { return weighted_; }
    double radius(VertexIndex v) const { return weighted_ ? radii_[v] : 0.0; }
    // A weighted mesh only: a disk whose power cell is empty, not in the mesh.
    bool is_hidden(VertexIndex v) const { return vertex_edge_[v] == kNoEdge; }
    std::size_t hidden_count() const { return hidden_count_; }
    // v, or if v is hidden the nearest vertex in the chain of those that hid
    // it that is still in the mesh: a walk start near v.
    VertexIndex visible(VertexIndex v) const {
        while (is_hidden(v)) v = hidden_by_[v];
        return v;
    }

    std::size_t vertex_count() const { return points_.size(); }
    const Point& point(std::uint32_t v) const { return points_[v]; }
    const std::vector<Point>& points() const { return points_; }
    static bool is_ghost(std::uint32_t v) { return v < kGhosts; }
    // An edge whose origin is v.
    EdgeRef edge_of(std::uint32_t v) const { return vertex_edge_[v]; }
    // Calls visit(n) for every neighbour n of v, counterclockwise (ghosts
    // included): the one walk around a vertex ring.
    template <class Visit>
    void for_each_neighbour(VertexIndex v, const Visit& visit) const {
        const EdgeRef first = vertex_edge_[v];
        EdgeRef e = first;
        do {
            visit(mesh_.dest(e));
            e = mesh_.onext(e);
        } while (e != first);
    }
    const QuadEdgeMesh& mesh() const { return mesh_; }

    // The triangle (left face of the returned edge) that contains p, walking
    // from `start`; p must be inside the ghost square.
    EdgeRef locate(const Point& p, EdgeRef start) const;

    // Asks the memory system for the vertex rings (edges and neighbour
    // points) of n vertices, walking all rings in step so that their cache
    // misses overlap. A hint only: no effect on results. With kShared they
    // may run on another thread while this one inserts, if set_shared(true)
    // was called before that thread started (jones/ring_prefetcher.hpp):
    // they then read the links by relaxed loads.
    template <bool kShared = false>
    void prefetch_rings(const std::uint32_t* vertices, std::size_t n) const;
    // For vertices whose rings are cached: asks for the triangles just beyond
    // them (the link edges, the edges behind those, and their far vertices),
    // which inserting a point next to such a vertex reads when it flips edges.
    template <bool kShared = false>
    void prefetch_beyond_rings(const std::uint32_t* vertices, std::size_t n) const;

private:
    // Inline: the walk and the flip loop call it at every step.
    bool right_of(const Point& p, EdgeRef e) const {
        return orient2d(p, points_[mesh_.dest(e)], points_[mesh_.org(e)]) > 0;
    }
    // Whether p is an end of e (a vertex already in the mesh).
    bool at_end(const Point& p, EdgeRef e) const {
        const Point& o = points_[mesh_.org(e)];
        const Point& d = points_[mesh_.dest(e)];
        return (p.x == o.x && p.y == o.y) || (p.x == d.x && p.y == d.y);
    }
    // locate()'s walk from e: an edge whose left triangle holds p (or with
    // p at an end). Each step enters the triangle left of an edge `next` of
    // the current one, only when may_cross(next); kNoEdge when one is
    // refused or after `limit` steps.
    template <class MayCross>
    EdgeRef walk(const Point& p, EdgeRef e, std::size_t limit, const MayCross& may_cross) const {
        for (std::size_t step = 0; step < limit; ++step) {
            if (at_end(p, e)) return e;
            EdgeRef next;
            if (right_of(p, e)) {
                next = QuadEdgeMesh::sym(e);
            } else if (!right_of(p, mesh_.onext(e))) {
                next = mesh_.onext(e);
            } else if (!right_of(p, mesh_.dprev(e))) {
                next = mesh_.dprev(e);
            } else {
                return e;
            }
            if (!may_cross(next)) return kNoEdge;
            e = next;
        }
        return kNoEdge;
    }
    // The insertions, with the mesh's writes shared (set_shared) or not.
    template <bool kShared>
    std::uint32_t insert_as(const Point& p, std::uint32_t near);
    template <bool kShared>
    std::uint32_t insert_as(const Point& p, double r, std::uint32_t near);
    // A vertex index inside the points' arrays: a shared walk may read an
    // origin mid-change (a free record's), which is none.
    bool has_vertex_slot(std::uint32_t v) const { return v < points_.capacity(); }
    template <bool kShared>
    EdgeRef load_vertex_edge(VertexIndex v) const {
        return load_word<kShared>(vertex_edge_[v]);
    }
    template <bool kShared>
    void set_vertex_edge(VertexIndex v, EdgeRef e) {
        store_word<kShared>(vertex_edge_[v], e);
    }
    template <bool kShared>
    void swap_edge(EdgeRef e);
    // Deletes e, its record going to `arena` (the mesh's free list if none).
    template <bool kShared>
    void delete_edge(EdgeRef e, QuadEdgeMesh::Arena* arena);
    // The triangle that holds p, walking from near's entry edge; throws
    // when p is a vertex (an unweighted insertion's location).
    EdgeRef locate_new(const Point& p, VertexIndex near) const;
    // can_insert_on_side's search: the edge whose left triangle holds p, or
    // kNoEdge when the insertion would not stay on the side.
    EdgeRef search_on_side(const Point& p, VertexIndex near, const Side& side) const;
    // std::logic_error unless slot is open and empty in an unweighted mesh
    // not shared.
    void require_open_slot(VertexIndex slot) const;
    // Unweighted: p becomes vertex v (its point already stored) inside the
    // face left of e, then the flips; new records from `arena`, or from the
    // mesh's free list and room if none.
    template <bool kShared>
    void connect_and_flip(const Point& p, EdgeRef e, VertexIndex v, QuadEdgeMesh::Arena* arena);
    // The new vertex's spokes to the corners of the face left of e (p on e
    // when on_edge): its ring before any flip; returns the first spoke.
    template <bool kShared>
    EdgeRef connect_spokes(EdgeRef e, VertexIndex v, bool on_edge, EdgeRef* link, QuadEdgeMesh::Arena* arena);
    // Removes vertex a, of degree 3, hidden by v.
    template <bool kShared>
    void hide_vertex(VertexIndex a, VertexIndex v);
    std::size_t degree(VertexIndex v) const;

    QuadEdgeMesh mesh_;
    std::vector<Point> points_;
    std::vector<EdgeRef> vertex_edge_;
    bool weighted_ = false;
    bool shared_ = false;  // set_shared
    std::vector<double> radii_;             // weighted only: per vertex (ghosts 0)
    std::vector<VertexIndex> hidden_by_;    // weighted only: who hid it, if hidden
    std::size_t hidden_count_ = 0;
};

}  // namespace pds

#endif
