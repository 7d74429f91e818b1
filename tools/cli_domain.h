/*
 * cli_domain.h - the domain files of the poissondisk program: --polygon FILE
 * (GeoJSON or "x y" text, shape_files.h) and --mask FILE (a PGM image,
 * pgm.h), given to the library as pds_set_polygon and pds_set_mask (1.4).
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
    struct shape_rings rings;  /* the polygon as read */
    size_t mask_w, mask_h;     /* the mask's size, the image's */
    unsigned char *inside;     /* mask_w * mask_h, 1 inside; row 0 along y0 */
    double area;               /* the domain's area, for --stats; 0: the box's */
};

/* Nonzero when --polygon or --mask shapes the domain. */
int cli_domain_shaped(const struct cli_domain *d);

/*
 * Reads the file given. With a polygon, box (x0 y0 x1 y1, in: --domain)
 * becomes the vertices' bounding box, as the library makes it; a mask spans
 * box. Returns 0, or CLI_EXIT_LIBRARY after "PROG: --OPTION FILE: WHERE:
 * WHAT" on stderr.
 */
int cli_domain_load(const char *prog, struct cli_domain *d, double box[4]);

/*
 * Gives the loaded domain to s (after pds_set_domain): the polygon or the
 * mask; a polygon's area is then measured into *area_out (NULL: not
 * wanted). Returns 0 or an exit status after a message naming the file.
 */
int cli_domain_configure(const char *prog, pds_sampler *s, const struct cli_domain *d,
                         double *area_out);

void cli_domain_free(struct cli_domain *d);

#endif /* POISSONDISK_CLI_DOMAIN_H */
