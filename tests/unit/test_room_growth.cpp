// test_room_growth.cpp - the growth policy for the points' room
// (core/room_growth.hpp): never less than asked, at least doubled below the
// cap, never past the cap unless asked, and so few growths for points
// added one at a time.
#include <cstddef>

#include "core/room_growth.hpp"
#include "suites.hpp"

START_TEST(asked_doubled_capped) {
    // Always what is asked, even beyond the cap.
    ck_assert_uint_eq(pds::grown_room(500, 10, 100), 500);
    // At least double what is held, and a first room from nothing.
    ck_assert_uint_eq(pds::grown_room(1, 0, 1000000), 64);
    ck_assert_uint_ge(pds::grown_room(1001, 1000, 1000000), 2000);
    // The cap bounds the doubling, not what is asked.
    ck_assert_uint_eq(pds::grown_room(1001, 1000, 1500), 1500);
    ck_assert_uint_eq(pds::grown_room(1600, 1000, 1500), 1600);
}
END_TEST

START_TEST(few_growths_one_point_at_a_time) {
    // Points added one by one up to 10^6, the room grown only when full.
    std::size_t room = 0, growths = 0;
    for (std::size_t held = 0; held < 1000000; ++held) {
        if (held + 1 <= room) continue;
        room = pds::grown_room(held + 1, held, 1000000);
        ck_assert_uint_ge(room, held + 1);
        ck_assert_uint_le(room, 1000000);
        ++growths;
    }
    // From 64, doubled: 14 growths pass 10^6 (O(log n), so O(1) amortized).
    ck_assert_uint_le(growths, 16);
}
END_TEST

Suite* room_growth_suite() {
    Suite* s = suite_create("room_growth");
    TCase* t = tcase_create("policy");
    tcase_add_test(t, asked_doubled_capped);
    tcase_add_test(t, few_growths_one_point_at_a_time);
    suite_add_tcase(s, t);
    return s;
}
