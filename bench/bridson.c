/*
 * bridson.c - plain Bridson sampling, written from the 2007 sketch:
 *
 *   start with one uniform point, active list = {it};
 *   while the active list is not empty:
 *     pick an active point p uniformly at random;
 *     try up to k = 30 candidates uniform (by area) in the annulus R..2R around p;
 *     accept the first that lies in the square and is at least R from every
 *     point (background grid of cell R/sqrt(2)), and make it active;
 *     if none was accepted, retire p.
 *
 * It is fast and valid (all pairs >= R) but neither maximal (gaps stay where
 * no candidate happened to land) nor distributed like dart throwing; that is
 * what the benchmark's coverage column shows.
 */
#include "bridson.h"

#include <math.h>
#include <stdlib.h>

#include "background_grid.h"
#include "rng.h"

int bridson_sample(double radius, uint64_t seed, double **xy_out, size_t *count_out) {
    const double two_pi = 6.283185307179586;
    struct background_grid grid;
    struct bench_rng rng;
    double *xy;
    uint32_t *active;
    size_t count = 0, active_count = 0, capacity;

    *xy_out = NULL;
    *count_out = 0;
    if (background_grid_init(&grid, radius) != 0) return -1;
    /* Sized for the worst case, one point per cell: only the pages actually
     * written count towards resident memory, and nothing is ever copied. */
    capacity = background_grid_capacity(&grid);
    xy = malloc(2 * capacity * sizeof *xy);
    active = malloc(capacity * sizeof *active);
    if (xy == NULL || active == NULL) {
        free(xy);
        free(active);
        background_grid_free(&grid);
        return -1;
    }
    bench_rng_seed(&rng, seed);

    xy[0] = bench_rng_uniform(&rng);
    xy[1] = bench_rng_uniform(&rng);
    background_grid_insert(&grid, background_grid_coord(&grid, xy[0]),
                           background_grid_coord(&grid, xy[1]), 0);
    active[active_count++] = 0;
    count = 1;

    while (active_count > 0) {
        uint32_t slot = bench_rng_below(&rng, (uint32_t)active_count);
        double px = xy[2 * (size_t)active[slot]], py = xy[2 * (size_t)active[slot] + 1];
        int attempt, accepted = 0;
        for (attempt = 0; attempt < BRIDSON_CANDIDATES; ++attempt) {
            /* Uniform by area in the annulus: r^2 uniform on [R^2, 4R^2]. */
            double r = radius * sqrt(1.0 + 3.0 * bench_rng_uniform(&rng));
            double angle = two_pi * bench_rng_uniform(&rng);
            double x = px + r * cos(angle), y = py + r * sin(angle);
            uint32_t cx, cy;
            if (x < 0.0 || x > 1.0 || y < 0.0 || y > 1.0) continue;
            cx = background_grid_coord(&grid, x);
            cy = background_grid_coord(&grid, y);
            if (background_grid_conflicts(&grid, xy, cx, cy, x, y)) continue;
            xy[2 * count] = x;
            xy[2 * count + 1] = y;
            background_grid_insert(&grid, cx, cy, (uint32_t)count);
            active[active_count++] = (uint32_t)count;
            ++count;
            accepted = 1;
            break;
        }
        if (!accepted) active[slot] = active[--active_count];
    }

    free(active);
    background_grid_free(&grid);
    *xy_out = xy;
    *count_out = count;
    return 0;
}
