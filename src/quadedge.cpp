// quadedge.cpp - edge algebra operators (Guibas & Stolfi 1985, section 4 and 6).
#include "quadedge.hpp"

#include <stdexcept>

namespace pds {

void QuadEdgeMesh::reserve(std::size_t records) {
    if (records > kMaxEdgeRecords) throw std::length_error("too many edges for 32-bit references");
    // vector::reserve either succeeds or changes nothing, so a failure here
    // leaves every edge as it was.
    rec_.reserve(records);
}

std::size_t QuadEdgeMesh::spare_records() const {
    return free_count_ + (rec_.capacity() - rec_.size());
}

EdgeRef QuadEdgeMesh::make_edge(std::uint32_t org, std::uint32_t dest) {
    EdgeRef e;
    if (free_list_ != kNoEdge) {
        e = free_list_;
        free_list_ = next_of(e);
        --free_count_;
    } else {
        if (record_count() >= kMaxEdgeRecords) throw std::length_error("edge references exhausted");
        e = static_cast<EdgeRef>(4 * rec_.size());
        rec_.emplace_back();
    }
    // An isolated edge: each end is its own ring; the two dual quarters point at
    // each other (one face on both sides).
    Record& r = rec_[e >> 2];
    r.next[0] = e;
    r.next[1] = e + 3;
    r.next[2] = e + 2;
    r.next[3] = e + 1;
    set_endpoints(e, org, dest);
    ++live_edges_;
    return e;
}

void QuadEdgeMesh::splice(EdgeRef a, EdgeRef b) {
    const EdgeRef alpha = rot(onext(a));
    const EdgeRef beta = rot(onext(b));
    const EdgeRef t1 = onext(b);
    const EdgeRef t2 = onext(a);
    const EdgeRef t3 = onext(beta);
    const EdgeRef t4 = onext(alpha);
    next_of(a) = t1;
    next_of(b) = t2;
    next_of(alpha) = t3;
    next_of(beta) = t4;
}

EdgeRef QuadEdgeMesh::connect(EdgeRef a, EdgeRef b) {
    const EdgeRef e = make_edge(dest(a), org(b));
    splice(e, lnext(a));
    splice(sym(e), b);
    return e;
}

void QuadEdgeMesh::delete_edge(EdgeRef e) {
    e &= ~3u;
    splice(e, oprev(e));
    splice(sym(e), oprev(sym(e)));
    set_endpoints(e, kNoVertex, kNoVertex);
    next_of(e) = free_list_;
    free_list_ = e;
    ++free_count_;
    --live_edges_;
}

void QuadEdgeMesh::swap(EdgeRef e) {
    const EdgeRef a = oprev(e);
    const EdgeRef b = oprev(sym(e));
    splice(e, a);
    splice(sym(e), b);
    splice(e, lnext(a));
    splice(sym(e), lnext(b));
    set_endpoints(e, dest(a), dest(b));
}


}  // namespace pds
