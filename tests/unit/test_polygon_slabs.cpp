// test_polygon_slabs.cpp - uniform points of a polygon by its vertical slabs
// (PolygonSlabs), against the polygon's area and against the rejection
// sampler over its outline grid's cells, which is uniform by construction;
// and the first point of a polygon far thinner than those cells, which
// rejection alone would take about 10^11 tries to find.
#include <check.h>

#include <cmath>
#include <vector>

#include "binned_chi2.hpp"
#include "core/rng.hpp"
#include "domain/polygon.hpp"
#include "domain/polygon_slabs.hpp"
#include "polygon_rings.hpp"
#include "suites.hpp"

namespace {

using pds::Point;
using pds::Polygon;

// A 12 x 12 histogram of points over the box.
std::vector<double> binned(const std::vector<Point>& points, const pds::Box& box) {
    std::vector<double> bins(144, 0.0);
    for (const Point& p : points) {
        const int i = std::min(11, static_cast<int>((p.x - box.x0) / box.width() * 12.0));
        const int j = std::min(11, static_cast<int>((p.y - box.y0) / box.height() * 12.0));
        bins[static_cast<std::size_t>(12 * j + i)] += 1.0;
    }
    return bins;
}

}  // namespace

START_TEST(slabs_hold_the_area_and_draw_as_rejection_does) {
    // An L, a bow tie (its edges cross, split at the crossing), a square with
    // a slanted hole, and a star of 7 spikes.
    std::vector<double> star;
    for (int k = 0; k < 14; ++k) {
        const double a = M_PI * k / 7.0, r = k % 2 ? 0.3 : 1.0;
        star.push_back(r * std::cos(a));
        star.push_back(r * std::sin(a));
    }
    const Polygon shapes[] = {
        rings_of({{0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2}}),
        rings_of({{0, 0, 2, 1, 2, 0, 0, 1}}),
        rings_of({{0, 0, 4, 0, 4, 4, 0, 4}, {1, 1, 3, 1.5, 2.5, 3}}),
        rings_of({star}),
    };
    const int n = test_light() ? 8000 : 60000;
    for (const Polygon& shape : shapes) {
        const pds::PolygonSlabs slabs(shape.rings());
        ck_assert_msg(std::fabs(slabs.area() - shape.area()) <= 1e-12 * shape.area(),
                      "slabs' area %.17g, the "
                      "polygon's %.17g",
                      slabs.area(), shape.area());
        pds::Rng rng(3), reference(4);
        std::vector<Point> drawn, rejected;
        int outside = 0;
        while (drawn.size() < static_cast<std::size_t>(n)) {
            Point p;
            ck_assert(slabs.draw(rng, &p));
            if (shape.contains(p))
                drawn.push_back(p);
            else
                ++outside;
        }
        for (int i = 0; i < n; ++i) rejected.push_back(shape.uniform_point(reference));
        ck_assert_msg(outside <= n / 1000, "%d of %d slab draws outside the polygon", outside, n);
        const BinnedChi2 c = binned_chi2(binned(drawn, shape.bounds()), binned(rejected, shape.bounds()));
        const double excess = (c.chi2 - c.dof) / std::sqrt(2.0 * c.dof);
        ck_assert_msg(excess < 5.0, "slab draws against rejection: chi-square %.1f on %d dof", c.chi2, c.dof);
    }
}
END_TEST

START_TEST(a_strip_far_thinner_than_its_cells_gets_uniform_points) {
    // A strip 1e-12 high along the diagonal of the unit square: the outline
    // grid's cells near it are 10^10 times its area. Its points must come at
    // once, inside, and spread evenly along it.
    const double w = 1e-12;
    const Polygon strip = rings_of({{0, 0, 1, 1, 1, 1 + w, 0, w}});
    const int n = test_light() ? 60 : 400;
    std::vector<int> tenth(10, 0);
    pds::Rng rng(9);
    for (int i = 0; i < n; ++i) {
        const Point p = strip.uniform_point(rng);
        ck_assert_msg(strip.contains(p), "(%.17g, %.17g) outside the strip", p.x, p.y);
        ++tenth[std::min(9, static_cast<int>(p.x * 10.0))];
    }
    double chi2 = 0.0;
    for (int t : tenth) chi2 += (t - n / 10.0) * (t - n / 10.0) / (n / 10.0);
    ck_assert_msg(chi2 < 9.0 + 5.0 * std::sqrt(18.0), "points along the strip by tenths: chi-square %.1f on 9 dof",
                  chi2);
}
END_TEST

Suite* polygon_slabs_suite() {
    Suite* s = suite_create("polygon_slabs");
    TCase* t = tcase_create("slabs");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, slabs_hold_the_area_and_draw_as_rejection_does);
    tcase_add_test(t, a_strip_far_thinner_than_its_cells_gets_uniform_points);
    suite_add_tcase(s, t);
    return s;
}
