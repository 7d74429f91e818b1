// test_space_time_fixed.cpp - the parallel process with fixed points: the
// opening keeps its darts out of the clearance disks (fixed_disks.hpp) and
// the free regions' darts run in the power cells. The disks' marked
// sub-squares lie inside them and every point inside one is marked or its
// cell lists the disk; no point lands inside a clearance; the points never
// depend on the threads or the calls; disks too costly to lay over the grid
// leave the run to the Jones loop alone, as without threads.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "darts/fixed_disks.hpp"
#include "darts/space_time_grid.hpp"
#include "fixed_cases.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "threaded_runs.hpp"

using fixed_cases::assert_clear;
using fixed_cases::with_fixed;

START_TEST(same_points_with_fixed_points_on_any_number_of_threads) {
    const unsigned most = test_light() ? 3 : 8;
    for (int polygon = 0; polygon < 2; ++polygon) {
        pds::Sampler first = with_fixed(0.01, 7, polygon != 0);
        const ThreadedRun one = run_threaded(first, 1);
        ck_assert(one.maximal);
        assert_clear(one.xy, 0.01, 0.01);
        // The opening and the free regions' darts placed most points.
        ck_assert_msg(first.jones().region_stats().points > one.xy.size() / 2 / 20, "%zu region points of %zu",
                      first.jones().region_stats().points, one.xy.size() / 2);
        for (unsigned t = 2; t <= most; ++t) {
            pds::Sampler s = with_fixed(0.01, 7, polygon != 0);
            assert_same(one, run_threaded(s, t), "threads");
        }
        pds::Sampler split = with_fixed(0.01, 7, polygon != 0);
        assert_same(one, run_threaded(split, 3, 777, 1), "777 a call, then 1 thread");
        // Another process than the default one (the single-thread dart stage).
        pds::Sampler plain = with_fixed(0.01, 7, polygon != 0);
        std::size_t added = 0;
        plain.run(0, &added);
        std::vector<double> xy(2 * plain.count());
        plain.copy_points(0, plain.count(), xy.data());
        ck_assert(xy.size() != one.xy.size() || std::memcmp(xy.data(), one.xy.data(), xy.size() * 8) != 0);
    }
}
END_TEST

// Count mode: exactly n points, stopped short of maximal (maximal at the
// radius before the last step, pds_set_count), apart and clear.
std::vector<double> counted(unsigned threads, std::size_t n) {
    pds::Sampler s = with_fixed(0.02, 9, false);
    s.set_count(n);
    const double r0 = s.radius();
    s.set_threads(threads);
    std::size_t added = 0;
    while (s.run(777, &added) != pds::Sampler::RunEnd::complete) {
    }
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    ck_assert_uint_eq(s.count(), n);
    assert_clear(xy, s.radius(), r0);
    return xy;
}

START_TEST(count_mode_and_refine_with_fixed_points_on_threads) {
    // Count mode lowers the radius (the clearances scale with it), a refine
    // hands the opening over: the same on 1 and 3 threads.
    const std::vector<double> one = counted(1, 3000), three = counted(3, 3000);
    ck_assert(one.size() == three.size() && std::memcmp(one.data(), three.data(), one.size() * 8) == 0);
    ThreadedRun refined[2];
    for (int k = 0; k < 2; ++k) {
        pds::Sampler u = with_fixed(0.02, 9, true);
        std::size_t added = 0;
        u.set_threads(k == 0 ? 1 : 3);
        u.run(500, &added);
        u.refine(0.012);
        refined[k] = run_threaded(u, k == 0 ? 1 : 3);
        ck_assert(refined[k].maximal);
    }
    assert_same(refined[0], refined[1], "refined");
}
END_TEST

START_TEST(fixed_disks_mark_and_list_the_cells_they_meet) {
    // Sub-squares marked lie inside a disk (corners and inner points); a
    // random point strictly inside a disk is in a marked sub-square or in a
    // cell that lists the disk, and covers() says so.
    const pds::Box box{0, 0, 1, 0.8};
    const pds::SpaceTimeGrid grid(box, 0.02);
    pds::Rng rng(5);
    std::vector<pds::Point> centres;
    std::vector<double> radii;
    for (int k = 0; k < 40; ++k) {
        centres.push_back(pds::Point{rng.next_double(), 0.8 * rng.next_double()});
        radii.push_back(k % 4 == 0 ? 0.3 * rng.next_double() : 0.04 * rng.next_double());
    }
    std::vector<std::uint16_t> masks(grid.cell_count(), 0);
    pds::FixedDisks disks;
    ck_assert(disks.build(grid, centres, radii, masks, 1u << 24));
    const double sx = grid.side_x(), sy = grid.side_y();
    std::size_t marked = 0;
    for (std::size_t cell = 0; cell < grid.cell_count(); ++cell)
        for (unsigned bit = 0; bit < 16; ++bit) {
            if (!(masks[cell] >> bit & 1u)) continue;
            ++marked;
            const auto col = static_cast<std::int64_t>(cell % grid.cols()), row = static_cast<std::int64_t>(cell / grid.cols());
            const double x0 = grid.cell_x0(col) + (bit % 4) * sx / 4, y0 = grid.cell_y0(row) + (bit / 4) * sy / 4;
            bool inside_one = false;
            for (std::size_t k = 0; k < centres.size() && !inside_one; ++k) {
                bool all = true;
                for (int i = 0; i <= 4 && all; ++i)
                    for (int j = 0; j <= 4 && all; ++j)
                        // (clipped to the box, as the grid's edge cells are)
                        all = pds::compare_distance(pds::Point{std::min(x0 + i * sx / 16, box.x1), std::min(y0 + j * sy / 16, box.y1)},
                                                    centres[k], radii[k]) < 0;
                inside_one = all;
            }
            if (!inside_one) ck_abort_msg("cell %zu sub-square %u marked, in no disk whole", cell, bit);
        }
    ck_assert_msg(marked > 1000, "only %zu sub-squares marked", marked);
    for (int trial = 0; trial < 200000; ++trial) {
        const pds::Point p{rng.next_double(), 0.8 * rng.next_double()};
        bool inside = false;
        for (std::size_t k = 0; k < centres.size() && !inside; ++k) inside = pds::compare_distance(p, centres[k], radii[k]) < 0;
        const auto col = std::min<std::size_t>(grid.cols() - 1, static_cast<std::size_t>(p.x / sx));
        const auto row = std::min<std::size_t>(grid.rows() - 1, static_cast<std::size_t>(p.y / sy));
        const auto cell = static_cast<std::uint32_t>(row * grid.cols() + col);
        const unsigned bit = pds::SpaceTimeGrid::sub_square((p.x - grid.cell_x0(static_cast<std::int64_t>(col))) / sx,
                                                            (p.y - grid.cell_y0(static_cast<std::int64_t>(row))) / sy);
        const bool marked_here = (masks[cell] >> bit & 1u) != 0;
        const bool said = disks.listed(cell) && disks.covers(p, cell);
        if (inside && !marked_here && !said) ck_abort_msg("(%.17g, %.17g) inside a disk, neither marked nor listed", p.x, p.y);
        if (!inside && (marked_here || said)) ck_abort_msg("(%.17g, %.17g) in no disk, yet marked or covered", p.x, p.y);
    }
    // Past the budget the disks decline.
    std::vector<std::uint16_t> again(grid.cell_count(), 0);
    pds::FixedDisks over;
    ck_assert(!over.build(grid, centres, radii, again, 1000));
}
END_TEST

START_TEST(disks_too_costly_leave_the_jones_loop_alone) {
    // A hundred clearances around the corner (0, 0), each spanning the whole
    // grid (about 20,000 cells a disk, past the budget of 4 grids and 2^20
    // cells): the opening declines and the run is the Jones loop's alone,
    // the points of a run without threads, in the far corner left free.
    std::vector<pds::Point> at;
    std::vector<double> c;
    for (int k = 0; k < 100; ++k) {
        at.push_back(pds::Point{1e-6 * k, 0.0});
        c.push_back(0.9);
    }
    pds::Sampler a(0.01, 4), b(0.01, 4);
    a.set_fixed(at, c);
    b.set_fixed(at, c);
    const ThreadedRun threaded = run_threaded(a, 2);
    std::size_t added = 0;
    b.run(0, &added);
    std::vector<double> xy(2 * b.count());
    b.copy_points(0, b.count(), xy.data());
    ck_assert_msg(xy.size() / 2 > 1000, "%zu points", xy.size() / 2);
    ck_assert_uint_eq(threaded.xy.size(), xy.size());
    ck_assert(std::memcmp(threaded.xy.data(), xy.data(), xy.size() * 8) == 0);
}
END_TEST

// A box and fixed points for the uniformity test below.
struct PowerCellCase {
    pds::Box box;
    std::vector<pds::Point> at;
    std::vector<double> clearance;
};

START_TEST(region_darts_in_power_cells_are_uniform) {
    // The free regions' darts from the first point on (a test hook) around
    // fixed points whose clearances are power disks. The first sampled point
    // must be uniform over the free area: chi-square of its block (4 x 4 over
    // the box) against the blocks' free areas (measured on a fine grid), over
    // 4000 seeds. Long epochs, so the darts, not the loop's own draws, place it.
    const PowerCellCase cases[2] = {
        // A large disk, a small one apart, one hidden inside the large one,
        // and one whose site lies just outside its own power cell (measured
        // 15.8; a piece chosen by a biased draw gives 867).
        {{0, 0, 1, 1}, {{0.5, 0.5}, {0.2, 0.2}, {0.55, 0.55}, {0.78, 0.5}, {0.9, 0.1}}, {0.3, 0.05, 0.01, 0.1, 0.02}},
        // A site deep inside the large disk, its own disk reaching past it,
        // in a tall box: its power cell is the last column of blocks (x >
        // 0.8), a tenth away from it, so its fan's clockwise triangle is
        // large, and much of its pieces' free area lies outside the cell. A
        // draw landing there must be lost, not drawn again in its piece: a
        // retry there gives chi-square 73.2 (measured 11.7).
        {{0.2, 0, 1, 3}, {{0.5, 1.5}, {0.7, 1.5}}, {0.45, 0.35}},
    };
    const pds::Box& box = cases[_i].box;
    const std::vector<pds::Point>& at = cases[_i].at;
    const std::vector<double>& c = cases[_i].clearance;
    const auto free_at = [&](double x, double y) {
        for (std::size_t k = 0; k < at.size(); ++k)
            if ((x - at[k].x) * (x - at[k].x) + (y - at[k].y) * (y - at[k].y) < c[k] * c[k]) return false;
        return true;
    };
    double expected[16] = {0};
    constexpr int kFine = 800;
    double total = 0;
    for (int i = 0; i < kFine; ++i)
        for (int j = 0; j < kFine; ++j) {
            const double x = box.x0 + (i + 0.5) / kFine * box.width(), y = box.y0 + (j + 0.5) / kFine * box.height();
            if (!free_at(x, y)) continue;
            expected[(j * 4 / kFine) * 4 + i * 4 / kFine] += 1;
            total += 1;
        }
    const int runs = test_light() ? 400 : 4000;
    double seen[16] = {0};
    std::size_t from_regions = 0;
    for (int seed = 1; seed <= runs; ++seed) {
        pds::Sampler s(0.05, static_cast<std::uint64_t>(seed));
        s.set_domain(box);
        s.set_fixed(at, c);
        s.carry_region_darts_from_start();
        s.set_region_darts_per_cell(4.0);  // an epoch seldom ends with no point
        std::size_t added = 0;
        s.run(1, &added);
        double xy[2];
        ck_assert_uint_eq(s.copy_points(0, 1, xy), 1);
        if (!free_at(xy[0], xy[1])) ck_abort_msg("seed %d: the first point inside a clearance", seed);
        const int bx = static_cast<int>((xy[0] - box.x0) / box.width() * 4);
        const int by = static_cast<int>((xy[1] - box.y0) / box.height() * 4);
        seen[std::min(3, by) * 4 + std::min(3, bx)] += 1;
        from_regions += s.jones().region_stats().points;
    }
    ck_assert_msg(from_regions + runs / 20 >= static_cast<std::size_t>(runs), "%zu of %d first points from the darts",
                  from_regions, runs);
    double chi2 = 0;
    int blocks = 0;
    for (int b = 0; b < 16; ++b) {
        if (expected[b] == 0) continue;  // inside a clearance: no point lands there (checked above)
        const double e = expected[b] / total * runs;
        chi2 += (seen[b] - e) * (seen[b] - e) / e;
        ++blocks;
    }
    // The 99.9th percentile of chi-square (Wilson and Hilferty): 37.7 for 15
    // degrees of freedom.
    const double k = blocks - 1, z = 3.09, w = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
    const double limit = k * w * w * w;
    if (getenv("PDS_LAW_PRINT")) printf("power cells, case %d: chi-square %.1f (limit %.1f)\n", _i, chi2, limit);
    ck_assert_msg(chi2 < limit, "chi-square %.1f over %d blocks (limit %.1f)", chi2, blocks, limit);
}
END_TEST

Suite* space_time_fixed_suite() {
    Suite* s = suite_create("space_time_fixed");
    TCase* t = tcase_create("the parallel process with fixed points");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, same_points_with_fixed_points_on_any_number_of_threads);
    tcase_add_test(t, count_mode_and_refine_with_fixed_points_on_threads);
    tcase_add_test(t, fixed_disks_mark_and_list_the_cells_they_meet);
    tcase_add_test(t, disks_too_costly_leave_the_jones_loop_alone);
    tcase_add_loop_test(t, region_darts_in_power_cells_are_uniform, 0, 2);
    suite_add_tcase(s, t);
    return s;
}
