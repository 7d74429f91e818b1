/*
 * pattern_png.c - a point pattern as a grey-scale PNG raster (see
 * pattern_pictures.h; the encoder is png.c).
 */
#include "pattern_pictures.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "png.h"

#define SUB 4 /* samples per pixel along each axis, for the anti-aliasing */

/* Darkens the pixels under the disk of radius r (pixels) centred at (cx, cy) (pixels). */
static void dot(unsigned char *pix, unsigned w, unsigned h, double cx, double cy, double r)
{
    long x0 = (long)floor(cx - r), x1 = (long)floor(cx + r);
    long y0 = (long)floor(cy - r), y1 = (long)floor(cy + r);
    long x, y;
    int a, b;

    if (x0 < 0)
        x0 = 0;
    if (y0 < 0)
        y0 = 0;
    if (x1 > (long)w - 1)
        x1 = (long)w - 1;
    if (y1 > (long)h - 1)
        y1 = (long)h - 1;
    for (y = y0; y <= y1; y++)
        for (x = x0; x <= x1; x++) {
            unsigned char *p = &pix[(size_t)y * w + (size_t)x];
            int inside = 0;
            double shade;
            for (a = 0; a < SUB; a++)
                for (b = 0; b < SUB; b++) {
                    double dx = (double)x + (a + 0.5) / SUB - cx, dy = (double)y + (b + 0.5) / SUB - cy;
                    inside += dx * dx + dy * dy <= r * r;
                }
            /* Coverage c leaves 255 (1 - c); overlapping dots keep the darker. */
            shade = floor(255.0 * (1.0 - (double)inside / (SUB * SUB)) + 0.5);
            if (shade < *p)
                *p = (unsigned char)shade;
        }
}

int pattern_write_png(const struct pattern *p, unsigned size, const char *path)
{
    const double *b = p->box;
    double w = b[2] - b[0], h = b[3] - b[1];
    double scale = size / (w > h ? w : h); /* pixels per unit length */
    unsigned pw = w >= h ? size : (unsigned)fmax(1.0, floor(w * scale + 0.5));
    unsigned ph = h >= w ? size : (unsigned)fmax(1.0, floor(h * scale + 0.5));
    double dot_r = p->dot > 0 ? p->dot : (p->radii != NULL ? p->rmin : p->radius) / 5;
    double r = fmax(dot_r * scale, 1.0);
    unsigned char *pix = malloc((size_t)pw * ph);
    size_t k;
    int i, j, rc;

    if (pix == NULL) {
        errno = ENOMEM;
        return -1;
    }
    for (k = 0; k < (size_t)pw * ph; k++)
        pix[k] = 255;
    /* The box outside a polygon or mask grey, the outline under the dots. */
    if (p->shape != NULL && (p->shape->rings_xy != NULL || p->shape->inside != NULL)
        && pattern_png_outline(pix, pw, ph, p, scale) != 0) {
        free(pix);
        return -1;
    }
    for (k = 0; k < p->n; k++) {
        /* Pixel coordinates: x to the right from x0, y downwards from y1. */
        double cx = (p->xy[2 * k] - b[0]) * scale, cy = (b[3] - p->xy[2 * k + 1]) * scale;
        /* On a torus a dot crossing a side is drawn again one period away. */
        int span = p->periodic ? 1 : 0;
        for (i = -span; i <= span; i++)
            for (j = -span; j <= span; j++)
                dot(pix, pw, ph, cx + i * w * scale, cy + j * h * scale, r);
    }
    if (p->shape != NULL)
        pattern_png_fixed(pix, pw, ph, p, scale, r);
    rc = png_write_gray(path, pix, pw, ph);
    free(pix);
    return rc;
}
