/*
 * threads.c - pds_set_threads and pds_threads (1.5): the arguments, and the
 * promise that the points never depend on the thread count.
 *
 * Contract (poissondisk.h): n is 0 (one per online core, at least 1) to 1024;
 * more, or a NULL sampler, is PDS_EINVAL and changes nothing; the default is
 * 1; pds_threads reads the count in force back (0 resolved), 0 for NULL. The
 * first call selects the parallel process, before the first point (after the
 * single-thread process's points: PDS_ESTATE); then it is allowed at any
 * time, between the calls of one run too, but not from inside the progress
 * callback (PDS_ESTATE). The same seed gives the same
 * points, byte for byte, for every thread count and whatever the count was
 * at each call.
 *
 * Determinism is checked in every mode a run can be in: the one-radius
 * rectangle, the torus (square; wider than tall, refined; in count mode),
 * count mode, a chain of refines, a radius map (in the square; in the
 * polygon; on the torus, refined), a polygon with a hole (one radius, refined, in count mode), a
 * mask, and fixed points (in the polygon; in the square in count mode). Each is
 * run once with 1 thread, one pds_run per radius (the reference), then
 *   - with 2, 3, 4, 5 and 8 threads, the same calls;
 *   - split into pds_run calls of 1, 7 and 1000 points in turn, the thread
 *     count changing between the calls (0 among them);
 *   - stopped by the progress callback twice and resumed at another count;
 * and every one must give the reference's bytes and radius. PDS_TEST_LIGHT
 * (make check-valgrind) runs larger radii: the same checks on fewer points.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

#define MAX_THREADS 1024u
#define MAX_STAGES 3

/* One way a pattern is made: its domain and options, and the radii it is run
 * at in turn (refined to after each maximal pattern). */
typedef struct mode {
    const char *name;
    void (*configure)(pds_sampler *s); /* NULL: the unit square as created */
    double radius[2][MAX_STAGES];      /* [native, light]; 0 ends the chain */
    size_t count[2];                   /* pds_set_count, or 0 */
} mode;

static void domain_2x1(pds_sampler *s) { ck_assert_int_eq(pds_set_domain(s, 0, 0, 2, 1), 0); }

static void torus(pds_sampler *s) { ck_assert_int_eq(pds_set_periodic(s, 1), 0); }

static void wide_torus(pds_sampler *s)
{
    ck_assert_int_eq(pds_set_domain(s, -0.4, 0.2, 0.9, 0.9), 0);
    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
}

/* Radii from 0.01 (0.03 light) at the bottom left to three times that. */
static void radius_map(pds_sampler *s)
{
    const double lo = test_light() ? 0.03 : 0.01;
    const double map[6] = {lo, 2 * lo, 3 * lo, 2 * lo, 3 * lo, 2 * lo};
    ck_assert_int_eq(pds_set_radius_map(s, 3, 2, map), 0);
}

/* An L-shaped outline with a square hole, one ring each. */
static void polygon(pds_sampler *s)
{
    static const double xy[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2,
                                0.3, 0.3, 0.7, 0.3, 0.7, 0.7, 0.3, 0.7};
    static const size_t ends[] = {6, 10};
    ck_assert_int_eq(pds_set_polygon(s, xy, ends, 2), 0);
}

/* A 12 x 9 mask: a disk of pixels with a notch and a lone pixel, on the
 * box [0,1.5]x[0,1] (pixels 0.125 x 0.111). */
static void mask(pds_sampler *s)
{
    unsigned char inside[12 * 9];
    size_t i, j;
    for (j = 0; j < 9; j++)
        for (i = 0; i < 12; i++) {
            const double dx = (double)i - 5.5, dy = (double)j - 4.0;
            inside[j * 12 + i] = dx * dx + dy * dy < 20.0 && !(i == 6 && j < 4);
        }
    inside[11] = 1;
    ck_assert_int_eq(pds_set_domain(s, 0, 0, 1.5, 1), 0);
    ck_assert_int_eq(pds_set_mask(s, 12, 9, inside), 0);
}

/* Three fixed points: the radius as clearance, a large one, a small one
 * inside the large one's disk. */
static void fixed_points(pds_sampler *s)
{
    static const double xy[6] = {0.5, 0.2, 0.55, 0.55, 0.6, 0.6};
    static const double c[3] = {0.0, 0.2, 0.01};
    ck_assert_int_eq(pds_set_fixed(s, xy, c, 3), 0);
}

static void polygon_with_radius_map(pds_sampler *s)
{
    polygon(s);
    radius_map(s);
}

static void wide_torus_with_radius_map(pds_sampler *s)
{
    wide_torus(s);
    radius_map(s);
}

static void polygon_with_fixed_points(pds_sampler *s)
{
    polygon(s);
    fixed_points(s);
}

static const mode modes[] = {
    {"rectangle [0,2]x[0,1]", domain_2x1, {{0.01}, {0.02}}, {0, 0}},
    {"torus", torus, {{0.01}, {0.05}}, {0, 0}},
    {"torus 1.3 x 0.7, refine", wide_torus, {{0.03, 0.012}, {0.09, 0.06}}, {0, 0}},
    {"torus, pds_set_count", torus, {{1.0}, {1.0}}, {3000, 1000}},
    {"pds_set_count", NULL, {{1.0}, {1.0}}, {3000, 1000}},
    {"refine", NULL, {{0.03, 0.02, 0.01}, {0.08, 0.06, 0.04}}, {0, 0}},
    {"radius map", radius_map, {{1.0}, {1.0}}, {0, 0}},
    {"radius map in a polygon with a hole", polygon_with_radius_map, {{1.0}, {1.0}}, {0, 0}},
    {"radius map on the torus 1.3 x 0.7, refine", wide_torus_with_radius_map, {{1.0, 0.024}, {1.0, 0.072}}, {0, 0}},
    {"polygon with a hole", polygon, {{0.015}, {0.06}}, {0, 0}},
    {"polygon, refine", polygon, {{0.03, 0.02}, {0.09, 0.07}}, {0, 0}},
    {"polygon, pds_set_count", polygon, {{1.0}, {1.0}}, {3000, 1000}},
    {"mask", mask, {{0.01}, {0.04}}, {0, 0}},
    {"polygon with fixed points", polygon_with_fixed_points, {{0.015}, {0.06}}, {0, 0}},
    {"fixed points, pds_set_count", fixed_points, {{1.0}, {1.0}}, {3000, 1000}},
};
#define N_MODES (sizeof modes / sizeof modes[0])

static double stage_radius(const mode *m, size_t k) { return m->radius[test_light()][k]; }

static pds_sampler *make(const mode *m, uint64_t seed)
{
    pds_sampler *s = sampler_new(stage_radius(m, 0), seed);
    if (m->configure != NULL)
        m->configure(s);
    if (m->count[test_light()] != 0)
        ck_assert_int_eq(pds_set_count(s, m->count[test_light()]), 0);
    return s;
}

/* pds_set_threads that must succeed, read back through pds_threads. */
static void set_threads(pds_sampler *s, unsigned n)
{
    int rc = pds_set_threads(s, n);
    ck_assert_msg(rc == 0, "pds_set_threads(s, %u) returned %d (%s)", n, rc, pds_errmsg(s));
    if (n != 0)
        ck_assert_uint_eq(pds_threads(s), n);
    else
        ck_assert_msg(pds_threads(s) >= 1 && pds_threads(s) <= MAX_THREADS,
                      "pds_set_threads(s, 0) resolved to %u", pds_threads(s));
}

/* How the calls of a run are made. */
enum policy { ONE_RUN, SPLIT, CANCELED };

/* The progress callback of CANCELED: stops the run at reports 3 and 20, and
 * tries to change the thread count from inside (it must be refused). */
typedef struct stopper {
    pds_sampler *s;
    size_t reports, stops;
    int inside_rc;
} stopper;

static int stop_twice(void *user, size_t count, double done)
{
    stopper *st = user;
    (void)count;
    (void)done;
    st->reports++;
    if (st->reports == 3)
        st->inside_rc = pds_set_threads(st->s, 2);
    return st->reports == 3 || st->reports == 20;
}

/* pds_run until PDS_DONE at the current radius, the calls made by policy p. */
static void run_stage(pds_sampler *s, enum policy p, stopper *st, size_t *calls,
                      const char *what)
{
    static const size_t chunk[3] = {1, 7, 1000};
    static const unsigned between[7] = {1, 2, 3, 0, 4, 5, 8};
    int rc;

    do {
        size_t before, added = (size_t)-1;
        size_t max_new = p == SPLIT ? chunk[*calls % 3] : 0;
        if (p == SPLIT)
            set_threads(s, between[*calls % 7]);
        before = pds_count(s);
        rc = pds_run(s, max_new, &added);
        ++*calls;
        ck_assert_msg(added == pds_count(s) - before, "%s: pds_run reported %zu added of %zu",
                      what, added, pds_count(s) - before);
        if (rc == PDS_ECANCELED && p == CANCELED) {
            st->stops++;
            set_threads(s, st->stops == 1 ? 5 : 0);
            rc = PDS_MORE;
            continue;
        }
        ck_assert_msg(rc == PDS_DONE || (rc == PDS_MORE && p == SPLIT),
                      "%s: pds_run(s, %zu) returned %d (%s)", what, max_new, rc, pds_errmsg(s));
    } while (rc != PDS_DONE);
}

/* Makes m's pattern with seed at `threads` threads by policy p: the points,
 * *n of them, and the last radius. */
static double *pattern(const mode *m, uint64_t seed, unsigned threads, enum policy p,
                       size_t *n, double *radius, const char *what)
{
    pds_sampler *s = make(m, seed);
    stopper st = {NULL, 0, 0, 0};
    size_t calls = 0, k;
    double *xy;

    set_threads(s, threads);
    if (p == CANCELED) {
        st.s = s;
        ck_assert_int_eq(pds_set_progress(s, stop_twice, &st), 0);
    }
    for (k = 0; k < MAX_STAGES && stage_radius(m, k) > 0; k++) {
        if (k > 0)
            ck_assert_int_eq(pds_refine(s, stage_radius(m, k)), 0);
        run_stage(s, p, &st, &calls, what);
    }
    if (p == CANCELED) {
        ck_assert_msg(st.stops == 2, "%s: the run was stopped %zu times, not twice", what,
                      st.stops);
        ck_assert_msg(st.inside_rc == PDS_ESTATE, "%s: pds_set_threads from inside the "
                      "progress callback returned %d, not PDS_ESTATE", what, st.inside_rc);
    }
    *radius = pds_radius(s);
    xy = points_copy(s, n);
    pds_destroy(s);
    return xy;
}

static void check_mode(const mode *m, uint64_t seed)
{
    static const unsigned counts[] = {2, 3, 4, 5, 8};
    static const char *const policy_name[] = {"one pds_run", "split calls", "canceled twice"};
    char what[160];
    size_t n_ref, n, i;
    double r_ref, r;
    double *ref;

    snprintf(what, sizeof what, "%s, seed %llu, 1 thread", m->name, (unsigned long long)seed);
    ref = pattern(m, seed, 1, ONE_RUN, &n_ref, &r_ref, what);
    ck_assert_msg(n_ref > (test_light() ? 50u : 1000u), "%s: only %zu points", what, n_ref);
    for (i = 0; i < sizeof counts / sizeof counts[0] + 2; i++) {
        const enum policy p = i < 5 ? ONE_RUN : i == 5 ? SPLIT : CANCELED;
        const unsigned threads = i < 5 ? counts[i] : i == 5 ? 4 : 3;
        double *xy;
        snprintf(what, sizeof what, "%s, seed %llu, %u threads, %s against 1 thread", m->name,
                 (unsigned long long)seed, threads, policy_name[p]);
        xy = pattern(m, seed, threads, p, &n, &r, what);
        assert_points_equal(xy, n, ref, n_ref, what);
        ck_assert_msg(r == r_ref, "%s: radius %.17g, 1 thread gave %.17g", what, r, r_ref);
        free(xy);
    }
    free(ref);
}

START_TEST(points_never_depend_on_threads)
{
    /* One seed each light, two otherwise. */
    uint64_t seed;
    for (seed = 1; seed <= pick(2, 1); seed++)
        check_mode(&modes[_i], seed);
}
END_TEST

START_TEST(arguments)
{
    pds_sampler *s = sampler_new(0.1, 1);
    unsigned cores;

    ck_assert_uint_eq(pds_threads(s), 1); /* the default: no thread started */
    ck_assert_int_eq(pds_set_threads(NULL, 2), PDS_EINVAL);
    ck_assert_uint_eq(pds_threads(NULL), 0);
    set_threads(s, 1);
    set_threads(s, MAX_THREADS);
    set_threads(s, 0);
    cores = pds_threads(s);
    set_threads(s, 3);
    assert_failed(s, pds_set_threads(s, MAX_THREADS + 1), PDS_EINVAL, "1025 threads");
    ck_assert_msg(strstr(pds_errmsg(s), "pds_set_threads") != NULL
                  && strstr(pds_errmsg(s), "1024") != NULL,
                  "the message names the call and the limit: '%s'", pds_errmsg(s));
    ck_assert_uint_eq(pds_threads(s), 3); /* unchanged */
    assert_failed(s, pds_set_threads(s, (unsigned)-1), PDS_EINVAL, "a wrapped -1");
    ck_assert_uint_eq(pds_threads(s), 3);
    /* 0 resolves the same way each time. */
    set_threads(s, 0);
    ck_assert_uint_eq(pds_threads(s), cores);
    pds_destroy(s);
}
END_TEST

/* Once selected, allowed at any time: after points exist, and once the
 * pattern is maximal. */
START_TEST(allowed_at_any_time)
{
    pds_sampler *s = sampler_new(0.05, 2);

    set_threads(s, 1);
    ck_assert_int_eq(pds_run(s, 10, NULL), PDS_MORE);
    set_threads(s, 2);
    ck_assert_int_eq(pds_step(s), PDS_MORE);
    set_threads(s, 7);
    run_to_end(s);
    set_threads(s, 1);
    ck_assert_int_eq(pds_refine(s, 0.04), 0);
    set_threads(s, 4);
    run_to_end(s);
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    pds_destroy(s);
}
END_TEST

/* The first call selects the parallel process: not after points of the
 * single-thread one (PDS_ESTATE, nothing changed, the run goes on). */
START_TEST(selects_the_process_before_the_first_point)
{
    pds_sampler *s = sampler_new(0.05, 2), *t = sampler_new(0.05, 2);
    double a[2], b[2];

    ck_assert_int_eq(pds_run(s, 10, NULL), PDS_MORE);
    assert_failed(s, pds_set_threads(s, 2), PDS_ESTATE, "after single-thread points");
    ck_assert_msg(strstr(pds_errmsg(s), "before the first point") != NULL, "message: %s", pds_errmsg(s));
    ck_assert_uint_eq(pds_threads(s), 1);
    run_to_end(s);
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    /* The selection happens: the first point differs from the default's. */
    set_threads(t, 1);
    ck_assert_int_eq(pds_step(t), PDS_MORE);
    ck_assert_uint_eq(pds_points(s, 0, 1, a), 1);
    ck_assert_uint_eq(pds_points(t, 0, 1, b), 1);
    ck_assert(a[0] != b[0] || a[1] != b[1]);
    pds_destroy(s);
    pds_destroy(t);
}
END_TEST

Suite *threads_suite(void)
{
    Suite *suite = suite_create("threads");
    TCase *tc = new_tcase(suite, "arguments");
    tcase_add_test(tc, arguments);
    tcase_add_test(tc, allowed_at_any_time);
    tcase_add_test(tc, selects_the_process_before_the_first_point);
    tc = new_tcase(suite, "determinism");
    tcase_add_loop_test(tc, points_never_depend_on_threads, 0, (int)N_MODES);
    return suite;
}
