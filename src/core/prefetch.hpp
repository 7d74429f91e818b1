// prefetch.hpp - ask for the cache line holding p before it is needed.
//
// The dart grids, the ring walks and the tree descents prefetch a batch
// ahead so that their cache misses overlap. Natively that is the prefetch
// instruction. WebAssembly has none (clang drops __builtin_prefetch there),
// so it reads one byte instead: a load whose value nobody waits for, which
// the processor running the engine still overlaps with the others. A hint
// only either way: it never changes a result.
//
// The read is skipped beyond the end of linear memory, where a load would
// trap and a prefetch would not: some prefetched addresses lie one row past
// an array's end.
#ifndef PDS_PREFETCH_HPP
#define PDS_PREFETCH_HPP

#include <cstdint>

namespace pds {

inline void prefetch(const void* p) {
#if defined(__wasm__)
    constexpr std::uintptr_t kWasmPage = 65536;
    const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(p);
    if (address < __builtin_wasm_memory_size(0) * kWasmPage) (void)*static_cast<const volatile char*>(p);
#else
    __builtin_prefetch(p);
#endif
}

}  // namespace pds

#endif
