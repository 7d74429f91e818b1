/*
 * poissondisk - command-line front end to libpoissondisk.
 *
 * Generates a maximal Poisson-disk pattern and writes one "x y" line per
 * point to stdout, in insertion order, with %.17g so every value reads back
 * as exactly the same double. Optional refinement stages (--refine) continue
 * the same pattern at smaller radii; --max-points caps the total.
 *
 * This file uses only the public header, like any other client would, so it
 * doubles as a worked example of the C API. It is plain C99 plus
 * clock_gettime() from POSIX.
 *
 * Exit status: 0 success, 1 library or output failure, 2 bad arguments.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "poissondisk.h"

#define PROG "poissondisk"

enum { EXIT_LIBRARY = 1, EXIT_USAGE = 2 };

/* Points fetched per pds_points() call when writing: bounded memory for any N. */
#define CHUNK_POINTS 4096

static const char usage_line[] =
    "usage: " PROG " --radius R [--seed S] [--domain X0 Y0 X1 Y1] [--refine R2]...\n"
    "                   [--max-points N] [--verify] [--stats] [--help] [--version]\n";

static const char help_text[] =
    "Write a maximal Poisson-disk point pattern to standard output, one\n"
    "\"x y\" line per point in insertion order (%.17g: values round-trip exactly).\n"
    "\n"
    "  --radius R             minimum distance between points (required, > 0)\n"
    "  --seed S               random seed, unsigned 64-bit decimal (default 1)\n"
    "  --domain X0 Y0 X1 Y1   sample the rectangle [X0,X1]x[Y0,Y1]\n"
    "                         (default the unit square 0 0 1 1)\n"
    "  --refine R2            when the pattern is maximal, continue at the smaller\n"
    "                         radius R2 keeping every point; may be repeated, each\n"
    "                         R2 no larger than the radius before it\n"
    "  --max-points N         stop after N points in total (N > 0); the pattern\n"
    "                         may then not be maximal\n"
    "  --verify               re-check the final pattern independently; exit 1 if\n"
    "                         the check fails\n"
    "  --stats                print a one-line summary to standard error\n"
    "  --help                 print this help and exit\n"
    "  --version              print the library version and exit\n"
    "\n"
    "Options taking a value accept both '--opt VALUE' and '--opt=VALUE'.\n"
    "Exit status: 0 success, 1 library or output error, 2 bad arguments.\n";

struct options {
    double radius;
    int have_radius;
    uint64_t seed;
    double domain[4]; /* x0 y0 x1 y1 */
    int have_domain;
    double *refine;   /* the --refine radii in command-line order */
    size_t nrefine;
    size_t max_points; /* 0: no cap (the option itself rejects 0) */
    int verify;
    int stats;
};

/* Report a bad argument (printf-style), then the short usage; gives exit status 2. */
static int usage_error(const char *fmt, ...)
{
    va_list ap;

    fputs(PROG ": ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    fputs(usage_line, stderr);
    fputs("Try '" PROG " --help' for more information.\n", stderr);
    return EXIT_USAGE;
}

/*
 * Parse a finite double that fills the whole string. strtod() alone would
 * accept leading blanks, trailing junk, "nan" and "inf", so check all of it.
 */
static int parse_double(const char *text, double *out)
{
    char *end;
    double v;

    if (text[0] == '\0' || text[0] == ' ' || (text[0] >= '\t' && text[0] <= '\r'))
        return -1;
    v = strtod(text, &end);
    if (*end != '\0' || !isfinite(v))
        return -1;
    /* Overflow gives +-HUGE_VAL (caught above); underflow is harmless here. */
    *out = v;
    return 0;
}

/* Parse a decimal unsigned 64-bit integer: digits only, no sign, no overflow. */
static int parse_u64(const char *text, uint64_t *out)
{
    char *end;
    unsigned long long v;

    /* strtoull() would silently negate "-5" and skip blanks: allow digits only. */
    if (text[0] < '0' || text[0] > '9')
        return -1;
    errno = 0;
    v = strtoull(text, &end, 10);
    /* The last test matters only where unsigned long long is wider than 64 bits. */
    if (*end != '\0' || errno == ERANGE || v > (unsigned long long)UINT64_MAX)
        return -1;
    *out = (uint64_t)v;
    return 0;
}

/*
 * The value of an option: the text after '=' in "--opt=VALUE", else the next
 * argument (taken as is, so "--radius -1" reaches the range check). NULL when
 * there is none.
 */
static const char *take_value(int argc, char **argv, int *i, const char *eq)
{
    if (eq != NULL)
        return eq + 1;
    if (*i + 1 >= argc)
        return NULL;
    *i += 1;
    return argv[*i];
}

/* parse_args() result meaning "all done, exit 0" (after --help or --version). */
#define PARSE_DONE (-1)

/* Returns 0 to go on, PARSE_DONE, or an exit status. */
static int parse_args(int argc, char **argv, struct options *o)
{
    static const char *const count_words[] = { "none", "one", "two", "three" };
    int i;

    /* At most one --refine per two arguments; argc bounds them all. */
    o->refine = malloc((size_t)argc * sizeof *o->refine);
    if (o->refine == NULL) {
        fputs(PROG ": out of memory\n", stderr);
        return EXIT_LIBRARY;
    }
    for (i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *eq = strchr(arg, '=');
        size_t namelen = eq != NULL ? (size_t)(eq - arg) : strlen(arg);
        const char *val;
        char name[16];

        if (arg[0] != '-')
            return usage_error("unexpected argument '%s'", arg);
        if (namelen >= sizeof name)
            return usage_error("unknown option '%s'", arg);
        memcpy(name, arg, namelen);
        name[namelen] = '\0';

        /* Flags: no value allowed. */
        if (strcmp(name, "--help") == 0 || strcmp(name, "--version") == 0
            || strcmp(name, "--verify") == 0 || strcmp(name, "--stats") == 0) {
            if (eq != NULL)
                return usage_error("option %s takes no value, got '%s'", name, eq + 1);
            if (strcmp(name, "--help") == 0) {
                printf("%s\n%s", usage_line, help_text);
                return fflush(stdout) == 0 ? PARSE_DONE : EXIT_LIBRARY;
            }
            if (strcmp(name, "--version") == 0) {
                printf(PROG " %s\n", pds_version_string());
                return fflush(stdout) == 0 ? PARSE_DONE : EXIT_LIBRARY;
            }
            if (strcmp(name, "--verify") == 0)
                o->verify = 1;
            else
                o->stats = 1;
            continue;
        }

        if (strcmp(name, "--radius") != 0 && strcmp(name, "--seed") != 0
            && strcmp(name, "--domain") != 0 && strcmp(name, "--refine") != 0
            && strcmp(name, "--max-points") != 0)
            return usage_error("unknown option '%s'", arg);

        val = take_value(argc, argv, &i, eq);
        if (val == NULL)
            return usage_error("option %s needs a value", name);

        if (strcmp(name, "--radius") == 0 || strcmp(name, "--refine") == 0) {
            double r;
            if (parse_double(val, &r) != 0 || !(r > 0))
                return usage_error("%s: expected a finite number > 0, got '%s'", name, val);
            if (strcmp(name, "--radius") == 0) {
                o->radius = r;
                o->have_radius = 1;
            } else {
                o->refine[o->nrefine++] = r;
            }
        } else if (strcmp(name, "--seed") == 0) {
            if (parse_u64(val, &o->seed) != 0)
                return usage_error("--seed: expected an unsigned 64-bit decimal "
                                   "integer, got '%s'", val);
        } else if (strcmp(name, "--max-points") == 0) {
            uint64_t n;
            if (parse_u64(val, &n) != 0 || n == 0 || n > SIZE_MAX)
                return usage_error("--max-points: expected a positive integer, "
                                   "got '%s'", val);
            o->max_points = (size_t)n;
        } else { /* --domain X0 Y0 X1 Y1; with '=' the first value is glued on */
            int k;
            for (k = 0; k < 4; k++) {
                if (k > 0) {
                    /* Stop at the end or at the next option ("--x" is no number). */
                    if (i + 1 >= argc || strncmp(argv[i + 1], "--", 2) == 0)
                        return usage_error("--domain needs four values X0 Y0 X1 Y1, "
                                           "got %s", count_words[k]);
                    val = argv[++i];
                }
                if (parse_double(val, &o->domain[k]) != 0)
                    return usage_error("--domain: expected a finite number, got '%s'",
                                       val);
            }
            o->have_domain = 1;
        }
    }
    if (!o->have_radius)
        return usage_error("option --radius is required");
    return 0;
}

static double now_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int library_error(const char *what, double value, const char *msg)
{
    fprintf(stderr, PROG ": %s %g: %s\n", what, value, msg);
    return EXIT_LIBRARY;
}

/* Write every point, CHUNK_POINTS at a time. Returns 0 or -1 on a write error. */
static int write_points(const pds_sampler *s)
{
    static double xy[2 * CHUNK_POINTS];
    size_t first = 0, got, k;

    while ((got = pds_points(s, first, CHUNK_POINTS, xy)) > 0) {
        for (k = 0; k < got; k++)
            if (printf("%.17g %.17g\n", xy[2 * k], xy[2 * k + 1]) < 0)
                return -1;
        first += got;
    }
    return fflush(stdout) == 0 && !ferror(stdout) ? 0 : -1;
}

/*
 * Run stage after stage: the initial radius, then each --refine radius.
 * *maximal tells whether the last run reached maximality.
 */
static int sample(pds_sampler *s, const struct options *o, int *maximal)
{
    size_t total = 0, stage;
    int rc;

    *maximal = 0;
    for (stage = 0; stage <= o->nrefine; stage++) {
        if (stage > 0) {
            rc = pds_refine(s, o->refine[stage - 1]);
            if (rc < 0)
                return library_error("cannot refine to radius", o->refine[stage - 1],
                                     pds_errmsg(s));
        }
        /* Once the cap is used up, later stages only lower the radius. */
        if (o->max_points == 0 || total < o->max_points) {
            size_t added = 0;
            size_t max_new = o->max_points == 0 ? 0 : o->max_points - total;
            rc = pds_run(s, max_new, &added);
            total += added;
            if (rc < 0)
                return library_error("sampling failed at radius", pds_radius(s),
                                     pds_errmsg(s));
            *maximal = rc == 0;
        } else {
            /* No run at this radius: maximal only if nothing is left free. */
            *maximal = pds_free_area(s) == 0.0;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    /* Full buffering in large blocks: 10^6 lines must not mean 10^6 writes. */
    static char outbuf[1 << 20];
    struct options o;
    pds_sampler *s = NULL;
    int status, rc, maximal = 0, verified = 0;
    double t0, seconds;

    memset(&o, 0, sizeof o);
    o.seed = 1;
    o.domain[0] = 0.0; o.domain[1] = 0.0; o.domain[2] = 1.0; o.domain[3] = 1.0;
    setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);

    status = parse_args(argc, argv, &o);
    if (status == PARSE_DONE)
        status = EXIT_SUCCESS;
    if (status != 0 || !o.have_radius)
        goto done;

    t0 = now_seconds();
    rc = pds_create(&s, o.radius, o.seed);
    if (rc < 0) {
        /* No handle, so no pds_errmsg(): the code's text is all there is. */
        status = library_error("cannot create a sampler with radius", o.radius,
                               pds_strerror(rc));
        goto done;
    }
    if (o.have_domain) {
        rc = pds_set_domain(s, o.domain[0], o.domain[1], o.domain[2], o.domain[3]);
        if (rc < 0) {
            fprintf(stderr, PROG ": cannot set domain [%g,%g]x[%g,%g]: %s\n",
                    o.domain[0], o.domain[2], o.domain[1], o.domain[3], pds_errmsg(s));
            status = EXIT_LIBRARY;
            goto done;
        }
    }
    status = sample(s, &o, &maximal);
    if (status != 0)
        goto done;
    seconds = now_seconds() - t0;

    /* Verify before writing, so a failed check leaves no plausible output. */
    if (o.verify) {
        rc = pds_verify(s);
        if (rc < 0) {
            fprintf(stderr, PROG ": verification failed: %s\n", pds_errmsg(s));
            status = EXIT_LIBRARY;
            goto done;
        }
        verified = 1;
        maximal = rc == 0; /* exact, so it overrides the running answer */
    }

    if (write_points(s) != 0) {
        fprintf(stderr, PROG ": error writing points: %s\n", strerror(errno));
        status = EXIT_LIBRARY;
        goto done;
    }

    if (o.stats) {
        double area = (o.domain[2] - o.domain[0]) * (o.domain[3] - o.domain[1]);
        fprintf(stderr, PROG ": N=%zu R=%g domain=[%g,%g]x[%g,%g] coverage=%.9f %s%s"
                " %.3f s\n", pds_count(s), pds_radius(s),
                o.domain[0], o.domain[2], o.domain[1], o.domain[3],
                1.0 - pds_free_area(s) / area, maximal ? "maximal" : "not maximal",
                verified ? " verified" : "", seconds);
    }

done:
    pds_destroy(s);
    free(o.refine);
    return status;
}
