/*
 * pattern_stats.h - nearest-neighbour distances of a point pattern, for the
 * --stats line: the smallest one (the minimum pair distance) and their mean.
 *
 * The points are put in a grid of about one point per cell (cells at least
 * R wide), and each point's nearest neighbour is searched in square rings of
 * cells around its own, stopping when the next ring cannot hold anything
 * nearer: O(N) for the patterns the program makes, exact for any pattern.
 * On a torus, distances wrap around with the domain's sides as periods.
 * Plain C99.
 */
#ifndef POISSONDISK_PATTERN_STATS_H
#define POISSONDISK_PATTERN_STATS_H

#include <stddef.h>

/*
 * For the n points xy (x,y interleaved) in box (x0 y0 x1 y1), radius r the
 * pattern's radius (it sets the cell size), sets *min_dist and *mean_nn.
 * Returns 0, 1 when n < 2 (no neighbour: both NaN), or -1 when out of
 * memory.
 */
int pattern_nn_stats(const double *xy, size_t n, const double box[4], int periodic, double r,
                     double *min_dist, double *mean_nn);

#endif /* POISSONDISK_PATTERN_STATS_H */
