// free_area_tree.hpp - sums of free areas for weighted random selection
// (Jones 2006, section 3, steps 1, 4 and 5: the weighted tree W).
//
// An implicit complete binary tree over the sites in insertion order: node k
// has children 2k and 2k+1, the root is node 1, leaf i is node L + i where L
// (the capacity) is a power of two. Selection descends from the root in
// O(log N), choosing a child with probability proportional to its sum.
//
// The paper inserts leaves at random positions to keep a pointer tree shallow
// and needs a hash map from vertex to leaf; an implicit tree is balanced by
// construction and the leaf is the site's index, so neither is needed.
//
// Invariant: every parent is exactly fl(left + right) of its children, always
// recomputed from them (never adjusted by deltas), so a subtree whose leaves
// are all 0 sums to exactly 0, and the root is 0 exactly when every cell is
// covered. Leaves are >= 0.
//
// Storage comes from calloc: reserving room for many leaves costs address
// space, not memory, until the leaves are used.
#ifndef PDS_FREE_AREA_TREE_HPP
#define PDS_FREE_AREA_TREE_HPP

#include <cstddef>
#include <cstdlib>
#include <memory>

namespace pds {

class FreeAreaTree {
public:
    FreeAreaTree() = default;

    // Room for `leaves` leaves in all; strong guarantee (std::bad_alloc).
    void reserve(std::size_t leaves);
    std::size_t capacity() const { return capacity_; }
    std::size_t size() const { return size_; }

    // Appends a leaf (requires capacity) and updates its ancestors.
    void push_back(double weight);
    // Sets a leaf and updates its ancestors: O(log N).
    void set(std::size_t leaf, double weight);
    // Sets a leaf without touching ancestors; call rebuild() afterwards.
    void set_leaf_only(std::size_t leaf, double weight) { nodes_[capacity_ + leaf] = weight; }
    // Recomputes every used ancestor from its children: O(N).
    void rebuild();

    double weight(std::size_t leaf) const { return nodes_[capacity_ + leaf]; }
    double total() const { return capacity_ == 0 ? 0.0 : nodes_[1]; }
    // The leaf whose cumulative range contains u, for u in [0, total());
    // requires total() > 0. Never returns a leaf of weight 0.
    std::size_t select(double u) const;

    std::size_t memory_bytes() const { return 2 * capacity_ * sizeof(double); }

private:
    struct Free {
        void operator()(double* p) const { std::free(p); }
    };
    void update_ancestors(std::size_t node);

    std::unique_ptr<double[], Free> nodes_;  // 2 * capacity_ doubles; [0] unused
    std::size_t capacity_ = 0;               // L, a power of two (or 0)
    std::size_t size_ = 0;
};

}  // namespace pds

#endif
