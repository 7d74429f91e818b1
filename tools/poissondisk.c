/*
 * poissondisk - command-line front end to libpoissondisk.
 *
 * Generates a maximal Poisson-disk pattern and writes one "x y" line per
 * point to stdout, in insertion order, with %.17g so every value reads back
 * as exactly the same double. Optional refinement stages (--refine) continue
 * the same pattern at smaller radii; --max-points caps the total.
 *
 * The options live in one table (option_list[] below); cli_options.c makes
 * the parsing, the defaults, the usage line and the --help text from it, so
 * they cannot disagree. Arguments are read left to right; --help or
 * --version prints and ends the program there, without sampling.
 *
 * The library is used through the public header only, like any client, so it
 * doubles as a worked example of the C API. It is plain C99 plus
 * clock_gettime() from POSIX.
 *
 * Exit status: 0 success, 1 library or output failure, 2 bad arguments,
 * including values only the library can judge (PDS_EINVAL, PDS_ERANGE).
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "poissondisk.h"

#include "cli_options.h"

/* Named results of pds_run/pds_verify (1.1.1); the values are those of 1.0. */
#ifndef PDS_DONE
#define PDS_DONE 0
#endif
#ifndef PDS_MORE
#define PDS_MORE 1
#endif

#define PROG "poissondisk"

enum { EXIT_LIBRARY = 1, EXIT_USAGE = CLI_EXIT_USAGE };
enum action { ACT_SAMPLE, ACT_HELP, ACT_VERSION };

/* Points fetched per pds_points() call when writing: bounded memory for any N. */
#define CHUNK_POINTS 4096

struct options {
    double radius;
    uint64_t seed;
    double domain[4];  /* x0 y0 x1 y1 */
    double *refine;    /* the --refine radii in command-line order */
    size_t nrefine;
    size_t max_points; /* 0: no cap (the option itself rejects 0) */
    int verify;
    int stats;
    enum action action;
};

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

/* Handlers: store an option's values (see cli_options.h). */

static int parse_radius(const char *text, double *out)
{
    return parse_double(text, out) == 0 && *out > 0 ? CLI_OK : CLI_BAD(0);
}

static int opt_radius(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    return parse_radius(v[0], &((struct options *)ctx)->radius);
}

static int opt_refine(void *ctx, const struct cli_option *opt, const char *const *v)
{
    struct options *o = ctx;
    (void)opt;
    return parse_radius(v[0], &o->refine[o->nrefine++]);
}

static int opt_seed(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    return parse_u64(v[0], &((struct options *)ctx)->seed) == 0 ? CLI_OK : CLI_BAD(0);
}

static int opt_max_points(void *ctx, const struct cli_option *opt, const char *const *v)
{
    uint64_t n;

    (void)opt;
    if (parse_u64(v[0], &n) != 0 || n == 0 || n > SIZE_MAX)
        return CLI_BAD(0);
    ((struct options *)ctx)->max_points = (size_t)n;
    return CLI_OK;
}

/* Only the numbers are checked here; the library judges the rectangle. */
static int opt_domain(void *ctx, const struct cli_option *opt, const char *const *v)
{
    int k;

    (void)opt;
    for (k = 0; k < 4; k++)
        if (parse_double(v[k], &((struct options *)ctx)->domain[k]) != 0)
            return CLI_BAD(k);
    return CLI_OK;
}

static int opt_verify(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt, (void)v;
    ((struct options *)ctx)->verify = 1;
    return CLI_OK;
}

static int opt_stats(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt, (void)v;
    ((struct options *)ctx)->stats = 1;
    return CLI_OK;
}

static int opt_help(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt, (void)v;
    ((struct options *)ctx)->action = ACT_HELP;
    return CLI_STOP;
}

static int opt_version(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt, (void)v;
    ((struct options *)ctx)->action = ACT_VERSION;
    return CLI_STOP;
}

/* The one list of options: parsing, defaults, usage and --help come from it. */
static const struct cli_option option_list[] = {
    { "--radius", 1, "R", CLI_REQUIRED, NULL, opt_radius, "a finite number > 0",
      "minimum distance between points, a finite number > 0" },
    { "--seed", 1, "S", 0, "1", opt_seed, "an unsigned 64-bit decimal integer",
      "random seed, an unsigned 64-bit decimal integer" },
    { "--domain", 4, "X0 Y0 X1 Y1", 0, "0 0 1 1", opt_domain, "a finite number",
      "sample the rectangle [X0,X1]x[Y0,Y1] instead of the unit square" },
    { "--refine", 1, "R2", CLI_REPEAT, NULL, opt_refine, "a finite number > 0",
      "when the pattern is maximal, continue at the smaller radius R2 keeping every "
      "point; may be repeated, each R2 no larger than the radius before it" },
    { "--max-points", 1, "N", 0, NULL, opt_max_points, "a positive integer",
      "stop after N points in total (N > 0); the pattern may then not be maximal" },
    { "--verify", 0, NULL, 0, NULL, opt_verify, NULL,
      "re-check the final pattern independently; exit 1 if the check fails" },
    { "--stats", 0, NULL, 0, NULL, opt_stats, NULL,
      "print a one-line summary to standard error" },
    { "--help", 0, NULL, CLI_ALONE, NULL, opt_help, NULL, "print this help and exit" },
    { "--version", 0, NULL, CLI_ALONE, NULL, opt_version, NULL,
      "print the library version and exit" },
};

static const struct cli_table cli = {
    PROG, option_list, sizeof option_list / sizeof option_list[0],
    "Write a maximal Poisson-disk point pattern to standard output, one\n"
    "\"x y\" line per point in insertion order (%.17g: values round-trip exactly).\n",
    "Options taking a value accept both '--opt VALUE' and '--opt=VALUE'.\n"
    "--help and --version end the command line: they print, exit 0 and sample\n"
    "nothing; the arguments after them are not read.\n"
    "Exit status: 0 success, 1 library or output error, 2 bad arguments, also\n"
    "when the library rejects a value (an empty --domain, or a radius too small\n"
    "for the domain).\n",
};

/* Returns 0 to go on, CLI_STOP (--help, --version), or an exit status. */
static int parse_args(int argc, char **argv, struct options *o)
{
    size_t k;
    int rc;

    /* At most one --refine per two arguments; argc bounds them all. */
    o->refine = malloc((size_t)argc * sizeof *o->refine);
    if (o->refine == NULL) {
        fputs(PROG ": out of memory\n", stderr);
        return EXIT_LIBRARY;
    }
    if ((rc = cli_parse(&cli, argc, argv, o)) != 0)
        return rc;
    /* Checked now rather than by pds_refine once the earlier stages ran. */
    for (k = 0; k < o->nrefine; k++) {
        double before = k == 0 ? o->radius : o->refine[k - 1];
        if (o->refine[k] > before)
            return cli_usage_error(&cli, "--refine %g is larger than the radius before it, %g",
                                   o->refine[k], before);
    }
    return 0;
}

static double now_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/*
 * Report a failed library call and give the exit status. An argument the
 * library rejects (PDS_EINVAL) or a radius too small for the domain
 * (PDS_ERANGE) came from the command line: status 2; anything else: 1.
 */
static int range_error(const struct options *o, double radius, const char *msg)
{
    fprintf(stderr, PROG ": radius %g is too small for the domain [%g,%g]x[%g,%g]: %s\n",
            radius, o->domain[0], o->domain[2], o->domain[1], o->domain[3], msg);
    return EXIT_USAGE;
}

static int library_error(const struct options *o, int rc, const char *what, double value,
                         const char *msg)
{
    if (rc == PDS_ERANGE)
        return range_error(o, value, msg);
    fprintf(stderr, PROG ": %s %g: %s\n", what, value, msg);
    return rc == PDS_EINVAL ? EXIT_USAGE : EXIT_LIBRARY;
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
 * *maximal tells whether the last run reached maximality. Returns an exit status.
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
                return library_error(o, rc, "cannot refine to radius", o->refine[stage - 1],
                                     pds_errmsg(s));
        }
        /* Once the cap is used up, later stages only lower the radius. */
        if (o->max_points == 0 || total < o->max_points) {
            size_t added = 0;
            size_t max_new = o->max_points == 0 ? 0 : o->max_points - total;
            rc = pds_run(s, max_new, &added);
            total += added;
            if (rc != PDS_DONE && rc != PDS_MORE) /* PDS_EINVAL would be our bug */
                return library_error(o, rc == PDS_EINVAL ? PDS_EINTERNAL : rc,
                                     "sampling failed at radius", pds_radius(s),
                                     pds_errmsg(s));
            *maximal = rc == PDS_DONE; /* PDS_MORE: the cap stopped it, room left */
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
    o.action = ACT_SAMPLE;
    setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);

    status = parse_args(argc, argv, &o);
    if (status == CLI_STOP) {
        /* --help or --version: print, and never go on to sample. */
        if (o.action == ACT_HELP)
            cli_print_help(&cli, stdout);
        else
            printf(PROG " %s\n", pds_version_string());
        status = fflush(stdout) == 0 && !ferror(stdout) ? EXIT_SUCCESS : EXIT_LIBRARY;
        goto done;
    }
    if (status != 0)
        goto done;

    t0 = now_seconds();
    rc = pds_create(&s, o.radius, o.seed);
    if (rc < 0) {
        /* No handle, so no pds_errmsg(): the code's text is all there is. */
        status = library_error(&o, rc, "cannot create a sampler with radius", o.radius,
                               pds_strerror(rc));
        goto done;
    }
    /* Always set: the default is the unit square, the library's own default. */
    rc = pds_set_domain(s, o.domain[0], o.domain[1], o.domain[2], o.domain[3]);
    if (rc < 0) {
        if (rc == PDS_ERANGE) {
            status = range_error(&o, o.radius, pds_errmsg(s));
        } else {
            fprintf(stderr, PROG ": cannot set domain [%g,%g]x[%g,%g]: %s\n",
                    o.domain[0], o.domain[2], o.domain[1], o.domain[3], pds_errmsg(s));
            status = rc == PDS_EINVAL ? EXIT_USAGE : EXIT_LIBRARY;
        }
        goto done;
    }
    status = sample(s, &o, &maximal);
    if (status != 0)
        goto done;
    seconds = now_seconds() - t0;

    /* Verify before writing, so a failed check leaves no plausible output. */
    if (o.verify) {
        rc = pds_verify(s);
        if (rc != PDS_DONE && rc != PDS_MORE) {
            fprintf(stderr, PROG ": verification failed: %s\n", pds_errmsg(s));
            status = EXIT_LIBRARY;
            goto done;
        }
        verified = 1;
        maximal = rc == PDS_DONE; /* exact, so it overrides the running answer */
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
