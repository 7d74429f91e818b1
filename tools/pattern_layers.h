/*
 * pattern_layers.h - near pairs of a variable-radius pattern, found in O(N)
 * whatever the ratio of the largest radius to the smallest (for the --stats
 * line of a radius map, see pattern_stats.h).
 *
 * The points are grouped by the power of two of their radius; each group
 * has its own grid, with cells at least twice as wide as its largest radius,
 * and each point looks at the 3x3 block of cells around it in the grid of
 * its own group and of every group above. A pair is so found whenever its
 * distance is under the cell side of the larger point's group. Plain C99.
 */
#ifndef POISSONDISK_PATTERN_LAYERS_H
#define POISSONDISK_PATTERN_LAYERS_H

#include <stddef.h>

/*
 * For the n points xy (x,y interleaved, n >= 2) with radii radii (all > 0):
 * nn_d2[k] the least squared distance from point k to another point found,
 * exact[k] 1 when nothing nearer can have been missed (else 0, nn_d2[k]
 * being only an upper bound, HUGE_VAL when nothing was found); *rule2 the
 * least d^2 / r_i^2 over the pairs i < j found. Every pair with d < 2 r_i
 * is found, so *rule2 is exact when below 4. Returns 0, or -1 when out of
 * memory.
 */
int pattern_layers_nearest(const double *xy, const double *radii, size_t n, double *nn_d2,
                           unsigned char *exact, double *rule2);

#endif /* POISSONDISK_PATTERN_LAYERS_H */
