// test_delaunay_sides.cpp - insertions side by side: the read-only search
// says yes only when the insertion's triangles are all on the side (against
// every triangle of the mesh), an insertion it allows writes nothing off the
// side, and two threads inserting the two sides build the records one thread
// builds in the same order (search and insertion in one call or two): an
// exact Delaunay mesh that later insertions continue.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/predicates.hpp"
#include "mesh/delaunay.hpp"
#include "mesh_checks.hpp"
#include "mesh_samples.hpp"
#include "suites.hpp"

namespace {

using pds::Delaunay;
using pds::EdgeRef;
using pds::Point;
using pds::QuadEdgeMesh;
using pds::VertexIndex;

Delaunay mesh_of(const std::vector<Point>& pts, std::size_t room) {
    Delaunay dt(pds::Box{0, 0, 1, 1});
    dt.reserve(Delaunay::kGhosts + room);
    VertexIndex near = 0;
    for (const Point& p : pts) near = dt.insert(p, near);
    return dt;
}

// A real corner of the triangle that holds p: where a sampler's dart starts
// (the site whose cell it was drawn in is a neighbour).
VertexIndex corner_near(const Delaunay& dt, const Point& p) {
    EdgeRef e = dt.locate(p, dt.edge_of(Delaunay::kGhosts));
    for (int k = 0; k < 3; ++k, e = dt.mesh().lnext(e))
        if (!Delaunay::is_ghost(dt.mesh().org(e))) return dt.mesh().org(e);
    return Delaunay::kGhosts;
}

// Every inner triangle, as the left-face edge that names it (the least).
std::vector<EdgeRef> triangles_of(const Delaunay& dt) {
    const QuadEdgeMesh& m = dt.mesh();
    std::vector<EdgeRef> out;
    for (std::size_t r = 0; r < m.record_count(); ++r) {
        if (!m.is_live(r)) continue;
        for (EdgeRef e : {static_cast<EdgeRef>(4 * r), static_cast<EdgeRef>(4 * r + 2)}) {
            const EdgeRef e1 = m.lnext(e), e2 = m.lnext(e1);
            if (m.lnext(e2) != e || e > e1 || e > e2) continue;  // not a triangle, or not its name
            if (pds::orient2d(dt.point(m.org(e)), dt.point(m.org(e1)), dt.point(m.org(e2))) <= 0) continue;
            out.push_back(e);
        }
    }
    return out;
}

// By brute force: are all corners of the triangles whose circles hold p
// strictly, and of the triangles next to them, real vertices of the side?
bool cavity_on_side(const Delaunay& dt, const std::vector<EdgeRef>& triangles, const Point& p,
                    const Delaunay::Side& side) {
    const QuadEdgeMesh& m = dt.mesh();
    for (EdgeRef t : triangles) {
        const VertexIndex a = m.org(t), b = m.org(m.lnext(t)), c = m.org(m.lnext(m.lnext(t)));
        if (pds::incircle(dt.point(a), dt.point(b), dt.point(c), p) <= 0) continue;
        EdgeRef s = t;
        for (int k = 0; k < 3; ++k, s = m.lnext(s)) {
            const VertexIndex far = m.dest(m.lnext(QuadEdgeMesh::sym(s)));
            if (!dt.on_side(m.org(s), side) || !dt.on_side(far, side)) return false;
        }
    }
    return true;
}

}  // namespace

START_TEST(search_agrees_with_every_triangle) {
    // Points near the middle line too, so that many cavities cross it; and
    // queries on the grid's edges and at its vertices (a point on an edge is
    // in both its triangles' circles; a vertex is never insertable).
    const std::vector<Point> pts = random_points(test_light() ? 800 : 3000, 7);
    Delaunay dt = mesh_of(pts, pts.size() + 1);
    const std::vector<EdgeRef> triangles = triangles_of(dt);
    ck_assert_uint_eq(triangles.size(), 2 * (pts.size() + 4) - 6);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::size_t yes = 0, brute_yes = 0;
    const int queries = test_light() ? 1500 : 6000;
    for (int q = 0; q < queries; ++q) {
        const Point p = q % 3 == 0 ? Point{0.5 + 0.04 * (u(rng) - 0.5), u(rng)} : Point{u(rng), u(rng)};
        const Delaunay::Side side{0.5, p.x < 0.5};
        const bool says = dt.can_insert_on_side(p, corner_near(dt, p), side);
        const bool brute = cavity_on_side(dt, triangles, p, side);
        ck_assert_msg(!says || brute, "query %d (%.17g, %.17g): the search allowed a cavity off its side", q, p.x,
                      p.y);
        yes += says;
        brute_yes += brute;
    }
    // It may refuse a point whose walk crosses the line; rarely.
    ck_assert_msg(static_cast<double>(yes) >= 0.97 * static_cast<double>(brute_yes), "allowed %zu of %zu", yes, brute_yes);
    ck_assert(brute_yes < static_cast<std::size_t>(queries));  // the queries reach across the line
    // Vertices: never.
    for (std::size_t i = 0; i < 50; ++i) {
        const VertexIndex v = static_cast<VertexIndex>(Delaunay::kGhosts + i);
        ck_assert(!dt.can_insert_on_side(pts[i], v, Delaunay::Side{0.5, pts[i].x < 0.5}));
    }
}
END_TEST

START_TEST(search_on_a_grid_of_ties) {
    // A 17 x 17 grid: every square cocircular (its triangles' circles pass
    // through the fourth corner, which holds no strictly). The midpoints of
    // its edges are exact, so the queries lie on edges.
    std::vector<Point> grid;
    for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16; ++j) grid.push_back({i / 16.0, j / 16.0});
    std::shuffle(grid.begin(), grid.end(), std::mt19937_64(3));
    Delaunay dt = mesh_of(grid, grid.size() + 1);
    const std::vector<EdgeRef> triangles = triangles_of(dt);
    std::size_t yes = 0, brute_yes = 0, queries = 0;
    for (int i = 1; i < 32; ++i)
        for (int j = 1; j < 32; ++j) {
            if (i % 2 == 0 && j % 2 == 0) continue;  // a vertex
            const Point p{i / 32.0, j / 32.0};
            const Delaunay::Side side{0.5 + 1.0 / 64, p.x < 0.5 + 1.0 / 64};
            const bool says = dt.can_insert_on_side(p, corner_near(dt, p), side);
            const bool brute = cavity_on_side(dt, triangles, p, side);
            ck_assert_msg(!says || brute, "(%g, %g): allowed off its side", p.x, p.y);
            yes += says;
            brute_yes += brute;
            ++queries;
        }
    ck_assert(yes > 0 && static_cast<double>(yes) >= 0.9 * static_cast<double>(brute_yes) && brute_yes < queries);
}
END_TEST

START_TEST(search_sees_a_lone_vertex_across) {
    // One vertex just across the line, in a gap of the other side: the
    // triangles around a point next to it have all their neighbours on the
    // point's side, but the vertex itself is a corner of its cavity.
    std::vector<Point> pts;
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    while (pts.size() < 2500) {
        const Point p{u(rng), u(rng)};
        if (p.x < 0.5 || p.x > 0.7) pts.push_back(p);
    }
    const Point lone{0.5005, 0.5};
    pts.push_back(lone);
    Delaunay dt = mesh_of(pts, pts.size() + 1);
    const std::vector<EdgeRef> triangles = triangles_of(dt);
    const Delaunay::Side side{0.5, true};
    std::size_t refused = 0;
    for (int q = 0; q < 400; ++q) {
        const Point p{0.5 - 0.02 * u(rng), 0.5 + 0.04 * (u(rng) - 0.5)};
        const bool says = dt.can_insert_on_side(p, corner_near(dt, p), side);
        const bool brute = cavity_on_side(dt, triangles, p, side);
        ck_assert_msg(!says || brute, "(%.17g, %.17g): allowed beside the lone vertex", p.x, p.y);
        refused += !brute;
    }
    ck_assert(refused > 40);
}
END_TEST

START_TEST(an_allowed_insertion_writes_only_its_side) {
    // Each allowed point is inserted; every record it changed must join
    // vertices of its side or the new vertex, before and after, and only
    // entry edges of its side (and the new one's) change.
    const std::vector<Point> pts = random_points(2000, 19);
    const std::vector<Point> more = random_points(test_light() ? 300 : 1200, 20);
    Delaunay dt = mesh_of(pts, pts.size() + more.size());
    std::size_t inserted = 0;
    for (const Point& p : more) {
        const Delaunay::Side side{0.5, p.x < 0.5};
        const VertexIndex near = corner_near(dt, p);
        if (!dt.can_insert_on_side(p, near, side)) continue;
        const QuadEdgeMesh& m = dt.mesh();
        const std::size_t records = m.record_count();
        std::vector<std::uint32_t> before;
        for (std::size_t r = 0; r < records; ++r) {
            const EdgeRef e = static_cast<EdgeRef>(4 * r);
            before.insert(before.end(), {m.org(e), m.dest(e), m.onext(e), m.onext(e + 1), m.onext(e + 2), m.onext(e + 3)});
        }
        std::vector<EdgeRef> entry;
        for (std::size_t v = 0; v < dt.vertex_count(); ++v) entry.push_back(dt.edge_of(static_cast<VertexIndex>(v)));
        const VertexIndex slot = dt.open_slots(1);
        QuadEdgeMesh::Arena arena = dt.edge_arena(1);
        dt.insert_in_slot(p, near, slot, arena);
        dt.close_edge_arena(arena);
        const auto ours = [&](VertexIndex v) { return v == slot || dt.on_side(v, side); };
        for (std::size_t r = 0; r < records; ++r) {
            const EdgeRef e = static_cast<EdgeRef>(4 * r);
            const std::uint32_t* b = &before[6 * r];
            const bool same = b[0] == m.org(e) && b[1] == m.dest(e) && b[2] == m.onext(e) && b[3] == m.onext(e + 1) &&
                              b[4] == m.onext(e + 2) && b[5] == m.onext(e + 3);
            if (same) continue;
            ck_assert_msg(ours(b[0]) && ours(b[1]), "record %zu changed, was %u-%u", r, b[0], b[1]);
            if (m.is_live(r)) ck_assert_msg(ours(m.org(e)) && ours(m.dest(e)), "record %zu now off the side", r);
        }
        for (std::size_t v = 0; v < entry.size(); ++v)
            if (dt.edge_of(static_cast<VertexIndex>(v)) != entry[v])
                ck_assert_msg(ours(static_cast<VertexIndex>(v)), "entry edge of %zu changed", v);
        ++inserted;
    }
    ck_assert(inserted > more.size() / 2);
    ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * (dt.vertex_count()) - 6);
}
END_TEST

namespace {

// One epoch of points, in order of time, inserted by sides: left points in
// the first slots, right ones after; each side in order of time on its own
// thread (or both on this one), what either side refused afterwards in order
// of time. Each side's search and insertion in one call (insert_on_side)
// or in two (can_insert_on_side, then insert_in_slot). Returns how many
// waited.
std::size_t insert_by_sides(Delaunay& dt, const std::vector<Point>& epoch, const std::vector<VertexIndex>& near,
                            unsigned threads, bool one_call = false) {
    const Delaunay::Side sides[2] = {{0.5, true}, {0.5, false}};
    std::vector<std::size_t> of_side[2];
    for (std::size_t i = 0; i < epoch.size(); ++i) of_side[epoch[i].x < 0.5 ? 0 : 1].push_back(i);
    const VertexIndex first = dt.open_slots(epoch.size());
    std::vector<VertexIndex> slot(epoch.size());
    VertexIndex next = first;
    for (const std::vector<std::size_t>& list : of_side)
        for (std::size_t i : list) slot[i] = next++;
    QuadEdgeMesh::Arena arena[2] = {dt.edge_arena(of_side[0].size()), dt.edge_arena(of_side[1].size())};
    std::vector<char> waiting(epoch.size(), 0);
    const auto side_job = [&](int s) {
        for (std::size_t i : of_side[s]) {
            if (one_call)
                waiting[i] = dt.insert_on_side(epoch[i], near[i], sides[s], slot[i], arena[s]) ? 0 : 1;
            else if (dt.can_insert_on_side(epoch[i], near[i], sides[s]))
                dt.insert_in_slot(epoch[i], near[i], slot[i], arena[s]);
            else
                waiting[i] = 1;
        }
    };
    if (threads > 1) {
        std::thread right(side_job, 1);
        side_job(0);
        right.join();
    } else {
        side_job(0);
        side_job(1);
    }
    std::size_t waited = 0;
    for (std::size_t i = 0; i < epoch.size(); ++i)
        if (waiting[i]) {
            dt.insert_in_slot(epoch[i], near[i], slot[i], arena[epoch[i].x < 0.5 ? 0 : 1]);
            ++waited;
        }
    dt.close_edge_arena(arena[0]);
    dt.close_edge_arena(arena[1]);
    return waited;
}

}  // namespace

START_TEST(two_sides_build_one_threads_records) {
    const std::vector<Point> pts = random_points(test_light() ? 4000 : 20000, 41);
    const std::vector<Point> epoch = random_points(test_light() ? 1500 : 6000, 42);
    const std::vector<Point> after = random_points(500, 43);
    std::vector<std::uint32_t> first;
    const struct {
        unsigned threads;
        bool one_call;
    } ways[] = {{1, false}, {2, false}, {2, false}, {1, true}, {2, true}};
    for (const auto& way : ways) {
        const unsigned threads = way.threads;
        Delaunay dt = mesh_of(pts, pts.size() + epoch.size() + after.size());
        std::vector<VertexIndex> near;
        for (const Point& p : epoch) near.push_back(corner_near(dt, p));
        const std::size_t waited = insert_by_sides(dt, epoch, near, threads, way.one_call);
        // Both ways are taken: most side by side, some waiting.
        ck_assert_msg(waited > 0 && waited < epoch.size() / 4, "%zu of %zu waited", waited, epoch.size());
        const std::size_t n = Delaunay::kGhosts + pts.size() + epoch.size();
        ck_assert_uint_eq(dt.vertex_count(), n);
        ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * n - 6);
        ck_assert_uint_eq(dt.mesh().live_count(), 3 * n - 7);  // four vertices on the hull
        const std::vector<std::uint32_t> layout = layout_of(dt);
        if (first.empty())
            first = layout;
        else
            ck_assert_msg(layout == first, "%u threads built other records%s", threads,
                          way.one_call ? " (search and insertion in one call)" : "");
        // The freed and spare records went back: plain insertions go on.
        VertexIndex v = Delaunay::kGhosts;
        for (const Point& p : after) v = dt.insert(p, v);
        ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * (n + after.size()) - 6);
    }
}
END_TEST

START_TEST(long_walks_beside_the_line) {
    // Points in a band around the line, each walk starting from one vertex
    // of its side at the band's foot: the walks run along the line, past
    // triangles the other thread is changing, and must not step into them
    // (ThreadSanitizer sees the reads if they do). The records are still
    // one thread's.
    const std::vector<Point> pts = random_points(test_light() ? 3000 : 12000, 51);
    std::vector<Point> epoch;
    for (const Point& p : random_points(test_light() ? 1000 : 4000, 52)) epoch.push_back({0.45 + 0.1 * p.x, p.y});
    std::vector<std::uint32_t> first;
    std::size_t waited[2] = {0, 0};
    for (unsigned threads : {1u, 2u}) {
        Delaunay dt = mesh_of(pts, pts.size() + epoch.size());
        // Each side's vertex nearest the line's foot.
        VertexIndex foot[2] = {0, 0};
        double best[2] = {2.0, 2.0};
        for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
            const Point& q = dt.point(v);
            const int s = q.x < 0.5 ? 0 : 1;
            const double d = std::fabs(q.x - 0.5) + q.y;
            if (d < best[s]) {
                best[s] = d;
                foot[s] = v;
            }
        }
        ck_assert(dt.on_side(foot[0], Delaunay::Side{0.5, true}) && dt.on_side(foot[1], Delaunay::Side{0.5, false}));
        std::vector<VertexIndex> near;
        for (const Point& p : epoch) near.push_back(foot[p.x < 0.5 ? 0 : 1]);
        waited[threads - 1] = insert_by_sides(dt, epoch, near, threads);
        ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * dt.vertex_count() - 6);
        if (first.empty())
            first = layout_of(dt);
        else
            ck_assert(layout_of(dt) == first);
    }
    ck_assert_uint_eq(waited[0], waited[1]);
    ck_assert(waited[0] > 0 && waited[0] < epoch.size());
}
END_TEST

START_TEST(slots_refuse_misuse) {
    const std::vector<Point> pts = random_points(100, 5);
    Delaunay dt = mesh_of(pts, pts.size() + 2);
    ck_assert_int_eq(static_cast<int>(dt.open_slots(0)), static_cast<int>(dt.vertex_count()));
    bool threw = false;
    try {
        dt.open_slots(3);  // room for 2
    } catch (const std::logic_error&) {
        threw = true;
    }
    ck_assert(threw && dt.vertex_count() == Delaunay::kGhosts + pts.size());
    const VertexIndex slot = dt.open_slots(2);
    QuadEdgeMesh::Arena arena = dt.edge_arena(2);
    const auto refuses = [&](const Point& p, VertexIndex s) {
        try {
            dt.insert_in_slot(p, Delaunay::kGhosts, s, arena);
        } catch (const std::logic_error&) {
            return true;
        }
        return false;
    };
    ck_assert(refuses({0.25, 0.75}, Delaunay::kGhosts));  // a vertex, not a slot
    ck_assert(refuses({0.25, 0.75}, slot + 2));           // beyond the slots
    ck_assert(refuses(pts[3], slot));                      // a duplicate point
    dt.insert_in_slot({0.25, 0.75}, Delaunay::kGhosts, slot, arena);
    ck_assert(refuses({0.75, 0.25}, slot));  // filled
    dt.insert_in_slot({0.75, 0.25}, Delaunay::kGhosts, slot + 1, arena);
    dt.close_edge_arena(arena);
    ck_assert_uint_eq(check_delaunay_mesh(dt), 2 * dt.vertex_count() - 6);
    // No arena beyond the records reserved.
    threw = false;
    try {
        dt.edge_arena(1u << 20);
    } catch (const std::logic_error&) {
        threw = true;
    }
    ck_assert(threw);
    // A weighted mesh has no slots.
    Delaunay weighted(pds::Box{0, 0, 1, 1}, true, 0.1);
    weighted.reserve(10);
    threw = false;
    try {
        weighted.open_slots(1);
    } catch (const std::logic_error&) {
        threw = true;
    }
    ck_assert(threw && !weighted.can_insert_on_side({0.5, 0.5}, 0, Delaunay::Side{0.6, true}));
}
END_TEST

Suite* delaunay_sides_suite() {
    Suite* s = suite_create("delaunay_sides");
    TCase* tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, search_agrees_with_every_triangle);
    tcase_add_test(tc, search_on_a_grid_of_ties);
    tcase_add_test(tc, search_sees_a_lone_vertex_across);
    tcase_add_test(tc, an_allowed_insertion_writes_only_its_side);
    tcase_add_test(tc, two_sides_build_one_threads_records);
    tcase_add_test(tc, long_walks_beside_the_line);
    tcase_add_test(tc, slots_refuse_misuse);
    suite_add_tcase(s, tc);
    return s;
}
