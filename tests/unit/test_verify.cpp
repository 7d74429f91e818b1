// test_verify.cpp - the certificate must catch what it claims to catch: a
// close pair, a missing point, an uncovered side or corner; and accept a
// maximal pattern.
#include <cmath>
#include <cstring>
#include <vector>

#include "mesh/delaunay.hpp"
#include "jones/jones_stage.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"
#include "verify/verify.hpp"

namespace {

pds::Delaunay build(const std::vector<pds::Point>& pts, const pds::Box& box) {
    pds::Delaunay dt(box);
    dt.reserve(pts.size() + pds::Delaunay::kGhosts);
    std::uint32_t near = 0;
    for (const pds::Point& p : pts) near = dt.insert(p, near);
    return dt;
}

}  // namespace

START_TEST(close_pair_is_invalid) {
    const pds::Box box{0, 0, 1, 1};
    const double r = 0.125;  // exact in binary, so the pair below is exactly R apart
    const pds::VerifyReport ok = pds::verify_pattern(build({{0.5, 0.5}, {0.625, 0.5}}, box), box, r);
    ck_assert(ok.valid);  // exactly R apart is allowed
    const pds::VerifyReport bad =
        pds::verify_pattern(build({{0.5, 0.5}, {std::nextafter(0.625, 0.0), 0.5}}, box), box, r);
    ck_assert(!bad.valid);
    ck_assert_ptr_nonnull(std::strstr(bad.failure.c_str(), "closer"));
}
END_TEST

START_TEST(point_outside_is_invalid) {
    const pds::Box box{0, 0, 1, 1};
    const pds::VerifyReport bad = pds::verify_pattern(build({{0.5, 0.5}, {1.2, 0.5}}, box), box, 0.1);
    ck_assert(!bad.valid);
}
END_TEST

START_TEST(missing_point_is_not_maximal) {
    // A maximal pattern from the sampler, then the same without each of a few
    // points: a hole opens (the removed point's disk was the only cover of its
    // own position), so maximality must fail.
    pds::Sampler s(0.07, 3);
    bool maximal = false;
    s.add_points(0, &maximal);
    const pds::Box& box = s.frame().box();
    const double r = s.frame().r();
    const auto& all = s.jones().mesh().points();
    std::vector<pds::Point> pts(all.begin() + pds::Delaunay::kGhosts, all.end());
    ck_assert(pds::verify_pattern(build(pts, box), box, r).maximal);
    for (std::size_t drop = 0; drop < pts.size(); drop += (test_light() ? 40 : 9)) {
        std::vector<pds::Point> fewer = pts;
        fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(drop));
        const pds::VerifyReport rep = pds::verify_pattern(build(fewer, box), box, r);
        ck_assert(rep.valid);
        ck_assert(!rep.maximal);
    }
}
END_TEST

START_TEST(sides_and_corners) {
    // One point in the middle of the unit square: no Voronoi vertex lies in
    // the domain, so only the side check can see the uncovered corners.
    const pds::Box box{0, 0, 1, 1};
    const double corner = std::sqrt(0.5);
    const pds::Delaunay one = build({{0.5, 0.5}}, box);
    ck_assert(!pds::verify_pattern(one, box, std::nextafter(corner, 0.0)).maximal);
    ck_assert(pds::verify_pattern(one, box, corner).maximal);
    // Two points on the diagonal, 1.13 apart; the corners (0,1) and (1,0) are
    // the farthest points from both.
    const pds::Delaunay two = build({{0.1, 0.1}, {0.9, 0.9}}, box);
    const double need = std::hypot(0.1, 0.9);
    ck_assert(!pds::verify_pattern(two, box, need * (1 - 1e-12)).maximal);
    ck_assert(pds::verify_pattern(two, box, need * (1 + 1e-12)).maximal);
    // Three points on the line y = 0.5, R apart: collinear sites have no
    // Voronoi vertex, and the disks leave gaps on the bottom and top sides
    // between the points (at (0.25, 0) the nearest point is 0.559 away).
    const pds::Delaunay row = build({{0, 0.5}, {0.5, 0.5}, {1, 0.5}}, box);
    const pds::VerifyReport rep = pds::verify_pattern(row, box, 0.5);
    ck_assert(rep.valid);
    ck_assert(!rep.maximal);
    ck_assert_ptr_nonnull(std::strstr(rep.failure.c_str(), "side"));
}
END_TEST

START_TEST(failure_names_the_users_point) {
    // The hand-over inserts points in a spatial order, so mesh vertices and
    // the user's order differ; the message must name the user's index.
    // Points 0..4 spread over the square; point 5 is too close to point 1.
    const pds::Box box{0, 0, 1, 1};
    const std::vector<pds::Point> pts = {{0.9, 0.9}, {0.1, 0.1}, {0.9, 0.1}, {0.1, 0.9},
                                         {0.5, 0.5}, {0.12, 0.1}};
    const std::uint32_t order[] = {5, 4, 3, 2, 1, 0};  // the mesh sees them reversed
    const auto stage = pds::make_jones_stage(box, 0.1);
    stage->reserve(pts.size());
    stage->adopt(pts, order);
    const pds::VerifyReport rep = stage->verify();
    ck_assert(!rep.valid);
    // Vertex order: point 5 comes first, so its partner found later is point 1.
    ck_assert_msg(std::strstr(rep.failure.c_str(), "(point 1)") != nullptr, "%s", rep.failure.c_str());
    // Same pattern in the user's order: now point 5 is the later one.
    const std::uint32_t same[] = {0, 1, 2, 3, 4, 5};
    const auto plain = pds::make_jones_stage(box, 0.1);
    plain->reserve(pts.size());
    plain->adopt(pts, same);
    const pds::VerifyReport rep2 = plain->verify();
    ck_assert_msg(std::strstr(rep2.failure.c_str(), "(point 5)") != nullptr, "%s", rep2.failure.c_str());
}
END_TEST

Suite* verify_suite() {
    Suite* s = suite_create("verify");
    TCase* t = tcase_create("certificate");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, close_pair_is_invalid);
    tcase_add_test(t, failure_names_the_users_point);
    tcase_add_test(t, point_outside_is_invalid);
    tcase_add_test(t, missing_point_is_not_maximal);
    tcase_add_test(t, sides_and_corners);
    suite_add_tcase(s, t);
    return s;
}
