/*
 * splits.c - the same bytes however the calls split the work, refine included.
 *
 * Contract (spec 1.1.1, "Determinism across call splits"): the same seed gives
 * byte-identical points whether a run to the end is one pds_run; bounded runs
 * in chunks of 1, 7, n-1, n or n+1 points (n = the maximal count), repeated
 * until PDS_DONE; pds_step until 0; or pds_step exactly n times, without the
 * final 0 -- each followed by pds_refine(smaller) and a second run to the end.
 * The hard cases stop exactly on the pattern's last point, where the sampler
 * has not yet seen for itself that no room is left when the refine comes. A
 * refine in the middle of a run, at count k, is also the same whatever split
 * led to k. And small chunks, one point a call: while (pds_run(s, 1, NULL) ==
 * PDS_MORE); gives the points of one pds_run at about 10^5 points (a
 * correctness test only: the cost is measured by make bench).
 */
#include <stdio.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

/* Enough to finish any pattern here; a loop bound, not a target. */
#define MAX_CALLS 10000000

/* (first radius, refined radius) pairs: about 300 -> 1800 and 7000 -> 28600 points. */
static const double radii[][2] = {{0.05, 0.02}, {0.01, 0.005}};

static size_t n_cases(void) { return pick(2, 1); }
/* Seeds 1..n_seeds; the refine in the middle tries three counts per seed, so fewer. */
static uint64_t n_seeds(size_t c) { return c == 0 ? pick(8, 1) : pick(3, 1); }
static uint64_t n_mid_seeds(size_t c) { return c == 0 ? pick(4, 1) : 1; }

/* The reference: one unbounded pds_run, refine, one unbounded pds_run. *n
 * receives the maximal count at the first radius. */
static double *reference(double r0, double r1, uint64_t seed, size_t *n, size_t *total)
{
    pds_sampler *s = sampler_new(r0, seed);
    double *xy;

    *n = run_to_end(s);
    ck_assert_int_eq(pds_refine(s, r1), 0);
    run_to_end(s);
    xy = points_copy(s, total);
    pds_destroy(s);
    return xy;
}

/*
 * pds_run(s, chunk, ...) until PDS_DONE or until the count reaches stop
 * (stop 0: no stop; the last chunk is then cut to reach it exactly). Each
 * call must return PDS_MORE with exactly the chunk added, or PDS_DONE.
 * Returns the number of calls.
 */
static size_t run_chunks(pds_sampler *s, size_t chunk, size_t stop, const char *what)
{
    size_t calls = 0;
    int rc;

    do {
        size_t want = stop != 0 && stop - pds_count(s) < chunk ? stop - pds_count(s) : chunk;
        size_t before = pds_count(s), added = (size_t)-1;
        rc = pds_run(s, want, &added);
        ck_assert_msg(rc == PDS_DONE || rc == PDS_MORE, "%s: pds_run(s, %zu) returned %d (%s)",
                      what, want, rc, pds_errmsg(s));
        ck_assert_msg(added == pds_count(s) - before, "%s: pds_run reported %zu added, the "
                      "count went from %zu to %zu", what, added, before, pds_count(s));
        ck_assert_msg(rc == PDS_DONE ? added <= want : added == want,
                      "%s: pds_run(s, %zu) returned %d after adding %zu", what, want, rc, added);
    } while (++calls < MAX_CALLS && rc == PDS_MORE && (stop == 0 || pds_count(s) < stop));
    return calls;
}

/* pds_step k times, each adding a point. */
static void steps(pds_sampler *s, size_t k, const char *what)
{
    size_t i;
    for (i = 0; i < k; i++) {
        int rc = pds_step(s);
        ck_assert_msg(rc == PDS_MORE, "%s: pds_step %zu of %zu returned %d (%s)", what, i + 1,
                      k, rc, pds_errmsg(s));
    }
}

/* The ways to reach the end of the first pattern (n points). */
enum way { CHUNK_1, CHUNK_7, CHUNK_N_MINUS_1, CHUNK_N, CHUNK_N_PLUS_1, STEP_TO_0, STEP_N, N_WAYS };
static const char *const way_name[N_WAYS] = {
    "pds_run chunks of 1", "pds_run chunks of 7", "pds_run chunks of n-1",
    "one pds_run(s, n)", "pds_run chunks of n+1", "pds_step until 0", "pds_step exactly n times",
};

/* Chunks of c: the call that adds the last point already says PDS_DONE (no
 * room left), so it takes ceil(n / c) calls; n and n+1 take one. */
static void chunks_to_the_end(pds_sampler *s, size_t c, size_t n, const char *what)
{
    size_t calls = run_chunks(s, c, 0, what);
    ck_assert_msg(calls == (n + c - 1) / c, "%s: %zu calls of pds_run(s, %zu) for %zu points, "
                  "expected %zu", what, calls, c, n, (n + c - 1) / c);
}

static void reach_the_end(pds_sampler *s, enum way w, size_t n, const char *what)
{
    static const size_t fixed[] = {1, 7};
    int rc;
    switch (w) {
    case CHUNK_1:
    case CHUNK_7: chunks_to_the_end(s, fixed[w], n, what); break;
    case CHUNK_N_MINUS_1: chunks_to_the_end(s, n - 1, n, what); break;
    case CHUNK_N: chunks_to_the_end(s, n, n, what); break;
    case CHUNK_N_PLUS_1: chunks_to_the_end(s, n + 1, n, what); break;
    case STEP_TO_0:
        steps(s, n, what);
        rc = pds_step(s);
        ck_assert_msg(rc == PDS_DONE, "%s: pds_step after n points returned %d", what, rc);
        break;
    case STEP_N: steps(s, n, what); break;
    case N_WAYS: break;
    }
}

START_TEST(refine_after_the_last_point)
{
    size_t c;

    for (c = 0; c < n_cases(); c++) {
        const double r0 = radii[c][0], r1 = radii[c][1];
        uint64_t seed;
        for (seed = 1; seed <= n_seeds(c); seed++) {
            size_t n, total, w;
            double *ref = reference(r0, r1, seed, &n, &total);
            for (w = 0; w < N_WAYS; w++) {
                pds_sampler *s = sampler_new(r0, seed);
                char what[160];
                size_t m;
                double *xy;
                snprintf(what, sizeof what, "R %g, seed %llu: %s (n = %zu), refine to %g, "
                         "run to the end", r0, (unsigned long long)seed, way_name[w], n, r1);
                reach_the_end(s, (enum way)w, n, what);
                ck_assert_msg(pds_count(s) == n, "%s: %zu points, the unbounded run gave %zu",
                              what, pds_count(s), n);
                ck_assert_int_eq(pds_refine(s, r1), 0);
                run_to_end(s);
                xy = points_copy(s, &m);
                assert_points_equal(xy, m, ref, total, what);
                free(xy);
                pds_destroy(s);
            }
            free(ref);
        }
    }
}
END_TEST

/* The ways to reach count k in the middle of the first run. */
enum mid_way { MID_ONE_RUN, MID_CHUNK_1, MID_CHUNK_7, MID_HALVES, MID_STEPS, N_MID_WAYS };
static const char *const mid_way_name[N_MID_WAYS] = {
    "one pds_run(s, k)", "pds_run chunks of 1", "pds_run chunks of 7",
    "pds_run(s, k/2) twice", "pds_step k times",
};

static void reach_k(pds_sampler *s, enum mid_way w, size_t k, const char *what)
{
    switch (w) {
    case MID_ONE_RUN: run_chunks(s, k, k, what); break;
    case MID_CHUNK_1: run_chunks(s, 1, k, what); break;
    case MID_CHUNK_7: run_chunks(s, 7, k, what); break;
    case MID_HALVES: run_chunks(s, (k + 1) / 2, k, what); break;
    case MID_STEPS: steps(s, k, what); break;
    case N_MID_WAYS: break;
    }
    ck_assert_msg(pds_count(s) == k, "%s: %zu points, expected %zu", what, pds_count(s), k);
}

START_TEST(refine_in_the_middle)
{
    size_t c;

    for (c = 0; c < n_cases(); c++) {
        const double r0 = radii[c][0], r1 = radii[c][1];
        uint64_t seed;
        for (seed = 1; seed <= n_mid_seeds(c); seed++) {
            size_t n, total, j;
            double *ref = reference(r0, r1, seed, &n, &total);
            /* Early (the opening stage), late, and one short of the end. */
            const size_t ks[3] = {n / 4, n - n / 10, n - 1};
            free(ref);
            for (j = 0; j < 3; j++) {
                double *first = NULL;
                size_t nfirst = 0, w;
                for (w = 0; w < N_MID_WAYS; w++) {
                    pds_sampler *s = sampler_new(r0, seed);
                    char what[160];
                    size_t m;
                    double *xy;
                    snprintf(what, sizeof what, "R %g, seed %llu: %s (k = %zu of %zu), refine "
                             "to %g, run to the end", r0, (unsigned long long)seed,
                             mid_way_name[w], ks[j], n, r1);
                    reach_k(s, (enum mid_way)w, ks[j], what);
                    ck_assert_int_eq(pds_refine(s, r1), 0);
                    run_to_end(s);
                    xy = points_copy(s, &m);
                    if (first == NULL) {
                        first = xy;
                        nfirst = m;
                        xy = NULL;
                    } else {
                        assert_points_equal(xy, m, first, nfirst, what);
                    }
                    free(xy);
                    pds_destroy(s);
                }
                free(first);
            }
        }
    }
}
END_TEST

START_TEST(chunks_of_one_match_one_run)
{
    /* About 10^5 points (3000 light): R = sqrt(0.6966 / N). */
    const double r = test_light() ? 0.0152 : 0.00264;
    pds_sampler *one = sampler_new(r, 5), *chunked = sampler_new(r, 5), *stepped = sampler_new(r, 5);
    size_t calls = 0;
    int rc;

    run_to_end(one);
    while ((rc = pds_run(chunked, 1, NULL)) == PDS_MORE && ++calls < MAX_CALLS)
        continue;
    ck_assert_msg(rc == PDS_DONE, "pds_run(s, 1, NULL) returned %d (%s)", rc,
                  pds_errmsg(chunked));
    calls = 0;
    while ((rc = pds_step(stepped)) == PDS_MORE && ++calls < MAX_CALLS)
        continue;
    ck_assert_msg(rc == PDS_DONE, "pds_step returned %d (%s)", rc, pds_errmsg(stepped));
    assert_same_points(chunked, one, "while (pds_run(s, 1, NULL) == PDS_MORE) vs one pds_run");
    assert_same_points(stepped, one, "while (pds_step(s) == PDS_MORE) vs one pds_run");
    pds_destroy(one);
    pds_destroy(chunked);
    pds_destroy(stepped);
}
END_TEST

Suite *splits_suite(void)
{
    Suite *suite = suite_create("splits");
    TCase *tc;

    tc = new_tcase(suite, "refine_after_the_last_point");
    tcase_add_test(tc, refine_after_the_last_point);
    tc = new_tcase(suite, "refine_in_the_middle");
    tcase_add_test(tc, refine_in_the_middle);
    tc = new_tcase(suite, "chunks_of_one");
    tcase_add_test(tc, chunks_of_one_match_one_run);
    return suite;
}
