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

/*
 * The same for a pattern with a radius per point (a radius map: radii[k]
 * for point k, from rmin to rmax), in units of the radii, on a plain
 * rectangle: *min_rule is the least |p_j - p_i| / r_i over the pairs i < j
 * (the variable-radius rule asks at least 1: a later point keeps out of
 * every earlier point's disk), *mean_nn the mean over the points of the
 * nearest-neighbour distance divided by the point's own radius. With equal
 * radii R both are pattern_nn_stats's values over R. The near pairs are found
 * by groups of radii (pattern_layers.h), O(N) at any ratio rmax / rmin; the
 * ring search above only decides what they leave open. Returns as
 * pattern_nn_stats.
 */
int pattern_field_stats(const double *xy, const double *radii, size_t n, const double box[4],
                        double rmin, double rmax, double *min_rule, double *mean_nn);

#endif /* POISSONDISK_PATTERN_STATS_H */
