// test_outline_clip.cpp - the sampler in a polygonal domain, checked against
// independent computations: the free area of partial patterns (cells cut by
// the outline, their clockwise pieces subtracted) against a grid count with
// a plain even-odd test; the mask's outline against its pixels; maximal
// patterns whose cells are all covered by the exact test.
#include <check.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "cells/outline_clip.hpp"
#include "core/rng.hpp"
#include "domain/mask_outline.hpp"
#include "even_odd.hpp"
#include "domain/polygon.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

using pds::Point;
using pds::Polygon;

struct Shape {
    std::vector<double> xy;
    std::vector<std::size_t> ends;
    void ring(const std::vector<Point>& pts) {
        for (const Point& p : pts) xy.push_back(p.x), xy.push_back(p.y);
        ends.push_back(xy.size() / 2);
    }
    std::shared_ptr<const Polygon> polygon() const {
        return std::make_shared<const Polygon>(xy.data(), ends.data(), ends.size());
    }
    // Even-odd, written out for the tests (not the library's index).
    bool contains(const Point& p) const { return even_odd_contains(xy.data(), ends.data(), ends.size(), p); }
};

// A five-armed star around (0.5, 0.5) with a square hole, 200 vertices.
Shape star_with_hole(bool clockwise) {
    Shape s;
    std::vector<Point> outer;
    for (int i = 0; i < 200; ++i) {
        const double a = 2 * M_PI * i / 200 * (clockwise ? -1 : 1);
        const double r = 0.32 + 0.14 * std::cos(5 * a);
        outer.push_back(Point{0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
    }
    s.ring(outer);
    s.ring({{0.45, 0.45}, {0.55, 0.45}, {0.55, 0.55}, {0.45, 0.55}});
    return s;
}

// A C shape (not star-shaped from most of its points) with a hole touching nothing.
Shape c_shape() {
    Shape s;
    s.ring({{0, 0}, {1, 0}, {1, 0.3}, {0.3, 0.3}, {0.3, 0.7}, {1, 0.7}, {1, 1}, {0, 1}});
    s.ring({{0.1, 0.4}, {0.2, 0.4}, {0.2, 0.6}, {0.1, 0.6}});
    return s;
}

// The free area by a grid count: probes in the shape and at least r from
// every point.
double grid_free_area(const Shape& s, const std::vector<Point>& pts, double r, const pds::Box& box, int n) {
    const double w = box.width() / n, h = box.height() / n;
    std::size_t free = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Point p{box.x0 + (i + 0.5) * w, box.y0 + (j + 0.5) * h};
            if (!s.contains(p)) continue;
            bool covered = false;
            for (const Point& q : pts)
                if ((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) < r * r) {
                    covered = true;
                    break;
                }
            if (!covered) ++free;
        }
    return static_cast<double>(free) * w * h;
}

std::vector<Point> points_of(const pds::Sampler& s) {
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    std::vector<Point> pts;
    for (std::size_t k = 0; k < s.count(); ++k) pts.push_back(Point{xy[2 * k], xy[2 * k + 1]});
    return pts;
}

void check_free_area(const Shape& shape, double r, std::uint64_t seed, std::size_t points, bool darts) {
    pds::Sampler s(r, seed);
    s.set_polygon(shape.polygon());
    if (!darts) s.skip_dart_stage();
    std::size_t added = 0;
    s.run(points, &added);
    const std::vector<Point> pts = points_of(s);
    for (const Point& p : pts) ck_assert_msg(shape.contains(p), "a point outside the shape");
    const int n = test_light() ? 250 : 700;
    const double grid = grid_free_area(shape, pts, r, s.domain(), n);
    const double exact = s.free_area();
    // The grid's error: about its cell times the length of the boundaries
    // (outline and circles) it resolves.
    const double tolerance = test_light() ? 0.03 : 0.01;
    ck_assert_msg(std::fabs(exact - grid) < tolerance * grid + 2e-4, "seed %llu, %zu points: free area %.6f, grid %.6f",
                  static_cast<unsigned long long>(seed), points, exact, grid);
}

START_TEST(free_area_of_cut_cells_matches_a_grid_count) {
    const Shape shapes[] = {star_with_hole(false), star_with_hole(true), c_shape()};
    const std::uint64_t seeds = test_light() ? 1 : 3;
    for (const Shape& shape : shapes)
        for (std::uint64_t seed = 1; seed <= seeds; ++seed)
            for (std::size_t points : {1, 8, 40, 120}) {
                if (test_light() && points == 120) continue;
                check_free_area(shape, 0.06, seed, points, false);
                check_free_area(shape, 0.06, seed + 10, points, true);
            }
}
END_TEST

START_TEST(maximal_patterns_are_covered_cell_by_cell) {
    const Shape shapes[] = {star_with_hole(false), c_shape()};
    const std::uint64_t seeds = test_light() ? 1 : 4;
    for (const Shape& shape : shapes)
        for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
            pds::Sampler s(test_light() ? 0.06 : 0.03, seed);
            s.set_polygon(shape.polygon());
            std::size_t added = 0;
            ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
            ck_assert_msg(s.verify().maximal, "%s", s.verify().failure.c_str());
            ck_assert(s.free_area() == 0.0);
            // Every cell, cut or not, is covered by the exact test.
            const pds::MeshCells cells = s.jones().cells();
            const pds::Delaunay& dt = s.jones().mesh();
            for (pds::VertexIndex v = pds::Delaunay::kGhosts; v < dt.vertex_count(); ++v)
                ck_assert_msg(cells.covered_exactly(v), "seed %llu: cell %u not covered",
                              static_cast<unsigned long long>(seed), v);
            // And a partial pattern is not: some cell has free room.
            pds::Sampler partial(0.03, seed);
            partial.set_polygon(shape.polygon());
            partial.skip_dart_stage();
            partial.run(30, &added);
            const pds::MeshCells pc = partial.jones().cells();
            const pds::Delaunay& pdt = partial.jones().mesh();
            bool some_free = false;
            for (pds::VertexIndex v = pds::Delaunay::kGhosts; v < pdt.vertex_count() && !some_free; ++v)
                some_free = !pc.covered_exactly(v);
            ck_assert(some_free);
        }
}
END_TEST

START_TEST(mask_outline_is_the_union_of_its_pixels) {
    // Pixels touching only at corners, a hole, a pixel on every side.
    const int w = 6, h = 5;
    const std::uint8_t px[h][w] = {{1, 1, 0, 1, 0, 1},
                                   {1, 0, 1, 0, 1, 1},
                                   {1, 1, 1, 1, 1, 0},
                                   {0, 1, 0, 1, 1, 1},
                                   {1, 1, 1, 1, 0, 1}};
    const pds::Box box{-1.0, 2.0, 2.0, 4.5};
    const pds::Outline o = pds::mask_outline(w, h, &px[0][0], box);
    const Polygon poly(o.xy.data(), o.ring_ends.data(), o.ring_ends.size());
    double area = 0.0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) area += px[j][i];
    const double cell = (box.width() / w) * (box.height() / h);
    ck_assert_msg(std::fabs(poly.area() - area * cell) < 1e-12, "area %.17g, pixels %.17g", poly.area(), area * cell);
    // Pixel centres and points near corners lie where their pixels say.
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            for (double fx : {0.5, 0.01, 0.99})
                for (double fy : {0.5, 0.01, 0.99}) {
                    const Point p{box.x0 + (i + fx) * box.width() / w, box.y0 + (j + fy) * box.height() / h};
                    ck_assert_msg(poly.contains(p) == (px[j][i] != 0), "pixel %d %d at %g %g", i, j, fx, fy);
                }
    // Collinear sides are merged: the bottom row's first two pixels make one edge.
    ck_assert_uint_lt(o.xy.size() / 2, static_cast<std::size_t>(4 * w * h));
}
END_TEST

// An outline of 10^5 vertices (a star whose edges are far shorter than R)
// with a hole: maximal, verified, every point inside by the plain test.
START_TEST(outline_of_a_hundred_thousand_vertices) {
    Shape s;
    std::vector<Point> outer;
    const int n = test_light() ? 20000 : 100000;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        const double r = 0.32 + 0.14 * std::cos(5 * a) + 0.004 * std::cos(997 * a);
        outer.push_back(Point{0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
    }
    s.ring(outer);
    s.ring({{0.45, 0.45}, {0.45, 0.55}, {0.55, 0.55}, {0.55, 0.45}});
    pds::Sampler sampler(test_light() ? 0.04 : 0.012, 5);
    sampler.set_polygon(s.polygon());
    std::size_t added = 0;
    ck_assert(sampler.run(0, &added) == pds::Sampler::RunEnd::complete);
    const pds::VerifyReport rep = sampler.verify();
    ck_assert_msg(rep.valid && rep.maximal, "%s", rep.failure.c_str());
    ck_assert(sampler.free_area() == 0.0);
    for (const Point& p : points_of(sampler)) ck_assert(s.contains(p));
}
END_TEST

// The second point of a run is uniform over the shape minus the first
// point's disk: the Jones loop's (cut cells, first exits) against plain
// rejection sampling, on a grid of bins, by a chi-square test over both
// samples. With R large, most cells are cut and the hole and the C's arms
// put several exits on one ray.
START_TEST(second_point_is_uniform_in_a_cut_region) {
    const Shape shape = c_shape();
    const double r = 0.25;
    const int nb = 5;  // nb x nb bins over the unit box
    std::vector<double> jones(nb * nb, 0.0), reference(nb * nb, 0.0);
    const auto bin = [&](const Point& p) {
        const int i = std::min(nb - 1, static_cast<int>(p.x * nb)), j = std::min(nb - 1, static_cast<int>(p.y * nb));
        return j * nb + i;
    };
    pds::Rng ref_rng(12345);
    const int runs = test_light() ? 1500 : 30000;
    for (int k = 0; k < runs; ++k) {
        pds::Sampler s(r, static_cast<std::uint64_t>(k) + 1);
        s.set_polygon(shape.polygon());
        s.skip_dart_stage();
        std::size_t added = 0;
        s.run(2, &added);
        ck_assert_uint_eq(added, 2);
        const std::vector<Point> pts = points_of(s);
        jones[bin(pts[1])] += 1.0;
        for (;;) {
            const Point p{ref_rng.next_double(), ref_rng.next_double()};
            if (!shape.contains(p) || std::hypot(p.x - pts[0].x, p.y - pts[0].y) < r) continue;
            reference[bin(p)] += 1.0;
            break;
        }
    }
    double chi2 = 0.0;
    int dof = -1;
    for (int b = 0; b < nb * nb; ++b) {
        const double total = jones[b] + reference[b];
        if (total == 0.0) continue;
        chi2 += (jones[b] - reference[b]) * (jones[b] - reference[b]) / total;
        ++dof;
    }
    // The 99.99th percentile of chi-square (Wilson and Hilferty): a fixed
    // seed passes or fails for good, and a bias of the first-exit rule
    // (every exit counted) gives about 150 here against about 54.
    const double k = dof, z = 3.719, c = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
    ck_assert_msg(chi2 < k * c * c * c, "chi2 %.1f with %d degrees of freedom (limit %.1f)", chi2, dof, k * c * c * c);
}
END_TEST

// The region a cell keeps: the signed area of the boundary the clip feeds
// its sink (relative to the site), and the number of sides.
struct RegionSink {
    double area = 0.0;
    int sides = 0;
    void vertex(const pds::OutlineClip::Vtx&) {}
    void edge(const pds::OutlineClip::Vtx& a, const pds::OutlineClip::Vtx& b) {
        area += 0.5 * (a.x * b.y - a.y * b.x);
        ++sides;
    }
    void finish() {}
};

// The square [x0, x0 + w] x [y0, y0 + w] as a cell of `site` (a power cell
// need not hold its site) in the square [0, 10]^2 with the hole [4, 6]^2.
RegionSink clip_square(pds::OutlineClip& clip, const Point& site, double x0, double y0, double w) {
    RegionSink sink;
    pds::OutlineClip::Stage<RegionSink> stage(clip, sink, site, pds::Box{0, 0, 10, 10}, 0.01);
    for (const Point& v : {Point{x0, y0}, Point{x0 + w, y0}, Point{x0 + w, y0 + w}, Point{x0, y0 + w}}) {
        const double x = v.x - site.x, y = v.y - site.y;
        stage.vertex(pds::OutlineClip::Vtx{x, y, 0.0, x * x + y * y});
    }
    stage.finish();
    return sink;
}

START_TEST(cells_no_edge_meets_are_kept_or_dropped_whole) {
    Shape s;
    s.ring({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
    s.ring({{4, 4}, {6, 4}, {6, 6}, {4, 6}});
    const auto polygon = s.polygon();
    pds::OutlineClip clip(*polygon);
    // Cells in grid cells the outline meets (the grid's cells are about 0.3
    // wide) but whose boxes no edge meets: kept whole inside, dropped whole
    // in the hole, wherever their sites are.
    struct Case {
        Point site;
        double x0, y0;
        bool inside;
    };
    for (const Case& c :
         {Case{{-0.5, 0.22}, 0.2, 0.2, true}, Case{{0.22, 0.22}, 0.2, 0.2, true}, Case{{3.9, 5.0}, 4.5, 5.0, false},
          Case{{4.55, 5.05}, 4.5, 5.0, false}, Case{{4.55, 5.05}, 6.1, 5.0, true}}) {
        const RegionSink r = clip_square(clip, c.site, c.x0, c.y0, 0.05);
        ck_assert_msg(clip.cut() && clip.edges().empty(), "the case must take the path it tests");
        const double want = c.inside ? 0.0025 : 0.0;
        ck_assert_msg(std::fabs(r.area - want) < 1e-15 && r.sides == (c.inside ? 4 : 0),
                      "cell at (%g, %g), site (%g, %g): area %.17g over %d sides, %g expected", c.x0, c.y0, c.site.x,
                      c.site.y, r.area, r.sides, want);
    }
    // A cell the hole's edge crosses: cut, the part outside the hole kept.
    const RegionSink r = clip_square(clip, Point{3.9, 5.0}, 3.95, 5.0, 0.1);
    ck_assert_msg(clip.cut() && !clip.edges().empty(), "the hole's side meets the cell");
    ck_assert_msg(std::fabs(r.area - 0.005) < 1e-15, "cut cell: area %.17g, 0.005 expected", r.area);
}
END_TEST

}  // namespace

Suite* outline_clip_suite() {
    Suite* s = suite_create("outline_clip");
    TCase* tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, free_area_of_cut_cells_matches_a_grid_count);
    tcase_add_test(tc, maximal_patterns_are_covered_cell_by_cell);
    tcase_add_test(tc, mask_outline_is_the_union_of_its_pixels);
    tcase_add_test(tc, second_point_is_uniform_in_a_cut_region);
    tcase_add_test(tc, outline_of_a_hundred_thousand_vertices);
    tcase_add_test(tc, cells_no_edge_meets_are_kept_or_dropped_whole);
    suite_add_tcase(s, tc);
    return s;
}
