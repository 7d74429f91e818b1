// huge_pages.cpp - see huge_pages.hpp.
#include "core/huge_pages.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pds {

std::size_t advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
    constexpr std::size_t kMinBytes = std::size_t{128} << 20;
    if (p == nullptr || bytes < kMinBytes) return 0;
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
    if (end <= begin) return 0;
    // A refused hint leaves ordinary pages: nothing to undo.
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    return end - begin;
#else
    (void)p;
    (void)bytes;
    return 0;
#endif
}

}  // namespace pds
