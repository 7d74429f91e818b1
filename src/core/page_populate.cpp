// page_populate.cpp - see page_populate.hpp.
#include "core/page_populate.hpp"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pds {

std::size_t populate_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    constexpr std::uintptr_t kPage = 4096;
    // Whole pages only: a partial page at either end may hold live entries
    // (it is resident already, written through them).
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kPage - 1) & ~(kPage - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kPage - 1);
    if (p == nullptr || end <= begin) return 0;
    // EINVAL on kernels before 5.14: the pages then fault in as before.
    if (madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE) != 0) return 0;
    return end - begin;
#else
    (void)p;
    (void)bytes;
    return 0;
#endif
}

}  // namespace pds
