// quadedge.cpp - edge algebra operators (Guibas & Stolfi 1985, section 4 and 6).
#include "mesh/quadedge.hpp"

#include <stdexcept>

#include "core/page_hints.hpp"

namespace pds {

void QuadEdgeMesh::reserve(std::size_t records) {
    if (records > kMaxEdgeRecords) throw std::length_error("too many edges for 32-bit references");
    // vector::reserve either succeeds or changes nothing, so a failure here
    // leaves every edge as it was.
    rec_.reserve(records);
    advise_huge_pages(rec_);
}

void QuadEdgeMesh::populate_for(std::size_t records) const { populate_ahead(rec_, records); }

std::size_t QuadEdgeMesh::spare_records() const {
    return free_count_ + (rec_.capacity() - rec_.size());
}

bool QuadEdgeMesh::lay_out_for_arenas(std::size_t records) {
    if (records > rec_.capacity()) return false;
    rec_.resize(records);  // within the room: does not allocate
    free_list_ = kNoEdge;
    free_count_ = 0;
    live_edges_ = 0;
    return true;
}

QuadEdgeMesh::Arena QuadEdgeMesh::join(Arena a, const Arena& b) {
    // a's records never handed out go on its free list, then b's list follows.
    for (; a.next != a.end; ++a.next) {
        const EdgeRef e = 4 * a.next;
        set_endpoints(e, kNoVertex, kNoVertex);
        set_next(e, a.free_head);
        if (a.free_head == kNoEdge) a.free_tail = e;
        a.free_head = e;
        ++a.free_count;
    }
    if (a.free_head == kNoEdge) {
        a.free_head = b.free_head;
        a.free_tail = b.free_tail;
    } else if (b.free_head != kNoEdge) {
        set_next(a.free_tail, b.free_head);
        a.free_tail = b.free_tail;
    }
    a.free_count += b.free_count;
    a.next = b.next;
    a.end = b.end;
    a.live_change += b.live_change;
    return a;
}

void QuadEdgeMesh::close_arenas(Arena last) {
    last = join(last, arena(0, 0));
    free_list_ = last.free_head;
    free_count_ = last.free_count;
    live_edges_ = rec_.size() - free_count_;
}

QuadEdgeMesh::Arena QuadEdgeMesh::append_arena(std::size_t records) {
    const std::size_t first = rec_.size();
    if (records > rec_.capacity() - first) throw std::logic_error("an appended arena beyond the reserved room");
    rec_.resize(first + records);  // within the room: does not allocate, and leaves the records unset
    return arena(static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(first + records));
}

void QuadEdgeMesh::close_appended(const Arena& appended) {
    const Arena a = join(appended, arena(0, 0));
    if (a.free_head != kNoEdge) {
        set_next(a.free_tail, free_list_);
        free_list_ = a.free_head;
    }
    free_count_ += a.free_count;
    live_edges_ = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(live_edges_) + a.live_change);
}

}  // namespace pds
