/*
 * periodic.c - pds_set_periodic: the domain as a flat torus.
 *
 * Contract (poissondisk.h, 1.2): points lie in [x0,x1) x [y0,y1); every pair
 * is at least R apart across the wrap too; maximality is decided on the torus;
 * each point is uniform over the torus's free area, so there is no density
 * excess at the edges (copies shifted by whole periods tile the plane with a
 * maximal Poisson-disk set). R above half the shorter period is PDS_ERANGE at
 * the first point; pds_set_periodic is allowed only before the first point.
 * Checked independently of the library: spacing by a wrapping bucket grid
 * (and brute force), maximality by probes, the law by RSA's saturation
 * coverage 0.547 and by the density of a strip across the seam against an
 * interior strip.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "spacing.h"
#include "suites.h"

#define PI 3.14159265358979323846

struct torus {
    const char *name;
    test_domain d;
    double r; /* a radius giving ~1e3 points */
};

static const struct torus tori[] = {
    {"unit torus", {0.0, 0.0, 1.0, 1.0}, 0.02},
    {"torus [-1,2]x[3,4.5]", {-1.0, 3.0, 2.0, 4.5}, 0.05},
};
#define N_TORI (sizeof tori / sizeof tori[0])

static double area(test_domain d) { return (d.x1 - d.x0) * (d.y1 - d.y0); }

/* A sampler on the torus over d (no pds_set_domain for the unit square). */
static pds_sampler *torus_new(double r, uint64_t seed, test_domain d)
{
    pds_sampler *s = sampler_new(r, seed);
    if (d.x0 != 0.0 || d.y0 != 0.0 || d.x1 != 1.0 || d.y1 != 1.0)
        ck_assert_int_eq(pds_set_domain(s, d.x0, d.y0, d.x1, d.y1), 0);
    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    return s;
}

/* A finished torus pattern at the current radius: inside, spaced, maximal. */
static void check_torus(pds_sampler *s, test_domain d, size_t lattice, const char *what)
{
    const double r = pds_radius(s);
    size_t n;
    double *xy = points_copy(s, &n);

    assert_inside_half_open(xy, n, d, what);
    assert_spacing(xy, n, r, d, 1, 0, what);
    if (n <= pick(2000, 500))
        assert_spacing(xy, n, r, d, 1, 1, what);
    assert_covered(xy, n, r, d, 1, lattice, 20000, n, what);
    assert_maximal(s, what);
    free(xy);
}

START_TEST(maximal_pattern_on_the_torus)
{
    const struct torus *t = &tori[_i];
    uint64_t seed;

    for (seed = 1; seed <= pick(4, 1); seed++) {
        pds_sampler *s = torus_new(t->r, seed, t->d);
        char what[96];
        snprintf(what, sizeof what, "%s, R %g, seed %llu", t->name, t->r,
                 (unsigned long long)seed);
        run_to_end(s);
        check_torus(s, t->d, pick(400, 100), what);
        pds_destroy(s);
    }
}
END_TEST

START_TEST(small_patterns_brute_force)
{
    /* A few dozen points: most of them touch the seam. */
    uint64_t seed;

    for (seed = 1; seed <= pick(20, 3); seed++) {
        pds_sampler *s = torus_new(0.1, seed, tori[_i].d);
        char what[96];
        snprintf(what, sizeof what, "%s, R 0.1, seed %llu", tori[_i].name,
                 (unsigned long long)seed);
        run_to_end(s);
        check_torus(s, tori[_i].d, 200, what);
        pds_destroy(s);
    }
}
END_TEST

/* Half the shorter period: the largest radius allowed, where a disk just does
 * not overlap its own copy; and the next radius above it worth trying. */
static const double half[N_TORI] = {0.5, 0.75};
static const double above[N_TORI] = {0.5000001, 0.7500001};

START_TEST(radius_half_the_shorter_period)
{
    uint64_t seed;

    for (seed = 1; seed <= 5; seed++) {
        pds_sampler *s = torus_new(half[_i], seed, tori[_i].d);
        run_to_end(s);
        check_torus(s, tori[_i].d, 200, "R half the shorter period");
        pds_destroy(s);
    }
}
END_TEST

START_TEST(radius_above_half_the_period)
{
    const test_domain d = tori[_i].d;
    pds_sampler *s = torus_new(above[_i], 1, d);
    size_t n;
    double *xy;

    assert_run_rejected(s, 0, "R above half the period, pds_run(s, 0)");
    ck_assert_msg(strncmp(pds_errmsg(s), "pds_run", 7) == 0, "pds_errmsg is \"%s\"",
                  pds_errmsg(s));
    assert_run_rejected(s, 1, "R above half the period, pds_run(s, 1)");
    assert_step_rejected(s, "R above half the period, pds_step");
    /* Still usable: a refine to half the period, then a maximal pattern. */
    ck_assert_int_eq(pds_refine(s, half[_i]), 0);
    run_to_end(s);
    check_torus(s, d, 100, "after the refused run, refined to half the period");
    pds_destroy(s);
    /* Or back to the plain rectangle, where that radius is fine. */
    s = torus_new(above[_i], 2, d);
    assert_run_rejected(s, 0, "R above half the period");
    ck_assert_int_eq(pds_set_periodic(s, 0), 0);
    run_to_end(s);
    xy = points_copy(s, &n);
    assert_inside(xy, n, d, "plain again after the refused run");
    assert_maximal(s, "plain again after the refused run");
    free(xy);
    pds_destroy(s);
}
END_TEST

START_TEST(periods_within_1024_to_1)
{
    /* 1024:1 is sampled, and a sparse pattern on it is cheap to query; one
     * more in 1024 is PDS_ERANGE at the first point, nothing added. */
    const test_domain thin = {0.0, 0.0, 1.0, 0x1p-10}, thinner = {0.0, 0.0, 1.0 + 0x1p-10, 0x1p-10};
    pds_sampler *s = torus_new(0x1p-11, 1, thinner);
    size_t added = 0;

    assert_run_rejected(s, 0, "1025:1 torus, pds_run(s, 0)");
    ck_assert_msg(strstr(pds_errmsg(s), "1024") != NULL, "pds_errmsg is \"%s\"", pds_errmsg(s));
    assert_step_rejected(s, "1025:1 torus, pds_step");
    ck_assert_int_eq(pds_set_domain(s, thin.x0, thin.y0, thin.x1, thin.y1), 0);
    ck_assert_int_eq(pds_run(s, 10, &added), PDS_MORE);
    ck_assert_int_eq(pds_verify(s), PDS_MORE);
    ck_assert_msg(pds_free_area(s) > 0.9 * area(thin), "10 points leave %g of %g free",
                  pds_free_area(s), area(thin));
    run_to_end(s);
    check_torus(s, thin, 40, "1024:1 torus");
    pds_destroy(s);
}
END_TEST

START_TEST(verify_memory_follows_the_points)
{
    /* 7 points at R 1e-5: the spacing check once sized a dense grid by
     * period / R, 2^32 buckets (32 GB), and failed with PDS_ENOMEM. */
    pds_sampler *s = torus_new(1e-5, 3, tori[0].d);
    size_t added = 0;

    ck_assert_int_eq(pds_run(s, 7, &added), PDS_MORE);
    ck_assert_msg(pds_verify(s) == PDS_MORE, "pds_verify on 7 points: %s", pds_errmsg(s));
    pds_destroy(s);
}
END_TEST

START_TEST(free_area_on_the_torus)
{
    const test_domain d = tori[_i].d;
    const double r = 0.2;
    uint64_t seed;

    for (seed = 1; seed <= 6; seed++) {
        pds_sampler *s = torus_new(r, seed, d);
        double fa;
        assert_rel_close(pds_free_area(s), area(d), 1e-15, "free area before the first point");
        /* One disk is never clipped on the torus, wherever it lies. */
        ck_assert_int_eq(pds_step(s), PDS_MORE);
        fa = pds_free_area(s);
        assert_rel_close(fa, area(d) - PI * r * r, 1e-9, "free area after one point");
        ck_assert_int_eq(pds_run(s, 2, NULL), PDS_MORE);
        fa = pds_free_area(s);
        ck_assert_msg(fa > 0.0 && fa < area(d) - PI * r * r, "free area %g after 3 points", fa);
        run_to_end(s);
        ck_assert_msg(pds_free_area(s) == 0.0, "free area %.17g when maximal", pds_free_area(s));
        pds_destroy(s);
    }
}
END_TEST

START_TEST(coverage_is_rsa_saturation)
{
    /* pi R^2 N / (4A) -> 0.547 for RSA; a rectangle adds 0.23 P / R points
     * (+0.0029 at R 0.004, +0.0072 at R 0.01), which the tolerance must not
     * absorb: 0.003 would let the plain square through. */
    const double r = test_light() ? 0.01 : 0.004;
    const uint64_t seeds = pick(6, 2);
    /* Measured on the torus: 0.5470 with a standard deviation of 0.0007 per
     * seed at R 0.004 and 0.0019 at R 0.01 (about 4 standard errors here). */
    const double tol = test_light() ? 0.005 : 0.0015;
    double sum = 0.0, cov;
    uint64_t seed;

    for (seed = 1; seed <= seeds; seed++) {
        pds_sampler *s = torus_new(r, 100 + seed, tori[0].d);
        run_to_end(s);
        sum += PI * r * r * (double)pds_count(s) / 4.0;
        pds_destroy(s);
    }
    cov = sum / (double)seeds;
    ck_assert_msg(fabs(cov - 0.547) <= tol, "coverage %.5f over %llu seeds at R %g, "
                  "expected 0.547 +- %g", cov, (unsigned long long)seeds, r, tol);
}
END_TEST

START_TEST(no_density_excess_at_the_seam)
{
    /* Points within R of the seam (a strip of width 2R across it) against a
     * strip of the same width in the middle, in x and in y, pooled. On a
     * rectangle the seam strip holds about a third more. */
    const double r = test_light() ? 0.01 : 0.004;
    const uint64_t seeds = pick(6, 2);
    double seam = 0.0, middle = 0.0;
    uint64_t seed;
    size_t i, n;

    for (seed = 1; seed <= seeds; seed++) {
        pds_sampler *s = torus_new(r, 200 + seed, tori[0].d);
        double *xy;
        run_to_end(s);
        xy = points_copy(s, &n);
        for (i = 0; i < 2 * n; i++) {
            const double v = xy[i];
            seam += v < r || v >= 1.0 - r;
            middle += fabs(v - 0.5) < r;
        }
        free(xy);
        pds_destroy(s);
    }
    /* 4.5 Poisson standard deviations; RSA counts vary less than Poisson. */
    ck_assert_msg(fabs(seam - middle) <= 4.5 * sqrt(seam + middle),
                  "%.0f points by the seam vs %.0f in the middle", seam, middle);
}
END_TEST

START_TEST(refine_on_the_torus)
{
    const struct torus *t = &tori[_i];
    pds_sampler *s = torus_new((test_light() ? 4.0 : 2.0) * t->r, 3, t->d);
    size_t n;
    double *first;

    run_to_end(s);
    first = points_copy(s, &n);
    ck_assert_int_eq(pds_refine(s, (test_light() ? 2.0 : 1.0) * t->r), 0);
    run_to_end(s);
    assert_prefix_kept(s, first, n, "refine on the torus");
    check_torus(s, t->d, pick(300, 100), "refine on the torus");
    free(first);
    pds_destroy(s);
}
END_TEST

/* pds_run(s, k) until done (k 0: pds_step until 0). */
static void run_split(pds_sampler *s, size_t k)
{
    size_t calls = 0;
    int rc;
    do
        rc = k ? pds_run(s, k, NULL) : pds_step(s);
    while ((rc == PDS_MORE) && ++calls < 1000000);
    ck_assert_msg(rc == PDS_DONE, "split %zu ended with %d (%s)", k, rc, pds_errmsg(s));
}

START_TEST(same_points_however_split)
{
    const test_domain d = tori[_i].d;
    const double r0 = test_light() ? 0.1 : 0.05, r1 = test_light() ? 0.06 : 0.03;
    pds_sampler *ref = torus_new(r0, 4, d);
    size_t n, nref, w;
    double *xy;

    n = run_to_end(ref);
    ck_assert_int_eq(pds_refine(ref, r1), 0);
    run_to_end(ref);
    xy = points_copy(ref, &nref);
    for (w = 0; w < 6; w++) {
        const size_t k[6] = {1, 7, n - 1, n, n + 1, 0};
        pds_sampler *s = torus_new(r0, 4, d);
        char what[96];
        size_t m;
        double *got;
        snprintf(what, sizeof what, "%s: split %zu of n = %zu, refine, run", tori[_i].name,
                 k[w], n);
        run_split(s, k[w]);
        ck_assert_int_eq(pds_refine(s, r1), 0);
        run_to_end(s);
        got = points_copy(s, &m);
        assert_points_equal(got, m, xy, nref, what);
        free(got);
        pds_destroy(s);
    }
    free(xy);
    pds_destroy(ref);
}
END_TEST

START_TEST(set_periodic_after_points)
{
    pds_sampler *a, *b;
    sampler_snapshot snap;

    ck_assert_int_eq(pds_set_periodic(NULL, 1), PDS_EINVAL);
    a = torus_new(0.05, 5, tori[_i].d);
    b = torus_new(0.05, 5, tori[_i].d);
    ck_assert_int_eq(pds_run(a, 10, NULL), PDS_MORE);
    ck_assert_int_eq(pds_run(b, 10, NULL), PDS_MORE);
    snapshot_take(a, &snap);
    assert_failed(a, pds_set_periodic(a, 0), PDS_ESTATE, "pds_set_periodic(s, 0) after points");
    ck_assert_msg(strncmp(pds_errmsg(a), "pds_set_periodic", 16) == 0, "pds_errmsg is \"%s\"",
                  pds_errmsg(a));
    assert_failed(a, pds_set_periodic(a, 1), PDS_ESTATE, "pds_set_periodic(s, 1) after points");
    snapshot_check(a, &snap, "pds_set_periodic after points");
    snapshot_free(&snap);
    assert_same_future(a, b, "pds_set_periodic after points");
    check_torus(a, tori[_i].d, 100, "pds_set_periodic after points");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(period_not_a_binary_fraction)
{
    /* A period of 0.1 is rounded down by less than 1e-15 of the domain: the
     * points stay below 0.1 and the spacing holds to that precision. */
    const test_domain d = {0.0, 0.0, 0.1, 0.1};
    pds_sampler *s = torus_new(0.005, 6, d);
    size_t n;
    double *xy;

    run_to_end(s);
    xy = points_copy(s, &n);
    assert_inside_half_open(xy, n, d, "period 0.1");
    assert_spacing(xy, n, 0.005 * (1.0 - 1e-12), d, 1, 0, "period 0.1");
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    free(xy);
    pds_destroy(s);
}
END_TEST

Suite *periodic_suite(void)
{
    Suite *s = suite_create("periodic");
    TCase *tc = new_tcase(s, "geometry");
    tcase_add_loop_test(tc, maximal_pattern_on_the_torus, 0, (int)N_TORI);
    tcase_add_loop_test(tc, small_patterns_brute_force, 0, (int)N_TORI);
    tcase_add_loop_test(tc, radius_half_the_shorter_period, 0, (int)N_TORI);
    tcase_add_loop_test(tc, free_area_on_the_torus, 0, (int)N_TORI);
    tcase_add_test(tc, period_not_a_binary_fraction);
    tcase_add_test(tc, periods_within_1024_to_1);
    tcase_add_test(tc, verify_memory_follows_the_points);
    tc = new_tcase(s, "law");
    tcase_add_test(tc, coverage_is_rsa_saturation);
    tcase_add_test(tc, no_density_excess_at_the_seam);
    tc = new_tcase(s, "refine, splits, state");
    tcase_add_loop_test(tc, refine_on_the_torus, 0, (int)N_TORI);
    tcase_add_loop_test(tc, same_points_however_split, 0, (int)N_TORI);
    tcase_add_loop_test(tc, set_periodic_after_points, 0, (int)N_TORI);
    tcase_add_loop_test(tc, radius_above_half_the_period, 0, (int)N_TORI);
    return s;
}
