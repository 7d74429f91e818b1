// grid_storage.hpp - where a dart grid (dart_grid.hpp) keeps its cells' 8-byte
// words (0: an empty cell), behind four calls (get, set, prefetch, reserve)
// chosen at compile time, so a dart's test is the same code over any store.
//
// DenseCells: one zeroed array over the whole padded grid. A dart's block is
// a few lines of it, prefetched a batch ahead. Zeroed memory is address
// space until points land; huge pages are asked for only once the points
// reserved would make most of its small pages resident anyway
// (huge_pages_worth): on 2 MiB pages each scattered point of a short run
// would make a whole huge page resident, so memory would follow the grid
// (the pattern that could be made) instead of the points made, while a full
// run still gets the large pages its random reads need.
#ifndef PDS_GRID_STORAGE_HPP
#define PDS_GRID_STORAGE_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "core/huge_pages.hpp"

namespace pds {

class DenseCells {
public:
    DenseCells() = default;
    // `cells` zeroed words; throws std::bad_alloc.
    explicit DenseCells(std::size_t cells) : bytes_(cells * sizeof(std::uint64_t)) {
        if (cells > static_cast<std::size_t>(-1) / sizeof(std::uint64_t)) throw std::bad_alloc();
        words_.reset(static_cast<std::uint64_t*>(std::calloc(cells, sizeof(std::uint64_t))));
        if (!words_) throw std::bad_alloc();
    }

    std::uint64_t get(std::size_t cell) const { return words_[cell]; }
    void set(std::size_t cell, std::uint64_t word) { words_[cell] = word; }
    void prefetch(std::size_t cell) const { __builtin_prefetch(words_.get() + cell); }

    // Room for `points` points writing `writes` cells in all (never fails:
    // the array is whole); asks for huge pages once the points are worth
    // them (copies on a torus are few: they are not counted).
    void reserve(std::size_t points, std::size_t) {
        if (advised_ == 0 && words_ && huge_pages_worth(bytes_, points))
            advised_ = advise_huge_pages(words_.get(), bytes_);
    }
    bool has_room_for(std::size_t, std::size_t) const { return true; }
    // Bytes under the huge-page hint (0: none asked; tests).
    std::size_t advised_bytes() const { return advised_; }
    void release() { words_.reset(); }

private:
    struct Free {
        void operator()(std::uint64_t* p) const { std::free(p); }
    };
    std::unique_ptr<std::uint64_t[], Free> words_;
    std::size_t bytes_ = 0;
    std::size_t advised_ = 0;
};

}  // namespace pds

#endif
