/*
 * determinism.c - the same seed gives the same bytes; samplers share nothing.
 *
 * Contract: "the same seed and version give byte-identical points"; "keeps no
 * global state: distinct samplers may be used from distinct threads at once".
 * So the points depend only on the seed, the domain and the radius history,
 * never on other samplers or on how the calls interleave.
 */
#define _POSIX_C_SOURCE 200809L /* pthreads under -std=c99 */

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

static const uint64_t seeds[] = {0, 1, 42, 0x9E3779B97F4A7C15u, UINT64_MAX};
#define N_SEEDS (sizeof seeds / sizeof seeds[0])

START_TEST(same_seed_same_points)
{
    static const test_domain domains[] = {
        {0.0, 0.0, 1.0, 1.0},
        {1000.0, -3.0, 1001.0, -2.0},
        {0.0, 0.0, 4.0, 0.5},
    };
    const double r = test_light() ? 0.08 : 0.03;
    size_t i, j;

    for (i = 0; i < N_SEEDS; i++) {
        for (j = 0; j < sizeof domains / sizeof domains[0]; j++) {
            pds_sampler *a = sampler_new_in(r, seeds[i], domains[j]);
            pds_sampler *b = sampler_new_in(r, seeds[i], domains[j]);
            char what[96];
            snprintf(what, sizeof what, "seed %llu, domain %zu, two handles",
                     (unsigned long long)seeds[i], j);
            run_to_end(a);
            run_to_end(b);
            assert_same_points(a, b, what);
            pds_destroy(a);
            pds_destroy(b);
        }
    }
}
END_TEST

START_TEST(same_seed_after_destroy)
{
    /* A sampler made after another was destroyed starts from the same seed,
     * not from anything the first one left behind. */
    pds_sampler *a = sampler_new(0.05, 7), *b;
    double *xy;
    size_t n;

    run_to_end(a);
    xy = points_copy(a, &n);
    pds_destroy(a);
    b = sampler_new(0.05, 7);
    run_to_end(b);
    assert_prefix_kept(b, xy, n, "seed 7 again after destroying the first sampler");
    ck_assert_uint_eq(pds_count(b), n);
    free(xy);
    pds_destroy(b);
}
END_TEST

START_TEST(different_seeds_differ)
{
    /* Pairs that differ in low bits, high bits only and all bits: every bit of
     * the seed must matter. */
    static const uint64_t pairs[][2] = {
        {1, 2},
        {0, 1},
        {1, 1 + ((uint64_t)1 << 32)},
        {1, 1 + ((uint64_t)1 << 63)},
        {0, UINT64_MAX},
    };
    size_t i;

    for (i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        pds_sampler *a = sampler_new(0.05, pairs[i][0]);
        pds_sampler *b = sampler_new(0.05, pairs[i][1]);
        double pa[2], pb[2];
        ck_assert_int_eq(pds_step(a), 1);
        ck_assert_int_eq(pds_step(b), 1);
        ck_assert_uint_eq(pds_points(a, 0, 1, pa), 1);
        ck_assert_uint_eq(pds_points(b, 0, 1, pb), 1);
        ck_assert_msg(memcmp(pa, pb, sizeof pa) != 0,
                      "seeds %llu and %llu give the same first point (%.17g, %.17g)",
                      (unsigned long long)pairs[i][0], (unsigned long long)pairs[i][1], pa[0],
                      pa[1]);
        run_to_end(a);
        run_to_end(b);
        if (pds_count(a) == pds_count(b)) {
            size_t n;
            double *xa = points_copy(a, &n), *xb = points_copy(b, &n);
            ck_assert_msg(memcmp(xa, xb, 2 * n * sizeof *xa) != 0,
                          "seeds %llu and %llu give the same pattern",
                          (unsigned long long)pairs[i][0], (unsigned long long)pairs[i][1]);
            free(xa);
            free(xb);
        }
        pds_destroy(a);
        pds_destroy(b);
    }
}
END_TEST

/* The reference: one handle alone doing run(20), refine(r1), run to the end. */
static pds_sampler *solo(uint64_t seed, double r0, double r1)
{
    pds_sampler *s = sampler_new(r0, seed);
    ck_assert_int_eq(pds_run(s, 20, NULL), 1);
    ck_assert_int_eq(pds_refine(s, r1), 0);
    run_to_end(s);
    return s;
}

START_TEST(interleaved_handles)
{
    const double r0 = 0.06, r1 = 0.04;
    pds_sampler *ra = solo(71, r0, r1), *rb = solo(72, r0, r1);
    pds_sampler *a = sampler_new(r0, 71), *b = sampler_new(r0, 72);
    int i, rc_a = 1, rc_b = 1;

    /* The same per-handle history, but alternating, with a third sampler born,
     * used and destroyed in between every time. */
    for (i = 0; i < 20; i++) {
        pds_sampler *c = sampler_new(r1, 999 + (uint64_t)i);
        ck_assert_int_eq(pds_step(a), 1);
        ck_assert_int_eq(pds_step(c), 1);
        ck_assert_int_eq(pds_step(b), 1);
        pds_destroy(c);
    }
    ck_assert_int_eq(pds_refine(a, r1), 0);
    ck_assert_int_eq(pds_refine(b, r1), 0);
    while (rc_a == 1 || rc_b == 1) {
        if (rc_a == 1)
            rc_a = pds_run(a, 3, NULL);
        if (rc_b == 1)
            rc_b = pds_step(b);
        ck_assert_int_ge(rc_a, 0);
        ck_assert_int_ge(rc_b, 0);
    }
    assert_same_points(a, ra, "handle a interleaved with b vs alone");
    assert_same_points(b, rb, "handle b interleaved with a vs alone");
    pds_destroy(a);
    pds_destroy(b);
    pds_destroy(ra);
    pds_destroy(rb);
}
END_TEST

/* ---- threads ------------------------------------------------------------------- */

#define N_THREADS 4

struct job {
    uint64_t seed;
    double radius;
    int rc;        /* pds_run's result, or the create failure */
    size_t n;      /* points copied */
    double *xy;    /* malloc'd copy of the points */
};

/* No Check assertions here: they are not for use off the main thread. */
static void *thread_run(void *arg)
{
    struct job *job = arg;
    pds_sampler *s = NULL;

    job->xy = NULL;
    job->n = 0;
    job->rc = pds_create(&s, job->radius, job->seed);
    if (job->rc != 0)
        return NULL;
    job->rc = pds_run(s, 0, NULL);
    job->n = pds_count(s);
    job->xy = malloc((2 * job->n + 2) * sizeof *job->xy);
    if (job->xy != NULL && pds_points(s, 0, job->n, job->xy) != job->n)
        job->rc = -100;
    pds_destroy(s);
    return NULL;
}

START_TEST(threads_independent)
{
    struct job jobs[N_THREADS];
    pthread_t tid[N_THREADS];
    const double r = test_light() ? 0.08 : 0.02;
    int i;

    for (i = 0; i < N_THREADS; i++) {
        jobs[i].seed = 300 + (uint64_t)i;
        jobs[i].radius = r;
        ck_assert_int_eq(pthread_create(&tid[i], NULL, thread_run, &jobs[i]), 0);
    }
    for (i = 0; i < N_THREADS; i++)
        ck_assert_int_eq(pthread_join(tid[i], NULL), 0);
    for (i = 0; i < N_THREADS; i++) {
        pds_sampler *ref = sampler_new(r, jobs[i].seed);
        char what[64];
        snprintf(what, sizeof what, "thread %d vs the same seed on the main thread", i);
        ck_assert_msg(jobs[i].rc == 0, "%s: pds_run in the thread returned %d", what,
                      jobs[i].rc);
        ck_assert_ptr_nonnull(jobs[i].xy);
        run_to_end(ref);
        ck_assert_uint_eq(pds_count(ref), jobs[i].n);
        assert_prefix_kept(ref, jobs[i].xy, jobs[i].n, what);
        free(jobs[i].xy);
        pds_destroy(ref);
    }
}
END_TEST

Suite *determinism_suite(void)
{
    Suite *suite = suite_create("determinism");
    TCase *tc;

    tc = new_tcase(suite, "same_seed");
    tcase_add_test(tc, same_seed_same_points);
    tcase_add_test(tc, same_seed_after_destroy);
    tc = new_tcase(suite, "different_seeds");
    tcase_add_test(tc, different_seeds_differ);
    tc = new_tcase(suite, "interleaved_handles");
    tcase_add_test(tc, interleaved_handles);
    tc = new_tcase(suite, "threads");
    tcase_add_test(tc, threads_independent);
    return suite;
}
