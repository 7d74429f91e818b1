// page_populate.hpp - make the pages a large array will soon write resident
// ahead of time, on a thread that would otherwise wait.
//
// The sampler reserves its arrays for the points it may place and writes
// them as points arrive; the first write to each page traps into the kernel,
// which zeroes the page. At the end of a parallel run those writes come from
// the insertions on the caller's thread while the others wait (most of its
// kernel time there: docs/performance.md, 1.7.1). Asking the kernel to
// populate the pages (Linux's MADV_POPULATE_WRITE) from a worker moves that
// work off the serial path. A hint only: contents never change (the pages
// are beyond what the arrays hold), and where the kernel or the platform
// lacks it, it does nothing.
#ifndef PDS_PAGE_POPULATE_HPP
#define PDS_PAGE_POPULATE_HPP

#include <cstddef>
#include <vector>

namespace pds {

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
