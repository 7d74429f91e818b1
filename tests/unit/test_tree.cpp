// test_tree.cpp - the free-area tree: sums always equal to a fresh recount,
// exact zero when every leaf is zero, selection frequencies proportional to
// the weights, and growth that keeps every leaf; its pages made resident
// ahead (core/page_hints.hpp) without a change to anything it holds.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/page_hints.hpp"
#include "jones/free_area_tree.hpp"
#include "suites.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace {

// The root must be exactly the sum tree recomputed from the leaves: groups of
// eight children added pairwise, ((c0+c1)+(c2+c3))+((c4+c5)+(c6+c7)), level by level.
double recount(const std::vector<double>& w, std::size_t cap) {
    const std::size_t k = pds::FreeAreaTree::kFanout;
    std::vector<double> level(cap, 0.0);
    for (std::size_t i = 0; i < w.size(); ++i) level[i] = w[i];
    while (level.size() > 1) {
        std::vector<double> up((level.size() + k - 1) / k, 0.0);
        for (std::size_t j = 0; j < up.size(); ++j) {
            double c[8];
            for (std::size_t i = 0; i < k; ++i) c[i] = (k * j + i < level.size()) ? level[k * j + i] : 0.0;
            up[j] = ((c[0] + c[1]) + (c[2] + c[3])) + ((c[4] + c[5]) + (c[6] + c[7]));
        }
        level.swap(up);
    }
    return level[0];
}

}  // namespace

START_TEST(sums_follow_updates) {
    pds::FreeAreaTree tree;
    tree.reserve(1000);
    std::vector<double> w;
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        w.push_back(u(rng) * std::ldexp(1.0, -static_cast<int>(rng() % 60)));
        tree.push_back(w.back());
    }
    for (int step = 0; step < 20000; ++step) {
        const std::size_t i = rng() % w.size();
        w[i] = (rng() % 3 == 0) ? 0.0 : w[i] * u(rng);  // cells only shrink
        tree.set(i, w[i]);
        if (step % 1000 == 0) ck_assert(tree.total() == recount(w, tree.capacity()));
    }
    ck_assert(tree.total() == recount(w, tree.capacity()));
    for (std::size_t i = 0; i < w.size(); ++i) tree.set(i, 0.0);
    ck_assert(tree.total() == 0.0);  // exactly, after any history
}
END_TEST

START_TEST(growth_keeps_leaves) {
    pds::FreeAreaTree tree;
    tree.reserve(3);
    std::vector<double> w;
    for (int i = 0; i < 5000; ++i) {
        if (tree.size() == tree.capacity()) tree.reserve(2 * tree.capacity());
        w.push_back(1.0 / (i + 1));
        tree.push_back(w.back());
    }
    for (std::size_t i = 0; i < w.size(); ++i) ck_assert(tree.weight(i) == w[i]);
    ck_assert(tree.total() == recount(w, tree.capacity()));
}
END_TEST

START_TEST(selection_is_proportional) {
    // Weights 1..8 plus zeros: counts over many draws match within 5 sigma,
    // and a zero-weight leaf is never chosen, even for u at the very top.
    pds::FreeAreaTree tree;
    tree.reserve(16);
    const double weights[12] = {1, 0, 2, 3, 0, 4, 5, 6, 0, 7, 8, 0};
    double total = 0;
    for (double x : weights) {
        tree.push_back(x);
        total += x;
    }
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int draws = test_light() ? 36000 : 360000;
    std::vector<int> hits(12, 0);
    for (int i = 0; i < draws; ++i) ++hits[tree.select(u(rng) * tree.total())];
    for (int i = 0; i < 12; ++i) {
        const double p = weights[i] / total, expect = p * draws;
        if (weights[i] == 0) ck_assert_int_eq(hits[i], 0);
        else ck_assert_double_le(std::fabs(hits[i] - expect), 5 * std::sqrt(expect * (1 - p)));
    }
    ck_assert_double_gt(weights[tree.select(std::nextafter(tree.total(), 0.0))], 0.0);
    ck_assert_double_gt(weights[tree.select(tree.total())], 0.0);  // rounding overshoot
    ck_assert_double_gt(weights[tree.select(0.0)], 0.0);
}
END_TEST

START_TEST(pages_made_resident_ahead_change_nothing) {
    // A vector's spare capacity: only whole pages past its entries are asked
    // for, never more than the room, and the entries stay as they were.
    std::vector<double> v(1000, 0.0);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = 0.5 + static_cast<double>(i);
    v.reserve(1 << 20);
    const std::vector<double> before(v.begin(), v.end());
    const std::size_t asked = pds::populate_ahead(v, 300000);
    ck_assert_uint_le(asked, (300000 - v.size()) * sizeof(double));
    ck_assert(std::vector<double>(v.begin(), v.end()) == before);
    ck_assert_uint_eq(pds::populate_ahead(v, 10), 0);  // nothing beyond the entries
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    if (asked > 0) {
        // The pages asked for are resident now.
        const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
        const std::uintptr_t start = (reinterpret_cast<std::uintptr_t>(v.data() + v.size()) + page - 1) & ~(page - 1);
        std::vector<unsigned char> in(asked / page);
        ck_assert_int_eq(mincore(reinterpret_cast<void*>(start), asked, in.data()), 0);
        for (std::size_t k = 0; k < in.size(); ++k) ck_assert_msg(in[k] & 1, "page %zu of %zu not resident", k, in.size());
    }
#endif
    // The tree: its weights and sums stay, leaves added later sum as ever.
    pds::FreeAreaTree tree;
    tree.reserve(1 << 18);
    std::vector<double> w;
    for (int i = 0; i < 5000; ++i) {
        w.push_back(static_cast<double>(i % 7) * 0.25);
        tree.push_back(w.back());
    }
    const double total = tree.total();
    tree.populate_for(1 << 17);
    tree.populate_for(std::size_t{1} << 40);  // past the capacity: capped
    ck_assert(tree.total() == total);
    for (std::size_t i = 0; i < w.size(); ++i) ck_assert(tree.weight(i) == w[i]);
    for (int i = 0; i < 3000; ++i) {
        w.push_back(1.0);
        tree.push_back(1.0);
    }
    ck_assert(tree.total() == recount(w, tree.capacity()));
}
END_TEST

Suite* tree_suite() {
    Suite* s = suite_create("free_area_tree");
    TCase* t = tcase_create("sums");
    tcase_add_test(t, sums_follow_updates);
    tcase_add_test(t, growth_keeps_leaves);
    tcase_add_test(t, pages_made_resident_ahead_change_nothing);
    suite_add_tcase(s, t);
    t = tcase_create("selection");
    tcase_add_test(t, selection_is_proportional);
    suite_add_tcase(s, t);
    return s;
}
