// test_field.cpp - the variable radius (radius_field.hpp) through the
// sampler: its law against saturated dart throwing under the same rule
// (law_compare.hpp, dart_throwing.hpp) for a gradient and a step field, also
// with threads (the free regions' darts, in epochs of the default length and
// 40 times as long) and on the torus (its dart stage, with threads too, and
// the Jones loop alone); a field of 1:16, and one whose dart stage ends at
// its memory budget; the rule and
// maximality by brute force; the density along a linear field; and equal
// radii through the weighted path giving the plain sampler's points.
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "dart_throwing.hpp"
#include "law_compare.hpp"
#include "radius/radius_field.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

// 1:2 along x, and a 1:2.5 step at x = 1/2 (beyond sqrt 2: power cells
// lose their sites and disks get hidden).
double gradient(void*, double x, double) { return 0.05 * (1.0 + x); }
double step(void*, double x, double) { return x < 0.5 ? 0.04 : 0.1; }
// 1:16 along x: nine layers in the dart stage's grids.
double wide(void*, double x, double) { return 0.02 * std::pow(16.0, x); }
// Specks of radius 0.01 in a field of 0.08 (1:8): a 6 x 6 lattice of
// squares 0.025 wide, each holding a few small disks.
double specks(void*, double x, double y) {
    const auto in_speck = [](double t) { return t * 6.0 - std::floor(t * 6.0) < 0.15; };
    return in_speck(x) && in_speck(y) ? 0.01 : 0.08;
}

using Pattern = oracle::Pattern;
// A budget (bytes a point, no floor) that ends the specks' dart stage well
// before its end (0.31-0.35 of the points placed by darts, 0.73 without it).
constexpr double kSpecksBudget = 160.0;
using law::run_to_the_end;

// Over the unit square or the unit torus, its dart stage and the Jones loop
// both placing a real share of the points (or, with `stages`, the loop alone).
void compare_field_laws(oracle::Field field, double rmin, double rmax, int runs, bool periodic = false,
                        unsigned threads = 0, double region_darts_per_cell = 0,
                        law::Stages stages = law::Stages::darts_then_jones) {
    law::Config c;
    c.periodic = periodic;
    c.threads = threads;
    c.region_darts_per_cell = region_darts_per_cell;
    c.field = field;
    c.rmin = rmin;
    c.rmax = rmax;
    c.runs = runs;
    c.stages = stages;
    law::compare(c);
}

// Every later point (from `first` on) outside every earlier disk, and no
// room left: probes on a fine grid must each lie in some disk (closed).
// Brute force.
void check_rule_and_maximality_from(const Pattern& t, std::size_t first, int probes) {
    for (std::size_t i = 0; i < t.p.size(); ++i) {
        for (std::size_t j = std::max(i + 1, first); j < t.p.size(); ++j) {
            const double dx = t.p[i].x - t.p[j].x, dy = t.p[i].y - t.p[j].y;
            ck_assert_msg(dx * dx + dy * dy >= t.r[i] * t.r[i] * (1.0 - 1e-12), "point %zu inside point %zu's disk",
                          j, i);
        }
    }
    for (int a = 0; a <= probes; ++a) {
        for (int b = 0; b <= probes; ++b) {
            const double x = a / double(probes), y = b / double(probes);
            bool in = false;
            for (std::size_t i = 0; i < t.p.size() && !in; ++i) {
                const double dx = t.p[i].x - x, dy = t.p[i].y - y;
                in = dx * dx + dy * dy <= t.r[i] * t.r[i] * (1.0 + 1e-12);
            }
            ck_assert_msg(in, "the probe (%g, %g) is in no disk", x, y);
        }
    }
}

void check_rule_and_maximality(const Pattern& t, int probes) { check_rule_and_maximality_from(t, 0, probes); }

}  // namespace

START_TEST(reference_is_maximal) {
    // The reference keeps the rule and saturates, in the plane and across
    // the torus's seam (where the step field steps a second time).
    const oracle::FieldRadius field{step, 0.04, 0.1};
    const oracle::Plane plane{pds::Box{0, 0, 1, 1}};
    const oracle::Torus torus{pds::Box{0, 0, 1, 1}};
    auto in_plane = oracle::dart_throwing(plane, field);
    auto on_torus = oracle::dart_throwing(torus, field);
    for (int seed = 1; seed <= 3; ++seed) {
        law::assert_saturated(in_plane.run(static_cast<std::uint64_t>(seed)), plane, test_light() ? 60 : 200);
        if (seed == 1 || !test_light())
            law::assert_saturated(on_torus.run(static_cast<std::uint64_t>(seed)), torus, test_light() ? 60 : 200);
    }
}
END_TEST

START_TEST(law_of_a_gradient_field) {
    compare_field_laws(gradient, 0.05, 0.1, test_light() ? 30 : 2000);
}
END_TEST

START_TEST(law_of_a_step_field) {
    compare_field_laws(step, 0.04, 0.1, test_light() ? 30 : 2000);
}
END_TEST

START_TEST(law_of_a_gradient_field_on_threads) {
    // The field's dart stage, then its darts carried on in the free regions
    // on 1, 2 and 3 threads (3 oversubscribes a 2-core machine).
    compare_field_laws(gradient, 0.05, 0.1, test_light() ? 30 : 2000, false, static_cast<unsigned>(_i));
}
END_TEST

START_TEST(law_of_a_step_field_in_long_region_epochs) {
    // Epochs 40 times as long, in the square and (_i = 1) on the torus:
    // darts of one epoch often fall in one another's disks (across a seam
    // too), so the law depends on each accepted dart keeping the later ones
    // out by its own radius (the step's two radii differ by 2.5).
    compare_field_laws(step, 0.04, 0.1, test_light() ? 30 : 2000, _i == 1, 2, 4.0);
}
END_TEST

START_TEST(law_of_a_gradient_field_in_a_polygon_on_threads) {
    // An L with a square hole in the unit square: cells the outline cuts,
    // drawn from by the free regions' darts too (2 threads).
    law::Config c;
    c.rings = {{0, 0, 1, 0, 1, 0.5, 0.5, 0.5, 0.5, 1, 0, 1}, {0.15, 0.15, 0.35, 0.15, 0.35, 0.35, 0.15, 0.35}};
    c.field = gradient;
    c.rmin = 0.05;
    c.rmax = 0.1;
    c.runs = test_light() ? 30 : 2000;
    c.threads = 2;
    law::compare(c);
}
END_TEST

START_TEST(law_of_a_step_field_on_the_torus) {
    // The step wraps too: x = 0 == 1 is a second step, which the dart
    // stage's layers meet across the seam. Without threads (_i = 0), and
    // on 1, 2 and 3 threads, whose free regions' darts are decided across
    // the seams too.
    compare_field_laws(step, 0.04, 0.1, test_light() ? 30 : 2000, true, static_cast<unsigned>(_i));
}
END_TEST

START_TEST(law_of_a_step_field_on_the_torus_by_the_jones_loop_alone) {
    compare_field_laws(step, 0.04, 0.1, test_light() ? 30 : 2000, true, 0, 0, law::Stages::jones_only);
}
END_TEST

START_TEST(law_of_a_field_of_1_to_16) {
    // Nine layers of grids, read where each tile says they have points.
    compare_field_laws(wide, 0.02, 0.32, test_light() ? 30 : 2000);
}
END_TEST

START_TEST(law_of_a_field_whose_dart_stage_ends_at_its_memory_budget) {
    // Each speck's first points touch pages of the fine layers' grids that
    // no other point touches, so a small budget ends the dart stage at a time
    // its points decide (a stopping time, as the acceptance rule's end).
    law::Config c;
    c.field = specks;
    c.rmin = 0.01;
    c.rmax = 0.08;
    c.runs = test_light() ? 30 : 2000;
    c.dart_budget_per_point = kSpecksBudget;
    const double share = law::compare(c);
    // The same runs without the budget: their stage places more of the points.
    law::Config unbounded = c;
    unbounded.dart_budget_per_point = 0;
    std::size_t from_darts = 0, total = 0;
    for (int seed = 1; seed <= 20; ++seed) {
        pds::Sampler s(1.0, static_cast<std::uint64_t>(seed));
        law::configure(s, unbounded);
        total += run_to_the_end(s, &from_darts).p.size();
    }
    const double unbounded_share = static_cast<double>(from_darts) / static_cast<double>(total);
    if (std::getenv("PDS_LAW_PRINT"))
        std::printf("dart stage share %.3f, %.3f without the budget\n", share, unbounded_share);
    ck_assert_msg(share < 0.8 * unbounded_share, "the stage placed %.3f of the points, %.3f without the budget",
                  share, unbounded_share);
}
END_TEST

START_TEST(rule_and_maximality_by_brute_force) {
    for (int seed = 1; seed <= (test_light() ? 2 : 4); ++seed) {
        pds::Sampler s(1.0, static_cast<std::uint64_t>(seed));
        s.set_field(pds::RadiusField::function(seed % 2 ? step : gradient, nullptr, seed % 2 ? 0.04 : 0.05, 0.1));
        const Pattern t = run_to_the_end(s);
        ck_assert(s.verify().valid && s.verify().maximal);
        check_rule_and_maximality(t, test_light() ? 60 : 300);
        // Each radius is the field's value at its point.
        for (std::size_t i = 0; i < t.p.size(); ++i)
            ck_assert_double_eq(t.r[i], (seed % 2 ? step : gradient)(nullptr, t.p[i].x, t.p[i].y));
        // A refine scales every radius, old points' too, and the pattern
        // goes on to a maximal one under the scaled field.
        s.refine(0.7 * 0.1);
        ck_assert_double_eq(s.radius(), 0.7 * 0.1);
        const Pattern u = run_to_the_end(s);
        ck_assert_uint_gt(u.p.size(), t.p.size());
        for (std::size_t i = 0; i < u.p.size(); ++i) {
            const double v = (seed % 2 ? step : gradient)(nullptr, u.p[i].x, u.p[i].y);
            ck_assert(std::fabs(u.r[i] - 0.7 * v) <= 1e-15);
        }
        ck_assert(s.verify().valid && s.verify().maximal);
        // Later points keep out of the scaled disks; old points may sit
        // closer than their new radii to each other, so check the probes.
        Pattern later = u;
        check_rule_and_maximality_from(later, t.p.size(), test_light() ? 60 : 300);
    }
}
END_TEST

START_TEST(density_follows_a_linear_field) {
    // r = r0 (1 + 3x): in a strip, RSA's saturation coverage 0.547 gives
    // about 0.547 * 4 / pi * integral of 1 / r^2 points. Strips away from
    // the left and right sides (their edge excess), the top and bottom
    // sides' excess (0.23 per R of side) taken out.
    const double r0 = test_light() ? 0.006 : 0.0015;
    pds::Sampler s(1.0, 5);
    s.set_field(pds::RadiusField::function(
        [](void* u, double x, double) { return *static_cast<double*>(u) * (1.0 + 3.0 * x); },
        const_cast<double*>(&r0), r0, 4 * r0));
    const Pattern t = run_to_the_end(s);
    const int strips = 10;
    std::vector<double> count(strips, 0.0);
    for (const pds::Point& p : t.p) count[std::min(strips - 1, static_cast<int>(p.x * strips))] += 1;
    for (int k = 1; k < strips - 1; ++k) {
        const double a = double(k) / strips, b = double(k + 1) / strips;
        // integral of 1 / (r0 (1 + 3x))^2 over [a, b]
        const double inv = (1.0 / (1.0 + 3.0 * a) - 1.0 / (1.0 + 3.0 * b)) / (3.0 * r0 * r0);
        // the edge excess along the top and bottom sides, 0.23 per radius
        const double rmid = r0 * (1.0 + 3.0 * (a + b) / 2);
        const double expected = 0.547 * 4.0 / M_PI * inv + 2.0 * 0.23 * (b - a) / rmid;
        ck_assert_msg(std::fabs(count[k] / expected - 1.0) < 0.05, "strip %d: %g points, expected %g", k,
                      count[k], expected);
    }
}
END_TEST

START_TEST(equal_radii_through_the_weighted_path_are_the_plain_points) {
    // A function field whose values are all R, with bounds wider than R, so
    // the sampler takes the variable-radius path: regular triangulation,
    // power cells, per-point radii. Every decision must be the plain one.
    for (int seed = 1; seed <= 3; ++seed) {
        const double r = 0.01 + 0.003 * seed;
        pds::Sampler plain(r, static_cast<std::uint64_t>(seed));
        plain.skip_dart_stage();
        pds::Sampler field(1.0, static_cast<std::uint64_t>(seed));
        field.set_field(pds::RadiusField::function([](void* u, double, double) { return *static_cast<double*>(u); },
                                                   const_cast<double*>(&r), r / 4, r));
        field.skip_dart_stage();  // the Jones loop on both sides: its weighted path
        // In batches: one point at a time, then 100, then to the end. (A
        // refine rebuilds the weighted mesh, whose walks may then reach a new
        // point's triangle by another edge: the same mesh, other edge
        // records, other draws; a constant field runs the plain stages, so
        // users never see that.)
        bool maximal = false;
        for (int i = 0; i < 50; ++i) {
            plain.add_points(1, &maximal);
            field.add_points(1, &maximal);
        }
        plain.add_points(100, &maximal);
        field.add_points(100, &maximal);
        plain.add_points(0, &maximal);
        field.add_points(0, &maximal);
        ck_assert_uint_eq(plain.count(), field.count());
        std::vector<double> a(2 * plain.count()), b(2 * field.count()), rb(field.count());
        plain.copy_points(0, plain.count(), a.data());
        field.copy_points(0, field.count(), b.data());
        ck_assert(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
        field.copy_radii(0, field.count(), rb.data());
        for (double x : rb) ck_assert_double_eq(x, r);
        ck_assert(field.verify().valid && field.verify().maximal);
    }
}
END_TEST

Suite* field_suite() {
    Suite* s = suite_create("field");
    TCase* t = tcase_create("variable radius");
    tcase_set_timeout(t, 900);
    tcase_add_test(t, reference_is_maximal);
    tcase_add_test(t, law_of_a_gradient_field);
    tcase_add_test(t, law_of_a_step_field);
    tcase_add_loop_test(t, law_of_a_gradient_field_on_threads, 1, 4);
    tcase_add_loop_test(t, law_of_a_step_field_in_long_region_epochs, 0, 2);
    tcase_add_test(t, law_of_a_gradient_field_in_a_polygon_on_threads);
    tcase_add_loop_test(t, law_of_a_step_field_on_the_torus, 0, 4);
    tcase_add_test(t, law_of_a_step_field_on_the_torus_by_the_jones_loop_alone);
    tcase_add_test(t, law_of_a_field_of_1_to_16);
    tcase_add_test(t, law_of_a_field_whose_dart_stage_ends_at_its_memory_budget);
    tcase_add_test(t, rule_and_maximality_by_brute_force);
    tcase_add_test(t, density_follows_a_linear_field);
    tcase_add_test(t, equal_radii_through_the_weighted_path_are_the_plain_points);
    suite_add_tcase(s, t);
    return s;
}
