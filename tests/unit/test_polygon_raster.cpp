// test_polygon_raster.cpp - a polygon's cells on a dart grid: every point of
// the closed polygon (inside, on its edges, at its vertices) lies in a cell
// of the runs; cells called inside lie wholly inside; the runs are in row
// order and disjoint, and hold little more than the polygon (a ring's hole
// and the sea between islands stay out); and the darts a grid draws among
// them (one radius, or a field's finest layer) are uniform over the polygon.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/rng.hpp"
#include "darts/dart_stage.hpp"
#include "darts/polygon_raster.hpp"
#include "domain/frame.hpp"
#include "radius/point_radii.hpp"
#include "radius/radius_field.hpp"
#include "polygon_rings.hpp"
#include "suites.hpp"

namespace {

using Rings = std::vector<std::vector<double>>;

Rings ring_around(double cx, double cy, double outer, double inner, int sides) {
    std::vector<double> a, b;
    for (int k = 0; k < sides; ++k) {
        const double t = 2.0 * M_PI * k / sides;
        a.insert(a.end(), {cx + outer * std::cos(t), cy + outer * std::sin(t)});
        b.insert(b.end(), {cx + inner * std::cos(t), cy + inner * std::sin(t)});
    }
    return {a, b};
}

struct Shape {
    const char* name;
    Rings rings;
};

std::vector<Shape> shapes() {
    const double d = 0.01;
    return {
        {"ring", ring_around(0.5, 0.5, 0.5, 0.49, 256)},
        {"islands far apart", {{0, 0, 1, 0, 1, 1, 0, 1}, {100, 100, 102, 100, 102, 101, 100, 101}}},
        {"diagonal strip", {{0, 0, d, 0, 1, 1 - d, 1, 1, 1 - d, 1, 0, d}}},
        {"bow tie and a hole", {{0, 0, 3, 2, 3, 0, 0, 2}, {0.2, 0.9, 0.6, 0.9, 0.6, 1.1, 0.2, 1.1}}},
        {"comb of slanted teeth",
         {{0, 0, 4, 0, 4, 0.1, 3.7, 3, 3.5, 0.1, 2.7, 3, 2.5, 0.1, 1.7, 3, 1.5, 0.1, 0.7, 3, 0.5, 0.1, 0, 0.1}}},
    };
}

// The raster over the polygon's box, about `across` cells along its longer
// side.
struct Grid {
    double x0, y0, s;
    std::size_t cols, rows;
};

Grid grid_over(const pds::Polygon& polygon, double across) {
    const pds::Box& b = polygon.bounds();
    const double s = std::max(b.width(), b.height()) / across;
    return Grid{b.x0, b.y0, s, static_cast<std::size_t>(std::ceil(b.width() / s)),
                static_cast<std::size_t>(std::ceil(b.height() / s))};
}

std::size_t cell_of(double v, double v0, double s, std::size_t n) {
    const double f = std::floor((v - v0) / s);
    return f <= 0.0 ? 0 : std::min(n - 1, static_cast<std::size_t>(f));
}

}  // namespace

START_TEST(every_point_of_the_polygon_lies_in_a_cell_of_the_runs) {
    for (const Shape& shape : shapes()) {
        const pds::Polygon polygon = rings_of(shape.rings);
        for (const double across : {97.0, 500.0, 2048.0}) {
            const Grid g = grid_over(polygon, across);
            pds::PolygonRaster raster;
            ck_assert(raster.build(polygon, g.x0, g.s, g.cols, g.y0, g.s, g.rows, std::size_t{1} << 30));
            // The cells in order: rows, then columns, each once.
            // Cells called inside are wholly inside: their corners, middle
            // and a random point.
            std::vector<std::uint64_t> keys(raster.cells());
            bool ordered = true;
            std::size_t inside_cells = 0, not_inside = 0;
            pds::Rng pick(3);
            for (std::size_t k = 0; k < keys.size(); ++k) {
                const pds::PolygonRaster::Cell c = raster.cell(k);
                keys[k] = std::uint64_t{c.row} * g.cols + c.col;
                ordered = ordered && c.col < g.cols && c.row < g.rows && (k == 0 || keys[k] > keys[k - 1]);
                if (!c.inside) continue;
                ++inside_cells;
                const double cx = g.x0 + static_cast<double>(c.col) * g.s, cy = g.y0 + static_cast<double>(c.row) * g.s;
                const double u = pick.next_double(), v = pick.next_double();
                const double fx[6] = {0, 1, 0, 1, 0.5, u}, fy[6] = {0, 0, 1, 1, 0.5, v};
                for (int m = 0; m < 6; ++m)
                    if (!polygon.contains(pds::Point{cx + fx[m] * g.s, cy + fy[m] * g.s})) ++not_inside;
            }
            ck_assert_msg(ordered, "%s, %g across: cells out of order", shape.name, across);
            ck_assert_msg(not_inside == 0, "%s, %g across: %zu points of cells called inside lie outside", shape.name,
                          across, not_inside);
            ck_assert_msg(inside_cells > 0 || across < 100.0, "%s, %g across: no cell called inside", shape.name,
                          across);
            const auto held = [&](const pds::Point& p) {
                const std::uint64_t key =
                    std::uint64_t{cell_of(p.y, g.y0, g.s, g.rows)} * g.cols + cell_of(p.x, g.x0, g.s, g.cols);
                return std::binary_search(keys.begin(), keys.end(), key);
            };
            // Points inside (drawn over each ring's box: islands far apart
            // fill little of the polygon's), and on every edge (its ends
            // and along it).
            std::size_t inside = 0, missed = 0;
            pds::Rng rng(11);
            for (const std::vector<double>& ring : shape.rings) {
                pds::Box b{ring[0], ring[1], ring[0], ring[1]};
                for (std::size_t i = 0; i < ring.size(); i += 2)
                    b = pds::Box{std::min(b.x0, ring[i]), std::min(b.y0, ring[i + 1]), std::max(b.x1, ring[i]),
                                 std::max(b.y1, ring[i + 1])};
                for (int k = 0; k < (test_light() ? 10000 : 100000); ++k) {
                    const pds::Point p{b.x0 + rng.next_double() * b.width(), b.y0 + rng.next_double() * b.height()};
                    if (!polygon.contains(p)) continue;
                    ++inside;
                    if (!held(p)) ++missed;
                }
            }
            const pds::PolygonRings& r = polygon.rings();
            for (std::size_t i = 0; i < r.vertices(); ++i) {
                const pds::Point a = r.edge_start(i), e = r.edge_end(i);
                for (const double t : {0.0, 0.25, 0.5, 0.999, 1.0})
                    if (!held(pds::Point{a.x + t * (e.x - a.x), a.y + t * (e.y - a.y)})) ++missed;
            }
            ck_assert_msg(inside > 100, "%s: %zu points inside", shape.name, inside);
            ck_assert_msg(missed == 0, "%s, %g across: %zu points of the polygon outside the runs", shape.name, across,
                          missed);
            // Little more than the polygon: its area in cells, and three
            // cells on either side of each edge's run along the rows.
            const double area_cells = polygon.area() / (g.s * g.s);
            const double edge_cells = polygon.perimeter() / g.s + static_cast<double>(r.vertices());
            ck_assert_msg(static_cast<double>(raster.cells()) <= area_cells + 6.0 * edge_cells,
                          "%s, %g across: %zu cells for an area of %.0f and edges of %.0f", shape.name, across,
                          raster.cells(), area_cells, edge_cells);
        }
    }
}
END_TEST

START_TEST(a_raster_that_would_cost_more_than_its_cap_is_not_built) {
    const pds::Polygon polygon = rings_of(ring_around(0.5, 0.5, 0.5, 0.49, 256));
    const Grid g = grid_over(polygon, 4096.0);
    pds::PolygonRaster raster;
    ck_assert(!raster.build(polygon, g.x0, g.s, g.cols, g.y0, g.s, g.rows, 1000));
    ck_assert_uint_eq(raster.cells(), 0);
    ck_assert(raster.build(polygon, g.x0, g.s, g.cols, g.y0, g.s, g.rows, std::size_t{1} << 30));
    ck_assert_uint_gt(raster.cells(), 0);
}
END_TEST

START_TEST(darts_among_the_cells_are_uniform_over_the_polygon) {
    // Two islands 100 apart, of areas 1 and 2 (each as tall), fill 1/3400
    // of their box: the dart grid draws among its raster's cells. The first
    // point lands in the larger island 2/3 of the time. Each island has one
    // run per row, so drawing a run first and then a cell in it would give
    // one half (z about 19 at 3000 seeds). The grid keeps its taken cells
    // only, as the sampler's would: the whole grid over the box is 1.6 GB.
    auto islands = std::make_shared<const pds::Polygon>(
        rings_of({{0, 0, 1, 0, 1, 1, 0, 1}, {100, 100, 102, 100, 102, 101, 100, 101}}));
    const pds::Box box = islands->bounds();
    ck_assert(pds::raster_suits(*islands, box));
    const int seeds = test_light() ? 600 : 3000;
    int large = 0, outside = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        pds::SparseDartStage stage(box, islands, 0.01);
        pds::Rng rng(static_cast<std::uint64_t>(seed));
        const pds::Point* p = stage.next(rng);
        ck_assert(p != nullptr);
        if (!islands->contains(*p)) ++outside;
        if (p->x > 50.0) ++large;
    }
    ck_assert_int_eq(outside, 0);
    const double n = seeds, expected = n * 2.0 / 3.0, sd = std::sqrt(n * 2.0 / 9.0);
    const double z = (large - expected) / sd;
    ck_assert_msg(std::fabs(z) < 4.0, "%d of %d in the larger island, %.1f expected (z %.2f)", large, seeds, expected,
                  z);
}
END_TEST

double twice_along_x(void* r0, double x, double) { return *static_cast<double*>(r0) * (1.0 + x); }

START_TEST(field_darts_among_the_cells_are_uniform_over_the_polygon) {
    // Islands of areas 1 and 2 (0.08 square, 0.08 by 0.16) in opposite
    // corners of the unit square fill 1/52 of it: a field's darts are drawn
    // among the finest layer's raster cells. The first point, by island and
    // by quarter of its width, against the areas (chi-square, 7 degrees of
    // freedom): darts placed from the padded grid's corner (two cells off)
    // leave each island's last quarter nearly empty.
    auto islands = std::make_shared<const pds::Polygon>(
        rings_of({{0, 0, 0.08, 0, 0.08, 0.08, 0, 0.08}, {0.92, 0.84, 1, 0.84, 1, 1, 0.92, 1}}));
    const pds::Box box{0, 0, 1, 1};
    ck_assert(pds::raster_suits(*islands, box));
    double r0 = 0.01;
    const pds::RadiusField field = pds::RadiusField::function(twice_along_x, &r0, r0, 2 * r0);
    const pds::Frame frame(box, 2 * r0);
    const pds::PointRadii radii(field, frame);
    const int seeds = test_light() ? 600 : 3000;
    std::vector<int> bins(8, 0);
    for (int seed = 1; seed <= seeds; ++seed) {
        pds::FieldDartStage stage(box, islands, radii);
        ck_assert(stage.grid().draws_in_raster());
        pds::Rng rng(static_cast<std::uint64_t>(seed));
        const pds::Point* p = stage.next(rng);
        ck_assert(p != nullptr && islands->contains(*p));
        const bool large = p->x > 0.5;
        const double x0 = large ? 0.92 : 0.0;
        bins[(large ? 4 : 0) + std::min(3, static_cast<int>((p->x - x0) / 0.02))]++;
    }
    double chi2 = 0.0;
    for (int k = 0; k < 8; ++k) {
        const double expected = seeds * (k < 4 ? 1.0 : 2.0) / 12.0;
        chi2 += (bins[k] - expected) * (bins[k] - expected) / expected;
    }
    ck_assert_msg(chi2 < 24.3, "chi2 %.1f (7 degrees of freedom, limit 24.3 at 0.001): %d %d %d %d | %d %d %d %d", chi2,
                  bins[0], bins[1], bins[2], bins[3], bins[4], bins[5], bins[6], bins[7]);
}
END_TEST

START_TEST(darts_stay_with_the_outline_grid_where_the_raster_is_coarser) {
    // A thin ring: at R 0.0005 the raster's cells are far fewer than the
    // outline grid's cells that meet the ring, and the darts are drawn among
    // them; at R 0.05 each raster cell is 9 times as wide as the ring, and
    // the outline grid's cells (0.004 wide) hold less: the darts stay there.
    // Two squares 1000 apart take the raster at either radius.
    auto ring = std::make_shared<const pds::Polygon>(rings_of(ring_around(0.5, 0.5, 0.5, 0.49, 256)));
    auto islands = std::make_shared<const pds::Polygon>(
        rings_of({{0, 0, 1, 0, 1, 1, 0, 1}, {1000, 1000, 1001, 1000, 1001, 1001, 1000, 1001}}));
    ck_assert(pds::SparseDartStage(ring->bounds(), ring, 0.0005).grid().draws_in_raster());
    ck_assert(!pds::SparseDartStage(ring->bounds(), ring, 0.05).grid().draws_in_raster());
    ck_assert(pds::SparseDartStage(islands->bounds(), islands, 0.01).grid().draws_in_raster());
    ck_assert(pds::SparseDartStage(islands->bounds(), islands, 0.3).grid().draws_in_raster());
}
END_TEST

START_TEST(a_raster_past_its_band_budget_is_not_built_for_the_darts) {
    // A square 1750 wide beside a hexagon traced twice (it cancels) in a
    // box 15375 by 9875, at R 0.001: the square's sides cross 5 million row
    // bands, past the 2^22 a grid builds (a bounded run of a few points in
    // a domain of 10^14 took seconds and gigabytes building it). At R 1 the
    // same polygon is rastered.
    const std::vector<double> hexagon = {14000, 13666.666666666666, 15916.666666666668, 14250, 19750, 14250, 19750,
                                         13083.333333333334, 17833.333333333332, 12500, 14000, 12500};
    std::vector<double> twice = hexagon;
    twice.insert(twice.end(), hexagon.begin(), hexagon.end());
    auto shape = std::make_shared<const pds::Polygon>(
        rings_of({twice, {4375, 5250, 4375, 6125, 5250, 6125, 6125, 6125, 6125, 5250, 6125, 4375, 5250, 4375, 4375,
                          4375, 4375, 5250}}));
    ck_assert(pds::raster_suits(*shape, shape->bounds()));
    ck_assert(!pds::SparseDartStage(shape->bounds(), shape, 0.001).grid().draws_in_raster());
    ck_assert(pds::SparseDartStage(shape->bounds(), shape, 1.0).grid().draws_in_raster());
}
END_TEST

Suite* polygon_raster_suite() {
    Suite* s = suite_create("polygon_raster");
    TCase* t = tcase_create("cells");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, every_point_of_the_polygon_lies_in_a_cell_of_the_runs);
    tcase_add_test(t, a_raster_that_would_cost_more_than_its_cap_is_not_built);
    tcase_add_test(t, darts_among_the_cells_are_uniform_over_the_polygon);
    tcase_add_test(t, field_darts_among_the_cells_are_uniform_over_the_polygon);
    tcase_add_test(t, darts_stay_with_the_outline_grid_where_the_raster_is_coarser);
    tcase_add_test(t, a_raster_past_its_band_budget_is_not_built_for_the_darts);
    suite_add_tcase(s, t);
    return s;
}
