// test_outline_filter.cpp - the verifier's floating-point filter for cells the
// outline cuts: whatever it certifies covered, the exact test finds covered,
// cell by cell, in maximal patterns and in patterns with points taken out
// (where many cut cells are not covered); and it settles nearly every cell of
// a maximal pattern, which is what makes verifying a thin domain fast.
#include <check.h>

#include <cmath>
#include <memory>
#include <vector>

#include "domain/polygon.hpp"
#include "jones/jones_stage.hpp"
#include "mesh/delaunay.hpp"
#include "sampler/sampler.hpp"
#include "polygon_rings.hpp"
#include "suites.hpp"
#include "verify/outline_filter.hpp"
#include "verify/verify_outline.hpp"

namespace {

using pds::Point;
using pds::Polygon;
using Verdict = pds::OutlineJudge::Verdict;

// A strip of width w along a unit segment turned by `turn` radians.
std::vector<double> strip(double w, double turn) {
    const double c = std::cos(turn), s = std::sin(turn);
    return {0.0, 0.0, c, s, c - w * s, s + w * c, -w * s, w * c};
}

// A comb: a base 0.1 tall, then `teeth` teeth of width 0.3 / teeth.
std::vector<double> comb(int teeth) {
    std::vector<double> xy{0.0, 0.0, 1.0, 0.0};
    const double step = 1.0 / teeth, width = 0.3 / teeth;
    for (int i = teeth - 1; i >= 0; --i) {
        const double right = i * step + width, left = i * step;
        xy.insert(xy.end(), {right, 0.1, right, 1.0, left, 1.0, left, 0.1});
    }
    xy.erase(xy.end() - 2, xy.end());  // the last tooth's foot is the base's corner
    xy.insert(xy.end(), {0.0, 0.1});
    return xy;
}

struct Shape {
    const char* name;
    std::vector<std::vector<double>> rings;
    double r;
    double settled;  // the least share of a maximal pattern's cut cells the filter settles
    bool light;      // also in light runs (Valgrind)
};

std::vector<Shape> shapes() {
    return {
        {"strip 0.01 turned 30 degrees", {strip(0.01, 0.5235987755982988)}, 0.003, 0.99, true},
        {"strip 0.001 turned 1 radian", {strip(0.001, 1.0)}, 0.0007, 0.99, true},
        {"comb of 12 teeth", {comb(12)}, 0.004, 0.99, false},
        {"square with a hole and a spike",
         {{0, 0, 1, 0, 1, 1, 0.52, 1, 0.5, 1.6, 0.48, 1, 0, 1}, {0.3, 0.3, 0.3, 0.7, 0.7, 0.7, 0.7, 0.3}},
         0.02,
         0.99,
         true},
        // A ring's side traced again along part of another ring's: not outline
        // there, but its edges are near, so fewer cells are settled.
        {"rectangle over its own lower half", {{0, 0, 1, 0, 1, 2, 0, 2}, {0, 0, 1, 0, 1, 1, 0, 1}}, 0.05, 0.8, true},
    };
}

struct Tally {
    int by_filter = 0, exactly = 0, uncovered = 0;
};

// Judges every cell with the filter and without: the verdicts must agree.
Tally compare(const pds::Delaunay& dt, const Polygon& polygon, double r, const char* what) {
    pds::OutlineJudge judge(dt, polygon, r);
    Tally t;
    for (pds::VertexIndex v = pds::Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
        const Verdict with = judge.judge(v, true), without = judge.judge(v, false);
        if (with == Verdict::covered_by_filter) {
            ck_assert_msg(without == Verdict::covered_exactly,
                          "%s: vertex %u certified by the filter, exact verdict %d", what, v,
                          static_cast<int>(without));
            ++t.by_filter;
        } else {
            ck_assert_msg(with == without, "%s: vertex %u: %d with the filter, %d without", what, v,
                          static_cast<int>(with), static_cast<int>(without));
            t.exactly += with == Verdict::covered_exactly;
            t.uncovered += with == Verdict::uncovered;
        }
    }
    return t;
}

pds::Delaunay build(const std::vector<Point>& pts, const pds::Box& box) {
    pds::Delaunay dt(box);
    dt.reserve(pts.size() + pds::Delaunay::kGhosts);
    std::uint32_t near = 0;
    for (const Point& p : pts) near = dt.insert(p, near);
    return dt;
}

}  // namespace

START_TEST(filter_certifies_only_what_the_exact_test_does) {
    // Light runs (Valgrind): one seed, a tenth of the points, no comb.
    const int seeds = test_light() ? 1 : 3;
    const double coarser = test_light() ? 3.2 : 1.0;
    for (const Shape& shape : shapes()) {
        if (test_light() && !shape.light) continue;
        for (int seed = 1; seed <= seeds; ++seed) {
            pds::Sampler s(shape.r * coarser, static_cast<std::uint64_t>(seed));
            s.set_polygon(std::make_shared<const Polygon>(rings_of(shape.rings)));
            std::size_t added = 0;
            ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
            const Polygon& polygon = *s.frame().polygon();
            const double r = s.frame().r();
            const pds::Delaunay& mesh = s.jones().mesh();
            // The maximal pattern: no cell uncovered, nearly all settled by the filter.
            const Tally full = compare(mesh, polygon, r, shape.name);
            ck_assert_msg(full.uncovered == 0, "%s, seed %d: %d cells uncovered", shape.name, seed, full.uncovered);
            ck_assert_msg(full.by_filter >= shape.settled * (full.by_filter + full.exactly) && full.by_filter > 0,
                          "%s, seed %d: %d cells by the filter, %d exactly", shape.name, seed, full.by_filter,
                          full.exactly);
            // Every third point taken out: holes near the outline, which the
            // filter must leave to the exact test.
            const auto& all = mesh.points();
            std::vector<Point> fewer;
            for (std::size_t i = pds::Delaunay::kGhosts; i < all.size(); ++i)
                if (i % 3 != 0) fewer.push_back(all[i]);
            const Tally holed = compare(build(fewer, s.frame().box()), polygon, r, shape.name);
            ck_assert_msg(holed.uncovered > 0 && holed.by_filter > 0, "%s, seed %d: %d uncovered, %d by the filter",
                          shape.name, seed, holed.uncovered, holed.by_filter);
        }
    }
}
END_TEST

START_TEST(clearance_is_certain_only_away_from_the_outline) {
    const Polygon square = rings_of({{0, 0, 1, 0, 1, 1, 0, 1}});
    pds::PolygonClearance clearance(square);
    const double tiny = std::ldexp(1.0, -40);
    ck_assert(clearance.certainly_outside(Point{1.5, 0.5}, 1e-12));
    ck_assert(clearance.certainly_outside(Point{0.5, -3.0}, 1e-12));  // outside the box
    ck_assert(clearance.certainly_outside(Point{1.0 + 8 * tiny, 0.5}, tiny));
    ck_assert(!clearance.certainly_outside(Point{0.5, 0.5}, 1e-12));                   // inside
    ck_assert(!clearance.certainly_outside(Point{1.0, 0.5}, 1e-12));                   // on an edge
    ck_assert(!clearance.certainly_outside(Point{1.0 + tiny, 0.5}, 4 * tiny));         // its error reaches in
    ck_assert(!clearance.certainly_outside(Point{1.0 + tiny, 1.0 + tiny}, 4 * tiny));  // near a corner
}
END_TEST

Suite* outline_filter_suite() {
    Suite* s = suite_create("outline_filter");
    TCase* t = tcase_create("core");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, filter_certifies_only_what_the_exact_test_does);
    tcase_add_test(t, clearance_is_certain_only_away_from_the_outline);
    suite_add_tcase(s, t);
    return s;
}
