// threaded_runs.hpp - a sampler run to the end with the parallel process on
// some threads, in calls of some size, and two runs' points compared byte
// for byte: for the unit tests of the parallel opening.
#ifndef PDS_TEST_THREADED_RUNS_HPP
#define PDS_TEST_THREADED_RUNS_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/point.hpp"
#include "core/predicates.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

struct ThreadedRun {
    std::vector<double> xy;
    bool maximal = false;
};

// Runs s (its domain set) on `threads` threads in calls of `chunk` points
// (0: one call), `threads_later` threads from the second call; the pattern
// must then verify.
inline ThreadedRun run_threaded(pds::Sampler& s, unsigned threads, std::size_t chunk = 0, unsigned threads_later = 0) {
    s.set_threads(threads);
    ThreadedRun out;
    bool first = true;
    for (;;) {
        std::size_t added = 0;
        const pds::Sampler::RunEnd end = s.run(chunk, &added);
        if (first && threads_later != 0) s.set_threads(threads_later);
        first = false;
        if (end == pds::Sampler::RunEnd::complete) {
            out.maximal = true;
            break;
        }
    }
    out.xy.resize(2 * s.count());
    s.copy_points(0, s.count(), out.xy.data());
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.failure.empty() && rep.maximal, "verify: %s", rep.failure.c_str());
    return out;
}

// Every pair of points in the unit square at least r apart, by brute force
// over a grid of cells of side r (one assertion at the end: Check records
// every one it is given).
inline void assert_apart_in_unit_square(const std::vector<pds::Point>& p, double r) {
    const auto cols = static_cast<std::size_t>(1.0 / r) + 1;
    std::vector<std::vector<std::uint32_t>> cells(cols * cols);
    for (std::uint32_t i = 0; i < p.size(); ++i)
        cells[static_cast<std::size_t>(p[i].y / r) * cols + static_cast<std::size_t>(p[i].x / r)].push_back(i);
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const auto cx = static_cast<long>(p[i].x / r), cy = static_cast<long>(p[i].y / r);
        for (long y = cy - 1; y <= cy + 1; ++y)
            for (long x = cx - 1; x <= cx + 1; ++x) {
                if (x < 0 || y < 0 || x >= static_cast<long>(cols) || y >= static_cast<long>(cols)) continue;
                for (std::uint32_t j : cells[static_cast<std::size_t>(y) * cols + static_cast<std::size_t>(x)])
                    if (j != i && pds::compare_distance(p[i], p[j], r) < 0) ck_abort_msg("points %u and %u closer than R", i, j);
            }
    }
}

inline void assert_same(const ThreadedRun& a, const ThreadedRun& b, const char* what) {
    ck_assert_msg(a.xy.size() == b.xy.size(), "%s: %zu points against %zu", what, a.xy.size() / 2, b.xy.size() / 2);
    ck_assert_msg(std::memcmp(a.xy.data(), b.xy.data(), a.xy.size() * sizeof(double)) == 0, "%s: other points", what);
}

#endif
