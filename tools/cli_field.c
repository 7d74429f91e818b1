/*
 * cli_field.c - the radius map of the poissondisk program (see cli_field.h).
 */
#include "cli_field.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_sample.h"
#include "pgm.h"

/* The radius of grey level g: rmin at 0, rmax at maxval, linear in between. */
static double radius_of(const struct cli_field *f, unsigned g, unsigned maxval)
{
    double r;

    if (g >= maxval)
        return f->rmax;
    r = f->rmin + (f->rmax - f->rmin) * ((double)g / (double)maxval);
    return r < f->rmax ? r : f->rmax; /* never above rmax, whatever the rounding */
}

int cli_field_load(const char *prog, struct cli_field *f)
{
    int from_stdin = strcmp(f->path, "-") == 0;
    FILE *in = from_stdin ? stdin : fopen(f->path, "rb");
    struct pgm img;
    char why[160];
    size_t row, col;
    int rc;

    if (in == NULL) {
        fprintf(stderr, "%s: --radius-map %s: cannot read it: %s\n", prog, f->path,
                strerror(errno));
        return CLI_EXIT_LIBRARY;
    }
    rc = pgm_read(in, &img, why, sizeof why);
    if (!from_stdin)
        fclose(in);
    if (rc != 0) {
        fprintf(stderr, "%s: --radius-map %s: %s\n", prog, f->path, why);
        return CLI_EXIT_LIBRARY;
    }
    f->w = img.width;
    f->h = img.height;
    f->r = malloc(f->w * f->h * sizeof *f->r);
    if (f->r == NULL) {
        pgm_free(&img);
        fprintf(stderr, "%s: --radius-map %s: out of memory for a %zu x %zu map\n", prog,
                f->path, f->w, f->h);
        return CLI_EXIT_LIBRARY;
    }
    f->lo = f->rmax;
    f->hi = f->rmin;
    /* The image's top row is the domain's top (y1); the map's row 0 lies along y0. */
    for (row = 0; row < f->h; row++)
        for (col = 0; col < f->w; col++) {
            double r = radius_of(f, img.pix[row * f->w + col], img.maxval);
            f->r[(f->h - 1 - row) * f->w + col] = r;
            f->lo = r < f->lo ? r : f->lo;
            f->hi = r > f->hi ? r : f->hi;
        }
    pgm_free(&img);
    return 0;
}

void cli_field_free(struct cli_field *f)
{
    free(f->r);
    f->r = NULL;
}

double cli_field_smallest(const struct cli_field *f, double largest)
{
    return largest == f->hi ? f->lo : f->lo * (largest / f->hi);
}

/* Where v lies between the pixel centres along an axis of n pixels over [lo, hi]: the
   lower centre *i (clamped) and the weight of the upper one. */
static double between(double v, double lo, double hi, size_t n, size_t *i)
{
    double u = (v - lo) / (hi - lo) * (double)n - 0.5;

    if (!(u > 0)) { /* also a NaN from an empty side */
        *i = 0;
        return 0;
    }
    if (u >= (double)(n - 1)) {
        *i = n - 1;
        return 0;
    }
    *i = (size_t)u;
    return u - (double)*i;
}

double cli_field_at(const struct cli_field *f, const double box[4], double x, double y,
                    double largest)
{
    size_t i, j, i1, j1;
    double t = between(x, box[0], box[2], f->w, &i), u = between(y, box[1], box[3], f->h, &j);
    double r;

    i1 = i + 1 < f->w ? i + 1 : i;
    j1 = j + 1 < f->h ? j + 1 : j;
    r = (1 - u) * ((1 - t) * f->r[j * f->w + i] + t * f->r[j * f->w + i1])
        + u * ((1 - t) * f->r[j1 * f->w + i] + t * f->r[j1 * f->w + i1]);
    return largest == f->hi ? r : r * (largest / f->hi);
}
