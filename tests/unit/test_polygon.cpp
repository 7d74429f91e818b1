// test_polygon.cpp - a polygonal outline checked and cleaned (PolygonRings),
// and where points lie against it by the even-odd rule (PolygonIndex),
// compared with an independent answer: outlines on an integer lattice, points
// on the half-integer lattice, and a brute-force parity in 64-bit integers
// over every edge (a winding test needs no rounding there); the cells of
// another grid that meet the outline, counted by runs.
#include <check.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "domain/polygon_index.hpp"
#include "domain/polygon_rings.hpp"
#include "suites.hpp"

namespace {

using pds::Point;
using pds::PolygonIndex;
using pds::PolygonRings;

// An outline on the integer lattice: rings of (x, y), and the same placed in
// the plane as offset + scale * (x, y) (exact for the scales and offsets used).
struct LatticeOutline {
    std::vector<std::vector<std::int64_t>> rings;  // x y interleaved
    double scale = 1.0, offset = 0.0;

    PolygonRings build() const {
        std::vector<double> xy;
        std::vector<std::size_t> ends;
        for (const auto& r : rings) {
            for (std::int64_t v : r) xy.push_back(offset + scale * static_cast<double>(v));
            ends.push_back(xy.size() / 2);
        }
        return PolygonRings(xy.data(), ends.data(), ends.size());
    }
    Point place(std::int64_t x2, std::int64_t y2) const {  // a half-integer point, doubled coordinates
        return Point{offset + scale * 0.5 * static_cast<double>(x2), offset + scale * 0.5 * static_cast<double>(y2)};
    }
    // -1 outside, 0 on an edge, 1 inside, for the point (x2 / 2, y2 / 2).
    int brute_place(std::int64_t x2, std::int64_t y2) const {
        bool odd = false;
        for (const auto& r : rings) {
            const std::size_t n = r.size() / 2;
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t j = (i + 1) % n;
                const std::int64_t ax = 2 * r[2 * i], ay = 2 * r[2 * i + 1], bx = 2 * r[2 * j], by = 2 * r[2 * j + 1];
                const std::int64_t cross = (bx - ax) * (y2 - ay) - (by - ay) * (x2 - ax);
                if (cross == 0 && x2 >= std::min(ax, bx) && x2 <= std::max(ax, bx) && y2 >= std::min(ay, by) &&
                    y2 <= std::max(ay, by))
                    return 0;
                if ((ay > y2) != (by > y2)) {
                    // x of the crossing > x2  <=>  (x2 - ax) * (by - ay) < (bx - ax) * (y2 - ay), sign-corrected.
                    const bool right = (by > ay) ? cross > 0 : cross < 0;
                    if (right) odd = !odd;
                }
            }
        }
        return odd ? 1 : -1;
    }
};

// A star around (0, 0): n spikes between radii inner and outer (integers,
// rounded), clockwise when reversed.
std::vector<std::int64_t> star(int n, double inner, double outer, bool reversed, double cx = 0.0, double cy = 0.0) {
    std::vector<std::int64_t> r;
    for (int k = 0; k < 2 * n; ++k) {
        const int i = reversed ? 2 * n - 1 - k : k;
        const double rad = (i % 2) ? inner : outer;
        const double a = M_PI * i / n;
        r.push_back(static_cast<std::int64_t>(std::llround(cx + rad * std::cos(a))));
        r.push_back(static_cast<std::int64_t>(std::llround(cy + rad * std::sin(a))));
    }
    return r;
}

// Compares the index with the brute force at random half-integer points of
// the box [-m, m]^2 and at the vertices and edge midpoints (about 1000 a ring).
// `cells`: the index's size, 0 for the default (cells_for_edges).
void check_against_brute_force(const LatticeOutline& outline, std::int64_t m, int probes, double cells = 0.0) {
    const PolygonRings rings = outline.build();
    const PolygonIndex index(rings, cells > 0.0 ? cells : PolygonIndex::cells_for_edges(rings));
    pds::Rng rng(17);
    int seen[3] = {0, 0, 0};
    auto compare = [&](std::int64_t x2, std::int64_t y2) {
        const int want = outline.brute_place(x2, y2);
        const int got = index.locate(outline.place(x2, y2));
        ck_assert_msg(got == want, "(%g, %g): index %d, brute force %d", 0.5 * static_cast<double>(x2), 0.5 * static_cast<double>(y2), got, want);
        ck_assert(index.contains(outline.place(x2, y2)) == (want >= 0));
        ++seen[want + 1];
    };
    for (int i = 0; i < probes; ++i) {
        const double span = 4.0 * static_cast<double>(m) + 1.0;
        const auto x2 = static_cast<std::int64_t>(rng.next_double() * span) - 2 * m;
        const auto y2 = static_cast<std::int64_t>(rng.next_double() * span) - 2 * m;
        compare(x2, y2);
    }
    for (const auto& r : outline.rings) {
        const std::size_t n = r.size() / 2;
        const std::size_t stride = 1 + n / 1000;  // the brute force reads every edge
        for (std::size_t i = 0; i < n; i += stride) {
            const std::size_t j = (i + 1) % n;
            compare(2 * r[2 * i], 2 * r[2 * i + 1]);
            compare(r[2 * i] + r[2 * j], r[2 * i + 1] + r[2 * j + 1]);
        }
    }
    ck_assert_msg(seen[0] > 0 && seen[1] > 0 && seen[2] > 0, "outside %d, on %d, inside %d", seen[0], seen[1],
                  seen[2]);
}

std::string error_of(const std::vector<double>& xy, const std::vector<std::size_t>& ends) {
    try {
        PolygonRings rings(xy.data(), ends.data(), ends.size());
    } catch (const pds::DomainError& e) {
        return e.what();
    }
    return "";
}

void expect_error(const std::vector<double>& xy, const std::vector<std::size_t>& ends, const char* want) {
    const std::string got = error_of(xy, ends);
    ck_assert_msg(got == want, "got \"%s\", want \"%s\"", got.c_str(), want);
}

START_TEST(refuses_with_ring_and_vertex_named) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> square{0, 0, 1, 0, 1, 1, 0, 1};
    std::vector<double> xy = square;
    xy.insert(xy.end(), {0.2, 0.2, 0.4, 0.2, nan, 0.4});
    expect_error(xy, {4, 7}, "ring 1 vertex 2: a coordinate is not finite");
    xy = square;
    xy[1] = inf;
    expect_error(xy, {4}, "ring 0 vertex 0: a coordinate is not finite");
    // Two distinct vertices, the closing one repeated: 4 given.
    expect_error({0, 0, 1, 1, 1, 1, 0, 0}, {4}, "ring 0: 2 distinct vertices (4 given); a ring needs 3");
    expect_error({0, 0, 1, 1, 2, 2, 3, 3}, {4}, "ring 0: its vertices lie on one line, it encloses nothing");
    ck_assert(error_of(square, {4, 2}).find("ring 1: its end 2 is before its start 4") == 0);
    expect_error(square, {}, "the outline has no rings");
}
END_TEST

START_TEST(cleaning_drops_repeats_keeps_collinear_runs) {
    // Closing vertex repeated, a vertex doubled, a collinear run on the bottom side.
    const std::vector<double> xy{0, 0, 0.5, 0, 1, 0, 1, 0, 1, 1, 0, 1, 0, 0};
    const std::size_t ends[] = {7};
    const PolygonRings rings(xy.data(), ends, 1);
    ck_assert_uint_eq(rings.rings(), 1);
    ck_assert_uint_eq(rings.vertices(), 5);
    ck_assert_double_eq(rings.perimeter(), 4.0);
    ck_assert_double_eq(rings.bounds().x1, 1.0);
    const PolygonIndex index(rings);
    ck_assert_int_eq(index.locate(Point{0.5, 0.0}), PolygonIndex::kOnOutline);
    ck_assert_int_eq(index.locate(Point{0.5, 0.5}), PolygonIndex::kInside);
    ck_assert_int_eq(index.locate(Point{0.5, std::nextafter(0.0, -1.0)}), PolygonIndex::kOutside);
    ck_assert_int_eq(index.locate(Point{std::nextafter(1.0, 2.0), 0.5}), PolygonIndex::kOutside);
}
END_TEST

START_TEST(stars_with_holes_both_orientations) {
    for (bool reversed : {false, true}) {
        LatticeOutline o;
        o.rings.push_back(star(40, 300, 1000, reversed));
        o.rings.push_back(star(7, 60, 200, !reversed));       // a hole
        o.rings.push_back(star(5, 20, 50, reversed, 10, 0));  // an island inside the hole
        check_against_brute_force(o, 1100, test_light() ? 2000 : 10000);
    }
}
END_TEST

START_TEST(touching_holes_spikes_and_collinear_runs) {
    LatticeOutline o;
    // An outer square with a collinear run along the bottom, a hole touching
    // it at (0, 50) and (50, 0)'s neighbourhood at a vertex, and a spike one
    // unit wide (far narrower than any cell).
    o.rings.push_back({-100, -100, -50, -100, 0, -100, 50, -100, 100, -100, 100, 100, 1, 100, 0, 400, -1, 100, -100, 100});
    o.rings.push_back({-100, 0, -40, 20, -40, -20});      // a hole touching the outer ring at (-100, 0)
    o.rings.push_back({0, 0, 30, 0, 30, 30, 0, 30});      // a hole
    o.rings.push_back({30, 30, 60, 30, 60, 60});          // a hole touching the last at a vertex
    check_against_brute_force(o, 420, test_light() ? 2000 : 10000);
}
END_TEST

START_TEST(far_from_the_origin_and_tiny) {
    LatticeOutline o;
    o.rings.push_back(star(16, 500, 1000, false));
    o.rings.push_back(star(6, 100, 300, false));
    o.scale = 0x1p-30;  // about 1e-6 wide
    o.offset = 1000.0;  // a thousand away: still exact (40 bits)
    check_against_brute_force(o, 1100, test_light() ? 2000 : 10000);
}
END_TEST

START_TEST(outline_of_many_vertices) {
    LatticeOutline o;
    const int spikes = test_light() ? 5000 : 50000;  // 10^5 vertices
    o.rings.push_back(star(spikes, 9000000, 10000000, false));
    o.rings.push_back(star(spikes / 10, 1000000, 3000000, true));
    const PolygonRings rings = o.build();
    const PolygonIndex index(rings);
    ck_assert_uint_ge(index.columns() * index.rows(), 4 * rings.vertices() / 2);
    // Most clean cells are settled; a few hundred probes against the brute force.
    check_against_brute_force(o, 10000000, test_light() ? 100 : 400);
}
END_TEST

// More than a third of the index's cells are clean, and every half-integer
// point of [-m, m]^2 (a lattice of the given step) in a clean cell has the
// cell's place; returns how many points were checked.
std::size_t check_clean_cells(const LatticeOutline& o, const PolygonRings& rings, const PolygonIndex& index,
                              std::int64_t m, std::int64_t step) {
    std::size_t clean = 0;
    for (std::size_t r = 0; r < index.rows(); ++r)
        for (std::size_t c = 0; c < index.columns(); ++c) clean += index.cell_place(c, r) != PolygonIndex::kOnOutline;
    ck_assert_msg(clean > index.rows() * index.columns() / 3, "%zu clean cells of %zu x %zu", clean, index.columns(),
                  index.rows());
    std::size_t checked = 0;
    for (std::int64_t y2 = -2 * m; y2 <= 2 * m; y2 += step)
        for (std::int64_t x2 = -2 * m; x2 <= 2 * m; x2 += step) {
            const Point p = o.place(x2, y2);
            if (!rings.bounds().contains(p)) continue;
            const PolygonIndex::Place place = index.cell_place(index.column_of(p.x), index.row_of(p.y));
            if (place == PolygonIndex::kOnOutline) continue;
            ck_assert_msg(o.brute_place(x2, y2) == place, "(%g, %g) in a clean cell of place %d", p.x, p.y, place);
            ++checked;
        }
    return checked;
}

// A comb on [-m, m]^2: a base, and `teeth` teeth of the given width, their
// gaps the rest of each period.
std::vector<std::int64_t> comb(int teeth, std::int64_t m, std::int64_t width) {
    const std::int64_t period = 2 * m / teeth, base = -m + m / 10;
    std::vector<std::int64_t> r = {-m, -m, m, -m, m, base};
    for (int i = teeth - 1; i >= 0; --i) {
        const std::int64_t left = -m + i * period, right = left + width;
        r.insert(r.end(), {right, base, right, m, left, m});
        if (i > 0) r.insert(r.end(), {left, base});
    }
    return r;
}

START_TEST(clean_cells_hold_their_points_place) {
    LatticeOutline o;
    o.rings.push_back(star(12, 400, 1000, false));
    o.rings.push_back(star(5, 50, 150, true));
    const PolygonRings rings = o.build();
    const PolygonIndex index(rings);
    ck_assert_uint_gt(check_clean_cells(o, rings, index, 1000, 7), 20000);
    // Cheap to locate in: no finer index.
    ck_assert_msg(index.finer_cells_for_location() == 0.0, "edges read %g", index.expected_edges_read());
}
END_TEST

// An outline crowded enough that its default index gets a finer one for
// locating, with more than 0 and at least `at_least` times its cells.
struct CrowdedOutline {
    PolygonRings rings;
    PolygonIndex index;
    double finer;
    PolygonIndex locator;

    CrowdedOutline(const LatticeOutline& o, double at_least, const char* what)
        : rings(o.build()), index(rings), finer(index.finer_cells_for_location()), locator(rings, finer) {
        const double cells = static_cast<double>(index.rows() * index.columns());
        ck_assert_msg(finer > 0.0 && finer >= at_least * cells,
                      "%s: finer index of %g cells, the default has %zu x %zu; edges read %g", what, finer,
                      index.columns(), index.rows(), index.expected_edges_read());
    }
};

START_TEST(a_comb_is_located_by_a_finer_index) {
    // 64 teeth, 1/64 of the width apart, each 0.3 of that: every cell of the
    // default index holds a tooth, and a row's ray meets 128 edges.
    LatticeOutline o;
    o.rings.push_back(comb(64, 6400, 60));
    const CrowdedOutline c(o, 16.0, "comb");
    // Locating reads far fewer edges there.
    ck_assert_msg(c.locator.expected_edges_read() < 0.25 * c.index.expected_edges_read(),
                  "edges read: %g with the finer index, %g without", c.locator.expected_edges_read(),
                  c.index.expected_edges_read());
    // Its clean cells, settled from their left neighbours through the teeth.
    ck_assert_uint_gt(check_clean_cells(o, c.rings, c.locator, 6400, test_light() ? 149 : 37),
                      test_light() ? 1000 : 20000);
    // And points anywhere, on the teeth's edges and corners included.
    check_against_brute_force(o, 6400, test_light() ? 2000 : 20000, c.finer);
    check_against_brute_force(o, 6400, test_light() ? 500 : 2000);
}
END_TEST

// A zig-zag band on [-m, m]^2 with `teeth` random teeth: its lower side
// runs left to right between two heights, its upper side back at a random
// thickness above; then turned by quarter turns (exact on the lattice).
std::vector<std::int64_t> zigzag(pds::Rng& rng, int teeth, std::int64_t m, int quarter_turns) {
    const auto draw = [&](std::int64_t lo, std::int64_t hi) {
        return lo + static_cast<std::int64_t>(rng.next_double() * static_cast<double>(hi - lo));
    };
    const std::int64_t low = draw(-m, -m / 2), high = draw(m / 2, m - m / 8), thick = draw(m / 200 + 1, m / 20);
    std::vector<std::int64_t> xs;
    for (int i = 0; i <= 2 * teeth; ++i) xs.push_back(-m + (2 * m * i) / (2 * teeth));
    std::vector<std::int64_t> r;
    for (std::size_t i = 0; i < xs.size(); ++i) r.insert(r.end(), {xs[i], i % 2 ? high : low});
    for (std::size_t i = xs.size(); i-- > 0;) r.insert(r.end(), {xs[i], (i % 2 ? high : low) + thick});
    for (int t = 0; t < quarter_turns; ++t)
        for (std::size_t k = 0; k < r.size(); k += 2) {
            const std::int64_t x = r[k], y = r[k + 1];
            r[k] = -y;
            r[k + 1] = x;
        }
    return r;
}

START_TEST(random_zigzags_are_located_alike_by_both_indexes) {
    // Thin bands of many teeth, some with a hole or a ring traced twice
    // nowhere near, in four orientations: each must be crowded enough for
    // a finer index, and both indexes must agree with the brute force.
    pds::Rng rng(41);
    const int shapes = test_light() ? 2 : 16;
    for (int k = 0; k < shapes; ++k) {
        LatticeOutline o;
        o.rings.push_back(zigzag(rng, 20 + static_cast<int>(rng.next_double() * 100.0), 5000, k % 4));
        if (k % 3 == 1) o.rings.push_back(star(6, 40, 90, k % 2 == 0, 0, 4000));  // an island
        const std::string what = "zig-zag " + std::to_string(k);
        const CrowdedOutline c(o, 0.0, what.c_str());
        ck_assert_msg(c.locator.expected_edges_read() < c.index.expected_edges_read(), "%s: edges read %g, %g",
                      what.c_str(), c.locator.expected_edges_read(), c.index.expected_edges_read());
        check_against_brute_force(o, 5000, 3000, c.finer);  // a thin band: enough probes to land inside
    }
}
END_TEST

START_TEST(a_ring_of_spikes_is_located_by_a_finer_index) {
    // 500 spikes between radii 0.84 and 1: near the rim every cell of the
    // default index is cut by a few of them.
    LatticeOutline o;
    o.rings.push_back(star(500, 8400, 10000, false));
    o.rings.push_back(star(7, 600, 2000, true));
    const CrowdedOutline c(o, 0.0, "spikes");
    ck_assert_uint_gt(check_clean_cells(o, c.rings, c.locator, 10000, test_light() ? 211 : 53),
                      test_light() ? 1000 : 20000);
    check_against_brute_force(o, 10000, test_light() ? 2000 : 20000, c.finer);
}
END_TEST

START_TEST(grid_cells_not_outside_count_as_cell_by_cell) {
    // Another grid's cells that meet a cell of the index not outside,
    // counted by runs of rows and columns, against asking all_cells cell by
    // cell: grids finer and coarser than the index, shifted, wider than the
    // outline's box, and one row or column thick. A run that merged rows
    // meeting different index rows, or a count off by one at a run's end,
    // differs.
    LatticeOutline o;
    o.rings.push_back(star(12, 400, 1000, false));
    o.rings.push_back(star(5, 50, 150, true));
    const PolygonRings rings = o.build();
    const PolygonIndex index(rings);
    struct Grid {
        double x0, sx;
        std::size_t cols;
        double y0, sy;
        std::size_t rows;
    };
    const Grid grids[] = {{-1000, 7.3, 274, -1000, 6.9, 290},  {-1000, 400, 5, -1000, 333, 7},
                          {-1200, 13.1, 190, -900, 4.7, 380},  {-1000, 2000, 1, -1000, 1.1, 1800},
                          {-977.5, 0.9, 2170, -15, 30, 1},     {-1000, 25, 80, -1000, 25, 80}};
    std::size_t total = 0, cells = 0;
    for (const Grid& g : grids) {
        std::size_t want = 0;
        for (std::size_t j = 0; j < g.rows; ++j)
            for (std::size_t i = 0; i < g.cols; ++i) {
                const double x = static_cast<double>(i), y = static_cast<double>(j);
                const pds::Box cell{g.x0 + x * g.sx, g.y0 + y * g.sy, g.x0 + (x + 1.0) * g.sx, g.y0 + (y + 1.0) * g.sy};
                want += !index.all_cells(cell, PolygonIndex::kOutside);
            }
        const std::size_t got = index.grid_cells_not_outside(g.x0, g.sx, g.cols, g.y0, g.sy, g.rows);
        ck_assert_msg(got == want, "grid %zu x %zu at (%g, %g): %zu cells, cell by cell %zu", g.cols, g.rows, g.x0,
                      g.y0, got, want);
        total += want;
        cells += g.cols * g.rows;
    }
    ck_assert_uint_gt(total, 50000);
    ck_assert_uint_lt(total, cells * 9 / 10);  // outside cells too
}
END_TEST

}  // namespace

Suite* polygon_suite() {
    Suite* s = suite_create("polygon");
    TCase* t = tcase_create("outline");
    tcase_add_test(t, refuses_with_ring_and_vertex_named);
    tcase_add_test(t, cleaning_drops_repeats_keeps_collinear_runs);
    tcase_add_test(t, stars_with_holes_both_orientations);
    tcase_add_test(t, touching_holes_spikes_and_collinear_runs);
    tcase_add_test(t, far_from_the_origin_and_tiny);
    tcase_add_test(t, outline_of_many_vertices);
    tcase_add_test(t, clean_cells_hold_their_points_place);
    tcase_add_test(t, a_comb_is_located_by_a_finer_index);
    tcase_add_test(t, a_ring_of_spikes_is_located_by_a_finer_index);
    tcase_add_test(t, random_zigzags_are_located_alike_by_both_indexes);
    tcase_add_test(t, grid_cells_not_outside_count_as_cell_by_cell);
    suite_add_tcase(s, t);
    return s;
}
