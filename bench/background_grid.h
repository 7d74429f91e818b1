/*
 * background_grid.h - the classic background grid of Bridson (2007) and of
 * grid dart throwing, shared so both baselines pay for exactly the same
 * conflict test.
 *
 * Cells are squares of side R/sqrt(2) over the unit square. Two points in one
 * cell would be less than R apart, so a valid pattern has at most one point
 * per cell and a cell holds just that point's index (plus one; 0 = empty).
 * Any point closer than R to a candidate lies within two cells of the
 * candidate's cell, so a conflict test looks at a 5x5 block.
 */
#ifndef BENCH_BACKGROUND_GRID_H
#define BENCH_BACKGROUND_GRID_H

#include <stddef.h>
#include <stdint.h>

struct background_grid {
    uint32_t *cells;       /* side*side entries: point index + 1, or 0 */
    uint32_t side;         /* cells per side of the unit square */
    double inverse_cell;   /* 1 / cell size */
    double radius_squared; /* R^2 */
};

/* Returns 0, or -1 if the grid would not fit (memory, or 2^32 cells). */
int background_grid_init(struct background_grid *g, double radius);
void background_grid_free(struct background_grid *g);

/* Cell row or column of a coordinate in [0, 1]; 1 itself goes to the last cell. */
static inline uint32_t background_grid_coord(const struct background_grid *g, double v) {
    uint32_t c = (uint32_t)(v * g->inverse_cell);
    return c < g->side ? c : g->side - 1;
}

/*
 * Nonzero if some point of xy (interleaved x,y) in the grid is closer than R
 * to (x, y). (cx, cy) is the cell of (x, y).
 */
static inline int background_grid_conflicts(const struct background_grid *g, const double *xy,
                                            uint32_t cx, uint32_t cy, double x, double y) {
    uint32_t x0 = cx >= 2 ? cx - 2 : 0, x1 = cx + 2 < g->side ? cx + 2 : g->side - 1;
    uint32_t y0 = cy >= 2 ? cy - 2 : 0, y1 = cy + 2 < g->side ? cy + 2 : g->side - 1;
    uint32_t i, j;
    /* An occupied own cell settles it at once; it is the common case near saturation. */
    if (g->cells[(size_t)cy * g->side + cx] != 0) return 1;
    for (j = y0; j <= y1; ++j) {
        const uint32_t *row = g->cells + (size_t)j * g->side;
        for (i = x0; i <= x1; ++i) {
            uint32_t p = row[i];
            if (p != 0) {
                double dx = xy[2 * (size_t)(p - 1)] - x, dy = xy[2 * (size_t)(p - 1) + 1] - y;
                if (dx * dx + dy * dy < g->radius_squared) return 1;
            }
        }
    }
    return 0;
}

static inline void background_grid_insert(struct background_grid *g, uint32_t cx, uint32_t cy,
                                          uint32_t point_index) {
    g->cells[(size_t)cy * g->side + cx] = point_index + 1;
}

/* The most points a valid pattern can have: one per cell. */
static inline size_t background_grid_capacity(const struct background_grid *g) {
    return (size_t)g->side * g->side;
}

#endif /* BENCH_BACKGROUND_GRID_H */
