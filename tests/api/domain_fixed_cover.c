/*
 * domain_fixed_cover.c - fixed points whose clearances leave no room: a run
 * ends maximal with no point, and the read-only calls say so.
 *
 * Contract (poissondisk.h, pds_set_fixed, pds_verify, pds_free_area): fixed
 * points count for coverage, and pds_free_area counts the clearances once a
 * run has started. So a domain the clearances cover is maximal with no
 * point: pds_run and pds_step return PDS_DONE, pds_verify PDS_DONE, and
 * pds_free_area 0. A refine before the first point is a fresh start at the
 * new radius, where clearances of 0 (the radius) shrink and leave room.
 */
#include <math.h>

#include "helpers.h"
#include "suites.h"

/* The unit square's corners with clearance 0: at R 1 their disks hold the
 * square (no point is farther than sqrt(1/2) from its nearest corner). */
static const double corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};

static void assert_maximal_without_points(pds_sampler *s)
{
    size_t added = 7;
    ck_assert_int_eq(pds_run(s, 0, &added), 0);
    ck_assert_uint_eq(added, 0);
    ck_assert_uint_eq(pds_count(s), 0);
    ck_assert_int_eq(pds_step(s), 0);
    ck_assert_int_eq(pds_verify(s), 0);
    ck_assert_double_eq(pds_free_area(s), 0.0);
}

START_TEST(corners_cover_the_square)
{
    pds_sampler *s = sampler_new(1.0, 3);
    ck_assert_int_eq(pds_set_fixed(s, corners, NULL, 4), 0);
    ck_assert_double_eq_tol(pds_free_area(s), 1.0, 1e-12); /* no run has started */
    assert_maximal_without_points(s);
    pds_destroy(s);
}
END_TEST

START_TEST(one_clearance_covers_a_polygon_and_a_mask)
{
    /* A triangle and a 3 x 2 mask, each inside one fixed point's disk. */
    static const double tri[6] = {0, 0, 4, 0, 0, 3};
    static const size_t ends[1] = {3};
    static const unsigned char pix[6] = {1, 0, 1, 1, 1, 0};
    const double centre[2] = {1, 1}, big[1] = {3.5};
    pds_sampler *s = sampler_new(0.2, 5);

    ck_assert_int_eq(pds_set_polygon(s, tri, ends, 1), 0);
    ck_assert_int_eq(pds_set_fixed(s, centre, big, 1), 0);
    assert_maximal_without_points(s);
    pds_destroy(s);

    s = sampler_new(0.2, 5);
    ck_assert_int_eq(pds_set_domain(s, 0, 0, 3, 2), 0);
    ck_assert_int_eq(pds_set_mask(s, 3, 2, pix), 0);
    ck_assert_int_eq(pds_set_fixed(s, centre, big, 1), 0);
    assert_maximal_without_points(s);
    pds_destroy(s);
}
END_TEST

START_TEST(a_refine_before_the_first_point_leaves_room)
{
    pds_sampler *s = sampler_new(1.0, 3);
    double xy[2 * 64];
    size_t n, i, k;

    ck_assert_int_eq(pds_set_fixed(s, corners, NULL, 4), 0);
    assert_maximal_without_points(s);
    ck_assert_int_eq(pds_refine(s, 0.3), 0);
    ck_assert_double_eq_tol(pds_free_area(s), 1.0, 1e-12); /* a fresh start */
    n = run_to_end(s);
    ck_assert_uint_gt(n, 0);
    ck_assert_uint_le(n, 64);
    ck_assert_uint_eq(pds_points(s, 0, n, xy), n);
    for (i = 0; i < n; i++)
        for (k = 0; k < 4; k++)
            ck_assert_double_ge(hypot(xy[2 * i] - corners[2 * k], xy[2 * i + 1] - corners[2 * k + 1]), 0.3);
    ck_assert_int_eq(pds_verify(s), 0);
    ck_assert_double_eq(pds_free_area(s), 0.0);
    pds_destroy(s);
}
END_TEST

Suite *domain_fixed_cover_suite(void)
{
    Suite *s = suite_create("domain_fixed_cover");
    TCase *tc = new_tcase(s, "no room left");
    tcase_add_test(tc, corners_cover_the_square);
    tcase_add_test(tc, one_clearance_covers_a_polygon_and_a_mask);
    tcase_add_test(tc, a_refine_before_the_first_point_leaves_room);
    return s;
}
