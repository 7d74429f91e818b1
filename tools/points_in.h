/*
 * points_in.h - read point patterns from a text file, for --spectrum-from.
 *
 * One point per line, "x y" or "x,y" (so the txt and csv outputs read back;
 * a csv header line "x,y" is skipped), blank lines between patterns, '#'
 * starting a comment line. Several blank lines in a row count as one.
 * Plain C99.
 */
#ifndef POISSONDISK_POINTS_IN_H
#define POISSONDISK_POINTS_IN_H

#include <stddef.h>
#include <stdio.h>

struct patterns_in {
    double *xy;        /* every point, x,y interleaved, patterns one after another */
    size_t npoints;
    size_t *first;     /* pattern p is points first[p] .. first[p+1]-1 */
    size_t npatterns;
};

/*
 * Reads f to its end. Returns 0; -1 when out of memory or on a read error
 * (errno tells which); or the 1-based number of the first line that is not
 * a point, a comment, a header or blank (then nothing is kept).
 */
long patterns_read(FILE *f, struct patterns_in *out);

void patterns_free(struct patterns_in *p);

#endif /* POISSONDISK_POINTS_IN_H */
