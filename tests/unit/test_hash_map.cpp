// test_hash_map.cpp - the hash map under growth, against std::map; and the
// spatial hash's neighbour queries against brute force, in the plane and on
// a torus.
#include <algorithm>
#include <map>
#include <random>
#include <utility>

#include "core/hash_map.hpp"
#include "verify/spatial_hash.hpp"
#include "suites.hpp"

START_TEST(agrees_with_std_map) {
    pds::HashMap h;
    std::map<std::uint64_t, std::uint32_t> ref;
    std::mt19937_64 rng(12);
    const int n = test_light() ? 20000 : 200000;
    for (int i = 0; i < n; ++i) {
        // Clustered keys (like grid cells) and random ones, with repeats.
        const std::uint64_t key = (i % 2) ? (rng() % 5000) << 32 | (rng() % 5000) : rng() >> 1;
        const std::uint32_t value = static_cast<std::uint32_t>(rng());
        h.insert_or_assign(key, value);
        ref[key] = value;
        ck_assert_uint_le(2 * h.size(), h.slot_count());  // load factor <= 1/2
    }
    ck_assert_uint_eq(h.size(), ref.size());
    for (const auto& kv : ref) {
        const std::uint32_t* v = h.find(kv.first);
        ck_assert_ptr_nonnull(v);
        ck_assert_uint_eq(*v, kv.second);
    }
    for (int i = 0; i < 1000; ++i) {
        const std::uint64_t key = (std::uint64_t{1} << 63) | rng();
        if (ref.count(key) == 0) ck_assert_ptr_null(h.find(key));
    }
}
END_TEST

START_TEST(spatial_hash_finds_every_close_pair) {
    // A full pattern takes the layout sorted by cell; a sparse one (a grid of
    // more than four cells a point) the hashed one: both are checked.
    for (const int n : {3000, 300}) {
        std::mt19937_64 rng(13);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<pds::Point> pts(4);  // the first `first` entries are skipped
        for (int i = 0; i < n; ++i) pts.push_back({u(rng), 0.5 * u(rng)});
        const double r = 0.013;
        const pds::SpatialHash grid(pts, 4, pds::Box{0, 0, 1, 0.5}, r);
        ck_assert(grid.dense() == (n == 3000));
        for (std::size_t i = 4; i < pts.size(); ++i) {
            std::vector<char> found(pts.size(), 0);
            grid.for_each_near(pts[i], [&](std::uint32_t j, int sx, int sy) {
                ck_assert(sx == 0 && sy == 0);
                found[j] = 1;
            });
            for (std::size_t j = 4; j < pts.size(); ++j) {
                const double dx = pts[i].x - pts[j].x, dy = pts[i].y - pts[j].y;
                if (dx * dx + dy * dy < r * r) ck_assert(found[j]);
            }
            for (std::size_t j = 0; j < 4; ++j) ck_assert(!found[j]);
        }
    }
}
END_TEST

START_TEST(spatial_hash_wraps_on_the_torus) {
    // Every pair closer than r on the torus [-1, 2) x [3, 3.5), across the
    // seams too, is visited with the shift that brings the copy next to the
    // query; on a period of two or three cells the shifts tell the copies apart.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // The last radius gives more than four cells a point: the hashed layout.
    for (double r : {0.05, 0.2, 0.24, 0.0125}) {
        pds::Torus t;
        t.px = 3.0, t.py = 0.5, t.x0 = -1.0, t.y0 = 3.0;
        const int n = r < 0.05 ? 2000 : 600;
        std::vector<pds::Point> pts(2);  // the first `first` entries are skipped
        for (int i = 0; i < n; ++i) pts.push_back({t.x0 + t.px * u(rng), t.y0 + t.py * u(rng)});
        const pds::SpatialHash grid(pts, 2, t, r);
        ck_assert(grid.dense() == (r >= 0.05));
        std::size_t pairs = 0;
        for (std::size_t i = 2; i < pts.size(); ++i) {
            std::vector<std::pair<std::uint32_t, std::pair<int, int>>> found;
            grid.for_each_near(pts[i], [&](std::uint32_t j, int sx, int sy) { found.push_back({j, {sx, sy}}); });
            for (std::size_t j = 2; j < pts.size(); ++j) {
                for (int sx = -1; sx <= 1; ++sx) {
                    for (int sy = -1; sy <= 1; ++sy) {
                        if (j == i && sx == 0 && sy == 0) continue;
                        const pds::Point q = t.shifted(pts[j], sx, sy);
                        const double dx = pts[i].x - q.x, dy = pts[i].y - q.y;
                        if (dx * dx + dy * dy >= r * r) continue;
                        ++pairs;
                        const auto want = std::make_pair(static_cast<std::uint32_t>(j), std::make_pair(sx, sy));
                        ck_assert_msg(std::find(found.begin(), found.end(), want) != found.end(),
                                      "r %g: point %zu, copy of %zu shifted (%d, %d) missed", r, i, j, sx, sy);
                    }
                }
            }
            for (const auto& f : found) ck_assert(f.first >= 2);
        }
        ck_assert_msg(pairs > 1000, "r %g: only %zu close pairs, the test would prove little", r, pairs);
    }
}
END_TEST

Suite* hash_map_suite() {
    Suite* s = suite_create("hash_map");
    TCase* t = tcase_create("map");
    tcase_add_test(t, agrees_with_std_map);
    suite_add_tcase(s, t);
    t = tcase_create("spatial");
    tcase_add_test(t, spatial_hash_finds_every_close_pair);
    tcase_add_test(t, spatial_hash_wraps_on_the_torus);
    suite_add_tcase(s, t);
    return s;
}
