// test_delaunay_build.cpp - the mesh built whole by divide and conquer is the
// mesh insertion builds (the same edges), exactly Delaunay also on grids full
// of collinear and cocircular sets, the same record for record on any number
// of threads, and ready for insertions afterwards.
#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "mesh/delaunay.hpp"
#include "mesh_checks.hpp"
#include "mesh_samples.hpp"
#include "suites.hpp"

namespace {

using Edges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

std::vector<std::uint32_t> identity(std::size_t n) {
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
    return order;
}

pds::Delaunay make(std::size_t n) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1});
    dt.reserve(n + pds::Delaunay::kGhosts);
    return dt;
}

Edges edges_of(const pds::Delaunay& dt) {
    Edges edges;
    const pds::QuadEdgeMesh& m = dt.mesh();
    for (std::size_t r = 0; r < m.record_count(); ++r) {
        if (!m.is_live(r)) continue;
        const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * r);
        edges.emplace_back(std::min(m.org(e), m.dest(e)), std::max(m.org(e), m.dest(e)));
    }
    std::sort(edges.begin(), edges.end());
    return edges;
}

}  // namespace

START_TEST(same_edges_as_insertion) {
    const std::size_t n = test_light() ? 6000 : 40000;
    const std::vector<pds::Point> pts = random_points(n, 17);
    const std::vector<std::uint32_t> order = identity(n);
    pds::Delaunay inserted = make(n), built = make(n);
    inserted.insert_in_order(pts, order.data(), n, [](std::uint32_t, std::uint32_t) {});
    std::size_t seen = 0;
    ck_assert(built.build_whole(pts, order.data(), n, 2, [&](std::uint32_t k, std::uint32_t v) {
        ck_assert_uint_eq(v, k + pds::Delaunay::kGhosts);
        ++seen;
    }));
    ck_assert_uint_eq(seen, n);
    ck_assert_uint_eq(check_delaunay_mesh(built), 2 * (n + 4) - 6);
    ck_assert(edges_of(built) == edges_of(inserted));
    for (std::uint32_t v = 0; v < built.vertex_count(); ++v) {
        ck_assert(built.point(v).x == inserted.point(v).x && built.point(v).y == inserted.point(v).y);
        ck_assert_uint_eq(built.mesh().org(built.edge_of(v)), v);
    }
}
END_TEST

START_TEST(vertices_follow_the_order_given) {
    // Vertex 4 + i is point order[i], whatever the order.
    const std::size_t n = 5000;
    const std::vector<pds::Point> pts = random_points(n, 4);
    std::vector<std::uint32_t> order = identity(n);
    std::shuffle(order.begin(), order.end(), std::mt19937_64(9));
    pds::Delaunay dt = make(n);
    ck_assert(dt.build_whole(pts, order.data(), n, 1, [](std::uint32_t, std::uint32_t) {}));
    for (std::size_t i = 0; i < n; ++i) {
        const pds::Point& p = dt.point(static_cast<std::uint32_t>(pds::Delaunay::kGhosts + i));
        ck_assert(p.x == pts[order[i]].x && p.y == pts[order[i]].y);
    }
    check_delaunay_mesh(dt);
}
END_TEST

START_TEST(same_records_on_any_number_of_threads) {
    const std::size_t n = test_light() ? 20000 : 300000;  // light: 4 leaves; else 64
    const std::vector<pds::Point> pts = random_points(n, 23);
    const std::vector<std::uint32_t> order = identity(n);
    std::vector<std::uint32_t> first;
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        pds::Delaunay dt = make(n);
        ck_assert(dt.build_whole(pts, order.data(), n, threads));
        const std::vector<std::uint32_t> layout = layout_of(dt);
        if (first.empty())
            first = layout;
        else
            ck_assert_msg(layout == first, "%u threads built other records", threads);
    }
    ck_assert(!first.empty());
}
END_TEST

START_TEST(records_follow_the_median_cuts) {
    // The cuts are at the median of each axis's order (ties by the other
    // coordinate): another cut still gives a Delaunay mesh, but other
    // records and entry edges, and so other points later. The fingerprints
    // of the layouts were taken from a build whose cuts were std::nth_element
    // over the whole order: random points, and a shuffled grid whose rows and
    // columns tie. 1 thread and 3.
    std::vector<pds::Point> grid;
    for (int i = 0; i < 120; ++i)
        for (int j = 0; j < 110; ++j) grid.push_back({i / 119.0, j / 109.0});
    std::shuffle(grid.begin(), grid.end(), std::mt19937_64(12));
    const std::vector<std::vector<pds::Point>> sets{random_points(70000, 31), grid};
    const std::uint64_t pinned[] = {0x7bce9e3326d2c0bcull, 0x5e5a5bf9ca216395ull};
    for (std::size_t k = test_light() ? 1 : 0; k < sets.size(); ++k)  // light: the grid only
        for (unsigned threads : {1u, 3u}) {
            const std::vector<std::uint32_t> order = identity(sets[k].size());
            pds::Delaunay dt = make(sets[k].size());
            ck_assert(dt.build_whole(sets[k], order.data(), sets[k].size(), threads));
            std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the words
            for (const std::uint32_t w : layout_of(dt)) h = (h ^ w) * 1099511628211ull;
            ck_assert_msg(h == pinned[k], "set %zu, %u threads: layout %016llx, pinned %016llx", k, threads,
                          static_cast<unsigned long long>(h), static_cast<unsigned long long>(pinned[k]));
        }
}
END_TEST

START_TEST(grids_collinear_and_cocircular) {
    // Every grid square is cocircular and every row and column collinear;
    // the columns also share x, so the sort's ties go by y. Also a single
    // column (all x equal) and a single row.
    const int k = test_light() ? 70 : 150;
    std::vector<std::vector<pds::Point>> sets(3);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) sets[0].push_back({i / double(k - 1), j / double(k - 1)});
    for (int j = 0; j < 5000; ++j) sets[1].push_back({0.5, j / 4999.0});
    for (int i = 0; i < 5000; ++i) sets[2].push_back({i / 4999.0, 0.25});
    for (std::vector<pds::Point>& pts : sets) {
        std::shuffle(pts.begin(), pts.end(), std::mt19937_64(5));
        const std::vector<std::uint32_t> order = identity(pts.size());
        pds::Delaunay dt = make(pts.size());
        ck_assert(dt.build_whole(pts, order.data(), pts.size(), 2));
        check_delaunay_mesh(dt);
    }
}
END_TEST

START_TEST(insertions_go_on_after_a_build) {
    // The build leaves its spare records on the free list: later insertions
    // take them first, within the room reserved.
    const std::size_t n = 8000, more = 3000;
    const std::vector<pds::Point> pts = random_points(n + more, 31);
    const std::vector<std::uint32_t> order = identity(n);
    pds::Delaunay dt = make(n + more);
    ck_assert(dt.build_whole(pts, order.data(), n, 2));
    std::uint32_t near = 4;
    for (std::size_t i = n; i < n + more; ++i) {
        ck_assert(dt.has_room_for_one());
        near = dt.insert(pts[i], near);
    }
    ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * (n + more + 4) - 6);
}
END_TEST

START_TEST(declines_what_it_does_not_build) {
    const std::vector<pds::Point> pts = random_points(6000, 2);
    const std::vector<std::uint32_t> order = identity(pts.size());
    // Too few points: insertion is as fast, and keeps the small meshes as they were.
    pds::Delaunay few = make(100);
    ck_assert(!few.build_whole(pts, order.data(), pds::Delaunay::kBuildWholeFrom - 1, 2));
    ck_assert_uint_eq(few.vertex_count(), 4);
    ck_assert_uint_eq(check_delaunay_mesh(few), 2);
    // No room reserved.
    pds::Delaunay cramped = make(100);
    ck_assert(!cramped.build_whole(pts, order.data(), pts.size(), 2));
    ck_assert_uint_eq(check_delaunay_mesh(cramped), 2);
    // A mesh that already holds points.
    pds::Delaunay started = make(pts.size());
    started.insert({0.5, 0.5}, 0);
    ck_assert(!started.build_whole(pts, order.data(), pts.size(), 2));
    ck_assert_uint_eq(started.vertex_count(), 5);
}
END_TEST

START_TEST(weighted_with_the_ghosts_radius) {
    // A weighted mesh whose points all have the ghosts' radius is the
    // Delaunay mesh: built whole, then disks of other radii inserted (some
    // hide points, some are hidden), it is the regular mesh that inserting
    // everything one by one gives, edge for edge and hidden for hidden.
    const std::size_t n = 6000, disks = 60;
    const double r = 0.004;
    std::vector<pds::Point> pts = random_points(n + disks, 43);
    const std::vector<std::uint32_t> order = identity(n + disks);
    const auto radius_of = [&](std::uint32_t k) { return k < n ? r : (k % 3 == 0 ? 0.05 : k % 3 == 1 ? 0.001 : 0.02); };
    pds::Delaunay built(pds::Box{0, 0, 1, 1}, true, r), inserted(pds::Box{0, 0, 1, 1}, true, r);
    built.reserve(n + disks + 4);
    inserted.reserve(n + disks + 4);
    ck_assert(built.build_whole(pts, order.data(), n, 2));
    for (std::uint32_t v = 4; v < built.vertex_count(); ++v) {
        ck_assert(built.radius(v) == r);
        ck_assert(!built.is_hidden(v));
    }
    built.insert_in_order(pts, order.data() + n, disks, radius_of, [](std::uint32_t, std::uint32_t) {});
    inserted.insert_in_order(pts, order.data(), n + disks, radius_of, [](std::uint32_t, std::uint32_t) {});
    ck_assert(built.hidden_count() > 0);
    ck_assert_uint_eq(built.hidden_count(), inserted.hidden_count());
    for (std::uint32_t v = 0; v < built.vertex_count(); ++v) ck_assert(built.is_hidden(v) == inserted.is_hidden(v));
    check_delaunay_mesh(built);
    ck_assert(edges_of(built) == edges_of(inserted));
}
END_TEST

Suite* delaunay_build_suite() {
    Suite* s = suite_create("delaunay_build");
    TCase* t = tcase_create("divide_and_conquer");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, same_edges_as_insertion);
    tcase_add_test(t, vertices_follow_the_order_given);
    tcase_add_test(t, same_records_on_any_number_of_threads);
    tcase_add_test(t, records_follow_the_median_cuts);
    tcase_add_test(t, grids_collinear_and_cocircular);
    tcase_add_test(t, insertions_go_on_after_a_build);
    tcase_add_test(t, declines_what_it_does_not_build);
    tcase_add_test(t, weighted_with_the_ghosts_radius);
    suite_add_tcase(s, t);
    return s;
}
