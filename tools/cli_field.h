/*
 * cli_field.h - the radius map of the poissondisk program (--radius-map,
 * --rmin, --rmax): a grey-scale PGM image (pgm.h) becomes a radius field
 * over the domain, pds_set_radius_map (1.3). Grey level 0 (black) is the
 * radius rmin, the densest points; maxval (white) is rmax; in between the
 * radius is linear in the grey level. The image spans the domain, its top
 * row along y1: the rows are flipped, as the library's row 0 lies along y0.
 * Public API only; plain C99.
 */
#ifndef POISSONDISK_CLI_FIELD_H
#define POISSONDISK_CLI_FIELD_H

#include <stddef.h>

struct cli_field {
    const char *path;  /* --radius-map FILE ("-": standard input); NULL: no map */
    double rmin, rmax; /* --rmin, --rmax: the radii of black and of white; 0: not given */
    size_t w, h;       /* the map's size, the image's */
    double *r;         /* w * h radii, row 0 along y0 (the image's bottom row) */
    double lo, hi;     /* the smallest and the largest radius of the map */
};

/*
 * Reads the image of f->path and makes the map. Returns 0, or
 * CLI_EXIT_LIBRARY after a message on stderr ("PROG: --radius-map FILE:
 * why") when the file cannot be read or is not a valid PGM image.
 */
int cli_field_load(const char *prog, struct cli_field *f);

void cli_field_free(struct cli_field *f);

/*
 * The smallest radius in force when the largest one is largest: the map's
 * smallest radius, scaled as pds_refine scales the field (largest / f->hi).
 */
double cli_field_smallest(const struct cli_field *f, double largest);

/*
 * The map's radius at (x, y) of box (x0 y0 x1 y1), as the library computes
 * it: bilinear between pixel centres, constant beyond the outermost ones,
 * scaled as cli_field_smallest. For the pictures' clearance circles.
 */
double cli_field_at(const struct cli_field *f, const double box[4], double x, double y,
                    double largest);

#endif /* POISSONDISK_CLI_FIELD_H */
