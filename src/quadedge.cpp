// quadedge.cpp - edge algebra operators (Guibas & Stolfi 1985, section 4 and 6).
#include "quadedge.hpp"

#include <stdexcept>

namespace pds {

void QuadEdgeMesh::reserve(std::size_t records) {
    if (records > kMaxEdgeRecords) throw std::length_error("too many edges for 32-bit references");
    // vector::reserve either succeeds or changes nothing, so a failure here
    // leaves every edge as it was.
    next_.reserve(4 * records);
    org_.reserve(2 * records);
}

std::size_t QuadEdgeMesh::spare_records() const {
    const std::size_t by_next = (next_.capacity() - next_.size()) / 4;
    const std::size_t by_org = (org_.capacity() - org_.size()) / 2;
    return free_count_ + (by_next < by_org ? by_next : by_org);
}

EdgeRef QuadEdgeMesh::make_edge(std::uint32_t org, std::uint32_t dest) {
    EdgeRef e;
    if (free_list_ != kNoEdge) {
        e = free_list_;
        free_list_ = next_[e];
        --free_count_;
    } else {
        if (record_count() >= kMaxEdgeRecords) throw std::length_error("edge references exhausted");
        e = static_cast<EdgeRef>(next_.size());
        next_.resize(next_.size() + 4);
        org_.resize(org_.size() + 2);
    }
    // An isolated edge: each end is its own ring; the two dual quarters point at
    // each other (one face on both sides).
    next_[e] = e;
    next_[e + 1] = e + 3;
    next_[e + 2] = e + 2;
    next_[e + 3] = e + 1;
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
    next_[a] = t1;
    next_[b] = t2;
    next_[alpha] = t3;
    next_[beta] = t4;
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
    next_[e] = free_list_;
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

std::size_t QuadEdgeMesh::memory_bytes() const {
    return next_.capacity() * sizeof(EdgeRef) + org_.capacity() * sizeof(std::uint32_t);
}

}  // namespace pds
