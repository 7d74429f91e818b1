/*
 * spectrum_out.c - the periodogram as a PNG and its rings as CSV (see
 * spectrum_out.h; the SVG plot is in spectrum_plot.c).
 */
#include "spectrum_out.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "png.h"

/* The grid index nearest to f (steps of 1/side), kept within [-max, max]. */
static int nearest(double f, double side, int max)
{
    double v = floor(f * side + 0.5);
    return v > max ? max : v < -max ? -max : (int)v;
}

int spectrum_write_png(const struct spectrum *sp, const char *path, unsigned size)
{
    unsigned char *pix = malloc((size_t)size * size);
    double fmax = spectrum_fmax(sp);
    unsigned i, j;
    int rc;

    if (pix == NULL) {
        errno = ENOMEM;
        return -1;
    }
    for (j = 0; j < size; j++) {
        /* Row 0 is the top: the highest fy. */
        double fy = (1.0 - 2.0 * (j + 0.5) / size) * fmax;
        int l = nearest(fy, sp->h, sp->lmax);
        for (i = 0; i < size; i++) {
            double fx = (2.0 * (i + 0.5) / size - 1.0) * fmax;
            double p = spectrum_power(sp, nearest(fx, sp->w, sp->kmax), l);
            double t = p > 0 ? (10.0 * log10(p) - SPECTRUM_DB_BLACK)
                                   / (SPECTRUM_DB_WHITE - SPECTRUM_DB_BLACK)
                             : 0.0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            pix[(size_t)j * size + i] = (unsigned char)floor(255.0 * t + 0.5);
        }
    }
    rc = png_write_gray(path, pix, size, size);
    free(pix);
    return rc;
}

int spectrum_write_csv(const struct spectrum_ring *rings, size_t n, double radius,
                       const char *path)
{
    FILE *f = fopen(path, "w");
    size_t b;
    int ok;

    if (f == NULL)
        return -1;
    ok = fputs("frequency,frequency_r,power,anisotropy_db,samples\n", f) >= 0;
    for (b = 0; b < n && ok; b++) {
        const struct spectrum_ring *r = &rings[b];
        /* NaN (a ring of one sample) is written as "nan", which CSV readers accept. */
        if (isnan(r->anisotropy_db))
            ok = fprintf(f, "%.17g,%.17g,%.17g,nan,%zu\n", r->f, r->f * radius, r->power,
                         r->samples) >= 0;
        else
            ok = fprintf(f, "%.17g,%.17g,%.17g,%.17g,%zu\n", r->f, r->f * radius, r->power,
                         r->anisotropy_db, r->samples) >= 0;
    }
    if (fclose(f) != 0)
        ok = 0;
    return ok ? 0 : -1;
}
