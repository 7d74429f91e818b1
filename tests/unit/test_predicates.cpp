// test_predicates.cpp - orientation, in-circle and distance predicates on
// near-degenerate input where plain floating point gets the sign wrong, with
// oracles derived by hand (exact arithmetic on a known configuration).
#include <cmath>
#include <random>
#include <utility>

#include "core/predicates.hpp"
#include "suites.hpp"

using pds::Point;

START_TEST(orient_near_a_line) {
    // p = (0.5 + i*u, 0.5 + j*u) against the line through (12,12) and (24,24):
    // p is left of it exactly when j > i (a classic failure of naive orient).
    const double u = std::ldexp(1.0, -53);
    const Point q{12.0, 12.0}, r{24.0, 24.0};
    int naive_wrong = 0;
    for (int i = -64; i < 64; ++i) {
        for (int j = -64; j < 64; ++j) {
            const Point p{0.5 + i * u, 0.5 + j * u};
            const int want = (j > i) - (j < i);
            ck_assert_int_eq(pds::orient2d(p, q, r), want);
            ck_assert_int_eq(pds::orient2d(q, r, p), want);
            ck_assert_int_eq(pds::orient2d(q, p, r), -want);
            const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
            if ((naive > 0) - (naive < 0) != want) ++naive_wrong;
        }
    }
    // The configuration really is hard: plain evaluation gets many wrong.
    ck_assert_int_gt(naive_wrong, 100);
}
END_TEST

START_TEST(incircle_near_a_circle) {
    // Circle through (0,0), (1,0), (0,1): centre (0.5,0.5), radius^2 0.5, and
    // (1,1) lies on it. d = (1 + i*e, 1 + j*e) is inside exactly when
    // i + j + (i*i + j*j) * e < 0, with e = 2^-52.
    const double e = std::ldexp(1.0, -52);
    const Point a{0, 0}, b{1, 0}, c{0, 1};
    for (int i = -40; i <= 40; ++i) {
        for (int j = -40; j <= 40; ++j) {
            const Point d{1.0 + i * e, 1.0 + j * e};
            int want;
            if (i + j != 0) want = (i + j < 0) ? 1 : -1;
            else want = (i == 0 && j == 0) ? 0 : -1;
            ck_assert_int_eq(pds::incircle(a, b, c, d), want);
            ck_assert_int_eq(pds::incircle(b, c, a, d), want);
            ck_assert_int_eq(pds::incircle(b, a, c, d), -want);  // clockwise flips the sign
        }
    }
}
END_TEST

START_TEST(distance_to_radius) {
    // |(3,4)| == 5 exactly; then one ulp either way.
    const Point o{0, 0};
    ck_assert_int_eq(pds::compare_distance({3, 4}, o, 5.0), 0);
    ck_assert_int_eq(pds::compare_distance({3, std::nextafter(4.0, 5.0)}, o, 5.0), 1);
    ck_assert_int_eq(pds::compare_distance({3, std::nextafter(4.0, 0.0)}, o, 5.0), -1);
    ck_assert_int_eq(pds::compare_distance({3, 4}, o, std::nextafter(5.0, 6.0)), -1);
    // r*r rounds: r = 0.1 (not exact), points on a 0.1-radius circle along the
    // axis: |(0.1, 0)| == 0.1 exactly although 0.1*0.1 rounds.
    ck_assert_int_eq(pds::compare_distance({0.1, 0.0}, o, 0.1), 0);
    ck_assert_int_eq(pds::compare_distance({0.1, std::ldexp(1.0, -300)}, o, 0.1), 1);
    // Translated frames: the differences themselves round.
    const Point p{0.7, 0.3}, q{0.7 + 0.1, 0.3};
    const int s = pds::compare_distance(q, p, 0.1);
    // q.x - p.x is not 0.1 exactly; the predicate must agree with exact math,
    // which we get by checking that (0.7+0.1)-0.7 computed exactly equals the
    // double difference here (it does: Sterbenz), so compare with that value.
    const double dx = q.x - p.x;
    ck_assert_int_eq(s, (dx > 0.1) - (dx < 0.1));
}
END_TEST

START_TEST(closer_on_the_bisector) {
    const Point a{0.25, 0.5}, b{0.75, 0.5};
    for (int k = -50; k <= 50; ++k) {
        const Point p{0.5 + k * std::ldexp(1.0, -53), 0.123456789};
        ck_assert_int_eq(pds::compare_closer(p, a, b), (k > 0) - (k < 0));
        ck_assert_int_eq(pds::compare_closer(p, b, a), (k < 0) - (k > 0));
    }
}
END_TEST

START_TEST(random_symmetries) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 20000; ++n) {
        const Point a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)}, d{u(rng), u(rng)};
        const int o = pds::orient2d(a, b, c);
        ck_assert_int_eq(pds::orient2d(b, c, a), o);
        ck_assert_int_eq(pds::orient2d(b, a, c), -o);
        if (o > 0) {
            const int ic = pds::incircle(a, b, c, d);
            ck_assert_int_eq(pds::incircle(c, a, b, d), ic);
            ck_assert_int_eq(pds::incircle(b, a, c, d), -ic);
        }
    }
}
END_TEST

// Weighted forms. a, b, c, d at the unit square's corners with radii
// (0.5, 0.75, 0.5, 0.75): the lifted d is exactly on the plane of the others
// (rd^2 = rb^2 + rc^2 - ra^2), so moving rd by ulps gives a known sign, at
// any scale and offset that keeps the arithmetic exact.
START_TEST(power_test_near_the_plane) {
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 200; ++trial) {
        const double s = std::ldexp(1.0, -static_cast<int>(rng() % 12));
        const double ox = std::ldexp(static_cast<double>(rng() % (1u << 20)), -20);
        const double oy = std::ldexp(static_cast<double>(rng() % (1u << 20)), -20);
        const Point a{ox, oy}, b{ox + s, oy}, c{ox, oy + s}, d{ox + s, oy + s};
        const double ra = 0.5 * s, rb = 0.75 * s, rc = 0.5 * s, rd0 = 0.75 * s;
        ck_assert_int_eq(pds::power_test(a, ra, b, rb, c, rc, d, rd0), 0);
        double up = rd0, down = rd0;
        for (int k = 1; k <= 4; ++k) {
            up = std::nextafter(up, 1.0);
            down = std::nextafter(down, 0.0);
            // A larger radius lowers the lifted d: below the plane, a conflict.
            ck_assert_int_eq(pds::power_test(a, ra, b, rb, c, rc, d, up), 1);
            ck_assert_int_eq(pds::power_test(a, ra, b, rb, c, rc, d, down), -1);
            ck_assert_int_eq(pds::power_test(b, rb, c, rc, a, ra, d, up), 1);
        }
    }
}
END_TEST

START_TEST(power_test_filter_agrees_with_exact) {
    // Random triangles and radii, and d's radius chosen so its lifted point
    // lies on the plane up to rounding: the cases the filter must not get wrong.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int near = 0;
    const int trials = test_light() ? 2000 : 20000;
    for (int n = 0; n < trials; ++n) {
        Point a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)};
        if (pds::orient2d(a, b, c) < 0) std::swap(b, c);
        if (pds::orient2d(a, b, c) == 0) continue;
        const double ra = 0.1 * u(rng), rb = 0.1 * u(rng), rc = 0.1 * u(rng);
        const Point d{u(rng), u(rng)};
        // Plane z = k0 + k1 x + k2 y through the lifted a, b, c.
        const auto lift = [](const Point& p, double r) { return p.x * p.x + p.y * p.y - r * r; };
        const double za = lift(a, ra), zb = lift(b, rb), zc = lift(c, rc);
        const double det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const double k1 = ((zb - za) * (c.y - a.y) - (zc - za) * (b.y - a.y)) / det;
        const double k2 = ((b.x - a.x) * (zc - za) - (c.x - a.x) * (zb - za)) / det;
        const double zd = za + k1 * (d.x - a.x) + k2 * (d.y - a.y);
        const double rd2 = d.x * d.x + d.y * d.y - zd;
        if (!(rd2 > 0.0)) continue;
        double rd = std::sqrt(rd2);
        for (int k = 0; k < 8; ++k, rd = std::nextafter(rd, 1.0)) {
            const int exact = pds::predicate_detail::power_test_exact(a, ra, b, rb, c, rc, d, rd);
            ck_assert_int_eq(pds::power_test(a, ra, b, rb, c, rc, d, rd), exact);
            ++near;
        }
    }
    ck_assert_int_gt(near, trials * 5 / 2);
}
END_TEST

START_TEST(power_test_with_equal_radii_is_incircle) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 20000; ++n) {
        Point a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)};
        if (pds::orient2d(a, b, c) <= 0) continue;
        const Point d{u(rng), u(rng)};
        const double r = u(rng);
        ck_assert_int_eq(pds::power_test(a, r, b, r, c, r, d, r), pds::incircle(a, b, c, d));
    }
    // And on the cocircular square, exactly 0.
    ck_assert_int_eq(pds::power_test({0, 0}, 0.3, {1, 0}, 0.3, {1, 1}, 0.3, {0, 1}, 0.3), 0);
}
END_TEST

START_TEST(power_on_the_radical_axis) {
    // pow_a = |p|^2 - 1/4, pow_b = |p - (1, 0)|^2: pow_a - pow_b = 2x - 5/4,
    // 0 on the line x = 5/8.
    const Point a{0.0, 0.0}, b{1.0, 0.0};
    for (int k = -50; k <= 50; ++k) {
        const Point p{0.625 + k * std::ldexp(1.0, -53), 0.7123};
        // Right of the axis p is nearer b in power.
        ck_assert_int_eq(pds::compare_power(p, a, 0.5, b, 0.0), (k > 0) - (k < 0));
        ck_assert_int_eq(pds::compare_power(p, b, 0.0, a, 0.5), (k < 0) - (k > 0));
    }
    // Equal radii: the plain bisector test.
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 20000; ++n) {
        const Point p{u(rng), u(rng)}, q{u(rng), u(rng)}, s{u(rng), u(rng)};
        const double r = u(rng);
        ck_assert_int_eq(pds::compare_power(p, q, r, s, r), pds::compare_closer(p, q, s));
    }
}
END_TEST

Suite* predicates_suite() {
    Suite* s = suite_create("predicates");
    TCase* t = tcase_create("orientation");
    tcase_add_test(t, orient_near_a_line);
    suite_add_tcase(s, t);
    t = tcase_create("in-circle");
    tcase_add_test(t, incircle_near_a_circle);
    suite_add_tcase(s, t);
    t = tcase_create("distances");
    tcase_add_test(t, distance_to_radius);
    tcase_add_test(t, closer_on_the_bisector);
    suite_add_tcase(s, t);
    t = tcase_create("weighted");
    tcase_add_test(t, power_test_near_the_plane);
    tcase_add_test(t, power_test_filter_agrees_with_exact);
    tcase_add_test(t, power_test_with_equal_radii_is_incircle);
    tcase_add_test(t, power_on_the_radical_axis);
    suite_add_tcase(s, t);
    t = tcase_create("symmetries");
    tcase_add_test(t, random_symmetries);
    suite_add_tcase(s, t);
    return s;
}
