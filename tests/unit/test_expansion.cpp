// test_expansion.cpp - exact expansion arithmetic: identities that only hold
// exactly, and comparison with 128-bit integer arithmetic.
#include <cmath>
#include <cstdint>
#include <random>

#include "core/expansion.hpp"
#include "suites.hpp"

using pds::Expansion;
using pds::exact_diff;
using pds::exact_product;
using pds::exact_value;

namespace {

// Doubles with widely varying exponents and random significands.
double wild_double(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> mant(1.0, 2.0);
    std::uniform_int_distribution<int> ex(-60, 60);
    const double sign = (rng() & 1) ? -1.0 : 1.0;
    return sign * std::ldexp(mant(rng), ex(rng));
}

}  // namespace

START_TEST(two_sum_and_product_are_exact) {
    std::mt19937_64 rng(1);
    for (int i = 0; i < 20000; ++i) {
        const double a = wild_double(rng), b = wild_double(rng);
        // (a - b) + b - a == 0 exactly, although a - b rounds.
        ck_assert_int_eq(((exact_diff(a, b) + exact_value(b)) - exact_value(a)).sign(), 0);
        // (a + b)^2 == a^2 + 2ab + b^2 exactly.
        const auto s = exact_value(a) + exact_value(b);
        const auto lhs = s * s;
        const auto rhs = exact_product(a, a) + exact_product(a, b) + exact_product(a, b) +
                         exact_product(b, b);
        ck_assert_int_eq((lhs - rhs).sign(), 0);
    }
}
END_TEST

START_TEST(tiny_differences_keep_their_sign) {
    // (a + t)^2 - a^2 > 0 even when t is far below a's last bit.
    for (int k = 60; k < 200; k += 7) {
        const double a = 0.75, t = std::ldexp(1.0, -k);
        const auto s = exact_value(a) + exact_value(t);
        ck_assert_int_eq((s * s - exact_product(a, a)).sign(), 1);
        const auto d = exact_value(a) - exact_value(t);
        ck_assert_int_eq((d * d - exact_product(a, a)).sign(), -1);
    }
}
END_TEST

START_TEST(matches_int128_determinants) {
    std::mt19937_64 rng(2);
    std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 52), std::int64_t{1} << 52);
    for (int i = 0; i < 20000; ++i) {
        std::int64_t a = coord(rng), b = coord(rng), c = coord(rng), d = coord(rng);
        if (i % 3 == 0) d = a, c = b;  // force exact zeros now and then
        const __int128 exact = static_cast<__int128>(a) * b - static_cast<__int128>(c) * d;
        const int want = exact > 0 ? 1 : (exact < 0 ? -1 : 0);
        const auto got = exact_product(static_cast<double>(a), static_cast<double>(b)) -
                         exact_product(static_cast<double>(c), static_cast<double>(d));
        ck_assert_int_eq(got.sign(), want);
        const Expansion heap = Expansion::product(static_cast<double>(a), static_cast<double>(b)) -
                               Expansion::product(static_cast<double>(c), static_cast<double>(d));
        ck_assert_int_eq(heap.sign(), want);
    }
}
END_TEST

START_TEST(heap_products_and_rationals) {
    std::mt19937_64 rng(3);
    for (int i = 0; i < 2000; ++i) {
        const double a = wild_double(rng), b = wild_double(rng), c = wild_double(rng);
        // (a*b)*c == a*(b*c) exactly.
        const Expansion left = Expansion::product(a, b) * Expansion(c);
        const Expansion right = Expansion(a) * Expansion::product(b, c);
        ck_assert_int_eq((left - right).sign(), 0);
        // a/b compared with (a*c)/(b*c): equal; with (a + tiny)/b: ordered.
        const pds::Rational r1 = pds::make_rational(Expansion(a), Expansion(b));
        const pds::Rational r2 = pds::make_rational(Expansion::product(a, c), Expansion::product(b, c));
        ck_assert_int_eq(pds::compare(r1, r2), 0);
        const Expansion bumped = Expansion(a) + Expansion(std::ldexp(std::fabs(a), -90));
        const pds::Rational r3 = pds::make_rational(bumped, Expansion(b));
        ck_assert_int_eq(pds::compare(r3, r1), b > 0 ? 1 : -1);
    }
}
END_TEST

Suite* expansion_suite() {
    Suite* s = suite_create("expansion");
    TCase* t = tcase_create("exact identities");
    tcase_add_test(t, two_sum_and_product_are_exact);
    tcase_add_test(t, tiny_differences_keep_their_sign);
    suite_add_tcase(s, t);
    t = tcase_create("against int128");
    tcase_add_test(t, matches_int128_determinants);
    suite_add_tcase(s, t);
    t = tcase_create("heap and rationals");
    tcase_add_test(t, heap_products_and_rationals);
    suite_add_tcase(s, t);
    return s;
}
