/*
 * args.c - every invalid argument of the public API.
 *
 * Contract (poissondisk.h, "Conventions"): a call that fails returns its
 * documented negative code, leaves the sampler as it was, and pds_errmsg()
 * says why. So each bad call here is checked three ways: the code; the
 * message (non-empty, not "no error"); and "nothing changed" -- the count,
 * radius, free area and points are as before (snapshot), and running the
 * sampler to the end afterwards gives byte-for-byte the points of a twin with
 * the same seed that never saw the bad call.
 * State errors (PDS_ESTATE) are in state.c. A radius too small for the
 * domain is not an invalid argument of pds_create or pds_set_domain since
 * 1.1.1: the first point is refused instead (PDS_ERANGE), see limits.c; only
 * pds_refine with points still refuses it at once (here).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

/* Radii that are not "finite and > 0". -NAN: a NaN with the sign bit set. */
static double bad_radius(int i)
{
    switch (i) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return -1.0;
    case 3: return -DBL_MIN;
    case 4: return -DBL_MAX;
    case 5: return NAN;
    case 6: return -NAN;
    case 7: return INFINITY;
    default: return -INFINITY;
    }
}
#define N_BAD_RADII 9

/* A sentinel that pds_points must never write. */
#define UNTOUCHED (-12345.0)

static void fill(double *buf, size_t n, double v)
{
    size_t i;
    for (i = 0; i < n; i++)
        buf[i] = v;
}

static void assert_untouched(const double *buf, size_t from, size_t to, const char *what)
{
    size_t i;
    for (i = from; i < to; i++)
        ck_assert_msg(buf[i] == UNTOUCHED, "%s: pds_points wrote buffer element %zu", what,
                      i);
}

/* ---- NULL handles ------------------------------------------------------------- */

START_TEST(null_handle_readers)
{
    double buf[8];
    const char *msg;

    fill(buf, 8, UNTOUCHED);
    pds_destroy(NULL); /* a no-op: must not crash */
    ck_assert_uint_eq(pds_count(NULL), 0);
    ck_assert_uint_eq(pds_points(NULL, 0, 4, buf), 0);
    assert_untouched(buf, 0, 8, "pds_points(NULL, ...)");
    ck_assert_msg(isnan(pds_radius(NULL)), "pds_radius(NULL) = %g, expected NaN",
                  pds_radius(NULL));
    ck_assert_msg(isnan(pds_free_area(NULL)), "pds_free_area(NULL) = %g, expected NaN",
                  pds_free_area(NULL));
    msg = pds_errmsg(NULL);
    ck_assert_ptr_nonnull(msg);
    ck_assert_msg(msg[0] != '\0', "pds_errmsg(NULL) is empty");
}
END_TEST

START_TEST(null_handle_calls)
{
    size_t added = 777;

    assert_failed(NULL, pds_step(NULL), PDS_EINVAL, "pds_step(NULL)");
    assert_failed(NULL, pds_run(NULL, 0, NULL), PDS_EINVAL, "pds_run(NULL, 0, NULL)");
    assert_failed(NULL, pds_run(NULL, 5, &added), PDS_EINVAL, "pds_run(NULL, 5, &added)");
    /* "added receives how many points this call added (also on error)": none. */
    ck_assert_msg(added == 0, "pds_run(NULL, 5, &added) left added = %zu, expected 0", added);
    assert_failed(NULL, pds_refine(NULL, 0.1), PDS_EINVAL, "pds_refine(NULL, 0.1)");
    assert_failed(NULL, pds_set_domain(NULL, 0, 0, 1, 1), PDS_EINVAL,
                  "pds_set_domain(NULL, unit square)");
    assert_failed(NULL, pds_verify(NULL), PDS_EINVAL, "pds_verify(NULL)");
    assert_failed(NULL, pds_create(NULL, 0.1, 1), PDS_EINVAL, "pds_create(NULL, 0.1, 1)");
    assert_failed(NULL, pds_create(NULL, NAN, 1), PDS_EINVAL, "pds_create(NULL, NaN, 1)");
}
END_TEST

/* ---- pds_create radius -------------------------------------------------------- */

START_TEST(create_bad_radius)
{
    /* *out must be set to NULL on failure: preload it with a live handle. */
    pds_sampler *live = sampler_new(0.1, 1);
    int i;

    for (i = 0; i < N_BAD_RADII; i++) {
        char what[64];
        pds_sampler *out = live;
        double r = bad_radius(i);
        snprintf(what, sizeof what, "pds_create(&s, %g, 1)", r);
        assert_failed(NULL, pds_create(&out, r, 1), PDS_EINVAL, what);
        ck_assert_msg(out == NULL, "%s failed but did not set *out to NULL", what);
    }
    pds_destroy(live);
}
END_TEST

/* ---- pds_set_domain ----------------------------------------------------------- */

/* The handle under test starts on this domain, so "unchanged" is not the default. */
static const test_domain OLD_DOMAIN = {0.0, 0.0, 2.0, 3.0};

START_TEST(set_domain_nonfinite)
{
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    const char *names[4] = {"x0", "y0", "x1", "y1"};
    pds_sampler *a, *b;
    sampler_snapshot snap;
    int pos, k;

    twins_new(0.05, 11, &OLD_DOMAIN, 0, &a, &b);
    snapshot_take(a, &snap);
    for (pos = 0; pos < 4; pos++) {
        for (k = 0; k < 3; k++) {
            double v[4] = {0.0, 0.0, 1.0, 1.0};
            char what[96];
            v[pos] = bad[k];
            snprintf(what, sizeof what, "pds_set_domain with %s = %g", names[pos], bad[k]);
            assert_failed(a, pds_set_domain(a, v[0], v[1], v[2], v[3]), PDS_EINVAL, what);
            snapshot_check(a, &snap, what);
        }
    }
    snapshot_free(&snap);
    assert_same_future(a, b, "after non-finite pds_set_domain calls");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(set_domain_empty_or_inverted)
{
    static const test_domain bad[] = {
        {0.0, 0.0, 0.0, 1.0},   /* x0 == x1 */
        {0.0, 0.0, 1.0, 0.0},   /* y0 == y1 */
        {0.0, 0.0, 0.0, 0.0},   /* a point */
        {5.0, 5.0, 5.0, 5.0},   /* a point away from the origin */
        {1.0, 0.0, 0.0, 1.0},   /* x inverted */
        {0.0, 1.0, 1.0, 0.0},   /* y inverted */
        {1.0, 1.0, 0.0, 0.0},   /* both inverted */
        {-1.0, 0.0, -2.0, 1.0}, /* x inverted, negative */
    };
    pds_sampler *a, *b;
    sampler_snapshot snap;
    size_t i, n;
    double *xy;

    twins_new(0.05, 12, &OLD_DOMAIN, 0, &a, &b);
    snapshot_take(a, &snap);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char what[128];
        test_domain d = bad[i];
        snprintf(what, sizeof what, "pds_set_domain(%g, %g, %g, %g)", d.x0, d.y0, d.x1, d.y1);
        assert_failed(a, pds_set_domain(a, d.x0, d.y0, d.x1, d.y1), PDS_EINVAL, what);
        snapshot_check(a, &snap, what);
    }
    snapshot_free(&snap);
    assert_same_future(a, b, "after empty/inverted pds_set_domain calls");
    xy = points_copy(a, &n);
    assert_inside(xy, n, OLD_DOMAIN, "after empty/inverted pds_set_domain calls");
    free(xy);
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* ---- pds_refine --------------------------------------------------------------- */

/* Each invalid radius at one stage of the sampler's life, then the twin check. */
static void check_bad_refines(size_t npoints, const char *stage)
{
    const double r = 0.05;
    pds_sampler *a, *b;
    sampler_snapshot snap;
    int i;

    twins_new(r, 21, NULL, npoints, &a, &b);
    snapshot_take(a, &snap);
    for (i = 0; i < N_BAD_RADII + 2; i++) {
        char what[96];
        /* Besides the bad radii: larger than the current one, by a lot and by one ulp. */
        double v = i == N_BAD_RADII ? 2 * r : i == N_BAD_RADII + 1 ? nextafter(r, 1.0)
                                                                 : bad_radius(i);
        snprintf(what, sizeof what, "%s: pds_refine(s, %.17g) with R = %g", stage, v, r);
        assert_failed(a, pds_refine(a, v), PDS_EINVAL, what);
        snapshot_check(a, &snap, what);
    }
    snapshot_free(&snap);
    assert_same_future(a, b, stage);
    pds_destroy(a);
    pds_destroy(b);
}

START_TEST(refine_bad_radius)
{
    check_bad_refines(0, "before the first point");
    check_bad_refines(25, "after 25 points");
    check_bad_refines(TO_END, "when maximal");
}
END_TEST

/* With points, a refine below the precision limit fails at once (PDS_ERANGE). */
static void check_tiny_refines(size_t npoints, const char *stage)
{
    const double tiny[] = {1e-9, 1e-300, DBL_MIN * DBL_EPSILON};
    pds_sampler *a, *b;
    sampler_snapshot snap;
    size_t i;

    twins_new(0.05, 22, NULL, npoints, &a, &b);
    snapshot_take(a, &snap);
    for (i = 0; i < sizeof tiny / sizeof tiny[0]; i++) {
        char what[96];
        snprintf(what, sizeof what, "%s: pds_refine(s, %g)", stage, tiny[i]);
        assert_failed(a, pds_refine(a, tiny[i]), PDS_ERANGE, what);
        snapshot_check(a, &snap, what);
    }
    snapshot_free(&snap);
    assert_same_future(a, b, stage);
    pds_destroy(a);
    pds_destroy(b);
}

/* Before the first point a refine is judged like pds_create's radius: at the
 * first point (spec 1.1.1). */
static void check_tiny_refines_before_points(void)
{
    const double tiny[] = {1e-9, 1e-300, DBL_MIN * DBL_EPSILON};
    size_t i;

    for (i = 0; i < sizeof tiny / sizeof tiny[0]; i++) {
        char what[96];
        pds_sampler *s = sampler_new(0.05, 22);
        int rc = pds_refine(s, tiny[i]);
        snprintf(what, sizeof what, "pds_refine(s, %g) before the first point", tiny[i]);
        ck_assert_msg(rc == 0, "%s returned %d (%s)", what, rc, pds_errmsg(s));
        ck_assert_msg(pds_radius(s) == tiny[i], "%s: radius %g", what, pds_radius(s));
        assert_run_rejected(s, 0, what);
        assert_step_rejected(s, what);
        pds_destroy(s);
    }
}

START_TEST(refine_radius_too_small)
{
    check_tiny_refines_before_points();
    check_tiny_refines(25, "after 25 points");
}
END_TEST

/* ---- pds_points --------------------------------------------------------------- */

START_TEST(points_out_of_range)
{
    pds_sampler *s = sampler_new(0.05, 31);
    double buf[2 * 16];
    size_t i;
    const size_t firsts[] = {30, 31, 1000, SIZE_MAX};

    /* An empty sampler has nothing to copy. */
    fill(buf, 32, UNTOUCHED);
    ck_assert_uint_eq(pds_points(s, 0, 4, buf), 0);
    assert_untouched(buf, 0, 32, "pds_points on an empty sampler");

    ck_assert_int_eq(pds_run(s, 30, NULL), 1);
    ck_assert_uint_eq(pds_count(s), 30);

    ck_assert_uint_eq(pds_points(s, 0, 4, NULL), 0);
    ck_assert_uint_eq(pds_points(s, 0, 0, buf), 0);
    assert_untouched(buf, 0, 32, "pds_points with count 0");
    for (i = 0; i < sizeof firsts / sizeof firsts[0]; i++) {
        ck_assert_msg(pds_points(s, firsts[i], 4, buf) == 0,
                      "pds_points(first = %zu) with 30 points did not return 0", firsts[i]);
        assert_untouched(buf, 0, 32, "pds_points with first >= count");
    }
    pds_destroy(s);
}
END_TEST

START_TEST(points_clipped)
{
    pds_sampler *s = sampler_new(0.05, 32);
    double buf[2 * 16];
    double *all;
    size_t n;

    ck_assert_int_eq(pds_run(s, 30, NULL), 1);
    all = points_copy(s, &n);

    /* Ask for 10 from index 27: only 27, 28, 29 exist. */
    fill(buf, 32, UNTOUCHED);
    ck_assert_uint_eq(pds_points(s, 27, 10, buf), 3);
    assert_points_equal(buf, 3, all + 2 * 27, 3, "pds_points(27, 10) with 30 points");
    assert_untouched(buf, 6, 32, "pds_points(27, 10) with 30 points");

    /* A count so large that first + count wraps around must clip, not wrap. */
    fill(buf, 32, UNTOUCHED);
    ck_assert_uint_eq(pds_points(s, 25, SIZE_MAX, buf), 5);
    assert_points_equal(buf, 5, all + 2 * 25, 5, "pds_points(25, SIZE_MAX) with 30 points");
    assert_untouched(buf, 10, 32, "pds_points(25, SIZE_MAX) with 30 points");

    pds_destroy(s);
    free(all);
}
END_TEST

Suite *args_suite(void)
{
    Suite *suite = suite_create("args");
    TCase *tc;

    tc = new_tcase(suite, "null_handles");
    tcase_add_test(tc, null_handle_readers);
    tcase_add_test(tc, null_handle_calls);
    tc = new_tcase(suite, "create_bad_radius");
    tcase_add_test(tc, create_bad_radius);
    tc = new_tcase(suite, "set_domain_nonfinite");
    tcase_add_test(tc, set_domain_nonfinite);
    tc = new_tcase(suite, "set_domain_empty_or_inverted");
    tcase_add_test(tc, set_domain_empty_or_inverted);
    tc = new_tcase(suite, "refine_bad_radius");
    tcase_add_test(tc, refine_bad_radius);
    tc = new_tcase(suite, "refine_radius_too_small");
    tcase_add_test(tc, refine_radius_too_small);
    tc = new_tcase(suite, "points_out_of_range");
    tcase_add_test(tc, points_out_of_range);
    tc = new_tcase(suite, "points_clipped");
    tcase_add_test(tc, points_clipped);
    return suite;
}
