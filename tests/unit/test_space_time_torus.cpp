// test_space_time_torus.cpp - the parallel process on the torus: the
// opening's grid wraps (its padding holds copies of the points and of each
// epoch's candidate lists), and the free regions' darts are decided across
// the seams. Its points depend on the seed and the settings, never on the
// number of threads nor on the calls; every pair is at least R apart by the
// wrapped distance; the points reach the seams from both sides; whole runs
// end maximal and verified.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "darts/space_time_stage.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "threaded_runs.hpp"

namespace {

using Run = ThreadedRun;

Run run_on_torus(const pds::Box& box, double r, std::uint64_t seed, unsigned threads, std::size_t chunk = 0,
                 unsigned threads_later = 0, bool region_darts_from_start = false) {
    pds::Sampler s(r, seed);
    s.set_domain(box);
    s.set_periodic(true);
    if (region_darts_from_start) s.carry_region_darts_from_start();
    return run_threaded(s, threads, chunk, threads_later);
}

// Every pair at least r apart by the wrapped distance (the nearest copy),
// by brute force over a grid of cells of side r at least that wraps too.
// One assertion at the end of a failure: Check records each one given.
void assert_apart_on_torus(const std::vector<pds::Point>& p, const pds::Box& box, double r) {
    const double px = box.width(), py = box.height();
    const auto nx = static_cast<long>(std::max(1.0, std::floor(px / r)));
    const auto ny = static_cast<long>(std::max(1.0, std::floor(py / r)));
    const auto col = [&](double x) { return std::min(nx - 1, static_cast<long>((x - box.x0) / px * static_cast<double>(nx))); };
    const auto row = [&](double y) { return std::min(ny - 1, static_cast<long>((y - box.y0) / py * static_cast<double>(ny))); };
    std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(nx * ny));
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        if (!(p[i].x >= box.x0 && p[i].x < box.x1 && p[i].y >= box.y0 && p[i].y < box.y1))
            ck_abort_msg("point %u (%.17g, %.17g) outside the fundamental domain", i, p[i].x, p[i].y);
        cells[static_cast<std::size_t>(row(p[i].y) * nx + col(p[i].x))].push_back(i);
    }
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const long cx = col(p[i].x), cy = row(p[i].y);
        for (long y = cy - 1; y <= cy + 1; ++y)
            for (long x = cx - 1; x <= cx + 1; ++x) {
                const long wx = ((x % nx) + nx) % nx, wy = ((y % ny) + ny) % ny;
                for (std::uint32_t j : cells[static_cast<std::size_t>(wy * nx + wx)]) {
                    if (j == i) continue;
                    for (int a = -1; a <= 1; ++a)
                        for (int b = -1; b <= 1; ++b)
                            if (pds::compare_distance(p[i], pds::Point{p[j].x + a * px, p[j].y + b * py}, r) < 0)
                                ck_abort_msg("points %u and %u closer than R across the periods (%d, %d)", i, j, a, b);
                }
            }
    }
}

std::vector<pds::Point> points_of(const Run& run) {
    std::vector<pds::Point> p(run.xy.size() / 2);
    for (std::size_t k = 0; k < p.size(); ++k) p[k] = pds::Point{run.xy[2 * k], run.xy[2 * k + 1]};
    return p;
}

}  // namespace

START_TEST(same_points_on_the_torus_on_any_number_of_threads) {
    // Square and long periods (many bands of rows: the first and the last
    // meet across the seam), an origin off zero, and periods of barely
    // more than 2R (three cells a side: a cell's copies lie on both sides).
    const pds::Box boxes[] = {{0, 0, 1, 1}, {0, 0, 0.7, 3}, {-1.5, 2, -0.9, 2.25}, {0, 0, 0.021, 0.0205}};
    const double radii[] = {0.01, 0.01, 0.008, 0.01};
    const unsigned most = test_light() ? 4 : 8;
    for (int b = 0; b < 4; ++b) {
        const Run one = run_on_torus(boxes[b], radii[b], 11, 1);
        ck_assert(one.maximal);
        assert_apart_on_torus(points_of(one), boxes[b], radii[b]);
        for (unsigned t = 2; t <= most; ++t) assert_same(one, run_on_torus(boxes[b], radii[b], 11, t), "threads");
    }
}
END_TEST

START_TEST(same_points_on_the_torus_in_any_calls) {
    const pds::Box box{0, 0, 2, 1};
    const Run whole = run_on_torus(box, 0.01, 5, 2);
    assert_same(whole, run_on_torus(box, 0.01, 5, 1, 1), "one point a call");
    assert_same(whole, run_on_torus(box, 0.01, 5, 3, 777), "777 a call");
    assert_same(whole, run_on_torus(box, 0.01, 5, 1, 5000, 4), "threads changed between calls");
    // Another process than the default one on the torus.
    pds::Sampler plain(0.01, 5);
    plain.set_domain(box);
    plain.set_periodic(true);
    std::size_t added = 0;
    plain.run(0, &added);
    std::vector<double> xy(2 * plain.count());
    plain.copy_points(0, plain.count(), xy.data());
    ck_assert(xy.size() != whole.xy.size() || std::memcmp(xy.data(), whole.xy.data(), xy.size() * 8) != 0);
}
END_TEST

START_TEST(the_opening_wraps_across_the_seams) {
    // The stage alone on 1 and 3 threads: points apart by the wrapped
    // distance (a grid without the copies would put points within R of one
    // another across the seams), and as many near each seam as inside (a
    // grid that treated the seams as walls, or dropped the darts near
    // them, would leave a strip along them with fewer points or more).
    const pds::Box box{0, 0, 1, 0.6};
    const pds::Rectangle domain(box);
    const pds::Torus torus{1.0, 0.6, 0.0, 0.0};
    const double r = 0.004;
    for (unsigned threads : {1u, 3u}) {
        pds::SpaceTimeDartStage stage(domain, nullptr, r, 9, torus);
        stage.set_threads(threads);
        stage.reserve(60000);
        pds::Rng unused(0);
        while (stage.next(unused) != nullptr) stage.add_next();
        const std::vector<pds::Point>& p = stage.points();
        ck_assert_msg(p.size() > 18000, "the stage placed only %zu points (of about 26000)", p.size());
        assert_apart_on_torus(p, box, r);
        // Strips of width 2R along the seams (x near 0 or 1, y near 0 or
        // 0.6) against strips of the same width through the middle.
        std::size_t seam_x = 0, middle_x = 0, seam_y = 0, middle_y = 0;
        for (const pds::Point& q : p) {
            seam_x += q.x < r || q.x >= 1 - r;
            middle_x += std::fabs(q.x - 0.5) < r;
            seam_y += q.y < r || q.y >= 0.6 - r;
            middle_y += std::fabs(q.y - 0.3) < r;
        }
        // About 155 and 104 points in each; the limits are 5 standard deviations off.
        const auto near = [](double a, double b) { return std::fabs(a - b) < 5.0 * std::sqrt(a + b); };
        ck_assert_msg(near(static_cast<double>(seam_x), static_cast<double>(middle_x)), "x: %zu at the seam, %zu inside",
                      seam_x, middle_x);
        ck_assert_msg(near(static_cast<double>(seam_y), static_cast<double>(middle_y)), "y: %zu at the seam, %zu inside",
                      seam_y, middle_y);
    }
}
END_TEST

START_TEST(region_darts_are_decided_across_the_seams) {
    // The free regions' darts from the first point on, in epochs long
    // enough that many darts of one epoch meet, on tori whose region grid
    // has one, two and several cells a side: every pair apart by the
    // wrapped distance, the pattern maximal, the same on 1 and 3 threads.
    const pds::Box boxes[] = {{0.3, -0.2, 0.8, 0.1}, {0, 0, 0.09, 0.06}, {0, 0, 0.05, 0.05}};
    std::size_t from_regions = 0, total = 0;
    for (const pds::Box& box : boxes) {
        for (std::uint64_t seed = 1; seed <= (test_light() ? 3u : 8u); ++seed) {
            Run runs[2];
            for (int k = 0; k < 2; ++k) {
                pds::Sampler s(0.02, seed);
                s.set_domain(box);
                s.set_periodic(true);
                s.carry_region_darts_from_start();
                s.set_region_darts_per_cell(4.0);
                runs[k] = run_threaded(s, k == 0 ? 1 : 3);
                if (k == 0) {
                    from_regions += s.jones().region_stats().points;
                    total += s.count();
                }
            }
            ck_assert(runs[0].maximal);
            assert_apart_on_torus(points_of(runs[0]), box, 0.02);
            assert_same(runs[0], runs[1], "3 threads");
        }
    }
    // The first epoch has one cell, the whole torus, whose draws are often
    // refused: it may place no point and end the process (seed 2 in the
    // largest box); the loop's own draws place the last few points of
    // every run. The darts must still have placed most points (measured:
    // 65% of them with the light seeds, 85% with all).
    ck_assert_msg(static_cast<double>(from_regions) > 0.5 * static_cast<double>(total),
                  "%zu of %zu points from the region darts", from_regions, total);
}
END_TEST

Suite* space_time_torus_suite() {
    Suite* s = suite_create("space_time_torus");
    TCase* t = tcase_create("the parallel process on the torus");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, same_points_on_the_torus_on_any_number_of_threads);
    tcase_add_test(t, same_points_on_the_torus_in_any_calls);
    tcase_add_test(t, the_opening_wraps_across_the_seams);
    tcase_add_test(t, region_darts_are_decided_across_the_seams);
    suite_add_tcase(s, t);
    return s;
}
