// test_polygon_domain.cpp - the polygon as the sampler's domain type: its
// even-odd area whatever the rings' orientations, an outline with nothing
// inside refused, a uniform point (inside, and spread by area), the count
// bound against a packing, exact scaling, a ring traced twice (no part of
// the outline) around and inside the region, frames far thinner than their
// sides are long, the law of region and fan draws in cut cells.
#include <check.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "law_compare.hpp"
#include "domain/polygon.hpp"
#include "sampler/sampler.hpp"
#include "polygon_rings.hpp"
#include "suites.hpp"

namespace {

using pds::Point;
using pds::Polygon;

std::vector<double> square(double x0, double y0, double side, bool clockwise) {
    std::vector<double> ccw{x0, y0, x0 + side, y0, x0 + side, y0 + side, x0, y0 + side};
    if (!clockwise) return ccw;
    return {ccw[6], ccw[7], ccw[4], ccw[5], ccw[2], ccw[3], ccw[0], ccw[1]};
}

START_TEST(a_comb_locates_with_a_finer_index_as_with_its_own) {
    // A triangle traced twice in the base: its edges count in the parity
    // only, which the finer index must know too.
    const std::vector<double> twice{0.5, 0.02, 0.6, 0.03, 0.55, 0.08, 0.5, 0.02, 0.6, 0.03, 0.55, 0.08};
    const Polygon p = rings_of({comb(64), twice});
    ck_assert_msg(&p.locator() != &p.index(), "no finer index for a comb of 64 teeth");
    const pds::PolygonRings& rings = p.rings();
    auto same = [&](const Point& q) {
        const int got = p.locate(q), want = p.index().locate(q);
        ck_assert_msg(got == want, "(%.17g, %.17g): located %d, the index says %d", q.x, q.y, got, want);
    };
    pds::Rng rng(5);
    const int probes = test_light() ? 5000 : 50000;
    for (int i = 0; i < probes; ++i) same(Point{-0.01 + 1.02 * rng.next_double(), -0.01 + 1.02 * rng.next_double()});
    for (std::size_t e = 0; e < rings.vertices(); ++e) {
        const Point a = rings.edge_start(e), b = rings.edge_end(e);
        same(a);
        same(Point{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)});
        same(Point{a.x + 0.25 * (b.x - a.x), a.y + 0.25 * (b.y - a.y)});
    }
    ck_assert(p.contains(Point{0.55, 0.03}) && p.locate(Point{0.5, 0.02}) == pds::PolygonIndex::kInside);
    // A pattern in it, verified.
    pds::Sampler s(0.01, 3);
    s.set_polygon(std::make_shared<const Polygon>(rings_of({comb(64), twice})));
    std::size_t added = 0;
    ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.maximal, "the comb: %s", rep.failure.c_str());
}
END_TEST

START_TEST(even_odd_area_in_any_orientation) {
    for (int mask = 0; mask < 8; ++mask) {
        // A 4x4 square, a 2x2 hole in it, a 1x1 island in the hole.
        const Polygon p = rings_of({square(0, 0, 4, mask & 1), square(1, 1, 2, mask & 2), square(1.5, 1.5, 1, mask & 4)});
        ck_assert_msg(std::fabs(p.area() - (16.0 - 4.0 + 1.0)) < 1e-12, "orientations %d: area %.17g", mask, p.area());
        ck_assert_double_eq(p.perimeter(), 16.0 + 8.0 + 4.0);
    }
    // Two separate squares, and a hole touching the outer ring at a vertex.
    ck_assert_double_eq_tol(rings_of({square(0, 0, 1, false), square(3, 0, 2, true)}).area(), 5.0, 1e-12);
    const Polygon touching = rings_of({square(0, 0, 4, false), {0, 0, 2, 1, 1, 2}});
    ck_assert_double_eq_tol(touching.area(), 16.0 - 1.5, 1e-12);
}
END_TEST

START_TEST(refuses_an_outline_with_nothing_inside) {
    std::string what;
    try {
        rings_of({square(0, 0, 1, false), square(0, 0, 1, true)});  // the same square twice
    } catch (const pds::DomainError& e) {
        what = e.what();
    }
    ck_assert_str_eq(what.c_str(), "the outline encloses nothing by the even-odd rule");
}
END_TEST

START_TEST(uniform_point_inside_and_spread_by_area) {
    // An L of three unit squares: the top-right square is missing.
    const Polygon l = rings_of({{0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2}});
    ck_assert_double_eq_tol(l.area(), 3.0, 1e-12);
    pds::Rng rng(11);
    const int n = test_light() ? 6000 : 60000;
    int quarter[3] = {0, 0, 0};  // bottom-left, bottom-right, top-left
    for (int i = 0; i < n; ++i) {
        const Point p = l.uniform_point(rng);
        ck_assert(l.contains(p));
        ck_assert_msg(!(p.x > 1.0 && p.y > 1.0), "(%g, %g) in the missing square", p.x, p.y);
        ++quarter[p.x > 1.0 ? 1 : (p.y > 1.0 ? 2 : 0)];
    }
    // Each square holds a third: 5 standard deviations.
    const double expect = n / 3.0, sd = std::sqrt(n * (1.0 / 3.0) * (2.0 / 3.0));
    for (int q : quarter) ck_assert_msg(std::fabs(q - expect) < 5.0 * sd, "%d of %d in one square", q, n);
}
END_TEST

START_TEST(count_bound_holds_a_packing) {
    const Polygon l = rings_of({{0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2}, square(0.2, 0.2, 0.5, true)});
    for (double r : {0.02, 0.05, 0.2}) {
        std::size_t packed = 0;
        int row = 0;
        for (double y = 0.0; y <= 2.0; y += std::sqrt(3.0) / 2.0 * r, ++row)
            for (double x = row % 2 ? r / 2 : 0.0; x <= 2.0; x += r) packed += l.contains(Point{x, y});
        ck_assert_msg(static_cast<double>(packed) <= l.count_bound(r), "r=%g: %zu > %g", r, packed, l.count_bound(r));
        ck_assert(l.count_bound(r) < 2.0 * static_cast<double>(packed) + 100.0);
    }
}
END_TEST

START_TEST(scaling_is_exact) {
    const Polygon p = rings_of({square(-1, 0.5, 3, false), square(0, 1, 1, false)});
    const Polygon big = p.scaled(5);
    ck_assert_double_eq(big.area(), 1024.0 * p.area());
    ck_assert_double_eq(big.bounds().x0, -32.0);
    const Polygon back = big.scaled(-5);
    ck_assert_double_eq(back.area(), p.area());
    pds::Rng rng(2);
    for (int i = 0; i < 2000; ++i) {
        const Point q{-1.5 + 4.0 * rng.next_double(), 4.0 * rng.next_double()};
        ck_assert(p.locate(q) == big.locate(Point{32.0 * q.x, 32.0 * q.y}));
    }
}
END_TEST

// A triangle traced twice cancels itself by the even-odd rule: its edges
// still count in the parity, but no point of them is on the outline, so the
// region and its closure are those of the other rings. Run alone it is the
// first case (the box reaches out to it: its corner is the triangle's
// vertex), inside a square the second (its edges lie in the region).
START_TEST(a_ring_traced_twice_is_no_outline) {
    const std::vector<double> twice{2, 0, 0, 0.1, -1.5, -2.7, 2, 0, 0, 0.1, -1.5, -2.7};
    const Point vertex{-1.5, -2.7}, on_edge{1, 0.05};
    const Polygon apart = rings_of({square(3, 13, 0.8, false), twice});
    ck_assert(!apart.contains(vertex) && !apart.contains(on_edge));
    ck_assert_double_eq_tol(apart.area(), 0.64, 1e-12);
    const Polygon inside = rings_of({square(-2, -3, 5, true), twice});
    ck_assert(inside.contains(vertex) && inside.contains(on_edge));
    ck_assert(inside.locate(vertex) == pds::PolygonIndex::kInside);
    ck_assert_double_eq_tol(inside.area(), 25.0, 1e-12);
    // Traced twice along an edge of the other ring: three copies of that
    // edge, one of which is outline; the area is the other ring's alone.
    const std::vector<double> triangle{2, 0, 0, 0.1, 5, 0.05};
    const Polygon along = rings_of({triangle, twice});
    ck_assert_double_eq_tol(along.area(), 0.2, 1e-12);
    ck_assert(!along.contains(vertex) && along.contains(Point{1, 0.05}));
    {
        pds::Sampler s(0.01, 7);
        s.set_polygon(std::make_shared<const Polygon>(rings_of({triangle, twice})));
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        const pds::VerifyReport rep = s.verify();
        ck_assert_msg(rep.maximal, "along an edge: %s", rep.failure.c_str());
    }
    for (std::uint64_t seed = 1; seed <= 3; ++seed)
        for (const Polygon* p : {&apart, &inside}) {
            pds::Sampler s(p == &apart ? 0.1 : 0.3, seed);
            s.set_polygon(std::make_shared<const Polygon>(rings_of({p == &apart ? square(3, 13, 0.8, false)
                                                                                  : square(-2, -3, 5, true),
                                                                    twice})));
            std::size_t added = 0;
            ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
            const pds::VerifyReport rep = s.verify();
            ck_assert_msg(rep.maximal, "seed %llu, %s: %s", static_cast<unsigned long long>(seed),
                          p == &apart ? "apart" : "inside", rep.failure.c_str());
        }
}
END_TEST

START_TEST(edges_that_overlap_in_part_cancel_there) {
    // Two squares the same way round, overlapping in a strip: their sides
    // overlap in part along the strip, where the even-odd rule cancels them
    // (the strip is outside), so the area is 4 + 4 - 2 * 0.5.
    const Polygon strip = rings_of({square(0, 0, 2, false), square(0, 1.75, 2, false)});
    ck_assert_double_eq_tol(strip.area(), 7.0, 1e-12);
    ck_assert(!strip.contains(Point{1, 1.875}) && strip.contains(Point{1, 1}) && strip.contains(Point{1, 3}));
    ck_assert(strip.locate(Point{2, 1.875}) == pds::PolygonIndex::kOutside);
    // Side by side, sharing part of a side (run opposite ways): the shared
    // part is inside, not outline.
    const Polygon side = rings_of({square(0, 0, 2, false), square(2, 1, 2, false)});
    ck_assert_double_eq_tol(side.area(), 8.0, 1e-12);
    ck_assert(side.locate(Point{2, 1.5}) == pds::PolygonIndex::kInside);
    ck_assert(side.locate(Point{2, 0.5}) == pds::PolygonIndex::kOnOutline);
    for (std::uint64_t seed = 1; seed <= 3; ++seed)
        for (const bool in_strip : {true, false}) {
            pds::Sampler s(0.1, seed);
            s.set_polygon(std::make_shared<const Polygon>(
                rings_of({square(0, 0, 2, false), in_strip ? square(0, 1.75, 2, false) : square(2, 1, 2, false)})));
            std::size_t added = 0;
            ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
            const pds::VerifyReport rep = s.verify();
            ck_assert_msg(rep.maximal, "seed %llu, %s: %s", static_cast<unsigned long long>(seed),
                          in_strip ? "strip" : "side by side", rep.failure.c_str());
        }
}
END_TEST

START_TEST(frames_far_thinner_than_their_sides_are_long) {
    // A unit square frame 2^-24 or 2^-36 wide, beside a small square. Each
    // side's probes must start closer than the frame is wide: at 2^-20 of a
    // side's length they jump over the frame, every side ties, and the frame
    // is dropped (the area was the small square's alone).
    for (const double d : {0x1p-24, 0x1p-36}) {
        const std::vector<double> outer{1, 1, 2, 1, 2, 2, 1, 2};
        const std::vector<double> inner{1 + d, 1 + d, 2 - d, 1 + d, 2 - d, 2 - d, 1 + d, 2 - d};
        const Polygon shape = rings_of({outer, inner, square(2.5, 2.5, 0.0625, false)});
        const double frame = 1.0 - (1.0 - 2 * d) * (1.0 - 2 * d);
        ck_assert_msg(std::fabs(shape.area() - (frame + 0x1p-8)) <= 1e-9 * frame, "d %a: area %.17g", d, shape.area());
        ck_assert(shape.locate(Point{1 + 0.5 * d, 1.5}) == pds::PolygonIndex::kInside);
        ck_assert(shape.locate(Point{1.5, 2 - 0.5 * d}) == pds::PolygonIndex::kInside);
        ck_assert(shape.locate(Point{1 + 2 * d, 1.5}) == pds::PolygonIndex::kOutside);
    }
}
END_TEST

START_TEST(a_thin_strip_turns_to_trapezoids_early) {
    // A unit square frame 10^-6 wide at R 0.01: nearly every fan draw in its
    // cells lands outside it, yet points come often enough that no run of
    // refusals reaches a failure. The refusals counted in all turn the cut
    // cells to their trapezoids after a few thousand (it took about 2000 a
    // point to the end before), and the run ends maximal.
    const std::vector<std::vector<double>> rings{{1, 1, 2, 1, 2, 2, 1, 2},
                                                 {1 + 1e-6, 1 + 1e-6, 1 + 1e-6, 2 - 1e-6, 2 - 1e-6, 2 - 1e-6, 2 - 1e-6, 1 + 1e-6}};
    for (std::uint64_t seed = 1; seed <= (test_light() ? 1u : 3u); ++seed) {
        pds::Sampler s(0.01, seed);
        s.set_polygon(std::make_shared<const Polygon>(rings_of(rings)));
        std::size_t added = 0;
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        ck_assert_msg(s.verify().maximal, "seed %llu", static_cast<unsigned long long>(seed));
        const pds::JonesStats& st = s.jones().stats();
        ck_assert_msg(st.region_draws > 0 && st.refused_draws < 3 * 4096,
                      "seed %llu: %zu refused, %zu placed by the fan, %zu from trapezoids",
                      static_cast<unsigned long long>(seed), st.refused_draws, st.placed_draws, st.region_draws);
        ck_assert_uint_gt(s.count(), 250);
    }
}
END_TEST

// The points within r of the outline's segments (as xy pairs, ring by ring).
std::size_t near_outline(const std::vector<pds::Point>& points, const std::vector<std::vector<double>>& rings, double r) {
    std::size_t near = 0;
    for (const pds::Point& p : points) {
        double best = HUGE_VAL;
        for (const auto& ring : rings)
            for (std::size_t i = 0; i < ring.size(); i += 2) {
                const std::size_t j = (i + 2) % ring.size();
                const double ax = ring[i], ay = ring[i + 1], dx = ring[j] - ax, dy = ring[j + 1] - ay;
                const double t = std::clamp(((p.x - ax) * dx + (p.y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
                best = std::min(best, std::hypot(p.x - ax - t * dx, p.y - ay - t * dy));
            }
        near += best < r;
    }
    return near;
}

START_TEST(region_draws_keep_the_law) {
    // The Jones loop alone in an L with a hole at R 0.1, where nearly every
    // cell is cut: cut cells drawn from their regions' trapezoids from the
    // first point, against the fan's draws (whose law the API suite
    // domain_law checks against dart throwing). Over many seeds each: the
    // count N and the points within R of the outline, by z tests on the
    // means, and N by a Kolmogorov-Smirnov test (law_compare.hpp's bounds).
    const std::vector<std::vector<double>> rings{{0, 0, 1, 0, 1, 0.4, 0.4, 0.4, 0.4, 1, 0, 1},
                                                 square(0.1, 0.1, 0.15, true)};
    const double r = 0.1;
    const std::uint64_t seeds = test_light() ? 40 : 400;
    std::vector<double> count[2], near[2];
    std::size_t region_draws[2] = {0, 0};
    for (int by_region = 0; by_region < 2; ++by_region)
        for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
            pds::Sampler s(r, seed + static_cast<std::uint64_t>(by_region) * 1000003);
            s.set_polygon(std::make_shared<const Polygon>(rings_of(rings)));
            s.skip_dart_stage();
            if (by_region) s.draw_cut_cells_by_region();
            std::size_t added = 0;
            ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
            ck_assert_msg(s.verify().maximal, "seed %llu", static_cast<unsigned long long>(seed));
            std::vector<double> xy(2 * s.count());
            s.copy_points(0, s.count(), xy.data());
            std::vector<pds::Point> points;
            for (std::size_t k = 0; k < s.count(); ++k) points.push_back(pds::Point{xy[2 * k], xy[2 * k + 1]});
            count[by_region].push_back(static_cast<double>(points.size()));
            near[by_region].push_back(static_cast<double>(near_outline(points, rings, r)));
            region_draws[by_region] += s.jones().stats().region_draws;
        }
    ck_assert_uint_eq(region_draws[0], 0);
    ck_assert_msg(region_draws[1] > seeds * 20, "%zu region draws", region_draws[1]);
    const double zn = law::z_score(count[1], count[0]), znear = law::z_score(near[1], near[0]);
    const double ks = law::ks_scaled(count[1], count[0]);
    ck_assert_msg(std::fabs(zn) < 4.5, "N %.3f by region, %.3f by the fan (z %.2f)", law::mean(count[1]),
                  law::mean(count[0]), zn);
    ck_assert_msg(std::fabs(znear) < 4.5, "near the outline %.3f by region, %.3f by the fan (z %.2f)",
                  law::mean(near[1]), law::mean(near[0]), znear);
    ck_assert_msg(ks < 1.95, "the distribution of N differs (KS %.3f)", ks);
}
END_TEST

START_TEST(cells_reaching_across_teeth_are_chosen_by_free_area) {
    // The first point beside fixed points is uniform over the free area. Here
    // the comb's site sees the teeth past the gaps: rays from it leave the
    // comb and enter it again, so its cell's fan has clockwise triangles and
    // its counterclockwise sum far exceeds its free area; the block's site
    // has none. Drawn from the trapezoids, the comb's cell must still be
    // chosen by its free area (an L has too few such cells to tell). The
    // counts in the base, the teeth and the block are compared with the
    // exact areas, for region and fan draws alike, and with each other.
    const std::vector<std::vector<double>> rings{comb(8), {1.2, 0, 2.0, 0, 2.0, 1.0, 1.2, 1.0}};
    const double r = 0.05, disk = M_PI * r * r;  // each fixed point's disk lies inside
    // Free areas: the base (less the comb's disk), the teeth, the block (less its disk).
    const double area[3] = {0.1 - disk, 8 * (0.3 / 8) * 0.9, 0.8 - disk};
    const double total = area[0] + area[1] + area[2];
    const int seeds = test_light() ? 600 : 4000;
    int parts[2][3] = {{0, 0, 0}, {0, 0, 0}};
    std::size_t region_draws[2] = {0, 0};
    for (int by_region = 0; by_region < 2; ++by_region)
        for (int seed = 1; seed <= seeds; ++seed) {
            pds::Sampler s(r, static_cast<std::uint64_t>(seed + by_region * 1000003));
            s.set_polygon(std::make_shared<const Polygon>(rings_of(rings)));
            s.set_fixed({Point{0.5, 0.05}, Point{1.6, 0.5}}, {0.0, 0.0});
            s.skip_dart_stage();
            if (by_region) s.draw_cut_cells_by_region();
            std::size_t added = 0;
            s.run(1, &added);
            ck_assert_uint_eq(added, 1);
            double xy[2];
            s.copy_points(0, 1, xy);
            ++parts[by_region][xy[0] > 1.1 ? 2 : xy[1] > 0.1 ? 1 : 0];
            region_draws[by_region] += s.jones().stats().region_draws;
        }
    ck_assert_uint_eq(region_draws[0], 0);
    ck_assert_uint_ge(region_draws[1], static_cast<std::size_t>(seeds));  // a batch draws several
    const char* how[2] = {"the fan", "the trapezoids"};
    for (int k = 0; k < 2; ++k) {
        // Pearson's chi-square against the exact shares, 2 degrees of
        // freedom: 23 has probability 1e-5.
        double chi2 = 0;
        for (int part = 0; part < 3; ++part) {
            const double expected = seeds * area[part] / total;
            chi2 += (parts[k][part] - expected) * (parts[k][part] - expected) / expected;
        }
        ck_assert_msg(chi2 < 23, "by %s: base %d, teeth %d, block %d of %d; expected %.1f, %.1f, %.1f (chi2 %.1f)",
                      how[k], parts[k][0], parts[k][1], parts[k][2], seeds, seeds * area[0] / total,
                      seeds * area[1] / total, seeds * area[2] / total, chi2);
    }
    // The comb's share, trapezoids against fan (two-sample z).
    const double a = (parts[1][0] + parts[1][1]) / double(seeds), b = (parts[0][0] + parts[0][1]) / double(seeds);
    const double pooled = (a + b) / 2, z = (a - b) / std::sqrt(2 * pooled * (1 - pooled) / seeds);
    ck_assert_msg(std::fabs(z) < 4.5, "the comb's share %.4f by the trapezoids, %.4f by the fan (z %.2f)", a, b, z);
}
END_TEST

}  // namespace

Suite* polygon_domain_suite() {
    Suite* s = suite_create("polygon_domain");
    TCase* t = tcase_create("domain");
    tcase_add_test(t, even_odd_area_in_any_orientation);
    tcase_add_test(t, a_comb_locates_with_a_finer_index_as_with_its_own);
    tcase_add_test(t, refuses_an_outline_with_nothing_inside);
    tcase_add_test(t, uniform_point_inside_and_spread_by_area);
    tcase_add_test(t, count_bound_holds_a_packing);
    tcase_add_test(t, scaling_is_exact);
    tcase_add_test(t, a_ring_traced_twice_is_no_outline);
    tcase_add_test(t, edges_that_overlap_in_part_cancel_there);
    tcase_add_test(t, frames_far_thinner_than_their_sides_are_long);
    tcase_add_test(t, a_thin_strip_turns_to_trapezoids_early);
    tcase_add_test(t, region_draws_keep_the_law);
    tcase_add_test(t, cells_reaching_across_teeth_are_chosen_by_free_area);
    suite_add_tcase(s, t);
    return s;
}
