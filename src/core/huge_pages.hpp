// huge_pages.hpp - ask the kernel for transparent huge pages under the large
// arrays the sampler reads at random.
//
// Every dart, ring walk and tree descent lands somewhere new in arrays of
// tens of bytes per point; past a few million points most of those accesses
// also miss the TLB, and a page-table walk is one more dependent miss.
// Backing the arrays with 2 MiB pages removes most of those walks. Linux
// gives huge pages to anonymous memory only where asked when its setting is
// "madvise" (Debian's default), so the large reservations ask. A hint only:
// it never changes a result, and where it is unsupported it does nothing.
//
// Only arrays of 128 MiB and more ask: below that the kernel's compaction
// to find huge pages costs more than the TLB misses it saves
// (docs/performance.md has the measurements).
//
// An array written sparsely (a dart grid over the whole domain early in a
// run, or a bounded run's prefix) asks only once the writes expected would
// make most of its small pages resident anyway (huge_pages_worth): before
// that, each scattered write would make a whole 2 MiB page resident, and
// memory would follow the array's size instead of what is written.
#ifndef PDS_HUGE_PAGES_HPP
#define PDS_HUGE_PAGES_HPP

#include <cstddef>
#include <vector>

namespace pds {

// Advises huge pages for the 2 MiB-aligned part of [p, p + bytes), when
// bytes is at least 128 MiB. Returns the bytes advised (0: none).
std::size_t advise_huge_pages(const void* p, std::size_t bytes);

template <class T>
std::size_t advise_huge_pages(const std::vector<T>& v) {
    return advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

// Whether `writes` writes scattered at random over an array of `bytes` make
// huge pages worth asking for: at least one write per 4 KiB page on average
// (then at most 1.6 times the bytes small pages would hold are resident).
inline bool huge_pages_worth(std::size_t bytes, std::size_t writes) {
    constexpr std::size_t kSmallPage = 4096;
    return writes >= bytes / kSmallPage;
}

}  // namespace pds

#endif
