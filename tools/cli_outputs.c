/*
 * cli_outputs.c - the points in a format and the pictures of the pattern
 * (see cli_outputs.h; the spectrum is in cli_spectrum.c).
 */
#include "cli_outputs.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pattern_pictures.h"

int cli_spectrum_wanted(const struct cli_outputs *o)
{
    return o->spectrum != NULL || o->spectrum_plot != NULL || o->spectrum_csv != NULL;
}

static int write_failed(const char *prog, const char *what)
{
    fprintf(stderr, "%s: cannot write %s: %s\n", prog, what, strerror(errno));
    return CLI_EXIT_LIBRARY;
}

int cli_write_points(const char *prog, const pds_sampler *s, const struct cli_outputs *o,
                     const struct cli_where *w)
{
    FILE *f = stdout;
    int rc;

    /* Binary formats are written byte for byte, also where "b" would matter. */
    if (o->output != NULL && (f = fopen(o->output, "wb")) == NULL)
        return write_failed(prog, o->output);
    errno = 0;
    rc = cli_format_write(f, o->format, s, w->box, w->periodic, o->radii);
    if (f != stdout && fclose(f) != 0)
        rc = -1;
    if (rc != 0) {
        if (o->output == NULL) {
            fprintf(stderr, "%s: error writing points: %s\n", prog, strerror(errno));
            return CLI_EXIT_LIBRARY;
        }
        return write_failed(prog, o->output);
    }
    return 0;
}

/*
 * The shape to draw, from the files read (cli_domain.h); clear[k] is fixed
 * point k's clearance at the final radius: the default (0 in the file) the
 * radius in force there, R or the map's radius at the point; one given in
 * the file scaled as the library scales it, by the final radius over the
 * first (--refine, --count).
 */
static void shape_of(struct pattern_shape *ps, double *clear, const struct cli_where *w,
                     double radius)
{
    const struct cli_domain *d = w->shape;
    size_t k;

    memset(ps, 0, sizeof *ps);
    if (d->polygon != NULL) {
        ps->rings_xy = d->rings.xy;
        ps->ring_ends = d->rings.ring_ends;
        ps->nrings = d->rings.nrings;
    } else if (d->mask != NULL) {
        ps->inside = d->inside;
        ps->mask_w = d->mask_w;
        ps->mask_h = d->mask_h;
    }
    for (k = 0; k < d->points.n; k++) {
        double x = d->points.xy[2 * k], y = d->points.xy[2 * k + 1];
        double given = d->points.clearance[k];
        clear[k] = given > 0 ? given * (radius / d->radius0)
                 : w->field != NULL ? cli_field_at(w->field, w->box, x, y, radius) : radius;
    }
    ps->fixed_xy = d->points.xy;
    ps->clearance = clear;
    ps->nfixed = d->points.n;
}

int cli_write_pictures(const char *prog, const pds_sampler *s, const struct cli_outputs *o,
                       const struct cli_where *w)
{
    struct pattern p;
    struct pattern_shape shape;
    double *xy, *radii = NULL, *clear = NULL;
    int status = 0;

    if (o->svg == NULL && o->png == NULL)
        return 0;
    p.n = pds_count(s);
    xy = malloc((p.n > 0 ? p.n : 1) * 2 * sizeof *xy);
    if (w->field != NULL)
        radii = malloc((p.n > 0 ? p.n : 1) * sizeof *radii);
    if (w->shape != NULL)
        clear = malloc((w->shape->points.n > 0 ? w->shape->points.n : 1) * sizeof *clear);
    if (xy == NULL || (w->field != NULL && radii == NULL) || (w->shape != NULL && clear == NULL)) {
        free(xy);
        free(radii);
        free(clear);
        fprintf(stderr, "%s: out of memory for the pictures\n", prog);
        return CLI_EXIT_LIBRARY;
    }
    pds_points(s, 0, p.n, xy);
    p.xy = xy;
    p.box = w->box;
    p.radius = pds_radius(s);
    p.radii = radii;
    p.rmin = p.radius;
    if (radii != NULL) {
        pds_radii(s, 0, p.n, radii);
        p.rmin = cli_field_smallest(w->field, p.radius);
    }
    p.dot = o->dot;
    p.periodic = w->periodic;
    p.shape = NULL;
    if (w->shape != NULL) {
        shape_of(&shape, clear, w, p.radius);
        p.shape = &shape;
    }
    if (o->svg != NULL && pattern_write_svg(&p, o->disks, o->svg) != 0)
        status = write_failed(prog, o->svg);
    if (status == 0 && o->png != NULL && pattern_write_png(&p, o->size, o->png) != 0)
        status = write_failed(prog, o->png);
    free(xy);
    free(radii);
    free(clear);
    return status;
}
