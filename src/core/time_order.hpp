// time_order.hpp - items put in order of a time uniform in [0, 1) (the
// darts of a space-time process), in linear expected time.
//
// A bucket sort: n buckets for n items (bucket order is time order, as
// t * n never decreases with t), so each holds one item on average; the
// items are copied into their buckets in the order given, then each moves
// past its few bucket-mates by insertion. The result is a stable sort by
// `before`: what std::stable_sort would give, and what std::sort gives when
// `before` is a total order.
#ifndef PDS_TIME_ORDER_HPP
#define PDS_TIME_ORDER_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pds {

// for_each_item(f) calls f(item) for each of the n items, in the same order
// each time; time_of(item) is its time in [0, 1) (larger ones go last);
// out receives the n items in order; starts is scratch (n + 1 entries).
template <class T, class ForEachItem, class TimeOf, class Before>
void order_by_time(std::size_t n, const ForEachItem& for_each_item, const TimeOf& time_of, const Before& before, T* out,
                   std::vector<std::uint32_t>& starts) {
    if (n == 0) return;
    const double scale = static_cast<double>(n);
    const auto bucket = [&](const T& item) { return std::min(n - 1, static_cast<std::size_t>(time_of(item) * scale)); };
    starts.assign(n + 1, 0);
    for_each_item([&](const T& item) { ++starts[bucket(item) + 1]; });
    for (std::size_t b = 0; b < n; ++b) starts[b + 1] += starts[b];
    for_each_item([&](const T& item) { out[starts[bucket(item)]++] = item; });
    for (std::size_t i = 1; i < n; ++i) {
        const T item = out[i];
        std::size_t j = i;
        for (; j > 0 && before(item, out[j - 1]); --j) out[j] = out[j - 1];
        out[j] = item;
    }
}

}  // namespace pds

#endif
