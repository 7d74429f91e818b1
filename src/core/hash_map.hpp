// hash_map.hpp - open-addressing hash map from 64-bit keys to 32-bit values.
//
// Linear probing in a power-of-two table kept at most half full; no deletion
// (the users build a map once and read it). One key value, kEmptyKey, is
// reserved to mark free slots. Growth rehashes into a table twice as large and
// has the strong guarantee (std::bad_alloc leaves the map as it was).
//
// Used by the spatial index (spatial_hash.hpp), whose keys are grid cells: a
// sparse map keeps memory proportional to the points, not to the domain.
#ifndef PDS_HASH_MAP_HPP
#define PDS_HASH_MAP_HPP

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/rng.hpp"

namespace pds {

class HashMap {
public:
    static constexpr std::uint64_t kEmptyKey = ~std::uint64_t{0};

    // Room for `n` keys without growing.
    void reserve(std::size_t n) {
        std::size_t cap = 16;
        while (cap / 2 < n) cap *= 2;
        if (cap > slots_.size()) rehash(cap);
    }

    // The value stored for key, or nullptr.
    const std::uint32_t* find(std::uint64_t key) const {
        if (slots_.empty()) return nullptr;
        for (std::size_t i = index(key);; i = (i + 1) & mask()) {
            if (slots_[i].key == key) return &slots_[i].value;
            if (slots_[i].key == kEmptyKey) return nullptr;
        }
    }

    // Stores value for key (replacing any previous value). key != kEmptyKey.
    void insert_or_assign(std::uint64_t key, std::uint32_t value) {
        if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 16 : 2 * slots_.size());
        for (std::size_t i = index(key);; i = (i + 1) & mask()) {
            if (slots_[i].key == key) {
                slots_[i].value = value;
                return;
            }
            if (slots_[i].key == kEmptyKey) {
                slots_[i] = Slot{key, value};
                ++size_;
                return;
            }
        }
    }

    std::size_t size() const { return size_; }
    std::size_t slot_count() const { return slots_.size(); }

private:
    struct Slot {
        std::uint64_t key;
        std::uint32_t value;
    };

    std::size_t mask() const { return slots_.size() - 1; }
    // mix64 spreads nearby grid cells over the table.
    std::size_t index(std::uint64_t key) const { return static_cast<std::size_t>(mix64(key)) & mask(); }

    void rehash(std::size_t cap) {
        std::vector<Slot> fresh(cap, Slot{kEmptyKey, 0});
        const std::size_t m = cap - 1;
        for (const Slot& s : slots_) {
            if (s.key == kEmptyKey) continue;
            std::size_t i = static_cast<std::size_t>(mix64(s.key)) & m;
            while (fresh[i].key != kEmptyKey) i = (i + 1) & m;
            fresh[i] = s;
        }
        slots_.swap(fresh);
    }

    std::vector<Slot> slots_;
    std::size_t size_ = 0;
};

}  // namespace pds

#endif
