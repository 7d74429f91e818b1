// free_area_tree.hpp - sums of free areas for weighted random selection
// (Jones 2006, section 3, steps 1, 4 and 5: the weighted tree W).
//
// An implicit 8-ary tree over the sites in insertion order. Level 0 holds the
// leaves (one free area per site); entry j of level k+1 is the sum of entries
// 8j .. 8j+7 of level k, added pairwise in a fixed order. Eight doubles fill one 64-byte
// cache line, so an update or a selection touches one line per level, about
// log8 N lines in all: at 10^6 sites 7 instead of the 20 of a binary tree.
//
// The paper inserts leaves at random positions to keep a pointer tree shallow
// and needs a hash map from vertex to leaf; an implicit tree is balanced by
// construction and the leaf is the site's index, so neither is needed.
//
// Invariant: every entry above the leaves is exactly the fixed-order
// floating-point sum of its eight children, always recomputed from them (never
// adjusted by deltas). So a group whose leaves are all 0 sums to exactly 0, and
// the root is 0 exactly when every cell is covered. Leaves are >= 0.
//
// Storage is reserved up front but each group of eight is written only when it
// comes into use, so room for many leaves costs address space, not memory.
#ifndef PDS_FREE_AREA_TREE_HPP
#define PDS_FREE_AREA_TREE_HPP

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <vector>

namespace pds {

class FreeAreaTree {
public:
    static constexpr std::size_t kFanout = 8;

    FreeAreaTree() = default;

    // Room for `leaves` leaves in all; strong guarantee (std::bad_alloc).
    void reserve(std::size_t leaves);
    std::size_t capacity() const { return capacity_; }
    std::size_t size() const { return size_; }

    // Appends a leaf (requires capacity) and updates its ancestors.
    void push_back(double weight);
    // Makes resident the pages of the leaves up to `leaves` in all
    // (core/page_hints.hpp); the tree is unchanged.
    void populate_for(std::size_t leaves) const;
    // Sets a leaf and updates its ancestors: O(log N).
    void set(std::size_t leaf, double weight);
    // Sets the number of leaves (requires capacity); new leaves must then be
    // written with set_leaf_only() before rebuild().
    void resize(std::size_t leaves) { size_ = leaves; }
    // Sets a leaf without touching ancestors; call rebuild() afterwards.
    void set_leaf_only(std::size_t leaf, double weight) { nodes_[leaf] = weight; }
    // Recomputes every used ancestor from its children: O(N).
    void rebuild();

    double weight(std::size_t leaf) const { return nodes_[leaf]; }
    double total() const { return capacity_ == 0 ? 0.0 : nodes_[offset_.back()]; }
    // The leaf whose cumulative range contains u, for u in [0, total());
    // requires total() > 0. Never returns a leaf of weight 0.
    std::size_t select(double u) const;
    // select() for n values at once, descending level by level for all of
    // them, so that their cache misses overlap instead of queueing.
    void select_many(const double* u, std::size_t n, std::size_t* leaves) const;

    // Calls visit(leaf) for every leaf of positive weight, in leaf order,
    // skipping zero subtrees, until visit returns false.
    template <class Visit>
    void for_each_positive(const Visit& visit) const {
        if (total() > 0.0) descend(offset_.size() - 1, 0, visit);
    }


private:
    struct Free {
        void operator()(double* p) const { std::free(p); }
    };
    // Entry j of level k is nodes_[offset_[k] + j]; level 0 starts at 0 and the
    // last level holds the root alone.
    double sum_of_children(std::size_t level, std::size_t j) const;
    // One step of the descent: the child of entry j (at `level`) that holds u.
    std::size_t pick_child(std::size_t level, std::size_t j, double& u) const;
    template <class Visit>
    bool descend(std::size_t level, std::size_t j, const Visit& visit) const {
        if (level == 0) return visit(j);
        const double* c = nodes_.get() + offset_[level - 1] + kFanout * j;
        for (std::size_t i = 0; i < kFanout; ++i)
            if (c[i] > 0.0 && !descend(level - 1, kFanout * j + i, visit)) return false;
        return true;
    }
    void update_ancestors(std::size_t leaf);

    std::unique_ptr<double[], Free> nodes_;
    std::vector<std::size_t> offset_;
    std::size_t capacity_ = 0;  // a multiple of kFanout (or 0)
    std::size_t size_ = 0;
};

}  // namespace pds

#endif
