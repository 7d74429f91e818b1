// relaxed.hpp - single words that one thread writes while another may read
// them: relaxed atomic loads and stores on plain memory.
//
// The mesh is written by the caller's thread while a helper walks it ahead
// of the insertions (jones/ring_prefetcher.hpp) to bring its lines near.
// The helper may see a word old or new, never torn, and needs nothing more:
// what it reads only chooses what to prefetch. The compilers' __atomic
// builtins (C++20's std::atomic_ref) make those accesses defined, and are
// plain moves on the machines we build for; the caller's own reads stay
// plain, as only the writer and the helper meet.
#ifndef PDS_RELAXED_HPP
#define PDS_RELAXED_HPP

#include <cstdint>

namespace pds {

// A word written or read while another thread may meet it (kShared: a
// relaxed atomic access), or plainly, which the compiler optimizes better.
template <bool kShared>
inline void store_word(std::uint32_t& word, std::uint32_t value) {
    if constexpr (kShared)
        __atomic_store_n(&word, value, __ATOMIC_RELAXED);
    else
        word = value;
}
template <bool kShared>
inline std::uint32_t load_word(const std::uint32_t& word) {
    if constexpr (kShared) return __atomic_load_n(&word, __ATOMIC_RELAXED);
    return word;
}

}  // namespace pds

#endif
