/*
 * domains.c - what a polygonal domain costs: nanoseconds per point of a
 * maximal pattern in an outline with a hole, against its bounding rectangle
 * in the same process, runs interleaved (make bench-domains).
 *
 *   bench-domains [--repeats K] [--points N] [--threads T]
 *
 * Outlines (the first three with a 64-vertex circular hole of radius 0.08 at
 * the centre):
 *   star1k    a five-armed star, r(t) = 0.34 + 0.15 cos 5t, 1000 vertices
 *   star100k  the same star with 10^5 vertices
 *   spiky1k   1000 vertices alternating between radii 0.42 and 0.5
 *   comb64    a comb: a base 0.1 tall and 64 teeth 0.9 long, each 0.3/64 wide
 *             (nearly every cell is cut by the outline)
 * R is chosen so each outline holds about N points (default 10^6); the
 * rectangle is the outline's bounding box at the same R. The first run of
 * each outline is verified (pds_verify), timed apart. Prints the median of K
 * runs (default 3) of each, the ratio of the medians, and the verification's
 * time per point in the outline. With --threads every run, outline and
 * rectangle, selects the parallel process on T threads (pds_set_threads; 0:
 * one per core); without it, the default single-thread process.
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <poissondisk.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define HOLE 64
#define PI 3.14159265358979323846
#define MAX_REPEATS 15

static int threads = -1; /* --threads, or -1: pds_set_threads is not called */

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

struct outline {
    const char *name;
    int vertices;
    int spiky;
    int comb;  /* teeth, or 0 for a star */
    double *xy;
    size_t ends[2];
    size_t rings;
    double box[4];
    double area;
};

static void make_comb(struct outline *o) {
    const int teeth = o->comb;
    const double step = 1.0 / teeth, width = 0.3 / teeth;
    size_t n = 0;
    o->xy = malloc(sizeof(double) * 2 * (size_t)(4 * teeth + 4));
    if (!o->xy) exit(1);
#define VERTEX(x, y) (o->xy[2 * n] = (x), o->xy[2 * n + 1] = (y), n++)
    VERTEX(0.0, 0.0);
    VERTEX(1.0, 0.0);
    VERTEX(1.0, 0.1);
    for (int i = teeth - 1; i >= 0; i--) {
        const double left = i * step, right = left + width;
        VERTEX(right, 0.1);
        VERTEX(right, 1.0);
        VERTEX(left, 1.0);
        if (i > 0) VERTEX(left, 0.1);
    }
#undef VERTEX
    o->ends[0] = n;
    o->rings = 1;
    o->box[0] = o->box[1] = 0.0;
    o->box[2] = o->box[3] = 1.0;
    o->area = 0.1 + 0.9 * 0.3;
}

static void make_outline(struct outline *o) {
    if (o->comb) {
        make_comb(o);
        return;
    }
    const int n = o->vertices;
    o->xy = malloc(sizeof(double) * 2 * (size_t)(n + HOLE));
    if (!o->xy) exit(1);
    o->box[0] = o->box[1] = 1.0;
    o->box[2] = o->box[3] = 0.0;
    double twice = 0.0;
    for (int i = 0; i < n; i++) {
        const double a = 2 * PI * i / n;
        const double r = o->spiky ? (i % 2 ? 0.5 : 0.42) : 0.34 + 0.15 * cos(5 * a);
        o->xy[2 * i] = 0.5 + r * cos(a);
        o->xy[2 * i + 1] = 0.5 + r * sin(a);
    }
    for (int i = 0; i < n; i++) {
        const double *p = o->xy + 2 * i, *q = o->xy + 2 * ((i + 1) % n);
        twice += p[0] * q[1] - p[1] * q[0];
        if (p[0] < o->box[0]) o->box[0] = p[0];
        if (p[1] < o->box[1]) o->box[1] = p[1];
        if (p[0] > o->box[2]) o->box[2] = p[0];
        if (p[1] > o->box[3]) o->box[3] = p[1];
    }
    for (int i = 0; i < HOLE; i++) {
        const double a = 2 * PI * i / HOLE;
        o->xy[2 * (n + i)] = 0.5 + 0.08 * cos(a);
        o->xy[2 * (n + i) + 1] = 0.5 + 0.08 * sin(a);
    }
    o->ends[0] = (size_t)n;
    o->ends[1] = (size_t)(n + HOLE);
    o->rings = 2;
    o->area = 0.5 * twice - HOLE * 0.5 * 0.08 * 0.08 * sin(2 * PI / HOLE);
}

/* One maximal run; returns seconds, *points the count; with verified, the
 * run is verified and *verified holds its seconds. */
static double run(const struct outline *o, int polygon, double r, unsigned long seed, size_t *points,
                  double *verified) {
    pds_sampler *s;
    if (pds_create(&s, r, seed) != 0) exit(1);
    if (threads >= 0 && pds_set_threads(s, (unsigned)threads) != 0) {
        fprintf(stderr, "%s\n", pds_errmsg(s));
        exit(1);
    }
    const double t0 = now();
    if (polygon ? pds_set_polygon(s, o->xy, o->ends, o->rings)
                : pds_set_domain(s, o->box[0], o->box[1], o->box[2], o->box[3])) {
        fprintf(stderr, "%s\n", pds_errmsg(s));
        exit(1);
    }
    size_t added = 0;
    if (pds_run(s, 0, &added) != PDS_DONE) {
        fprintf(stderr, "run: %s\n", pds_errmsg(s));
        exit(1);
    }
    const double t = now() - t0;
    *points = pds_count(s);
    if (verified) {
        const double v0 = now();
        if (pds_verify(s) != PDS_DONE) {
            fprintf(stderr, "verify: %s\n", pds_errmsg(s));
            exit(1);
        }
        *verified = now() - v0;
    }
    pds_destroy(s);
    return t;
}

static int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv) {
    int repeats = 3;
    double target = 1e6;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeats") && i + 1 < argc) repeats = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--points") && i + 1 < argc) target = atof(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: bench-domains [--repeats K] [--points N] [--threads T]\n");
            return 2;
        }
    }
    if (repeats < 1 || repeats > MAX_REPEATS || !(target >= 100) || threads > 1024) return 2;
    struct outline outlines[4];
    memset(outlines, 0, sizeof outlines);
    const char *names[4] = {"star1k", "star100k", "spiky1k", "comb64"};
    const int vertices[4] = {1000, 100000, 1000, 0};
    for (int k = 0; k < 4; k++) {
        outlines[k].name = names[k];
        outlines[k].vertices = vertices[k];
        outlines[k].spiky = k == 2;
        outlines[k].comb = k == 3 ? 64 : 0;
    }
    printf("%-9s %10s %12s %12s %12s %7s %12s\n", "outline", "points", "ns/pt", "rect points", "rect ns/pt", "ratio",
           "verify ns/pt");
    for (size_t k = 0; k < sizeof outlines / sizeof outlines[0]; k++) {
        struct outline *o = &outlines[k];
        make_outline(o);
        /* A maximal pattern covers about 0.7 A / R^2 points in the plane. */
        const double r = sqrt(0.7 * o->area / target);
        double poly[MAX_REPEATS], rect[MAX_REPEATS];
        size_t np = 0, nr = 0;
        double verify = 0.0;
        for (int i = 0; i < repeats; i++) {
            poly[i] = run(o, 1, r, (unsigned long)i + 1, &np, i == 0 ? &verify : NULL);
            if (i == 0) verify *= 1e9 / (double)np;
            rect[i] = run(o, 0, r, (unsigned long)i + 1, &nr, NULL);
            poly[i] *= 1e9 / (double)np;
            rect[i] *= 1e9 / (double)nr;
        }
        qsort(poly, (size_t)repeats, sizeof poly[0], by_value);
        qsort(rect, (size_t)repeats, sizeof rect[0], by_value);
        const double mp = poly[repeats / 2], mr = rect[repeats / 2];
        printf("%-9s %10zu %12.0f %12zu %12.0f %7.2f %12.0f\n", o->name, np, mp, nr, mr, mp / mr, verify);
        fflush(stdout);
        free(o->xy);
    }
    return 0;
}
