/*
 * semantics.c - what step, run, refine, points, free_area and verify mean.
 *
 * Contract: before the first point the count is 0 and the free area is the
 * domain's area; pds_step adds one point (1) until the pattern is maximal (0,
 * free area exactly 0); pds_run adds up to max_new points and says whether
 * room is left; points come in insertion order and never change; pds_refine
 * keeps every point and index, and running on makes the pattern maximal at
 * the new radius; pds_verify says 1 while room is left and 0 when maximal.
 * The splitting of the work into calls does not change the points.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

/* Enough to finish any pattern these tests make; a loop bound, not a target. */
#define MAX_STEPS 1000000

/* ---- before the first point ---------------------------------------------------- */

START_TEST(initial_unit_square)
{
    double buf[2];
    pds_sampler *s = sampler_new(0.05, 51);

    ck_assert_uint_eq(pds_count(s), 0);
    ck_assert_msg(pds_radius(s) == 0.05, "radius %.17g, expected 0.05", pds_radius(s));
    ck_assert_msg(pds_free_area(s) == 1.0, "free area %.17g, expected exactly 1",
                  pds_free_area(s));
    ck_assert_uint_eq(pds_points(s, 0, 1, buf), 0);
    /* An empty pattern is valid and has room. */
    ck_assert_int_eq(pds_verify(s), 1);
    pds_destroy(s);
}
END_TEST

START_TEST(initial_set_domain)
{
    static const test_domain domains[] = {
        {0.0, 0.0, 4.0, 0.5},
        {1000.0, -3.0, 1001.0, -2.0},
        {-0.3, 0.1, 0.7, 0.35},
        {0.0, 0.0, 100.0, 100.0},
    };
    static const double radii[] = {0.05, 0.05, 0.05, 2.0};
    size_t i;

    for (i = 0; i < sizeof domains / sizeof domains[0]; i++) {
        test_domain d = domains[i];
        pds_sampler *s = sampler_new_in(radii[i], 52, d);
        char what[96];
        snprintf(what, sizeof what, "free area of [%g,%g]x[%g,%g] before any point", d.x0,
                 d.x1, d.y0, d.y1);
        ck_assert_uint_eq(pds_count(s), 0);
        assert_rel_close(pds_free_area(s), (d.x1 - d.x0) * (d.y1 - d.y0), 1e-12, what);
        ck_assert_int_eq(pds_verify(s), 1);
        pds_destroy(s);
    }
}
END_TEST

/* ---- pds_step ------------------------------------------------------------------ */

START_TEST(step_until_maximal)
{
    double r = test_light() ? 0.1 : 0.04;
    pds_sampler *s = sampler_new(r, 53);
    double before = pds_free_area(s);
    size_t steps = 0;
    int rc = 1, i;

    while (steps < MAX_STEPS) {
        rc = pds_step(s);
        if (rc != 1)
            break;
        steps++;
        /* A point was added, so there was room for it. */
        ck_assert_msg(before > 0.0, "step %zu added a point but the free area was %.17g",
                      steps, before);
        ck_assert_uint_eq(pds_count(s), steps);
        ck_assert_msg(pds_free_area(s) <= before,
                      "free area grew from %.17g to %.17g at step %zu", before,
                      pds_free_area(s), steps);
        before = pds_free_area(s);
    }
    ck_assert_msg(rc == 0, "pds_step returned %d (%s)", rc, pds_errmsg(s));
    ck_assert_msg(steps > 1, "only %zu points at R = %g", steps, r);
    for (i = 0; i < 5; i++) {
        ck_assert_int_eq(pds_step(s), 0);
        ck_assert_uint_eq(pds_count(s), steps);
    }
    assert_maximal(s, "after stepping to the end");
    pds_destroy(s);
}
END_TEST

START_TEST(step_matches_run)
{
    pds_sampler *a = sampler_new(0.05, 54), *b = sampler_new(0.05, 54);
    size_t steps = 0;

    while (steps < MAX_STEPS && pds_step(a) == 1)
        steps++;
    run_to_end(b);
    assert_same_points(a, b, "pds_step loop vs one pds_run");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* ---- pds_run ------------------------------------------------------------------- */

START_TEST(run_unlimited)
{
    pds_sampler *s = sampler_new(0.05, 55);
    size_t added = 0;

    ck_assert_int_eq(pds_run(s, 0, &added), 0);
    ck_assert_uint_eq(added, pds_count(s));
    ck_assert_msg(added > 100, "only %zu points at R = 0.05", added);
    assert_maximal(s, "after pds_run(s, 0, &added)");
    added = 5;
    ck_assert_int_eq(pds_run(s, 0, &added), 0);
    ck_assert_uint_eq(added, 0);
    pds_destroy(s);
}
END_TEST

START_TEST(run_limited)
{
    /* At R = 0.05 a maximal pattern has about 280 points: 1 + 7 + 100 leave room. */
    static const size_t ks[] = {1, 7, 100};
    pds_sampler *s = sampler_new(0.05, 56);
    size_t i, total = 0;

    for (i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        size_t added = 0;
        ck_assert_int_eq(pds_run(s, ks[i], &added), 1);
        ck_assert_uint_eq(added, ks[i]);
        total += ks[i];
        ck_assert_uint_eq(pds_count(s), total);
        ck_assert_msg(pds_free_area(s) > 0.0, "free area %.17g but pds_run said room is left",
                      pds_free_area(s));
        ck_assert_int_eq(pds_verify(s), 1);
    }
    pds_destroy(s);
}
END_TEST

START_TEST(run_added_null)
{
    pds_sampler *s = sampler_new(0.05, 57);

    ck_assert_int_eq(pds_run(s, 5, NULL), 1);
    ck_assert_uint_eq(pds_count(s), 5);
    ck_assert_int_eq(pds_run(s, 0, NULL), 0);
    assert_maximal(s, "after pds_run(s, 0, NULL)");
    ck_assert_int_eq(pds_run(s, 0, NULL), 0);
    pds_destroy(s);
}
END_TEST

START_TEST(run_exactly_to_the_end)
{
    /* When the max_new-th point is the last one that fits, room is not left:
     * the answer is 0, not 1. The twin tells how many points there will be. */
    pds_sampler *a = sampler_new(0.05, 66), *b = sampler_new(0.05, 66);
    size_t total = run_to_end(b), added = 0;

    ck_assert_int_eq(pds_run(a, total - 1, &added), 1);
    ck_assert_uint_eq(added, total - 1);
    ck_assert_int_eq(pds_run(a, 1, &added), 0);
    ck_assert_uint_eq(added, 1);
    assert_maximal(a, "after pds_run(s, 1) added the last point");
    pds_destroy(a);
    a = sampler_new(0.05, 66);
    ck_assert_int_eq(pds_run(a, total, &added), 0);
    ck_assert_uint_eq(added, total);
    assert_same_points(a, b, "pds_run(s, total) vs pds_run(s, 0)");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* Runs a to the end in calls of at most chunk points each. */
static void run_in_chunks(pds_sampler *a, size_t chunk)
{
    size_t total = 0, calls = 0;
    int rc;

    do {
        size_t added = 0;
        rc = pds_run(a, chunk, &added);
        ck_assert_msg(rc == 0 || rc == 1, "pds_run(s, %zu) returned %d (%s)", chunk, rc,
                      pds_errmsg(a));
        if (rc == 1)
            ck_assert_msg(added == chunk, "pds_run(s, %zu) returned 1 but added %zu", chunk,
                          added);
        else
            ck_assert_msg(added <= chunk, "pds_run(s, %zu) added %zu", chunk, added);
        total += added;
        calls++;
    } while (rc == 1 && calls < MAX_STEPS);
    ck_assert_int_eq(rc, 0);
    ck_assert_uint_eq(total, pds_count(a));
}

START_TEST(run_chunks_match_single_run)
{
    static const size_t chunks[] = {7, 1, 64};
    size_t i;

    for (i = 0; i < sizeof chunks / sizeof chunks[0]; i++) {
        pds_sampler *a = sampler_new(0.04, 58), *b = sampler_new(0.04, 58);
        char what[64];
        snprintf(what, sizeof what, "pds_run in chunks of %zu vs one pds_run", chunks[i]);
        run_in_chunks(a, chunks[i]);
        run_to_end(b);
        assert_same_points(a, b, what);
        pds_destroy(a);
        pds_destroy(b);
    }
}
END_TEST

/* ---- pds_points ---------------------------------------------------------------- */

START_TEST(points_insertion_order)
{
    pds_sampler *s = sampler_new(0.05, 59);
    double *early, *all, window[2 * 7], prefix[2 * 10];
    size_t nearly, nall;

    ck_assert_int_eq(pds_run(s, 20, NULL), 1);
    early = points_copy(s, &nearly);
    run_to_end(s);
    /* Points already there keep their place as the pattern grows. */
    assert_prefix_kept(s, early, nearly, "the first 20 points after running on");
    all = points_copy(s, &nall);
    ck_assert_uint_eq(pds_points(s, 0, 10, prefix), 10);
    assert_points_equal(prefix, 10, all, 10, "pds_points(0, 10) vs a full copy");
    ck_assert_uint_eq(pds_points(s, 5, 7, window), 7);
    assert_points_equal(window, 7, all + 2 * 5, 7, "pds_points(5, 7) vs a full copy");
    free(early);
    free(all);
    pds_destroy(s);
}
END_TEST

/* ---- pds_refine ---------------------------------------------------------------- */

START_TEST(refine_after_maximal)
{
    const double r0 = 0.08, r1 = 0.05;
    pds_sampler *s = sampler_new(r0, 60);
    double *old, *xy;
    size_t nold, n;

    run_to_end(s);
    old = points_copy(s, &nold);
    ck_assert_int_eq(pds_refine(s, r1), 0);
    ck_assert_msg(pds_radius(s) == r1, "radius %.17g after pds_refine(%g)", pds_radius(s), r1);
    ck_assert_uint_eq(pds_count(s), nold);
    assert_prefix_kept(s, old, nold, "points right after pds_refine");
    /* A pattern maximal at r0 has gaps wider than r1. */
    ck_assert_msg(pds_free_area(s) > 0.0, "free area %.17g after refining to %g",
                  pds_free_area(s), r1);
    ck_assert_int_eq(pds_verify(s), 1);
    run_to_end(s);
    ck_assert_msg(pds_count(s) > nold, "no point added after refining");
    assert_prefix_kept(s, old, nold, "old points after refining and running");
    xy = points_copy(s, &n);
    assert_min_distance(xy, n, r1, "after refine");
    assert_maximal(s, "after refine");
    free(old);
    free(xy);
    pds_destroy(s);
}
END_TEST

START_TEST(refine_mid_run)
{
    const double r0 = 0.07, r1 = 0.045;
    pds_sampler *s = sampler_new(r0, 61);
    double *old, *xy;
    size_t nold, n;

    ck_assert_int_eq(pds_run(s, 30, NULL), 1);
    old = points_copy(s, &nold);
    ck_assert_int_eq(pds_refine(s, r1), 0);
    run_to_end(s);
    assert_prefix_kept(s, old, nold, "old points after a refine mid-run");
    xy = points_copy(s, &n);
    assert_min_distance(xy, n, r1, "after a refine mid-run");
    assert_maximal(s, "after a refine mid-run");
    free(old);
    free(xy);
    pds_destroy(s);
}
END_TEST

static void check_equal_refine(size_t npoints, const char *stage)
{
    pds_sampler *a, *b;
    sampler_snapshot snap;

    twins_new(0.05, 62, NULL, npoints, &a, &b);
    snapshot_take(a, &snap);
    ck_assert_int_eq(pds_refine(a, pds_radius(a)), 0);
    snapshot_check(a, &snap, stage);
    snapshot_free(&snap);
    assert_same_future(a, b, stage);
    pds_destroy(a);
    pds_destroy(b);
}

START_TEST(refine_equal_is_noop)
{
    check_equal_refine(0, "pds_refine to the same radius before any point");
    check_equal_refine(20, "pds_refine to the same radius after 20 points");
    check_equal_refine(TO_END, "pds_refine to the same radius when maximal");
}
END_TEST

START_TEST(refine_one_ulp_smaller)
{
    /* The smallest legal step down: accepted, and the end is maximal again. */
    const double r0 = 0.05, r1 = nextafter(r0, 0.0);
    pds_sampler *s = sampler_new(r0, 63);
    double *xy;
    size_t n;

    run_to_end(s);
    ck_assert_int_eq(pds_refine(s, r1), 0);
    ck_assert_msg(pds_radius(s) == r1, "radius %.17g, expected %.17g", pds_radius(s), r1);
    run_to_end(s);
    xy = points_copy(s, &n);
    assert_min_distance(xy, n, r1, "after refining by one ulp");
    assert_maximal(s, "after refining by one ulp");
    free(xy);
    pds_destroy(s);
}
END_TEST

/* ---- pds_verify ---------------------------------------------------------------- */

START_TEST(verify_stages)
{
    pds_sampler *a = sampler_new(0.05, 64), *b = sampler_new(0.05, 64);

    ck_assert_int_eq(pds_verify(a), 1);
    ck_assert_int_eq(pds_run(a, 1, NULL), 1);
    ck_assert_int_eq(pds_verify(a), 1);
    ck_assert_int_eq(pds_run(a, 50, NULL), 1);
    ck_assert_int_eq(pds_verify(a), 1);
    ck_assert_str_eq(pds_errmsg(a), "no error");
    run_to_end(a);
    ck_assert_int_eq(pds_verify(a), 0);
    /* Verifying is reading: it does not change what comes out. */
    run_to_end(b);
    assert_same_points(a, b, "with and without pds_verify calls");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* ---- radius larger than the domain --------------------------------------------- */

START_TEST(radius_larger_than_domain)
{
    /* Anything finite and > 0 is a valid radius: with R above the diagonal one
     * point fills the square. Huge values must not overflow into NaN. */
    const double radii[] = {2.0, 1e10, 1e300, DBL_MAX};
    size_t i, n;

    for (i = 0; i < sizeof radii / sizeof radii[0]; i++) {
        pds_sampler *s = sampler_new(radii[i], 65);
        char what[64];
        double *xy;
        snprintf(what, sizeof what, "R = %g in the unit square", radii[i]);
        ck_assert_msg(pds_free_area(s) == 1.0, "%s: free area %.17g", what, pds_free_area(s));
        ck_assert_msg(run_to_end(s) == 1, "%s: %zu points, expected 1", what, pds_count(s));
        xy = points_copy(s, &n);
        assert_inside(xy, n, UNIT_SQUARE, what);
        assert_maximal(s, what);
        free(xy);
        pds_destroy(s);
    }
}
END_TEST

Suite *semantics_suite(void)
{
    Suite *suite = suite_create("semantics");
    TCase *tc;

    tc = new_tcase(suite, "initial_state");
    tcase_add_test(tc, initial_unit_square);
    tcase_add_test(tc, initial_set_domain);
    tc = new_tcase(suite, "step");
    tcase_add_test(tc, step_until_maximal);
    tcase_add_test(tc, step_matches_run);
    tc = new_tcase(suite, "run");
    tcase_add_test(tc, run_unlimited);
    tcase_add_test(tc, run_limited);
    tcase_add_test(tc, run_added_null);
    tcase_add_test(tc, run_exactly_to_the_end);
    tcase_add_test(tc, run_chunks_match_single_run);
    tc = new_tcase(suite, "points_order");
    tcase_add_test(tc, points_insertion_order);
    tc = new_tcase(suite, "refine");
    tcase_add_test(tc, refine_after_maximal);
    tcase_add_test(tc, refine_mid_run);
    tcase_add_test(tc, refine_one_ulp_smaller);
    tc = new_tcase(suite, "refine_equal");
    tcase_add_test(tc, refine_equal_is_noop);
    tc = new_tcase(suite, "verify");
    tcase_add_test(tc, verify_stages);
    tc = new_tcase(suite, "large_radius");
    tcase_add_test(tc, radius_larger_than_domain);
    return suite;
}
