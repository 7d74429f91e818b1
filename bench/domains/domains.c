/*
 * domains.c - what a polygonal domain costs: nanoseconds per point of a
 * maximal pattern in an outline with a hole, against its bounding rectangle
 * in the same process, runs interleaved (make bench-domains).
 *
 *   bench-domains [--repeats K] [--points N]
 *
 * Outlines (each with a 64-vertex circular hole of radius 0.08 at the centre):
 *   star1k    a five-armed star, r(t) = 0.34 + 0.15 cos 5t, 1000 vertices
 *   star100k  the same star with 10^5 vertices
 *   spiky1k   1000 vertices alternating between radii 0.42 and 0.5
 * R is chosen so each outline holds about N points (default 10^6); the
 * rectangle is the outline's bounding box at the same R. Each run is
 * verified once (pds_verify) outside the timing. Prints the median of K
 * runs (default 3) of each and the ratio of the medians.
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

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

struct outline {
    const char *name;
    int vertices;
    int spiky;
    double *xy;
    size_t ends[2];
    double box[4];
    double area;
};

static void make_outline(struct outline *o) {
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
    o->area = 0.5 * twice - HOLE * 0.5 * 0.08 * 0.08 * sin(2 * PI / HOLE);
}

/* One maximal run; returns seconds, *points the count. */
static double run(const struct outline *o, int polygon, double r, unsigned long seed, size_t *points) {
    pds_sampler *s;
    if (pds_create(&s, r, seed) != 0) exit(1);
    const double t0 = now();
    if (polygon ? pds_set_polygon(s, o->xy, o->ends, 2) : pds_set_domain(s, o->box[0], o->box[1], o->box[2], o->box[3])) {
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
    if (seed == 1 && pds_verify(s) != PDS_DONE) {
        fprintf(stderr, "verify: %s\n", pds_errmsg(s));
        exit(1);
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
        else {
            fprintf(stderr, "usage: bench-domains [--repeats K] [--points N]\n");
            return 2;
        }
    }
    if (repeats < 1 || repeats > MAX_REPEATS || !(target >= 100)) return 2;
    struct outline outlines[3];
    memset(outlines, 0, sizeof outlines);
    const char *names[3] = {"star1k", "star100k", "spiky1k"};
    const int vertices[3] = {1000, 100000, 1000};
    for (int k = 0; k < 3; k++) {
        outlines[k].name = names[k];
        outlines[k].vertices = vertices[k];
        outlines[k].spiky = k == 2;
    }
    printf("%-9s %10s %12s %12s %12s %7s\n", "outline", "points", "ns/pt", "rect points", "rect ns/pt", "ratio");
    for (size_t k = 0; k < sizeof outlines / sizeof outlines[0]; k++) {
        struct outline *o = &outlines[k];
        make_outline(o);
        /* A maximal pattern covers about 0.7 A / R^2 points in the plane. */
        const double r = sqrt(0.7 * o->area / target);
        double poly[MAX_REPEATS], rect[MAX_REPEATS];
        size_t np = 0, nr = 0;
        for (int i = 0; i < repeats; i++) {
            poly[i] = run(o, 1, r, (unsigned long)i + 1, &np);
            rect[i] = run(o, 0, r, (unsigned long)i + 1, &nr);
            poly[i] *= 1e9 / (double)np;
            rect[i] *= 1e9 / (double)nr;
        }
        qsort(poly, (size_t)repeats, sizeof poly[0], by_value);
        qsort(rect, (size_t)repeats, sizeof rect[0], by_value);
        const double mp = poly[repeats / 2], mr = rect[repeats / 2];
        printf("%-9s %10zu %12.0f %12zu %12.0f %7.2f\n", o->name, np, mp, nr, mr, mp / mr);
        fflush(stdout);
        free(o->xy);
    }
    return 0;
}
