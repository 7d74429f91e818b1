/*
 * state.c - which calls are allowed when.
 *
 * Contract: pds_set_domain only before the first point (PDS_ESTATE after,
 * with nothing changed); it may be called again before the first point, the
 * last successful call wins; pds_refine is allowed at any time; once maximal,
 * pds_step and pds_run add nothing and keep saying so.
 */
#include <stdio.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

static void check_estate_domain(size_t npoints, const char *stage)
{
    pds_sampler *a, *b;
    sampler_snapshot snap;
    char what[96];

    twins_new(0.05, 41, NULL, npoints, &a, &b);
    snapshot_take(a, &snap);
    snprintf(what, sizeof what, "pds_set_domain %s", stage);
    assert_failed(a, pds_set_domain(a, 0.0, 0.0, 2.0, 2.0), PDS_ESTATE, what);
    snapshot_check(a, &snap, what);
    /* Even the domain it already has is refused: the rule is about state. */
    assert_failed(a, pds_set_domain(a, 0.0, 0.0, 1.0, 1.0), PDS_ESTATE, what);
    snapshot_check(a, &snap, what);
    snapshot_free(&snap);
    assert_same_future(a, b, what);
    pds_destroy(a);
    pds_destroy(b);
}

START_TEST(set_domain_after_points)
{
    check_estate_domain(1, "after one point");
    check_estate_domain(40, "after 40 points");
    check_estate_domain(TO_END, "when maximal");
}
END_TEST

START_TEST(set_domain_after_refine_with_points)
{
    pds_sampler *s = sampler_new(0.05, 42);
    sampler_snapshot snap;

    ck_assert_int_eq(pds_run(s, 10, NULL), 1);
    ck_assert_int_eq(pds_refine(s, 0.03), 0);
    snapshot_take(s, &snap);
    assert_failed(s, pds_set_domain(s, 0.0, 0.0, 2.0, 2.0), PDS_ESTATE,
                  "pds_set_domain after points and a refine");
    snapshot_check(s, &snap, "pds_set_domain after points and a refine");
    snapshot_free(&snap);
    pds_destroy(s);
}
END_TEST

START_TEST(set_domain_repeated_before_points)
{
    static const test_domain last = {-2.0, 1.0, 1.0, 1.5};
    pds_sampler *s = sampler_new(0.05, 43);
    size_t n;
    double *xy;

    ck_assert_int_eq(pds_set_domain(s, 0.0, 0.0, 3.0, 3.0), 0);
    /* A failed call in between does not lock the domain either. */
    ck_assert_int_eq(pds_set_domain(s, 0.0, 0.0, -1.0, 1.0), PDS_EINVAL);
    /* Too large for R = 0.05 is accepted here (1.1.1) and refused at the first
     * point: a refused run adds nothing, so the domain can still change. */
    ck_assert_int_eq(pds_set_domain(s, 0.0, 0.0, 1e9, 1e9), 0);
    assert_run_rejected(s, 0, "pds_run(s, 0) with R = 0.05 in [0,1e9]^2");
    /* pds_verify reads; it adds no point. */
    ck_assert_int_eq(pds_verify(s), 1);
    ck_assert_int_eq(pds_set_domain(s, last.x0, last.y0, last.x1, last.y1), 0);
    assert_rel_close(pds_free_area(s), 3.0 * 0.5, 1e-12, "free area of the last domain");
    run_to_end(s);
    xy = points_copy(s, &n);
    assert_inside(xy, n, last, "the last pds_set_domain wins");
    free(xy);
    pds_destroy(s);
}
END_TEST

START_TEST(set_domain_after_refine_without_points)
{
    /* A refine adds no point, so the domain may still change; the refined
     * radius is the one used in the new domain. */
    static const test_domain d = {10.0, 20.0, 11.0, 20.5};
    pds_sampler *s = sampler_new(0.1, 44);
    size_t n;
    double *xy;

    ck_assert_int_eq(pds_refine(s, 0.04), 0);
    ck_assert_int_eq(pds_set_domain(s, d.x0, d.y0, d.x1, d.y1), 0);
    ck_assert_msg(pds_radius(s) == 0.04, "radius %.17g after refine and set_domain",
                  pds_radius(s));
    run_to_end(s);
    xy = points_copy(s, &n);
    assert_inside(xy, n, d, "set_domain after refine");
    assert_min_distance(xy, n, 0.04, "set_domain after refine");
    assert_maximal(s, "set_domain after refine");
    free(xy);
    pds_destroy(s);
}
END_TEST

START_TEST(refine_at_any_time)
{
    pds_sampler *s = sampler_new(0.1, 45);

    ck_assert_int_eq(pds_refine(s, 0.09), 0); /* no point yet */
    ck_assert_int_eq(pds_run(s, 5, NULL), 1);
    ck_assert_int_eq(pds_refine(s, 0.08), 0); /* mid-run */
    run_to_end(s);
    ck_assert_int_eq(pds_refine(s, 0.07), 0); /* when maximal */
    ck_assert_msg(pds_radius(s) == 0.07, "radius %.17g after refines", pds_radius(s));
    run_to_end(s);
    assert_maximal(s, "after three refines");
    pds_destroy(s);
}
END_TEST

START_TEST(maximal_is_final)
{
    pds_sampler *s = sampler_new(0.1, 46);
    size_t count, added;
    int i;

    run_to_end(s);
    count = pds_count(s);
    for (i = 0; i < 5; i++) {
        ck_assert_int_eq(pds_step(s), 0);
        added = 99;
        ck_assert_int_eq(pds_run(s, 0, &added), 0);
        ck_assert_uint_eq(added, 0);
        added = 99;
        ck_assert_int_eq(pds_run(s, 3, &added), 0);
        ck_assert_uint_eq(added, 0);
        ck_assert_uint_eq(pds_count(s), count);
        ck_assert_msg(pds_free_area(s) == 0.0, "free area %.17g once maximal",
                      pds_free_area(s));
    }
    pds_destroy(s);
}
END_TEST

Suite *state_suite(void)
{
    Suite *suite = suite_create("state");
    TCase *tc;

    tc = new_tcase(suite, "set_domain_after_points");
    tcase_add_test(tc, set_domain_after_points);
    tcase_add_test(tc, set_domain_after_refine_with_points);
    tc = new_tcase(suite, "set_domain_before_points");
    tcase_add_test(tc, set_domain_repeated_before_points);
    tcase_add_test(tc, set_domain_after_refine_without_points);
    tc = new_tcase(suite, "refine_at_any_time");
    tcase_add_test(tc, refine_at_any_time);
    tc = new_tcase(suite, "maximal_is_final");
    tcase_add_test(tc, maximal_is_final);
    return suite;
}
