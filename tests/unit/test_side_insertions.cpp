// test_side_insertions.cpp - the free regions' epochs inserted on two sides
// of the domain's middle at once (JonesStage::set_side_insertions): the
// points are the same on 1, 2 and 3 threads and for any split into calls,
// pairs stay R apart and the pattern ends maximal; an epoch's points are
// handed out in order of time; the points differ from those of the
// one-by-one insertions (the mesh's records differ, so later draws do), so
// the switch is not a no-op; a check inside an epoch not yet handed out is
// refused; an allocation failure loses nothing; the torus, where the switch
// does not apply, gives the same points with it on or off.
#include <cstdint>
#include <new>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "alloc_hook.hpp"
#include "core/rng.hpp"
#include "core/space_time_stream.hpp"
#include "jones/jones_stage.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

void set_up(pds::Sampler& s, unsigned threads, bool sides) {
    s.set_threads(threads);
    s.set_side_insertions(sides);
}

// The points of a run at radius r with `threads` threads, to the end in
// calls of at most `per_call` points (0: one call); checked R apart and
// maximal at the end. *refused counts the calls after which verify()
// refused (an epoch partly handed out).
std::vector<double> run_points(double r, std::uint64_t seed, unsigned threads, bool sides, bool periodic,
                               std::size_t per_call = 0, std::size_t* refused = nullptr) {
    pds::Sampler s(r, seed);
    s.set_periodic(periodic);
    set_up(s, threads, sides);
    for (;;) {
        std::size_t added = 0;
        const pds::Sampler::RunEnd end = s.run(per_call, &added);
        if (end == pds::Sampler::RunEnd::complete) break;
        ck_assert(end == pds::Sampler::RunEnd::limit);
        ck_assert_uint_eq(added, per_call);
        try {
            const pds::VerifyReport mid = s.verify();
            ck_assert_msg(mid.valid, "mid-run verify: %s", mid.failure.c_str());
        } catch (const std::logic_error&) {
            if (refused) ++*refused;
        }
    }
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.valid && rep.maximal, "verify: %s", rep.failure.c_str());
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    return xy;
}

}  // namespace

START_TEST(same_points_on_any_threads_and_maximal) {
    // 40,000 points: each epoch has thousands of darts on each side and
    // some across the middle, which wait.
    const std::vector<double> one = run_points(0.004, 5, 1, true, false);
    ck_assert_msg(one.size() > 2 * 35000, "%zu points", one.size() / 2);
    for (unsigned threads = 2; threads <= 3; ++threads)
        ck_assert_msg(run_points(0.004, 5, threads, true, false) == one, "%u threads: other points", threads);
    ck_assert_msg(run_points(0.004, 5, 2, false, false) != one, "the same points as the one-by-one insertions");
}
END_TEST

START_TEST(call_splits_give_the_same_points) {
    // Calls of 997 points stop inside epochs: the rest of an epoch, in the
    // mesh already, is handed out by the next calls; a check there is
    // refused rather than answered from a mesh ahead of the points.
    const std::vector<double> whole = run_points(0.01, 8, 2, true, false);
    std::size_t refused = 0;
    ck_assert(run_points(0.01, 8, 2, true, false, 997, &refused) == whole);
    ck_assert_uint_gt(refused, 0);
    ck_assert(run_points(0.01, 8, 1, true, false, 389) == whole);
}
END_TEST

START_TEST(an_epoch_is_handed_out_in_order_of_time) {
    // The first free regions' epoch is drawn from the hand-over's mesh and
    // decided alike in both ways: by sides it must give the same points in
    // the same order (of time) as one by one; the mesh's records differ
    // from there on.
    std::vector<double> xy[2];
    std::size_t first_epoch_end = 0;
    for (const bool sides : {false, true}) {
        pds::Sampler s(0.004, 11);
        set_up(s, 2, sides);
        bool maximal = false;
        while (s.in_dart_stage() && s.add_points(1, &maximal) == 1) {
        }
        const std::size_t handed_over = s.count();
        ck_assert_uint_eq(s.add_points(1, &maximal), 1);
        const std::size_t end = handed_over + s.jones().region_stats().points;
        ck_assert_uint_gt(end, handed_over + 100);
        if (sides) ck_assert_uint_eq(end, first_epoch_end);
        first_epoch_end = end;
        s.add_points(0, &maximal);
        xy[sides].resize(2 * s.count());
        s.copy_points(0, s.count(), xy[sides].data());
    }
    ck_assert(xy[0].size() >= 2 * first_epoch_end && xy[1].size() >= 2 * first_epoch_end);
    for (std::size_t k = 0; k < 2 * first_epoch_end; ++k)
        ck_assert_msg(xy[0][k] == xy[1][k], "point %zu of %zu differs", k / 2, first_epoch_end);
    ck_assert(xy[0] != xy[1]);
}
END_TEST

START_TEST(an_allocation_failure_loses_nothing) {
    // The call that hands over and draws and inserts the first epoch,
    // failed at each of its allocations in turn (the mesh, the epoch's
    // pool, blocks and lists), then the run finished; and calls of 300
    // points each failed at its k-th allocation, the call after a failure
    // left alone. Either way the points are those of an undisturbed run.
    if (!alloc_hook::in_effect()) return;  // under Valgrind
    const std::vector<double> whole = run_points(0.01, 8, 2, true, false);
    const auto finish = [&](pds::Sampler& s, const char* what, long k) {
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        std::vector<double> xy(2 * s.count());
        s.copy_points(0, s.count(), xy.data());
        ck_assert_msg(xy == whole, "%s, k = %ld: other points", what, k);
        const pds::VerifyReport rep = s.verify();
        ck_assert_msg(rep.valid && rep.maximal, "%s, k = %ld: %s", what, k, rep.failure.c_str());
    };
    // The calls of one point up to the hand-over, whose last one also draws
    // and inserts the first epoch, and that call's allocations.
    std::size_t calls = 0;
    long allocations = 0;
    {
        pds::Sampler s(0.01, 8);
        set_up(s, 2, true);
        bool maximal = false;
        for (;;) {
            alloc_hook::arm(0);
            const std::size_t added = s.add_points(1, &maximal);
            allocations = alloc_hook::disarm();
            if (added == 1) ++calls;
            if (added != 1 || !s.in_dart_stage()) break;
        }
        ck_assert_uint_eq(s.jones().region_stats().epochs, 1);
    }
    ck_assert_msg(allocations >= 10, "the hand-over's call made %ld allocations", allocations);
    std::size_t failed = 0;
    for (long k = 1; k <= allocations; ++k) {
        pds::Sampler s(0.01, 8);
        set_up(s, 2, true);
        bool maximal = false;
        for (std::size_t c = 1; c < calls; ++c) s.add_points(1, &maximal);
        alloc_hook::arm(k);
        try {
            s.add_points(1, &maximal);
        } catch (const std::bad_alloc&) {
            ++failed;
        }
        alloc_hook::disarm();
        finish(s, "the hand-over's call", k);  // a thread not started: no failure, the same points
    }
    ck_assert_uint_gt(failed, 0);
    for (const long k : {1L, 3L, 8L}) {
        pds::Sampler s(0.01, 8);
        set_up(s, 2, true);
        std::size_t failures = 0;
        bool arm = true;
        for (;;) {
            std::size_t added = 0;
            if (arm) alloc_hook::arm(k);
            pds::Sampler::RunEnd end;
            try {
                end = s.run(300, &added);
            } catch (const std::bad_alloc&) {
                alloc_hook::disarm();
                ++failures;
                arm = false;
                continue;
            }
            alloc_hook::disarm();
            arm = true;
            if (end == pds::Sampler::RunEnd::complete) break;
        }
        ck_assert_msg(failures >= 2, "calls of 300, k = %ld: %zu failures", k, failures);
        finish(s, "calls of 300", k);
    }
}
END_TEST

START_TEST(an_epoch_grows_the_room_within_the_cap) {
    // The Jones stage alone, handed a lattice 2.2 R apart (much free room
    // left) and then the free regions' darts, by sides, with room for one
    // more point at a time: the epochs outgrow it and grow it themselves,
    // doubling, but not far past the cap they were given (their records
    // are appended after the free ones, so an epoch may ask a little past
    // it; before, that was found only by an error in the insertions).
    const double r = 0.01;
    const std::size_t cap = 5000;
    std::vector<pds::Point> lattice;
    for (int i = 0; i < 45; ++i)
        for (int j = 0; j < 45; ++j) lattice.push_back(pds::Point{(i + 0.5) * 2.2 * r, (j + 0.5) * 2.2 * r});
    std::vector<std::uint32_t> order(lattice.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto stage = pds::make_jones_stage(pds::Box{0, 0, 1, 1}, r);
    stage->set_side_insertions(true);
    stage->set_room_cap(cap);
    stage->reserve(lattice.size());
    stage->adopt(lattice, order.data());
    stage->carry_darts(pds::SpaceTimeStream::salted(3), 0);
    pds::Rng rng(3);
    std::size_t past_half = 0;
    while (stage->count() < 4900) {
        if (!stage->has_room_for(stage->count() + 1)) stage->reserve(stage->count() + 1);
        ck_assert(stage->next(rng) != nullptr);
        stage->add_next();
        // Past half the cap, doubling alone would pass it.
        if (stage->count() > cap / 2 && stage->has_room_for(stage->count() + 2)) {
            ++past_half;
            ck_assert_msg(!stage->has_room_for(cap + cap / 10), "room far past the cap at %zu points", stage->count());
        }
    }
    ck_assert_uint_gt(stage->region_stats().points, 1000);
    ck_assert_uint_gt(past_half, 0);
}
END_TEST

START_TEST(the_torus_ignores_it) {
    ck_assert(run_points(0.01, 3, 2, true, true) == run_points(0.01, 3, 2, false, true));
}
END_TEST

Suite* side_insertions_suite() {
    Suite* s = suite_create("side_insertions");
    TCase* t = tcase_create("side_insertions");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, same_points_on_any_threads_and_maximal);
    tcase_add_test(t, call_splits_give_the_same_points);
    tcase_add_test(t, an_epoch_is_handed_out_in_order_of_time);
    tcase_add_test(t, an_allocation_failure_loses_nothing);
    tcase_add_test(t, an_epoch_grows_the_room_within_the_cap);
    tcase_add_test(t, the_torus_ignores_it);
    suite_add_tcase(s, t);
    return s;
}
