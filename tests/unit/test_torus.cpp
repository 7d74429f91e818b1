// test_torus.cpp - the periodic domain's internals: the grid arithmetic, the
// torus certificate (it must catch a close pair across the wrap, a missing
// copy and a gap), and the margin widening that keeps real cells true.
#include <cmath>
#include <cstring>
#include <vector>

#include "mesh/delaunay.hpp"
#include "domain/frame.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "mesh/torus_copies.hpp"
#include "verify/verify_torus.hpp"

namespace {

// The torus [0,1)^2 in the internal frame (the unit square scales by 1).
pds::Torus unit_torus() {
    pds::Torus t;
    t.px = t.py = 1.0;
    return t;
}

// The mesh of `real` points and all their copies within the margin, as the
// sampler keeps it; copies for which drop(copy) is true are left out.
template <class Drop>
pds::Delaunay torus_mesh(const std::vector<pds::Point>& real, const pds::TorusCopies& copies,
                         std::vector<std::uint8_t>& is_copy, const Drop& drop) {
    pds::Delaunay dt(copies.largest_region());
    dt.reserve(64 * real.size() + pds::Delaunay::kGhosts);
    is_copy.assign(pds::Delaunay::kGhosts, 0);
    std::uint32_t near = 0;
    for (const pds::Point& p : real) {
        near = dt.insert(p, near);
        is_copy.push_back(0);
    }
    for (const pds::Point& p : real)
        copies.for_each_copy(p, copies.margin(), -1.0, [&](const pds::Point& c, int, int) {
            if (drop(c)) return;
            near = dt.insert(c, near);
            is_copy.push_back(1);
        });
    return dt;
}

std::vector<pds::Point> maximal_torus_points(double r, std::uint64_t seed) {
    pds::Sampler s(r, seed);
    s.set_periodic(true);
    bool maximal = false;
    s.add_points(0, &maximal);
    ck_assert(maximal);
    std::vector<pds::Point> pts(s.count());
    for (std::size_t k = 0; k < pts.size(); ++k) pts[k] = s.jones().point(k);
    return pts;
}

}  // namespace

START_TEST(grid_snap_and_wrap_are_exact) {
    const pds::Torus t = unit_torus();
    const double q = pds::Torus::kQuantum;
    ck_assert(pds::Torus::snap(0.3) == std::nearbyint(0.3 / q) * q);
    // Just below 0 wraps to just below 1, exactly one period up.
    const pds::Point w = t.wrap(pds::Point{-q, 1.0});
    ck_assert(w.x == 1.0 - q && w.y == 0.0);
    // A period that is not on the grid (0.1) is rounded down onto it, and
    // x0 + period stays within the user's x1.
    pds::Frame f(pds::Box{0.0, 0.0, 0.1, 0.1}, 0.01);
    f.set_periodic(true);
    const pds::Torus& ft = f.torus();
    ck_assert(ft.on());
    ck_assert(pds::Torus::snap(ft.px) == ft.px);
    ck_assert(ft.px <= f.box().x1 - f.box().x0 && ft.px > f.box().x1 - f.box().x0 - 2 * q);
}
END_TEST

START_TEST(close_pair_across_the_wrap_is_invalid) {
    const double r = 0.125;
    // Two points: their cells are wide, so copies are kept at the widest margin.
    pds::TorusCopies copies(unit_torus(), r);
    while (copies.next_margin() > copies.margin()) copies.set_margin(copies.next_margin());
    std::vector<std::uint8_t> is_copy;
    const auto keep = [](const pds::Point&) { return false; };
    // 0.0625 + (1 - 0.9375) = 0.125: exactly R across the wrap is allowed.
    pds::Delaunay ok = torus_mesh({{0.0625, 0.5}, {0.9375, 0.5}}, copies, is_copy, keep);
    ck_assert(pds::verify_torus(ok, copies, is_copy, r).valid);
    // One grid step nearer across the wrap.
    pds::Delaunay bad = torus_mesh({{0.0625, 0.5}, {0.9375 + 0x1.0p-50, 0.5}}, copies, is_copy, keep);
    const pds::VerifyReport rep = pds::verify_torus(bad, copies, is_copy, r);
    ck_assert(!rep.valid);
    ck_assert_ptr_nonnull(std::strstr(rep.failure.c_str(), "closer"));
}
END_TEST

START_TEST(missing_copy_is_invalid) {
    const double r = 0.05;
    const std::vector<pds::Point> pts = maximal_torus_points(r, 3);
    pds::TorusCopies copies(unit_torus(), r);
    std::vector<std::uint8_t> is_copy;
    pds::Delaunay full = torus_mesh(pts, copies, is_copy, [](const pds::Point&) { return false; });
    const pds::VerifyReport good = pds::verify_torus(full, copies, is_copy, r);
    ck_assert_msg(good.valid && good.maximal, "%s", good.failure.c_str());
    // Leave out the copies left of the domain: real cells near x = 0 would
    // reach past them, and the pattern is no longer described exactly.
    pds::Delaunay holed = torus_mesh(pts, copies, is_copy, [](const pds::Point& c) { return c.x < 0.0; });
    const pds::VerifyReport bad = pds::verify_torus(holed, copies, is_copy, r);
    ck_assert(!bad.valid);
    ck_assert_ptr_nonnull(std::strstr(bad.failure.c_str(), "copies"));
}
END_TEST

START_TEST(gap_is_not_maximal) {
    const double r = 0.05;
    std::vector<pds::Point> pts = maximal_torus_points(r, 5);
    const pds::TorusCopies copies(unit_torus(), r);
    std::vector<std::uint8_t> is_copy;
    // Without a point near the corner (0, 0), there is room across the wrap.
    std::vector<pds::Point> fewer;
    for (const pds::Point& p : pts) {
        const double dx = std::min(p.x, 1.0 - p.x), dy = std::min(p.y, 1.0 - p.y);
        if (dx * dx + dy * dy > 0.03 * 0.03) fewer.push_back(p);
    }
    ck_assert_uint_lt(fewer.size(), pts.size());
    pds::Delaunay dt = torus_mesh(fewer, copies, is_copy, [](const pds::Point&) { return false; });
    const pds::VerifyReport rep = pds::verify_torus(dt, copies, is_copy, r);
    ck_assert_msg(rep.valid, "%s", rep.failure.c_str());
    ck_assert(!rep.maximal);
}
END_TEST

START_TEST(margin_widens_from_the_first_point) {
    // Without the dart stage the Jones loop starts from one point, whose
    // cell is the whole torus: the margin must widen until cells are true.
    const double r = 0.1;
    pds::Sampler s(r, 7);
    s.set_periodic(true);
    s.skip_dart_stage();
    ck_assert(s.step());
    ck_assert(s.jones().torus_copies().margin() > 4.0 * r);
    bool maximal = false;
    s.add_points(0, &maximal);
    ck_assert(maximal);
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.valid && rep.maximal, "%s", rep.failure.c_str());
}
END_TEST

START_TEST(dart_stage_sees_across_the_wrap) {
    // Many small patterns, each checked on the torus while still in the dart
    // stage and at the end: a dart grid that missed its padding copies would
    // place a point too close to one across the edge.
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        pds::Sampler s(0.09, seed);
        s.set_periodic(true);
        bool maximal = false;
        s.add_points(20, &maximal);
        ck_assert(s.in_dart_stage());
        pds::VerifyReport rep = s.verify();
        ck_assert_msg(rep.valid, "seed %llu: %s", static_cast<unsigned long long>(seed), rep.failure.c_str());
        s.add_points(0, &maximal);
        rep = s.verify();
        ck_assert_msg(rep.valid && rep.maximal, "seed %llu: %s", static_cast<unsigned long long>(seed),
                      rep.failure.c_str());
    }
}
END_TEST

Suite* torus_suite() {
    Suite* s = suite_create("torus");
    TCase* tc = tcase_create("torus");
    tcase_add_test(tc, grid_snap_and_wrap_are_exact);
    tcase_add_test(tc, close_pair_across_the_wrap_is_invalid);
    tcase_add_test(tc, missing_copy_is_invalid);
    tcase_add_test(tc, gap_is_not_maximal);
    tcase_add_test(tc, margin_widens_from_the_first_point);
    tcase_add_test(tc, dart_stage_sees_across_the_wrap);
    suite_add_tcase(s, tc);
    return s;
}
