/*
 * count.c - count mode: pds_set_count(s, n) makes a run end with exactly n points.
 *
 * Contract (poissondisk.h, 1.2): the sampler chooses the radius, starting
 * (1.015 + 10/n) times the radius R_ref at which a maximal pattern holds n
 * points on average, n = 0.547 * 4A / (pi R^2) + 0.23 P / R (no P term on the
 * torus), and lowering it by at most 1% each time the pattern is maximal
 * short of n; so once lowered, no room is left at pds_radius() / 0.99.
 * pds_run and pds_step then say PDS_DONE once n points exist; every pair is
 * at least pds_radius() apart; pds_refine is refused (PDS_ESTATE) while a
 * count is set; the radius given to pds_create is ignored; the same seed gives
 * the same points however the work is split. pds_set_count is allowed only
 * before the first point; n == 0 is PDS_EINVAL; a failed call changes nothing.
 * Checked on the unit square, on an off-centre rectangle and on the torus,
 * and on rectangles whose sides come near DBL_MAX, where the start is capped
 * at DBL_MAX.
 */
#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "spacing.h"
#include "suites.h"

#define PI 3.14159265358979323846

struct place {
    const char *name;
    test_domain d;
    int periodic;
};

static const struct place places[] = {
    {"unit square", {0.0, 0.0, 1.0, 1.0}, 0},
    {"[-1,2]x[3,4.5]", {-1.0, 3.0, 2.0, 4.5}, 0},
    {"unit torus", {0.0, 0.0, 1.0, 1.0}, 1},
};
#define N_PLACES (sizeof places / sizeof places[0])

/* The radius at which a maximal pattern holds n points on average. */
static double r_ref(size_t n, const struct place *p)
{
    const double w = p->d.x1 - p->d.x0, h = p->d.y1 - p->d.y0;
    const double a = 0.547 * 4.0 * w * h / PI, b = p->periodic ? 0.0 : 0.23 * 2.0 * (w + h);
    return (b + sqrt(b * b + 4.0 * a * (double)n)) / (2.0 * (double)n);
}

/* A sampler in count mode; the unit square keeps the default domain. */
static pds_sampler *counted_new(const struct place *p, size_t n, uint64_t seed, double radius)
{
    pds_sampler *s = sampler_new(radius, seed);
    if (p != &places[0])
        ck_assert_int_eq(pds_set_domain(s, p->d.x0, p->d.y0, p->d.x1, p->d.y1), 0);
    if (p->periodic)
        ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    ck_assert_msg(pds_set_count(s, n) == 0, "pds_set_count(%zu): %s", n, pds_errmsg(s));
    return s;
}

/* pds_errmsg(s) names the function that failed first. */
static void assert_msg_names(const pds_sampler *s, const char *fn)
{
    const char *msg = pds_errmsg(s);
    size_t len = strlen(fn);
    ck_assert_msg(strncmp(msg, fn, len) == 0 && !isalnum((unsigned char)msg[len]) &&
                      msg[len] != '_',
                  "pds_errmsg is \"%s\", expected it to start with %s", msg, fn);
}

/* A finished count-mode pattern: n points, spaced, and nothing more to add. */
static void check_counted(pds_sampler *s, const struct place *p, size_t n, const char *what)
{
    const double r = pds_radius(s);
    size_t m, added = 77;
    double *xy;
    int rc;

    ck_assert_msg(pds_count(s) == n, "%s: %zu points, expected exactly %zu", what, pds_count(s), n);
    rc = pds_step(s);
    ck_assert_msg(rc == PDS_DONE, "%s: pds_step after n points returned %d", what, rc);
    rc = pds_run(s, 0, &added);
    ck_assert_msg(rc == PDS_DONE && added == 0, "%s: pds_run after n points returned %d, added %zu",
                  what, rc, added);
    rc = pds_verify(s);
    ck_assert_msg(rc == PDS_DONE || rc == PDS_MORE, "%s: pds_verify returned %d (%s)", what, rc,
                  pds_errmsg(s));
    xy = points_copy(s, &m);
    if (p->periodic)
        assert_inside_half_open(xy, m, p->d, what);
    else
        assert_inside(xy, m, p->d, what);
    assert_spacing(xy, m, r, p->d, p->periodic, m <= 1000, what);
    if (n >= 1000) {
        /* Started at (1.015 + 10/n) R_ref, only ever lowered; lowered at least
         * once at this size, so maximal at the radius before the last step. */
        const double ref = r_ref(n, p), start = (1.015 + 10.0 / (double)n) * ref;
        ck_assert_msg(r >= 0.98 * ref && r <= start * (1.0 + 1e-12),
                      "%s: radius %.17g, expected within [0.98, %.4f] x R_ref = %.17g", what, r,
                      start / ref, ref);
        assert_covered(xy, m, r / 0.99, p->d, p->periodic, 200, 2000, n, what);
    }
    free(xy);
}

/* Each place with each n: one loop index per pair, so each fails on its own. */
#define N_COUNTS 5
static size_t count_of(int i)
{
    const size_t ns[N_COUNTS] = {1, 2, 10, 1000, 100000};
    return i % N_COUNTS == N_COUNTS - 1 ? pick(ns[N_COUNTS - 1], 1000) : ns[i % N_COUNTS];
}

START_TEST(exactly_n_points)
{
    const struct place *p = &places[_i / N_COUNTS];
    const size_t n = count_of(_i);
    pds_sampler *s = counted_new(p, n, 10 + (uint64_t)_i, 0.1);
    size_t added = 0;
    char what[128];
    int rc;

    snprintf(what, sizeof what, "%s, n = %zu", p->name, n);
    rc = pds_run(s, 0, &added);
    ck_assert_msg(rc == PDS_DONE, "%s: pds_run returned %d (%s)", what, rc, pds_errmsg(s));
    ck_assert_msg(added == n, "%s: pds_run added %zu", what, added);
    check_counted(s, p, n, what);
    pds_destroy(s);
}
END_TEST

START_TEST(radius_of_create_ignored)
{
    const struct place *p = &places[_i];
    pds_sampler *a = counted_new(p, 1000, 5, 0.3);
    pds_sampler *b = counted_new(p, 1000, 5, 1e-4);

    ck_assert_msg(pds_radius(a) == pds_radius(b), "%s: radius %.17g vs %.17g before the run",
                  p->name, pds_radius(a), pds_radius(b));
    assert_same_future(a, b, "count mode, R 0.3 vs 1e-4 given to pds_create");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(setter_order_free)
{
    /* The count may come before or after the domain and the torus. */
    const struct place *p = &places[_i];
    pds_sampler *a = counted_new(p, 700, 6, 0.1);
    pds_sampler *b = sampler_new(0.1, 6);

    ck_assert_int_eq(pds_set_count(b, 700), 0);
    if (p->periodic)
        ck_assert_int_eq(pds_set_periodic(b, 1), 0);
    ck_assert_int_eq(pds_set_domain(b, p->d.x0, p->d.y0, p->d.x1, p->d.y1), 0);
    assert_same_future(a, b, "pds_set_count first");
    check_counted(b, p, 700, "pds_set_count first");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(judged_at_the_lowest_radius)
{
    /* A square 3 * 2^-26 * 1e15 wide at 1e15, where the precision limit is
     * 2^-26 * 2^49: 37 points start 1.03 times above it, and lowering the
     * radius used to cross it in the middle of the run (PDS_ERANGE after 23
     * points; found by the fuzz harness). The lowest radius count mode can
     * reach, 0.98 sqrt(A / (pi n)), is judged at the first point instead. */
    const double lo = 1e15, hi = 1e15 + 3.0 * 0x1p-26 * 1e15;
    pds_sampler *s = sampler_new(1.0, 1);
    size_t added = 99, n;
    double *xy;
    int rc;

    ck_assert_int_eq(pds_set_domain(s, lo, lo, hi, hi), 0);
    ck_assert_int_eq(pds_set_count(s, 37), 0);
    rc = pds_run(s, 0, &added);
    ck_assert_msg(rc == PDS_ERANGE && added == 0 && pds_count(s) == 0,
                  "37 points near the precision limit: pds_run returned %d, added %zu, count %zu",
                  rc, added, pds_count(s));
    ck_assert_msg(strncmp(pds_errmsg(s), "pds_run", 7) == 0, "pds_errmsg is \"%s\"",
                  pds_errmsg(s));
    assert_step_rejected(s, "37 points near the precision limit, pds_step");
    /* Four points are judged at 0.98 sqrt(A / 4 pi), above the limit: exactly 4. */
    ck_assert_int_eq(pds_set_count(s, 4), 0);
    rc = pds_run(s, 0, &added);
    ck_assert_msg(rc == PDS_DONE && added == 4, "4 points: pds_run returned %d (%s), added %zu", rc,
                  pds_errmsg(s), added);
    xy = points_copy(s, &n);
    assert_spacing(xy, n, pds_radius(s), (test_domain){lo, lo, hi, hi}, 0, 1, "4 points near the limit");
    free(xy);
    pds_destroy(s);
}
END_TEST

/* pds_run(s, k) until PDS_DONE (k 0: pds_step until 0); each call adds k or finishes. */
static void run_split(pds_sampler *s, size_t k, size_t n, const char *what)
{
    size_t calls = 0;
    int rc;

    do {
        size_t before = pds_count(s), added = 0;
        if (k == 0) {
            rc = pds_step(s);
            added = pds_count(s) - before;
            ck_assert_msg(rc == (before < n ? PDS_MORE : PDS_DONE) && added == (rc == PDS_MORE),
                          "%s: pds_step at %zu points returned %d", what, before, rc);
        } else {
            rc = pds_run(s, k, &added);
            ck_assert_msg(rc == (before + k < n ? PDS_MORE : PDS_DONE) &&
                              added == (before + k < n ? k : n - before),
                          "%s: pds_run(s, %zu) at %zu points returned %d, added %zu", what, k,
                          before, rc, added);
        }
    } while (rc == PDS_MORE && ++calls <= n + 1);
}

START_TEST(same_points_however_split)
{
    const struct place *p = &places[_i];
    const size_t n = pick(1000, 300), ks[] = {1, 7, n - 1, n, n + 1, 0};
    pds_sampler *ref = counted_new(p, n, 7, 0.1);
    size_t i, nref;
    double *xy;

    run_to_end(ref);
    xy = points_copy(ref, &nref);
    for (i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        pds_sampler *s = counted_new(p, n, 7, 0.1);
        char what[128];
        size_t m;
        double *got;

        snprintf(what, sizeof what, "%s, n = %zu, %s %zu", p->name, n,
                 ks[i] ? "pds_run chunks of" : "pds_step loop", ks[i] ? ks[i] : n);
        run_split(s, ks[i], n, what);
        got = points_copy(s, &m);
        assert_points_equal(got, m, xy, nref, what);
        ck_assert_msg(pds_radius(s) == pds_radius(ref), "%s: radius %.17g vs %.17g", what,
                      pds_radius(s), pds_radius(ref));
        free(got);
        pds_destroy(s);
    }
    free(xy);
    pds_destroy(ref);
}
END_TEST

START_TEST(large_split)
{
    const size_t n = pick(100000, 2000);
    pds_sampler *a = counted_new(&places[0], n, 8, 0.1);
    pds_sampler *b = counted_new(&places[0], n, 8, 0.1);

    run_split(a, 4099, n, "n = 1e5 in chunks of 4099");
    run_to_end(b);
    assert_same_points(a, b, "n = 1e5 in chunks of 4099");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* pds_refine(smaller) refused with PDS_ESTATE; nothing changes. */
static void check_refine_refused(pds_sampler *s, const char *what)
{
    sampler_snapshot snap;

    snapshot_take(s, &snap);
    assert_failed(s, pds_refine(s, 0.5 * pds_radius(s)), PDS_ESTATE, what);
    assert_msg_names(s, "pds_refine");
    snapshot_check(s, &snap, what);
    snapshot_free(&snap);
}

START_TEST(refine_refused)
{
    pds_sampler *a = counted_new(&places[0], 800, 9, 0.1);
    pds_sampler *b = counted_new(&places[0], 800, 9, 0.1);

    check_refine_refused(a, "pds_refine in count mode, no point yet");
    ck_assert_int_eq(pds_run(a, 10, NULL), PDS_MORE);
    ck_assert_int_eq(pds_run(b, 10, NULL), PDS_MORE);
    check_refine_refused(a, "pds_refine in count mode, 10 points");
    assert_same_future(a, b, "after the refused refines");
    check_refine_refused(a, "pds_refine in count mode, n points");
    check_counted(a, &places[0], 800, "after the refused refines");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* Domains whose sides come near DBL_MAX: there the start, R(n) times
 * 1.015 + 10/n, is above the largest double for small n. It is capped at
 * DBL_MAX, so the run ends (an infinite start lowered by 1% stays infinite)
 * and pds_radius() stays finite. Checked in units 2^-1020 of the user's,
 * where the distances do not overflow. */
static const test_domain huge_places[] = {
    {-DBL_MAX, -DBL_MAX, DBL_MAX, DBL_MAX},
    {-DBL_MAX, -DBL_MAX / 2, DBL_MAX / 8, DBL_MAX / 2},
};

START_TEST(start_beyond_the_largest_double)
{
    const size_t ns[] = {1, 2, 3, 5, 10, 40};
    const test_domain d = huge_places[_i];
    const test_domain scaled = {ldexp(d.x0, -1020), ldexp(d.y0, -1020), ldexp(d.x1, -1020),
                                ldexp(d.y1, -1020)};
    size_t k, m, j;

    for (k = 0; k < sizeof ns / sizeof ns[0]; k++) {
        const size_t n = ns[k];
        pds_sampler *s = sampler_new(1.0, 40 + (uint64_t)k);
        char what[128];
        double *xy, r;
        int rc;

        snprintf(what, sizeof what, "[%g,%g]x[%g,%g], n = %zu", d.x0, d.x1, d.y0, d.y1, n);
        ck_assert_int_eq(pds_set_domain(s, d.x0, d.y0, d.x1, d.y1), 0);
        ck_assert_int_eq(pds_set_count(s, n), 0);
        r = pds_radius(s);
        ck_assert_msg(r == DBL_MAX || n > 3, "%s: start radius %.17g, expected DBL_MAX", what, r);
        rc = pds_run(s, 0, NULL);
        ck_assert_msg(rc == PDS_DONE, "%s: pds_run returned %d (%s)", what, rc, pds_errmsg(s));
        r = pds_radius(s);
        ck_assert_msg(isfinite(r) && r > 0.0, "%s: pds_radius is %.17g", what, r);
        xy = points_copy(s, &m);
        ck_assert_msg(m == n, "%s: %zu points", what, m);
        for (j = 0; j < 2 * m; j++) xy[j] = ldexp(xy[j], -1020);
        assert_inside(xy, m, scaled, what);
        assert_spacing(xy, m, ldexp(r, -1020), scaled, 0, 1, what);
        if (r < DBL_MAX) /* lowered at least once */
            assert_covered(xy, m, ldexp(r, -1020) / 0.99, scaled, 0, 200, 2000, n, what);
        free(xy);
        pds_destroy(s);
    }
}
END_TEST

START_TEST(bad_counts)
{
    pds_sampler *a = sampler_new(0.05, 11), *b = sampler_new(0.05, 11);
    sampler_snapshot snap;

    ck_assert_int_eq(pds_set_count(NULL, 10), PDS_EINVAL);
    /* n == 0: refused, and the sampler stays in its plain mode. */
    assert_failed(a, pds_set_count(a, 0), PDS_EINVAL, "pds_set_count(s, 0)");
    assert_msg_names(a, "pds_set_count");
    assert_same_future(a, b, "after pds_set_count(s, 0)");
    assert_maximal(a, "after pds_set_count(s, 0)");
    pds_destroy(a);
    pds_destroy(b);

    /* n == 0 after a valid count keeps that count. */
    a = counted_new(&places[1], 500, 12, 0.1);
    assert_failed(a, pds_set_count(a, 0), PDS_EINVAL, "pds_set_count(s, 0) in count mode");
    run_to_end(a);
    check_counted(a, &places[1], 500, "count kept after pds_set_count(s, 0)");
    pds_destroy(a);

    /* After points, plain mode: refused, nothing changed, same future. */
    twins_new(0.05, 13, NULL, 5, &a, &b);
    snapshot_take(a, &snap);
    assert_failed(a, pds_set_count(a, 20), PDS_ESTATE, "pds_set_count after points");
    assert_msg_names(a, "pds_set_count");
    snapshot_check(a, &snap, "pds_set_count after points");
    snapshot_free(&snap);
    assert_same_future(a, b, "after pds_set_count refused");
    pds_destroy(a);
    pds_destroy(b);

    /* After points, count mode: the first count stays. */
    a = counted_new(&places[0], 300, 14, 0.1);
    ck_assert_int_eq(pds_run(a, 10, NULL), PDS_MORE);
    assert_failed(a, pds_set_count(a, 600), PDS_ESTATE, "pds_set_count twice");
    assert_msg_names(a, "pds_set_count");
    run_to_end(a);
    check_counted(a, &places[0], 300, "count kept after pds_set_count refused");
    pds_destroy(a);
}
END_TEST

Suite *count_suite(void)
{
    Suite *s = suite_create("count");
    TCase *tc = new_tcase(s, "exact count");
    tcase_add_loop_test(tc, exactly_n_points, 0, (int)(N_PLACES * N_COUNTS));
    tcase_add_loop_test(tc, radius_of_create_ignored, 0, (int)N_PLACES);
    tcase_add_loop_test(tc, setter_order_free, 0, (int)N_PLACES);
    tcase_add_loop_test(tc, start_beyond_the_largest_double, 0,
                        (int)(sizeof huge_places / sizeof huge_places[0]));
    tc = new_tcase(s, "split");
    tcase_add_loop_test(tc, same_points_however_split, 0, (int)N_PLACES);
    tcase_add_test(tc, large_split);
    tc = new_tcase(s, "refused calls");
    tcase_add_test(tc, refine_refused);
    tcase_add_test(tc, judged_at_the_lowest_radius);
    tcase_add_test(tc, bad_counts);
    return s;
}
