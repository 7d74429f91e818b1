// test_predicates.cpp - orientation, in-circle and distance predicates on
// near-degenerate input where plain floating point gets the sign wrong, with
// oracles derived by hand (exact arithmetic on a known configuration).
#include <cmath>
#include <random>

#include "predicates.hpp"
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
    t = tcase_create("symmetries");
    tcase_add_test(t, random_symmetries);
    suite_add_tcase(s, t);
    return s;
}
