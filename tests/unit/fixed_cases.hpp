// fixed_cases.hpp - fixed points of every kind, a sampler around them in the
// unit square or in an L with a square hole, and the check that no point
// lies inside a clearance: shared by the suites of both dart stages around
// fixed points.
#ifndef PDS_TEST_FIXED_CASES_HPP
#define PDS_TEST_FIXED_CASES_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "core/predicates.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace fixed_cases {

// Clearances of every kind: 0 (the radius), small, large, one disk inside
// another (its power cell empty: hidden), one on the box's edge.
const std::vector<pds::Point> kFixed = {{0.3, 0.3}, {0.7, 0.25}, {0.72, 0.27}, {0.5, 0.8}, {1.0, 0.5}, {0.1, 0.9}};
const std::vector<double> kClearance = {0.0, 0.002, 0.004, 0.15, 0.08, 0.3};

inline pds::Sampler with_fixed(double r, std::uint64_t seed, bool polygon) {
    pds::Sampler s(r, seed);
    if (polygon) {
        // An L with a square hole, as the API's tests use.
        const double xy[] = {0, 0, 1, 0, 1, 0.5, 0.5, 0.5, 0.5, 1, 0, 1, 0.15, 0.15, 0.35, 0.15, 0.35, 0.35, 0.15, 0.35};
        const std::size_t ends[] = {6, 10};
        s.set_polygon(xy, ends, 2);
    }
    s.set_fixed(kFixed, kClearance);
    return s;
}

// No point (x y pairs) strictly inside a clearance at radius r, the run
// having started at r0 (the clearances scale with the radius; the domain is
// the unit square, the internal units are the user's).
inline void assert_clear(const std::vector<double>& xy, double r, double r0) {
    for (std::size_t i = 0; i < xy.size() / 2; ++i)
        for (std::size_t k = 0; k < kFixed.size(); ++k) {
            const double c = kClearance[k] > 0.0 ? kClearance[k] * (r / r0) : r;
            if (pds::compare_distance(pds::Point{xy[2 * i], xy[2 * i + 1]}, kFixed[k], c) < 0)
                ck_abort_msg("point %zu inside fixed point %zu's clearance", i, k);
        }
}

}  // namespace fixed_cases

#endif
