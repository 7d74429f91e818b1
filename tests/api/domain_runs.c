/*
 * domain_runs.c - how runs behave in the unit L; see domain_runs.h.
 *
 * Contract (poissondisk.h, 1.4): in a polygon, with or without fixed points,
 * the same seed gives the same points however pds_run and pds_step split the
 * work, and when a progress callback cancels every run; pds_set_count gives
 * exactly n points, every pair at least the last radius apart, the
 * clearances scaled as the radius was; pds_refine keeps every point and the
 * run ends maximal at the new radius, the clearances scaled with it.
 */
#include "domain_runs.h"

#include <stdio.h>
#include <stdlib.h>

#include "domain_check.h"
#include "helpers.h"

pds_sampler *extra_new(const domain_extra *e, double r, uint64_t seed)
{
    pds_sampler *s = sampler_new(r, seed);

    ck_assert_int_eq(pds_set_polygon(s, UNIT_L.xy, UNIT_L.ends, UNIT_L.nrings), 0);
    if (e->setup)
        e->setup(s);
    return s;
}

static size_t fixed_at(const domain_extra *e, double r0, double r, disk out[8])
{
    return e->fixed ? e->fixed(r0, r, out) : 0;
}

/* pds_run(s, k) until done (k 0: pds_step until 0). */
static void run_split(pds_sampler *s, size_t k)
{
    size_t calls = 0;
    int rc;

    do
        rc = k ? pds_run(s, k, NULL) : pds_step(s);
    while (rc == PDS_MORE && ++calls < 1000000);
    ck_assert_msg(rc == PDS_DONE, "split %zu ended with %d (%s)", k, rc, pds_errmsg(s));
}

void check_splits(const domain_extra *e)
{
    const size_t splits[5] = {1, 7, 33, 250, 0};
    pds_sampler *ref = extra_new(e, 0.03, 6);
    size_t w, n, m;
    double *want;

    run_to_end(ref);
    want = points_copy(ref, &n);
    for (w = 0; w < 5; w++) {
        pds_sampler *s = extra_new(e, 0.03, 6);
        double *got;
        char what[96];
        snprintf(what, sizeof what, "%s, split %zu", e->name, splits[w]);
        run_split(s, splits[w]);
        got = points_copy(s, &m);
        assert_points_equal(got, m, want, n, what);
        free(got);
        pds_destroy(s);
    }
    free(want);
    pds_destroy(ref);
}

/* Asks to stop at every call. */
static int stop_always(void *user, size_t count, double done)
{
    (void)count;
    (void)done;
    ++*(size_t *)user;
    return 1;
}

void check_cancel(const domain_extra *e)
{
    pds_sampler *ref = extra_new(e, 0.02, 7), *s = extra_new(e, 0.02, 7);
    size_t calls = 0, runs = 0;
    int rc;

    run_to_end(ref);
    ck_assert_int_eq(pds_set_progress(s, stop_always, &calls), 0);
    do
        rc = pds_run(s, 0, NULL);
    while (rc == PDS_ECANCELED && ++runs < 100000);
    ck_assert_msg(rc == PDS_DONE, "%s: canceled runs ended with %d (%s)", e->name, rc,
                  pds_errmsg(s));
    ck_assert_msg(runs > 1 && calls > 1, "%s: %zu runs, %zu calls: nothing was canceled",
                  e->name, runs, calls);
    assert_same_points(s, ref, "canceled at every progress call");
    pds_destroy(ref);
    pds_destroy(s);
}

void check_count(const domain_extra *e)
{
    const size_t want = pick(400, 120);
    uint64_t seed;

    for (seed = 1; seed <= pick(3, 1); seed++) {
        pds_sampler *s = extra_new(e, 1.0, seed);
        double *xy, *r;
        size_t n, i, nf;
        disk fx[8];
        double r0;
        int rc;
        ck_assert_int_eq(pds_set_count(s, want), 0);
        /* The radius count mode starts at: set when the first point is
         * placed (with fixed points, from the room their clearances leave). */
        ck_assert_int_eq(pds_step(s), PDS_MORE);
        r0 = pds_radius(s);
        rc = pds_run(s, 0, NULL);
        ck_assert_msg(rc == PDS_DONE, "%s, count mode: pds_run %d (%s)", e->name, rc,
                      pds_errmsg(s));
        ck_assert_uint_eq(pds_count(s), want);
        domain_pattern(s, &xy, &r, &n);
        /* Every pair at least the last radius apart. */
        for (i = 0; i < n; i++)
            r[i] = pds_radius(s);
        nf = fixed_at(e, r0, pds_radius(s), fx);
        assert_domain_rules(xy, r, n, &UNIT_L, fx, nf, e->name);
        rc = pds_verify(s);
        ck_assert_msg(rc == PDS_DONE || rc == PDS_MORE, "%s, count mode: pds_verify %d (%s)",
                      e->name, rc, pds_errmsg(s));
        free(xy);
        free(r);
        pds_destroy(s);
    }
}

void check_refine(const domain_extra *e)
{
    const double r0 = 0.06, r1 = 0.03;
    pds_sampler *s = extra_new(e, r0, 8);
    double *first;
    size_t n, nf;
    disk fx[8];

    run_to_end(s);
    nf = fixed_at(e, r0, r0, fx);
    assert_domain_pattern(s, &UNIT_L, fx, nf, "before the refine");
    first = points_copy(s, &n);
    ck_assert_int_eq(pds_refine(s, r1), 0);
    ck_assert_int_eq(pds_verify(s), PDS_MORE);
    run_to_end(s);
    assert_prefix_kept(s, first, n, "refine in the L");
    nf = fixed_at(e, r0, r1, fx);
    assert_domain_pattern(s, &UNIT_L, fx, nf, "after the refine");
    free(first);
    pds_destroy(s);
}
