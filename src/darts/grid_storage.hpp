// grid_storage.hpp - where a dart grid (dart_grid.hpp) keeps its cells' 8-byte
// words (0: an empty cell): two stores behind the same calls (get, set,
// prefetch, reserve), chosen at compile time, so a dart's test is the same
// code over either.
//
// DenseCells: one zeroed array over the whole padded grid. A dart's block is
// a few lines of it, prefetched a batch ahead. Zeroed memory is address
// space until points land; huge pages are asked for only once the points
// reserved would make most of its small pages resident anyway
// (huge_pages_worth): on 2 MiB pages each scattered point of a short run
// would make a whole huge page resident, so memory would follow the grid
// (the pattern that could be made) instead of the points made, while a full
// run still gets the large pages its random reads need. A polygon that keeps
// under half of the grid's cells gets neither: its writes miss most pages.
//
// SparseCells: the taken cells only, in an open-addressing table kept at
// most half full, reserved with the points (a write never allocates). For
// domains whose whole grid would not fit the address space: memory follows
// the points, at a probe or two per cell read.
#ifndef PDS_GRID_STORAGE_HPP
#define PDS_GRID_STORAGE_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "core/indices.hpp"
#include "core/page_hints.hpp"
#include "core/rng.hpp"
#include "core/prefetch.hpp"

namespace pds {

class DenseCells {
public:
    DenseCells() = default;
    // `cells` zeroed words; throws std::bad_alloc.
    explicit DenseCells(GridCell cells) {
        if (cells > static_cast<std::size_t>(-1) / sizeof(std::uint64_t)) throw std::bad_alloc();
        bytes_ = static_cast<std::size_t>(cells) * sizeof(std::uint64_t);
        words_.reset(static_cast<std::uint64_t*>(std::calloc(static_cast<std::size_t>(cells), sizeof(std::uint64_t))));
        if (!words_) throw std::bad_alloc();
    }

    // A cell's number is below the array's size, so it fits a size_t.
    std::uint64_t get(GridCell cell) const { return words_[static_cast<std::size_t>(cell)]; }
    void set(GridCell cell, std::uint64_t word) { words_[static_cast<std::size_t>(cell)] = word; }
    void prefetch(GridCell cell) const { pds::prefetch(words_.get() + static_cast<std::size_t>(cell)); }
    // The same, for a grid that threads read while one of them writes (the
    // space-time stage's bands): relaxed atomic accesses, a plain load or
    // store on the machines we build for, but defined behaviour.
    std::uint64_t load(GridCell cell) const {
        return __atomic_load_n(words_.get() + static_cast<std::size_t>(cell), __ATOMIC_RELAXED);
    }
    void store(GridCell cell, std::uint64_t word) {
        __atomic_store_n(words_.get() + static_cast<std::size_t>(cell), word, __ATOMIC_RELAXED);
    }

    // Room for `points` points writing `writes` cells in all (never fails:
    // the array is whole). Once the points are worth them (copies on a
    // torus are few: they are not counted), asks for huge pages, and has
    // the pages made writable in one call: else each is read first (the
    // darts' checks map the shared zero page) and faults again when written,
    // and on a threaded run that second fault flushes every core's TLB.
    void reserve(std::size_t points, std::size_t) {
        if (populated_ || !words_ || !spread_ || !huge_pages_worth(bytes_, points)) return;
        advised_ = advise_huge_pages(words_.get(), bytes_);
        populated_bytes_ = populate_pages(words_.get(), bytes_);
        populated_ = true;
    }
    bool has_room_for(std::size_t, std::size_t) const { return true; }
    // Writes will land only in `cells` of the array's cells (those a polygon
    // keeps). Under half of them, the pages are left to be made resident
    // one by one as points land: huge pages, or all pages made writable,
    // would make the grid over the polygon's bounding box resident, not the
    // polygon's cells (a thin ring across its box: 1.6 GB against 0.2).
    void writes_only_in(GridCell cells) { spread_ = 2 * cells >= bytes_ / sizeof(std::uint64_t); }
    // Bytes under the huge-page hint (0: none asked), bytes made writable
    // ahead (0: none, or no support), and the words (tests).
    std::size_t advised_bytes() const { return advised_; }
    std::size_t populated_bytes() const { return populated_bytes_; }
    const std::uint64_t* words() const { return words_.get(); }
    void release() { words_.reset(); }

private:
    struct Free {
        void operator()(std::uint64_t* p) const { std::free(p); }
    };
    std::unique_ptr<std::uint64_t[], Free> words_;
    std::size_t bytes_ = 0;
    std::size_t advised_ = 0;
    std::size_t populated_bytes_ = 0;
    bool populated_ = false;
    bool spread_ = true;  // writes may land anywhere in the array
};

class SparseCells {
public:
    SparseCells() { reserve(0, 1); }
    explicit SparseCells(GridCell) : SparseCells() {}

    std::uint64_t get(GridCell cell) const {
        for (std::size_t i = slot_of(cell);; i = (i + 1) & mask_) {
            const Slot& s = slots_[i];
            if (s.word == 0 || s.cell == cell) return s.word;
        }
    }
    // word != 0; requires room (reserve).
    void set(GridCell cell, std::uint64_t word) {
        std::size_t i = slot_of(cell);
        while (slots_[i].word != 0 && slots_[i].cell != cell) i = (i + 1) & mask_;
        if (slots_[i].word == 0) ++used_;
        slots_[i] = Slot{cell, word};
    }
    void prefetch(GridCell cell) const { pds::prefetch(&slots_[slot_of(cell)]); }

    // Room for `writes` taken cells in all (the points' and their copies');
    // strong guarantee (std::bad_alloc).
    void reserve(std::size_t, std::size_t writes) {
        if (has_room_for(0, writes)) return;
        std::size_t size = 16;
        while (size / 2 < writes) size *= 2;
        std::vector<Slot> fresh(size, Slot{0, 0});
        const std::size_t mask = size - 1;
        for (const Slot& s : slots_) {
            if (s.word == 0) continue;
            std::size_t i = slot_in(s.cell, mask);
            while (fresh[i].word != 0) i = (i + 1) & mask;
            fresh[i] = s;
        }
        slots_.swap(fresh);
        mask_ = mask;
    }
    bool has_room_for(std::size_t, std::size_t writes) const { return slots_.size() / 2 >= writes && !slots_.empty(); }
    void writes_only_in(GridCell) {}  // memory follows the points already
    std::size_t advised_bytes() const { return 0; }
    // Taken cells (tests).
    std::size_t taken() const { return used_; }
    void release() {
        slots_ = std::vector<Slot>();
        mask_ = 0;
        used_ = 0;
    }

private:
    struct Slot {
        GridCell cell;
        std::uint64_t word;  // 0: a free slot
    };
    // mix64 spreads runs of kRun cells along a row over the table, each run
    // to kRun slots side by side: a dart's block reads a row's few cells
    // from one or two lines, as the dense store does, not from one line each.
    static constexpr unsigned kRunBits = 3;
    static std::size_t mix(std::uint64_t x) { return static_cast<std::size_t>(mix64(x)); }
    static std::size_t slot_in(GridCell cell, std::size_t mask) {
        constexpr GridCell kRunMask = (GridCell{1} << kRunBits) - 1;
        return ((mix(cell >> kRunBits) << kRunBits) | static_cast<std::size_t>(cell & kRunMask)) & mask;
    }
    std::size_t slot_of(GridCell cell) const { return slot_in(cell, mask_); }

    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::size_t used_ = 0;
};

}  // namespace pds

#endif
