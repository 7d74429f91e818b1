/*
 * threads.c - distinct handles on distinct threads at once give exactly the
 * bytes each gives alone.
 *
 * Contract (include/poissondisk.h, DESIGN.md): the library keeps no global
 * state; distinct handles may be used from distinct threads at once. Each of
 * N_THREADS threads runs its own script on its own handle: create, set_domain
 * (then, for two of them, a polygon with a hole, one of these with a radius
 * map; for one, the torus, with a radius map; for one, fixed points),
 * a bounded run, free_area in the middle of the run, run to the end, refine,
 * run to the end, count/radius/points, verify, free_area, a refused call and
 * its message, destroy. In between it calls the global functions (pds_strerror,
 * pds_version_string, pds_version_number, pds_errmsg(NULL)). Every result is
 * appended to a transcript, and each thread's transcript must equal, byte for
 * byte, the one the same script gave when run alone on the main thread first.
 * Alone a script runs on one thread; at once, each handle may also start
 * threads of its own (pds_set_threads, 1.5: 1, 2, 3, or one per core, the
 * count changed after the first run), which must not change a byte either.
 *
 * `make check-threads` runs it built normally; `make check-tsan` (part of
 * `make check-sanitizers`) runs it built with -fsanitize=thread, so that a data
 * race between the threads is reported even when it changes no byte.
 * Plain C99 + POSIX threads; sees only the public header (no Check: its
 * assertions are not for use off the main thread).
 * Exit status: 0 all transcripts match, 1 a mismatch, 2 setup failure.
 */
#define _POSIX_C_SOURCE 200809L /* pthreads and barriers under -std=c99 */

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "poissondisk.h"

#define N_THREADS 4
#define ROUNDS 3 /* each thread repeats its script, so the scripts overlap in many ways */

/* One thread's work: a handle with its own seed, domain and radii. */
struct script {
    uint64_t seed;
    double r0, r1;          /* radius at creation, then refined to r1 */
    double x0, y0, x1, y1;  /* the domain */
    size_t first_chunk;     /* max_new of the first, bounded run */
    unsigned threads[2];    /* run at once: its own threads, then after the first run */
    int polygon;            /* an octagon with a square hole inside the domain */
    int periodic;           /* the domain made a torus */
    int fixed;              /* three fixed points, one a large obstacle */
    int field;              /* a 2 x 1 radius map, r0 to 2 r0 */
};

static const struct script scripts[N_THREADS] = {
    {1, 0.020, 0.012, 0.0, 0.0, 1.0, 1.0, 100, {1, 2}, 0, 0, 1, 0},
    {0x9E3779B97F4A7C15u, 0.030, 0.020, -3.0, 10.0, 1.0, 11.0, 1, {2, 1}, 1, 0, 0, 0},
    {42, 0.004, 0.0035, 0.0, 0.0, 2.0, 0.5, 2000, {3, 0}, 1, 0, 0, 1}, /* several blocks of free cells */
    {UINT64_MAX, 0.020, 0.011, 1000.0, -3.0, 1001.0, -2.0, 500, {0, 4}, 0, 1, 0, 1}, /* its darts across the seams */
};

/* A growable byte buffer: everything the calls of one script returned. */
struct transcript {
    unsigned char *buf;
    size_t len, cap;
    int oom;
};

static void put_bytes(struct transcript *t, const void *p, size_t n)
{
    if (t->oom)
        return;
    if (t->len + n > t->cap) {
        size_t cap = t->cap ? t->cap : 4096;
        unsigned char *grown;
        while (cap < t->len + n)
            cap *= 2;
        grown = realloc(t->buf, cap);
        if (grown == NULL) {
            t->oom = 1;
            return;
        }
        t->buf = grown;
        t->cap = cap;
    }
    memcpy(t->buf + t->len, p, n);
    t->len += n;
}

static void put_int(struct transcript *t, int v) { put_bytes(t, &v, sizeof v); }
static void put_size(struct transcript *t, size_t v) { put_bytes(t, &v, sizeof v); }
static void put_double(struct transcript *t, double v) { put_bytes(t, &v, sizeof v); }
static void put_str(struct transcript *t, const char *s)
{
    put_bytes(t, s ? s : "(null)", strlen(s ? s : "(null)") + 1);
}

/* The global functions, called from every thread while the others sample. */
static void put_globals(struct transcript *t)
{
    unsigned version = pds_version_number();
    int code;
    for (code = -7; code <= 2; code++) /* every code, and unknown ones */
        put_str(t, pds_strerror(code));
    put_str(t, pds_version_string());
    put_bytes(t, &version, sizeof version);
    put_str(t, pds_errmsg(NULL));
}

/* The results the main thread checks on the sequential run, so that equal
 * transcripts cannot come from a script that failed early everywhere. */
struct summary {
    int create, set_domain, last_run, verify, refused;
    size_t count;
    double free_area;
};

/* An octagon with a square hole, centred in sc's domain: outline cells cut
 * at every angle, for the workers' own outline cutters. */
static int set_octagon(pds_sampler *s, const struct script *sc)
{
    static const double unit[16] = {1, 0.4, 0.4, 1, -0.4, 1, -1, 0.4, -1, -0.4, -0.4, -1, 0.4, -1, 1, -0.4};
    static const double hole[8] = {-0.2, -0.2, -0.2, 0.2, 0.2, 0.2, 0.2, -0.2};
    const double cx = (sc->x0 + sc->x1) / 2, cy = (sc->y0 + sc->y1) / 2;
    const double hx = 0.48 * (sc->x1 - sc->x0), hy = 0.48 * (sc->y1 - sc->y0);
    const size_t ends[2] = {8, 12};
    double xy[24];
    int k;
    for (k = 0; k < 8; k++) {
        xy[2 * k] = cx + hx * unit[2 * k];
        xy[2 * k + 1] = cy + hy * unit[2 * k + 1];
    }
    for (k = 0; k < 4; k++) {
        xy[16 + 2 * k] = cx + hx * hole[2 * k];
        xy[16 + 2 * k + 1] = cy + hy * hole[2 * k + 1];
    }
    return pds_set_polygon(s, xy, ends, 2);
}

/* alone: on one thread throughout, the reference; else sc->threads. */
static void run_script(const struct script *sc, int alone, struct transcript *t,
                       struct summary *sum)
{
    pds_sampler *s = NULL;
    size_t added = 0, n;
    double *xy;
    int rc;

    memset(sum, 0, sizeof *sum);
    sum->create = rc = pds_create(&s, sc->r0, sc->seed);
    put_int(t, rc);
    if (rc != 0)
        return;
    put_globals(t);
    sum->set_domain = rc = pds_set_domain(s, sc->x0, sc->y0, sc->x1, sc->y1);
    put_int(t, rc);
    if (sc->polygon && rc == 0) {
        sum->set_domain = rc = set_octagon(s, sc);
        put_int(t, rc);
    }
    if (sc->periodic && rc == 0) {
        sum->set_domain = rc = pds_set_periodic(s, 1);
        put_int(t, rc);
    }
    if (sc->fixed && rc == 0) {
        static const double at[6] = {0.5, 0.5, 0.2, 0.8, 0.9, 0.1};
        static const double c[3] = {0.25, 0.0, 0.05};
        sum->set_domain = rc = pds_set_fixed(s, at, c, 3);
        put_int(t, rc);
    }
    if (sc->field && rc == 0) {
        const double map[2] = {sc->r0, 2 * sc->r0};
        sum->set_domain = rc = pds_set_radius_map(s, 2, 1, map);
        put_int(t, rc);
    }
    put_int(t, pds_set_threads(s, alone ? 1 : sc->threads[0]));
    rc = pds_run(s, sc->first_chunk, &added);
    put_int(t, rc);
    put_size(t, added);
    put_double(t, pds_free_area(s)); /* mid-run: measures the open cells */
    put_globals(t);
    put_int(t, pds_set_threads(s, alone ? 1 : sc->threads[1]));
    rc = pds_run(s, 0, &added);
    put_int(t, rc);
    put_size(t, added);
    put_int(t, pds_refine(s, sc->r1));
    put_globals(t);
    sum->last_run = rc = pds_run(s, 0, &added);
    put_int(t, rc);
    put_size(t, added);

    sum->count = n = pds_count(s);
    put_size(t, n);
    put_double(t, pds_radius(s));
    xy = malloc((2 * n + 2) * sizeof *xy);
    if (xy == NULL) {
        t->oom = 1;
    } else {
        put_size(t, pds_points(s, 0, n, xy));
        put_bytes(t, xy, 2 * n * sizeof *xy);
        free(xy);
    }
    sum->verify = rc = pds_verify(s);
    put_int(t, rc);
    put_str(t, pds_errmsg(s));
    sum->free_area = pds_free_area(s);
    put_double(t, sum->free_area);
    /* A refused call: its message lives in this handle, not in shared storage. */
    sum->refused = rc = pds_set_domain(s, 0.0, 0.0, 1.0, 1.0);
    put_int(t, rc);
    put_str(t, pds_errmsg(s));
    put_globals(t);
    pds_destroy(s);
}

struct worker {
    int index;
    const struct transcript *expected;
    pthread_barrier_t *start;
    int mismatches, oom;
    int bad_round;     /* the first round that differed */
    size_t bad_offset; /* where its transcript first differed */
    size_t bad_len;    /* its length */
};

static size_t first_difference(const struct transcript *a, const struct transcript *b)
{
    size_t i, n = a->len < b->len ? a->len : b->len;
    for (i = 0; i < n && a->buf[i] == b->buf[i]; i++)
        ;
    return i;
}

static void *worker_main(void *arg)
{
    struct worker *w = arg;
    int round;

    pthread_barrier_wait(w->start); /* all threads begin together */
    for (round = 0; round < ROUNDS; round++) {
        struct transcript t = {NULL, 0, 0, 0};
        struct summary sum;
        run_script(&scripts[w->index], 0, &t, &sum);
        if (t.oom) {
            w->oom = 1;
        } else if (t.len != w->expected->len ||
                   memcmp(t.buf, w->expected->buf, t.len) != 0) {
            if (w->mismatches++ == 0) {
                w->bad_round = round;
                w->bad_offset = first_difference(&t, w->expected);
                w->bad_len = t.len;
            }
        }
        free(t.buf);
    }
    return NULL;
}

/* The sequential run must be a real one: every call did what it should. */
static int summary_ok(int i, const struct summary *sum)
{
    if (sum->create == 0 && sum->set_domain == 0 && sum->last_run == 0 &&
        sum->verify == 0 && sum->refused == PDS_ESTATE && sum->count > 0 &&
        sum->free_area == 0.0)
        return 1;
    fprintf(stderr,
            "threads: script %d alone: create %d, set_domain %d, last run %d, verify %d, "
            "late set_domain %d, %zu points, free area %g\n",
            i, sum->create, sum->set_domain, sum->last_run, sum->verify, sum->refused,
            sum->count, sum->free_area);
    return 0;
}

int main(void)
{
    struct transcript expected[N_THREADS];
    struct worker workers[N_THREADS];
    pthread_t tid[N_THREADS];
    pthread_barrier_t start;
    int i, failed = 0, setup_failed = 0;

    for (i = 0; i < N_THREADS; i++) {
        struct summary sum;
        expected[i] = (struct transcript){NULL, 0, 0, 0};
        run_script(&scripts[i], 1, &expected[i], &sum);
        if (expected[i].oom || !summary_ok(i, &sum))
            setup_failed = 1;
    }
    if (setup_failed || pthread_barrier_init(&start, NULL, N_THREADS) != 0) {
        fprintf(stderr, "threads: setup failed\n");
        return 2;
    }
    for (i = 0; i < N_THREADS; i++) {
        workers[i] = (struct worker){i, &expected[i], &start, 0, 0, -1, 0, 0};
        if (pthread_create(&tid[i], NULL, worker_main, &workers[i]) != 0) {
            fprintf(stderr, "threads: pthread_create failed\n");
            return 2; /* the others wait at the barrier forever: exit now */
        }
    }
    for (i = 0; i < N_THREADS; i++)
        pthread_join(tid[i], NULL);
    pthread_barrier_destroy(&start);

    for (i = 0; i < N_THREADS; i++) {
        const struct worker *w = &workers[i];
        if (w->oom) {
            fprintf(stderr, "threads: thread %d: out of memory\n", i);
            setup_failed = 1;
        }
        if (w->mismatches > 0) {
            failed++;
            fprintf(stderr,
                    "FAIL: thread %d: %d of %d rounds differ from the sequential run "
                    "(round %d: first at byte %zu; %zu bytes vs %zu)\n",
                    i, w->mismatches, ROUNDS, w->bad_round, w->bad_offset, w->bad_len,
                    expected[i].len);
        }
        free(expected[i].buf);
    }
    printf("threads: %d threads x %d rounds, %d passed, %d failed\n", N_THREADS, ROUNDS,
           N_THREADS - failed, failed);
    return setup_failed ? 2 : failed ? 1 : 0;
}
