// page_hints.hpp - hints to the kernel about the pages under the sampler's
// large arrays. Hints only: no result depends on them, and where the kernel
// or the platform lacks one, it does nothing.
//
// Huge pages for the arrays the sampler reads at random.
//
// Every dart, ring walk and tree descent lands somewhere new in arrays of
// tens of bytes per point; past a few million points most of those accesses
// also miss the TLB, and a page-table walk is one more dependent miss.
// Backing the arrays with 2 MiB pages removes most of those walks. Linux
// gives huge pages to anonymous memory only where asked when its setting is
// "madvise" (Debian's default), so the large reservations ask.
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
//
// Pages made resident ahead of time, on a thread that would otherwise wait.
//
// The sampler reserves its arrays for the points it may place and writes
// them as points arrive; the first write to each page traps into the kernel,
// which zeroes the page. At the end of a parallel run those writes come from
// the insertions on the caller's thread while the others wait (most of its
// kernel time there: docs/performance.md, 1.7.1). Asking the kernel to
// populate the pages (Linux's MADV_POPULATE_WRITE) from a worker moves that
// work off the serial path. Contents never change: the pages are beyond
// what the arrays hold. The dart grids ask for all their pages when a run
// reserves enough points (grid_storage.hpp): darts read a page before any
// point writes it, and that write would fault a second time.
#ifndef PDS_PAGE_HINTS_HPP
#define PDS_PAGE_HINTS_HPP

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

// Populates the whole pages inside [p, p + bytes) for writing. Returns the
// bytes asked for (0: nothing, or no support).
std::size_t populate_pages(const void* p, std::size_t bytes);

// The pages of v's spare capacity that entries [v.size(), until) will take
// (until capped by the capacity). Reads only the vector's bounds: safe while
// another thread reads its entries.
template <class T>
std::size_t populate_ahead(const std::vector<T>& v, std::size_t until) {
    if (until > v.capacity()) until = v.capacity();
    if (until <= v.size()) return 0;
    return populate_pages(v.data() + v.size(), (until - v.size()) * sizeof(T));
}

}  // namespace pds

#endif
