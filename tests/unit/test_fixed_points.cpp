// test_fixed_points.cpp - fixed points: the first sampled point uniform over
// the domain minus their clearance disks (against rejection sampling, in a
// polygon with a hole, with an obstacle partly outside it and two fixed
// points that overlap); maximal patterns that keep every clearance, count
// and return only the sampled points, and pass verify; a refine's mesh
// rebuilt whole around them.
#include <check.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/rng.hpp"
#include "domain/polygon.hpp"
#include "even_odd.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

using pds::Point;

// A C shape with a hole (as in test_outline_clip.cpp), and its even-odd test.
const std::vector<double> kXY = {0, 0, 1, 0, 1, 0.3, 0.3, 0.3, 0.3, 0.7, 1, 0.7, 1, 1, 0, 1,
                                 0.1, 0.4, 0.2, 0.4, 0.2, 0.6, 0.1, 0.6};
const std::vector<std::size_t> kEnds = {8, 12};

bool in_shape(const Point& p) { return even_odd_contains(kXY.data(), kEnds.data(), kEnds.size(), p); }

// An obstacle over the C's mouth (partly outside), two overlapping small ones.
const std::vector<Point> kFixed = {{0.8, 0.5}, {0.5, 0.15}, {0.55, 0.15}};
const std::vector<double> kClearance = {0.3, 0.1, 0.1};

pds::Sampler make(double r, std::uint64_t seed) {
    pds::Sampler s(r, seed);
    s.set_polygon(std::make_shared<const pds::Polygon>(kXY.data(), kEnds.data(), kEnds.size()));
    s.set_fixed(kFixed, kClearance);
    return s;
}

bool clear_of_fixed(const Point& p) {
    for (std::size_t k = 0; k < kFixed.size(); ++k)
        if (std::hypot(p.x - kFixed[k].x, p.y - kFixed[k].y) < kClearance[k]) return false;
    return true;
}

START_TEST(first_point_is_uniform_around_fixed_points) {
    const int nb = 5;
    std::vector<double> sampled(nb * nb, 0.0), reference(nb * nb, 0.0);
    const auto bin = [&](const Point& p) {
        return std::min(nb - 1, static_cast<int>(p.y * nb)) * nb + std::min(nb - 1, static_cast<int>(p.x * nb));
    };
    pds::Rng rng(777);
    const int runs = test_light() ? 1500 : 30000;
    for (int k = 0; k < runs; ++k) {
        pds::Sampler s = make(0.2, static_cast<std::uint64_t>(k) + 1);
        std::size_t added = 0;
        s.run(1, &added);
        ck_assert_uint_eq(s.count(), 1);
        double xy[2];
        s.copy_points(0, 1, xy);
        sampled[bin(Point{xy[0], xy[1]})] += 1.0;
        for (;;) {
            const Point p{rng.next_double(), rng.next_double()};
            if (!in_shape(p) || !clear_of_fixed(p)) continue;
            reference[bin(p)] += 1.0;
            break;
        }
    }
    double chi2 = 0.0;
    int dof = -1;
    for (int b = 0; b < nb * nb; ++b) {
        const double total = sampled[b] + reference[b];
        if (total == 0.0) continue;
        chi2 += (sampled[b] - reference[b]) * (sampled[b] - reference[b]) / total;
        ++dof;
    }
    const double k = dof, z = 3.719, c = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
    ck_assert_msg(chi2 < k * c * c * c, "chi2 %.1f with %d degrees of freedom (limit %.1f)", chi2, dof, k * c * c * c);
}
END_TEST

START_TEST(maximal_patterns_keep_the_clearances) {
    const std::uint64_t seeds = test_light() ? 1 : 4;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        pds::Sampler s = make(test_light() ? 0.06 : 0.03, seed);
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        ck_assert_uint_eq(added, s.count());
        std::vector<double> xy(2 * s.count());
        ck_assert_uint_eq(s.copy_points(0, s.count(), xy.data()), s.count());
        for (std::size_t i = 0; i < s.count(); ++i) {
            const Point p{xy[2 * i], xy[2 * i + 1]};
            ck_assert(in_shape(p) || s.verify().valid);
            ck_assert_msg(clear_of_fixed(p), "seed %llu: point %zu within a clearance",
                          static_cast<unsigned long long>(seed), i);
            for (const Point& f : kFixed) ck_assert(p.x != f.x || p.y != f.y);  // never returned
        }
        const pds::VerifyReport rep = s.verify();
        ck_assert_msg(rep.valid && rep.maximal, "%s", rep.failure.c_str());
        ck_assert(s.free_area() == 0.0);
        // Without the fixed points the same seed makes more points.
        pds::Sampler plain(test_light() ? 0.06 : 0.03, seed);
        plain.set_polygon(std::make_shared<const pds::Polygon>(kXY.data(), kEnds.data(), kEnds.size()));
        plain.run(0, &added);
        ck_assert_uint_gt(plain.count(), s.count());
    }
}
END_TEST

START_TEST(a_refine_rebuilds_the_mesh_around_them) {
    // Past 4096 sampled points a refine builds their mesh whole and inserts
    // the fixed points after (their vertices numbered anew): the points so
    // far read back unchanged, the pattern goes on valid and maximal, clear
    // of every clearance (scaled with the radius), and the same with the
    // parallel process on 1 and 3 threads.
    for (unsigned threads = 0; threads <= 3; threads += 1 + (threads == 1)) {
        pds::Sampler s = make(0.007, 5);
        if (threads != 0) s.set_threads(threads);
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        const std::size_t before = s.count();
        ck_assert_uint_gt(before, 4096 + 100);
        std::vector<double> first(2 * before), again(2 * before);
        s.copy_points(0, before, first.data());
        s.refine(0.005);
        s.copy_points(0, before, again.data());
        ck_assert(first == again);
        pds::VerifyReport rep = s.verify();
        ck_assert_msg(rep.valid && !rep.maximal, "threads %u: %s", threads, rep.failure.c_str());
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        rep = s.verify();
        ck_assert_msg(rep.valid && rep.maximal, "threads %u: %s", threads, rep.failure.c_str());
        std::vector<double> xy(2 * s.count());
        s.copy_points(0, s.count(), xy.data());
        for (std::size_t i = 0; i < s.count(); ++i)  // the clearances scaled with the radius
            for (std::size_t k = 0; k < kFixed.size(); ++k)
                ck_assert(std::hypot(xy[2 * i] - kFixed[k].x, xy[2 * i + 1] - kFixed[k].y) >=
                          kClearance[k] * (0.005 / 0.007) * (1.0 - 1e-12));
    }
}
END_TEST

}  // namespace

Suite* fixed_points_suite() {
    Suite* s = suite_create("fixed_points");
    TCase* tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, first_point_is_uniform_around_fixed_points);
    tcase_add_test(tc, maximal_patterns_keep_the_clearances);
    tcase_add_test(tc, a_refine_rebuilds_the_mesh_around_them);
    suite_add_tcase(s, tc);
    return s;
}
