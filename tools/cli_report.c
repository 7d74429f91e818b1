/*
 * cli_report.c - the --stats line and the PDS_ERANGE message of the
 * poissondisk program (see cli_report.h).
 */
#include "cli_report.h"

#include <stdio.h>
#include <stdlib.h>

#include "cli_options.h"
#include "pattern_stats.h"

/* The shortest of %.6g .. %.17g that reads back as v: exact, and short when it can be. */
static const char *exact(char *buf, size_t size, double v)
{
    int digits;

    for (digits = 6; digits < 17; digits++) {
        snprintf(buf, size, "%.*g", digits, v);
        if (strtod(buf, NULL) == v)
            return buf;
    }
    snprintf(buf, size, "%.17g", v);
    return buf;
}

#define PI 3.14159265358979323846

/*
 * With a radius map: "packing=P min_dist=Dr mean_nn=Mr", in units of the
 * points' own radii (see cli_report.h).
 */
static void field_spacing(char *buf, size_t size, const pds_sampler *s,
                          const struct cli_where *w, double area)
{
    size_t n = pds_count(s), k;
    double rmax = pds_radius(s), rmin = cli_field_smallest(w->field, rmax);
    double disks = 0.0, least, mean;
    double *xy = malloc((n > 0 ? n : 1) * 2 * sizeof *xy);
    double *r = malloc((n > 0 ? n : 1) * sizeof *r);
    int rc = -1;

    if (xy != NULL && r != NULL) {
        pds_points(s, 0, n, xy);
        pds_radii(s, 0, n, r);
        for (k = 0; k < n; k++)
            disks += PI * r[k] * r[k];
        rc = pattern_field_stats(xy, r, n, w->box, rmin, rmax, &least, &mean);
    }
    free(xy);
    free(r);
    if (rc == 0)
        snprintf(buf, size, "packing=%.6f min_dist=%.9fr mean_nn=%.6fr", disks / (4 * area),
                 least, mean);
    else if (rc > 0)
        snprintf(buf, size, "packing=%.6f min_dist=- mean_nn=-", disks / (4 * area));
    else
        snprintf(buf, size, "packing=- min_dist=- mean_nn=- (out of memory)");
}

/* "packing=P min_dist=DR mean_nn=MR": the pattern's spacing (see cli_report.h). */
static void spacing(char *buf, size_t size, const pds_sampler *s, const struct cli_where *w,
                    double area)
{
    size_t n = pds_count(s);
    double r = pds_radius(s), least, mean;
    double *xy = malloc((n > 0 ? n : 1) * 2 * sizeof *xy);
    int rc = -1;

    if (xy != NULL) {
        pds_points(s, 0, n, xy);
        rc = pattern_nn_stats(xy, n, w->box, w->periodic, r, &least, &mean);
        free(xy);
    }
    if (rc == 0)
        snprintf(buf, size, "packing=%.6f min_dist=%.9fR mean_nn=%.6fR",
                 PI * r * r * (double)n / (4 * area), least / r, mean / r);
    else
        snprintf(buf, size, "packing=%.6f min_dist=- mean_nn=-%s",
                 PI * r * r * (double)n / (4 * area),
                 rc < 0 ? " (out of memory)" : "");
}

void cli_print_stats(const char *prog, const pds_sampler *s, const struct cli_where *w,
                     int maximal, int verified, double seconds)
{
    const double *d = w->box;
    double area = (d[2] - d[0]) * (d[3] - d[1]);
    double free_area = pds_free_area(s);
    char close = w->periodic ? ')' : ']';
    char radius[80], lo[32], hi[32], space[128];

    if (w->count > 0 && !verified)
        maximal = free_area == 0.0;
    if (w->field != NULL) {
        field_spacing(space, sizeof space, s, w, area);
        snprintf(radius, sizeof radius, "%s..%s (radius map)",
                 exact(lo, sizeof lo, cli_field_smallest(w->field, pds_radius(s))),
                 exact(hi, sizeof hi, pds_radius(s)));
    } else {
        spacing(space, sizeof space, s, w, area);
        exact(radius, sizeof radius, pds_radius(s));
    }
    fprintf(stderr,
            "%s: N=%zu R=%s%s domain=[%g,%g%cx[%g,%g%c%s coverage=%.9f %s%s %s %.3f s\n", prog,
            pds_count(s), radius,
            w->count > 0 ? " (chosen for --count)" : "", d[0], d[2], close, d[1], d[3], close,
            w->periodic ? " periodic" : "", 1.0 - free_area / area,
            maximal ? "maximal" : "not maximal", verified ? " verified" : "", space, seconds);
}

int cli_range_error(const char *prog, const struct cli_where *w, double radius,
                    const char *msg)
{
    const double *d = w->box;
    char what[64];
    char close = w->periodic ? ')' : ']';

    /* With a radius map the smallest radius is the one judged (radius is the largest). */
    if (w->field != NULL) {
        fprintf(stderr, "%s: the smallest radius of --radius-map %s, %g, is too small for the "
                        "domain [%g,%g]x[%g,%g]: %s\n", prog, w->field->path,
                cli_field_smallest(w->field, radius), d[0], d[2], d[1], d[3], msg);
        return CLI_EXIT_USAGE;
    }
    /* On a torus the radius may also be too large (over half a period, after the
       period's rounding), and a count asks for a radius: the library says which. */
    if (w->count > 0 || w->periodic) {
        if (w->count > 0)
            snprintf(what, sizeof what, "--count %zu", w->count);
        else
            snprintf(what, sizeof what, "radius %g", radius);
        fprintf(stderr, "%s: %s does not suit the %sdomain [%g,%g%cx[%g,%g%c: %s\n", prog, what,
                w->periodic ? "periodic " : "", d[0], d[2], close, d[1], d[3], close, msg);
    } else {
        fprintf(stderr, "%s: radius %g is too small for the domain [%g,%g]x[%g,%g]: %s\n",
                prog, radius, d[0], d[2], d[1], d[3], msg);
    }
    return CLI_EXIT_USAGE;
}
