/*
 * cli_report.h - what the poissondisk program tells on stderr: the --stats
 * line, and the message for a radius (or count) that does not suit the
 * domain. (The points and pictures are written by cli_outputs.c.) Uses the
 * public API only; plain C99.
 */
#ifndef POISSONDISK_CLI_REPORT_H
#define POISSONDISK_CLI_REPORT_H

#include <stddef.h>

#include "poissondisk.h"

#include "cli_domain.h"
#include "cli_field.h"

/* Where the points go, as the command line gave it. */
struct cli_where {
    double box[4]; /* --domain: x0 y0 x1 y1 */
    int periodic;  /* --periodic: a torus, the points in [x0,x1)x[y0,y1) */
    size_t count;  /* --count N, or 0 when --radius or --radius-map gives the radius */
    const struct cli_field *field; /* --radius-map, once loaded; NULL: one radius */
    struct cli_domain *shape;      /* --polygon, --mask, --fixed, once loaded (box is
                                      then a polygon's bounding box); NULL: none */
};

/*
 * Prints the --stats line to stderr: N, the radius (with the fewest digits
 * that read back exactly, so a chosen radius can be checked), the domain
 * (half-open and "periodic" on a torus; the bounding box followed by
 * "polygon" or "mask" and "fixed=K" with the domain options), the coverage
 * (the share of the domain where no point fits), maximal or not, verified,
 * then the packing density pi R^2 N / (4A) (the share covered by the disks
 * of radius R/2; A the polygon's or mask's area, when shaped),
 * the smallest pair distance and the mean nearest-neighbour distance in
 * units of R (pattern_stats.c; wrapped on a torus; "-" below two points),
 * and the seconds spent sampling. All are computed with lengths in units of
 * a power of two near the domain's size, so they stay finite from 1e-300 to
 * 1e308; the coverage is "-" where the library's free area, in user units,
 * cannot give it (overflowed or underflowed on a domain not maximal). In count mode maximality is asked of the
 * library, as a run that reached N points does not tell it. The distances
 * need a copy of the points (16 bytes each) while they are computed.
 * With a radius map (w->field) the radius is "R=RMIN..RMAX (radius map)",
 * the smallest and largest radius of the field, and the spacing is in units
 * of the points' own radii r_i (the suffix "r"): packing sum(pi r_i^2)/(4A),
 * min_dist the least |p_j - p_i| / r_i over the pairs i < j (at least 1 by
 * the rule), mean_nn the mean nearest-neighbour distance over the point's
 * own radius (pattern_field_stats); with equal radii, the values above.
 */
/* The domain as "[x0,x1]x[y0,y1]", half-open "[x0,x1)x[y0,y1)" on a torus, in buf. */
const char *cli_domain_text(char *buf, size_t size, const struct cli_where *w);

void cli_print_stats(const char *prog, const pds_sampler *s, const struct cli_where *w,
                     int maximal, int verified, double seconds);

/*
 * The message for PDS_ERANGE ("radius R is too small for the domain ...",
 * or on a torus, where the radius may also be too large, "... does not suit
 * the periodic domain ..." with the library's reason); returns 2.
 */
int cli_range_error(const char *prog, const struct cli_where *w, double radius,
                    const char *msg);

#endif /* POISSONDISK_CLI_REPORT_H */
