// test_free_area.cpp - one cell's free region: area against a brute-force
// polar integration, float classification against the exact classifier, the
// paper's cases 1-4, and uniformity of the points drawn in one free region.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "cells/cell_coverage.hpp"
#include "binned_chi2.hpp"
#include "cell_oracle.hpp"
#include "cells/free_area.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

std::vector<pds::Point> real_points(const pds::Sampler& s) {
    const auto& all = s.jones().mesh().points();
    return std::vector<pds::Point>(all.begin() + pds::Delaunay::kGhosts, all.end());
}

double measured_area(const pds::Sampler& s, std::size_t site) {
    const std::vector<pds::Point> ring = s.jones().cells().ring_points(pds::vertex_of(site));
    return pds::measure_cell(s.jones().cells().query(pds::vertex_of(site)), [&](const auto& visit) {
               for (const pds::Point& p : ring) visit(p, 0.0);
           }).area;
}

}  // namespace

START_TEST(area_matches_integration) {
    // Partial patterns (so cells are large and irregular), square and thin
    // domains; every cell compared with the brute-force integral.
    struct Case {
        pds::Box box;
        double r;
        std::size_t points;
    };
    const Case cases[] = {{{0, 0, 1, 1}, 0.05, 1},   {{0, 0, 1, 1}, 0.05, 2},
                          {{0, 0, 1, 1}, 0.05, 40},  {{0, 0, 1, 1}, 0.03, 300},
                          {{0, 0, 4, 0.5}, 0.07, 80}, {{-3, 2, -1, 5}, 0.2, 60}};
    // The midpoint rule's error falls as 1/steps^2; the tolerance follows it.
    const int steps = test_light() ? 10000 : 40000;
    const double tolerance = 2e-5 * (40000.0 / steps) * (40000.0 / steps);
    for (const Case& cs : cases) {
        pds::Sampler s(cs.r, 21);
        s.set_domain(cs.box);
        s.skip_dart_stage();  // partial patterns: the Jones loop from the start keeps a mesh
        bool maximal = false;
        s.add_points(cs.points, &maximal);
        ck_assert_uint_eq(real_points(s).size(), cs.points);
        const std::vector<pds::Point> pts = real_points(s);
        const double r_int = s.frame().r();
        const pds::Box& box = s.frame().box();
        double total = 0;
        for (std::size_t i = 0; i < pts.size(); i += (test_light() ? 7 : 1)) {
            const double got = measured_area(s, i);
            const double want = free_area_by_integration(pts[i], pts, box, r_int, steps);
            ck_assert_double_le(std::fabs(got - want), tolerance * (want + r_int * r_int));
            total += got;
        }
        (void)total;
    }
}
END_TEST

START_TEST(pieces_cover_the_cases) {
    // Fan triangle (0, a, b) with R = 1: the piece areas must add up to the
    // triangle's area minus its intersection with the unit disk, computed here
    // by fine integration over the triangle.
    struct Tri {
        pds::Point a, b;
        int pieces;
    };
    const Tri tris[] = {
        {{2, -1}, {2, 1}, 2},        // case 3: closest approach inside the side
        {{0.5, -0.2}, {2, 1}, 1},    // case 1: one end inside the circle
        {{1.5, -2}, {0.2, 1.5}, 2},  // case 2: the side cuts the circle twice
        {{1.2, 0.1}, {1.5, 1.0}, 1}, // case 4 already
        {{3, 0}, {-3, 0.1}, 2},      // angle beyond 90 degrees
    };
    for (const Tri& t : tris) {
        pds::Piece pieces[2];
        const int n = pds::split_fan_triangle(t.a, t.b, 1.0, pieces);
        ck_assert_int_eq(n, t.pieces);
        double area = 0;
        for (int i = 0; i < n; ++i) area += pds::piece_area(pieces[i], 1.0);
        // Reference: the triangle's area outside the disk, by a fine grid.
        const int g = test_light() ? 600 : 2000;
        double minx = std::min({0.0, t.a.x, t.b.x}), maxx = std::max({0.0, t.a.x, t.b.x});
        double miny = std::min({0.0, t.a.y, t.b.y}), maxy = std::max({0.0, t.a.y, t.b.y});
        const double hx = (maxx - minx) / g, hy = (maxy - miny) / g;
        long count = 0;
        for (int i = 0; i < g; ++i) {
            for (int j = 0; j < g; ++j) {
                const double x = minx + (i + 0.5) * hx, y = miny + (j + 0.5) * hy;
                const double c1 = t.a.x * y - t.a.y * x, c2 = (t.b.x - t.a.x) * (y - t.a.y) - (t.b.y - t.a.y) * (x - t.a.x),
                             c3 = -(t.b.x * y - t.b.y * x);
                if (c1 >= 0 && c2 >= 0 && c3 >= 0 && x * x + y * y >= 1) ++count;
            }
        }
        const double want = static_cast<double>(count) * hx * hy;
        ck_assert_double_le(std::fabs(area - want), 4e-3 * want + 10 * hx * hy * g * 0.01);
    }
}
END_TEST

START_TEST(float_classification_is_certified) {
    // For every cell of partial and maximal patterns: when the float pass says
    // covered, the exact classifier agrees; when it says free (not doubtful),
    // the exact classifier agrees too.
    const int seeds = test_light() ? 2 : 8;
    for (int seed = 1; seed <= seeds; ++seed) {
        for (std::size_t stop : {std::size_t{50}, std::size_t{400}, std::size_t{0}}) {
            pds::Sampler s(0.04, static_cast<std::uint64_t>(seed));
            if (seed % 2 == 0) s.set_domain(pds::Box{0, 0, 2, 0.7});
            // Partial patterns need the mesh from the start; maximal ones
            // come from the dart stage handing over to the Jones loop.
            if (stop != 0) s.skip_dart_stage();
            bool maximal = false;
            s.add_points(stop, &maximal);
            for (std::size_t i = 0; i < s.count(); ++i) {
                const std::vector<pds::Point> ring = s.jones().cells().ring_points(pds::vertex_of(i));
                const pds::CellMeasure m = pds::measure_cell(s.jones().cells().query(pds::vertex_of(i)), [&](const auto& visit) {
                    for (const pds::Point& p : ring) visit(p, 0.0);
                });
                if (m.doubtful) continue;
                const bool exact = pds::cell_is_covered_exact(s.jones().cells().query(pds::vertex_of(i)).site, ring,
                                                              s.frame().box(), s.frame().r());
                ck_assert_int_eq(exact, m.area == 0.0);
            }
            if (stop == 0) ck_assert(maximal);
        }
    }
}
END_TEST

START_TEST(exact_classifier_on_known_cells) {
    // One site at the centre of the unit square with four neighbours on the
    // axes at distance 2a: its cell is the square [0.5-a, 0.5+a]^2, whose corner
    // lies at a*sqrt(2). Covered iff R >= a*sqrt(2) (here a = 0.125).
    const pds::Point c{0.5, 0.5};
    const std::vector<pds::Point> ring = {{0.75, 0.5}, {0.5, 0.75}, {0.25, 0.5}, {0.5, 0.25}};
    const pds::Box box{0, 0, 1, 1};
    const double corner = std::sqrt(2.0) * 0.125;
    ck_assert(pds::cell_is_covered_exact(c, ring, box, std::nextafter(corner, 1.0)));
    ck_assert(!pds::cell_is_covered_exact(c, ring, box, std::nextafter(corner, 0.0)));
    // Clipped by the domain: a site near the left side, neighbours far away on
    // the right. Its cell reaches the corners (0,0) and (0,1).
    const pds::Point d{0.1, 0.5};
    const std::vector<pds::Point> ring2 = {{0.9, 0.5}, {-30, 30}, {-30, -30}};
    const double far = std::hypot(0.1, 0.5);  // to the corners
    ck_assert(!pds::cell_is_covered_exact(d, ring2, box, far * 0.999));
    ck_assert(pds::cell_is_covered_exact(d, ring2, box, std::hypot(0.4, 0.5) * 1.0001));
}
END_TEST

namespace {

// Compares the sampler's draws in one cell (select_in_cell at target u * A,
// then sample_chunk) with plain rejection sampling of
// the same free region (uniform in a square around the site, kept when in the
// cell and at least R from it), bin by bin over the region's bounding box.
// Adds the chi-square statistic and its degrees of freedom to *chi2, *dof.
void add_uniformity_chi2(const pds::Sampler& s, std::size_t site, int n, std::uint64_t seed,
                         double* total_chi2, int* total_dof) {
    const std::vector<pds::Point> pts = real_points(s);
    const pds::Point c = pts[site];
    const std::vector<pds::Point> ring = s.jones().cells().ring_points(pds::vertex_of(site));
    const pds::CellQuery q = s.jones().cells().query(pds::vertex_of(site));
    const auto ring_fn = [&](const auto& visit) {
        for (const pds::Point& p : ring) visit(p, 0.0);
    };
    const pds::Box& box = s.frame().box();
    const double r = q.radius;
    const auto accept = [&](const pds::Point& p) { return box.contains(p) && in_free_region_of(p, c, pts, r); };
    double reach = 0;
    for (int i = 0; i < 1440; ++i) {
        const double phi = i * 3.14159265358979 / 720;
        reach = std::max(reach, cell_reach(c, std::cos(phi), std::sin(phi), pts, box));
    }
    std::mt19937_64 ref(seed);
    std::uniform_real_distribution<double> u(-reach, reach);
    std::vector<pds::Point> want;
    while (static_cast<int>(want.size()) < n) {
        const pds::Point p{c.x + u(ref), c.y + u(ref)};
        if (accept(p)) want.push_back(p);
    }
    pds::Rng rng(seed + 1);
    const double area = s.jones().cells().measure(pds::vertex_of(site)).area;
    std::vector<pds::Point> got;
    while (static_cast<int>(got.size()) < n) {
        const pds::CellSelection sel = pds::select_in_cell(q, ring_fn, rng.next_double() * area);
        ck_assert(sel.found());
        pds::Point p;
        if (pds::sample_chunk(q, sel.chunk(), rng.next_double(), rng, accept, 64, &p) ==
            pds::SampleOutcome::placed) {
            ck_assert(accept(p));
            got.push_back(p);
        }
    }
    // Bins by angle around the site: the free region's pieces are angular
    // sectors, so a piece drawn too often or too rarely shows up directly.
    const int bins = 72;
    const auto bin = [&](const pds::Point& p) {
        const double a = std::atan2(p.y - c.y, p.x - c.x) + 3.14159265358979323846;
        return std::min(bins - 1, static_cast<int>(a / (2 * 3.14159265358979323846) * bins));
    };
    std::vector<double> a(bins, 0), b(bins, 0);
    for (const pds::Point& p : got) ++a[bin(p)];
    for (const pds::Point& p : want) ++b[bin(p)];
    const BinnedChi2 test = binned_chi2(a, b);
    const double chi2 = test.chi2;
    const int dof = test.dof;
    ck_assert_int_gt(dof, 4);
    // One cell alone must not be wildly off either.
    ck_assert_msg(chi2 - dof < 7 * std::sqrt(2.0 * dof), "cell %zu: chi-square %.1f on %d dof", site, chi2, dof);
    *total_chi2 += chi2;
    *total_dof += dof;
}

}  // namespace

START_TEST(draws_are_uniform_in_free_regions) {
    // Early cells (large, far from covered), middle and late ones (thin free
    // regions next to the circle, where the quadrilaterals reject up to half
    // the draws): drawn points must be uniform in all. The chi-squares are
    // pooled: drawing a piece again after a rejection elsewhere (instead of
    // retrying in the same piece) skews pieces by their acceptance rate, which
    // this pooled test sees at about 14 standard deviations.
    const int n = test_light() ? 8000 : 60000;
    double chi2 = 0;
    int dof = 0;
    for (std::size_t stop : {std::size_t{12}, std::size_t{250}, std::size_t{520}}) {
        pds::Sampler s(stop == 12 ? 0.12 : 0.03, 33);
        s.skip_dart_stage();
        bool maximal = false;
        s.add_points(stop, &maximal);
        ck_assert(!maximal);
        // The cells with the largest free areas.
        std::vector<double> area(s.count());
        std::vector<std::size_t> order(s.count());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i, area[i] = s.jones().cells().measure(pds::vertex_of(i)).area;
        std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return area[x] > area[y]; });
        const int cells = test_light() ? 1 : 4;
        for (int k = 0; k < cells; ++k) {
            ck_assert_double_gt(area[order[k]], 0.0);
            add_uniformity_chi2(s, order[k], n, 500 + static_cast<std::uint64_t>(k), &chi2, &dof);
        }
    }
    const double excess = (chi2 - dof) / std::sqrt(2.0 * dof);
    ck_assert_msg(excess < 5.0, "pooled chi-square %.1f on %d dof (%.1f sd above the mean)", chi2, dof, excess);
}
END_TEST

START_TEST(short_sides_keep_their_area) {
    // Fan triangles whose far side is so short that its squared length
    // underflows (the cells of a domain far thinner than R), with R = 1: the
    // pieces must hold the triangle minus its sector, 0.5 (cross - angle).
    for (const double len : {1e-150, 1e-200, 1e-300}) {
        struct Tri {
            pds::Point a, b;
            int pieces;
        };
        const Tri tris[] = {
            {{len, 2}, {0, 2}, 0},                 // ends at the closest approach (1 or 2 pieces)
            {{2, -0.5 * len}, {2, 0.5 * len}, 2},  // case 3: the closest approach inside the side
            {{-3, len}, {-3, 0}, 0},
            {{2 * len, 1.5}, {len, 1.5}, 1},       // the closest approach lies beyond the side
        };
        for (const Tri& t : tris) {
            pds::Piece pieces[2];
            const int n = pds::split_fan_triangle(t.a, t.b, 1.0, pieces);
            ck_assert(t.pieces == 0 ? n == 1 || n == 2 : n == t.pieces);
            double area = 0;
            for (int i = 0; i < n; ++i) area += pds::piece_area(pieces[i], 1.0);
            const double cr = pds::cross(t.a, t.b);
            const double want = 0.5 * (cr - std::atan2(cr, pds::dot(t.a, t.b)));
            ck_assert_msg(std::fabs(area - want) <= 1e-12 * want, "side %g from (%g, %g): pieces' area %.17g, want %.17g",
                          len, t.a.x, t.a.y, area, want);
        }
    }
    // The least weight of a possibly-free cell: 2^-100 of R^2, or of the
    // cell's own area when that is smaller.
    ck_assert(pds::area_floor(0.01, 1.0) == 1e-4 * 0x1.0p-100);
    ck_assert(pds::area_floor(0.01, 1e-240) == 1e-240 * 0x1.0p-100);
    ck_assert(pds::area_floor(0.01, 0.0) > 0.0);
}
END_TEST

Suite* free_area_suite() {
    Suite* s = suite_create("free_area");
    TCase* t = tcase_create("area");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, area_matches_integration);
    tcase_add_test(t, pieces_cover_the_cases);
    tcase_add_test(t, short_sides_keep_their_area);
    suite_add_tcase(s, t);
    t = tcase_create("classification");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, float_classification_is_certified);
    tcase_add_test(t, exact_classifier_on_known_cells);
    suite_add_tcase(s, t);
    t = tcase_create("uniformity");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, draws_are_uniform_in_free_regions);
    suite_add_tcase(s, t);
    return s;
}
