// test_regular.cpp - the weighted mesh (regular triangulation, delaunay.hpp):
// exact regularity by a brute-force check of every triangle against every
// disk, hidden disks (at insertion, by 3-1 flips, and on a line through the
// new disk), independence of the insertion order, and equal radii giving the
// unweighted mesh record for record.
#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

#include "mesh/delaunay.hpp"
#include "disk_patterns.hpp"
#include "mesh_checks.hpp"
#include "core/predicates.hpp"
#include "suites.hpp"

namespace {

pds::Delaunay build(const std::vector<Disk>& disks) { return weighted_mesh(disks); }

// Every inner triangle's orthocircle conflicts with no disk, hidden or not:
// with the mesh invariants, the mesh is the regular triangulation of them all.
// Returns the triangles as sorted vertex triples of the disks' indices.
std::set<std::array<std::uint32_t, 3>> check_regular_brute(const pds::Delaunay& dt) {
    check_delaunay_mesh(dt);
    const pds::QuadEdgeMesh& m = dt.mesh();
    std::set<std::array<std::uint32_t, 3>> triangles;
    for (std::size_t rec = 0; rec < m.record_count(); ++rec) {
        if (!m.is_live(rec)) continue;
        for (std::uint32_t k = 0; k < 4; k += 2) {
            const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * rec + k);
            if (m.lnext(m.lnext(m.lnext(e))) != e) continue;  // the outer face
            const std::uint32_t a = m.org(e), b = m.dest(e), c = m.dest(m.lnext(e));
            std::array<std::uint32_t, 3> t{a, b, c};
            std::sort(t.begin(), t.end());
            if (!triangles.insert(t).second) continue;
            for (std::uint32_t q = 0; q < dt.vertex_count(); ++q) {
                if (q == a || q == b || q == c) continue;
                ck_assert_int_le(pds::power_test(dt.point(a), dt.radius(a), dt.point(b), dt.radius(b),
                                                 dt.point(c), dt.radius(c), dt.point(q), dt.radius(q)),
                                 0);
            }
        }
    }
    return triangles;
}

std::vector<Disk> rsa(std::size_t darts, double (*field)(const pds::Point&), std::uint64_t seed) {
    return rsa_disks(darts, field, seed);
}

}  // namespace

START_TEST(random_disks_are_regular) {
    // Radii up to the spacing: many disks end hidden.
    const std::size_t n = test_light() ? 150 : 400;
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Disk> disks;
    for (std::size_t i = 0; i < n; ++i) disks.push_back({{u(rng), u(rng)}, 0.08 * u(rng)});
    const pds::Delaunay dt = build(disks);
    check_regular_brute(dt);
    ck_assert_uint_gt(dt.hidden_count(), n / 20);
}
END_TEST

START_TEST(heavy_disks_hide_a_light_one) {
    // A light disk, then three heavier ones around it that the sampler's rule
    // allows (each outside the earlier disks): the first loses its cell.
    std::vector<Disk> disks{{{0.5, 0.5}, 0.01}};
    const double r = 0.016, d = 0.01;
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0943951023931953 * k + 0.1;
        disks.push_back({{0.5 + d * std::cos(a), 0.5 + d * std::sin(a)}, r});
    }
    const pds::Delaunay dt = build(disks);
    check_regular_brute(dt);
    const std::uint32_t first = pds::Delaunay::kGhosts;
    ck_assert(dt.is_hidden(first));
    ck_assert_uint_eq(dt.hidden_count(), 1);
    ck_assert(!dt.is_hidden(dt.visible(first)));
}
END_TEST

START_TEST(insertion_order_does_not_matter) {
    // The sampler's rule under a step field (1:4): later heavy disks near the
    // step hide light ones. Inserted in time order and shuffled (disks then
    // hidden at insertion), the mesh is the same regular triangulation.
    const std::vector<Disk> disks = rsa(test_light() ? 600 : 20000, step_field, 7);
    const pds::Delaunay in_time = build(disks);
    std::vector<std::size_t> order(disks.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::mt19937_64 rng(9);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Disk> shuffled;
    for (std::size_t i : order) shuffled.push_back(disks[i]);
    const pds::Delaunay mixed = build(shuffled);
    // Name triangles by disk indices in the time order.
    const auto named = [&](const pds::Delaunay& dt, const std::vector<std::size_t>* perm) {
        std::set<std::array<std::uint32_t, 3>> out;
        for (auto t : check_regular_brute(dt)) {
            for (auto& v : t)
                if (v >= pds::Delaunay::kGhosts && perm)
                    v = static_cast<std::uint32_t>((*perm)[v - pds::Delaunay::kGhosts] + pds::Delaunay::kGhosts);
            std::sort(t.begin(), t.end());
            out.insert(t);
        }
        return out;
    };
    ck_assert(named(in_time, nullptr) == named(mixed, &order));
    ck_assert_uint_eq(in_time.hidden_count(), mixed.hidden_count());
}
END_TEST

START_TEST(equal_radii_give_the_unweighted_mesh) {
    // Random points and a scrambled grid (points on edges, cocircular
    // squares): the same records, links and entry edges.
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<pds::Point> pts;
        std::mt19937_64 rng(13);
        if (pass == 0) {
            std::uniform_real_distribution<double> u(0.0, 1.0);
            for (int i = 0; i < (test_light() ? 400 : 2000); ++i) pts.push_back({u(rng), u(rng)});
        } else {
            const int k = test_light() ? 10 : 20;
            for (int i = 0; i < k; ++i)
                for (int j = 0; j < k; ++j) pts.push_back({i / double(k - 1), j / double(k - 1)});
            std::shuffle(pts.begin(), pts.end(), rng);
        }
        pds::Delaunay plain(pds::Box{0, 0, 1, 1});
        pds::Delaunay weighted(pds::Box{0, 0, 1, 1}, true);
        plain.reserve(pts.size() + 4);
        weighted.reserve(pts.size() + 4);
        std::uint32_t a = 0, b = 0;
        for (const pds::Point& p : pts) {
            a = plain.insert(p, a);
            b = weighted.insert(p, 0.01, b);
        }
        ck_assert_uint_eq(weighted.hidden_count(), 0);
        const pds::QuadEdgeMesh& m = plain.mesh();
        const pds::QuadEdgeMesh& w = weighted.mesh();
        ck_assert_uint_eq(m.record_count(), w.record_count());
        for (std::size_t rec = 0; rec < m.record_count(); ++rec) {
            ck_assert_int_eq(m.is_live(rec), w.is_live(rec));
            if (!m.is_live(rec)) continue;
            for (std::uint32_t k = 0; k < 4; ++k) {
                const pds::EdgeRef e = static_cast<pds::EdgeRef>(4 * rec + k);
                ck_assert_uint_eq(m.onext(e), w.onext(e));
                if (k % 2 == 0) ck_assert_uint_eq(m.org(e), w.org(e));
            }
        }
        for (std::uint32_t v = 0; v < plain.vertex_count(); ++v) ck_assert_uint_eq(plain.edge_of(v), weighted.edge_of(v));
    }
}
END_TEST

START_TEST(a_disk_between_two_on_a_line_is_hidden) {
    // Three disks on a line, the middle one inside the power of the heavy one
    // beside it: it is hidden, though it lies on the segment between its
    // neighbours, not inside a triangle (the insertion looped before). Every
    // order of the three; then a line of 60 disks with random radii among 40
    // off it, in 4 orders.
    const std::vector<Disk> three{{{0.67, 0.5}, 0.0155}, {{0.669, 0.5}, 0.0418}, {{0.8, 0.5}, 0.0162}};
    std::vector<std::size_t> order{0, 1, 2};
    do {
        std::vector<Disk> disks;
        for (std::size_t i : order) disks.push_back(three[i]);
        const pds::Delaunay dt = build(disks);
        check_regular_brute(dt);
        ck_assert_uint_eq(dt.hidden_count(), 1);
        for (std::size_t k = 0; k < 3; ++k)
            ck_assert(dt.is_hidden(static_cast<std::uint32_t>(k + pds::Delaunay::kGhosts)) == (order[k] == 0));
    } while (std::next_permutation(order.begin(), order.end()));
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Disk> mixed;
    for (int i = 0; i < 60; ++i) mixed.push_back({{u(rng), 0.5}, 0.05 * u(rng)});
    for (int i = 0; i < 40; ++i) mixed.push_back({{u(rng), u(rng)}, 0.05 * u(rng)});
    std::size_t hidden = 0;
    for (int round = 0; round < 4; ++round) {
        std::shuffle(mixed.begin(), mixed.end(), rng);
        const pds::Delaunay dt = build(mixed);
        check_regular_brute(dt);
        if (round == 0) hidden = dt.hidden_count();
        ck_assert_uint_eq(dt.hidden_count(), hidden);
    }
    ck_assert_uint_gt(hidden, 10);
}
END_TEST

START_TEST(weighted_grid_with_ties) {
    // A grid with two radii in a pattern: many exact ties in the power test
    // (lifted points on one plane) and points on edges.
    std::vector<Disk> disks;
    const int k = test_light() ? 8 : 16;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
            disks.push_back({{i / double(k - 1), j / double(k - 1)}, (i + 2 * j) % 3 == 0 ? 0.05 : 0.025});
    std::mt19937_64 rng(17);
    std::shuffle(disks.begin(), disks.end(), rng);
    check_regular_brute(build(disks));
}
END_TEST

Suite* regular_suite() {
    Suite* s = suite_create("regular");
    TCase* t = tcase_create("weighted insertion");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, random_disks_are_regular);
    tcase_add_test(t, heavy_disks_hide_a_light_one);
    tcase_add_test(t, insertion_order_does_not_matter);
    tcase_add_test(t, equal_radii_give_the_unweighted_mesh);
    tcase_add_test(t, weighted_grid_with_ties);
    tcase_add_test(t, a_disk_between_two_on_a_line_is_hidden);
    suite_add_tcase(s, t);
    return s;
}
