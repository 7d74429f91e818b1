// test_verify_field.cpp - the certificate under a variable radius: its
// spacing rule (each later point outside every earlier point's disk, with
// that point's radius) decided as a brute-force check of all pairs decides
// it, whatever the classes of the two radii, in the plane and on the torus;
// a hole found; and its work linear in the points when the radii span a
// wide range (counted, not timed: pairs examined per point).
#include <cmath>
#include <cstring>
#include <vector>

#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/torus_copies.hpp"
#include "radius/radius_field.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "verify/radius_layers.hpp"
#include "verify/verify.hpp"
#include "verify/verify_torus.hpp"

namespace {

// A pattern in insertion order: point k has radius r[k].
struct Disks {
    std::vector<pds::Point> p;
    std::vector<double> r;
};

pds::Torus unit_torus() {
    pds::Torus t;
    t.px = t.py = 1.0;
    return t;
}

// The regular triangulation of the disks, inserted in order (so vertex
// kGhosts + k is disk k), and each vertex's place in that order.
pds::Delaunay weighted_mesh(const Disks& d, const pds::Box& region, double rmax, std::vector<std::size_t>* rank) {
    pds::Delaunay dt(region, true, rmax);
    dt.reserve(d.p.size() + pds::Delaunay::kGhosts);
    rank->assign(pds::Delaunay::kGhosts, 0);
    std::uint32_t near = 0;
    for (std::size_t k = 0; k < d.p.size(); ++k) {
        near = dt.insert(d.p[k], d.r[k], near);
        ck_assert_uint_eq(near, pds::Delaunay::kGhosts + k);
        rank->push_back(k);
    }
    return dt;
}

// The plane: verify_pattern on the disks.
pds::VerifyReport verify_plane(const Disks& d, double rmax) {
    const pds::Box box{0, 0, 1, 1};
    std::vector<std::size_t> rank;
    const pds::Delaunay dt = weighted_mesh(d, box, rmax, &rank);
    return pds::verify_pattern(dt, box, rmax, &rank);
}

// The unit torus: verify_torus on a mesh of the points alone (no copies).
// The spacing is checked before the copies, so a report that does not blame
// the spacing is one that passed it.
pds::VerifyReport verify_on_torus(const Disks& d, double rmax) {
    const pds::TorusCopies copies(unit_torus(), rmax, true);
    std::vector<std::size_t> rank;
    const pds::Delaunay dt = weighted_mesh(d, copies.largest_region(), rmax, &rank);
    const std::vector<std::uint8_t> is_copy(dt.vertex_count(), 0);
    return pds::verify_torus(dt, copies, is_copy, rmax, &rank);
}

bool blames_spacing(const pds::VerifyReport& rep) {
    return !rep.valid && std::strstr(rep.failure.c_str(), "inside an earlier point's disk") != nullptr;
}

// Brute force (on the torus over all nine copies): disk b's point inside
// disk a's, a earlier.
bool inside(const Disks& d, std::size_t a, std::size_t b, bool torus) {
    for (int sx = torus ? -1 : 0; sx <= (torus ? 1 : 0); ++sx)
        for (int sy = torus ? -1 : 0; sy <= (torus ? 1 : 0); ++sy)
            if (pds::compare_distance(d.p[b], pds::Point{d.p[a].x + sx, d.p[a].y + sy}, d.r[a]) < 0) return true;
    return false;
}

// The later points that lie inside an earlier point's disk.
std::vector<bool> later_inside(const Disks& d, bool torus) {
    std::vector<bool> in(d.p.size(), false);
    for (std::size_t b = 0; b < d.p.size(); ++b)
        for (std::size_t a = 0; a < b && !in[b]; ++a) in[b] = inside(d, a, b, torus);
    return in;
}

// Disks i and j, in either order, break the rule.
bool clash(const Disks& d, std::size_t i, std::size_t j, bool torus) {
    return i < j ? inside(d, i, j, torus) : inside(d, j, i, torus);
}

// Grid values (as the torus keeps them) in [0, 1).
pds::Point random_point(pds::Rng& rng) {
    const pds::Point p{pds::Torus::snap(rng.next_double()), pds::Torus::snap(rng.next_double())};
    return pds::Point{p.x < 1.0 ? p.x : 0.0, p.y < 1.0 ? p.y : 0.0};
}

// Up to 150 disks with radii log-uniform over 2^-13 .. 2^-3 (ten classes),
// each later point outside the earlier disks (dart throwing), then one
// later point b moved onto the circle of an earlier point a, and by one grid
// step inside or outside it, where it breaks the rule with no other disk.
// `arrangement` picks the pair: 0 a's radius under an eighth of b's, 1 over
// eight times b's, 2 the two in adjacent classes; 3 moves nothing.
Disks random_disks(std::uint64_t seed, int arrangement, bool torus) {
    pds::Rng rng(seed);
    Disks d;
    for (int tries = 0; d.p.size() < 150 && tries < 20000; ++tries) {
        const int k = static_cast<int>(rng.next_double() * 10.0);
        d.r.push_back(std::ldexp(1.0 + rng.next_double(), -13 + k));
        d.p.push_back(random_point(rng));
        bool free = true;
        for (std::size_t a = 0; a + 1 < d.p.size() && free; ++a) free = !inside(d, a, d.p.size() - 1, torus);
        if (!free) d.p.pop_back(), d.r.pop_back();
    }
    ck_assert_uint_gt(d.p.size(), 60);
    if (arrangement == 3) return d;
    const auto classes_apart = [](double ra, double rb) { return std::abs(std::ilogb(ra) - std::ilogb(rb)); };
    for (int tries = 0; tries < 100000; ++tries) {
        const std::size_t b = 1 + static_cast<std::size_t>(rng.next_double() * static_cast<double>(d.p.size() - 1));
        const std::size_t a = static_cast<std::size_t>(rng.next_double() * static_cast<double>(b));
        const bool fits = arrangement == 0   ? d.r[a] < d.r[b] / 8.0
                          : arrangement == 1 ? d.r[a] > d.r[b] * 8.0
                                             : classes_apart(d.r[a], d.r[b]) == 1;
        if (!fits) continue;
        const double angle = 6.283185307179586 * rng.next_double();
        pds::Point q{pds::Torus::snap(d.p[a].x + d.r[a] * std::cos(angle)),
                     pds::Torus::snap(d.p[a].y + d.r[a] * std::sin(angle))};
        // One grid step along x, towards a or away from it.
        q.x += (rng.next_double() < 0.5 ? 1.0 : -1.0) * pds::Torus::kQuantum;
        if (torus) q = unit_torus().wrap(q);
        if (!(q.x >= 0.0 && q.x < 1.0 && q.y >= 0.0 && q.y < 1.0)) continue;
        Disks moved = d;
        moved.p[b] = q;
        bool alone = true;
        for (std::size_t c = 0; c < d.p.size() && alone; ++c)
            alone = c == a || c == b || (!clash(moved, b, c, torus) && (moved.p[c].x != q.x || moved.p[c].y != q.y));
        if (alone) return moved;
    }
    ck_abort_msg("no pair in arrangement %d", arrangement);
    return d;
}

// Runs s to the end and checks it; returns the report.
pds::VerifyReport run_and_verify(pds::Sampler& s) {
    bool maximal = false;
    s.add_points(0, &maximal);
    ck_assert(maximal);
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.valid && rep.maximal, "%s", rep.failure.c_str());
    return rep;
}

// 0.005 for x < 0.15, 0.2 for x > 0.5, geometric between: 40:1 over six
// classes, three quarters of the points where the radius is smallest.
double ramp(void*, double x, double) {
    const double t = x < 0.15 ? 0.0 : x > 0.5 ? 1.0 : (x - 0.15) / 0.35;
    return 0.005 * std::pow(40.0, t);
}
// 0.01 .. 0.16 (the torus's limit, 16:1), periodic in x.
double wave(void*, double x, double) {
    const double s = std::sin(3.141592653589793 * x);
    return 0.01 * std::pow(16.0, s * s);
}

}  // namespace

START_TEST(earlier_radius_decides) {
    // Exactly on the earlier disk's circle is allowed; one step inside is
    // not; the later point's own radius plays no part.
    const double big = 0.125, small = 0x1.0p-10;
    const double rmax = big;
    // Large before small: the small point must keep out of the large disk.
    ck_assert(verify_plane({{{0.5, 0.5}, {0.625, 0.5}}, {big, small}}, rmax).valid);
    ck_assert(blames_spacing(verify_plane({{{0.5, 0.5}, {std::nextafter(0.625, 0.0), 0.5}}, {big, small}}, rmax)));
    // Small before large: only the small disk counts, 2^-10 wide.
    ck_assert(verify_plane({{{0.5, 0.5}, {0.5 + small, 0.5}}, {small, big}}, rmax).valid);
    ck_assert(blames_spacing(verify_plane({{{0.5, 0.5}, {std::nextafter(0.5 + small, 0.0), 0.5}}, {small, big}}, rmax)));
    // Radii 1024:1 apart, and in adjacent classes (0.25 and just below).
    const double tiny = 0x1.0p-12, below = std::nextafter(0.25, 0.0);
    ck_assert(blames_spacing(verify_plane({{{0.5, 0.5}, {0.5, std::nextafter(0.5 + tiny, 0.0)}}, {tiny, 0.25}}, 0.25)));
    ck_assert(verify_plane({{{0.5, 0.5}, {0.5, 0.5 + tiny}}, {tiny, 0.25}}, 0.25).valid);
    ck_assert(blames_spacing(verify_plane({{{0.5, 0.5}, {0.5, 0.74}}, {0.25, below}}, 0.25)));
    ck_assert(blames_spacing(verify_plane({{{0.5, 0.5}, {0.5, 0.74}}, {below, 0.25}}, 0.25)));
    ck_assert(verify_plane({{{0.5, 0.5}, {0.5, 0.75}}, {below, 0.25}}, 0.25).valid);
}
END_TEST

START_TEST(radius_must_be_positive_and_finite) {
    // A radius of NaN or 0 has no disk the rule could use: reported, not
    // passed (NaN compares false with every distance).
    for (double bad : {std::nan(""), 0.0}) {
        const pds::VerifyReport rep = verify_plane({{{0.25, 0.25}, {0.75, 0.75}}, {0.1, bad}}, 0.1);
        ck_assert(!rep.valid);
        ck_assert_msg(std::strstr(rep.failure.c_str(), "positive finite") != nullptr, "%s", rep.failure.c_str());
        ck_assert_uint_eq(rep.vertex, pds::Delaunay::kGhosts + 1);
    }
}
END_TEST

START_TEST(earlier_radius_decides_across_the_wrap) {
    // 2^-8 from each side of the wrap: 2^-7 apart across it.
    const double q = pds::Torus::kQuantum, r = 0x1.0p-7, big = 0.125;
    const pds::Point a{0x1.0p-8, 0.5}, b{1.0 - 0x1.0p-8, 0.5}, nearer{1.0 - 0x1.0p-8 + q, 0.5};
    ck_assert(!blames_spacing(verify_on_torus({{a, b}, {r, big}}, big)));
    ck_assert(blames_spacing(verify_on_torus({{a, nearer}, {r, big}}, big)));
    ck_assert(blames_spacing(verify_on_torus({{a, b}, {big, r}}, big)));  // 2^-7 inside 0.125
    const pds::VerifyReport rep = verify_on_torus({{a, nearer}, {big, r}}, big);
    ck_assert(blames_spacing(rep));
    ck_assert_ptr_nonnull(std::strstr(rep.failure.c_str(), "torus"));
}
END_TEST

START_TEST(layers_find_every_close_pair) {
    // Every pair closer than the larger of its radii is visited from the
    // point in the lower class (or from either, in one class), with the
    // shift of the copy that is close; over grids of both layouts.
    for (int torus = 0; torus <= 1; ++torus) {
        for (std::uint64_t seed = 1; seed <= (test_light() ? 2u : 6u); ++seed) {
            const Disks d = random_disks(seed, 3, torus != 0);
            const pds::RadiusLayers::RadiusOf radius_of = [&](std::size_t k) { return d.r[k]; };
            const pds::RadiusLayers layers = torus ? pds::RadiusLayers(d.p, 0, unit_torus(), radius_of)
                                                   : pds::RadiusLayers(d.p, 0, radius_of);
            ck_assert_uint_ge(layers.layer_count(), 8);
            ck_assert_uint_gt(layers.dense_count(), 0);
            ck_assert_uint_lt(layers.dense_count(), layers.layer_count());
            for (std::size_t i = 0; i < d.p.size(); ++i) {
                std::vector<std::vector<bool>> seen(d.p.size(), std::vector<bool>(9, false));
                layers.for_each_near(d.p[i], d.r[i], [&](std::uint32_t j, int sx, int sy, bool same) {
                    ck_assert(same == (std::ilogb(d.r[j]) == std::ilogb(d.r[i])));
                    seen[j][static_cast<std::size_t>(3 * (sx + 1) + sy + 1)] = true;
                });
                for (std::size_t j = 0; j < d.p.size(); ++j) {
                    if (j == i || std::ilogb(d.r[j]) < std::ilogb(d.r[i])) continue;
                    for (int sx = -torus; sx <= torus; ++sx)
                        for (int sy = -torus; sy <= torus; ++sy) {
                            const pds::Point c{d.p[j].x + sx, d.p[j].y + sy};
                            if (pds::compare_distance(d.p[i], c, std::fmax(d.r[i], d.r[j])) < 0)
                                ck_assert_msg(seen[j][static_cast<std::size_t>(3 * (sx + 1) + sy + 1)],
                                              "seed %d torus %d: pair %zu %zu missed", static_cast<int>(seed), torus, i, j);
                        }
                }
            }
        }
    }
}
END_TEST

START_TEST(verdicts_match_brute_force) {
    const int seeds = test_light() ? 8 : 40;
    for (int torus = 0; torus <= 1; ++torus) {
        int broken = 0;
        for (int seed = 1; seed <= seeds; ++seed) {
            const int arrangement = seed % 4;
            const Disks d = random_disks(static_cast<std::uint64_t>(seed), arrangement, torus != 0);
            double rmax = 0.0;
            for (double r : d.r) rmax = std::fmax(rmax, r);
            const std::vector<bool> inside = later_inside(d, torus != 0);
            bool any = false;
            for (bool b : inside) any = any || b;
            const pds::VerifyReport rep = torus ? verify_on_torus(d, rmax) : verify_plane(d, rmax);
            ck_assert_msg(blames_spacing(rep) == any, "seed %d torus %d: %s", seed, torus, rep.failure.c_str());
            if (!torus && !any) ck_assert_msg(rep.valid, "seed %d: %s", seed, rep.failure.c_str());
            // The point named is one that lies inside an earlier disk.
            if (any) ck_assert(inside[rep.vertex - pds::Delaunay::kGhosts]);
            broken += any ? 1 : 0;
        }
        // Both verdicts seen, each several times.
        ck_assert_msg(broken >= seeds / 8 && broken <= seeds - seeds / 4, "%d of %d broken", broken, seeds);
    }
}
END_TEST

START_TEST(hole_is_not_maximal) {
    // A maximal pattern under the 40:1 ramp, then the same without a point
    // no other disk covers: its position is left uncovered.
    pds::Sampler s(1.0, 11);
    s.set_field(pds::RadiusField::function(ramp, nullptr, 0.005, 0.2));
    run_and_verify(s);
    Disks all;
    all.p.resize(s.count());
    all.r.resize(s.count());
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    s.copy_radii(0, s.count(), all.r.data());
    for (std::size_t k = 0; k < s.count(); ++k) all.p[k] = {xy[2 * k], xy[2 * k + 1]};
    int dropped = 0;
    for (std::size_t drop = 0; drop < all.p.size() && dropped < (test_light() ? 2 : 6); drop += 97) {
        bool covered = false;
        for (std::size_t j = 0; j < all.p.size(); ++j)
            covered = covered || (j != drop && pds::compare_distance(all.p[drop], all.p[j], all.r[j]) <= 0);
        if (covered) continue;
        Disks fewer = all;
        fewer.p.erase(fewer.p.begin() + static_cast<std::ptrdiff_t>(drop));
        fewer.r.erase(fewer.r.begin() + static_cast<std::ptrdiff_t>(drop));
        const pds::VerifyReport rep = verify_plane(fewer, 0.2);
        ck_assert_msg(rep.valid, "%s", rep.failure.c_str());
        ck_assert(!rep.maximal);
        ++dropped;
    }
    ck_assert_int_gt(dropped, 0);
}
END_TEST

START_TEST(work_is_linear_with_a_wide_field) {
    // Under the 40:1 ramp one grid with cells 0.2 wide would put each point
    // where the radius is 0.005 next to ~2000 others; classes of radii keep
    // it to a few per class.
    pds::Sampler s(1.0, 5);
    s.set_field(pds::RadiusField::function(ramp, nullptr, 0.005, 0.2));
    const pds::VerifyReport rep = run_and_verify(s);
    const double per_point = static_cast<double>(rep.pairs_examined) / static_cast<double>(s.count());
    ck_assert_uint_gt(s.count(), 3000);
    ck_assert_msg(per_point < 40.0, "%.1f pairs examined per point (%zu points)", per_point, s.count());
    // The index the check builds stays small: a few bytes a point.
    const pds::Delaunay& dt = s.jones().mesh();
    const pds::RadiusLayers layers(dt.points(), pds::Delaunay::kGhosts,
                                   [&](std::size_t v) { return dt.radius(static_cast<pds::VertexIndex>(v)); });
    ck_assert_uint_ge(layers.layer_count(), 6);
    ck_assert_uint_le(layers.bytes(), 16 * s.count());
}
END_TEST

START_TEST(work_is_linear_with_a_field_on_the_torus) {
    pds::Sampler s(1.0, 6);
    s.set_periodic(true);
    s.set_field(pds::RadiusField::function(wave, nullptr, 0.01, 0.16));
    const pds::VerifyReport rep = run_and_verify(s);
    const double per_point = static_cast<double>(rep.pairs_examined) / static_cast<double>(s.count());
    ck_assert_msg(per_point < 40.0, "%.1f pairs examined per point (%zu points)", per_point, s.count());
}
END_TEST

Suite* verify_field_suite() {
    Suite* s = suite_create("verify_field");
    TCase* rule = tcase_create("rule");
    tcase_set_timeout(rule, 120);
    tcase_add_test(rule, earlier_radius_decides);
    tcase_add_test(rule, radius_must_be_positive_and_finite);
    tcase_add_test(rule, earlier_radius_decides_across_the_wrap);
    tcase_add_test(rule, layers_find_every_close_pair);
    tcase_add_test(rule, verdicts_match_brute_force);
    suite_add_tcase(s, rule);
    TCase* hole = tcase_create("hole");
    tcase_set_timeout(hole, 120);
    tcase_add_test(hole, hole_is_not_maximal);
    suite_add_tcase(s, hole);
    TCase* work = tcase_create("work");
    tcase_set_timeout(work, 120);
    tcase_add_test(work, work_is_linear_with_a_wide_field);
    tcase_add_test(work, work_is_linear_with_a_field_on_the_torus);
    suite_add_tcase(s, work);
    return s;
}
