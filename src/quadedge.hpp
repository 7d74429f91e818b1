// quadedge.hpp - the Guibas-Stolfi quad-edge structure (ACM TOG 4(2), 1985).
//
// Every undirected edge is one record of four directed "quarter" edges: the
// edge e, its dual rot(e), its reverse sym(e) and rot(sym(e)). An edge
// reference packs record and rotation as 4 * record + r into a uint32, so rot,
// sym and rot_inv are bit operations and the whole mesh lives in two flat
// arrays (no pointers): next_ (one onext link per quarter edge) and org_ (the
// origin vertex of the two primal quarters; dual quarters carry no data).
//
// Invariants: for every live edge e, onext is a permutation whose cycles are the
// vertex rings, rot(onext(rot(onext(e)))) == e (the algebra's duality), and
// org(e) is the vertex whose ring contains e. Deleted records go on a free
// list threaded through next_, are marked by kNoVertex as origin, and are
// reused first.
#ifndef PDS_QUADEDGE_HPP
#define PDS_QUADEDGE_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

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

    // A new isolated edge org -> dest (its own ring at both ends).
    EdgeRef make_edge(std::uint32_t org, std::uint32_t dest);
    // Detaches e from the mesh and recycles its record.
    void delete_edge(EdgeRef e);
    // The splice operator: exchanges the rings of a and b (and of their duals).
    void splice(EdgeRef a, EdgeRef b);
    // A new edge from dest(a) to org(b), placed so that a, the new edge and b
    // share a left face.
    EdgeRef connect(EdgeRef a, EdgeRef b);
    // Turns e counterclockwise inside the quadrilateral formed by its two faces.
    void swap(EdgeRef e);

    static EdgeRef rot(EdgeRef e) { return (e & ~3u) | ((e + 1u) & 3u); }
    static EdgeRef sym(EdgeRef e) { return e ^ 2u; }
    static EdgeRef rot_inv(EdgeRef e) { return (e & ~3u) | ((e + 3u) & 3u); }

    EdgeRef onext(EdgeRef e) const { return next_[e]; }
    EdgeRef oprev(EdgeRef e) const { return rot(onext(rot(e))); }
    EdgeRef lnext(EdgeRef e) const { return rot(onext(rot_inv(e))); }
    EdgeRef lprev(EdgeRef e) const { return sym(onext(e)); }
    EdgeRef rnext(EdgeRef e) const { return rot_inv(onext(rot(e))); }
    EdgeRef rprev(EdgeRef e) const { return onext(sym(e)); }
    EdgeRef dnext(EdgeRef e) const { return sym(onext(sym(e))); }
    EdgeRef dprev(EdgeRef e) const { return rot_inv(onext(rot_inv(e))); }

    // Endpoints of a primal edge (rotation 0 or 2).
    std::uint32_t org(EdgeRef e) const { return org_[e >> 1]; }
    std::uint32_t dest(EdgeRef e) const { return org_[sym(e) >> 1]; }
    void set_endpoints(EdgeRef e, std::uint32_t org, std::uint32_t dest) {
        org_[e >> 1] = org;
        org_[sym(e) >> 1] = dest;
    }

    // Number of records ever handed out (live or free) and whether one is live.
    std::size_t record_count() const { return next_.size() / 4; }
    bool is_live(std::size_t record) const { return org_[2 * record] != kNoVertex; }
    std::size_t live_count() const { return live_edges_; }
    std::size_t memory_bytes() const;

private:
    std::vector<EdgeRef> next_;        // 4 per record
    std::vector<std::uint32_t> org_;   // 2 per record (primal quarters only)
    EdgeRef free_list_ = kNoEdge;      // record-0 quarters of deleted records
    std::size_t free_count_ = 0;
    std::size_t live_edges_ = 0;
};

}  // namespace pds

#endif
