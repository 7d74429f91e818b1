/* background_grid.c - allocation of the baselines' background grid. */
#include "background_grid.h"

#include <math.h>
#include <stdlib.h>

int background_grid_init(struct background_grid *g, double radius) {
    double cell = radius / sqrt(2.0), side = ceil(1.0 / cell);
    g->cells = NULL;
    if (!(radius > 0.0) || side * side >= 4294967295.0) return -1;
    g->side = (uint32_t)side;
    g->inverse_cell = 1.0 / cell;
    g->radius_squared = radius * radius;
    /* calloc: large blocks come zeroed from mmap, untouched cells cost no memory. */
    g->cells = calloc((size_t)g->side * g->side, sizeof *g->cells);
    return g->cells != NULL ? 0 : -1;
}

void background_grid_free(struct background_grid *g) {
    free(g->cells);
    g->cells = NULL;
}
