// free_area_tree.cpp - implicit sum tree (see free_area_tree.hpp).
#include "free_area_tree.hpp"

#include <cstring>
#include <new>

namespace pds {

void FreeAreaTree::reserve(std::size_t leaves) {
    if (leaves <= capacity_) return;
    std::size_t cap = capacity_ == 0 ? 1 : capacity_;
    while (cap < leaves) {
        if (cap > (static_cast<std::size_t>(-1) / 4) / sizeof(double)) throw std::bad_alloc();
        cap *= 2;
    }
    double* raw = static_cast<double*>(std::calloc(2 * cap, sizeof(double)));
    if (raw == nullptr) throw std::bad_alloc();
    std::unique_ptr<double[], Free> fresh(raw);
    if (size_ != 0) std::memcpy(raw + cap, nodes_.get() + capacity_, size_ * sizeof(double));
    nodes_ = std::move(fresh);
    capacity_ = cap;
    rebuild();
}

void FreeAreaTree::update_ancestors(std::size_t node) {
    double* n = nodes_.get();
    while (node > 1) {
        node >>= 1;
        n[node] = n[2 * node] + n[2 * node + 1];
    }
}

void FreeAreaTree::push_back(double weight) {
    nodes_[capacity_ + size_] = weight;
    ++size_;
    update_ancestors(capacity_ + size_ - 1);
}

void FreeAreaTree::set(std::size_t leaf, double weight) {
    nodes_[capacity_ + leaf] = weight;
    update_ancestors(capacity_ + leaf);
}

void FreeAreaTree::rebuild() {
    // Only ancestors of used leaves: the rest are zero from calloc and stay so,
    // which keeps untouched pages untouched.
    double* n = nodes_.get();
    std::size_t lo = capacity_, hi = capacity_ + size_;  // used nodes of this level: [lo, hi)
    while (lo > 1) {
        const std::size_t plo = lo / 2, phi = (hi + 1) / 2;
        for (std::size_t k = plo; k < phi; ++k) n[k] = n[2 * k] + n[2 * k + 1];
        lo = plo;
        hi = phi;
    }
}

std::size_t FreeAreaTree::select(double u) const {
    const double* n = nodes_.get();
    std::size_t k = 1;
    while (k < capacity_) {
        const double left = n[2 * k], right = n[2 * k + 1];
        // Rounding may leave u at or past the last nonzero child; never step
        // into a child whose sum is 0.
        if (u < left || right == 0.0) {
            k = 2 * k;
        } else {
            u -= left;
            k = 2 * k + 1;
        }
    }
    return k - capacity_;
}

}  // namespace pds
