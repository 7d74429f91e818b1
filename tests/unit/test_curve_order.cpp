// test_curve_order.cpp - the hand-over's insertion order
// (darts/curve_order.hpp): the Hilbert keys walk every grid cell once, each
// step to a neighbouring cell, and equal those of a level-by-level evaluation
// of the same curve; the order is a permutation made of BRIO rounds, each
// sorted by key, ties kept in point order, the same on any number of threads;
// fixed points first, in rounds of their own.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/rng.hpp"
#include "darts/curve_order.hpp"
#include "suites.hpp"

namespace {

// The curve evaluated one level at a time, with the quadrant rotations as
// explicit flips and swaps: the reference the table-driven keys must equal.
std::uint64_t reference_key(std::uint64_t x, std::uint64_t y, std::uint64_t side) {
    std::uint64_t key = 0;
    for (std::uint64_t s = side / 2; s > 0; s /= 2) {
        const bool rx = (x & s) != 0, ry = (y & s) != 0;
        key += s * s * ((3u * (rx ? 1u : 0u)) ^ (ry ? 1u : 0u));
        x &= s - 1;
        y &= s - 1;
        if (!ry) {
            if (rx) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            std::swap(x, y);
        }
    }
    return key;
}

// The centre of cell (i, j) of unit cells from the origin.
pds::Point centre(std::size_t i, std::size_t j) {
    return pds::Point{static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5};
}

std::uint64_t side_for(std::size_t cols, std::size_t rows) {
    std::uint64_t side = 1;
    while (side < cols || side < rows) side *= 2;
    return side;
}

// Checks that order[first, last) holds the indices first .. last - 1 in BRIO
// rounds (prefixes of the range, ends last - first, /4, ... down to 256 or
// fewer), each sorted by key, ties in point order.
void check_rounds(const pds::CurveOrder& curve, const std::vector<pds::Point>& points, const std::uint32_t* order,
                  std::size_t first, std::size_t last) {
    std::vector<std::size_t> ends;
    for (std::size_t end = last - first; end > 0; end = end > 256 ? end / 4 : 0) ends.push_back(first + end);
    std::reverse(ends.begin(), ends.end());
    std::size_t begin = first;
    for (std::size_t end : ends) {
        for (std::size_t k = begin; k < end; ++k) {
            ck_assert_msg(order[k] >= begin && order[k] < end, "[%zu, %zu): entry %zu is not from its round", first,
                          last, k);
            if (k == begin) continue;
            const std::uint64_t a = curve.key(points[order[k - 1]]), b = curve.key(points[order[k]]);
            ck_assert_msg(a < b || (a == b && order[k - 1] < order[k]), "[%zu, %zu): entries %zu, %zu out of order",
                          first, last, k - 1, k);
        }
        begin = end;
    }
}

}  // namespace

START_TEST(keys_walk_a_square_grid_cell_by_neighbouring_cell) {
    for (std::size_t side = 1; side <= 256; side *= 2) {
        const pds::CurveOrder curve(pds::Box{0.0, 0.0, double(side), double(side)}, 1.0, 1.0, side, side);
        std::vector<std::int64_t> cell_at(side * side, -1);
        for (std::size_t i = 0; i < side; ++i)
            for (std::size_t j = 0; j < side; ++j) {
                const std::uint64_t key = curve.key(centre(i, j));
                ck_assert_msg(key < side * side, "side %zu: key %llu out of range", side, (unsigned long long)key);
                ck_assert_msg(cell_at[key] < 0, "side %zu: key %llu given twice", side, (unsigned long long)key);
                cell_at[key] = static_cast<std::int64_t>(i * side + j);
            }
        ck_assert_int_eq(cell_at[0], 0);  // the curve starts in the lower left cell
        for (std::size_t k = 1; k < side * side; ++k) {
            const std::int64_t a = cell_at[k - 1], b = cell_at[k];
            const std::int64_t di = a / std::int64_t(side) - b / std::int64_t(side);
            const std::int64_t dj = a % std::int64_t(side) - b % std::int64_t(side);
            ck_assert_msg(std::llabs(di) + std::llabs(dj) == 1, "side %zu: keys %zu and %zu are not neighbours", side,
                          k - 1, k);
        }
    }
}
END_TEST

START_TEST(keys_equal_the_level_by_level_curve) {
    // Odd and even level counts, grids that are not square and not powers of
    // two, and points outside the box (they count as in the nearest cell).
    const std::size_t shapes[][2] = {{1, 1},       {3, 1},       {2, 5},       {17, 9},      {100, 37},
                                     {1000, 1000}, {1700, 1700}, {5400, 3000}, {1 << 20, 3}, {(1 << 21) + 5, 1 << 19}};
    pds::Rng rng(7);
    for (const auto& shape : shapes) {
        const std::size_t cols = shape[0], rows = shape[1];
        const std::uint64_t side = side_for(cols, rows);
        const pds::CurveOrder curve(pds::Box{0.0, 0.0, double(cols), double(rows)}, 1.0, 1.0, cols, rows);
        for (int n = 0; n < 20000; ++n) {
            const double x = (1.2 * rng.next_double() - 0.1) * double(cols);
            const double y = (1.2 * rng.next_double() - 0.1) * double(rows);
            const std::uint64_t i = x <= 0.0 ? 0 : std::min<std::uint64_t>(std::uint64_t(x), cols - 1);
            const std::uint64_t j = y <= 0.0 ? 0 : std::min<std::uint64_t>(std::uint64_t(y), rows - 1);
            const std::uint64_t want = reference_key(i, j, side), got = curve.key(pds::Point{x, y});
            ck_assert_msg(got == want, "%zu x %zu grid, cell (%llu, %llu): key %llu, the curve says %llu", cols, rows,
                          (unsigned long long)i, (unsigned long long)j, (unsigned long long)got,
                          (unsigned long long)want);
        }
    }
}
END_TEST

START_TEST(order_is_rounds_sorted_by_key) {
    const std::size_t cols = 300, rows = 200;
    pds::CurveOrder curve(pds::Box{0.0, 0.0, 3.0, 2.0}, 0.01, 0.01, cols, rows);
    pds::Rng rng(11);
    for (std::size_t n : {std::size_t{1}, std::size_t{256}, std::size_t{257}, std::size_t{5000}, std::size_t{70001}}) {
        std::vector<pds::Point> points(n);
        // Few distinct cells for the small sizes' ties, many for the large.
        const double spread = n < 1000 ? 0.05 : 1.0;
        for (pds::Point& p : points) p = pds::Point{3.0 * spread * rng.next_double(), 2.0 * spread * rng.next_double()};
        curve.reserve(n);
        const std::uint32_t* order = curve.order(points);
        ck_assert(curve.fresh_order(points) == std::vector<std::uint32_t>(order, order + n));
        check_rounds(curve, points, order, 0, n);
    }
}
END_TEST

START_TEST(fixed_points_come_first_in_rounds_of_their_own) {
    // Fixed points are inserted after the others' mesh is built: sorted
    // among themselves, each walk is short wherever they lie.
    const std::size_t n = 9000;
    pds::CurveOrder curve(pds::Box{0.0, 0.0, 1.0, 1.0}, 0.01, 0.01, 100, 100);
    pds::Rng rng(17);
    std::vector<pds::Point> points(n);
    for (pds::Point& p : points) p = pds::Point{rng.next_double(), rng.next_double()};
    curve.reserve(n);
    for (std::size_t first : {std::size_t{0}, std::size_t{1}, std::size_t{200}, std::size_t{3000}, n}) {
        for (unsigned threads : {1u, 3u}) {
            const std::uint32_t* order = curve.order(points, threads, first);
            check_rounds(curve, points, order, 0, first);
            check_rounds(curve, points, order, first, n);
        }
    }
}
END_TEST

START_TEST(order_on_several_threads_is_the_one_thread_order) {
    // Large enough for the keys and the largest rounds to be split among
    // workers; many points share a cell, so ties test the sort's stability.
    const std::size_t n = test_light() ? 140000 : 400000;
    pds::CurveOrder curve(pds::Box{0.0, 0.0, 1.0, 1.0}, 1.0 / 300, 1.0 / 300, 300, 300);
    pds::Rng rng(5);
    std::vector<pds::Point> points(n);
    for (pds::Point& p : points) p = pds::Point{rng.next_double(), rng.next_double()};
    const std::vector<std::uint32_t> one = curve.fresh_order(points);
    curve.reserve(n);
    for (unsigned threads : {2u, 3u, 8u, 20u}) {
        const std::uint32_t* order = curve.order(points, threads);
        for (std::size_t k = 0; k < n; ++k)
            ck_assert_msg(order[k] == one[k], "%u threads: entry %zu is %u, one thread gives %u", threads, k, order[k],
                          one[k]);
    }
}
END_TEST

Suite* curve_order_suite() {
    Suite* s = suite_create("curve_order");
    TCase* tc = tcase_create("curve_order");
    // 20 workers on two cores took 5-7 s alone on a slow VM: Check's 4 s
    // default fails there.
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, keys_walk_a_square_grid_cell_by_neighbouring_cell);
    tcase_add_test(tc, keys_equal_the_level_by_level_curve);
    tcase_add_test(tc, order_is_rounds_sorted_by_key);
    tcase_add_test(tc, fixed_points_come_first_in_rounds_of_their_own);
    tcase_add_test(tc, order_on_several_threads_is_the_one_thread_order);
    suite_add_tcase(s, tc);
    return s;
}
