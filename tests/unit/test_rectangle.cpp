// test_rectangle.cpp - the rectangle as the sampler's domain type: the
// closed region it contains, its measures and count bound, a uniform point,
// exact scaling by powers of two.
#include <check.h>

#include <cmath>

#include "core/rng.hpp"
#include "domain/rectangle.hpp"
#include "mesh/delaunay.hpp"
#include "suites.hpp"

namespace {

const pds::Rectangle kDomain(pds::Box{-1.5, 0.25, 2.0, 1.0});

START_TEST(contains_its_closed_boundary_only) {
    ck_assert(kDomain.contains(pds::Point{-1.5, 0.25}));
    ck_assert(kDomain.contains(pds::Point{2.0, 1.0}));
    ck_assert(kDomain.contains(pds::Point{0.0, 0.5}));
    ck_assert(!kDomain.contains(pds::Point{std::nextafter(-1.5, -2.0), 0.5}));
    ck_assert(!kDomain.contains(pds::Point{0.0, std::nextafter(1.0, 2.0)}));
}
END_TEST

START_TEST(measures_and_count_bound) {
    ck_assert_double_eq(kDomain.area(), 3.5 * 0.75);
    ck_assert_double_eq(kDomain.perimeter(), 2.0 * (3.5 + 0.75));
    ck_assert_double_eq(kDomain.diameter(), std::sqrt(3.5 * 3.5 + 0.75 * 0.75));
    // Oler's bound holds a hexagonal packing of the rectangle (rows sqrt(3)/2 r
    // apart, points r apart along each, offset by r/2 every other row).
    for (double r : {0.05, 0.1, 0.3}) {
        const pds::Box& b = kDomain.bounds();
        std::size_t packed = 0;
        int row = 0;
        for (double y = b.y0; y <= b.y1; y += std::sqrt(3.0) / 2.0 * r, ++row)
            for (double x = b.x0 + (row % 2 ? r / 2 : 0.0); x <= b.x1; x += r) ++packed;
        ck_assert_msg(static_cast<double>(packed) <= kDomain.count_bound(r), "r=%g: %zu points > bound %g", r, packed,
                      kDomain.count_bound(r));
        ck_assert(kDomain.count_bound(r) < 1.2 * static_cast<double>(packed) + 2.0 * kDomain.perimeter() / r);
    }
}
END_TEST

START_TEST(uniform_point_inside_and_spread) {
    pds::Rng rng(5);
    int left = 0, low = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const pds::Point p = kDomain.uniform_point(rng);
        ck_assert(kDomain.contains(p));
        if (p.x < 0.25) ++left;   // the left half in x
        if (p.y < 0.625) ++low;   // the lower half in y
    }
    // Binomial(n, 1/2): 5 standard deviations is about 350.
    ck_assert_int_lt(std::abs(2 * left - n), 700);
    ck_assert_int_lt(std::abs(2 * low - n), 700);
}
END_TEST

START_TEST(scaling_is_exact) {
    const pds::Rectangle up = kDomain.scaled(3), back = up.scaled(-3);
    ck_assert_double_eq(up.bounds().x0, -12.0);
    ck_assert_double_eq(up.bounds().y1, 8.0);
    ck_assert_double_eq(up.area(), kDomain.area() * 64.0);
    ck_assert(back.bounds().x0 == kDomain.bounds().x0 && back.bounds().y0 == kDomain.bounds().y0 &&
              back.bounds().x1 == kDomain.bounds().x1 && back.bounds().y1 == kDomain.bounds().y1);
    ck_assert_double_eq(kDomain.largest_magnitude(), 2.0);
}
END_TEST

// The four points (0.25 or 0.75, y0 or y1) in the unit square, meshed.
pds::Delaunay four_points(double y0, double y1) {
    pds::Delaunay dt(pds::Box{0.0, 0.0, 1.0, 1.0});
    dt.reserve(8);
    pds::VertexIndex near = 0;
    for (double y : {y0, y1})
        for (double x : {0.25, 0.75}) near = dt.insert(pds::Point{x, y}, near);
    return dt;
}

START_TEST(boundary_certificate_names_the_uncovered_side) {
    const pds::Rectangle unit(pds::Box{0.0, 0.0, 1.0, 1.0});
    // Symmetric: the corners are 0.3536 from their nearest point.
    const pds::Delaunay even = four_points(0.25, 0.75);
    ck_assert_ptr_null(unit.uncovered_side(even, 0.36));
    ck_assert_str_eq(unit.uncovered_side(even, 0.35), "bottom");
    // Shifted down: the bottom corners are 0.32 away, the top ones 0.39.
    const pds::Delaunay low = four_points(0.2, 0.7);
    ck_assert_str_eq(unit.uncovered_side(low, 0.36), "top");
    ck_assert_ptr_null(unit.uncovered_side(low, 0.4));
    // Exact at the boundary: the corners lie exactly 0.625 from (0.5, 0.5)
    // (0.375^2 + 0.5^2), covered by a disk of radius 0.625, not by one just below.
    pds::Delaunay one(pds::Box{0.0, 0.0, 1.0, 1.0});
    one.reserve(5);
    one.insert(pds::Point{0.5, 0.5}, 0);
    const pds::Rectangle narrow(pds::Box{0.125, 0.0, 0.875, 1.0});
    ck_assert_ptr_null(narrow.uncovered_side(one, 0.625));
    ck_assert_ptr_nonnull(narrow.uncovered_side(one, std::nextafter(0.625, 0.0)));
}
END_TEST

}  // namespace

Suite* rectangle_suite() {
    Suite* s = suite_create("rectangle");
    TCase* t = tcase_create("domain");
    tcase_add_test(t, contains_its_closed_boundary_only);
    tcase_add_test(t, measures_and_count_bound);
    tcase_add_test(t, uniform_point_inside_and_spread);
    tcase_add_test(t, scaling_is_exact);
    tcase_add_test(t, boundary_certificate_names_the_uncovered_side);
    suite_add_tcase(s, t);
    return s;
}
