// quadedge.hpp - the Guibas-Stolfi quad-edge structure (ACM TOG 4(2), 1985).
//
// Every undirected edge is one record of four directed "quarter" edges: the
// edge e, its dual rot(e), its reverse sym(e) and rot(sym(e)). An edge
// reference packs record and rotation as 4 * record + r into a uint32, so rot,
// sym and rot_inv are bit operations and the whole mesh lives in one flat
// array of 24-byte records (no pointers): four onext links, one per quarter,
// and the origin vertices of the two primal quarters (dual quarters carry no
// data). Links and origins share a record because walking a vertex ring reads
// both: one cache line instead of two.
//
// Invariants: for every live edge e, onext is a permutation whose cycles are the
// vertex rings, rot(onext(rot(onext(e)))) == e (the algebra's duality), and
// org(e) is the vertex whose ring contains e. Deleted records go on a free
// list threaded through their first link, are marked by kNoVertex as origin, and are
// reused first.
//
// The operators that change the mesh take kShared: true while a helper
// thread may walk the rings (load_onext, load_org), as one does ahead
// of the free regions' insertions; their links and origins are then
// written by relaxed atomic stores (core/relaxed.hpp). Plain stores
// otherwise: the atomic ones keep the compiler from reusing what it wrote
// (2-4% of a one-thread run at 10^6 points).
#ifndef PDS_QUADEDGE_HPP
#define PDS_QUADEDGE_HPP

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/relaxed.hpp"

namespace pds {

using EdgeRef = std::uint32_t;
constexpr EdgeRef kNoEdge = 0xFFFFFFFFu;
constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;
// Largest number of records: 4 * records must stay below kNoEdge.
constexpr std::size_t kMaxEdgeRecords = (std::size_t{1} << 30) - 1;

class QuadEdgeMesh {
public:
    // Makes room for `records` edges in all; may throw std::bad_alloc, and then
    // changes nothing.
    void reserve(std::size_t records);
    // Records the next make_edge calls can take without allocating.
    std::size_t spare_records() const;
    // Records append_arena can take: only those past the last, never free ones.
    std::size_t appendable_records() const { return rec_.capacity() - rec_.size(); }
    // Makes resident the pages of the records up to `records` in all that
    // new edges will take (core/page_hints.hpp); the edges are unchanged.
    void populate_for(std::size_t records) const;

    // A new isolated edge org -> dest (its own ring at both ends).
    template <bool kShared = false>
    EdgeRef make_edge(std::uint32_t org, std::uint32_t dest);
    // Detaches e from the mesh and recycles its record.
    template <bool kShared = false>
    void delete_edge(EdgeRef e);
    // The splice operator: exchanges the rings of a and b (and of their duals).
    template <bool kShared = false>
    void splice(EdgeRef a, EdgeRef b);
    // A new edge from dest(a) to org(b), placed so that a, the new edge and b
    // share a left face.
    template <bool kShared = false>
    EdgeRef connect(EdgeRef a, EdgeRef b);
    // Turns e counterclockwise inside the quadrilateral formed by its two faces.
    template <bool kShared = false>
    void swap(EdgeRef e);

    static EdgeRef rot(EdgeRef e) { return (e & ~3u) | ((e + 1u) & 3u); }
    static EdgeRef sym(EdgeRef e) { return e ^ 2u; }
    static EdgeRef rot_inv(EdgeRef e) { return (e & ~3u) | ((e + 3u) & 3u); }

    EdgeRef onext(EdgeRef e) const { return rec_[e >> 2].next[e & 3u]; }
    // onext, org, oprev and lnext, as a reader on another thread reads them
    // while the mesh changes (kShared: a link or an origin, old or new), or
    // plainly.
    template <bool kShared>
    EdgeRef load_onext(EdgeRef e) const {
        return load_word<kShared>(rec_[e >> 2].next[e & 3u]);
    }
    template <bool kShared>
    std::uint32_t load_org(EdgeRef e) const {
        return load_word<kShared>(rec_[e >> 2].org[(e >> 1) & 1u]);
    }
    template <bool kShared>
    EdgeRef load_oprev(EdgeRef e) const { return rot(load_onext<kShared>(rot(e))); }
    template <bool kShared>
    EdgeRef load_lnext(EdgeRef e) const { return rot(load_onext<kShared>(rot_inv(e))); }
    EdgeRef oprev(EdgeRef e) const { return load_oprev<false>(e); }
    EdgeRef lnext(EdgeRef e) const { return load_lnext<false>(e); }
    EdgeRef lprev(EdgeRef e) const { return sym(onext(e)); }
    EdgeRef rnext(EdgeRef e) const { return rot_inv(onext(rot(e))); }
    EdgeRef rprev(EdgeRef e) const { return onext(sym(e)); }
    EdgeRef dnext(EdgeRef e) const { return sym(onext(sym(e))); }
    EdgeRef dprev(EdgeRef e) const { return rot_inv(onext(rot_inv(e))); }

    // Endpoints of a primal edge (rotation 0 or 2).
    std::uint32_t org(EdgeRef e) const { return rec_[e >> 2].org[(e >> 1) & 1u]; }
    std::uint32_t dest(EdgeRef e) const { return rec_[e >> 2].org[((e >> 1) & 1u) ^ 1u]; }
    template <bool kShared = false>
    void set_endpoints(EdgeRef e, std::uint32_t org, std::uint32_t dest) {
        Record& r = rec_[e >> 2];
        store_word<kShared>(r.org[(e >> 1) & 1u], org);
        store_word<kShared>(r.org[((e >> 1) & 1u) ^ 1u], dest);
    }

    // Building a mesh whole, in parts side by side (delaunay_build.cpp):
    // each part takes records from its own arena, a range of the array with
    // its own free list, so parts running at once never share a record, and
    // the records a part gets do not depend on what runs beside it.
    struct Arena {
        EdgeRef free_head = kNoEdge, free_tail = kNoEdge;  // record-0 quarters
        std::size_t free_count = 0;
        std::uint32_t next = 0, end = 0;  // records [next, end) never handed out
        std::ptrdiff_t live_change = 0;   // edges made less edges deleted
    };
    // Drops every edge and lays out `records` unused records for arenas;
    // false (and nothing changed) when that is more than reserve() made room for.
    bool lay_out_for_arenas(std::size_t records);
    static Arena arena(std::uint32_t first, std::uint32_t end) { return Arena{kNoEdge, kNoEdge, 0, first, end}; }
    EdgeRef make_edge(Arena& arena, std::uint32_t org, std::uint32_t dest);
    void delete_edge(Arena& arena, EdgeRef e);
    EdgeRef connect(Arena& arena, EdgeRef a, EdgeRef b);
    // The arena of a part made of parts a and b (a's spare records first).
    Arena join(Arena a, const Arena& b);
    // Ends the build: the last arena's spare records become the free list.
    void close_arenas(Arena last);
    // Insertions side by side into a whole mesh (delaunay_sides.cpp): an
    // arena of `records` new records after the last, within the room
    // reserve() made (std::logic_error beyond it); and its end, its spare
    // and freed records put before the free list and its edges counted.
    // Neither runs while another thread uses the mesh.
    Arena append_arena(std::size_t records);
    void close_appended(const Arena& arena);

    // Number of records ever handed out (live or free) and whether one is live.
    std::size_t record_count() const { return rec_.size(); }
    bool is_live(std::size_t record) const { return rec_[record].org[0] != kNoVertex; }
    // The record of e, for prefetching.
    const void* record_address(EdgeRef e) const { return &rec_[e >> 2]; }
    // Whether e names a record of the array (handed out or not): what a
    // reader of a mesh that changes checks before following a link.
    bool within(EdgeRef e) const { return (e >> 2) < rec_.capacity(); }
    std::size_t live_count() const { return live_edges_; }

private:
    struct Record {
        // Left unset: a record is written whole when handed out, and laying
        // out a build's records must not write (and fault in) them all on one
        // thread before its parts write them side by side.
        Record() {}  // NOLINT: no member initializers on purpose
        EdgeRef next[4];           // onext of quarters 0..3
        std::uint32_t org[2];      // origins of quarters 0 and 2
    };
    template <bool kShared = false>
    void set_next(EdgeRef e, EdgeRef next) { store_word<kShared>(rec_[e >> 2].next[e & 3u], next); }
    // Makes record e an isolated edge org -> dest.
    template <bool kShared = false>
    void init_edge(EdgeRef e, std::uint32_t org, std::uint32_t dest);
    // Takes e out of its rings and marks its record unused.
    template <bool kShared = false>
    void detach(EdgeRef e);

    std::vector<Record> rec_;
    EdgeRef free_list_ = kNoEdge;      // record-0 quarters of deleted records
    std::size_t free_count_ = 0;
    std::size_t live_edges_ = 0;
};

// The operators below are inline: insertion and flips call them in their
// innermost loops.

template <bool kShared>
inline void QuadEdgeMesh::init_edge(EdgeRef e, std::uint32_t org, std::uint32_t dest) {
    // An isolated edge: each end is its own ring; the two dual quarters point at
    // each other (one face on both sides).
    Record& r = rec_[e >> 2];
    store_word<kShared>(r.next[0], e);
    store_word<kShared>(r.next[1], e + 3);
    store_word<kShared>(r.next[2], e + 2);
    store_word<kShared>(r.next[3], e + 1);
    set_endpoints<kShared>(e, org, dest);
}

template <bool kShared>
inline EdgeRef QuadEdgeMesh::make_edge(std::uint32_t org, std::uint32_t dest) {
    EdgeRef e;
    if (free_list_ != kNoEdge) {
        e = free_list_;
        free_list_ = onext(e);
        --free_count_;
    } else {
        if (record_count() >= kMaxEdgeRecords) throw std::length_error("edge references exhausted");
        e = static_cast<EdgeRef>(4 * rec_.size());
        rec_.emplace_back();
    }
    init_edge<kShared>(e, org, dest);
    ++live_edges_;
    return e;
}

inline EdgeRef QuadEdgeMesh::make_edge(Arena& arena, std::uint32_t org, std::uint32_t dest) {
    EdgeRef e;
    if (arena.free_head != kNoEdge) {
        e = arena.free_head;
        arena.free_head = onext(e);
        if (arena.free_head == kNoEdge) arena.free_tail = kNoEdge;
        --arena.free_count;
    } else {
        if (arena.next == arena.end) throw std::logic_error("a mesh part outgrew its arena");
        e = 4 * arena.next++;
    }
    init_edge(e, org, dest);
    ++arena.live_change;
    return e;
}

template <bool kShared>
inline void QuadEdgeMesh::splice(EdgeRef a, EdgeRef b) {
    const EdgeRef alpha = rot(onext(a));
    const EdgeRef beta = rot(onext(b));
    const EdgeRef t1 = onext(b);
    const EdgeRef t2 = onext(a);
    const EdgeRef t3 = onext(beta);
    const EdgeRef t4 = onext(alpha);
    set_next<kShared>(a, t1);
    set_next<kShared>(b, t2);
    set_next<kShared>(alpha, t3);
    set_next<kShared>(beta, t4);
}

template <bool kShared>
inline EdgeRef QuadEdgeMesh::connect(EdgeRef a, EdgeRef b) {
    const EdgeRef e = make_edge<kShared>(dest(a), org(b));
    splice<kShared>(e, lnext(a));
    splice<kShared>(sym(e), b);
    return e;
}

inline EdgeRef QuadEdgeMesh::connect(Arena& arena, EdgeRef a, EdgeRef b) {
    const EdgeRef e = make_edge(arena, dest(a), org(b));
    splice(e, lnext(a));
    splice(sym(e), b);
    return e;
}

template <bool kShared>
inline void QuadEdgeMesh::detach(EdgeRef e) {
    splice<kShared>(e, oprev(e));
    splice<kShared>(sym(e), oprev(sym(e)));
    set_endpoints<kShared>(e, kNoVertex, kNoVertex);
}

template <bool kShared>
inline void QuadEdgeMesh::delete_edge(EdgeRef e) {
    e &= ~3u;
    detach<kShared>(e);
    set_next<kShared>(e, free_list_);
    free_list_ = e;
    ++free_count_;
    --live_edges_;
}

inline void QuadEdgeMesh::delete_edge(Arena& arena, EdgeRef e) {
    e &= ~3u;
    detach(e);
    set_next(e, arena.free_head);
    if (arena.free_head == kNoEdge) arena.free_tail = e;
    arena.free_head = e;
    ++arena.free_count;
    --arena.live_change;
}

template <bool kShared>
inline void QuadEdgeMesh::swap(EdgeRef e) {
    const EdgeRef a = oprev(e);
    const EdgeRef b = oprev(sym(e));
    splice<kShared>(e, a);
    splice<kShared>(sym(e), b);
    splice<kShared>(e, lnext(a));
    splice<kShared>(sym(e), lnext(b));
    set_endpoints<kShared>(e, dest(a), dest(b));
}

}  // namespace pds

#endif
