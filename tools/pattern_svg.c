/*
 * pattern_svg.c - a point pattern as an SVG picture (see pattern_pictures.h).
 */
#include "pattern_pictures.h"

#include <stdio.h>

#define LONG_SIDE_PX 800.0

/*
 * Circles at the points shifted by (dx, dy), those that reach the box: of
 * radius r, or with radii (not NULL) of radius radii[k] * r for point k.
 */
static int circles(FILE *f, const struct pattern *p, double r, const double *radii, double dx,
                   double dy)
{
    const double *b = p->box;
    size_t k;

    for (k = 0; k < p->n; k++) {
        double x = p->xy[2 * k] + dx, y = p->xy[2 * k + 1] + dy;
        double rk = radii != NULL ? radii[k] * r : r;
        if (x + rk <= b[0] || x - rk >= b[2] || y + rk <= b[1] || y - rk >= b[3])
            continue;
        if (fprintf(f, "<circle cx=\"%.10g\" cy=\"%.10g\" r=\"%.10g\"/>\n", x,
                    b[1] + b[3] - y, rk) < 0)
            return -1;
    }
    return 0;
}

int pattern_write_svg(const struct pattern *p, int disks, const char *path)
{
    const double *b = p->box;
    double w = b[2] - b[0], h = b[3] - b[1], longer = w > h ? w : h;
    double line = longer / 1000.0, margin = p->radius / 2 + line;
    double vw = w + 2 * margin, vh = h + 2 * margin;
    double scale = LONG_SIDE_PX / (vw > vh ? vw : vh);
    double dot = p->dot > 0 ? p->dot : (p->radii != NULL ? p->rmin : p->radius) / 8;
    const struct pattern_shape *m = p->shape;
    int shaped = m != NULL;
    FILE *f = fopen(path, "w");
    int rc = 0, i, j;
    char close = p->periodic ? ')' : ']';

    if (f == NULL)
        return -1;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
               "width=\"%.0f\" height=\"%.0f\" viewBox=\"%.10g %.10g %.10g %.10g\">\n",
            vw * scale, vh * scale, b[0] - margin, b[1] - margin, vw, vh);
    /* A torus is half-open: its points lie in [x0,x1)x[y0,y1). */
    if (p->radii != NULL)
        fprintf(f, "<title>poissondisk: %zu points, radius map from %.10g to %.10g, domain "
                   "[%.10g,%.10g%cx[%.10g,%.10g%c%s</title>\n", p->n, p->rmin, p->radius,
                b[0], b[2], close, b[1], b[3], close, p->periodic ? ", periodic" : "");
    else
        fprintf(f, "<title>poissondisk: %zu points, R = %.10g, domain "
                   "[%.10g,%.10g%cx[%.10g,%.10g%c%s</title>\n", p->n, p->radius, b[0], b[2],
                close, b[1], b[3], close, p->periodic ? ", periodic" : "");
    /* "; K fixed points" only when there are some (%.0zu prints nothing for 0). */
    if (shaped)
        fprintf(f, "<desc>domain: %s%s%.0zu%s</desc>\n",
                m->rings_xy != NULL ? "a polygon (even-odd rings)"
                : m->inside != NULL ? "the inside pixels of a mask" : "the box",
                m->nfixed > 0 ? "; " : "", m->nfixed, m->nfixed > 0 ? " fixed points" : "");
    fprintf(f, "<desc>y grows upwards: the point (x, y) is drawn at (x, %.10g - y)</desc>\n",
            b[1] + b[3]);
    fprintf(f, "<defs><clipPath id=\"box\"><rect x=\"%.10g\" y=\"%.10g\" width=\"%.10g\" "
               "height=\"%.10g\"/></clipPath></defs>\n", b[0], b[1], w, h);
    /* A polygon or mask fills part of the box: the box grey, the domain white. */
    if (shaped && (m->rings_xy != NULL || m->inside != NULL))
        fprintf(f, "<rect id=\"domain\" x=\"%.10g\" y=\"%.10g\" width=\"%.10g\" "
                   "height=\"%.10g\" fill=\"#e6e6e6\" stroke=\"none\"/>\n", b[0], b[1], w, h);
    else
        fprintf(f, "<rect id=\"domain\" x=\"%.10g\" y=\"%.10g\" width=\"%.10g\" "
                   "height=\"%.10g\" fill=\"white\" stroke=\"black\" stroke-width=\"%.10g\"/>\n",
                b[0], b[1], w, h, line);
    if (shaped) {
        rc |= pattern_svg_outline(f, p, line);
        rc |= pattern_svg_fixed(f, p, line, dot, 1);
    }
    if (disks) {
        /* On a torus the disks are clipped to the box, and the parts that cross a
           side come back on the other side: the picture then tiles. */
        fprintf(f, "<g id=\"disks\" fill=\"#bcd3ee\" fill-opacity=\"0.8\" stroke=\"#2b5d9b\" "
                   "stroke-width=\"%.10g\"%s>\n", line / 2,
                p->periodic ? " clip-path=\"url(#box)\"" : "");
        rc |= circles(f, p, p->radii != NULL ? 0.5 : p->radius / 2, p->radii, 0, 0);
        fputs("</g>\n", f);
        if (p->periodic) {
            fprintf(f, "<g id=\"disk-copies\" fill=\"#bcd3ee\" fill-opacity=\"0.8\" "
                       "stroke=\"#2b5d9b\" stroke-width=\"%.10g\" clip-path=\"url(#box)\">\n",
                    line / 2);
            for (i = -1; i <= 1; i++)
                for (j = -1; j <= 1; j++)
                    if (i != 0 || j != 0)
                        rc |= circles(f, p, p->radii != NULL ? 0.5 : p->radius / 2,
                                      p->radii, i * w, j * h);
            fputs("</g>\n", f);
        }
    }
    fputs("<g id=\"points\" fill=\"black\">\n", f);
    rc |= circles(f, p, dot, NULL, 0, 0);
    fputs("</g>\n", f);
    if (shaped)
        rc |= pattern_svg_fixed(f, p, line, dot, 0);
    fputs("</svg>\n", f);
    if (ferror(f))
        rc = -1;
    if (fclose(f) != 0)
        rc = -1;
    return rc;
}
