// test_free_room.cpp - the estimate of the room disks leave in a domain
// (free_room.hpp), which count mode's first radius around fixed points uses:
// its area and outline against closed forms, clipped to the rectangle and
// to a polygon, narrow disks by their circumference, and the cases where it
// declines.
#include <check.h>

#include <cmath>
#include <memory>
#include <vector>

#include "domain/free_room.hpp"
#include "polygon_rings.hpp"
#include "suites.hpp"

namespace {

pds::Frame unit_square() { return pds::Frame(pds::Box{0.0, 0.0, 1.0, 1.0}, 0.01); }

void assert_near(double got, double want, double tolerance, const char* what) {
    ck_assert_msg(std::fabs(got - want) <= tolerance * want, "%s: %.6f, expected %.6f (within %g)", what, got, want,
                  tolerance);
}

START_TEST(a_disk_inside) {
    const pds::Frame frame = unit_square();
    pds::FreeRoomLattice lattice(frame);
    const auto room = lattice.estimate({pds::Point{0.5, 0.5}}, {0.3});
    ck_assert(room.has_value());
    assert_near(room->area, 1.0 - M_PI * 0.09, 0.005, "area");
    assert_near(room->outline, 2.0 * M_PI * 0.3, 0.03, "outline");
    // No disk: all the room, no outline.
    const auto empty = lattice.estimate({}, {});
    ck_assert(empty.has_value());
    ck_assert_double_eq(empty->area, 1.0);
    ck_assert_double_eq(empty->outline, 0.0);
}
END_TEST

START_TEST(clipped_to_the_rectangle) {
    // A quarter of a disk in a corner, half of one on an edge (overlapping
    // the first): their union's area and the arcs inside.
    const pds::Frame frame = unit_square();
    pds::FreeRoomLattice lattice(frame);
    const auto quarter = lattice.estimate({pds::Point{0.0, 0.0}}, {0.5});
    ck_assert(quarter.has_value());
    assert_near(quarter->area, 1.0 - M_PI * 0.25 / 4.0, 0.005, "corner: area");
    assert_near(quarter->outline, 2.0 * M_PI * 0.5 / 4.0, 0.03, "corner: outline");
    const auto two = lattice.estimate({pds::Point{0.0, 0.0}, pds::Point{1.0, 0.0}}, {0.5, 0.5});
    ck_assert(two.has_value());
    // Two quarter disks that touch at (0.5, 0): no overlap. Where the arcs
    // meet, both cross the lattice between the same two points, which counts
    // neither (measured: 4.3% short).
    assert_near(two->area, 1.0 - M_PI * 0.25 / 2.0, 0.005, "two corners: area");
    assert_near(two->outline, 2.0 * M_PI * 0.5 / 2.0, 0.06, "two corners: outline");
}
END_TEST

START_TEST(clipped_to_a_polygon) {
    // The unit L (the square less its upper right quarter), a disk of 0.2 at
    // the notch's corner (0.5, 0.5): three quarters of it lie in the L.
    pds::Frame frame = unit_square();
    frame.set_polygon(std::make_shared<const pds::Polygon>(
        rings_of({{0.0, 0.0, 1.0, 0.0, 1.0, 0.5, 0.5, 0.5, 0.5, 1.0, 0.0, 1.0}})));
    pds::FreeRoomLattice lattice(frame);
    const auto room = lattice.estimate({pds::Point{0.5, 0.5}}, {0.2});
    ck_assert(room.has_value());
    assert_near(room->area, 0.75 - 0.75 * M_PI * 0.04, 0.005, "area");
    assert_near(room->outline, 0.75 * 2.0 * M_PI * 0.2, 0.03, "outline");
}
END_TEST

START_TEST(narrow_disks_count_their_circumference) {
    // 400 disks of radius 0.002 (under two lattice spacings), apart: the
    // outline is their circumferences, whether the lattice meets them or not.
    const pds::Frame frame = unit_square();
    pds::FreeRoomLattice lattice(frame);
    std::vector<pds::Point> centres;
    std::vector<double> radii;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            centres.push_back(pds::Point{0.025 + 0.05 * i, 0.025 + 0.05 * j});
            radii.push_back(0.002);
        }
    const auto room = lattice.estimate(centres, radii);
    ck_assert(room.has_value());
    assert_near(room->outline, 400 * 2.0 * M_PI * 0.002, 1e-9, "outline");
    ck_assert(room->area <= 1.0 && room->area > 0.99);
}
END_TEST

START_TEST(declines_past_its_budget) {
    // 100 disks each covering the square: 100 marks a lattice point, over
    // the budget of 64.
    const pds::Frame frame = unit_square();
    pds::FreeRoomLattice lattice(frame);
    const std::vector<pds::Point> centres(100, pds::Point{0.5, 0.5});
    const std::vector<double> radii(100, 1.0);
    ck_assert(!lattice.estimate(centres, radii).has_value());
    // 50 are within it: nothing left.
    const auto covered = lattice.estimate(std::vector<pds::Point>(50, pds::Point{0.5, 0.5}), std::vector<double>(50, 1.0));
    ck_assert(covered.has_value());
    ck_assert_double_eq(covered->area, 0.0);
}
END_TEST

}  // namespace

Suite* free_room_suite() {
    Suite* s = suite_create("free_room");
    TCase* tc = tcase_create("estimate");
    tcase_add_test(tc, a_disk_inside);
    tcase_add_test(tc, clipped_to_the_rectangle);
    tcase_add_test(tc, clipped_to_a_polygon);
    tcase_add_test(tc, narrow_disks_count_their_circumference);
    tcase_add_test(tc, declines_past_its_budget);
    suite_add_tcase(s, tc);
    return s;
}
