/*
 * dart_grid.h - baseline: plain dart throwing with a background grid, stopped
 * after a run of consecutive misses (the classic non-maximal sampler).
 */
#ifndef BENCH_DART_GRID_H
#define BENCH_DART_GRID_H

#include <stddef.h>
#include <stdint.h>

/*
 * Default run of consecutive misses that ends the throwing. The chance that a
 * dart lands is the uncovered fraction p of the square, so the run ends once
 * p is of the order of 1/misses, whatever N is: the final coverage does not
 * depend on N and the cost stays O(N). 3000 = 100 x Bridson's k of 30; see
 * README.md, "Performance", for what it leaves uncovered.
 */
#define DART_DEFAULT_MISSES 3000

/*
 * Fills *xy (interleaved x,y, malloc'd, the caller frees it) and *count.
 * Returns 0, or -1 when memory runs out (then *xy is NULL).
 */
int dart_grid_sample(double radius, uint64_t seed, unsigned long misses, double **xy,
                     size_t *count);

#endif /* BENCH_DART_GRID_H */
