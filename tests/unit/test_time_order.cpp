// test_time_order.cpp - items put in order of a uniform time by buckets
// (core/time_order.hpp): the order std::stable_sort gives, ties included,
// from one list or several joined, at times 0 and just below 1 as well.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/time_order.hpp"
#include "suites.hpp"

namespace {

struct Item {
    double t;
    std::uint32_t id;  // its place in the input
};

bool same(const std::vector<Item>& a, const std::vector<Item>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].t != b[i].t || a[i].id != b[i].id) return false;
    return true;
}

}  // namespace

START_TEST(the_order_of_a_stable_sort) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const std::size_t n : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{1000}, std::size_t{50000}})
        for (int kind = 0; kind < 3; ++kind) {
            std::vector<Item> in(n);
            for (std::size_t i = 0; i < n; ++i) {
                // Uniform; a few times only (ties everywhere); the ends of [0, 1).
                double t = u(rng);
                if (kind == 1) t = std::floor(t * 5.0) / 5.0;
                if (kind == 2) t = i % 2 ? 0.0 : 0x1.fffffffffffffp-1;
                in[i] = Item{t, static_cast<std::uint32_t>(i)};
            }
            std::vector<Item> expected = in;
            const auto before = [](const Item& a, const Item& b) { return a.t < b.t; };
            std::stable_sort(expected.begin(), expected.end(), before);
            std::vector<Item> out(n);
            std::vector<std::uint32_t> starts;
            pds::order_by_time(
                n,
                [&](const auto& put) {
                    for (const Item& x : in) put(x);
                },
                [](const Item& x) { return x.t; }, before, out.data(), starts);
            ck_assert_msg(same(out, expected), "n %zu, kind %d: not the stable order", n, kind);
        }
}
END_TEST

START_TEST(several_lists_joined_in_their_order) {
    // Two lists given one after the other: ties keep the first list's first.
    std::vector<Item> a{{0.5, 0}, {0.25, 1}, {0.75, 2}}, b{{0.5, 3}, {0.25, 4}, {0.0, 5}};
    std::vector<Item> out(6);
    std::vector<std::uint32_t> starts;
    pds::order_by_time(
        6,
        [&](const auto& put) {
            for (const Item& x : a) put(x);
            for (const Item& x : b) put(x);
        },
        [](const Item& x) { return x.t; }, [](const Item& x, const Item& y) { return x.t < y.t; }, out.data(),
        starts);
    const std::uint32_t ids[] = {5, 1, 4, 0, 3, 2};
    for (int i = 0; i < 6; ++i) ck_assert_uint_eq(out[i].id, ids[i]);
}
END_TEST

Suite* time_order_suite() {
    Suite* s = suite_create("time_order");
    TCase* t = tcase_create("buckets");
    tcase_add_test(t, the_order_of_a_stable_sort);
    tcase_add_test(t, several_lists_joined_in_their_order);
    suite_add_tcase(s, t);
    return s;
}
