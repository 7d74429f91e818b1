// test_delaunay.cpp - incremental insertion keeps a valid, exactly Delaunay
// mesh, for random points and for grids full of collinear and cocircular sets
// (points landing exactly on edges, four points on one circle).
#include <algorithm>
#include <random>
#include <stdexcept>

#include "mesh/delaunay.hpp"
#include "mesh_checks.hpp"
#include "suites.hpp"

namespace {

pds::Delaunay make(std::size_t n) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1});
    dt.reserve(n + pds::Delaunay::kGhosts);
    return dt;
}

}  // namespace

START_TEST(ghost_square_only) {
    pds::Delaunay dt = make(0);
    ck_assert_uint_eq(check_delaunay_mesh(dt), 2);
}
END_TEST

START_TEST(random_points) {
    const std::size_t n = test_light() ? 300 : 3000;
    pds::Delaunay dt = make(n);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uint32_t last = 0;
    for (std::size_t i = 0; i < n; ++i) last = dt.insert({u(rng), u(rng)}, last);
    // n + 4 vertices, 4 on the hull: 2(n + 4) - 2 - 4 triangles.
    ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * (n + 4) - 6);
}
END_TEST

START_TEST(grid_points) {
    // A 25 x 25 grid inserted in a scrambled order: many later points fall
    // exactly on existing edges, and every grid square is cocircular.
    const int k = test_light() ? 12 : 25;
    std::vector<pds::Point> pts;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) pts.push_back({i / double(k - 1), j / double(k - 1)});
    std::mt19937_64 rng(5);
    std::shuffle(pts.begin(), pts.end(), rng);
    pds::Delaunay dt = make(pts.size());
    std::uint32_t near = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        near = dt.insert(pts[i], near);
        if (i % 97 == 0) check_delaunay_mesh(dt);
    }
    check_delaunay_mesh(dt);
}
END_TEST

START_TEST(walk_from_far_away) {
    // Starting the walk at a ghost, far from the point, still finds it.
    pds::Delaunay dt = make(500);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 500; ++i) dt.insert({u(rng), u(rng)}, static_cast<std::uint32_t>(i % 4));
    check_delaunay_mesh(dt);
}
END_TEST

START_TEST(no_room_is_an_error_not_a_corruption) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1});
    dt.reserve(5);
    dt.insert({0.5, 0.5}, 0);
    ck_assert(!dt.has_room_for_one());
    bool threw = false;
    try {
        dt.insert({0.25, 0.25}, 4);
    } catch (const std::logic_error&) {
        threw = true;
    }
    ck_assert(threw);
    ck_assert_uint_eq(dt.vertex_count(), 5);
    check_delaunay_mesh(dt);
}
END_TEST

Suite* delaunay_suite() {
    Suite* s = suite_create("delaunay");
    TCase* t = tcase_create("insertion");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, ghost_square_only);
    tcase_add_test(t, random_points);
    tcase_add_test(t, grid_points);
    tcase_add_test(t, walk_from_far_away);
    tcase_add_test(t, no_room_is_an_error_not_a_corruption);
    suite_add_tcase(s, t);
    return s;
}
