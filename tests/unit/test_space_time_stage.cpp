// test_space_time_stage.cpp - the parallel opening (the space-time dart
// process): its points depend on the seed and the settings, never on the
// number of threads nor on how a run is split into calls (the hand-over's
// cells measured side by side included); the epochs'
// greedy set keeps every pair at least R apart; cells certified covered
// really are; the whole run ends maximal and verified; and the worker pool
// runs with the threads it could start.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <vector>

#include "alloc_hook.hpp"
#include "core/worker_pool.hpp"
#include "darts/space_time_grid.hpp"
#include "darts/space_time_stage.hpp"
#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "threaded_runs.hpp"

namespace {

using Run = ThreadedRun;

// A sampler in `box` with the parallel opening (threaded_runs.hpp).
Run run(const pds::Box& box, double r, std::uint64_t seed, unsigned threads, std::size_t chunk = 0,
        unsigned threads_later = 0) {
    pds::Sampler s(r, seed);
    s.set_domain(box);
    return run_threaded(s, threads, chunk, threads_later);
}

}  // namespace

START_TEST(same_points_on_any_number_of_threads) {
    // Wide and tall domains (many bands of rows), and one too small for two.
    const pds::Box boxes[] = {{0, 0, 1, 1}, {0, 0, 3, 0.7}, {-1, 2, -0.6, 5}, {0, 0, 0.1, 0.1}};
    const double radii[] = {0.01, 0.01, 0.008, 0.02};
    const unsigned most = test_light() ? 4 : 8;
    for (int b = 0; b < 4; ++b) {
        const Run one = run(boxes[b], radii[b], 11, 1);
        ck_assert(one.maximal);
        for (unsigned t = 2; t <= most; ++t) assert_same(one, run(boxes[b], radii[b], 11, t), "threads");
    }
}
END_TEST

START_TEST(hand_over_measures_cells_side_by_side) {
    // Over 16384 points the hand-over (and a refine) measures the cells on
    // the threads too: the Jones loop's choices, hence the points, and the
    // free area left at a partial pattern must not change.
    const pds::Box box{0, 0, 1, 1};
    const Run one = run(box, 0.005, 21, 1);
    ck_assert_msg(one.xy.size() / 2 > 4 * 4096, "only %zu points", one.xy.size() / 2);
    assert_same(one, run(box, 0.005, 21, 3), "3 threads");
    double area[2];
    for (int k = 0; k < 2; ++k) {
        pds::Sampler s(0.005, 21);
        s.set_threads(k == 0 ? 1 : 2);
        std::size_t added = 0;
        s.run(26000, &added);
        s.refine(0.0045);
        s.run(100, &added);
        area[k] = s.free_area();
    }
    ck_assert_msg(area[0] == area[1], "free area %.17g against %.17g", area[0], area[1]);
}
END_TEST

START_TEST(same_points_in_any_calls) {
    const pds::Box box{0, 0, 2, 1};
    const Run whole = run(box, 0.01, 5, 2);
    assert_same(whole, run(box, 0.01, 5, 1, 1), "one point a call");
    assert_same(whole, run(box, 0.01, 5, 3, 777), "777 a call");
    assert_same(whole, run(box, 0.01, 5, 1, 5000, 4), "threads changed between calls");
}
END_TEST

START_TEST(the_opening_differs_from_the_default_one) {
    // set_threads selects another dart process: its points are not the
    // default opening's (a test that the selection happens at all).
    pds::Sampler plain(0.01, 3);
    std::size_t added = 0;
    plain.run(0, &added);
    std::vector<double> xy(2 * plain.count());
    plain.copy_points(0, plain.count(), xy.data());
    const Run threaded = run(pds::Box{0, 0, 1, 1}, 0.01, 3, 1);
    ck_assert(xy.size() != threaded.xy.size() || std::memcmp(xy.data(), threaded.xy.data(), xy.size() * 8) != 0);
}
END_TEST

START_TEST(epochs_keep_points_apart_and_carry_most_of_the_pattern) {
    // The stage alone, every pair checked exactly by brute force over a
    // neighbour grid of the points themselves.
    const pds::Rectangle domain(pds::Box{0, 0, 1, 1});
    const double r = 0.004;
    for (unsigned threads : {1u, 3u}) {
        pds::SpaceTimeDartStage stage(domain, nullptr, r, 9);
        stage.set_threads(threads);
        stage.reserve(80000);
        pds::Rng unused(0);
        while (stage.next(unused) != nullptr) stage.add_next();
        const std::vector<pds::Point>& p = stage.points();
        ck_assert_msg(p.size() > 30000, "the stage placed only %zu points (of about 43500)", p.size());
        ck_assert(stage.epochs() > 3);
        assert_apart_in_unit_square(p, r);
    }
}
END_TEST

START_TEST(certified_sub_squares_lie_in_the_disk) {
    // Every sub-square covered_by() certifies has its 4 corners and a dense
    // set of inner points within R of the point; and a point far off
    // certifies none. In the plane (square cells) and on a torus whose
    // periods the cells divide (rectangles, narrower along y).
    const pds::Box box{0, 0, 1, 1};
    const pds::Torus torus{1.0, 0.71, 0.0, 0.0};
    for (const pds::Torus& t : {pds::Torus{}, torus}) {
        const pds::SpaceTimeGrid grid(box, 0.05, t);
        const pds::Box span = grid.box();
        const double sx = grid.side_x(), sy = grid.side_y();
        ck_assert(sx <= pds::darts::cell_side(0.05) && sy <= pds::darts::cell_side(0.05));
        if (t.on()) {
            ck_assert_double_eq_tol(sx * static_cast<double>(grid.cols()), 1.0, 1e-12);
            ck_assert_double_eq_tol(sy * static_cast<double>(grid.rows()), 0.71, 1e-12);
            ck_assert(sy < sx);
        }
        pds::Rng rng(4);
        int certified = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const std::int64_t col = 3 + static_cast<std::int64_t>(rng.next_double() * 8), row = 3 + static_cast<std::int64_t>(rng.next_double() * 8);
            const pds::Point q{grid.cell_x0(col) + (rng.next_double() * 5 - 2) * sx, grid.cell_y0(row) + (rng.next_double() * 5 - 2) * sy};
            const std::uint16_t mask = grid.covered_by(col, row, q, span);
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a) {
                    if (!(mask >> (4 * b + a) & 1)) continue;
                    ++certified;
                    for (int i = 0; i <= 4; ++i)
                        for (int j = 0; j <= 4; ++j) {
                            const pds::Point x{grid.cell_x0(col) + (a + i / 4.0) * sx / 4, grid.cell_y0(row) + (b + j / 4.0) * sy / 4};
                            if (pds::compare_distance(x, q, 0.05) >= 0) ck_abort_msg("a certified sub-square leaves the disk");
                        }
                }
        }
        ck_assert_msg(certified > 1000, "only %d sub-squares certified", certified);
        ck_assert_int_eq(grid.covered_by(3, 3, pds::Point{grid.cell_x0(7), grid.cell_y0(3)}, span), 0);
    }
    // The part of an edge cell beyond the domain counts as covered.
    const double side = pds::darts::cell_side(0.05);
    const pds::Box narrow{0, 0, 1.3 * side, 1};
    const pds::SpaceTimeGrid edge(narrow, 0.05);
    ck_assert_int_ne(edge.outside(1, 0, narrow), 0);
    ck_assert_int_eq(edge.outside(0, 0, narrow), 0);
}
END_TEST

START_TEST(a_thread_that_cannot_start_is_done_without) {
    // The pool's allocations: its error slots, its thread list, then one
    // state per thread started. Failing the second thread's leaves a pool
    // of two workers, which still runs every task index it reports.
    if (!alloc_hook::in_effect()) return;  // under Valgrind
    alloc_hook::arm(4);
    pds::WorkerPool pool(4);
    alloc_hook::disarm();
    ck_assert_uint_eq(pool.size(), 2);
    std::atomic<unsigned> ran{0};
    pool.run([&](unsigned w) { ran.fetch_or(1u << w); });
    ck_assert_uint_eq(ran.load(), 3u);
    // And none at all when the first allocation fails: the caller alone.
    alloc_hook::arm(1);
    pds::WorkerPool alone(4);
    alloc_hook::disarm();
    ck_assert_uint_eq(alone.size(), 1);
}
END_TEST

Suite* space_time_stage_suite() {
    Suite* s = suite_create("space_time_stage");
    TCase* t = tcase_create("parallel opening");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, same_points_on_any_number_of_threads);
    tcase_add_test(t, same_points_in_any_calls);
    tcase_add_test(t, hand_over_measures_cells_side_by_side);
    tcase_add_test(t, the_opening_differs_from_the_default_one);
    tcase_add_test(t, epochs_keep_points_apart_and_carry_most_of_the_pattern);
    tcase_add_test(t, certified_sub_squares_lie_in_the_disk);
    tcase_add_test(t, a_thread_that_cannot_start_is_done_without);
    suite_add_tcase(s, t);
    return s;
}
