// even_odd.hpp - the tests' own point-in-polygon test by the even-odd rule,
// written out here so the oracles do not lean on the library's index. Rings
// as pds_set_polygon takes them: x y pairs, ring k ending at vertex ends[k].
#ifndef PDS_TEST_EVEN_ODD_HPP
#define PDS_TEST_EVEN_ODD_HPP

#include <cstddef>

#include "core/point.hpp"

// f(ax, ay, bx, by) for each edge, ring by ring; true as soon as f is.
template <class F>
bool any_ring_edge(const double* xy, const std::size_t* ends, std::size_t rings, const F& f) {
    std::size_t begin = 0;
    for (std::size_t k = 0; k < rings; ++k) {
        const std::size_t end = ends[k];
        for (std::size_t i = begin; i < end; ++i) {
            const std::size_t j = i + 1 == end ? begin : i + 1;
            if (f(xy[2 * i], xy[2 * i + 1], xy[2 * j], xy[2 * j + 1])) return true;
        }
        begin = end;
    }
    return false;
}

// An odd number of edges crossed by the ray from p to +x.
inline bool even_odd_contains(const double* xy, const std::size_t* ends, std::size_t rings, const pds::Point& p) {
    bool odd = false;
    any_ring_edge(xy, ends, rings, [&](double ax, double ay, double bx, double by) {
        if ((ay > p.y) != (by > p.y) && p.x < ax + (bx - ax) * (p.y - ay) / (by - ay)) odd = !odd;
        return false;
    });
    return odd;
}

#endif
