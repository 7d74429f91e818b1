// test_field_dart_stage.cpp - the dart stage of a varying radius
// (dart_stage.hpp over layered_grid.hpp): every pair of its points keeps the
// field's rule, checked exactly, in the plane and across the torus's seams;
// the cells its bitmap marks lie inside their disk (covered_bitmap.hpp); and
// its hand-over gives the Jones stage the same points and values, which then
// ends maximal, in the plane and on the torus; and a fine-grained field's
// stage ends at its memory budget.
#include <cmath>
#include <cstdint>
#include <vector>

#include "darts/covered_bitmap.hpp"
#include "darts/dart_stage.hpp"
#include "jones/jones_stage.hpp"
#include "core/predicates.hpp"
#include "radius/radius_field.hpp"
#include "core/rng.hpp"
#include "verify/spatial_hash.hpp"
#include "suites.hpp"

namespace {

// 1:4 along x; and a 1:2.5 step at x = 1/2.
double gradient(void* u, double x, double) { return *static_cast<double*>(u) * (1.0 + 3.0 * x); }
double step(void* u, double x, double) { return *static_cast<double*>(u) * (x < 0.5 ? 1.0 : 2.5); }
// 1:8, fine-grained: each square 0.004 wide gets its own value, hashed.
double grains(void* u, double x, double y) {
    std::uint64_t h = static_cast<std::uint64_t>(x * 250.0) * 0x9E3779B97F4A7C15ull ^
                      static_cast<std::uint64_t>(y * 250.0) * 0xC2B2AE3D27D4EB4Full;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return *static_cast<double*>(u) * (1.0 + 7.0 * static_cast<double>(h >> 11) * 0x1.0p-53);
}

struct Field {
    pds::RadiusField field;
    pds::Frame frame;
    pds::PointRadii radii;
    Field(pds::RadiusField::Function fn, double* r0, double ratio, const pds::Box& box = pds::Box{0, 0, 1, 1})
        : field(pds::RadiusField::function(fn, r0, *r0, ratio * *r0)),
          frame(box, ratio * *r0),
          radii(field, frame) {}
};

void fill(pds::FieldDartStage& stage, std::uint64_t seed) {
    pds::Rng rng(seed);
    stage.reserve(200000);
    while (stage.next(rng) != nullptr) stage.add_next();
}

// Every later point outside every earlier disk, exactly (|p_j - p_i| >= r_i
// for i < j), and on the torus t (if on) outside its copies a period away;
// counts the pairs within 1.01 r_i, and those of them across a seam.
struct NearPairs {
    std::size_t all = 0, across_seams = 0;
};
NearPairs check_rule(const pds::FieldDartStage& stage, const pds::PointRadii& radii, const pds::Box& box,
                     const pds::Torus& t = pds::Torus{}) {
    std::vector<pds::Point> pts(stage.count());
    for (std::size_t k = 0; k < pts.size(); ++k) pts[k] = stage.point(k);
    const pds::SpatialHash grid = t.on() ? pds::SpatialHash(pts, 0, t, radii.rmax())
                                         : pds::SpatialHash(pts, 0, box, radii.rmax());
    NearPairs near;
    for (std::size_t j = 0; j < pts.size(); ++j) {
        ck_assert(box.contains(pts[j]));
        if (t.on()) ck_assert(t.wrap(pts[j]).x == pts[j].x && t.wrap(pts[j]).y == pts[j].y);
        grid.for_each_near(pts[j], [&](std::uint32_t i, int sx, int sy) {
            if (i >= j) return;
            const pds::Point copy = t.shifted(pts[i], sx, sy);  // off the torus, pts[i]
            const double ri = radii.radius_of(stage.value(i));
            ck_assert_msg(pds::compare_distance(pts[j], copy, ri) >= 0,
                          "point %zu inside the disk of point %u (copy %d, %d)", j, static_cast<unsigned>(i), sx, sy);
            if (pds::compare_distance(pts[j], copy, 1.01 * ri) >= 0) return;
            ++near.all;
            if (sx != 0 || sy != 0) ++near.across_seams;
        });
    }
    return near;
}

// A torus of periods 1 x 0.625 (on the torus grid) with the 1:4 gradient
// along x, which steps from 4 r0 back to r0 across the seam at x = 0.
struct TorusField : Field {
    pds::Torus torus{1.0, 0.625, 0.0, 0.0};
    explicit TorusField(double* r0) : Field(gradient, r0, 4.0, pds::Box{0, 0, 1.0, 0.625}) {}
};

}  // namespace

START_TEST(field_dart_points_keep_the_rule) {
    // Layers by radius, each point in the grid of its own layer, darts
    // reading the layers marked near them now (not when they were drawn),
    // radii kept as floats with the exact ones behind the filter: every
    // pair is checked exactly, and the exact path must have been taken. A
    // layer mask read when the dart was drawn gave points deep inside
    // earlier disks, and marks from disks 2% too large went unseen until
    // the bitmap was compared with its points' disks (both measured to
    // fail here).
    double r0 = test_light() ? 0.006 : 0.003;
    for (auto fn : {gradient, step}) {
        const Field f(fn, &r0, fn == gradient ? 4.0 : 2.5);
        std::size_t near_pairs = 0, exact = 0;
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            pds::FieldDartStage stage(f.frame.box(), nullptr, f.radii);
            ck_assert_uint_ge(stage.grid().layer_count(), fn == gradient ? 5 : 3);
            fill(stage, seed);
            ck_assert_uint_gt(stage.count(), 500);
            near_pairs += check_rule(stage, f.radii, f.frame.box()).all;
            // The bitmap marks exactly what the points' own disks mark.
            pds::CoveredBitmap again = stage.grid().covered();
            again.clear();
            for (std::size_t k = 0; k < stage.count(); ++k)
                again.cover_disk(stage.point(k), f.radii.radius_of(stage.value(k)));
            ck_assert(again == stage.grid().covered());
            exact += stage.exact_checks();
        }
        ck_assert_uint_gt(near_pairs, 100);
        ck_assert_uint_gt(exact, 0);
    }
}
END_TEST

START_TEST(torus_field_dart_points_keep_the_rule_across_the_seams) {
    // Each point is kept in the grid once; a dart near a seam is tested at
    // its copies too. Without those tests, points fall inside the disks of
    // copies across the seam (measured to fail here).
    double r0 = test_light() ? 0.006 : 0.003;
    const TorusField f(&r0);
    std::size_t seam_pairs = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        pds::FieldDartStage stage(f.frame.box(), nullptr, f.radii, f.torus);
        fill(stage, seed);
        ck_assert_uint_gt(stage.count(), 500);
        seam_pairs += check_rule(stage, f.radii, f.frame.box(), f.torus).across_seams;
    }
    ck_assert_uint_gt(seam_pairs, test_light() ? 0 : 10);
}
END_TEST

START_TEST(torus_field_darts_are_free_exactly_when_no_copy_covers_them) {
    // Half way through the stage, each of many darts is judged free by the
    // grid exactly when no point's disk, nor any copy's across a seam,
    // holds it (brute force over the spatial hash). This sees darts wrongly
    // rejected as well as wrongly accepted: a copy's block clamped to the
    // grid's edge that trusted its own cell rejected free darts (measured).
    double r0 = test_light() ? 0.006 : 0.003;
    const TorusField f(&r0);
    pds::FieldDartStage stage(f.frame.box(), nullptr, f.radii, f.torus);
    pds::Rng rng(3);
    stage.reserve(200000);
    for (std::size_t k = 0; k < (test_light() ? 700u : 2800u) && stage.next(rng) != nullptr; ++k) stage.add_next();
    const std::vector<pds::Point>& pts = stage.points();
    std::vector<double> values(pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) values[k] = stage.value(k);
    const pds::SpatialHash near(pts, 0, f.torus, f.radii.rmax());
    std::vector<pds::LayeredGrid::Dart> darts(1 << 16);
    std::size_t free_near_seams = 0, covered_by_copies = 0;
    const double edge = f.radii.rmax();
    for (int round = 0; round < (test_light() ? 1 : 4); ++round) {
        stage.grid().throw_darts(darts.data(), darts.size(), rng);
        for (const pds::LayeredGrid::Dart& d : darts) {
            bool covered = false, by_copy = false;
            near.for_each_near(d.p, [&](std::uint32_t i, int sx, int sy) {
                if (pds::compare_distance(d.p, f.torus.shifted(pts[i], sx, sy), f.radii.radius_of(values[i])) < 0) {
                    covered = true;
                    by_copy = by_copy || sx != 0 || sy != 0;
                }
            });
            ck_assert_msg(stage.grid().is_free(d, pts, values) == !covered, "dart (%.17g, %.17g): the grid says %s",
                          d.p.x, d.p.y, covered ? "free" : "covered");
            const bool near_seam = d.p.x < edge || d.p.x > 1.0 - edge || d.p.y < edge || d.p.y > 0.625 - edge;
            if (!covered && near_seam) ++free_near_seams;
            if (by_copy) ++covered_by_copies;
        }
    }
    ck_assert_uint_gt(free_near_seams, 50);
    ck_assert_uint_gt(covered_by_copies, 50);
}
END_TEST

START_TEST(torus_field_hand_over_ends_maximal) {
    // The points and their values go to the torus's Jones stage (each with
    // its radius, and copies across the seams), which ends maximal.
    double r0 = 0.008;
    const TorusField f(&r0);
    pds::FieldDartStage stage(f.frame.box(), nullptr, f.radii, f.torus);
    fill(stage, 5);
    const std::size_t n = stage.count();
    ck_assert_uint_gt(n, 500);
    std::vector<pds::Point> pts(n);
    std::vector<double> values(n);
    for (std::size_t k = 0; k < n; ++k) pts[k] = stage.point(k), values[k] = stage.value(k);
    const auto jones_stage = pds::make_jones_stage(f.frame.box(), f.frame.r(), f.torus, &f.radii);
    pds::JonesStage& jones = *jones_stage;
    jones.reserve(4 * n);
    stage.hand_over_to(jones);
    jones.settle();
    ck_assert_uint_eq(jones.count(), n);
    for (std::size_t k = 0; k < n; ++k) {
        ck_assert(jones.point(k).x == pts[k].x && jones.point(k).y == pts[k].y);
        ck_assert(jones.value(k) == values[k]);
    }
    ck_assert(jones.free_area() > 0.0);
    pds::Rng rng(6);
    std::size_t added = 0;
    for (; jones.next(rng) != nullptr; ++added) jones.add_next();
    ck_assert_uint_gt(added, 0);
    const pds::VerifyReport done = jones.verify();
    ck_assert_msg(done.valid && done.maximal, "%s", done.failure.c_str());
}
END_TEST

START_TEST(fine_grained_field_dart_stage_ends_at_its_memory_budget) {
    // A fine-grained field scatters each layer's points over the domain, a
    // few to a page of cells: with a budget of 200 bytes a point and no
    // floor, the stage ends once its pages pass it. The budget only ends the
    // stage: its points are the first of those the stage places without
    // one (whose default floor this small run never reaches), and its Jones
    // stage then ends maximal.
    double r0 = 0.002;
    const Field f(grains, &r0, 8.0);
    pds::FieldDartStage unbounded(f.frame.box(), nullptr, f.radii);
    fill(unbounded, 3);
    ck_assert(!unbounded.grid().past_memory_budget());
    pds::FieldDartStage bounded(f.frame.box(), nullptr, f.radii);
    bounded.set_memory_budget(200.0, 0);
    fill(bounded, 3);
    ck_assert(bounded.grid().past_memory_budget());
    ck_assert_uint_gt(bounded.count(), 100);
    ck_assert_uint_lt(bounded.count(), unbounded.count() / 2);
    ck_assert_uint_lt(bounded.grid().touched_bytes(), unbounded.grid().touched_bytes() / 2);
    for (std::size_t k = 0; k < bounded.count(); ++k) {
        ck_assert(bounded.point(k).x == unbounded.point(k).x && bounded.point(k).y == unbounded.point(k).y);
        ck_assert(bounded.value(k) == unbounded.value(k));
    }
    const auto jones_stage = pds::make_jones_stage(f.frame.box(), f.frame.r(), pds::Torus{}, &f.radii);
    pds::JonesStage& jones = *jones_stage;
    jones.reserve(4 * unbounded.count());
    bounded.hand_over_to(jones);
    pds::Rng rng(4);
    while (jones.next(rng) != nullptr) jones.add_next();
    ck_assert_uint_gt(jones.count(), 2 * bounded.count());
    const pds::VerifyReport done = jones.verify();
    ck_assert_msg(done.valid && done.maximal, "%s", done.failure.c_str());
}
END_TEST

START_TEST(expected_count_follows_the_maximal_pattern) {
    // The budget's expected count, for a 1:4 ramp over a 2 x 1.25 box and a
    // radius in force 1.5 times the field's largest value, against the
    // count the maximal pattern reaches: a map's (its values,
    // taken at the start) within 10%; a function's (its values at the
    // points so far, at the end of the stage) low, as the points then lie
    // more evenly than the pattern's, but within a factor 2.
    const pds::Box box{-1.0, 2.0, 1.0, 3.25};
    double r0 = test_light() ? 0.008 : 0.004;
    const pds::RadiusField::Function ramp = [](void* u, double x, double) {
        return *static_cast<double*>(u) * (1.0 + 1.5 * (x + 1.0));
    };
    const std::size_t side = 64;
    std::vector<double> pixels(side * side);
    for (std::size_t j = 0; j < side; ++j)
        for (std::size_t i = 0; i < side; ++i)
            pixels[j * side + i] = ramp(&r0, -1.0 + 2.0 * static_cast<double>(i) / static_cast<double>(side - 1), 0.0);
    const pds::RadiusField map = pds::RadiusField::map(side, side, pixels.data());
    const pds::RadiusField function = pds::RadiusField::function(ramp, &r0, r0, 4.0 * r0);
    for (const pds::RadiusField* field : {&map, &function}) {
        const pds::Frame frame(box, 1.5 * field->rmax());  // every radius 1.5 times its value
        const pds::PointRadii radii(*field, frame);
        pds::FieldDartStage stage(frame.box(), nullptr, radii);
        fill(stage, 9);
        const double expected = stage.grid().expected_count();
        const auto jones_stage = pds::make_jones_stage(frame.box(), frame.r(), pds::Torus{}, &radii);
        pds::JonesStage& jones = *jones_stage;
        jones.reserve(4 * stage.count());
        stage.hand_over_to(jones);
        pds::Rng rng(10);
        while (jones.next(rng) != nullptr) jones.add_next();
        const double ratio = expected / static_cast<double>(jones.count());
        if (field == &map)
            ck_assert_msg(std::fabs(ratio - 1.0) < 0.1, "the map's expected count is %.3f of the pattern's", ratio);
        else
            ck_assert_msg(ratio > 0.5 && ratio < 1.0, "the function's expected count is %.3f of the pattern's", ratio);
    }
}
END_TEST

START_TEST(covered_bitmap_cells_lie_inside_their_disk) {
    // Each marked cell's corners strictly inside the disk (a dart there is
    // covered); and the marks are nearly all the cells wholly inside, found
    // by brute force (a mark test on the nearer edge of a row, or no margin,
    // marks cells reaching outside; one that gave up would mark few).
    const double x0 = -0.37, y0 = 1.21, side = 0.0137;
    const std::size_t cols = 40, rows = 30;
    pds::Rng rng(7);
    std::size_t marked_total = 0, inside_total = 0;
    for (int disk = 0; disk < 300; ++disk) {
        pds::CoveredBitmap cells(x0, y0, side, cols, rows);
        const pds::Point c{x0 + rng.next_double() * static_cast<double>(cols) * side,
                           y0 + rng.next_double() * static_cast<double>(rows) * side};
        const double r = side * (0.5 + 8.0 * rng.next_double());
        cells.cover_disk(c, r);
        for (std::size_t j = 0; j < rows; ++j) {
            for (std::size_t i = 0; i < cols; ++i) {
                bool inside = true;
                for (int corner = 0; corner < 4; ++corner) {
                    const auto qi = static_cast<double>(i + static_cast<std::size_t>(corner % 2));
                    const auto qj = static_cast<double>(j + static_cast<std::size_t>(corner / 2));
                    const pds::Point q{x0 + qi * side, y0 + qj * side};
                    inside = inside && pds::compare_distance(q, c, r) < 0;
                }
                if (cells.covered(i, j)) {
                    ck_assert_msg(inside, "disk %d: cell (%zu, %zu) marked but not inside", disk, i, j);
                    ++marked_total;
                }
                if (inside) ++inside_total;
            }
        }
    }
    ck_assert_uint_gt(marked_total, 2000);
    ck_assert_uint_ge(marked_total, inside_total * 99 / 100);
}
END_TEST

START_TEST(field_hand_over_keeps_points_and_values) {
    double r0 = 0.01;
    const Field f(gradient, &r0, 4.0);
    pds::FieldDartStage stage(f.frame.box(), nullptr, f.radii);
    fill(stage, 11);
    const std::size_t n = stage.count();
    ck_assert_uint_gt(n, 500);
    // The stage's own queries build a mesh of its points: valid, not yet maximal.
    const pds::VerifyReport partial = stage.verify();
    ck_assert_msg(partial.valid, "%s", partial.failure.c_str());
    ck_assert(!partial.maximal);
    const double free_before = stage.free_area();
    ck_assert(free_before > 0.0);
    std::vector<pds::Point> pts(n);
    std::vector<double> values(n);
    for (std::size_t k = 0; k < n; ++k) pts[k] = stage.point(k), values[k] = stage.value(k);
    const auto jones_stage = pds::make_jones_stage(f.frame.box(), f.frame.r(), pds::Torus{}, &f.radii);
    pds::JonesStage& jones = *jones_stage;
    jones.reserve(4 * n);
    stage.hand_over_to(jones);
    ck_assert_uint_eq(jones.count(), n);
    for (std::size_t k = 0; k < n; ++k) {
        ck_assert(jones.point(k).x == pts[k].x && jones.point(k).y == pts[k].y);
        ck_assert(jones.value(k) == values[k]);
    }
    ck_assert_double_eq_tol(jones.free_area(), free_before, 1e-12);
    pds::Rng rng(12);
    while (jones.next(rng) != nullptr) jones.add_next();
    const pds::VerifyReport done = jones.verify();
    ck_assert_msg(done.valid && done.maximal, "%s", done.failure.c_str());
}
END_TEST

Suite* field_dart_stage_suite() {
    Suite* s = suite_create("field_dart_stage");
    TCase* t = tcase_create("layers");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, field_dart_points_keep_the_rule);
    tcase_add_test(t, covered_bitmap_cells_lie_inside_their_disk);
    tcase_add_test(t, field_hand_over_keeps_points_and_values);
    tcase_add_test(t, torus_field_dart_points_keep_the_rule_across_the_seams);
    tcase_add_test(t, torus_field_darts_are_free_exactly_when_no_copy_covers_them);
    tcase_add_test(t, torus_field_hand_over_ends_maximal);
    tcase_add_test(t, fine_grained_field_dart_stage_ends_at_its_memory_budget);
    tcase_add_test(t, expected_count_follows_the_maximal_pattern);
    suite_add_tcase(s, t);
    return s;
}
