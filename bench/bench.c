/*
 * bench.c - figures for maximal patterns in the unit square (make bench),
 * against two in-tree baselines timed in the same run at the same N and R.
 *
 * Methods:
 *   poissondisk  this library: pds_create + pds_run to maximality
 *   bridson      plain Bridson sampling, k = 30 (bridson.c)
 *   dart         grid dart throwing, stopped after a run of misses (dart_grid.c)
 *   periodic     this library on the unit torus (pds_set_periodic)
 *   threads1     this library's parallel process on one thread (pds_set_threads 1)
 *   threads      the same on one thread per online core (pds_set_threads 0):
 *                the same points as threads1
 *   field        this library with a variable radius varying 1:4 across the
 *                square, r(x) = (R/2)(1 + 3x), whose maximal patterns hold
 *                about as many points as R does (pds_set_radius_fn); checked
 *                by pds_verify (untimed), as the probes assume one radius
 *
 * For each target size N (10^4 .. 10^7 by default) the radius is
 * R = sqrt(0.6966 / N) (random sequential adsorption saturates at
 * N pi R^2 / 4 = 0.547 per unit area). Every run happens in a fresh child
 * process, seeds 1..K for K repeats, the methods one after another for each
 * seed (so a machine whose speed drifts moves every method alike):
 *   - The timed region covers generating the points and nothing else: for
 *     the library pds_create and pds_run, for a baseline its whole sampler,
 *     grid included. Releasing the points (pds_destroy, free) is not timed.
 *   - Around it the child counts user-space instructions with
 *     perf_event_open, when the kernel allows it.
 *   - Right after it the child reads its own ru_maxrss: the peak resident
 *     memory that wait4() would report, read before the checks below
 *     allocate anything. Peaks are reported net of the same method's run at
 *     R = 0.5 (a handful of points), which holds the process's own memory
 *     and the code pages that method touches.
 *   - Then, untimed, the child judges the pattern (pattern_check.c): the
 *     minimum pair distance, and the fraction of the square left uncovered
 *     on a fixed jittered lattice of about 16 probes per point (at most 2^26).
 *
 * Per size and method it prints the median seconds, ns per point,
 * ns / (N log2 N) (the paper's figure 7), peak bytes per point (the largest
 * of the repeats), instructions per point, the uncovered fraction pooled over
 * the repeats with its binomial standard error, and the minimum-distance
 * verdict; then the baselines' times relative to the library's, as ratios
 * of the medians and paired (the median over the seeds of each seed's
 * ratio, whose two runs were minutes apart at most), with the parallel
 * process's one thread against all (threads1/threads) paired too. Then the
 * chunked section (chunked.c): one pds_run against pds_run(s, 1) and pds_step
 * repeated, at the largest size up to 10^5. Figures, not assertions: nothing
 * here fails on a slow machine. It exits 1 only when a run fails, a pattern
 * has two points closer than R, the library's pattern is not maximal (probes
 * left uncovered), or the chunked ways give other points: those are bugs.
 *
 * usage: see usage_text below, or bench --help.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
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

#include "bridson.h"
#include "chunked.h"
#include "dart_grid.h"
#include "pattern_check.h"
#include "pattern_check_test.h"
#include "perf_counter.h"
#include "plot_svg.h"

#define PROG "bench"
#define MAX_SIZES 16
#define MAX_REPEATS 99
/* RSA's saturation density: N pi R^2 / 4 = 0.547, so R = sqrt(0.6966 / N). */
#define SATURATION_AREA 0.6966

static const char usage_text[] =
    "usage: " PROG " [--repeats K] [--methods LIST] [--csv FILE] [--svg FILE]\n"
    "             [--dart-misses F] [--callgrind] [N ...]\n"
    "       " PROG " --self-test\n"
    "\n"
    "Time maximal patterns of about N points in the unit square (R = sqrt(0.6966/N));\n"
    "default sizes 10000 100000 1000000 10000000.\n"
    "\n"
    "  --repeats K      runs per size and method, each in a fresh process, seeds\n"
    "                   1..K; the table shows medians (default 3)\n"
    "  --methods LIST   comma-separated subset of poissondisk,bridson,dart,periodic,field,\n"
    "                   threads1,threads\n"
    "  --csv FILE       also write one CSV row per method and size; FILE '-' or\n"
    "                   no FILE: to standard output, the table then to stderr\n"
    "  --svg FILE       also write time / (N log2 N) against N as an SVG chart\n"
    "  --dart-misses F  darts missed in a row that end dart throwing (default 3000)\n"
    "  --chunked N      time one pds_run against pds_run(s, 1) and pds_step loops at\n"
    "                   N points; 0: skip (default: the largest size, at most 100000)\n"
    "  --callgrind      count instructions per point under valgrind's callgrind\n"
    "                   (one extra run per size and method, seed 1; roughly 50-100\n"
    "                   times slower than native: meant for N up to about 10^5)\n"
    "  --self-test      run the pattern checks on known patterns and exit\n"
    "\n"
    "Exit status: 0, 1 if a run failed, a pattern failed its checks or the chunked\n"
    "ways disagree, 2 bad arguments.\n";

/* "periodic" is the library on the unit torus (pds_set_periodic): same law,
 * no edges, the copies near the edges are its extra cost. */
enum method {
    METHOD_POISSONDISK, METHOD_BRIDSON, METHOD_DART, METHOD_PERIODIC, METHOD_FIELD,
    METHOD_THREADS1, METHOD_THREADS, METHOD_COUNT
};
static const char *const method_name[METHOD_COUNT] = {"poissondisk", "bridson", "dart", "periodic", "field",
                                                      "threads1", "threads"};
static const char *const method_color[METHOD_COUNT] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                                       "#17becf", "#8c564b"};

/* The field method's radius: r0 (1 + 3x) over the unit square, 1:4. Its
 * maximal patterns hold about 0.6966 / 4 / r0^2 points (the mean of 1/r^2
 * is 1 / (4 r0^2)): r0 = R/2 matches R's count. */
static double gradient_field(void *user, double x, double y) {
    (void)y;
    return *(const double *)user * (1.0 + 3.0 * x);
}

/* What a child sends back through its pipe: plain data, same binary both ends. */
struct run_record {
    int ok;
    double seconds;
    double points;
    double instructions; /* < 0: not counted */
    long peak_kib;
    struct pattern_check check;
    char error[200];
};

/* One row of the table and the CSV. */
struct summary {
    enum method method;
    size_t target;
    double radius;
    double seconds; /* median */
    double points;  /* median */
    double instructions_per_point; /* < 0: not counted */
    double peak_bytes_per_point;
    double uncovered_fraction, uncovered_stderr;
    double min_distance;
    int min_distance_ok;
};

struct options {
    size_t targets[MAX_SIZES];
    int target_count;
    int repeats;
    int use_method[METHOD_COUNT];
    const char *csv_path; /* NULL: none; "-": stdout */
    const char *svg_path;
    unsigned long dart_misses;
    int callgrind;
    long chunked; /* points for the chunked section; 0: skip; -1: the default */
};

/* The points a method produced: the library keeps them in its sampler, the
 * baselines in an array. */
struct generated {
    pds_sampler *sampler;
    double *xy;
    size_t count;
};

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/*
 * Everything that is timed, counted and measured, and nothing else. Kept out
 * of line so callgrind can collect exactly this function (--toggle-collect).
 */
__attribute__((noinline)) int bench_timed_region(enum method m, double radius, uint64_t seed,
                                                 unsigned long dart_misses, struct generated *out,
                                                 char *error, size_t error_size) {
    int rc;
    memset(out, 0, sizeof *out);
    switch (m) {
    case METHOD_POISSONDISK:
    case METHOD_PERIODIC:
    case METHOD_THREADS1:
    case METHOD_THREADS:
        rc = pds_create(&out->sampler, radius, seed);
        if (rc == 0 && m == METHOD_PERIODIC) rc = pds_set_periodic(out->sampler, 1);
        if (rc == 0 && m == METHOD_THREADS1) rc = pds_set_threads(out->sampler, 1);
        if (rc == 0 && m == METHOD_THREADS) rc = pds_set_threads(out->sampler, 0);
        if (rc == 0) rc = pds_run(out->sampler, 0, &out->count);
        if (rc != 0) snprintf(error, error_size, "%s", pds_errmsg(out->sampler));
        if (rc != 0 && out->sampler == NULL) snprintf(error, error_size, "%s", pds_strerror(rc));
        return rc == 0 ? 0 : -1;
    case METHOD_FIELD: {
        static double r0;
        r0 = 0.5 * radius;
        rc = pds_create(&out->sampler, 1.0, seed);
        if (rc == 0) rc = pds_set_radius_fn(out->sampler, gradient_field, &r0, r0, 4.0 * r0);
        if (rc == 0) rc = pds_run(out->sampler, 0, &out->count);
        if (rc != 0) snprintf(error, error_size, "%s", pds_errmsg(out->sampler));
        if (rc != 0 && out->sampler == NULL) snprintf(error, error_size, "%s", pds_strerror(rc));
        return rc == 0 ? 0 : -1;
    }
    case METHOD_BRIDSON:
        rc = bridson_sample(radius, seed, &out->xy, &out->count);
        break;
    case METHOD_DART:
        rc = dart_grid_sample(radius, seed, dart_misses, &out->xy, &out->count);
        break;
    default:
        rc = -1;
    }
    if (rc != 0) snprintf(error, error_size, "%s: out of memory", method_name[m]);
    return rc;
}

/* The points as an interleaved array, copied out of the sampler if need be. */
static const double *generated_points(struct generated *g) {
    if (g->xy == NULL && g->sampler != NULL) {
        g->xy = malloc((g->count > 0 ? 2 * g->count : 1) * sizeof *g->xy);
        if (g->xy != NULL) pds_points(g->sampler, 0, g->count, g->xy);
    }
    return g->xy;
}

static void generated_free(struct generated *g) {
    pds_destroy(g->sampler);
    free(g->xy);
    memset(g, 0, sizeof *g);
}

/* In the child: one run, timed, then checked; the record goes to fd. */
static int child_run(enum method m, double radius, uint64_t seed, const struct options *opt,
                     uint32_t probe_side, int fd) {
    struct run_record rec;
    struct perf_counter counter;
    struct generated gen;
    struct rusage usage;
    double t0, t1;
    int rc;

    memset(&rec, 0, sizeof rec);
    perf_counter_open(&counter);
    perf_counter_start(&counter);
    t0 = now();
    rc = bench_timed_region(m, radius, seed, opt->dart_misses, &gen, rec.error, sizeof rec.error);
    t1 = now();
    rec.instructions = perf_counter_stop(&counter);
    perf_counter_close(&counter);
    /* The peak so far: the generation's. The checks below allocate their own. */
    getrusage(RUSAGE_SELF, &usage);
    rec.peak_kib = usage.ru_maxrss;
    rec.seconds = t1 - t0;
    rec.points = (double)gen.count;
    if (rc == 0 && m == METHOD_FIELD) {
        /* Every pair is at least the smallest radius apart; maximality by the
         * library's exact certificate (the probes assume one radius). */
        const double *xy = generated_points(&gen);
        const int verdict = pds_verify(gen.sampler);
        if (xy == NULL || pattern_check(xy, gen.count, 0.5 * radius, 0, 0, &rec.check) != 0)
            snprintf(rec.error, sizeof rec.error, "out of memory in the checks");
        else if (verdict != PDS_DONE)
            snprintf(rec.error, sizeof rec.error, "pds_verify: %d (%s)", verdict, pds_errmsg(gen.sampler));
        else
            rec.ok = 1;
    } else if (rc == 0) {
        const double *xy = generated_points(&gen);
        if (xy == NULL || pattern_check(xy, gen.count, radius, m == METHOD_PERIODIC, probe_side,
                                         &rec.check) != 0)
            snprintf(rec.error, sizeof rec.error, "out of memory in the checks");
        else
            rec.ok = 1;
    }
    generated_free(&gen);
    return write(fd, &rec, sizeof rec) == (ssize_t)sizeof rec ? 0 : 1;
}

static struct run_record measure(enum method m, double radius, uint64_t seed,
                                 const struct options *opt, uint32_t probe_side) {
    struct run_record rec;
    int fds[2], status = 0;
    pid_t pid;
    ssize_t got;

    memset(&rec, 0, sizeof rec);
    if (pipe(fds) != 0) {
        snprintf(rec.error, sizeof rec.error, "pipe: %s", strerror(errno));
        return rec;
    }
    fflush(NULL); /* or the child would flush our buffered output a second time */
    pid = fork();
    if (pid < 0) {
        snprintf(rec.error, sizeof rec.error, "fork: %s", strerror(errno));
        close(fds[0]);
        close(fds[1]);
        return rec;
    }
    if (pid == 0) {
        close(fds[0]);
        _exit(child_run(m, radius, seed, opt, probe_side, fds[1]));
    }
    close(fds[1]);
    got = read(fds[0], &rec, sizeof rec);
    close(fds[0]);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) continue;
    if (got != (ssize_t)sizeof rec || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        memset(&rec, 0, sizeof rec);
        snprintf(rec.error, sizeof rec.error, "child died (status 0x%x)", (unsigned)status);
    }
    rec.error[sizeof rec.error - 1] = '\0';
    return rec;
}

/* ---- instructions under callgrind ------------------------------------------------ */

/*
 * Runs this program under callgrind in --single mode, collecting only inside
 * bench_timed_region. Returns instructions per point, or -1 on any failure.
 */
static double callgrind_instructions_per_point(enum method m, double radius,
                                               unsigned long dart_misses) {
    char self[4096], out_file[4200], radius_text[40], misses_text[24], line[256];
    const char *valgrind = getenv("VALGRIND") != NULL ? getenv("VALGRIND") : "valgrind";
    const char *tmpdir = getenv("TMPDIR") != NULL ? getenv("TMPDIR") : "/tmp";
    double instructions = -1.0, points = -1.0;
    ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
    int fds[2], status = 0;
    pid_t pid;
    FILE *f;

    if (len <= 0) return -1.0;
    self[len] = '\0';
    snprintf(out_file, sizeof out_file, "%s/bench-callgrind.%ld", tmpdir, (long)getpid());
    snprintf(radius_text, sizeof radius_text, "%.17g", radius);
    snprintf(misses_text, sizeof misses_text, "%lu", dart_misses);
    if (pipe(fds) != 0) return -1.0;
    fflush(NULL);
    pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return -1.0;
    }
    if (pid == 0) {
        char out_option[4300];
        snprintf(out_option, sizeof out_option, "--callgrind-out-file=%s", out_file);
        dup2(fds[1], STDOUT_FILENO);
        close(fds[0]);
        close(fds[1]);
        execlp(valgrind, valgrind, "--tool=callgrind", "-q", out_option,
               "--toggle-collect=bench_timed_region", self, "--single", method_name[m], radius_text,
               misses_text, (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    f = fdopen(fds[0], "r");
    if (f != NULL) {
        while (fgets(line, sizeof line, f) != NULL) sscanf(line, "points %lf", &points);
        fclose(f);
    } else {
        close(fds[0]);
    }
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) continue;
    f = fopen(out_file, "r");
    if (f != NULL) {
        /* "totals:" is the sum of what was collected; older versions write "summary:". */
        while (fgets(line, sizeof line, f) != NULL)
            if (sscanf(line, "totals: %lf", &instructions) != 1)
                sscanf(line, "summary: %lf", &instructions);
        fclose(f);
    }
    remove(out_file);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !(points > 0.0) ||
        !(instructions > 0.0)) {
        fprintf(stderr, PROG ": the callgrind run of %s failed (is %s installed?)\n", method_name[m],
                valgrind);
        return -1.0;
    }
    return instructions / points;
}

/* --single METHOD RADIUS MISSES: the process callgrind watches; seed 1. */
static int single_run(int argc, char **argv, int i) {
    struct generated gen;
    char error[200] = "";
    enum method m;
    double radius;
    unsigned long misses;
    if (argc != i + 3) return 2;
    for (m = 0; m < METHOD_COUNT; ++m)
        if (strcmp(argv[i], method_name[m]) == 0) break;
    radius = strtod(argv[i + 1], NULL);
    misses = strtoul(argv[i + 2], NULL, 10);
    if (m == METHOD_COUNT || !(radius > 0.0)) return 2;
    if (bench_timed_region(m, radius, 1, misses, &gen, error, sizeof error) != 0) {
        fprintf(stderr, PROG ": %s\n", error);
        generated_free(&gen);
        return 1;
    }
    printf("points %zu\n", gen.count);
    generated_free(&gen);
    return 0;
}

/* ---- summaries --------------------------------------------------------------------- */

static int by_value(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *values, int n) {
    qsort(values, (size_t)n, sizeof *values, by_value);
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

static void summarize(struct summary *s, const struct run_record *runs, int n, long empty_kib) {
    double seconds[MAX_REPEATS], points[MAX_REPEATS], instructions[MAX_REPEATS];
    uint64_t probes = 0, uncovered = 0;
    long peak = 0;
    int i, counted = 1;
    double p;
    s->min_distance_ok = 1;
    s->min_distance = HUGE_VAL;
    for (i = 0; i < n; ++i) {
        seconds[i] = runs[i].seconds;
        points[i] = runs[i].points;
        instructions[i] = runs[i].instructions;
        if (runs[i].instructions < 0.0) counted = 0;
        if (runs[i].peak_kib > peak) peak = runs[i].peak_kib;
        probes += runs[i].check.probes;
        uncovered += runs[i].check.uncovered;
        if (!runs[i].check.min_distance_ok) s->min_distance_ok = 0;
        if (runs[i].check.min_distance < s->min_distance) s->min_distance = runs[i].check.min_distance;
    }
    s->seconds = median(seconds, n);
    s->points = median(points, n);
    s->instructions_per_point = counted ? median(instructions, n) / s->points : -1.0;
    s->peak_bytes_per_point = 1024.0 * (double)(peak - empty_kib) / s->points;
    /* Pooled over the repeats' patterns; binomial, so conservative for a
     * jittered (stratified) probe set. */
    p = probes > 0 ? (double)uncovered / (double)probes : 0.0;
    s->uncovered_fraction = p;
    s->uncovered_stderr = probes > 0 ? sqrt(p * (1.0 - p) / (double)probes) : 0.0;
}

static double ns_per_point(const struct summary *s) { return 1e9 * s->seconds / s->points; }

static double ns_per_n_log_n(const struct summary *s) {
    return s->points > 1.0 ? 1e9 * s->seconds / (s->points * log2(s->points)) : NAN;
}

/* ---- output ------------------------------------------------------------------------ */

/* The median over the seeds of runs a's time over runs b's, seed by seed. */
static double paired_ratio(const struct run_record *a, const struct run_record *b, int n) {
    double ratios[MAX_REPEATS];
    int i;
    for (i = 0; i < n; ++i) ratios[i] = a[i].seconds / b[i].seconds;
    return median(ratios, n);
}

/* The paired line: each method against the library, and the parallel
 * process on one thread against all, when those ran. */
static void print_paired(FILE *out, const struct options *opt, size_t target,
                         struct run_record runs[METHOD_COUNT][MAX_REPEATS]) {
    const char *const lead = "paired, the median of each seed's ratio:";
    int m, any = 0;
    if (opt->use_method[METHOD_POISSONDISK]) {
        for (m = 0; m < METHOD_COUNT; ++m) {
            if (m == METHOD_POISSONDISK || !opt->use_method[m]) continue;
            if (!any) fprintf(out, "%-11s %9zu  %s", "", target, lead);
            any = 1;
            fprintf(out, "  %s/poissondisk %.2f", method_name[m],
                    paired_ratio(runs[m], runs[METHOD_POISSONDISK], opt->repeats));
        }
    }
    if (opt->use_method[METHOD_THREADS1] && opt->use_method[METHOD_THREADS]) {
        if (!any) fprintf(out, "%-11s %9zu  %s", "", target, lead);
        any = 1;
        fprintf(out, "  threads1/threads %.2f",
                paired_ratio(runs[METHOD_THREADS1], runs[METHOD_THREADS], opt->repeats));
    }
    if (any) fprintf(out, "\n");
}

static void print_header(FILE *out, const struct options *opt, const char *instruction_source) {
    fprintf(out,
            "poissondisk %s bench: maximal patterns in the unit square, R = sqrt(0.6966/N), "
            "median of %d run%s, the methods in turn for each seed\n",
            pds_version_string(), opt->repeats, opt->repeats == 1 ? "" : "s");
    fprintf(out, "baselines: bridson k=%d; dart stops after %lu misses in a row\n",
            BRIDSON_CANDIDATES, opt->dart_misses);
    fprintf(out, "instructions: %s\n", instruction_source);
    fprintf(out, "%-11s %9s %9s %9s %9s %9s %9s %8s %9s  %-21s %s\n", "method", "N", "points", "R",
            "seconds", "ns/point", "ns/NlogN", "B/point", "instr/pt", "uncovered (+/- se)",
            "min dist");
}

static void print_row(FILE *out, const struct summary *s) {
    char instructions[32], uncovered[48];
    if (s->instructions_per_point >= 0.0)
        snprintf(instructions, sizeof instructions, "%.0f", s->instructions_per_point);
    else
        snprintf(instructions, sizeof instructions, "-");
    if (s->uncovered_fraction > 0.0)
        snprintf(uncovered, sizeof uncovered, "%.3e +/- %.1e", s->uncovered_fraction,
                 s->uncovered_stderr);
    else
        snprintf(uncovered, sizeof uncovered, "0");
    fprintf(out, "%-11s %9zu %9.0f %9.6f %9.4f %9.1f %9.2f %8.1f %9s  %-21s %s %.4fR\n",
            method_name[s->method], s->target, s->points, s->radius, s->seconds, ns_per_point(s),
            ns_per_n_log_n(s), s->peak_bytes_per_point, instructions, uncovered,
            s->min_distance_ok ? "ok" : "FAIL", s->min_distance / s->radius);
}

static int write_csv(const char *path, const struct summary *rows, int n) {
    FILE *f = strcmp(path, "-") == 0 ? stdout : fopen(path, "w");
    int i, failed;
    if (f == NULL) return -1;
    fprintf(f, "method,N_target,N_points,radius,seconds_median,ns_per_point,ns_per_NlogN,"
               "peak_bytes_per_point,instructions_per_point,uncovered_fraction,uncovered_stderr,"
               "min_distance_ok\n");
    for (i = 0; i < n; ++i) {
        const struct summary *s = &rows[i];
        fprintf(f, "%s,%zu,%.0f,%.9g,%.6g,%.6g,%.6g,%.6g,", method_name[s->method], s->target,
                s->points, s->radius, s->seconds, ns_per_point(s), ns_per_n_log_n(s),
                s->peak_bytes_per_point);
        if (s->instructions_per_point >= 0.0) fprintf(f, "%.6g", s->instructions_per_point);
        fprintf(f, ",%.6e,%.3e,%d\n", s->uncovered_fraction, s->uncovered_stderr,
                s->min_distance_ok);
    }
    failed = ferror(f) || fflush(f) != 0;
    if (f != stdout && fclose(f) != 0) failed = 1;
    return failed ? -1 : 0;
}

static int write_svg(const char *path, const struct summary *rows, int n, int repeats) {
    double x[METHOD_COUNT][MAX_SIZES], y[METHOD_COUNT][MAX_SIZES];
    struct plot_series series[METHOD_COUNT];
    size_t count[METHOD_COUNT] = {0}, used = 0;
    char title[160];
    int i, m;
    for (i = 0; i < n; ++i) {
        m = (int)rows[i].method;
        x[m][count[m]] = rows[i].points;
        y[m][count[m]] = ns_per_n_log_n(&rows[i]);
        ++count[m];
    }
    for (m = 0; m < METHOD_COUNT; ++m) {
        if (count[m] == 0) continue;
        series[used].name = method_name[m];
        series[used].color = method_color[m];
        series[used].x = x[m];
        series[used].y = y[m];
        series[used].count = count[m];
        ++used;
    }
    snprintf(title, sizeof title, "poissondisk %s: time / (N log2 N), unit square, median of %d",
             pds_version_string(), repeats);
    return plot_svg_write(path, title, "N (points)", "ns / (N log2 N)", series, used);
}

/* ---- arguments --------------------------------------------------------------------- */

static int usage_error(const char *what, const char *text) {
    fprintf(stderr, PROG ": %s '%s'\n%s", what, text, usage_text);
    return 2;
}

/* "--name VALUE" or "--name=VALUE": sets *value and advances *i; 0 if argv[*i]
 * is not this option. */
static int option_value(int argc, char **argv, int *i, const char *name, const char **value) {
    size_t len = strlen(name);
    if (strncmp(argv[*i], name, len) != 0) return 0;
    if (argv[*i][len] == '=') {
        *value = argv[*i] + len + 1;
        return 1;
    }
    if (argv[*i][len] != '\0') return 0;
    *value = *i + 1 < argc ? argv[++*i] : NULL;
    return 1;
}

static int parse_methods(const char *list, int *use) {
    char buffer[128], *token, *rest;
    int m, any = 0;
    if (strlen(list) >= sizeof buffer) return -1;
    strcpy(buffer, list);
    for (m = 0; m < METHOD_COUNT; ++m) use[m] = 0;
    for (token = strtok_r(buffer, ",", &rest); token != NULL; token = strtok_r(NULL, ",", &rest)) {
        for (m = 0; m < METHOD_COUNT; ++m)
            if (strcmp(token, method_name[m]) == 0) break;
        if (m == METHOD_COUNT) return -1;
        use[m] = any = 1;
    }
    return any ? 0 : -1;
}

static int parse_args(int argc, char **argv, struct options *opt) {
    int i, m;
    memset(opt, 0, sizeof *opt);
    opt->repeats = 3;
    opt->dart_misses = DART_DEFAULT_MISSES;
    opt->chunked = -1;
    for (m = 0; m < METHOD_COUNT; ++m) opt->use_method[m] = 1;
    for (i = 1; i < argc; ++i) {
        const char *value = NULL;
        char *end;
        if (strcmp(argv[i], "--help") == 0) {
            fputs(usage_text, stdout);
            exit(0);
        } else if (strcmp(argv[i], "--callgrind") == 0) {
            opt->callgrind = 1;
        } else if (option_value(argc, argv, &i, "--repeats", &value)) {
            long k = value != NULL ? strtol(value, &end, 10) : 0;
            if (value == NULL || *end != '\0' || k < 1 || k > MAX_REPEATS)
                return usage_error("--repeats wants 1..99, not", value != NULL ? value : "");
            opt->repeats = (int)k;
        } else if (option_value(argc, argv, &i, "--methods", &value)) {
            if (value == NULL || parse_methods(value, opt->use_method) != 0)
                return usage_error("--methods: unknown list", value != NULL ? value : "");
        } else if (option_value(argc, argv, &i, "--csv", &value)) {
            /* A bare --csv (last, or before another option) means stdout. */
            if (value == NULL || (value[0] == '-' && value[1] == '-')) {
                if (value != NULL) --i;
                value = "-";
            }
            opt->csv_path = value;
        } else if (option_value(argc, argv, &i, "--svg", &value)) {
            if (value == NULL || value[0] == '\0') return usage_error("--svg wants a file name", "");
            opt->svg_path = value;
        } else if (option_value(argc, argv, &i, "--dart-misses", &value)) {
            unsigned long f = value != NULL ? strtoul(value, &end, 10) : 0;
            if (value == NULL || *end != '\0' || f < 1 || value[0] == '-')
                return usage_error("--dart-misses wants a positive integer, not",
                                   value != NULL ? value : "");
            opt->dart_misses = f;
        } else if (option_value(argc, argv, &i, "--chunked", &value)) {
            double n = value != NULL ? strtod(value, &end) : -1.0;
            if (value == NULL || *end != '\0' || end == value || n != floor(n) ||
                !(n == 0.0 || (n >= 10.0 && n <= 1e9)))
                return usage_error("--chunked wants 0 or a whole number from 10 to 1e9, not",
                                   value != NULL ? value : "");
            opt->chunked = (long)n;
        } else if (argv[i][0] == '-') {
            return usage_error("unknown option", argv[i]);
        } else {
            /* A size: 10000, 1e5, ... a whole number of points, 10 .. 10^9. */
            double n = strtod(argv[i], &end);
            if (*end != '\0' || end == argv[i] || !(n >= 10.0 && n <= 1e9) || n != floor(n))
                return usage_error("a size must be a whole number from 10 to 1e9, not", argv[i]);
            if (opt->target_count == MAX_SIZES) return usage_error("too many sizes at", argv[i]);
            opt->targets[opt->target_count++] = (size_t)n;
        }
    }
    if (opt->target_count == 0) {
        static const size_t defaults[] = {10000, 100000, 1000000, 10000000};
        for (i = 0; i < 4; ++i) opt->targets[i] = defaults[i];
        opt->target_count = 4;
    }
    return 0;
}

/* ---- main -------------------------------------------------------------------------- */

int main(int argc, char **argv) {
    static struct summary rows[MAX_SIZES * METHOD_COUNT];
    static struct run_record runs[METHOD_COUNT][MAX_REPEATS];
    struct options opt;
    struct run_record empty;
    long empty_kib[METHOD_COUNT] = {0};
    struct perf_counter probe;
    const char *instruction_source;
    FILE *out;
    int row_count = 0, failures = 0, k, m, r, rc;

    if (argc == 2 && strcmp(argv[1], "--self-test") == 0) return pattern_check_self_test(stdout);
    if (argc >= 2 && strcmp(argv[1], "--single") == 0) {
        rc = single_run(argc, argv, 2);
        if (rc == 2) fprintf(stderr, "usage: " PROG " --single METHOD RADIUS DART_MISSES\n");
        return rc;
    }
    rc = parse_args(argc, argv, &opt);
    if (rc != 0) return rc;
    out = opt.csv_path != NULL && strcmp(opt.csv_path, "-") == 0 ? stderr : stdout;

    if (opt.callgrind) {
        instruction_source = "callgrind (user space, seed 1)";
    } else if (perf_counter_open(&probe) == 0) {
        perf_counter_close(&probe);
        instruction_source = "perf_event_open, user space";
    } else {
        instruction_source = "not counted: perf_event_open refused the hardware counter "
                             "(no PMU on this machine?); try --callgrind";
    }

    /* Each method's run at R = 0.5 (a handful of points): the process's own
     * memory, code pages of that method included, subtracted from its peaks. */
    for (m = 0; m < METHOD_COUNT; ++m) {
        if (!opt.use_method[m]) continue;
        empty = measure((enum method)m, 0.5, 1, &opt, 1);
        if (!empty.ok) {
            fprintf(stderr, PROG ": empty %s run failed: %s\n", method_name[m], empty.error);
            return 1;
        }
        empty_kib[m] = empty.peak_kib;
    }
    print_header(out, &opt, instruction_source);

    for (k = 0; k < opt.target_count; ++k) {
        size_t target = opt.targets[k];
        double radius = sqrt(SATURATION_AREA / (double)target), ours_seconds = -1.0;
        uint32_t probe_side = pattern_probe_side(target);
        int first_row = row_count;
        for (r = 0; r < opt.repeats; ++r)
            for (m = 0; m < METHOD_COUNT; ++m) {
                if (!opt.use_method[m]) continue;
                runs[m][r] = measure((enum method)m, radius, (uint64_t)r + 1, &opt, probe_side);
                if (!runs[m][r].ok) {
                    fprintf(stderr, PROG ": %s at N=%zu, seed %d failed: %s\n", method_name[m], target, r + 1,
                            runs[m][r].error);
                    return 1;
                }
            }
        for (m = 0; m < METHOD_COUNT; ++m) {
            struct summary *s = &rows[row_count];
            if (!opt.use_method[m]) continue;
            s->method = (enum method)m;
            s->target = target;
            s->radius = radius;
            summarize(s, runs[m], opt.repeats, empty_kib[m]);
            if (opt.callgrind) s->instructions_per_point = callgrind_instructions_per_point(
                                   (enum method)m, radius, opt.dart_misses);
            print_row(out, s);
            fflush(out);
            if (!s->min_distance_ok) {
                fprintf(stderr, PROG ": %s at N=%zu: two points closer than R (%.6gR)\n",
                        method_name[m], target, s->min_distance / radius);
                ++failures;
            }
            if (m == METHOD_POISSONDISK) {
                ours_seconds = s->seconds;
                if (s->uncovered_fraction > 0.0) {
                    fprintf(stderr, PROG ": poissondisk at N=%zu is not maximal\n", target);
                    ++failures;
                }
            }
            ++row_count;
        }
        if (ours_seconds > 0.0 && row_count - first_row > 1) {
            int i;
            fprintf(out, "%-11s %9zu  time relative to poissondisk:", "", target);
            for (i = first_row; i < row_count; ++i)
                if (rows[i].method != METHOD_POISSONDISK)
                    fprintf(out, "  %s %.2f", method_name[rows[i].method],
                            rows[i].seconds / ours_seconds);
            fprintf(out, "\n");
        }
        print_paired(out, &opt, target, runs);
    }

    if (opt.chunked < 0) {
        opt.chunked = 0;
        for (k = 0; k < opt.target_count; ++k)
            if ((long)opt.targets[k] > opt.chunked) opt.chunked = (long)opt.targets[k];
        if (opt.chunked > 100000) opt.chunked = 100000;
    }
    if (opt.chunked > 0 && opt.use_method[METHOD_POISSONDISK] &&
        chunked_bench(out, (size_t)opt.chunked, opt.repeats) != 0)
        ++failures;

    if (opt.csv_path != NULL && write_csv(opt.csv_path, rows, row_count) != 0) {
        fprintf(stderr, PROG ": cannot write %s\n", opt.csv_path);
        return 1;
    }
    if (opt.svg_path != NULL && write_svg(opt.svg_path, rows, row_count, opt.repeats) != 0) {
        fprintf(stderr, PROG ": cannot write %s\n", opt.svg_path);
        return 1;
    }
    return failures > 0 ? 1 : 0;
}
