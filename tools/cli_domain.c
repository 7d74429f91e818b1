/*
 * cli_domain.c - the domain files of the poissondisk program (see
 * cli_domain.h): reading them, and giving them to the library.
 */
#include "cli_domain.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_sample.h"
#include "pgm.h"

int cli_domain_shaped(const struct cli_domain *d)
{
    return d != NULL && (d->polygon != NULL || d->mask != NULL);
}

/* The blanks of a text line (shape_text.c), and those that may precede a JSON value. */
static int is_blank(int c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/*
 * Where the index-th vertex (or point) of a text file is: the number of its
 * line, counting from 1, or 0 when the file cannot be read again or is
 * GeoJSON (*json set: its first non-blank character is '{' or '['). A
 * vertex is a line with something before any '#' (shape_files.h: comment
 * and blank lines hold none), so the index-th such line, after a UTF-8
 * byte-order mark. Read again only for a message.
 */
static size_t data_line(const char *path, size_t index, int *json)
{
    FILE *f = fopen(path, "rb");
    unsigned char bom[3];
    size_t line = 1, seen = 0, found = 0;
    int c = EOF, content = 0, comment = 0, looked = 0;

    *json = 0;
    if (f == NULL)
        return 0;
    if (fread(bom, 1, 3, f) != 3 || memcmp(bom, "\xef\xbb\xbf", 3) != 0)
        rewind(f);
    while ((c = getc(f)) != EOF) {
        if (!looked && !is_blank(c) && c != '\n') {
            looked = 1;
            if (c == '{' || c == '[') {
                *json = 1;
                break;
            }
        }
        if (c == '\n') {
            if (content && seen++ == index) {
                found = line;
                break;
            }
            line++;
            content = comment = 0;
        } else if (c == '#') {
            comment = 1;
        } else if (!comment && !is_blank(c)) {
            content = 1;
        }
    }
    if (c == EOF && content && seen == index) /* the last line, without a newline */
        found = line;
    fclose(f);
    return found;
}

/* "line N" for the index-th vertex or point of a text file, "" when it cannot say. */
static const char *where_text(char *buf, size_t size, const char *path, size_t index)
{
    int json;
    size_t line = data_line(path, index, &json);

    if (line > 0)
        snprintf(buf, size, "line %zu: ", line);
    else
        buf[0] = '\0';
    return buf;
}

static int load_mask(const char *prog, struct cli_domain *d)
{
    FILE *in = fopen(d->mask, "rb");
    struct pgm img;
    char why[160];
    size_t row, col, count = 0;
    int rc;

    if (in == NULL) {
        fprintf(stderr, "%s: --mask %s: cannot read it: %s\n", prog, d->mask, strerror(errno));
        return CLI_EXIT_LIBRARY;
    }
    rc = pgm_read(in, &img, why, sizeof why);
    fclose(in);
    if (rc != 0) {
        fprintf(stderr, "%s: --mask %s: %s\n", prog, d->mask, why);
        return CLI_EXIT_LIBRARY;
    }
    d->mask_w = img.width;
    d->mask_h = img.height;
    d->inside = malloc(d->mask_w * d->mask_h);
    if (d->inside == NULL) {
        pgm_free(&img);
        fprintf(stderr, "%s: --mask %s: out of memory for a %zu x %zu mask\n", prog, d->mask,
                d->mask_w, d->mask_h);
        return CLI_EXIT_LIBRARY;
    }
    /* The image's top row is the domain's top (y1); the mask's row 0 lies along y0. */
    d->mask_c0 = d->mask_r0 = (size_t)-1;
    d->mask_c1 = d->mask_r1 = 0;
    for (row = 0; row < d->mask_h; row++)
        for (col = 0; col < d->mask_w; col++) {
            unsigned g = img.pix[row * d->mask_w + col];
            unsigned char in_it = 2u * g < img.maxval; /* darker than mid-grey */
            size_t r = d->mask_h - 1 - row;
            d->inside[r * d->mask_w + col] = in_it;
            count += in_it;
            if (in_it) {
                d->mask_c0 = col < d->mask_c0 ? col : d->mask_c0;
                d->mask_c1 = col > d->mask_c1 ? col : d->mask_c1;
                d->mask_r0 = r < d->mask_r0 ? r : d->mask_r0;
                d->mask_r1 = r > d->mask_r1 ? r : d->mask_r1;
            }
        }
    pgm_free(&img);
    if (count == 0) {
        fprintf(stderr, "%s: --mask %s: no pixel is darker than mid-grey, so nothing is "
                        "inside (the domain is the dark pixels)\n", prog, d->mask);
        return CLI_EXIT_LIBRARY;
    }
    /* Exact: whole pixels of a box the library and the pictures share. */
    d->area = (double)count / (double)(d->mask_w * d->mask_h);
    return 0;
}

/*
 * The domain's bounding box as the library takes it for fixed points: a
 * mask's is the box of its inside pixels within box (the rectangle it spans),
 * else box itself.
 */
static void mask_or_box(const struct cli_domain *d, const double box[4], double out[4])
{
    double pw, ph;

    memcpy(out, box, 4 * sizeof out[0]);
    if (d->mask == NULL)
        return;
    pw = (box[2] - box[0]) / (double)d->mask_w;
    ph = (box[3] - box[1]) / (double)d->mask_h;
    out[0] = box[0] + (double)d->mask_c0 * pw;
    out[2] = d->mask_c1 + 1 == d->mask_w ? box[2] : box[0] + (double)(d->mask_c1 + 1) * pw;
    out[1] = box[1] + (double)d->mask_r0 * ph;
    out[3] = d->mask_r1 + 1 == d->mask_h ? box[3] : box[1] + (double)(d->mask_r1 + 1) * ph;
}

int cli_domain_load(const char *prog, struct cli_domain *d, double box[4])
{
    char msg[512], where[48];
    size_t k;

    if (d->polygon != NULL) {
        const struct shape_rings *r = &d->rings;
        if (shape_rings_read(d->polygon, &d->rings, msg, sizeof msg) != 0) {
            fprintf(stderr, "%s: --polygon %s\n", prog, msg);
            return CLI_EXIT_LIBRARY;
        }
        /* The library's domain is the polygon's bounding box; the outputs use it too. */
        box[0] = box[2] = r->xy[0];
        box[1] = box[3] = r->xy[1];
        for (k = 1; k < r->nvertices; k++) {
            double x = r->xy[2 * k], y = r->xy[2 * k + 1];
            box[0] = x < box[0] ? x : box[0];
            box[2] = x > box[2] ? x : box[2];
            box[1] = y < box[1] ? y : box[1];
            box[3] = y > box[3] ? y : box[3];
        }
    }
    if (d->mask != NULL) {
        int rc = load_mask(prog, d);
        if (rc != 0)
            return rc;
        d->area *= (box[2] - box[0]) * (box[3] - box[1]);
    }
    if (d->fixed != NULL) {
        const struct fixed_points *p = &d->points;
        double fbox[4];
        mask_or_box(d, box, fbox);
        if (fixed_points_read(d->fixed, &d->points, msg, sizeof msg) != 0) {
            fprintf(stderr, "%s: --fixed %s\n", prog, msg);
            return CLI_EXIT_LIBRARY;
        }
        /* Within a few rounding steps of the box counts as on it, as in the
         * library (a mask's pixel line computed another way). */
        double slack = fabs(fbox[0]);
        for (k = 1; k < 4; k++)
            slack = fabs(fbox[k]) > slack ? fabs(fbox[k]) : slack;
        slack *= 8.0 * DBL_EPSILON;
        for (k = 0; k < p->n; k++) {
            double x = p->xy[2 * k], y = p->xy[2 * k + 1];
            if (x < fbox[0] - slack || x > fbox[2] + slack || y < fbox[1] - slack || y > fbox[3] + slack) {
                fprintf(stderr, "%s: --fixed %s: %sthe point (%g, %g) lies outside the "
                                "domain's bounding box [%g,%g]x[%g,%g]\n", prog, d->fixed,
                        where_text(where, sizeof where, d->fixed, k), x, y, fbox[0], fbox[2],
                        fbox[1], fbox[3]);
                return CLI_EXIT_LIBRARY;
            }
        }
    }
    return 0;
}

/*
 * The library's message for a refused polygon names "ring K vertex V"
 * (from 0); this finds the vertex in the file. Writes "line N" (text) or
 * "ring K+1 in file order" (GeoJSON, which keeps no line per ring) into buf,
 * "" when the message names no ring.
 */
static const char *ring_place(char *buf, size_t size, const struct cli_domain *d,
                              const char *libmsg)
{
    const struct shape_rings *r = &d->rings;
    const char *p = strstr(libmsg, "ring ");
    size_t ring, vertex = 0, index, line;
    int json;

    buf[0] = '\0';
    if (p == NULL || sscanf(p, "ring %zu", &ring) != 1 || ring >= r->nrings)
        return buf;
    if ((p = strstr(p, "vertex ")) != NULL && sscanf(p, "vertex %zu", &vertex) != 1)
        vertex = 0;
    index = (ring > 0 ? r->ring_ends[ring - 1] : 0) + vertex;
    if (index >= r->ring_ends[ring])
        index = ring > 0 ? r->ring_ends[ring - 1] : 0;
    line = data_line(d->polygon, index, &json);
    if (line > 0)
        snprintf(buf, size, "line %zu: ", line);
    else if (json)
        snprintf(buf, size, "ring %zu in file order (the library's ring %zu): ", ring + 1, ring);
    return buf;
}

int cli_domain_configure(const char *prog, pds_sampler *s, const struct cli_domain *d,
                         double *area_out)
{
    char where[64];
    int rc;

    if (d->polygon != NULL) {
        const struct shape_rings *r = &d->rings;
        if ((rc = pds_set_polygon(s, r->xy, r->ring_ends, r->nrings)) < 0) {
            const char *msg = pds_errmsg(s);
            fprintf(stderr, "%s: --polygon %s: %s%s\n", prog, d->polygon,
                    ring_place(where, sizeof where, d, msg), msg);
            return CLI_EXIT_LIBRARY;
        }
        /* The whole domain's area, before the first point (pds_free_area). */
        if (area_out != NULL)
            *area_out = pds_free_area(s);
    }
    if (d->mask != NULL && (rc = pds_set_mask(s, d->mask_w, d->mask_h, d->inside)) < 0) {
        fprintf(stderr, "%s: --mask %s: %s\n", prog, d->mask, pds_errmsg(s));
        return CLI_EXIT_LIBRARY;
    }
    if (d->fixed != NULL && d->points.n > 0
        && (rc = pds_set_fixed(s, d->points.xy, d->points.clearance, d->points.n)) < 0) {
        fprintf(stderr, "%s: --fixed %s: %s\n", prog, d->fixed, pds_errmsg(s));
        return CLI_EXIT_LIBRARY;
    }
    return 0;
}

void cli_domain_free(struct cli_domain *d)
{
    shape_rings_free(&d->rings);
    fixed_points_free(&d->points);
    free(d->inside);
    d->inside = NULL;
}
