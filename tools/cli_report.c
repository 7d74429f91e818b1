/*
 * cli_report.c - the --stats line and the PDS_ERANGE message of the
 * poissondisk program (see cli_report.h).
 */
#include "cli_report.h"

#include <float.h>
#include <math.h>
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
 * The statistics are computed in scaled units: every length divided by 2^e,
 * the power of two that brings the domain's largest |coordinate| into
 * [0.5, 1). Dividing by a power of two is exact, and in these units squared
 * distances, areas and disks neither overflow (a 1e300 domain) nor
 * underflow (a 1e-199 one); the library keeps R at least 2^-26 of that
 * coordinate, so R^2 stays far from the bottom of the range too. The ratios
 * printed do not depend on the unit.
 */
struct scaled {
    int e;          /* lengths in units of 2^e */
    double box[4];  /* the domain in those units */
    double area;    /* its area in units of 2^2e */
};

static void scale_domain(struct scaled *u, const double box[4])
{
    double m = fmax(fmax(fabs(box[0]), fabs(box[1])), fmax(fabs(box[2]), fabs(box[3])));
    int k;

    frexp(m, &u->e);
    for (k = 0; k < 4; k++)
        u->box[k] = ldexp(box[k], -u->e);
    u->area = (u->box[2] - u->box[0]) * (u->box[3] - u->box[1]);
}

static void scale_values(double *v, size_t n, int e)
{
    size_t k;
    for (k = 0; k < n; k++)
        v[k] = ldexp(v[k], -e);
}

/*
 * The coverage 1 - F/A from the library's free area F (in user units),
 * or -1 when F cannot give it: F overflowed (a domain over about 1e154 on a
 * side, not maximal), or F is below DBL_MIN, where it may have underflowed,
 * in a domain so small (under 2^53 DBL_MIN in area) that this matters.
 */
static double coverage(double free_area, const struct scaled *u, int maximal)
{
    if (maximal && free_area == 0.0)
        return 1.0;
    if (!isfinite(free_area)
        || (free_area < DBL_MIN && ldexp(u->area, 2 * u->e) < ldexp(DBL_MIN, 53)))
        return -1.0;
    return 1.0 - ldexp(free_area, -2 * u->e) / u->area;
}

/*
 * With a radius map: "packing=P min_dist=Dr mean_nn=Mr", in units of the
 * points' own radii (see cli_report.h).
 */
static void field_spacing(char *buf, size_t size, const pds_sampler *s,
                          const struct cli_where *w, const struct scaled *u)
{
    size_t n = pds_count(s), k;
    double rmax = ldexp(pds_radius(s), -u->e);
    double rmin = ldexp(cli_field_smallest(w->field, pds_radius(s)), -u->e);
    double disks = 0.0, least, mean, area = u->area;
    double *xy = malloc((n > 0 ? n : 1) * 2 * sizeof *xy);
    double *r = malloc((n > 0 ? n : 1) * sizeof *r);
    int rc = -1;

    if (xy != NULL && r != NULL) {
        pds_points(s, 0, n, xy);
        pds_radii(s, 0, n, r);
        scale_values(xy, 2 * n, u->e);
        scale_values(r, n, u->e);
        for (k = 0; k < n; k++)
            disks += PI * r[k] * r[k];
        rc = pattern_field_stats(xy, r, n, u->box, rmin, rmax, &least, &mean);
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
                    const struct scaled *u)
{
    size_t n = pds_count(s);
    double r = ldexp(pds_radius(s), -u->e), least, mean, area = u->area;
    double *xy = malloc((n > 0 ? n : 1) * 2 * sizeof *xy);
    int rc = -1;

    if (xy != NULL) {
        pds_points(s, 0, n, xy);
        scale_values(xy, 2 * n, u->e);
        rc = pattern_nn_stats(xy, n, u->box, w->periodic, r, &least, &mean);
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
    double free_area = pds_free_area(s), covered;
    char close = w->periodic ? ')' : ']';
    char radius[80], lo[32], hi[32], space[128], cover[32], shape[64];
    struct scaled u;

    scale_domain(&u, d);
    /* A polygon or mask fills only part of its box: its own area, when known. */
    if (cli_domain_shaped(w->shape) && w->shape->area > 0 && isfinite(w->shape->area))
        u.area = ldexp(w->shape->area, -2 * u.e);
    if (w->count > 0 && !verified)
        maximal = free_area == 0.0;
    covered = coverage(free_area, &u, maximal);
    if (covered < 0)
        snprintf(cover, sizeof cover, "-");
    else
        snprintf(cover, sizeof cover, "%.9f", covered);
    if (w->field != NULL) {
        field_spacing(space, sizeof space, s, w, &u);
        snprintf(radius, sizeof radius, "%s..%s (radius map)",
                 exact(lo, sizeof lo, cli_field_smallest(w->field, pds_radius(s))),
                 exact(hi, sizeof hi, pds_radius(s)));
    } else {
        spacing(space, sizeof space, s, w, &u);
        exact(radius, sizeof radius, pds_radius(s));
    }
    /* What shapes the domain, after the box: " polygon" or " mask", " fixed=K". */
    shape[0] = '\0';
    if (w->shape != NULL) {
        int n = snprintf(shape, sizeof shape, "%s", w->shape->polygon != NULL ? " polygon"
                                                    : w->shape->mask != NULL  ? " mask" : "");
        if (w->shape->fixed != NULL)
            snprintf(shape + n, sizeof shape - (size_t)n, " fixed=%zu", w->shape->points.n);
    }
    fprintf(stderr,
            "%s: N=%zu R=%s%s domain=[%g,%g%cx[%g,%g%c%s%s coverage=%s %s%s %s %.3f s\n", prog,
            pds_count(s), radius,
            w->count > 0 ? " (chosen for --count)" : "", d[0], d[2], close, d[1], d[3], close,
            w->periodic ? " periodic" : "", shape, cover,
            maximal ? "maximal" : "not maximal", verified ? " verified" : "", space, seconds);
}

const char *cli_domain_text(char *buf, size_t size, const struct cli_where *w)
{
    const double *d = w->box;
    char close = w->periodic ? ')' : ']';

    snprintf(buf, size, "[%g,%g%cx[%g,%g%c", d[0], d[2], close, d[1], d[3], close);
    return buf;
}

int cli_range_error(const char *prog, const struct cli_where *w, double radius,
                    const char *msg)
{
    char what[160], domain[128];

    cli_domain_text(domain, sizeof domain, w);
    /* On a plane with a radius map the smallest radius is the one judged (radius
       is the largest): too small for double precision or for the index type. */
    if (w->field != NULL && !w->periodic) {
        fprintf(stderr, "%s: the smallest radius of --radius-map %s, %g, is too small for the "
                        "domain %s: %s\n", prog, w->field->path,
                cli_field_smallest(w->field, radius), domain, msg);
        return CLI_EXIT_USAGE;
    }
    /* On a torus the radius may also be too large (over half a period, after the
       period's rounding), and a count asks for a radius: the library says which. */
    if (w->field != NULL || w->count > 0 || w->periodic) {
        if (w->field != NULL)
            snprintf(what, sizeof what, "the radii of --radius-map %s, %g to %g,", w->field->path,
                     cli_field_smallest(w->field, radius), radius);
        else if (w->count > 0)
            snprintf(what, sizeof what, "--count %zu", w->count);
        else
            snprintf(what, sizeof what, "radius %g", radius);
        fprintf(stderr, "%s: %s %s not suit the %sdomain %s: %s\n", prog, what,
                w->field != NULL ? "do" : "does", w->periodic ? "periodic " : "", domain, msg);
    } else {
        fprintf(stderr, "%s: radius %g is too small for the domain %s: %s\n", prog, radius,
                domain, msg);
    }
    return CLI_EXIT_USAGE;
}
