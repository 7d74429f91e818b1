/*
 * pattern_pictures.h - a point pattern drawn as SVG (--svg, --disks) or as a
 * PNG raster (--png, --size). Both show the domain with y upwards, as in
 * mathematics. Plain C99.
 */
#ifndef POISSONDISK_PATTERN_PICTURES_H
#define POISSONDISK_PATTERN_PICTURES_H

#include <stddef.h>
#include <stdio.h>

/*
 * A pattern to draw: n points (x,y interleaved) in box (x0 y0 x1 y1), with
 * the radius R, or with each point's own radius (a radius map: radii[k]
 * for point k, R then the largest). The dots are drawn with radius dot, the
 * same for every point (0: the picture's default, R/8 or R/5).
 */
/*
 * What shapes the domain (--polygon, --mask, --fixed), drawn over the box:
 * a polygon's rings (even-odd), or a mask of mask_w x mask_h pixels over
 * the box (row 0 along y0), and the fixed points with their clearances.
 */
struct pattern_shape {
    const double *rings_xy;     /* the polygon's vertices, x,y interleaved; NULL: none */
    const size_t *ring_ends;    /* ring k ends before vertex ring_ends[k] */
    size_t nrings;
    const unsigned char *inside;/* the mask, nonzero inside; NULL: none */
    size_t mask_w, mask_h;
    const double *fixed_xy;     /* nfixed fixed points */
    const double *clearance;    /* their clearances, each > 0 (the default resolved) */
    size_t nfixed;
};

struct pattern {
    const double *xy;
    size_t n;
    const double *box;
    double radius;
    const double *radii; /* NULL: every point has the radius R */
    double rmin;         /* with radii: the smallest radius of the field */
    double dot;          /* the dots' radius in the domain's units; 0: default */
    int periodic;
    const struct pattern_shape *shape; /* NULL: the domain is the box */
};

/*
 * The SVG picture (pattern_svg.c). The user coordinates are the domain's,
 * with y mirrored so that it grows upwards: a point (x, y) is the circle at
 * cx = x, cy = y0 + y1 - y. The viewBox is the domain grown by a margin of
 * R/2 plus the line width on each side; the longer side is 800 pixels wide.
 * Groups, in drawing order:
 *   rect id="domain"        the domain's box;
 *   g id="disks"            with disks: one circle of radius R/2 per point,
 *                           in point order (no two overlap: the points are
 *                           at least R apart); with radii, of radius r_k/2
 *                           (these may overlap where the radius grows: a
 *                           later point keeps only out of the earlier
 *                           point's disk);
 *   g id="disk-copies"      with disks on a torus: the copies, shifted by
 *                           whole periods, of the disks that cross a side,
 *                           clipped to the box so the picture tiles;
 *   g id="points"           one small circle per point, in point order, of
 *                           radius dot (default R/8, with radii rmin/8).
 * With a shape the box is filled light grey without a stroke, and
 * pattern_domain.c adds (before the disks):
 *   path id="outline"       the domain filled white and outlined in black:
 *                           a polygon's rings as closed subpaths (fill-rule
 *                           evenodd); for a mask the pixel boundary, the
 *                           edges between inside and outside pixels merged
 *                           into runs, over a path id="mask" that fills the
 *                           inside pixels (one rectangle per run in a row);
 *   g id="clearances"       with fixed points: a dashed red circle of the
 *                           clearance around each, in file order;
 * and after the points:
 *   g id="fixed"            a red dot of radius 1.5 dot per fixed point.
 * Returns 0, or -1 with errno set.
 */
int pattern_write_svg(const struct pattern *p, int disks, const char *path);

/*
 * The PNG raster (pattern_png.c), 8-bit grey: white background, each point a
 * black dot of radius dot (default R/5, with radii rmin/5) but at least 1
 * pixel, anti-aliased (4 x 4 samples
 * per pixel); on a torus the dots crossing a side also show on the other
 * side. The longer side of the domain is size pixels, the other one keeps
 * the aspect ratio (at least 1 pixel). With a shape (pattern_domain.c) the
 * box outside the domain is light grey (224), the outline (a polygon's
 * rings, a mask's pixel boundary) a dark grey line (96) about a pixel wide,
 * and each fixed point a black ring of radius 1.6 dot (at least 2.5
 * pixels), drawn over the points. Returns 0, or -1
 * with errno set.
 */
int pattern_write_png(const struct pattern *p, unsigned size, const char *path);

/* The shape's parts of the pictures (pattern_domain.c); each returns 0, or -1
   (a write error; out of memory with errno ENOMEM). */
int pattern_svg_outline(FILE *f, const struct pattern *p, double line);
int pattern_svg_fixed(FILE *f, const struct pattern *p, double line, double dot, int clearances);
/* pix is w x h, top row first, scale pixels per unit length. */
int pattern_png_outline(unsigned char *pix, unsigned w, unsigned h, const struct pattern *p,
                        double scale);
void pattern_png_fixed(unsigned char *pix, unsigned w, unsigned h, const struct pattern *p,
                       double scale, double dot_px);

#endif /* POISSONDISK_PATTERN_PICTURES_H */
