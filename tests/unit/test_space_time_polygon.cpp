// test_space_time_polygon.cpp - the parallel opening in a polygon: which
// sub-squares it skips as outside and keeps untested as inside (a wrong
// bit would lose part of the domain or put points outside it); the
// stage's points inside and apart; whole runs, through the free regions'
// darts in cells the outline cuts, with the same points on any number of
// threads and in any calls, ending maximal and verified; and those darts
// uniform over the free area where the outline folds a cell's fan.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "darts/space_time_grid.hpp"
#include "darts/space_time_stage.hpp"
#include "darts/sub_square_raster.hpp"
#include "polygon_rings.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "threaded_runs.hpp"

namespace {

using pds::Point;
using pds::Polygon;

// A ring about (cx, cy): m vertices at radii between lo and hi of `size`.
std::vector<double> star(double cx, double cy, double size, int m, double lo, pds::Rng& rng) {
    std::vector<double> ring;
    for (int k = 0; k < m; ++k) {
        const double t = 2 * M_PI * k / m, rr = size * (lo + (1 - lo) * rng.next_double());
        ring.push_back(cx + rr * std::cos(t));
        ring.push_back(cy + rr * std::sin(t));
    }
    return ring;
}

// A disk of radius 0.45 with a square hole, and an L with a notch: outlines
// at every angle, axis-parallel sides on and off the grid lines.
std::vector<std::vector<double>> annulus() {
    pds::Rng rng(1);
    return {star(0.5, 0.5, 0.45, 200, 1.0, rng), {0.4, 0.4, 0.4, 0.6, 0.6, 0.6, 0.6, 0.4}};
}
std::vector<std::vector<double>> notched_l() {
    return {{0, 0, 1.2, 0, 1.2, 0.5, 0.5, 0.5, 0.5, 1, 0.3, 1, 0.3, 0.8, 0, 0.8}};
}

using Run = ThreadedRun;

// A sampler in `rings` with the parallel opening (threaded_runs.hpp).
Run run(const std::vector<std::vector<double>>& rings, double r, std::uint64_t seed, unsigned threads,
        std::size_t chunk = 0, unsigned threads_later = 0) {
    pds::Sampler s(r, seed);
    s.set_polygon(std::make_shared<const Polygon>(rings_of(rings)));
    return run_threaded(s, threads, chunk, threads_later);
}

}  // namespace

START_TEST(sub_squares_outside_and_inside_are_so) {
    // Random stars and rings with holes, grids at several sides and
    // offsets. Points drawn in every sub-square, at its corners and an ulp
    // around them: none in an "outside" sub-square lies in the closed
    // polygon, every one in an "inside" sub-square does. Both kinds must
    // occur (the raster is not empty nor all cut).
    pds::Rng rng(7);
    std::size_t outside_seen = 0, inside_seen = 0;
    for (int trial = 0; trial < (test_light() ? 6 : 24); ++trial) {
        std::vector<std::vector<double>> rings{star(0.5, 0.5, 0.4, 3 + trial * 5, 0.3, rng)};
        if (trial % 3 == 1) rings.push_back(star(0.5, 0.5, 0.12, 5, 0.8, rng));
        if (trial % 4 == 2) rings = notched_l();
        const Polygon polygon = rings_of(rings);
        const pds::Box box = polygon.bounds();
        const double side = pds::darts::cell_side(0.02 + 0.01 * (trial % 5));
        const pds::SpaceTimeGrid grid(box, 0.02 + 0.01 * (trial % 5));
        const std::size_t cols = grid.cols(), rows = grid.rows();
        std::vector<std::uint16_t> outside(cols * rows, 0), inside(cols * rows, 0);
        ck_assert(pds::classify_sub_squares(polygon, box.x0, box.y0, side, cols, rows, outside, inside));
        for (std::size_t row = 0; row < rows; ++row)
            for (std::size_t col = 0; col < cols; ++col) {
                const std::size_t cell = row * cols + col;
                if ((outside[cell] & inside[cell]) != 0) ck_abort_msg("a sub-square both outside and inside");
                for (unsigned bit = 0; bit < 16; ++bit) {
                    const bool out = outside[cell] >> bit & 1, in = inside[cell] >> bit & 1;
                    if (!out && !in) continue;
                    (out ? outside_seen : inside_seen) += 1;
                    const double x0 = grid.cell_x0(static_cast<std::int64_t>(col)) + (bit % 4) * side / 4;
                    const double y0 = grid.cell_y0(static_cast<std::int64_t>(row)) + (bit / 4) * side / 4;
                    const double q = side / 4;
                    Point probes[16];
                    int n = 0;
                    for (int k = 0; k < 8; ++k) probes[n++] = Point{x0 + rng.next_double() * q, y0 + rng.next_double() * q};
                    probes[n++] = Point{x0, y0};
                    probes[n++] = Point{x0 + q, y0 + q};
                    probes[n++] = Point{std::nextafter(x0, -1e300), std::nextafter(y0, -1e300)};
                    probes[n++] = Point{std::nextafter(x0 + q, 1e300), std::nextafter(y0 + q, 1e300)};
                    // (Checked without an assertion each: Check records every one.)
                    for (int k = 0; k < n; ++k)
                        if (polygon.contains(probes[k]) == out)
                            ck_abort_msg("trial %d: (%.17g, %.17g) %s the polygon, its sub-square %s", trial,
                                         probes[k].x, probes[k].y, out ? "in" : "outside", out ? "outside" : "inside");
                }
            }
    }
    ck_assert_msg(outside_seen > 1000 && inside_seen > 1000, "outside %zu, inside %zu", outside_seen, inside_seen);
}
END_TEST

START_TEST(epochs_keep_points_inside_and_apart) {
    // The stage alone in the annulus: every point in the polygon, every
    // pair at least R apart (brute force over a grid of the points), and
    // most of the pattern placed.
    const auto shared = std::make_shared<const Polygon>(rings_of(annulus()));
    const Polygon& polygon = *shared;
    const double r = 0.006;
    for (unsigned threads : {1u, 3u}) {
        pds::SpaceTimeDartStage stage(pds::Rectangle(polygon.bounds()), shared, r, 9);
        ck_assert(stage.outline_rastered());
        stage.set_threads(threads);
        stage.reserve(40000);
        pds::Rng unused(0);
        while (stage.next(unused) != nullptr) stage.add_next();
        const std::vector<Point>& p = stage.points();
        ck_assert_msg(p.size() > 7500, "the stage placed only %zu points (of about 11500)", p.size());
        for (std::uint32_t i = 0; i < p.size(); ++i)
            if (!polygon.contains(p[i])) ck_abort_msg("point %u outside the polygon", i);
        assert_apart_in_unit_square(p, r);
    }
}
END_TEST

START_TEST(same_points_in_polygons_on_any_number_of_threads) {
    // Over 16384 points in the annulus: the hand-over measures its cut
    // cells side by side, each worker with its own outline cutter.
    const unsigned most = test_light() ? 4 : 8;
    const Run one = run(annulus(), 0.004, 11, 1);
    ck_assert_msg(one.xy.size() / 2 > 4 * 4096, "only %zu points", one.xy.size() / 2);
    for (unsigned t = 2; t <= most; ++t) assert_same(one, run(annulus(), 0.004, 11, t), "threads in the annulus");
    const Run l = run(notched_l(), 0.01, 4, 2);
    assert_same(l, run(notched_l(), 0.01, 4, 3), "threads in the L");
    assert_same(l, run(notched_l(), 0.01, 4, 1, 1), "one point a call");
    assert_same(l, run(notched_l(), 0.01, 4, 3, 777), "777 a call");
    assert_same(l, run(notched_l(), 0.01, 4, 1, 3000, 4), "threads changed between calls");
}
END_TEST

START_TEST(the_free_regions_darts_run_in_polygons) {
    // After the opening the dart process goes on in the free regions, also
    // in cells the outline cuts, and places points there; the default
    // process's points differ (another opening).
    pds::Sampler s(0.01, 4);
    s.set_polygon(std::make_shared<const Polygon>(rings_of(notched_l())));
    s.set_threads(2);
    std::size_t added = 0;
    ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
    ck_assert_msg(s.jones().region_stats().points > 100, "%zu points from the free regions' darts",
                  s.jones().region_stats().points);
    pds::Sampler plain(0.01, 4);
    plain.set_polygon(std::make_shared<const Polygon>(rings_of(notched_l())));
    plain.run(0, &added);
    std::vector<double> a(2 * s.count()), b(2 * plain.count());
    s.copy_points(0, s.count(), a.data());
    plain.copy_points(0, plain.count(), b.data());
    ck_assert(a.size() != b.size() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) != 0);
}
END_TEST

START_TEST(region_darts_in_cut_cells_are_uniform) {
    // The free regions' darts from the second point on, in a comb of 8
    // teeth beside a block, at R 0.01. The first point's cell is the whole
    // box cut by the outline: rays from its site leave the comb and enter
    // it again, so its fan has clockwise triangles, and a draw counts only
    // from the first exit beyond it, with no retry in its piece (a retry
    // favours the pieces' parts inside the comb). The second point must be
    // uniform over the free area: the counts in the base, the teeth and the
    // block against their areas (the first disk takes under 3e-4 of them),
    // by the fan's pieces and by the trapezoids. Measured with a draw
    // counted at every exit: chi-square 634; retried in its piece: 4450.
    const std::vector<std::vector<double>> rings{comb(8), {1.2, 0, 2.0, 0, 2.0, 1.0, 1.2, 1.0}};
    const double area[3] = {0.1, 8 * (0.3 / 8) * 0.9, 0.8}, total = area[0] + area[1] + area[2];
    const int seeds = test_light() ? 800 : 4000;
    for (int by_region = 0; by_region < 2; ++by_region) {
        int parts[3] = {0, 0, 0};
        std::size_t from_regions = 0;
        for (int seed = 1; seed <= seeds; ++seed) {
            pds::Sampler s(0.01, static_cast<std::uint64_t>(seed + by_region * 1000003));
            s.set_polygon(std::make_shared<const Polygon>(rings_of(rings)));
            s.carry_region_darts_from_start();
            s.set_region_darts_per_cell(16.0);  // an epoch seldom ends with no point
            if (by_region) s.draw_cut_cells_by_region();
            std::size_t added = 0;
            s.run(2, &added);
            ck_assert_uint_eq(added, 2);
            from_regions += s.jones().region_stats().points > 0;
            double xy[4];
            s.copy_points(0, 2, xy);
            ++parts[xy[2] > 1.1 ? 2 : xy[3] > 0.1 ? 1 : 0];
        }
        ck_assert_msg(from_regions > static_cast<std::size_t>(seeds) * 9 / 10, "%zu of %d second points by the darts",
                      from_regions, seeds);
        // Pearson's chi-square, 2 degrees of freedom: 23 has probability 1e-5.
        double chi2 = 0;
        for (int part = 0; part < 3; ++part) {
            const double expected = seeds * area[part] / total;
            chi2 += (parts[part] - expected) * (parts[part] - expected) / expected;
        }
        ck_assert_msg(chi2 < 23, "by %s: base %d, teeth %d, block %d of %d; expected %.1f, %.1f, %.1f (chi2 %.1f)",
                      by_region ? "the trapezoids" : "the fan", parts[0], parts[1], parts[2], seeds,
                      seeds * area[0] / total, seeds * area[1] / total, seeds * area[2] / total, chi2);
    }
}
END_TEST

Suite* space_time_polygon_suite() {
    Suite* s = suite_create("space_time_polygon");
    TCase* t = tcase_create("parallel opening in a polygon");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, sub_squares_outside_and_inside_are_so);
    tcase_add_test(t, epochs_keep_points_inside_and_apart);
    tcase_add_test(t, same_points_in_polygons_on_any_number_of_threads);
    tcase_add_test(t, the_free_regions_darts_run_in_polygons);
    tcase_add_test(t, region_darts_in_cut_cells_are_uniform);
    suite_add_tcase(s, t);
    return s;
}
