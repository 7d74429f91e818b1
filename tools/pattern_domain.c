/*
 * pattern_domain.c - the shaped domain in the pictures (see
 * pattern_pictures.h): a polygon's rings or a mask's pixel boundary, and the
 * fixed points, in SVG and in the PNG raster. The PNG fills the domain by
 * scanlines, 4 x 4 samples per pixel as the dots: a sample is inside when a
 * horizontal ray from it crosses the rings an odd number of times (the
 * library's even-odd rule), or when its mask pixel is inside.
 */
#include "pattern_pictures.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#define SUB 4         /* samples per pixel along each axis */
#define OUTSIDE 224   /* the PNG's grey outside the domain */
#define LINE_INK 96   /* the PNG outline's grey */
#define LINE_HALF 0.6 /* half the PNG outline's width, pixels */

/* A segment of the outline, in user units. */
typedef int (*segment_fn)(void *ctx, double x0, double y0, double x1, double y1);

/* The x (vertical = 0) or y (vertical = 1) of grid line k of n over [lo, hi]. */
static double grid(const double *b, int vertical, size_t k, size_t n)
{
    double lo = vertical ? b[1] : b[0], hi = vertical ? b[3] : b[2];
    return k == n ? hi : lo + (hi - lo) * (double)k / (double)n;
}

static int mask_in(const struct pattern_shape *m, long col, long row)
{
    if (col < 0 || row < 0 || (size_t)col >= m->mask_w || (size_t)row >= m->mask_h)
        return 0;
    return m->inside[(size_t)row * m->mask_w + (size_t)col] != 0;
}

/* Whether the unit edge k along grid line `line` (horizontal: between rows line-1 and
   line; vertical: between columns) parts an inside pixel from an outside one. */
static int mask_edge(const struct pattern_shape *m, int vertical, size_t line, size_t k)
{
    long l = (long)line, c = (long)k;
    return vertical ? mask_in(m, l - 1, c) != mask_in(m, l, c)
                    : mask_in(m, c, l - 1) != mask_in(m, c, l);
}

/*
 * The mask's pixel boundary: every edge between an inside and an outside
 * pixel (beyond the mask is outside), consecutive edges along one grid line
 * merged into one segment.
 */
static int mask_boundary(const struct pattern *p, segment_fn fn, void *ctx)
{
    const struct pattern_shape *m = p->shape;
    const double *b = p->box;
    size_t line, k, end, w = m->mask_w, h = m->mask_h;
    int vertical;

    for (vertical = 0; vertical < 2; vertical++) {
        size_t lines = vertical ? w : h, along = vertical ? h : w;
        for (line = 0; line <= lines; line++)
            for (k = 0; k < along; k = end) {
                end = k + 1;
                if (!mask_edge(m, vertical, line, k))
                    continue;
                while (end < along && mask_edge(m, vertical, line, end))
                    end++;
                if (vertical ? fn(ctx, grid(b, 0, line, w), grid(b, 1, k, h),
                                  grid(b, 0, line, w), grid(b, 1, end, h))
                             : fn(ctx, grid(b, 0, k, w), grid(b, 1, line, h),
                                  grid(b, 0, end, w), grid(b, 1, line, h)))
                    return -1;
            }
    }
    return 0;
}

/* ---- SVG ------------------------------------------------------------------------------ */

struct svg_ctx {
    FILE *f;
    double ysum; /* y0 + y1: y is drawn at ysum - y */
};

static int svg_segment(void *ctx, double x0, double y0, double x1, double y1)
{
    struct svg_ctx *c = ctx;
    return fprintf(c->f, "M%.10g,%.10g L%.10g,%.10g\n", x0, c->ysum - y0, x1, c->ysum - y1) < 0;
}

int pattern_svg_outline(FILE *f, const struct pattern *p, double line)
{
    const struct pattern_shape *m = p->shape;
    struct svg_ctx c;
    size_t k, v = 0, row, col;

    c.f = f;
    c.ysum = p->box[1] + p->box[3];
    if (m->rings_xy != NULL) {
        fprintf(f, "<path id=\"outline\" fill=\"white\" fill-rule=\"evenodd\" stroke=\"black\" "
                   "stroke-width=\"%.10g\" stroke-linejoin=\"round\" d=\"", line);
        for (k = 0; k < m->nrings; k++) {
            for (; v < m->ring_ends[k]; v++)
                fprintf(f, "%s%.10g,%.10g", v == (k ? m->ring_ends[k - 1] : 0) ? "M" : " L",
                        m->rings_xy[2 * v], c.ysum - m->rings_xy[2 * v + 1]);
            fputs(" Z\n", f);
        }
        fputs("\"/>\n", f);
    } else if (m->inside != NULL) {
        /* The inside pixels filled, one rectangle per run in a row; then the boundary. */
        fputs("<path id=\"mask\" fill=\"white\" stroke=\"none\" d=\"", f);
        for (row = 0; row < m->mask_h; row++)
            for (col = 0; col < m->mask_w; col++) {
                size_t end = col;
                if (!mask_in(m, (long)col, (long)row))
                    continue;
                while (end < m->mask_w && mask_in(m, (long)end, (long)row))
                    end++;
                fprintf(f, "M%.10g,%.10g H%.10g V%.10g H%.10g Z\n", grid(p->box, 0, col, m->mask_w),
                        c.ysum - grid(p->box, 1, row, m->mask_h), grid(p->box, 0, end, m->mask_w),
                        c.ysum - grid(p->box, 1, row + 1, m->mask_h),
                        grid(p->box, 0, col, m->mask_w));
                col = end;
            }
        fprintf(f, "\"/>\n<path id=\"outline\" fill=\"none\" stroke=\"black\" "
                   "stroke-width=\"%.10g\" stroke-linecap=\"square\" d=\"", line);
        if (mask_boundary(p, svg_segment, &c) != 0)
            return -1;
        fputs("\"/>\n", f);
    }
    return ferror(f) ? -1 : 0;
}

int pattern_svg_fixed(FILE *f, const struct pattern *p, double line, double dot, int clearances)
{
    const struct pattern_shape *m = p->shape;
    double ysum = p->box[1] + p->box[3];
    size_t k;

    if (m->nfixed == 0)
        return 0;
    if (clearances) {
        fprintf(f, "<g id=\"clearances\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"%.10g\" "
                   "stroke-dasharray=\"%.10g %.10g\">\n", line / 2, 2 * line, line);
        for (k = 0; k < m->nfixed; k++)
            fprintf(f, "<circle cx=\"%.10g\" cy=\"%.10g\" r=\"%.10g\"/>\n", m->fixed_xy[2 * k],
                    ysum - m->fixed_xy[2 * k + 1], m->clearance[k]);
    } else {
        fputs("<g id=\"fixed\" fill=\"#d62728\">\n", f);
        for (k = 0; k < m->nfixed; k++)
            fprintf(f, "<circle cx=\"%.10g\" cy=\"%.10g\" r=\"%.10g\"/>\n", m->fixed_xy[2 * k],
                    ysum - m->fixed_xy[2 * k + 1], 1.5 * dot);
    }
    fputs("</g>\n", f);
    return ferror(f) ? -1 : 0;
}

/* ---- PNG ------------------------------------------------------------------------------ */

struct raster {
    unsigned char *pix;
    unsigned w, h;
    const double *box;
    double scale; /* pixels per unit length */
};

/* Darkens pix[x, y] towards ink by the share c of its samples covered. */
static void ink(const struct raster *r, long x, long y, double c, int to)
{
    unsigned char *q = &r->pix[(size_t)y * r->w + (size_t)x];
    double shade = floor(255.0 - c * (255.0 - to) + 0.5);
    if (shade < *q)
        *q = (unsigned char)shade;
}

/* Distance squared from (px, py) to the segment a-b (pixels). */
static double seg_d2(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    dx = ax + t * dx - px;
    dy = ay + t * dy - py;
    return dx * dx + dy * dy;
}

/* The outline segment, LINE_HALF pixels either side, anti-aliased; the pixels
   are visited piece by piece (2 pixels long) so a long slanted edge costs its length. */
static int png_segment(void *ctx, double x0, double y0, double x1, double y1)
{
    const struct raster *r = ctx;
    double ax = (x0 - r->box[0]) * r->scale, ay = (r->box[3] - y0) * r->scale;
    double bx = (x1 - r->box[0]) * r->scale, by = (r->box[3] - y1) * r->scale;
    double len = hypot(bx - ax, by - ay), reach = LINE_HALF + 1.0;
    long pieces = (long)ceil(len / 2.0), k, x, y;
    int a, c;

    for (k = 0; k < (pieces > 0 ? pieces : 1); k++) {
        double t0 = pieces > 0 ? (double)k / (double)pieces : 0;
        double t1 = pieces > 0 ? (double)(k + 1) / (double)pieces : 0;
        double sx = ax + t0 * (bx - ax), sy = ay + t0 * (by - ay);
        double ex = ax + t1 * (bx - ax), ey = ay + t1 * (by - ay);
        long xa = (long)floor(fmin(sx, ex) - reach), xb = (long)floor(fmax(sx, ex) + reach);
        long ya = (long)floor(fmin(sy, ey) - reach), yb = (long)floor(fmax(sy, ey) + reach);
        for (y = ya < 0 ? 0 : ya; y <= yb && y < (long)r->h; y++)
            for (x = xa < 0 ? 0 : xa; x <= xb && x < (long)r->w; x++) {
                int in = 0;
                for (a = 0; a < SUB; a++)
                    for (c = 0; c < SUB; c++)
                        in += seg_d2(x + (a + 0.5) / SUB, y + (c + 0.5) / SUB, ax, ay, bx, by)
                              <= LINE_HALF * LINE_HALF;
                if (in > 0) /* the whole segment's distance: pieces agree where they meet */
                    ink(r, x, y, (double)in / (SUB * SUB), LINE_INK);
            }
    }
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Sub-row j's sample centre is at pixel y (j + 1/2) / SUB: the sub-rows an edge
   from pixel y ya to yb crosses, half-open [lo, hi), clipped to [0, n). */
static void subrows(double ya, double yb, long n, long *lo, long *hi)
{
    double a = fmin(ya, yb), b = fmax(ya, yb);
    *lo = (long)fmax(0.0, ceil(a * SUB - 0.5));
    *hi = (long)fmin((double)n, ceil(b * SUB - 0.5));
}

/*
 * The polygon's crossings: for each sub-row j, xs[start[j] .. start[j+1]) the
 * sorted pixel x where the rings cross its sample line. Counted, then filled.
 */
static int polygon_crossings(const struct raster *r, const struct pattern_shape *m,
                             size_t **start_out, double **xs_out)
{
    long n = (long)r->h * SUB, j, lo, hi;
    size_t *start = calloc((size_t)n + 2, sizeof *start), total, k, v, first, pass;
    double *xs = NULL;

    if (start == NULL)
        return -1;
    for (pass = 0; pass < 2; pass++) {
        for (k = 0, first = 0; k < m->nrings; first = m->ring_ends[k++])
            for (v = first; v < m->ring_ends[k]; v++) {
                size_t u = v + 1 < m->ring_ends[k] ? v + 1 : first; /* the ring closes */
                double ax = (m->rings_xy[2 * v] - r->box[0]) * r->scale;
                double ay = (r->box[3] - m->rings_xy[2 * v + 1]) * r->scale;
                double bx = (m->rings_xy[2 * u] - r->box[0]) * r->scale;
                double by = (r->box[3] - m->rings_xy[2 * u + 1]) * r->scale;
                if (ay == by)
                    continue;
                subrows(ay, by, n, &lo, &hi);
                for (j = lo; j < hi; j++) {
                    if (pass == 0)
                        start[j + 2]++;
                    else
                        xs[start[j + 1]++] = ax + ((j + 0.5) / SUB - ay) * (bx - ax) / (by - ay);
                }
            }
        if (pass == 0) {
            for (j = 0; j < n; j++)
                start[j + 2] += start[j + 1];
            total = start[n + 1];
            if ((xs = malloc((total > 0 ? total : 1) * sizeof *xs)) == NULL) {
                free(start);
                return -1;
            }
        }
    }
    /* The fill moved start[j + 1] to where sub-row j ends: start[j] .. start[j + 1]. */
    for (j = 0; j < n; j++)
        qsort(xs + start[j], start[j + 1] - start[j], sizeof *xs, cmp_double);
    *start_out = start;
    *xs_out = xs;
    return 0;
}

/* Adds the samples of sub-row span [xa, xb) (pixels) to cover, per pixel. */
static void add_span(unsigned *cover, unsigned w, double xa, double xb)
{
    long i, lo = (long)fmax(0.0, ceil(xa * SUB - 0.5));
    long hi = (long)fmin((double)w * SUB, ceil(xb * SUB - 0.5));
    for (i = lo; i < hi; i++)
        cover[i / SUB]++;
}

int pattern_png_outline(unsigned char *pix, unsigned w, unsigned h, const struct pattern *p,
                        double scale)
{
    const struct pattern_shape *m = p->shape;
    struct raster r;
    unsigned *cover = malloc((size_t)w * sizeof *cover);
    size_t *start = NULL, k, v, first;
    double *xs = NULL;
    unsigned x, y;
    int j;

    r.pix = pix;
    r.w = w;
    r.h = h;
    r.box = p->box;
    r.scale = scale;
    if (cover == NULL || (m->rings_xy != NULL && polygon_crossings(&r, m, &start, &xs) != 0)) {
        free(cover);
        errno = ENOMEM;
        return -1;
    }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++)
            cover[x] = 0;
        for (j = 0; j < SUB; j++) {
            long sub = (long)y * SUB + j;
            if (m->rings_xy != NULL) {
                for (k = start[sub]; k + 1 < start[sub + 1]; k += 2) /* even-odd pairs */
                    add_span(cover, w, xs[k], xs[k + 1]);
            } else {
                /* The mask row under the sample line (the mask's row 0 is at the bottom). */
                double yu = p->box[3] - ((sub + 0.5) / SUB) / scale;
                long row = (long)floor((yu - p->box[1]) / (p->box[3] - p->box[1])
                                       * (double)m->mask_h);
                for (v = 0; v < m->mask_w; v = first) {
                    for (first = v + 1; first < m->mask_w
                         && mask_in(m, (long)first, row) == mask_in(m, (long)v, row);)
                        first++;
                    if (mask_in(m, (long)v, row))
                        add_span(cover, w, (grid(p->box, 0, v, m->mask_w) - p->box[0]) * scale,
                                 (grid(p->box, 0, first, m->mask_w) - p->box[0]) * scale);
                }
            }
        }
        for (x = 0; x < w; x++)
            ink(&r, (long)x, (long)y, 1.0 - (double)cover[x] / (SUB * SUB), OUTSIDE);
    }
    free(cover);
    free(start);
    free(xs);
    if (m->rings_xy != NULL) {
        for (k = 0, first = 0; k < m->nrings; first = m->ring_ends[k++])
            for (v = first; v < m->ring_ends[k]; v++) {
                size_t u = v + 1 < m->ring_ends[k] ? v + 1 : first;
                png_segment(&r, m->rings_xy[2 * v], m->rings_xy[2 * v + 1], m->rings_xy[2 * u],
                            m->rings_xy[2 * u + 1]);
            }
        return 0;
    }
    return mask_boundary(p, png_segment, &r);
}

void pattern_png_fixed(unsigned char *pix, unsigned w, unsigned h, const struct pattern *p,
                       double scale, double dot_px)
{
    const struct pattern_shape *m = p->shape;
    double radius = fmax(1.6 * dot_px, 2.5), half = fmax(0.5, 0.2 * radius);
    struct raster r;
    size_t k;
    long x, y;
    int a, c;

    r.pix = pix;
    r.w = w;
    r.h = h;
    for (k = 0; k < m->nfixed; k++) {
        double cx = (m->fixed_xy[2 * k] - p->box[0]) * scale;
        double cy = (p->box[3] - m->fixed_xy[2 * k + 1]) * scale;
        long x0 = (long)floor(cx - radius - half), x1 = (long)floor(cx + radius + half);
        long y0 = (long)floor(cy - radius - half), y1 = (long)floor(cy + radius + half);
        for (y = y0 < 0 ? 0 : y0; y <= y1 && y < (long)h; y++)
            for (x = x0 < 0 ? 0 : x0; x <= x1 && x < (long)w; x++) {
                int ring = 0;
                for (a = 0; a < SUB; a++)
                    for (c = 0; c < SUB; c++)
                        ring += fabs(hypot(x + (a + 0.5) / SUB - cx, y + (c + 0.5) / SUB - cy)
                                     - radius) <= half;
                if (ring > 0)
                    ink(&r, x, y, (double)ring / (SUB * SUB), 0);
            }
    }
}
