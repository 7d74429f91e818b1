// test_dart_stage_fixed.cpp - the single-thread process with fixed points:
// its dart stage (one radius, or a field's layers) keeps its darts out of
// the clearance disks, laid over the dart grid's cells (fixed_disks.hpp's
// plain grid). For any point of a closed cell the disks say covered exactly
// when the point lies strictly inside a disk, whole cells included; the
// stage opens the run (it is still running after the first points), the
// patterns keep every clearance, are maximal, and do not depend on how the
// run is split; count mode and a refine hand over from it; and whole runs
// around fixed disks, with one radius and with a field, follow the law of
// saturated dart throwing in the box less the disks, the arrival time of the
// points near the circles included.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "darts/dart_constants.hpp"
#include "darts/fixed_disks.hpp"
#include "dart_throwing.hpp"
#include "fixed_cases.hpp"
#include "law_compare.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "threaded_runs.hpp"

namespace {

using fixed_cases::assert_clear;
using fixed_cases::with_fixed;

// The run to the end in calls of `chunk` points (0: one call), verified.
std::vector<double> run_in_calls(pds::Sampler& s, std::size_t chunk) {
    std::size_t added = 0;
    while (s.run(chunk, &added) != pds::Sampler::RunEnd::complete) {
    }
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.failure.empty() && rep.maximal, "verify: %s", rep.failure.c_str());
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    return xy;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The law tests' disks in the unit square: a large one, one on the edge,
// two that overlap.
const std::vector<pds::Point> kLawFixed = {{0.35, 0.4}, {1.0, 0.8}, {0.75, 0.3}, {0.8, 0.35}};
const std::vector<double> kLawClearance = {0.2, 0.15, 0.08, 0.06};

double gradient(void*, double x, double) { return 0.06 * (1.0 + x); }

// The mean arrival time (index / count) of the points in the band within
// their own radius of a clearance circle: darts kept out of that band by
// mistake leave it to the Jones loop, later, which the counts and distances
// of law_compare.hpp barely see (the Jones loop fills the band all the same).
double band_arrival(const oracle::Pattern& t) {
    double sum = 0;
    std::size_t in_band = 0;
    for (std::size_t i = 0; i < t.p.size(); ++i)
        for (std::size_t k = 0; k < kLawFixed.size(); ++k) {
            const double dx = t.p[i].x - kLawFixed[k].x, dy = t.p[i].y - kLawFixed[k].y;
            if (std::sqrt(dx * dx + dy * dy) - kLawClearance[k] < t.r[i]) {
                sum += (static_cast<double>(i) + 0.5) / static_cast<double>(t.p.size());
                ++in_band;
                break;
            }
        }
    return in_band ? sum / static_cast<double>(in_band) : 0.5;
}

// Runs configured as c around the law disks against saturated dart
// throwing in the box less the disks, under the same radius rule.
template <class Radius>
void compare_around_disks(const law::Config& c, const Radius& radius) {
    oracle::AroundDisks rule;
    rule.box = c.box;
    rule.centre = kLawFixed;
    rule.radius = kLawClearance;
    auto reference = oracle::dart_throwing(rule, radius);
    law::Sample sampler, darts;
    std::vector<double> band_sampler, band_darts;
    std::size_t from_darts = 0, total = 0;
    for (int seed = 1; seed <= c.runs; ++seed) {
        pds::Sampler s(c.field ? 1.0 : c.r, static_cast<std::uint64_t>(seed));
        law::configure(s, c);
        s.set_fixed(kLawFixed, kLawClearance);
        const oracle::Pattern a = law::run_to_the_end(s, &from_darts);
        const oracle::Pattern b = reference.run(static_cast<std::uint64_t>(1000000 + seed));
        total += a.p.size();
        law::add(sampler, a, rule);
        law::add(darts, b, rule);
        band_sampler.push_back(band_arrival(a));
        band_darts.push_back(band_arrival(b));
    }
    const double z_band = law::z_score(band_sampler, band_darts);
    law::assert_stages(c, from_darts, total);
    if (std::getenv("PDS_LAW_PRINT"))
        std::printf("around disks%s: N %.4f / %.4f (z %.2f), close pairs %.4f / %.4f (z %.2f), to earlier %.5f / "
                    "%.5f (z %.2f), KS %.2f, band arrival %.4f / %.4f (z %.2f), darts %.3f\n",
                    c.field ? ", a field" : "", law::mean(sampler.count), law::mean(darts.count),
                    law::z_score(sampler.count, darts.count), law::mean(sampler.close_pairs),
                    law::mean(darts.close_pairs), law::z_score(sampler.close_pairs, darts.close_pairs),
                    law::mean(sampler.to_earlier), law::mean(darts.to_earlier),
                    law::z_score(sampler.to_earlier, darts.to_earlier), law::ks_scaled(sampler.count, darts.count),
                    law::mean(band_sampler), law::mean(band_darts), z_band,
                    static_cast<double>(from_darts) / static_cast<double>(total));
    law::assert_same_law(sampler, darts);
    ck_assert_msg(std::fabs(z_band) < 4.5,
                  "arrival in the band around the clearances: sampler %.4f, dart throwing %.4f (z = %.2f)",
                  law::mean(band_sampler), law::mean(band_darts), z_band);
}

}  // namespace

START_TEST(plain_grid_disks_cover_exactly_the_points_inside) {
    // Cells of a dart grid at R 0.02 over a box; 40 disks, some large (many
    // cells wholly inside), some small (under a cell), one of radius 0.
    const double side = pds::darts::cell_side(0.02);
    const pds::Box box{0.0, 0.0, 1.0, 0.8};
    const pds::DiskGrid grid{box, static_cast<std::size_t>(std::ceil(1.0 / side)),
                             static_cast<std::size_t>(std::ceil(0.8 / side)), side, side};
    pds::Rng rng(11);
    std::vector<pds::Point> centres;
    std::vector<double> radii;
    for (int k = 0; k < 40; ++k) {
        centres.push_back(pds::Point{rng.next_double(), 0.8 * rng.next_double()});
        radii.push_back(k == 0 ? 0.0 : k % 4 == 0 ? 0.3 * rng.next_double() : 0.02 * rng.next_double());
    }
    pds::FixedDisks disks;
    ck_assert(disks.build(grid, centres, radii, std::size_t{1} << 24));
    const auto inside = [&](const pds::Point& p) {
        for (std::size_t k = 0; k < centres.size(); ++k)
            if (pds::compare_distance(p, centres[k], radii[k]) < 0) return true;
        return false;
    };
    // Each closed cell's corners, centre and random points; then points on
    // and just inside the circles.
    std::size_t covered = 0, checked = 0;
    for (std::size_t row = 0; row < grid.rows; ++row)
        for (std::size_t col = 0; col < grid.cols; ++col) {
            const auto cell = static_cast<std::uint32_t>(row * grid.cols + col);
            const double x0 = static_cast<double>(col) * side, y0 = static_cast<double>(row) * side;
            std::vector<pds::Point> probes = {{x0, y0}, {x0 + side, y0}, {x0, y0 + side}, {x0 + side, y0 + side},
                                              {x0 + 0.5 * side, y0 + 0.5 * side}};
            for (int t = 0; t < 3; ++t) probes.push_back({x0 + side * rng.next_double(), y0 + side * rng.next_double()});
            for (const pds::Point& p : probes) {
                const bool said = disks.covered(p, cell), in = inside(p);
                ++checked;
                covered += said;
                if (said != in)
                    ck_abort_msg("(%.17g, %.17g) in cell %u: covered %d, inside a disk %d", p.x, p.y, cell, said, in);
            }
        }
    ck_assert_msg(covered > checked / 20, "only %zu of %zu probes covered", covered, checked);
    for (std::size_t k = 1; k < centres.size(); ++k)
        for (int t = 0; t < 64; ++t) {
            const double a = 2.0 * M_PI * t / 64.0;
            for (const double f : {1.0, 1.0 - 1e-12, 1.0 - 1e-6}) {
                const pds::Point p{centres[k].x + f * radii[k] * std::cos(a), centres[k].y + f * radii[k] * std::sin(a)};
                if (p.x < 0.0 || p.y < 0.0 || p.x > 1.0 || p.y > 0.8) continue;
                const auto col = std::min(grid.cols - 1, static_cast<std::size_t>(p.x / side));
                const auto row = std::min(grid.rows - 1, static_cast<std::size_t>(p.y / side));
                const auto cell = static_cast<std::uint32_t>(row * grid.cols + col);
                if (disks.covered(p, cell) != inside(p))
                    ck_abort_msg("(%.17g, %.17g) near disk %zu's circle misjudged", p.x, p.y, k);
            }
        }
    // Circles through cell corners (cells of side 1/64, a 3-4-5 triangle: exact):
    // a cell whose farthest corner lies on a circle is not wholly inside.
    const double s64 = 1.0 / 64.0;
    const pds::DiskGrid exact{pds::Box{0.0, 0.0, 1.0, 1.0}, 64, 64, s64, s64};
    const std::vector<pds::Point> at = {{0.25, 0.25}, {0.625, 0.5}};
    const std::vector<double> five = {5.0 * s64, 10.0 * s64};
    pds::FixedDisks on_corners;
    ck_assert(on_corners.build(exact, at, five, std::size_t{1} << 24));
    std::size_t on_circle = 0;
    for (std::uint32_t cell = 0; cell < 64 * 64; ++cell)
        for (int c = 0; c < 4; ++c) {
            const pds::Point p{(cell % 64 + c % 2) * s64, (cell / 64 + c / 2) * s64};
            bool in = false;
            for (std::size_t k = 0; k < at.size(); ++k) {
                const int d = pds::compare_distance(p, at[k], five[k]);
                in = in || d < 0;
                on_circle += d == 0;
            }
            if (on_corners.covered(p, cell) != in)
                ck_abort_msg("corner (%.17g, %.17g) of cell %u misjudged", p.x, p.y, cell);
        }
    ck_assert_msg(on_circle > 50, "%zu corners on a circle", on_circle);
    // Past the budget, or past 2^32 cells, the disks decline.
    pds::FixedDisks over;
    ck_assert(!over.build(grid, centres, radii, 1000));
    pds::FixedDisks huge;
    ck_assert(!huge.build(pds::DiskGrid{box, std::size_t{1} << 17, std::size_t{1} << 16, 1e-6, 1e-6}, centres,
                          radii, std::size_t{1} << 24));
}
END_TEST

START_TEST(dart_stage_opens_around_fixed_points) {
    for (int polygon = 0; polygon < 2; ++polygon) {
        pds::Sampler s = with_fixed(0.01, 7, polygon != 0);
        std::size_t added = 0;
        s.run(200, &added);
        ck_assert_msg(s.in_dart_stage(), "the run left its dart stage within 200 points");
        std::vector<double> xy = run_in_calls(s, 0);
        ck_assert_msg(xy.size() / 2 > 2000, "%zu points", xy.size() / 2);
        assert_clear(xy, 0.01, 0.01);
        std::vector<pds::Point> points(xy.size() / 2);
        for (std::size_t i = 0; i < points.size(); ++i) points[i] = pds::Point{xy[2 * i], xy[2 * i + 1]};
        assert_apart_in_unit_square(points, 0.01);
        // The same points in calls of 777 and of 1.
        pds::Sampler a = with_fixed(0.01, 7, polygon != 0), b = with_fixed(0.01, 7, polygon != 0);
        const std::vector<double> whole = run_in_calls(a, 0);
        ck_assert(same(whole, run_in_calls(b, 777)));
        if (!test_light()) {
            pds::Sampler c = with_fixed(0.01, 7, polygon != 0);
            ck_assert(same(whole, run_in_calls(c, 1)));
        }
        // The Jones loop alone places other points, as many on average.
        pds::Sampler loop = with_fixed(0.01, 7, polygon != 0);
        loop.skip_dart_stage();
        ck_assert(!same(whole, run_in_calls(loop, 0)));
    }
}
END_TEST

START_TEST(many_fixed_points_stay_in_the_dart_stage) {
    // 400 scattered fixed points over a grid of about 141 x 141 cells: the
    // stage holds them (their insertion after the others' mesh walks along
    // the curve, not across the mesh); every clearance is kept, the pattern
    // is maximal and the same in calls of 777, and not the Jones loop's.
    std::vector<pds::Point> at;
    std::vector<double> c;
    pds::Rng rng(3);
    for (std::size_t k = 0; k < 400; ++k) {
        at.push_back(pds::Point{rng.next_double(), rng.next_double()});
        c.push_back(k % 2 ? 0.005 : 0.02);
    }
    const auto sampler = [&] {
        pds::Sampler s(0.01, 8);
        s.set_fixed(at, c);
        return s;
    };
    pds::Sampler darts = sampler(), calls = sampler(), loop = sampler();
    loop.skip_dart_stage();
    std::size_t added = 0;
    darts.run(1, &added);
    ck_assert_msg(darts.in_dart_stage(), "400 fixed points: not in the dart stage");
    const std::vector<double> a = run_in_calls(darts, 0);
    for (std::size_t i = 0; i < a.size() / 2; ++i)
        for (std::size_t k = 0; k < at.size(); ++k)
            if (pds::compare_distance(pds::Point{a[2 * i], a[2 * i + 1]}, at[k], c[k]) < 0)
                ck_abort_msg("point %zu inside fixed point %zu's clearance", i, k);
    ck_assert(same(a, run_in_calls(calls, 777)));
    ck_assert(!same(a, run_in_calls(loop, 0)));
}
END_TEST

START_TEST(count_mode_and_refine_hand_over_from_the_darts) {
    // Count mode lowers the radius (the clearances scale with it): exactly n
    // points, clear at the last radius, the same in calls of 777.
    std::vector<double> counted[2];
    for (int k = 0; k < 2; ++k) {
        pds::Sampler s = with_fixed(0.02, 9, false);
        s.set_count(3000);
        const double r0 = s.radius();
        std::size_t added = 0;
        while (s.run(k == 0 ? 0 : 777, &added) != pds::Sampler::RunEnd::complete) {
        }
        ck_assert_uint_eq(s.count(), 3000);
        counted[k].resize(2 * s.count());
        s.copy_points(0, s.count(), counted[k].data());
        assert_clear(counted[k], s.radius(), r0);
    }
    ck_assert(same(counted[0], counted[1]));
    // A refine in the dart stage hands over, the run then goes on to a
    // maximal pattern at the new radius.
    pds::Sampler u = with_fixed(0.02, 9, true);
    std::size_t added = 0;
    u.run(300, &added);
    ck_assert(u.in_dart_stage());
    u.refine(0.012);
    const std::vector<double> xy = run_in_calls(u, 0);
    assert_clear(xy, 0.012, 0.02);
}
END_TEST

START_TEST(law_around_fixed_disks) {
    law::Config c;
    c.runs = test_light() ? 300 : 2000;
    if (_i == 0) {
        c.r = 0.1;
        compare_around_disks(c, oracle::ConstantRadius{c.r});
    } else {
        c.field = gradient;
        c.rmin = 0.06;
        c.rmax = 0.12;
        compare_around_disks(c, oracle::FieldRadius{gradient, c.rmin, c.rmax});
    }
}
END_TEST

START_TEST(reference_around_disks_is_saturated) {
    // The reference keeps the disks and leaves no free probe, in the box
    // less the disks (probes inside a disk count as covered).
    oracle::AroundDisks rule;
    rule.box = pds::Box{0, 0, 1, 1};
    rule.centre = kLawFixed;
    rule.radius = kLawClearance;
    auto reference = oracle::dart_throwing(rule, oracle::FieldRadius{gradient, 0.06, 0.12});
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const oracle::Pattern t = reference.run(seed);
        for (std::size_t i = 0; i < t.p.size(); ++i) {
            if (!rule.inside(t.p[i])) ck_abort_msg("point %zu inside a fixed disk", i);
            for (std::size_t j = i + 1; j < t.p.size(); ++j)
                if (rule.d2(t.p[i], t.p[j]) < t.r[i] * t.r[i]) ck_abort_msg("point %zu inside point %zu's disk", j, i);
        }
        for (int a = 0; a <= 400; ++a)
            for (int b = 0; b <= 400; ++b) {
                const pds::Point x{a / 400.0, b / 400.0};
                if (!rule.inside(x)) continue;
                bool in = false;
                for (std::size_t i = 0; i < t.p.size() && !in; ++i) in = rule.d2(x, t.p[i]) <= t.r[i] * t.r[i];
                if (!in) ck_abort_msg("seed %llu: (%g, %g) is free", static_cast<unsigned long long>(seed), x.x, x.y);
            }
    }
}
END_TEST

Suite* dart_stage_fixed_suite() {
    Suite* s = suite_create("dart_stage_fixed");
    TCase* t = tcase_create("the single-thread dart stage with fixed points");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, plain_grid_disks_cover_exactly_the_points_inside);
    tcase_add_test(t, dart_stage_opens_around_fixed_points);
    tcase_add_test(t, count_mode_and_refine_hand_over_from_the_darts);
    tcase_add_test(t, many_fixed_points_stay_in_the_dart_stage);
    tcase_add_test(t, reference_around_disks_is_saturated);
    tcase_add_loop_test(t, law_around_fixed_disks, 0, 2);
    suite_add_tcase(s, t);
    return s;
}
