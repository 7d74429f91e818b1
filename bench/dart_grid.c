/*
 * dart_grid.c - plain dart throwing: darts uniform in the unit square, each
 * kept if it is at least R from every point so far (background grid of cell
 * R/sqrt(2)); stop after `misses` darts in a row were rejected.
 *
 * Run long enough this converges to the same law as the library's maximal
 * patterns (random sequential adsorption); stopped early, as everyone does,
 * it leaves a fraction of the square uncovered.
 */
#include "dart_grid.h"

#include <stdlib.h>

#include "background_grid.h"
#include "rng.h"

int dart_grid_sample(double radius, uint64_t seed, unsigned long misses, double **xy_out,
                     size_t *count_out) {
    struct background_grid grid;
    struct bench_rng rng;
    double *xy;
    size_t count = 0, capacity;
    unsigned long misses_in_a_row = 0;

    *xy_out = NULL;
    *count_out = 0;
    if (background_grid_init(&grid, radius) != 0) return -1;
    /* Worst case, one point per cell; untouched pages cost nothing. */
    capacity = background_grid_capacity(&grid);
    xy = malloc(2 * capacity * sizeof *xy);
    if (xy == NULL) {
        background_grid_free(&grid);
        return -1;
    }
    bench_rng_seed(&rng, seed);

    while (misses_in_a_row < misses) {
        double x = bench_rng_uniform(&rng), y = bench_rng_uniform(&rng);
        uint32_t cx = background_grid_coord(&grid, x), cy = background_grid_coord(&grid, y);
        if (background_grid_conflicts(&grid, xy, cx, cy, x, y)) {
            ++misses_in_a_row;
            continue;
        }
        xy[2 * count] = x;
        xy[2 * count + 1] = y;
        background_grid_insert(&grid, cx, cy, (uint32_t)count);
        ++count;
        misses_in_a_row = 0;
    }

    background_grid_free(&grid);
    *xy_out = xy;
    *count_out = count;
    return 0;
}
