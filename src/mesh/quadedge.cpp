// quadedge.cpp - edge algebra operators (Guibas & Stolfi 1985, section 4 and 6).
#include "mesh/quadedge.hpp"

#include <stdexcept>

#include "core/huge_pages.hpp"

namespace pds {

void QuadEdgeMesh::reserve(std::size_t records) {
    if (records > kMaxEdgeRecords) throw std::length_error("too many edges for 32-bit references");
    // vector::reserve either succeeds or changes nothing, so a failure here
    // leaves every edge as it was.
    rec_.reserve(records);
    advise_huge_pages(rec_);
}

std::size_t QuadEdgeMesh::spare_records() const {
    return free_count_ + (rec_.capacity() - rec_.size());
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

}  // namespace pds
