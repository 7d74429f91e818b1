/*
 * alloc_fail.c - every allocation the library makes may fail (make check-alloc).
 *
 * Contract (spec 1.1.1, "Out of memory"): a call that runs out of memory
 * returns PDS_ENOMEM (pds_free_area: NaN; pds_create: *out NULL), never
 * aborts, leaves the handle usable, and once allocation works again,
 * continuing gives the points an undisturbed sequence gives; pds_destroy
 * frees everything. pds_run may have added points before the failure (the
 * exact-arithmetic fallback): *added counts them and they are the undisturbed
 * run's first ones.
 *
 * How: interpose.c replaces the allocator and counts the allocations made
 * inside pds_* calls ("armed"). A fixed sequence of calls is run undisturbed
 * (K armed allocations, the reference), then once more as the driver: before
 * each call it forks one child per allocation k of that call, in which the
 * k-th allocation fails (once) and the rest of the sequence runs with every
 * check; an abort or a hang in a child is reported, not fatal. A call that
 * fails is retried at once (pds_run with the rest of its budget).
 *
 * "alloc_fail small" tries every k of a ~300-point sequence. "polygon", "mask"
 * and "field" run the small sequence in a domain users have (1.4): a star
 * with a hole (50 vertices), an 8 x 8 mask, and that star with a radius
 * function; setting the domain (and the field) is one more call whose
 * allocations fail in turn. "threads" runs the parallel process on 2 threads
 * in the rectangle, "polygon-threads" in the star, "torus-threads" on the
 * torus, "fixed-threads" in the star with fixed points, "fixed-large" the
 * same with points enough for the weighted mesh built whole;
 * "fixed-one-thread" and "fixed-large-one-thread" the same two without
 * threads (the single-thread dart stage holds the fixed points);
 * "field-threads" the star with the radius function on 2 threads (the
 * field's darts go on in the free regions, each asked for its radius), and
 * "field-torus-threads" the radius function on the torus on 2 threads. The default,
 * ~7000-point sequence tries every k in calls that make at most 3 * SPAN
 * allocations; in larger ones (pds_verify's exact arithmetic makes tens of
 * thousands) the first SPAN, the last SPAN and SPAN spread evenly in
 * between, so the run stays short. PDS_ALLOC_ALL=1 tries every k (~30 min).
 *
 * Plain C against the public header only; not run under Valgrind (it
 * replaces the allocator). Ends with "alloc-fail: N passed, M failed".
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "interpose.h"
#include "poissondisk.h"

#define SEED 3
#define SPAN 100

/* Two sequences of the same shape. "small" (about 300 points, still with a
 * dart stage and a hand-over) is short enough to try every allocation; the
 * default one (R = 0.01: runs of 2000 and 500 points around a refine) samples
 * its largest calls (pds_verify) unless PDS_ALLOC_ALL is set. */
struct config {
    const char *name;
    double radius, refined;
    size_t first_run, second_run;
    int every_k;
    int periodic; /* the torus: copies allocate as points are added */
    int shape;    /* the domain: the rectangle, a polygon, a mask, a polygon with a field */
};
enum {
    RECTANGLE, POLYGON, MASK, POLYGON_FIELD, THREADS, POLYGON_THREADS, FIXED_THREADS, FIXED, FIELD_THREADS,
    TORUS_FIELD_THREADS
};
static const struct config kSmall = {"small", 0.05, 0.035, 100, 50, 1, 0, RECTANGLE};
static const struct config kLarge = {"large", 0.01, 0.007, 2000, 500, 0, 0, RECTANGLE};
static const struct config kTorus = {"torus", 0.05, 0.035, 100, 50, 1, 1, RECTANGLE};
/* pds_verify's exact arithmetic along an outline makes thousands of
 * allocations: those calls are sampled (SPAN), the others tried in full. */
static const struct config kPolygon = {"polygon", 0.05, 0.035, 100, 50, 0, 0, POLYGON};
static const struct config kMask = {"mask", 0.05, 0.035, 100, 50, 0, 0, MASK};
/* The field's rmax is 0.06: a refine to 0.045 scales every radius by 3/4. */
static const struct config kField = {"field", 0.06, 0.045, 100, 50, 0, 0, POLYGON_FIELD};
/* The parallel opening on 2 threads: rows enough for two bands of darts,
 * allocations made on the worker threads too (a failure there is rethrown
 * in the call; a thread that cannot start is done without). */
static const struct config kThreads = {"threads", 0.025, 0.02, 300, 100, 0, 0, THREADS};
/* The same in the star with a hole: its sub-squares rastered, the free
 * regions' darts drawn by each worker's own outline cutter. */
static const struct config kPolygonThreads = {"polygon-threads", 0.025, 0.02, 300, 100, 0, 0, POLYGON_THREADS};
/* The same on the torus: the grid's copies in its padding, the free
 * regions' darts decided across the seams, the mesh built whole. */
static const struct config kTorusThreads = {"torus-threads", 0.025, 0.02, 300, 100, 0, 1, THREADS};
/* The same in the star with fixed points: the opening's clearance disks,
 * the free regions' darts in the power cells. */
static const struct config kFixedThreads = {"fixed-threads", 0.025, 0.02, 300, 100, 0, 0, FIXED_THREADS};
/* The same with points enough (over 4096 at the hand-over and at the
 * refine) for the weighted mesh to be built whole, then the fixed points
 * inserted: its largest calls sampled. */
static const struct config kFixedLarge = {"fixed-large", 0.0055, 0.0045, 3000, 500, 0, 0, FIXED_THREADS};
/* The star with fixed points without threads: the single-thread dart
 * stage's clearance disks, every allocation tried; then with points enough
 * for the whole build at the hand-over and at the refine, sampled. */
static const struct config kFixedOne = {"fixed-one-thread", 0.025, 0.02, 300, 100, 1, 0, FIXED};
static const struct config kFixedLargeOne = {"fixed-large-one-thread", 0.0055, 0.0045, 3000, 500, 0, 0, FIXED};
/* The star with the field on 2 threads, every allocation tried. */
static const struct config kFieldThreads = {"field-threads", 0.06, 0.045, 100, 50, 1, 0, FIELD_THREADS};
/* The field on the torus on 2 threads: the layers' darts tested at their
 * copies, the hand-over's points inserted with their radii and copies, the
 * free regions' darts decided across the seams; every allocation tried. */
static const struct config kFieldTorusThreads = {"field-torus-threads", 0.06, 0.045, 100, 50, 1, 1,
                                                 TORUS_FIELD_THREADS};
static const struct config *cfg = &kLarge;
#define RADIUS (cfg->radius)
#define REFINED (cfg->refined)

/* The sequence: a run that stops in the middle (at 2000 of about 7000
 * points, still in the dart stage), the queries that triangulate it, a run
 * to the end, a refine, a bounded and an unbounded run, the queries again. */
enum call {
    CREATE, SHAPE, RUN_2000, FREE_AREA_1, VERIFY_1, RUN_END_1, REFINE, RUN_500, RUN_END_2,
    POINTS, VERIFY_2, FREE_AREA_2, DESTROY, N_CALLS
};

/* What the undisturbed sequence gave, per call. */
struct reference {
    int rc[N_CALLS];
    double value[N_CALLS];  /* pds_free_area, the radius after pds_refine */
    size_t count[N_CALLS];  /* pds_count after the call */
    long allocs[N_CALLS];   /* armed allocations up to the end of the call */
    const char *name[N_CALLS];
    double *xy;             /* the final points */
    size_t n;
};

struct trial {
    const struct reference *ref; /* NULL: the first undisturbed run, which records */
    struct reference *record;
    int call;   /* index of the current call in the sequence */
    int errors; /* failed checks */
    int enomem; /* calls that reported running out of memory */
};

#ifdef __GNUC__
__attribute__((format(printf, 3, 4)))
#endif
static void error_at(struct trial *t, const char *what, const char *fmt, ...)
{
    va_list args;
    if (t->errors++ >= 5)
        return;
    printf("  call %d, %s: ", t->call, what);
    va_start(args, fmt);
    vprintf(fmt, args);
    va_end(args);
    printf("\n");
}

/* After a call reported running out of memory: the failure must be the
 * injected one, during this call; the message names the function. */
static void check_injected(struct trial *t, long injected_before, pds_sampler *s,
                           const char *what)
{
    t->enomem++;
    if (alloc_failures() == injected_before)
        error_at(t, what, "out of memory, though no allocation failed");
    if (s != NULL && strncmp(pds_errmsg(s), what, strlen(what)) != 0)
        error_at(t, what, "the message \"%s\" does not name %s", pds_errmsg(s), what);
}

/* The sampler's points are the first pds_count(s) of the reference's. */
static void check_prefix(struct trial *t, pds_sampler *s, const char *what)
{
    size_t n = pds_count(s), i;
    double *xy;
    if (t->ref == NULL)
        return;
    if (n > t->ref->n) {
        error_at(t, what, "%zu points, more than the undisturbed %zu", n, t->ref->n);
        return;
    }
    xy = malloc((2 * n + 2) * sizeof *xy);
    if (xy == NULL || pds_points(s, 0, n, xy) != n) {
        error_at(t, what, "cannot copy the points");
    } else {
        for (i = 0; i < n; i++)
            if (memcmp(xy + 2 * i, t->ref->xy + 2 * i, 2 * sizeof *xy) != 0)
                break;
        if (i < n)
            error_at(t, what, "point %zu of %zu is not the undisturbed run's", i, n);
    }
    free(xy);
}

/* Records (undisturbed) or compares (trial) a call's outcome. */
static void outcome(struct trial *t, pds_sampler *s, int rc, double value, const char *what)
{
    if (t->ref == NULL) {
        t->record->rc[t->call] = rc;
        t->record->value[t->call] = value;
        t->record->count[t->call] = pds_count(s);
        t->record->allocs[t->call] = alloc_armed_count();
        t->record->name[t->call] = what;
    } else {
        if (rc != t->ref->rc[t->call])
            error_at(t, what, "returned %d, undisturbed %d", rc, t->ref->rc[t->call]);
        if (memcmp(&value, &t->ref->value[t->call], sizeof value) != 0)
            error_at(t, what, "gave %.17g, undisturbed %.17g", value, t->ref->value[t->call]);
        if (pds_count(s) != t->ref->count[t->call])
            error_at(t, what, "count %zu, undisturbed %zu", pds_count(s), t->ref->count[t->call]);
    }
    t->call++;
}

static pds_sampler *do_create(struct trial *t)
{
    pds_sampler *s = (pds_sampler *)&s; /* not NULL: a failure must reset it */
    long injected = alloc_failures();
    int rc;
    alloc_arm();
    rc = pds_create(&s, RADIUS, SEED);
    alloc_disarm();
    if (rc == PDS_ENOMEM) {
        check_injected(t, injected, NULL, "pds_create");
        if (s != NULL)
            error_at(t, "pds_create", "PDS_ENOMEM but *out is not NULL");
        alloc_arm();
        rc = pds_create(&s, RADIUS, SEED);
        alloc_disarm();
    }
    if (rc != 0 || s == NULL) {
        error_at(t, "pds_create", "returned %d", rc);
        return NULL;
    }
    if (cfg->periodic && pds_set_periodic(s, 1) != 0) {
        error_at(t, "pds_set_periodic", "failed: %s", pds_errmsg(s));
        return NULL;
    }
    outcome(t, s, rc, 0.0, "pds_create");
    return s;
}

static void do_run(struct trial *t, pds_sampler *s, size_t max_new)
{
    size_t before = pds_count(s), added = 777, more = 0;
    long injected = alloc_failures();
    int rc;
    alloc_arm();
    rc = pds_run(s, max_new, &added);
    alloc_disarm();
    if (rc == PDS_ENOMEM) {
        check_injected(t, injected, s, "pds_run");
        if (pds_count(s) != before + added || (max_new != 0 && added > max_new))
            error_at(t, "pds_run", "PDS_ENOMEM with %zu reported added, but the count went "
                     "from %zu to %zu", added, before, pds_count(s));
        check_prefix(t, s, "pds_run after PDS_ENOMEM");
        /* Allowed only for the rare exact-arithmetic fallback: shown, not judged. */
        if (added > 0)
            printf("  note: allocation %ld failing: pds_run returned PDS_ENOMEM after adding "
                   "%zu points\n", alloc_fail_planned(), added);
        /* Again with the rest of the budget. When a bounded run had added all
         * its points and failed only on the "room left?" decision, nothing is
         * left to do, and its answer is unknown: take the undisturbed one. */
        if (max_new == 0 || added < max_new) {
            alloc_arm();
            rc = pds_run(s, max_new == 0 ? 0 : max_new - added, &more);
            alloc_disarm();
        } else if (t->ref != NULL) {
            rc = t->ref->rc[t->call];
        }
    }
    if (rc < 0)
        error_at(t, "pds_run", "returned %d (%s)", rc, pds_errmsg(s));
    outcome(t, s, rc, 0.0, max_new == 0 ? "pds_run(s, 0)" : "pds_run(s, max_new)");
}

static void do_free_area(struct trial *t, pds_sampler *s)
{
    long injected = alloc_failures();
    double area;
    alloc_arm();
    area = pds_free_area(s);
    alloc_disarm();
    if (isnan(area)) {
        check_injected(t, injected, NULL, "pds_free_area");
        alloc_arm();
        area = pds_free_area(s);
        alloc_disarm();
    }
    outcome(t, s, 0, area, "pds_free_area");
}

static void do_verify(struct trial *t, pds_sampler *s)
{
    size_t before = pds_count(s);
    long injected = alloc_failures();
    int rc;
    alloc_arm();
    rc = pds_verify(s);
    alloc_disarm();
    if (rc == PDS_ENOMEM) {
        check_injected(t, injected, s, "pds_verify");
        if (pds_count(s) != before)
            error_at(t, "pds_verify", "count changed from %zu to %zu", before, pds_count(s));
        alloc_arm();
        rc = pds_verify(s);
        alloc_disarm();
    }
    outcome(t, s, rc, 0.0, "pds_verify");
}

static void do_refine(struct trial *t, pds_sampler *s, double r)
{
    size_t before = pds_count(s);
    double radius = pds_radius(s);
    long injected = alloc_failures();
    int rc;
    alloc_arm();
    rc = pds_refine(s, r);
    alloc_disarm();
    if (rc == PDS_ENOMEM) {
        check_injected(t, injected, s, "pds_refine");
        if (pds_count(s) != before || pds_radius(s) != radius)
            error_at(t, "pds_refine", "PDS_ENOMEM, yet the count went from %zu to %zu, the "
                     "radius from %g to %g", before, pds_count(s), radius, pds_radius(s));
        check_prefix(t, s, "pds_refine after PDS_ENOMEM");
        alloc_arm();
        rc = pds_refine(s, r);
        alloc_disarm();
    }
    outcome(t, s, rc, pds_radius(s), "pds_refine");
}

/* The radius field of "field": 0.04 at the left of the unit square, 0.06 at the right. */
static double field_fn(void *user, double x, double y)
{
    (void)user;
    (void)y;
    return 0.04 + 0.02 * (x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x);
}

/* A star of 40 vertices (radii 0.45 and 0.3 about the centre, alternating)
 * with a 10-vertex hole of radius 0.1 turning the other way. */
static void star_with_hole(double *xy, size_t ends[2])
{
    const double pi = 3.14159265358979323846;
    int k;
    for (k = 0; k < 40; k++) {
        const double a = 2.0 * pi * k / 40.0, r = (k & 1) ? 0.3 : 0.45;
        xy[2 * k] = 0.5 + r * cos(a);
        xy[2 * k + 1] = 0.5 + r * sin(a);
    }
    for (k = 0; k < 10; k++) {
        const double a = -2.0 * pi * k / 10.0;
        xy[80 + 2 * k] = 0.5 + 0.1 * cos(a);
        xy[80 + 2 * k + 1] = 0.5 + 0.1 * sin(a);
    }
    ends[0] = 40;
    ends[1] = 50;
}

/* One setter of the domain; retried once after PDS_ENOMEM, which must leave
 * the sampler as it was (no point, the radius unchanged). */
static int set_domain_part(struct trial *t, pds_sampler *s, int part)
{
    static const unsigned char rows[8] = {0x00, 0x7e, 0x42, 0x5a, 0x5a, 0x42, 0x7e, 0x81};
    unsigned char inside[64];
    double xy[100];
    size_t ends[2];
    static const double fixed_xy[6] = {0.3, 0.5, 0.72, 0.55, 0.5, 0.2};
    static const double fixed_c[3] = {0.0, 0.12, 0.004};
    const char *what = part == 0 ? "pds_set_polygon" : part == 1 ? "pds_set_mask"
                     : part == 2 ? "pds_set_radius_fn" : part == 3 ? "pds_set_threads" : "pds_set_fixed";
    const double radius = pds_radius(s);
    int i, tries, rc = 0;
    for (i = 0; i < 64; i++) inside[i] = (unsigned char)(rows[i / 8] >> (i % 8) & 1);
    star_with_hole(xy, ends);
    for (tries = 0; tries < 2; tries++) {
        long injected = alloc_failures();
        alloc_arm();
        if (part == 0)
            rc = pds_set_polygon(s, xy, ends, 2);
        else if (part == 1)
            rc = pds_set_mask(s, 8, 8, inside);
        else if (part == 2)
            rc = pds_set_radius_fn(s, field_fn, NULL, 0.04, 0.06);
        else if (part == 3)
            rc = pds_set_threads(s, 2);
        else
            rc = pds_set_fixed(s, fixed_xy, fixed_c, 3);
        alloc_disarm();
        if (rc != PDS_ENOMEM) break;
        check_injected(t, injected, s, what);
        if (pds_count(s) != 0 || pds_radius(s) != radius)
            error_at(t, what, "PDS_ENOMEM, yet the count is %zu and the radius went from %g to %g",
                     pds_count(s), radius, pds_radius(s));
    }
    if (rc != 0) error_at(t, what, "returned %d (%s)", rc, pds_errmsg(s));
    return rc;
}

static void do_shape(struct trial *t, pds_sampler *s)
{
    int rc = 0;
    if (cfg->shape == POLYGON || cfg->shape == POLYGON_FIELD || cfg->shape == POLYGON_THREADS ||
        cfg->shape == FIXED_THREADS || cfg->shape == FIXED || cfg->shape == FIELD_THREADS)
        rc = set_domain_part(t, s, 0);
    if (cfg->shape == MASK) rc = set_domain_part(t, s, 1);
    if ((cfg->shape == POLYGON_FIELD || cfg->shape == FIELD_THREADS || cfg->shape == TORUS_FIELD_THREADS) &&
        rc == 0)
        rc = set_domain_part(t, s, 2);
    if ((cfg->shape == THREADS || cfg->shape == POLYGON_THREADS || cfg->shape == FIXED_THREADS ||
         cfg->shape == FIELD_THREADS || cfg->shape == TORUS_FIELD_THREADS) && rc == 0)
        rc = set_domain_part(t, s, 3);
    if ((cfg->shape == FIXED_THREADS || cfg->shape == FIXED) && rc == 0) rc = set_domain_part(t, s, 4);
    outcome(t, s, rc, pds_free_area(s), "pds_set_polygon/mask");
}

/* Copies the final points: into the record, or compared with the reference. */
static void do_points(struct trial *t, pds_sampler *s)
{
    size_t n = pds_count(s), got;
    double *xy = malloc((2 * n + 2) * sizeof *xy);
    if (xy == NULL) {
        error_at(t, "pds_points", "no memory for the test's copy of %zu points", n);
        return;
    }
    alloc_arm();
    got = pds_points(s, 0, n, xy);
    alloc_disarm();
    if (got != n)
        error_at(t, "pds_points", "copied %zu of %zu points", got, n);
    outcome(t, s, 0, 0.0, "pds_points");
    if (t->ref == NULL) {
        t->record->xy = xy;
        t->record->n = n;
        return;
    }
    if (n != t->ref->n || memcmp(xy, t->ref->xy, 2 * n * sizeof *xy) != 0)
        error_at(t, "pds_points", "the final points differ from the undisturbed run's (%zu vs "
                 "%zu points)", n, t->ref->n);
    free(xy);
}

/* Call c of the sequence on *s (made by CREATE, released by DESTROY). */
static void do_call(struct trial *t, pds_sampler **s, int c)
{
    switch ((enum call)c) {
    case CREATE: *s = do_create(t); break;
    case SHAPE: do_shape(t, *s); break;
    case RUN_2000: do_run(t, *s, cfg->first_run); break;
    case RUN_500: do_run(t, *s, cfg->second_run); break;
    case RUN_END_1:
    case RUN_END_2: do_run(t, *s, 0); break;
    case FREE_AREA_1:
    case FREE_AREA_2: do_free_area(t, *s); break;
    case VERIFY_1:
    case VERIFY_2: do_verify(t, *s); break;
    case REFINE: do_refine(t, *s, REFINED); break;
    case POINTS: do_points(t, *s); break;
    case DESTROY:
        alloc_arm();
        pds_destroy(*s);
        alloc_disarm();
        *s = NULL;
        if (t->ref == NULL) {
            t->record->allocs[c] = alloc_armed_count();
            t->record->name[c] = "pds_destroy";
        }
        if (alloc_live() < 0)
            error_at(t, "pds_destroy", "too many live blocks to track");
        else if (alloc_live() != 0)
            error_at(t, "pds_destroy", "%ld blocks allocated inside pds_* calls are still live "
                     "(a leak)", alloc_live());
        t->call++;
        break;
    case N_CALLS: break;
    }
}

/* Calls first .. the end; stops early if the sampler could not be made. */
static void run_from(struct trial *t, pds_sampler **s, int first)
{
    int c;
    t->call = first;
    for (c = first; c < N_CALLS; c++) {
        if (c > CREATE && *s == NULL)
            return;
        do_call(t, s, c);
    }
}

/* ---- driver ---------------------------------------------------------------------- */

/* In a child: allocation k fails, then calls first .. the end run on a copy
 * of the driver's state. Returns 0 when every check passed; *enomem receives
 * how many calls reported running out of memory. */
static int trial_in_child(const struct reference *ref, pds_sampler *s, int first, long k,
                          int *enomem)
{
    int fds[2], status = 0, report[2] = {1, 0};
    pid_t pid;
    fflush(NULL); /* or the child would print our buffered output again */
    if (pipe(fds) != 0)
        return 1;
    pid = fork();
    if (pid < 0)
        return 1;
    if (pid == 0) {
        struct trial t;
        close(fds[0]);
        memset(&t, 0, sizeof t);
        t.ref = ref;
        alarm(60); /* a hang fails instead of blocking */
        alloc_fail_at(k);
        run_from(&t, &s, first);
        if (alloc_failures() != 1)
            error_at(&t, "the sequence", "allocation %ld was never made (%ld in all)", k,
                     alloc_armed_count());
        report[0] = t.errors;
        report[1] = t.enomem;
        fflush(stdout);
        _exit(write(fds[1], report, sizeof report) == (ssize_t)sizeof report ? 0 : 1);
    }
    close(fds[1]);
    if (read(fds[0], report, sizeof report) != (ssize_t)sizeof report)
        report[0] = -1;
    close(fds[0]);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        continue;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || report[0] < 0) {
        printf("  allocation %ld: the child died (status 0x%x%s)\n", k, (unsigned)status,
               WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT ? ", aborted" : "");
        return 1;
    }
    *enomem = report[1];
    return report[0] != 0;
}

/* The j-th allocation to try among the m of a call (0 <= j < tries(m)). */
static long tries(long m, int all)
{
    return all || m <= 3 * SPAN ? m : 3 * SPAN;
}

static long nth_try(long m, long j, int all)
{
    if (all || m <= 3 * SPAN || j < SPAN)
        return j + 1;
    if (j >= 2 * SPAN)
        return m - (3 * SPAN - j) + 1;
    return SPAN + 1 + (j - SPAN + 1) * (m - 2 * SPAN) / (SPAN + 1);
}

/* glibc keeps the stacks of joined threads for later ones, each with a
 * block of its own (the thread's TLS vector): made once, unarmed, before
 * the sequences, they are not counted as blocks a call left live. */
static void warm_up_threads(void)
{
    pds_sampler *s = NULL;
    if (pds_create(&s, 0.02, 1) != 0 || pds_set_threads(s, 2) != 0 || pds_run(s, 0, NULL) != PDS_DONE) {
        printf("alloc-fail: the warm-up run failed\n");
        exit(1);
    }
    pds_destroy(s);
}

int main(int argc, char **argv)
{
    static struct reference ref;
    struct trial t;
    pds_sampler *s = NULL;
    const char *env = getenv("PDS_ALLOC_ALL");
    int all;
    long K, tried = 0;
    int c, passed = 0, failed = 0, with_enomem = 0;

    if (argc > 1 && strcmp(argv[1], "small") == 0)
        cfg = &kSmall;
    else if (argc > 1 && strcmp(argv[1], "torus") == 0)
        cfg = &kTorus;
    else if (argc > 1 && strcmp(argv[1], "polygon") == 0)
        cfg = &kPolygon;
    else if (argc > 1 && strcmp(argv[1], "mask") == 0)
        cfg = &kMask;
    else if (argc > 1 && strcmp(argv[1], "field") == 0)
        cfg = &kField;
    else if (argc > 1 && strcmp(argv[1], "threads") == 0)
        cfg = &kThreads;
    else if (argc > 1 && strcmp(argv[1], "polygon-threads") == 0)
        cfg = &kPolygonThreads;
    else if (argc > 1 && strcmp(argv[1], "torus-threads") == 0)
        cfg = &kTorusThreads;
    else if (argc > 1 && strcmp(argv[1], "fixed-threads") == 0)
        cfg = &kFixedThreads;
    else if (argc > 1 && strcmp(argv[1], "fixed-large") == 0)
        cfg = &kFixedLarge;
    else if (argc > 1 && strcmp(argv[1], "fixed-one-thread") == 0)
        cfg = &kFixedOne;
    else if (argc > 1 && strcmp(argv[1], "fixed-large-one-thread") == 0)
        cfg = &kFixedLargeOne;
    else if (argc > 1 && strcmp(argv[1], "field-threads") == 0)
        cfg = &kFieldThreads;
    else if (argc > 1 && strcmp(argv[1], "field-torus-threads") == 0)
        cfg = &kFieldTorusThreads;
    else if (argc > 1) {
        printf("usage: alloc_fail [small|torus|polygon|mask|field|threads|polygon-threads|torus-threads|fixed-threads|"
               "fixed-large|fixed-one-thread|fixed-large-one-thread|field-threads|field-torus-threads]\n");
        return 2;
    }
    if (cfg->shape == THREADS || cfg->shape == POLYGON_THREADS || cfg->shape == FIXED_THREADS ||
        cfg->shape == FIELD_THREADS || cfg->shape == TORUS_FIELD_THREADS)
        warm_up_threads();
    all = cfg->every_k || (env != NULL && env[0] != '\0' && strcmp(env, "0") != 0);
    printf("alloc-fail: sequence \"%s\": R = %g, refined to %g\n", cfg->name, cfg->radius, cfg->refined);

    /* The reference, once undisturbed; this also warms up whatever libstdc++
     * allocates once. */
    memset(&t, 0, sizeof t);
    t.record = &ref;
    alloc_reset();
    run_from(&t, &s, CREATE);
    K = alloc_armed_count();
    if (t.errors != 0 || ref.xy == NULL) {
        printf("alloc-fail: the undisturbed sequence failed\n");
        return 1;
    }
    printf("alloc-fail: the sequence (%zu points) makes K = %ld armed allocations:", ref.n, K);
    for (c = 0; c < N_CALLS; c++)
        printf(" %s %ld%s", ref.name[c], ref.allocs[c] - (c > 0 ? ref.allocs[c - 1] : 0),
               c + 1 < N_CALLS ? "," : "\n");

    /* The driver: the same sequence again, undisturbed and checked against
     * the reference, forking the trials of each call before making it. */
    memset(&t, 0, sizeof t);
    t.ref = &ref;
    alloc_reset();
    for (c = 0; c < N_CALLS; c++) {
        const long first = c > 0 ? ref.allocs[c - 1] : 0, m = ref.allocs[c] - first;
        long j;
        for (j = 0; j < tries(m, all); j++) {
            const long k = first + nth_try(m, j, all);
            int enomem = 0;
            if (trial_in_child(&ref, s, c, k, &enomem) != 0) {
                printf("FAIL: allocation %ld of %ld (in %s) failing\n", k, K, ref.name[c]);
                failed++;
            } else {
                passed++;
            }
            with_enomem += enomem > 0;
            tried++;
        }
        do_call(&t, &s, c);
        if (alloc_armed_count() != ref.allocs[c])
            error_at(&t, ref.name[c], "%ld allocations so far, the first time %ld",
                     alloc_armed_count(), ref.allocs[c]);
    }
    if (t.errors != 0) {
        printf("FAIL: the undisturbed sequence, a second time, differs from the first\n");
        failed++;
    } else {
        passed++;
    }
    printf("alloc-fail: tried %ld of the %ld allocations%s; %d surfaced as PDS_ENOMEM (or NaN)\n",
           tried, K, all ? "" : " (PDS_ALLOC_ALL=1: every one)", with_enomem);
    printf("alloc-fail: %d passed, %d failed\n", passed, failed);
    free(ref.xy);
    return failed == 0 ? 0 : 1;
}
