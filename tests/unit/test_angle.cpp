// test_angle.cpp - the deterministic arctangent against libm's atan2.
#include <cmath>
#include <random>

#include "core/angle.hpp"
#include "suites.hpp"

START_TEST(matches_atan2_everywhere) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
        const double y = u(rng) * std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
        const double x = u(rng) * std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
        const double want = std::atan2(y, x), got = pds::angle_of(y, x);
        const double err = std::fabs(got - want) / std::max(std::fabs(want), 1e-300);
        worst = std::max(worst, err);
    }
    ck_assert_double_le(worst, 8e-16);
}
END_TEST

START_TEST(special_directions) {
    const double pi = 3.141592653589793;
    ck_assert_double_eq(pds::angle_of(0.0, 0.0), 0.0);
    ck_assert_double_eq(pds::angle_of(0.0, 1.0), 0.0);
    ck_assert_double_eq_tol(pds::angle_of(1.0, 0.0), pi / 2, 1e-15);
    ck_assert_double_eq_tol(pds::angle_of(1.0, 1.0), pi / 4, 1e-15);
    ck_assert_double_eq_tol(pds::angle_of(0.0, -1.0), pi, 1e-15);
    ck_assert_double_eq_tol(pds::angle_of(-1.0, 0.0), -pi / 2, 1e-15);
    // Past 90 degrees (the paper's code used asin there and got it wrong).
    ck_assert_double_eq_tol(pds::angle_of(1.0, -1.0), 3 * pi / 4, 1e-15);
    ck_assert_double_eq_tol(pds::angle_of(1e-3, -1.0), pi - 1e-3 + 1e-9 / 3, 1e-14);
}
END_TEST

Suite* angle_suite() {
    Suite* s = suite_create("angle");
    TCase* t = tcase_create("arctangent");
    tcase_add_test(t, matches_atan2_everywhere);
    tcase_add_test(t, special_directions);
    suite_add_tcase(s, t);
    return s;
}
