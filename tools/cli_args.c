/*
 * cli_args.c - the program's options: one table (option_list[]) from which
 * cli_options.c makes the parsing, the defaults, the usage line and the
 * --help text, the handlers that store each option's values, and the checks
 * across options made once all are read.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "poissondisk.h"

#include "cli_args.h"
#include "cli_options.h"

#define PROG "poissondisk"

enum { EXIT_LIBRARY = CLI_EXIT_LIBRARY };



/* Handlers: store an option's values (see cli_options.h). */

static int parse_radius(const char *text, double *out)
{
    return cli_parse_double(text, out) == 0 && *out > 0 ? CLI_OK : CLI_BAD(0);
}

static int opt_radius(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    return parse_radius(v[0], &((struct options *)ctx)->refines.radius);
}

static int opt_refine(void *ctx, const struct cli_option *opt, const char *const *v)
{
    struct cli_refines *rf = &((struct options *)ctx)->refines;
    (void)opt;
    return parse_radius(v[0], &rf->refine[rf->nrefine++]);
}

static int opt_radius_map(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    if (v[0][0] == '\0')
        return CLI_BAD(0);
    ((struct options *)ctx)->field.path = v[0];
    return CLI_OK;
}

/* --rmin and --rmax: the radii of black and white in the map. */
static int opt_field_radius(void *ctx, const struct cli_option *opt, const char *const *v)
{
    struct cli_field *f = &((struct options *)ctx)->field;
    return parse_radius(v[0], strcmp(opt->name, "--rmin") == 0 ? &f->rmin : &f->rmax);
}

static int opt_seed(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    return cli_parse_u64(v[0], &((struct options *)ctx)->seed) == 0 ? CLI_OK : CLI_BAD(0);
}

/* --threads: 0 (one per online core) to 1024, the library's range. */
static int opt_threads(void *ctx, const struct cli_option *opt, const char *const *v)
{
    uint64_t n;

    (void)opt;
    if (cli_parse_u64(v[0], &n) != 0 || n > 1024)
        return CLI_BAD(0);
    ((struct options *)ctx)->refines.threads = (int)n;
    return CLI_OK;
}

/* A number of points: a positive integer that fits size_t. */
static int parse_points(const char *text, size_t *out)
{
    uint64_t n;

    if (cli_parse_u64(text, &n) != 0 || n == 0 || n > SIZE_MAX)
        return CLI_BAD(0);
    *out = (size_t)n;
    return CLI_OK;
}

static int opt_max_points(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    return parse_points(v[0], &((struct options *)ctx)->refines.max_points);
}

static int opt_count(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)opt;
    return parse_points(v[0], &((struct options *)ctx)->where.count);
}

/* Only the numbers are checked here; the library judges the rectangle. */
static int opt_domain(void *ctx, const struct cli_option *opt, const char *const *v)
{
    int k;

    (void)opt;
    ((struct options *)ctx)->domain_values++;
    for (k = 0; k < 4; k++)
        if (cli_parse_double(v[k], &((struct options *)ctx)->where.box[k]) != 0)
            return CLI_BAD(k);
    return CLI_OK;
}

/* --polygon, --mask, --fixed: file names, read once all options are (cli_domain.c). */
static int opt_domain_file(void *ctx, const struct cli_option *opt, const char *const *v)
{
    struct cli_domain *d = &((struct options *)ctx)->domain;

    if (v[0][0] == '\0')
        return CLI_BAD(0);
    if (strcmp(opt->name, "--polygon") == 0)
        d->polygon = v[0];
    else if (strcmp(opt->name, "--mask") == 0)
        d->mask = v[0];
    else
        d->fixed = v[0];
    return CLI_OK;
}

/* The flags, one field each; of --progress and --no-progress the last wins. */
static int opt_flag(void *ctx, const struct cli_option *opt, const char *const *v)
{
    struct options *o = ctx;

    (void)v;
    if (strcmp(opt->name, "--periodic") == 0)
        o->where.periodic = 1;
    else if (strcmp(opt->name, "--verify") == 0)
        o->verify = 1;
    else if (strcmp(opt->name, "--stats") == 0)
        o->stats = 1;
    else if (strcmp(opt->name, "--partial") == 0)
        o->partial = 1;
    else
        o->refines.progress = strcmp(opt->name, "--progress") == 0;
    return CLI_OK;
}

/* The output options: files, formats, picture sizes (cli_output_args.c). */
static int opt_output(void *ctx, const struct cli_option *opt, const char *const *v)
{
    return cli_outputs_option(&((struct options *)ctx)->out, opt->name,
                              opt->nvalues > 0 ? v[0] : NULL);
}

/* --help and --version: the action, and the end of the command line. */
static int opt_alone(void *ctx, const struct cli_option *opt, const char *const *v)
{
    (void)v;
    ((struct options *)ctx)->action = strcmp(opt->name, "--help") == 0 ? ACT_HELP : ACT_VERSION;
    return CLI_STOP;
}

/* The one list of options: parsing, defaults, usage and --help come from it. */
static const struct cli_option option_list[] = {
    { "--radius", 1, "R", CLI_ONE_OF, NULL, opt_radius, "a finite number > 0",
      "minimum distance between points, a finite number > 0" },
    { "--count", 1, "N", CLI_ONE_OF, NULL, opt_count, "a positive integer",
      "let the library choose the radius for exactly N points (N > 0), evenly "
      "spread: it starts a little above the radius whose maximal pattern holds about N "
      "(with --fixed, in the room their clearances leave) and lowers the radius by up to "
      "1% whenever the pattern is maximal with fewer; every pair is at least the final "
      "radius apart (--stats shows it); "
      "not with --refine" },
    { "--radius-map", 1, "FILE", CLI_ONE_OF, NULL, opt_radius_map, "a file name",
      "a variable radius from a grey-scale PGM image (P2 or P5; - for standard input) "
      "stretched over the domain, its top row along Y1: a point's radius is the map's "
      "at the point, linear in the grey level from --rmin (black: the densest points) "
      "to --rmax (white), bilinear between pixel centres, and each later point keeps "
      "out of every earlier point's disk; needs --rmin and --rmax; with --periodic the "
      "map spans the torus, --rmax at most half the shorter side" },
    { "--rmin", 1, "R", 0, NULL, opt_field_radius, "a finite number > 0",
      "with --radius-map, the radius of black (grey level 0), a finite number > 0" },
    { "--rmax", 1, "R", 0, NULL, opt_field_radius, "a finite number > 0",
      "with --radius-map, the radius of white (the image's maxval), at least --rmin" },
    { "--seed", 1, "S", 0, "1", opt_seed, "an unsigned 64-bit decimal integer",
      "random seed, an unsigned 64-bit decimal integer" },
    { "--domain", 4, "X0 Y0 X1 Y1", 0, "0 0 1 1", opt_domain, "a finite number",
      "sample the rectangle [X0,X1]x[Y0,Y1] instead of the unit square" },
    { "--periodic", 0, NULL, 0, NULL, opt_flag, NULL,
      "make the domain a torus: distances wrap around in x and y, the points lie in "
      "[X0,X1)x[Y0,Y1) and the pattern tiles the plane; R must not exceed half the "
      "shorter side" },
    { "--polygon", 1, "FILE", 0, NULL, opt_domain_file, "a file name",
      "sample inside a polygon instead of the rectangle: GeoJSON (a Polygon, MultiPolygon, "
      "or a Feature or FeatureCollection of those) or text, an \"x y\" line per vertex and "
      "a blank line between rings; the rings combine by the even-odd rule (holes too), the "
      "outline belongs to the domain, and the polygon's bounding box is the domain of "
      "--radius-map and the pictures; not with --domain, --mask or --periodic" },
    { "--mask", 1, "FILE", 0, NULL, opt_domain_file, "a file name",
      "sample inside the dark pixels of a grey-scale PGM image (P2 or P5): a pixel darker "
      "than mid-grey (grey level under half maxval) is inside; the image is stretched over "
      "--domain, its top row along Y1, and the domain is the union of the inside pixels' "
      "squares, exactly; not with --polygon or --periodic" },
    { "--fixed", 1, "FILE", 0, NULL, opt_domain_file, "a file name",
      "points already there, \"x y\" or \"x y clearance\" per line ('#' comments): every "
      "new point keeps at least the clearance from each (default: the radius in force "
      "there; a given one scales with the radius, as --refine or --count change it), they "
      "count for maximality, and the output holds only the new points; each must lie in "
      "the domain's bounding box; not with --periodic" },
    { "--refine", 1, "R2", CLI_REPEAT, NULL, opt_refine, "a finite number > 0",
      "when the pattern is maximal, continue at the smaller radius R2 keeping every "
      "point; may be repeated, each R2 no larger than the radius before it; with "
      "--radius-map, R2 is the new largest radius: every radius, the points' too, is "
      "scaled by R2 over the largest" },
    { "--max-points", 1, "N", 0, NULL, opt_max_points, "a positive integer",
      "stop after N points in total (N > 0); the pattern may then not be maximal" },
    { "--threads", 1, "N", 0, NULL, opt_threads, "an integer from 0 to 1024",
      "run the parallel dart process on up to N threads (0: one per online core); its "
      "points are the same, byte for byte, for every N, but not those of a run without "
      "--threads (the single-thread process, faster on one core). A one-radius "
      "rectangle, polygon, mask or torus (with --count, --refine or --fixed too) uses "
      "them, and so does a radius map (with --periodic too), but not one whose largest "
      "radius is over 16 times its smallest (one thread, the same points)" },
    { "--verify", 0, NULL, 0, NULL, opt_flag, NULL,
      "re-check the final pattern independently; exit 1 if the check fails" },
    { "--stats", 0, NULL, 0, NULL, opt_flag, NULL,
      "print a one-line summary to standard error" },
    { "--progress", 0, NULL, 0, NULL, opt_flag, NULL,
      "draw a progress line on standard error even when it is not a terminal "
      "(by default only on a terminal)" },
    { "--no-progress", 0, NULL, 0, NULL, opt_flag, NULL,
      "never draw the progress line" },
    { "--partial", 0, NULL, 0, NULL, opt_flag, NULL,
      "when interrupted (Ctrl-C), still write the points made so far, a prefix of "
      "the full output" },
    { "--format", 1, "FMT", 0, "txt", opt_output, "one of txt, csv, json, bin, npy",
      "how the points are written: txt (\"x y\" lines), csv (header x,y), json (radius, "
      "domain, periodic, count, points), bin (raw little-endian doubles x,y) or npy "
      "(NumPy, float64, shape (N, 2)); bin and npy refuse a terminal" },
    { "--output", 1, "FILE", 0, NULL, opt_output, "a file name",
      "write the points to FILE instead of standard output" },
    { "--radii", 0, NULL, 0, NULL, opt_output, NULL,
      "add each point's radius as a third value: \"x y r\" lines, csv header x,y,r, "
      "json [x, y, r], bin x,y,r triples, npy shape (N, 3); with --radius-map the "
      "radius of the map at the point, else R" },
    { "--svg", 1, "FILE", 0, NULL, opt_output, "a file name",
      "also draw the pattern as SVG: the domain's box and a dot per point, y upwards" },
    { "--disks", 0, NULL, 0, NULL, opt_output, NULL,
      "with --svg, draw each point's disk of radius R/2 (no two overlap)" },
    { "--png", 1, "FILE", 0, NULL, opt_output, "a file name",
      "also draw the points as a grey-scale PNG, black dots on white" },
    { "--dot-radius", 1, "D", 0, NULL, opt_output, "a finite number > 0",
      "the radius of the dots drawn at the points by --svg and --png, in the domain's "
      "units, the same for every point (default: R/8 in SVG, R/5 in PNG, with "
      "--radius-map the smallest radius in place of R)" },
    { "--size", 1, "PX", 0, "512", opt_output, "an integer from 1 to 16384",
      "the side of the PNG pictures in pixels (for --png the longer side; the aspect "
      "ratio is kept)" },
    { "--spectrum", 1, "FILE", 0, NULL, opt_output, "a file name",
      "write the periodogram as a PNG: f = 0 in the centre, up to 2/R, log scale from "
      "-20 dB (black) to +10 dB (white); costs N^2, use --periodic for clean spectra" },
    { "--patterns", 1, "K", 0, "1", opt_output, "an integer from 1 to 100000",
      "average the spectrum over K patterns, seeds S to S+K-1" },
    { "--spectrum-plot", 1, "FILE", 0, NULL, opt_output, "a file name",
      "write the radially averaged power and the anisotropy as an SVG plot" },
    { "--spectrum-csv", 1, "FILE", 0, NULL, opt_output, "a file name",
      "write them as CSV: frequency, frequency times R, power, anisotropy (dB), samples" },
    { "--spectrum-from", 1, "FILE", 0, NULL, opt_output, "a file name",
      "sample nothing: the spectrum of the patterns in FILE (\"x y\" lines, blank lines "
      "between patterns; - for standard input), R from --radius" },
    { "--help", 0, NULL, CLI_ALONE, NULL, opt_alone, NULL, "print this help and exit" },
    { "--version", 0, NULL, CLI_ALONE, NULL, opt_alone, NULL,
      "print the library version and exit" },
};

static const struct cli_table cli = {
    PROG, option_list, sizeof option_list / sizeof option_list[0],
    "Write a maximal Poisson-disk point pattern to standard output (or --output\n"
    "FILE): by default one \"x y\" line per point in insertion order (%.17g: values\n"
    "round-trip exactly), or another --format. --svg and --png draw the pattern,\n"
    "--spectrum and its companions analyse it.\n",
    "Options taking a value accept both '--opt VALUE' and '--opt=VALUE'.\n"
    "--help and --version end the command line: they print, exit 0 and sample\n"
    "nothing; the arguments after them are not read.\n"
    "An option given twice takes its last value (--refine adds a stage); of\n"
    "--progress and --no-progress the last one counts.\n"
    "Ctrl-C stops the sampling, and the spectrum's patterns, within about a\n"
    "second; nothing is written then, unless --partial is given (the points\n"
    "are the last output). A second Ctrl-C ends the program at once.\n"
    "Exit status: 0 success, 1 library or output error, 2 bad arguments, also\n"
    "when the library rejects a value (an empty --domain, a radius too small for\n"
    "the domain or, with --periodic, over half its shorter side), 130\n"
    "interrupted by Ctrl-C (SIGINT).\n",
};

const struct cli_table *cli_program_table(void) { return &cli; }

/* The domain options against the others: 0, or the exit status after the message. */
static int domain_check(const struct options *o)
{
    const struct cli_domain *d = &o->domain;
    const char *shape = d->polygon != NULL ? "--polygon" : d->mask != NULL ? "--mask" : NULL;

    if (d->polygon != NULL && d->mask != NULL)
        return cli_usage_error(&cli, "--mask cannot be used with --polygon: the domain is "
                               "either a polygon or the dark pixels of an image");
    if (shape != NULL && o->where.periodic)
        return cli_usage_error(&cli, "--periodic cannot be used with %s: a torus has no "
                               "outline, and the library samples %s on the plane only", shape,
                               d->polygon != NULL ? "polygons" : "masks");
    if (d->fixed != NULL && o->where.periodic)
        return cli_usage_error(&cli, "--periodic cannot be used with --fixed: the library "
                               "takes fixed points on the plane only");
    if (d->polygon != NULL && o->domain_values > 1)
        return cli_usage_error(&cli, "--domain cannot be used with --polygon: the polygon's "
                               "bounding box is the domain");
    if (o->out.spectrum_from != NULL && (shape != NULL || d->fixed != NULL))
        return cli_usage_error(&cli, "%s cannot be used with --spectrum-from: the patterns are "
                               "read, not made", shape != NULL ? shape : "--fixed");
    return 0;
}

/* Returns 0 to go on, CLI_STOP (--help, --version), or an exit status. */
int cli_parse_args(int argc, char **argv, struct options *o)
{
    struct cli_refines *rf = &o->refines;
    const struct cli_field *f = &o->field;
    char why[160];
    size_t k;
    int rc;

    /* At most one --refine per two arguments; argc bounds them all. */
    rf->refine = malloc((size_t)argc * sizeof *rf->refine);
    if (rf->refine == NULL) {
        fputs(PROG ": out of memory\n", stderr);
        return EXIT_LIBRARY;
    }
    if ((rc = cli_parse(&cli, argc, argv, o)) != 0)
        return rc;
    if (f->path == NULL && (f->rmin > 0 || f->rmax > 0))
        return cli_usage_error(&cli, "%s needs --radius-map", f->rmin > 0 ? "--rmin" : "--rmax");
    if (f->path != NULL) {
        if (f->rmin == 0 || f->rmax == 0)
            return cli_usage_error(&cli, "--radius-map needs --rmin and --rmax, the radii of "
                                   "black and of white");
        if (f->rmin > f->rmax)
            return cli_usage_error(&cli, "--rmin %g is larger than --rmax %g", f->rmin,
                                   f->rmax);
        if (o->out.spectrum_from != NULL)
            return cli_usage_error(&cli, "--radius-map cannot be used with --spectrum-from: "
                                   "the patterns are read, not made");
    }
    if ((rc = domain_check(o)) != 0)
        return rc;
    if (o->where.count > 0 && rf->nrefine > 0)
        return cli_usage_error(&cli, "--refine cannot be used with --count: the library "
                               "chooses the radius");
    if (cli_outputs_check(&o->out, rf, &o->where, o->verify, o->stats, o->partial, why,
                          sizeof why) != NULL)
        return cli_usage_error(&cli, "%s", why);
    /* Checked now rather than by pds_refine once the earlier radii ran. */
    for (k = 0; k < rf->nrefine; k++) {
        double before = k > 0 ? rf->refine[k - 1] : f->path != NULL ? f->rmax : rf->radius;
        if (rf->refine[k] > before)
            return cli_usage_error(&cli, "--refine %g is larger than the radius before it, %g",
                                   rf->refine[k], before);
    }
    return 0;
}

