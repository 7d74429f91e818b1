// page_hints.cpp - see page_hints.hpp.
#include "core/page_hints.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pds {

namespace {

// The whole `align`-sized units inside [p, p + bytes): a partial unit at
// either end may hold live entries, or belong to another array.
struct Units {
    std::uintptr_t begin, end;
    bool empty() const { return end <= begin; }
    void* start() const { return reinterpret_cast<void*>(begin); }
    std::size_t bytes() const { return end - begin; }
};
[[maybe_unused]] Units whole_units(const void* p, std::size_t bytes, std::uintptr_t align) {
    const std::uintptr_t at = reinterpret_cast<std::uintptr_t>(p);
    if (p == nullptr) return Units{0, 0};
    return Units{(at + align - 1) & ~(align - 1), (at + bytes) & ~(align - 1)};
}

}  // namespace

std::size_t advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::size_t kMinBytes = std::size_t{128} << 20;
    const Units units = whole_units(p, bytes, std::uintptr_t{1} << 21);
    if (bytes < kMinBytes || units.empty()) return 0;
    // A refused hint leaves ordinary pages: nothing to undo.
    (void)madvise(units.start(), units.bytes(), MADV_HUGEPAGE);
    return units.bytes();
#else
    (void)p;
    (void)bytes;
    return 0;
#endif
}

std::size_t populate_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    const Units units = whole_units(p, bytes, 4096);
    if (units.empty()) return 0;
    // Kernels before 5.14 refuse it (EINVAL): the pages then fault in as before.
    return madvise(units.start(), units.bytes(), MADV_POPULATE_WRITE) == 0 ? units.bytes() : 0;
#else
    (void)p;
    (void)bytes;
    return 0;
#endif
}

}  // namespace pds
