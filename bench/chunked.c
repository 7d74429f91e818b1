/*
 * chunked.c - the cost of splitting a run into one-point calls.
 *
 * The header promises (since 1.1.1) that small chunks are O(1) amortized, so
 *     while (pds_run(s, 1, NULL) == PDS_MORE);
 * costs within about 3 times one pds_run(s, 0, NULL) at 10^5 points, and
 * gives the same points. This section of make bench times three ways of
 * making the same maximal pattern, with the same seed:
 *     one      pds_run(s, 0, NULL)
 *     run(1)   pds_run(s, 1, NULL) until it returns 0
 *     step     pds_step(s) until it returns 0
 * Each run is a fresh child process (as in bench.c: no allocator or cache
 * state carried over); the timed region is pds_create and the calls. The
 * child then fingerprints the points (count and a 64-bit FNV-1a hash of their
 * bytes), untimed; the three ways must agree for every seed, else the
 * program fails. Figures, not assertions: the ratios are printed, not judged.
 */
#define _POSIX_C_SOURCE 200809L
#include "chunked.h"

#include <errno.h>
#include <math.h>
#include <poissondisk.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define MAX_REPEATS 99

enum way { WAY_ONE, WAY_RUN1, WAY_STEP, N_WAYS };
static const char *const way_label[N_WAYS] = {
    "one pds_run(s, 0)", "pds_run(s, 1) until done", "pds_step(s) until done",
};

struct chunk_record {
    int ok;
    double seconds;
    size_t points;
    uint64_t hash;
};

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t fingerprint(const double *v, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    const unsigned char *bytes = (const unsigned char *)v;
    size_t i;
    for (i = 0; i < n * sizeof *v; ++i) {
        h ^= bytes[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* In the child: one way, timed, then fingerprinted. */
static struct chunk_record child_run(enum way w, double radius, uint64_t seed)
{
    struct chunk_record rec;
    pds_sampler *s = NULL;
    double t0, t1, *xy;
    int rc;

    memset(&rec, 0, sizeof rec);
    t0 = now();
    rc = pds_create(&s, radius, seed);
    if (rc == 0) {
        switch (w) {
        case WAY_ONE: rc = pds_run(s, 0, NULL); break;
        case WAY_RUN1:
            while ((rc = pds_run(s, 1, NULL)) == PDS_MORE) continue;
            break;
        case WAY_STEP:
            while ((rc = pds_step(s)) == PDS_MORE) continue;
            break;
        case N_WAYS: break;
        }
    }
    t1 = now();
    rec.seconds = t1 - t0;
    rec.points = pds_count(s);
    xy = malloc((2 * rec.points + 2) * sizeof *xy);
    if (rc == PDS_DONE && xy != NULL && pds_points(s, 0, rec.points, xy) == rec.points) {
        rec.hash = fingerprint(xy, 2 * rec.points);
        rec.ok = 1;
    }
    free(xy);
    pds_destroy(s);
    return rec;
}

static struct chunk_record measure(enum way w, double radius, uint64_t seed)
{
    struct chunk_record rec;
    int fds[2], status = 0;
    ssize_t got;
    pid_t pid;

    memset(&rec, 0, sizeof rec);
    if (pipe(fds) != 0) return rec;
    fflush(NULL); /* or the child would flush our buffered output a second time */
    pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return rec;
    }
    if (pid == 0) {
        close(fds[0]);
        rec = child_run(w, radius, seed);
        _exit(write(fds[1], &rec, sizeof rec) == (ssize_t)sizeof rec ? 0 : 1);
    }
    close(fds[1]);
    got = read(fds[0], &rec, sizeof rec);
    close(fds[0]);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) continue;
    if (got != (ssize_t)sizeof rec || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        memset(&rec, 0, sizeof rec);
    return rec;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int chunked_bench(FILE *out, size_t target, int repeats)
{
    static double seconds[N_WAYS][MAX_REPEATS];
    const double radius = sqrt(0.6966 / (double)target);
    size_t points = 0;
    int r, w, same[N_WAYS] = {1, 1, 1}, all_same = 1;
    double one;

    if (repeats > MAX_REPEATS) repeats = MAX_REPEATS;
    for (r = 0; r < repeats; ++r) {
        struct chunk_record rec[N_WAYS];
        for (w = 0; w < N_WAYS; ++w) {
            rec[w] = measure((enum way)w, radius, (uint64_t)r + 1);
            if (!rec[w].ok) {
                fprintf(stderr, "bench: chunked, %s at N=%zu, seed %d failed\n", way_label[w],
                        target, r + 1);
                return 1;
            }
            seconds[w][r] = rec[w].seconds;
            if (rec[w].points != rec[WAY_ONE].points || rec[w].hash != rec[WAY_ONE].hash) {
                fprintf(stderr, "bench: chunked, seed %d: %s gave %zu points (hash %016llx), "
                        "one pds_run %zu (%016llx)\n", r + 1, way_label[w], rec[w].points,
                        (unsigned long long)rec[w].hash, rec[WAY_ONE].points,
                        (unsigned long long)rec[WAY_ONE].hash);
                same[w] = all_same = 0;
            }
        }
        points = rec[WAY_ONE].points;
    }
    fprintf(out, "chunked runs, N=%zu, R=%.6f, seeds 1..%d (seed %d: %zu points), median: "
            "time relative to one pds_run(s, 0)\n", target, radius, repeats, repeats, points);
    one = median(seconds[WAY_ONE], repeats);
    for (w = 0; w < N_WAYS; ++w) {
        double t = w == WAY_ONE ? one : median(seconds[w], repeats);
        fprintf(out, "  %-26s %9.4f s  %7.2fx", way_label[w], t, t / one);
        fprintf(out, "%s\n", w == WAY_ONE ? "" : same[w] ? "  same points" : "  POINTS DIFFER");
    }
    fflush(out);
    return all_same ? 0 : 1;
}
