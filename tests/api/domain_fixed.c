/*
 * domain_fixed.c - pds_set_fixed: points there before the first, each with a
 * clearance the sampled points keep from it.
 *
 * Contract (poissondisk.h, 1.4): a coordinate not finite, a clearance not
 * finite or negative, xy NULL with n > 0, or a periodic sampler (either way
 * round) is PDS_EINVAL, the message naming the point; a point outside the
 * domain's bounding box is PDS_EINVAL at the first point, with nothing added;
 * n 0 removes them; PDS_ESTATE once points exist. Every sampled point keeps
 * at least each clearance (0 or NULL: the radius in force there at the first
 * point, R or the field's value; pds_refine and count mode scale them all)
 * from its fixed point; fixed points count for coverage, may lie outside the
 * polygon, and are neither returned nor counted. Runs split, canceled,
 * counted and refined behave as without them (domain_runs.c), and the law is
 * random sequential adsorption conditioned on them (domain_law.c), by the
 * default process and by the parallel one on 1, 2 and 3 threads.
 *
 * The law measured (1.4.0, 2000 patterns each side, R 0.1): N 45.913 against
 * the reference's 45.930 (z -0.27), nearest neighbour z 0.34, near the
 * outline z -1.15, KS 0.33 and 0.71. The library's points in the bounding
 * box filtered by the L and the clearances give N 37.372 (z -133).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "domain_check.h"
#include "domain_law.h"
#include "domain_runs.h"
#include "helpers.h"
#include "region.h"
#include "suites.h"

/* Three fixed points around the unit L: clearance 0.2 in the foot, which it
 * cuts in two at R 0.1; clearance 0 (the radius) in the leg; 0.2 outside the
 * polygon in the notch, reaching into both arms. */
static const double fixed_xy[6] = {0.7, 0.2, 0.2, 0.75, 0.55, 0.55};
static const double fixed_c[3] = {0.2, 0.0, 0.2};

/* Their disks for a run that started at radius r0 and is now at r. */
static size_t fixed_disks(double r0, double r, disk *out)
{
    size_t k;

    for (k = 0; k < 3; k++) {
        out[k].x = fixed_xy[2 * k];
        out[k].y = fixed_xy[2 * k + 1];
        out[k].r = fixed_c[k] > 0.0 ? fixed_c[k] * (r / r0) : r;
    }
    return 3;
}

static void set_fixed(pds_sampler *s)
{
    ck_assert_int_eq(pds_set_fixed(s, fixed_xy, fixed_c, 3), 0);
}

static const domain_extra with_fixed = {"the L with 3 fixed points", set_fixed, fixed_disks};

static void assert_says(const pds_sampler *s, const char *part, const char *what)
{
    ck_assert_msg(strstr(pds_errmsg(s), part) != NULL, "%s: \"%s\" does not say \"%s\"", what,
                  pds_errmsg(s), part);
}

static const domain_extra nothing = {"the L", NULL, NULL};

/* Sets the n fixed points xy (clearances c, NULL for none) on s, runs to the
 * end, checks the pattern in g against the disks fx, and destroys s. */
static void fixed_run_checked(pds_sampler *s, const region *g, const double *xy, const double *c,
                              const disk *fx, size_t n, const char *what)
{
    ck_assert_int_eq(pds_set_fixed(s, xy, c, n), 0);
    run_to_end(s);
    assert_domain_pattern(s, g, fx, n, what);
    pds_destroy(s);
}

START_TEST(fixed_refused)
{
    const double xy[6] = {0.5, 0.2, 0.2, 0.6, 0.8, 0.1};
    double bad_xy[6], c[3] = {0.1, 0.0, 0.2};
    pds_sampler *a = extra_new(&nothing, 0.05, 12), *b = extra_new(&nothing, 0.05, 12);

    assert_failed(NULL, pds_set_fixed(NULL, xy, NULL, 3), PDS_EINVAL, "pds_set_fixed(NULL, ...)");
    assert_failed(a, pds_set_fixed(a, NULL, NULL, 3), PDS_EINVAL, "xy NULL with n 3");
    memcpy(bad_xy, xy, sizeof xy);
    bad_xy[3] = NAN;
    assert_failed(a, pds_set_fixed(a, bad_xy, NULL, 3), PDS_EINVAL, "NaN y of point 1");
    assert_says(a, "point 1", "NaN y of point 1");
    bad_xy[3] = 0.6;
    bad_xy[4] = -INFINITY;
    assert_failed(a, pds_set_fixed(a, bad_xy, c, 3), PDS_EINVAL, "infinite x of point 2");
    assert_says(a, "point 2", "infinite x of point 2");
    c[2] = -0.1;
    assert_failed(a, pds_set_fixed(a, xy, c, 3), PDS_EINVAL, "clearance -0.1 of point 2");
    assert_says(a, "point 2", "clearance -0.1 of point 2");
    c[2] = 0.2;
    c[1] = INFINITY;
    assert_failed(a, pds_set_fixed(a, xy, c, 3), PDS_EINVAL, "infinite clearance of point 1");
    assert_says(a, "point 1", "infinite clearance of point 1");
    c[1] = NAN;
    assert_failed(a, pds_set_fixed(a, xy, c, 3), PDS_EINVAL, "NaN clearance of point 1");
    ck_assert_msg(strncmp(pds_errmsg(a), "pds_set_fixed", 13) == 0, "\"%s\"", pds_errmsg(a));
    ck_assert_uint_eq(pds_count(a), 0);
    assert_same_future(a, b, "after the refused fixed points");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(fixed_outside_the_box_at_the_first_point)
{
    /* (1.5, 0.5) is outside the L's bounding box, the unit square: accepted
     * by pds_set_fixed, refused at the first point with nothing added; a
     * valid set then samples as a twin that never had the bad one. */
    const double out[4] = {0.5, 0.2, 1.5, 0.5}, in[2] = {0.5, 0.2};
    pds_sampler *a = extra_new(&nothing, 0.05, 13), *b = extra_new(&nothing, 0.05, 13);
    size_t added = 99;

    ck_assert_int_eq(pds_set_fixed(a, out, NULL, 2), 0);
    assert_failed(a, pds_run(a, 0, &added), PDS_EINVAL, "fixed point outside the box, pds_run");
    ck_assert_msg(strstr(pds_errmsg(a), "fixed point 1 (1.5, 0.5) lies outside the domain's bounding box "
                                        "[0,1]x[0,1]") != NULL,
                  "the message names the point and the box: %s", pds_errmsg(a));
    ck_assert_uint_eq(added, 0);
    assert_failed(a, pds_step(a), PDS_EINVAL, "fixed point outside the box, pds_step");
    ck_assert_uint_eq(pds_count(a), 0);
    ck_assert_int_eq(pds_set_fixed(a, in, NULL, 1), 0);
    ck_assert_int_eq(pds_set_fixed(b, in, NULL, 1), 0);
    assert_same_future(a, b, "after the fixed point outside the box was replaced");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(fixed_n_0_removes)
{
    pds_sampler *a = extra_new(&with_fixed, 0.05, 14), *b = extra_new(&nothing, 0.05, 14);

    ck_assert_int_eq(pds_set_fixed(a, NULL, NULL, 0), 0);
    assert_same_future(a, b, "pds_set_fixed(s, NULL, NULL, 0)");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(fixed_refused_on_a_torus_either_way)
{
    const double xy[2] = {0.5, 0.5};
    pds_sampler *a = sampler_new(0.05, 15), *b = sampler_new(0.05, 15);

    ck_assert_int_eq(pds_set_periodic(a, 1), 0);
    assert_failed(a, pds_set_fixed(a, xy, NULL, 1), PDS_EINVAL, "pds_set_fixed on a torus");
    ck_assert_int_eq(pds_set_periodic(a, 0), 0);
    ck_assert_int_eq(pds_set_fixed(a, xy, NULL, 1), 0);
    assert_failed(a, pds_set_periodic(a, 1), PDS_EINVAL, "pds_set_periodic with fixed points");
    ck_assert_int_eq(pds_set_fixed(b, xy, NULL, 1), 0);
    assert_same_future(a, b, "pds_set_periodic refused with fixed points");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(fixed_estate_once_points_exist)
{
    pds_sampler *a = extra_new(&with_fixed, 0.05, 17), *b = extra_new(&with_fixed, 0.05, 17);
    sampler_snapshot snap;

    ck_assert_int_eq(pds_step(a), PDS_MORE);
    ck_assert_int_eq(pds_step(b), PDS_MORE);
    snapshot_take(a, &snap);
    assert_failed(a, pds_set_fixed(a, fixed_xy, NULL, 2), PDS_ESTATE,
                  "pds_set_fixed after a point");
    assert_failed(a, pds_set_fixed(a, NULL, NULL, 0), PDS_ESTATE,
                  "pds_set_fixed(s, NULL, NULL, 0) after a point");
    snapshot_check(a, &snap, "pds_set_fixed after a point");
    snapshot_free(&snap);
    assert_same_future(a, b, "pds_set_fixed after a point");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(kept_clear_counted_for_coverage_not_returned)
{
    const double r = 0.03;
    disk fx[3], *d;
    double buf[4], *xy, *rad;
    char why[256];
    uint64_t seed;
    size_t n, i;

    fixed_disks(r, r, fx);
    for (seed = 1; seed <= pick(4, 1); seed++) {
        pds_sampler *s = extra_new(&with_fixed, r, seed);
        char what[96];
        snprintf(what, sizeof what, "the L with 3 fixed points, seed %llu",
                 (unsigned long long)seed);
        ck_assert_uint_eq(pds_count(s), 0);
        ck_assert_uint_eq(pds_points(s, 0, 2, buf), 0);
        run_to_end(s);
        /* Clear of every fixed point (so none of them is returned). */
        assert_domain_pattern(s, &UNIT_L, fx, 3, what);
        /* Without the clearances the L is not covered: they count. */
        domain_pattern(s, &xy, &rad, &n);
        d = malloc((n + 1) * sizeof *d);
        ck_assert_ptr_nonnull(d);
        for (i = 0; i < n; i++)
            d[i].x = xy[2 * i], d[i].y = xy[2 * i + 1], d[i].r = rad[i];
        ck_assert_msg(!region_covered(&UNIT_L, d, n, 1e-9, why, sizeof why),
                      "%s: the points alone cover the L", what);
        free(d);
        free(xy);
        free(rad);
        pds_destroy(s);
    }
}
END_TEST

/* Fixed points on one line with clearances that leave one inside another's
 * (weighted, it is hidden, lying between its neighbours): the weighted
 * insertion looped on this before. In the L's foot, along y = 0.1. */
START_TEST(fixed_on_a_line_one_inside_another)
{
    const double xy[8] = {0.67, 0.1, 0.669, 0.1, 0.8, 0.1, 0.3, 0.1};
    const double c[4] = {0.0155, 0.0418, 0.0162, 0.02};
    disk fx[4];
    size_t k;
    pds_sampler *s = extra_new(&nothing, 0.036, 3);

    for (k = 0; k < 4; k++)
        fx[k].x = xy[2 * k], fx[k].y = xy[2 * k + 1], fx[k].r = c[k];
    fixed_run_checked(s, &UNIT_L, xy, c, fx, 4, "fixed on a line, one inside another");
}
END_TEST

/* A position given more than once is one fixed point, the one with the
 * largest clearance (the first of equal ones), in its place among the others:
 * the same points as with that one alone (before, PDS_EINTERNAL: a duplicate
 * vertex). */
START_TEST(fixed_given_twice_count_once)
{
    const double thrice[8] = {0.3, 0.1, 0.8, 0.15, 0.3, 0.1, 0.3, 0.1};
    const double c[4] = {0.03, 0.05, 0.08, 0.02}, once_c[2] = {0.05, 0.08};
    const double once[2][4] = {{0.3, 0.1, 0.8, 0.15}, {0.8, 0.15, 0.3, 0.1}};
    const double *cs[2] = {NULL, c};
    const double *once_cs[2] = {NULL, once_c};
    int k;

    for (k = 0; k < 2; k++) {
        pds_sampler *a = extra_new(&nothing, 0.04, 8), *b = extra_new(&nothing, 0.04, 8);
        ck_assert_int_eq(pds_set_fixed(a, thrice, cs[k], 4), 0);
        ck_assert_int_eq(pds_set_fixed(b, once[k], once_cs[k], 2), 0);
        run_to_end(a);
        run_to_end(b);
        assert_same_points(a, b, k ? "a point given thrice with clearances" : "a point given thrice");
        pds_destroy(a);
        pds_destroy(b);
    }
}
END_TEST

START_TEST(clearance_null_is_r)
{
    const double r = 0.04;
    disk fx[3];
    pds_sampler *s = extra_new(&nothing, r, 5);
    size_t k;

    fixed_disks(r, r, fx);
    for (k = 0; k < 3; k++)
        fx[k].r = r;
    fixed_run_checked(s, &UNIT_L, fixed_xy, NULL, fx, 3, "clearance NULL");
}
END_TEST

START_TEST(clearance_0_is_the_field_value)
{
    /* A 2 x 1 map over the L's box, the unit square: 0.02 left of x = 0.25,
     * 0.04 right of x = 0.75. A fixed point in each part, clearance 0. */
    const double map[2] = {0.02, 0.04}, xy[4] = {0.1, 0.9, 0.9, 0.2};
    disk fx[2];
    pds_sampler *s = sampler_new(1.0, 6);

    fx[0].x = xy[0], fx[0].y = xy[1], fx[0].r = 0.02;
    fx[1].x = xy[2], fx[1].y = xy[3], fx[1].r = 0.04;
    ck_assert_int_eq(pds_set_polygon(s, UNIT_L.xy, UNIT_L.ends, UNIT_L.nrings), 0);
    ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
    fixed_run_checked(s, &UNIT_L, xy, NULL, fx, 2, "clearance 0 with a radius map");
}
END_TEST

START_TEST(obstacle_in_a_mask)
{
    /* An L of 3 pixels in 4 over the unit square, and an obstacle on the
     * missing pixel that reaches into both arms. */
    static const unsigned char mask[4] = {1, 1, 1, 0};
    static const double l_xy[12] = {0, 0, 1, 0, 1, 0.5, 0.5, 0.5, 0.5, 1, 0, 1};
    static const size_t l_ends[1] = {6};
    const region l = {l_xy, l_ends, 1};
    const double xy[2] = {0.75, 0.75}, c[1] = {0.4};
    disk fx[1];
    pds_sampler *s = sampler_new(0.03, 7);

    fx[0].x = xy[0], fx[0].y = xy[1], fx[0].r = c[0];
    ck_assert_int_eq(pds_set_mask(s, 2, 2, mask), 0);
    fixed_run_checked(s, &l, xy, c, fx, 1, "an obstacle in an L mask");
}
END_TEST

START_TEST(same_points_however_split)
{
    check_splits(&with_fixed);
}
END_TEST

START_TEST(same_points_canceled_at_every_call)
{
    check_cancel(&with_fixed);
}
END_TEST

START_TEST(count_mode_exact)
{
    check_count(&with_fixed);
}
END_TEST

START_TEST(refine_scales_the_clearances)
{
    check_refine(&with_fixed);
}
END_TEST

static disk law_disks[3];
static const law_case law_with_fixed = {"the L with 3 fixed points", set_fixed, law_disks, 3, 0};

START_TEST(coverage_check_finds_a_removed_point)
{
    fixed_disks(LAW_R, LAW_R, law_disks);
    law_removals_found(&law_with_fixed, pick(10, 2));
}
END_TEST

START_TEST(law_conditioned_on_fixed_points)
{
    fixed_disks(LAW_R, LAW_R, law_disks);
    law_compare(&law_with_fixed);
}
END_TEST

/* The parallel process (its opening keeps the darts out of the clearance
 * disks; the free regions' darts run in the power cells) on 1, 2 and 3
 * threads. */
static const law_case law_with_fixed_threads[3] = {
    {"the L with 3 fixed points on 1 thread", set_fixed, law_disks, 3, 1},
    {"the L with 3 fixed points on 2 threads", set_fixed, law_disks, 3, 2},
    {"the L with 3 fixed points on 3 threads", set_fixed, law_disks, 3, 3},
};

START_TEST(law_conditioned_on_fixed_points_on_threads)
{
    fixed_disks(LAW_R, LAW_R, law_disks);
    law_compare(&law_with_fixed_threads[_i]);
}
END_TEST

Suite *domain_fixed_suite(void)
{
    Suite *s = suite_create("domain_fixed");
    TCase *tc = new_tcase(s, "arguments and states");
    tcase_add_test(tc, fixed_refused);
    tcase_add_test(tc, fixed_outside_the_box_at_the_first_point);
    tcase_add_test(tc, fixed_n_0_removes);
    tcase_add_test(tc, fixed_refused_on_a_torus_either_way);
    tcase_add_test(tc, fixed_estate_once_points_exist);
    tc = new_tcase(s, "clearance and coverage");
    tcase_add_test(tc, kept_clear_counted_for_coverage_not_returned);
    tcase_add_test(tc, clearance_null_is_r);
    tcase_add_test(tc, fixed_on_a_line_one_inside_another);
    tcase_add_test(tc, fixed_given_twice_count_once);
    tcase_add_test(tc, clearance_0_is_the_field_value);
    tcase_add_test(tc, obstacle_in_a_mask);
    tc = new_tcase(s, "splits, cancel, count, refine");
    tcase_add_test(tc, same_points_however_split);
    tcase_add_test(tc, same_points_canceled_at_every_call);
    tcase_add_test(tc, count_mode_exact);
    tcase_add_test(tc, refine_scales_the_clearances);
    tc = new_tcase(s, "law");
    tcase_add_test(tc, coverage_check_finds_a_removed_point);
    tcase_add_test(tc, law_conditioned_on_fixed_points);
    tcase_add_loop_test(tc, law_conditioned_on_fixed_points_on_threads, 0, 3);
    return s;
}
