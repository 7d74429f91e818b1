/*
 * cli_domain.h - the domain files of the poissondisk program: --polygon FILE
 * (GeoJSON or "x y" text, shape_files.h), --mask FILE (a PGM image, pgm.h)
 * and --fixed FILE ("x y [clearance]" lines), given to the library as
 * pds_set_polygon, pds_set_mask and pds_set_fixed (1.4).
 *
 * The files are read whole, and every error in them reported, before the
 * sampler exists and so before any output is opened: a malformed file
 * leaves no output behind. What only the library judges (a ring with fewer
 * than 3 distinct vertices, an outline that encloses nothing) comes back
 * from pds_set_polygon; its message names the ring and vertex from 0, and
 * the program adds where that vertex is in the file: the line for a text
 * file, the ring in file order (counted from 1) for GeoJSON.
 *
 * A mask pixel is inside when darker than mid-grey (2 g < maxval). The
 * image spans the rectangle of --domain, its top row along y1: the rows are
 * flipped, as the library's row 0 lies along y0 (as cli_field.c does).
 * Public API only; plain C99.
 */
#ifndef POISSONDISK_CLI_DOMAIN_H
#define POISSONDISK_CLI_DOMAIN_H

#include <stddef.h>

#include "poissondisk.h"

#include "shape_files.h"

struct cli_domain {
    const char *polygon;       /* --polygon FILE; NULL: not given */
    const char *mask;          /* --mask FILE; NULL: not given */
    const char *fixed;         /* --fixed FILE; NULL: not given */
    int polygon_is_text;       /* the polygon file is "x y" lines, not GeoJSON */
    struct shape_rings rings;  /* the polygon as read */
    size_t mask_w, mask_h;     /* the mask's size, the image's */
    unsigned char *inside;     /* mask_w * mask_h, 1 inside; row 0 along y0 */
    size_t mask_c0, mask_c1;   /* the inside pixels' first and last column */
    size_t mask_r0, mask_r1;   /* and row (row 0 along y0) */
    struct fixed_points points;/* the fixed points as read (clearance 0: not given) */
    double radius0;            /* pds_radius as the run starts: the library scales every
                                  clearance by pds_radius / radius0 (--refine, --count) */
    double area;               /* the domain's area, for --stats; 0: the box's */
};

/* Nonzero when --polygon or --mask shapes the domain. */
int cli_domain_shaped(const struct cli_domain *d);

/*
 * Reads the files given, in the order polygon, mask, fixed points. With a
 * polygon, box (x0 y0 x1 y1, in: --domain) becomes the vertices' bounding
 * box, as the library makes it; a mask spans box. Checks what the library
 * would only find at the first point: a fixed point outside box (with a
 * mask, outside its inside pixels' bounding box). Returns 0,
 * or CLI_EXIT_LIBRARY after "PROG: --OPTION FILE: WHERE: WHAT" on stderr.
 */
int cli_domain_load(const char *prog, struct cli_domain *d, double box[4]);

/*
 * Gives the loaded domain to s (after pds_set_domain): the polygon or the
 * mask, then (once *area_out is measured: the domain's area, NULL: not
 * wanted) the fixed points. Returns 0 or an exit status after a message
 * naming the file.
 */
int cli_domain_configure(const char *prog, pds_sampler *s, const struct cli_domain *d,
                         double *area_out);

void cli_domain_free(struct cli_domain *d);

#endif /* POISSONDISK_CLI_DOMAIN_H */
