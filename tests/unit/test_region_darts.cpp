// test_region_darts.cpp - the free regions' dart process after the parallel
// opening (jones/region_darts.hpp): an epoch's decision is the greedy set in
// order of time, against a brute-force one, over blocks, across epochs and
// at the domain's edges; and in a run it places a real share of the points,
// which stay the same on any number of threads and are dropped by a refine;
// a cell's count is Poisson whatever its mean. With a field: each accepted
// dart keeps the later ones out of its own disk, the field is asked once per
// accepted dart in order of time, a refusal leaves the epoch undecided, and a
// run's points stay the same on any number of threads, in the plane and on
// the torus (where the disks reach across the seams).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "core/space_time_stream.hpp"
#include "jones/region_darts.hpp"
#include "radius/radius_field.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

using Dart = pds::RegionDarts::Dart;

// Greedy in order of time (ties: the earlier in the list), by brute force:
// a dart is kept unless holds(k, dart) for an earlier kept dart k.
template <class Holds>
std::vector<Dart> greedy_with(const std::vector<Dart>& darts, const Holds& holds) {
    std::vector<std::size_t> order(darts.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return darts[a].t < darts[b].t; });
    std::vector<Dart> kept;
    for (std::size_t i : order)
        if (std::none_of(kept.begin(), kept.end(), [&](const Dart& k) { return holds(k.p, darts[i].p); }))
            kept.push_back(darts[i]);
    return kept;
}

// Each kept dart holding the later ones out of its disk of radius
// radius(dart); on the torus t (darts inside its fundamental domain, on its
// grid), out of its copies' a period away too.
template <class Radius>
std::vector<Dart> greedy_by(const std::vector<Dart>& darts, const Radius& radius) {
    return greedy_with(darts, [&](const pds::Point& k, const pds::Point& p) {
        return pds::compare_distance(p, k, radius(k)) < 0;
    });
}
template <class Radius>
std::vector<Dart> greedy_on_torus(const std::vector<Dart>& darts, const pds::Torus& t, const Radius& radius) {
    return greedy_with(darts, [&](const pds::Point& k, const pds::Point& p) {
        for (int sy = -1; sy <= 1; ++sy)
            for (int sx = -1; sx <= 1; ++sx)
                if (pds::compare_distance(p, t.shifted(k, sx, sy), radius(k)) < 0) return true;
        return false;
    });
}
std::vector<Dart> greedy(const std::vector<Dart>& darts, double r) {
    return greedy_by(darts, [r](const pds::Point&) { return r; });
}

// A 1:4 field along x over the unit square, r = 0.02 + 0.06 x, which
// records where it is asked and can refuse its call number `refuse_at`.
struct GradientField final : pds::DartField {
    static double radius_at(const pds::Point& p) { return 0.02 + 0.06 * p.x; }
    double value_at(const pds::Point& p) const override {
        if (asked.size() == refuse_at) throw std::range_error("refused");
        asked.push_back(p);
        return radius_at(p);
    }
    double radius_of(double value) const override { return value; }
    mutable std::vector<pds::Point> asked;
    std::size_t refuse_at = std::numeric_limits<std::size_t>::max();
};

// Hands `darts` to `rd` split over `nblocks` blocks in list order.
std::vector<pds::RegionDarts::Block>& fill_blocks(pds::RegionDarts& rd, const std::vector<Dart>& darts,
                                                  std::size_t nblocks) {
    std::vector<pds::RegionDarts::Block>& blocks = rd.blocks(nblocks);
    for (std::size_t i = 0; i < darts.size(); ++i) blocks[i * nblocks / darts.size()].darts.push_back(darts[i]);
    return blocks;
}

// Hands `darts` to `rd` as fill_blocks does, decides them (with `field`, if
// any) and returns what became pending.
std::vector<Dart> decide(pds::RegionDarts& rd, const std::vector<Dart>& darts, std::size_t nblocks,
                         const pds::DartField* field = nullptr) {
    fill_blocks(rd, darts, nblocks);
    rd.decide_and_commit(nblocks, [](pds::SiteIndex, double) {}, field);
    std::vector<Dart> out;
    for (; rd.has_pending(); rd.pop()) out.push_back(rd.pending());
    return out;
}

// The gradient field's largest radius, over the unit square.
const double kFieldRmax = GradientField::radius_at({1, 0});

// Starts `rd` in the unit square for the gradient field, from `epoch`.
void start_with_field(pds::RegionDarts& rd, std::size_t epoch) {
    rd.start(1, epoch, pds::Box{0, 0, 1, 1}, kFieldRmax, pds::Torus{}, true);
}

// One epoch of `darts` in the unit square.
std::vector<Dart> decide_once(const std::vector<Dart>& darts, std::size_t nblocks, double r) {
    pds::RegionDarts rd;
    rd.start(1, 0, pds::Box{0, 0, 1, 1}, r);
    return decide(rd, darts, nblocks);
}

void assert_same_darts(const std::vector<Dart>& got, const std::vector<Dart>& want, const char* what) {
    ck_assert_msg(got.size() == want.size(), "%s: %zu accepted, the greedy set has %zu", what, got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        ck_assert_msg(got[i].p.x == want[i].p.x && got[i].p.y == want[i].p.y && got[i].t == want[i].t,
                      "%s: accepted dart %zu differs", what, i);
}

// n darts uniform in box and in time, a tenth of them on its edges.
std::vector<Dart> random_darts(pds::Rng& rng, const pds::Box& box, std::size_t n) {
    std::vector<Dart> d(n);
    for (std::size_t i = 0; i < n; ++i) {
        double x = box.x0 + rng.next_double() * box.width(), y = box.y0 + rng.next_double() * box.height();
        if (i % 10 == 0) x = (i % 20 == 0) ? box.x0 : box.x1;
        if (i % 15 == 0) y = (i % 30 == 0) ? box.y0 : box.y1;
        d[i] = Dart{{x, y}, rng.next_double(), static_cast<pds::VertexIndex>(i)};
    }
    return d;
}

}  // namespace

START_TEST(decision_is_the_greedy_set_in_order_of_time) {
    // Many darts per disk, so nearly every one meets others: the order
    // decides. Several epochs in a row: the grid must forget the last one's.
    const pds::Box box{-1.0, 2.0, 0.5, 2.6};
    const double r = 0.05;
    pds::RegionDarts rd;
    rd.start(1, 0, box, r);
    pds::Rng rng(17);
    for (int epoch = 0; epoch < 4; ++epoch) {
        const std::vector<Dart> darts = random_darts(rng, box, 1500);
        const std::vector<Dart> got = decide(rd, darts, 1 + static_cast<std::size_t>(epoch) * 3);
        assert_same_darts(got, greedy(darts, r), "epoch");
        ck_assert_uint_gt(got.size(), 50);
        ck_assert_uint_lt(got.size(), 1000);
    }
    ck_assert_uint_eq(rd.stats().epochs, 4);
}
END_TEST

START_TEST(ties_in_time_go_to_the_earlier_block) {
    // Two darts 0.05 apart at the same time, in two blocks; a third, far
    // away and later, is kept too.
    const std::vector<Dart> darts{{{0.5, 0.5}, 0.25, 7}, {{0.55, 0.5}, 0.25, 8}, {{0.9, 0.9}, 0.5, 9}};
    const std::vector<Dart> got = decide_once(darts, 3, 0.1);
    ck_assert_uint_eq(got.size(), 2);
    ck_assert_uint_eq(got[0].source, 7);
    ck_assert_uint_eq(got[1].source, 9);
}
END_TEST

START_TEST(darts_exactly_r_apart_are_both_kept) {
    // "At least R apart" is allowed: only a distance below R conflicts.
    const std::vector<Dart> darts{{{0.25, 0.5}, 0.1, 1}, {{0.5, 0.5}, 0.2, 2}, {{0.5, 0.7}, 0.3, 3}};
    const std::vector<Dart> got = decide_once(darts, 1, 0.25);
    ck_assert_uint_eq(got.size(), 2);
    ck_assert_uint_eq(got[1].source, 2);
}
END_TEST

START_TEST(run_places_a_share_the_same_on_any_threads) {
    // 40,000 points: the free cells at the hand-over fill several blocks.
    std::vector<double> first;
    for (unsigned threads = 1; threads <= 3; ++threads) {
        pds::Sampler s(0.004, 5);
        s.set_threads(threads);
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        const pds::RegionDarts::Stats& st = s.jones().region_stats();
        const double share = static_cast<double>(st.points) / static_cast<double>(s.count());
        ck_assert_msg(share > 0.15 && share < 0.4, "the free regions' darts placed %.3f of the points", share);
        ck_assert_uint_ge(st.darts, st.points);
        std::vector<double> xy(2 * s.count());
        s.copy_points(0, s.count(), xy.data());
        if (threads == 1) first = xy;
        else ck_assert_msg(xy == first, "%u threads: other points", threads);
        ck_assert_msg(s.verify().failure.empty(), "verify: %s", s.verify().failure.c_str());
    }
}
END_TEST

START_TEST(refine_ends_the_free_regions_darts) {
    // A refine in the middle of the process: the darts drawn for the old
    // radius are dropped and the loop's own draws finish maximal.
    pds::Sampler s(0.004, 5);
    s.set_threads(2);
    std::size_t added = 0;
    s.run(50000 * 3 / 4 + 2000, &added);  // past the hand-over (about 75%)
    const std::size_t placed = s.jones().region_stats().points;
    ck_assert_uint_gt(placed, 0);
    s.refine(0.0035);
    ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
    ck_assert_uint_eq(s.jones().region_stats().points, placed);
    ck_assert_msg(s.verify().failure.empty(), "verify: %s", s.verify().failure.c_str());
}
END_TEST

START_TEST(field_decision_keeps_later_darts_out_of_each_disk) {
    // Three epochs of darts decided by the 1:4 field: the greedy set in
    // order of time, each accepted dart's disk its own radius. Deciding by
    // the largest or the smallest radius gives other sets, so the test
    // sees which radius is used.
    const pds::Box box{0, 0, 1, 1};
    pds::RegionDarts rd;
    start_with_field(rd, 0);
    ck_assert(rd.has_values());
    pds::Rng rng(23);
    for (int epoch = 0; epoch < 3; ++epoch) {
        const std::vector<Dart> darts = random_darts(rng, box, 2000);
        GradientField field;
        fill_blocks(rd, darts, 4);
        rd.decide_and_commit(4, [](pds::SiteIndex, double) {}, &field);
        std::vector<Dart> got;
        std::vector<double> values;
        for (; rd.has_pending(); rd.pop()) {
            got.push_back(rd.pending());
            values.push_back(rd.pending_value());
        }
        const std::vector<Dart> want = greedy_by(darts, GradientField::radius_at);
        assert_same_darts(got, want, "field epoch");
        // Asked once per accepted dart, in order of time; the values kept.
        ck_assert_uint_eq(field.asked.size(), got.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
            ck_assert(field.asked[i].x == got[i].p.x && field.asked[i].y == got[i].p.y);
            ck_assert(values[i] == GradientField::radius_at(got[i].p));
        }
        const auto by_rmax = greedy_by(darts, [&](const pds::Point&) { return kFieldRmax; });
        const auto by_rmin = greedy_by(darts, [&](const pds::Point&) { return 0.02; });
        ck_assert_uint_lt(by_rmax.size(), got.size());
        ck_assert_uint_gt(by_rmin.size(), got.size());
    }
}
END_TEST

START_TEST(torus_field_decision_keeps_later_darts_out_of_each_disk_and_its_copies) {
    // The 1:4 field on the unit torus steps from its largest radius back to
    // its smallest across the seam at x = 0; a fifth of the darts lie
    // within the largest radius of a seam. Deciding by the largest radius
    // gives another set, so the test sees which radius is used there.
    const pds::Torus torus{1.0, 1.0, 0.0, 0.0};
    pds::RegionDarts rd;
    rd.start(1, 0, pds::Box{0, 0, 1, 1}, kFieldRmax, torus, true);
    pds::Rng rng(31);
    for (int epoch = 0; epoch < 2; ++epoch) {
        std::vector<Dart> darts = random_darts(rng, pds::Box{0, 0, 1, 1}, 1500);
        for (std::size_t i = 0; i < darts.size(); ++i) {
            pds::Point& p = darts[i].p;
            if (i % 5 == 0) p.x = (i % 10 == 0 ? 0.0 : 1.0 - kFieldRmax) + kFieldRmax * rng.next_double();
            p = torus.wrap(pds::Point{pds::Torus::snap(p.x), pds::Torus::snap(p.y)});
        }
        GradientField field;
        fill_blocks(rd, darts, 3);
        rd.decide_and_commit(3, [](pds::SiteIndex, double) {}, &field);
        std::vector<Dart> got;
        for (; rd.has_pending(); rd.pop()) got.push_back(rd.pending());
        assert_same_darts(got, greedy_on_torus(darts, torus, GradientField::radius_at), "torus field epoch");
        ck_assert_uint_eq(field.asked.size(), got.size());
        const auto by_rmax = greedy_on_torus(darts, torus, [&](const pds::Point&) { return kFieldRmax; });
        ck_assert_uint_lt(by_rmax.size(), got.size());
    }
}
END_TEST

START_TEST(refused_field_value_leaves_the_epoch_undecided) {
    // The field refuses its sixth call: nothing is pending, no bound is
    // committed, the epoch is the same; deciding the same darts again
    // gives the greedy set (the grid kept none of the undone darts).
    pds::RegionDarts rd;
    start_with_field(rd, 3);
    pds::Rng rng(29);
    const std::vector<Dart> darts = random_darts(rng, pds::Box{0, 0, 1, 1}, 800);
    GradientField refusing;
    refusing.refuse_at = 5;
    fill_blocks(rd, darts, 2)[0].bounds.push_back(pds::RegionDarts::Bound{7, 0.5});
    std::size_t committed = 0;
    bool refused = false;
    try {
        rd.decide_and_commit(2, [&](pds::SiteIndex, double) { ++committed; }, &refusing);
    } catch (const std::range_error&) {
        refused = true;
    }
    ck_assert(refused);
    ck_assert(!rd.has_pending());
    ck_assert_uint_eq(committed, 0);
    ck_assert_uint_eq(rd.epoch(), 3);
    ck_assert_uint_eq(rd.stats().epochs, 0);
    GradientField field;
    assert_same_darts(decide(rd, darts, 2, &field), greedy_by(darts, GradientField::radius_at), "again");
    ck_assert_uint_eq(rd.epoch(), 4);
}
END_TEST

namespace {

double gradient_field(void*, double x, double) { return 0.004 * (1.0 + 2.0 * x); }

// Counts the calls of a gradient field (1:3 along x).
struct CallCount {
    std::size_t calls = 0;
    static double radius(void* self, double x, double y) {
        ++static_cast<CallCount*>(self)->calls;
        return gradient_field(nullptr, x, y);
    }
};

}  // namespace

START_TEST(field_run_places_a_share_the_same_on_any_threads) {
    // About 24,000 points, in the unit square and (_i = 1) on the unit
    // torus; the field's dart stage, then its darts carried on in the free
    // regions with threads: the same points on 1, 2 and 3, other than
    // without threads, the field asked once per point.
    std::vector<double> first, alone;
    for (unsigned threads = 0; threads <= 3; ++threads) {
        CallCount count;
        pds::Sampler s(1.0, 8);
        s.set_periodic(_i == 1);
        s.set_field(pds::RadiusField::function(&CallCount::radius, &count, 0.004, 0.012));
        if (threads != 0) s.set_threads(threads);
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        ck_assert_uint_eq(count.calls, s.count());
        const pds::RegionDarts::Stats& st = s.jones().region_stats();
        const double share = static_cast<double>(st.points) / static_cast<double>(s.count());
        if (threads == 0) ck_assert_uint_eq(st.points, 0);
        else ck_assert_msg(share > 0.1 && share < 0.4, "the free regions' darts placed %.3f of the points", share);
        std::vector<double> xy(2 * s.count());
        s.copy_points(0, s.count(), xy.data());
        if (threads == 0) alone = xy;
        else if (threads == 1) first = xy;
        else ck_assert_msg(xy == first, "%u threads: other points", threads);
        ck_assert_msg(s.verify().failure.empty(), "verify: %s", s.verify().failure.c_str());
    }
    ck_assert(first != alone);
}
END_TEST

START_TEST(poisson_counts_of_large_means) {
    // Over 4000 streams, the counts' mean and variance are the mean's, far
    // past one inversion's cap of 63 (and past e^-mean's underflow at 1000).
    for (const double mean : {17.0, 100.0, 1000.0}) {
        double sum = 0.0, squares = 0.0;
        constexpr int kStreams = 4000;
        for (int c = 0; c < kStreams; ++c) {
            pds::SpaceTimeStream stream(99, static_cast<std::uint64_t>(c), 5);
            const double k = stream.poisson_large(mean);
            sum += k;
            squares += k * k;
        }
        const double m = sum / kStreams, var = squares / kStreams - m * m;
        ck_assert_msg(std::fabs(m - mean) < 5.0 * std::sqrt(mean / kStreams), "mean %g: the counts' mean %g", mean, m);
        ck_assert_msg(std::fabs(var / mean - 1.0) < 0.12, "mean %g: the counts' variance %g", mean, var);
    }
}
END_TEST

START_TEST(a_cell_far_above_the_others_gets_its_whole_count) {
    // From the first point on, in epochs of 400 darts per cell at its
    // bound: the first epoch's one cell draws a Poisson(400) count, which
    // a count capped at 63 would cut short.
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        pds::Sampler s(0.01, seed);
        s.carry_region_darts_from_start();
        s.set_region_darts_per_cell(400.0);
        std::size_t added = 0;
        s.run(2, &added);
        const pds::RegionDarts::Stats& st = s.jones().region_stats();
        ck_assert_uint_eq(st.epochs, 1);
        ck_assert_msg(st.darts > 300 && st.darts < 500, "seed %d: %zu darts in the first epoch", int(seed), st.darts);
    }
}
END_TEST

Suite* region_darts_suite() {
    Suite* s = suite_create("region_darts");
    TCase* t = tcase_create("region_darts");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, decision_is_the_greedy_set_in_order_of_time);
    tcase_add_test(t, ties_in_time_go_to_the_earlier_block);
    tcase_add_test(t, darts_exactly_r_apart_are_both_kept);
    tcase_add_test(t, run_places_a_share_the_same_on_any_threads);
    tcase_add_test(t, refine_ends_the_free_regions_darts);
    tcase_add_test(t, poisson_counts_of_large_means);
    tcase_add_test(t, a_cell_far_above_the_others_gets_its_whole_count);
    tcase_add_test(t, field_decision_keeps_later_darts_out_of_each_disk);
    tcase_add_test(t, torus_field_decision_keeps_later_darts_out_of_each_disk_and_its_copies);
    tcase_add_test(t, refused_field_value_leaves_the_epoch_undecided);
    tcase_add_loop_test(t, field_run_places_a_share_the_same_on_any_threads, 0, 2);
    suite_add_tcase(s, t);
    return s;
}
