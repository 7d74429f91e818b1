/*
 * bench.c - figures for maximal patterns in the unit square (make bench).
 *
 * For each target size N (about 10^4, 10^5, 10^6 points by default) the radius
 * is R = sqrt(0.6966 / N) (random sequential adsorption saturates at
 * N pi R^2 / 4 = 0.547 per unit area). Each run happens in a fresh child
 * process, so its peak resident memory can be read with wait4(); the time
 * covers pds_create, pds_run to maximality and pds_destroy. Prints N, median
 * seconds over the repeats, ns per point, time / (N log2 N) (the paper's
 * figure 7) and peak memory per point net of an empty run's. Figures, not
 * assertions: nothing here fails on a slow machine.
 *
 * usage: bench [--repeats K] [N ...]
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE
#include <math.h>
#include <poissondisk.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

struct result {
    double seconds;
    size_t points;
    long peak_kib;
    int ok;
};

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* In the child: one maximal pattern; writes seconds and count to fd. */
static int child_run(double radius, uint64_t seed, int fd) {
    double t0 = now(), t1;
    pds_sampler *s = NULL;
    size_t added = 0;
    int rc = pds_create(&s, radius, seed);
    if (rc == 0) rc = pds_run(s, 0, &added);
    pds_destroy(s);
    t1 = now();
    {
        double msg[2];
        msg[0] = t1 - t0;
        msg[1] = (double)added;
        if (write(fd, msg, sizeof msg) != (ssize_t)sizeof msg) return 1;
    }
    return rc == 0 ? 0 : 1;
}

static struct result measure(double radius, uint64_t seed) {
    struct result r = {0.0, 0, 0, 0};
    int fds[2];
    pid_t pid;
    if (pipe(fds) != 0) return r;
    fflush(stdout);
    pid = fork();
    if (pid < 0) return r;
    if (pid == 0) {
        close(fds[0]);
        _exit(child_run(radius, seed, fds[1]));
    }
    close(fds[1]);
    {
        double msg[2];
        int status = 0;
        struct rusage ru;
        ssize_t got = read(fds[0], msg, sizeof msg);
        close(fds[0]);
        if (wait4(pid, &status, 0, &ru) < 0) return r;
        if (got == (ssize_t)sizeof msg && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
            r.seconds = msg[0];
            r.points = (size_t)msg[1];
            r.peak_kib = ru.ru_maxrss;
            r.ok = 1;
        }
    }
    return r;
}

static int by_seconds(const void *a, const void *b) {
    double x = ((const struct result *)a)->seconds, y = ((const struct result *)b)->seconds;
    return (x > y) - (x < y);
}

int main(int argc, char **argv) {
    size_t targets[16];
    int ntargets = 0, repeats = 3, i, k;
    struct result empty;
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
            repeats = atoi(argv[++i]);
            if (repeats < 1 || repeats > 99) repeats = 3;
        } else if (ntargets < 16) {
            targets[ntargets++] = (size_t)strtod(argv[i], NULL);
        }
    }
    if (ntargets == 0) {
        targets[0] = 10000;
        targets[1] = 100000;
        targets[2] = 1000000;
        ntargets = 3;
    }
    empty = measure(0.5, 1); /* a one- or two-point pattern: the process's base memory */
    printf("poissondisk %s bench: maximal patterns in the unit square, median of %d runs\n",
           pds_version_string(), repeats);
    printf("%10s %10s %9s %9s %13s %11s %9s\n", "N", "R", "seconds", "ns/point", "ns/(N log2N)",
           "peak MiB", "B/point");
    for (k = 0; k < ntargets; ++k) {
        double radius = sqrt(0.6966 / (double)targets[k]);
        struct result runs[99], med;
        long peak = 0;
        for (i = 0; i < repeats; ++i) {
            runs[i] = measure(radius, (uint64_t)(i + 1));
            if (!runs[i].ok) {
                fprintf(stderr, "bench: run failed at R=%g\n", radius);
                return 1;
            }
            if (runs[i].peak_kib > peak) peak = runs[i].peak_kib;
        }
        qsort(runs, (size_t)repeats, sizeof runs[0], by_seconds);
        med = runs[repeats / 2];
        printf("%10zu %10.6f %9.3f %9.1f %13.3f %11.1f %9.1f\n", med.points, radius, med.seconds,
               1e9 * med.seconds / (double)med.points,
               1e9 * med.seconds / ((double)med.points * log2((double)med.points)),
               (double)peak / 1024.0,
               1024.0 * (double)(peak - empty.peak_kib) / (double)med.points);
    }
    return 0;
}
