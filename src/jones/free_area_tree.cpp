// free_area_tree.cpp - implicit 8-ary sum tree (see free_area_tree.hpp).
#include "jones/free_area_tree.hpp"

#include <cstring>
#include <new>

#include "core/batch.hpp"
#include "core/page_hints.hpp"
#include "core/prefetch.hpp"

namespace pds {

namespace {

std::size_t round_up(std::size_t n, std::size_t m) { return (n + m - 1) / m * m; }

// sum_of_children and pick_child spell out the pairwise order of eight children.
static_assert(FreeAreaTree::kFanout == 8, "the pairwise sums are written for eight children");
// One group of children fills one 64-byte cache line.
static_assert(FreeAreaTree::kFanout * sizeof(double) == 64, "a group is one cache line");

}  // namespace

void FreeAreaTree::populate_for(std::size_t leaves) const {
    if (leaves > capacity_) leaves = capacity_;
    if (leaves > size_) populate_pages(nodes_.get() + size_, (leaves - size_) * sizeof(double));
}

void FreeAreaTree::reserve(std::size_t leaves) {
    if (leaves <= capacity_) return;
    // Grow at least geometrically, and keep every level a whole number of
    // cache-line groups so children of one parent share a line.
    std::size_t cap = round_up(leaves > 2 * capacity_ ? leaves : 2 * capacity_, kFanout);
    std::vector<std::size_t> offset;
    std::size_t total = 0, level = cap;
    for (;;) {
        offset.push_back(total);
        total += round_up(level, kFanout);
        if (level == 1) break;
        level = (level + kFanout - 1) / kFanout;
    }
    if (total > (static_cast<std::size_t>(-1) / 2) / sizeof(double)) throw std::bad_alloc();
    // 64-byte alignment: a group of eight children is exactly one cache line.
    // Not zeroed here: pages stay untouched until used. Each group of eight is
    // zeroed when it comes into use (push_back), and rebuild() writes every
    // used entry, so nothing uninitialized is ever read.
    void* raw = nullptr;
    if (posix_memalign(&raw, 64, total * sizeof(double)) != 0) throw std::bad_alloc();
    advise_huge_pages(raw, total * sizeof(double));
    std::unique_ptr<double[], Free> fresh(static_cast<double*>(raw));
    if (size_ != 0) std::memcpy(fresh.get(), nodes_.get(), size_ * sizeof(double));
    nodes_ = std::move(fresh);
    offset_.swap(offset);
    capacity_ = cap;
    rebuild();
}

double FreeAreaTree::sum_of_children(std::size_t level, std::size_t j) const {
    const double* c = nodes_.get() + offset_[level - 1] + kFanout * j;
    // Pairwise, in a fixed order (the same on every platform): pick_child
    // splits the group along the same pairs.
    return ((c[0] + c[1]) + (c[2] + c[3])) + ((c[4] + c[5]) + (c[6] + c[7]));
}

void FreeAreaTree::update_ancestors(std::size_t leaf) {
    std::size_t j = leaf;
    for (std::size_t level = 1; level < offset_.size(); ++level) {
        j /= kFanout;
        nodes_[offset_[level] + j] = sum_of_children(level, j);
    }
}

void FreeAreaTree::push_back(double weight) {
    // A new group of children starts zeroed, so its unused entries read as 0.
    if (size_ % kFanout == 0) {
        std::memset(nodes_.get() + size_, 0, kFanout * sizeof(double));
        for (std::size_t level = 1, j = size_ / kFanout; level < offset_.size(); ++level, j /= kFanout) {
            if (j % kFanout != 0) break;
            std::memset(nodes_.get() + offset_[level] + j, 0, kFanout * sizeof(double));
        }
    }
    nodes_[size_] = weight;
    ++size_;
    update_ancestors(size_ - 1);
}

void FreeAreaTree::set(std::size_t leaf, double weight) {
    nodes_[leaf] = weight;
    update_ancestors(leaf);
}

void FreeAreaTree::rebuild() {
    // Zero the tail of the last used group of every level, then recompute the
    // used prefix of each level from the one below.
    std::size_t used = size_;
    for (std::size_t level = 0; level < offset_.size(); ++level) {
        const std::size_t end = round_up(used == 0 ? 1 : used, kFanout);
        for (std::size_t k = used; k < end; ++k) nodes_[offset_[level] + k] = 0.0;
        if (level > 0)
            for (std::size_t j = 0; j < used; ++j) nodes_[offset_[level] + j] = sum_of_children(level, j);
        used = (used + kFanout - 1) / kFanout;
    }
}

std::size_t FreeAreaTree::pick_child(std::size_t level, std::size_t j, double& u) const {
    const double* c = nodes_.get() + offset_[level - 1] + kFanout * j;
    // Three halvings along the pairs sum_of_children adds: take the right part
    // when u is past the left one and the right one is not empty (rounding
    // may leave u at or past the end of the left part); so a part of sum 0 is
    // never entered and the leaf reached has positive weight. Written with
    // 0/1 integers and indexing, not branches: the choices are random, and a
    // mispredicted branch per level would cost more than the arithmetic.
    const double pair[4] = {c[0] + c[1], c[2] + c[3], c[4] + c[5], c[6] + c[7]};
    const double half[2] = {pair[0] + pair[1], pair[2] + pair[3]};
    const int r1 = (u >= half[0]) & (half[1] != 0.0);
    u -= half[0] * r1;
    const int r2 = (u >= pair[2 * r1]) & (pair[2 * r1 + 1] != 0.0);
    u -= pair[2 * r1] * r2;
    const int k = 4 * r1 + 2 * r2;
    const int r3 = (u >= c[k]) & (c[k + 1] != 0.0);
    u -= c[k] * r3;
    if (u < 0.0) u = 0.0;
    return kFanout * j + static_cast<std::size_t>(k + r3);
}

std::size_t FreeAreaTree::select(double u) const {
    std::size_t j = 0;
    for (std::size_t level = offset_.size() - 1; level > 0; --level) j = pick_child(level, j, u);
    return j;
}

void FreeAreaTree::select_many(const double* u, std::size_t n, std::size_t* leaves) const {
    double rest[kMaxBatch];
    for (std::size_t done = 0; done < n; done += kMaxBatch) {
        const std::size_t m = n - done < kMaxBatch ? n - done : kMaxBatch;
        for (std::size_t k = 0; k < m; ++k) {
            rest[k] = u[done + k];
            leaves[done + k] = 0;
        }
        for (std::size_t level = offset_.size() - 1; level > 0; --level) {
            // Ask for every group of this level first, then descend: the
            // loads are independent, so their misses overlap.
            for (std::size_t k = 0; k < m; ++k)
                pds::prefetch(nodes_.get() + offset_[level - 1] + kFanout * leaves[done + k]);
            for (std::size_t k = 0; k < m; ++k) leaves[done + k] = pick_child(level, leaves[done + k], rest[k]);
        }
    }
}

}  // namespace pds
