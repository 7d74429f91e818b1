/*
 * pattern_check.c - minimum distance and probe coverage through a bucket grid.
 *
 * The grid has cells a little larger than R, so every point closer than R to
 * a point (or to a probe) lies in the 3x3 block of cells around it, whatever
 * the pattern: unlike the baselines' one-point-per-cell grid, this one also
 * holds invalid patterns and then reports them. Points are stored sorted by
 * cell (counting sort), so a block scan reads contiguous memory. On the unit
 * torus the blocks wrap around, and a wrapped cell's points are shifted by the
 * period that brings them next to the one asked about.
 */
#include "pattern_check.h"

#include <math.h>
#include <stdlib.h>

#include "rng.h"

/* Fixed, so the probe set depends on the lattice side alone. */
#define PROBE_SEED 0x5eed0f9b0be5ULL

struct bucket_grid {
    uint32_t side;     /* cells per side */
    int periodic;      /* the unit torus: neighbours wrap around */
    uint32_t *start;   /* side*side + 1 offsets into sorted */
    double *sorted;    /* the points, interleaved x,y, grouped by cell */
};

static uint32_t cell_coord(const struct bucket_grid *g, double v) {
    double c = v * (double)g->side;
    if (!(c > 0.0)) return 0; /* negative or NaN: points outside are flagged apart */
    return c < (double)g->side ? (uint32_t)c : g->side - 1;
}

static size_t cell_of(const struct bucket_grid *g, double x, double y) {
    return (size_t)cell_coord(g, y) * g->side + cell_coord(g, x);
}

/* Cell (cx + dx, cy + dy) wrapped on the torus, with the shift of its points
 * towards (cx, cy); 0 when it lies outside the square. */
static int neighbour(const struct bucket_grid *g, uint32_t cx, uint32_t cy, int dx, int dy,
                     size_t *cell, double *sx, double *sy) {
    long nx = (long)cx + dx, ny = (long)cy + dy, side = (long)g->side;
    *sx = *sy = 0.0;
    if (nx < 0 || nx >= side || ny < 0 || ny >= side) {
        if (!g->periodic) return 0;
        if (nx < 0) nx += side, *sx = -1.0;
        else if (nx >= side) nx -= side, *sx = 1.0;
        if (ny < 0) ny += side, *sy = -1.0;
        else if (ny >= side) ny -= side, *sy = 1.0;
    }
    *cell = (size_t)ny * g->side + (size_t)nx;
    return 1;
}

/* Smallest squared distance from (x, y) to the points of cell c shifted by (sx, sy). */
static double closest_in(const struct bucket_grid *g, size_t c, double x, double y, double sx,
                         double sy, double best) {
    uint32_t b;
    for (b = g->start[c]; b < g->start[c + 1]; ++b) {
        double dx = g->sorted[2 * (size_t)b] + sx - x, dy = g->sorted[2 * (size_t)b + 1] + sy - y;
        double d2 = dx * dx + dy * dy;
        if (d2 < best) best = d2;
    }
    return best;
}

static int bucket_grid_build(struct bucket_grid *g, const double *xy, size_t n, double radius,
                             int periodic) {
    /* 1e-9 of slack: rounding in the cell index can never split a close pair
     * across non-adjacent cells. */
    double side = floor(1.0 / (radius * (1.0 + 1e-9)));
    size_t cells, i;
    if (side < 1.0) side = 1.0;
    if (side > 65535.0) return -1; /* 2^32 cells: far beyond any benchmarked size */
    g->side = (uint32_t)side;
    g->periodic = periodic;
    cells = (size_t)g->side * g->side;
    g->start = calloc(cells + 1, sizeof *g->start);
    g->sorted = malloc((n > 0 ? 2 * n : 1) * sizeof *g->sorted);
    if (g->start == NULL || g->sorted == NULL || n >= UINT32_MAX) {
        free(g->start);
        free(g->sorted);
        return -1;
    }
    for (i = 0; i < n; ++i) ++g->start[cell_of(g, xy[2 * i], xy[2 * i + 1]) + 1];
    for (i = 0; i < cells; ++i) g->start[i + 1] += g->start[i];
    /* start[c] runs ahead while filling and ends at start[c + 1]; shift back after. */
    for (i = 0; i < n; ++i) {
        size_t c = cell_of(g, xy[2 * i], xy[2 * i + 1]);
        uint32_t slot = g->start[c]++;
        g->sorted[2 * (size_t)slot] = xy[2 * i];
        g->sorted[2 * (size_t)slot + 1] = xy[2 * i + 1];
    }
    for (i = cells; i > 0; --i) g->start[i] = g->start[i - 1];
    g->start[0] = 0;
    return 0;
}

static void bucket_grid_free(struct bucket_grid *g) {
    free(g->start);
    free(g->sorted);
}

/* Smallest squared distance from point slot a to any later point in its cell
 * or to any point in the four cells after it (right, and the three above), so
 * each pair is looked at once (on a torus of one or two cells a side, some
 * twice: harmless for a minimum). */
static double closest_later(const struct bucket_grid *g, uint32_t cx, uint32_t cy, uint32_t a,
                            double best) {
    static const int step[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    double x = g->sorted[2 * (size_t)a], y = g->sorted[2 * (size_t)a + 1], sx, sy;
    size_t own = (size_t)cy * g->side + cx, c;
    uint32_t b;
    int k;
    for (b = a + 1; b < g->start[own + 1]; ++b) {
        double dx = g->sorted[2 * (size_t)b] - x, dy = g->sorted[2 * (size_t)b + 1] - y;
        double d2 = dx * dx + dy * dy;
        if (d2 < best) best = d2;
    }
    for (k = 0; k < 4; ++k)
        if (neighbour(g, cx, cy, step[k][0], step[k][1], &c, &sx, &sy))
            best = closest_in(g, c, x, y, sx, sy, best);
    return best;
}

/* Nonzero if some point lies within R of (x, y) (up to 1e-12 relative). */
static int covered(const struct bucket_grid *g, double x, double y, double reach2) {
    uint32_t cx = cell_coord(g, x), cy = cell_coord(g, y);
    if (g->periodic) {
        double sx, sy;
        size_t c;
        int dx, dy;
        for (dy = -1; dy <= 1; ++dy)
            for (dx = -1; dx <= 1; ++dx)
                if (neighbour(g, cx, cy, dx, dy, &c, &sx, &sy) &&
                    closest_in(g, c, x, y, sx, sy, HUGE_VAL) <= reach2)
                    return 1;
        return 0;
    }
    uint32_t x0 = cx > 0 ? cx - 1 : 0, x1 = cx + 1 < g->side ? cx + 1 : cx;
    uint32_t y0 = cy > 0 ? cy - 1 : 0, y1 = cy + 1 < g->side ? cy + 1 : cy;
    uint32_t j, b;
    for (j = y0; j <= y1; ++j) {
        /* The cells of one row are adjacent in sorted: one contiguous run. */
        size_t row = (size_t)j * g->side;
        for (b = g->start[row + x0]; b < g->start[row + x1 + 1]; ++b) {
            double dx = g->sorted[2 * (size_t)b] - x, dy = g->sorted[2 * (size_t)b + 1] - y;
            if (dx * dx + dy * dy <= reach2) return 1;
        }
    }
    return 0;
}

uint32_t pattern_probe_side(size_t target_points) {
    double side = ceil(sqrt((double)PATTERN_PROBES_PER_POINT * (double)target_points));
    if (side < 1.0) side = 1.0;
    return side < PATTERN_PROBE_SIDE_MAX ? (uint32_t)side : PATTERN_PROBE_SIDE_MAX;
}

int pattern_check(const double *xy, size_t n, double radius, int periodic, uint32_t probe_side,
                  struct pattern_check *out) {
    struct bucket_grid grid;
    struct bench_rng rng;
    double best = HUGE_VAL, reach2 = radius * radius * (1.0 + 1e-12);
    int inside = 1;
    uint32_t cx, cy, a, i, j;
    size_t p;

    if (bucket_grid_build(&grid, xy, n, radius, periodic) != 0) return -1;
    for (p = 0; p < n; ++p) {
        double x = xy[2 * p], y = xy[2 * p + 1];
        if (!(x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0)) inside = 0;
        if (periodic && (x == 1.0 || y == 1.0)) inside = 0; /* the torus is [0,1)^2 */
    }
    for (cy = 0; cy < grid.side; ++cy)
        for (cx = 0; cx < grid.side; ++cx) {
            size_t c = (size_t)cy * grid.side + cx;
            for (a = grid.start[c]; a < grid.start[c + 1]; ++a) best = closest_later(&grid, cx, cy, a, best);
        }
    out->min_distance = sqrt(best);
    out->min_distance_ok = inside && best >= radius * radius * (1.0 - 1e-12);

    /* Jittered lattice, row by row: neighbouring probes hit neighbouring cells. */
    bench_rng_seed(&rng, PROBE_SEED);
    out->probes = (uint64_t)probe_side * probe_side;
    out->uncovered = 0;
    for (j = 0; j < probe_side; ++j)
        for (i = 0; i < probe_side; ++i) {
            double x = ((double)i + bench_rng_uniform(&rng)) / (double)probe_side;
            double y = ((double)j + bench_rng_uniform(&rng)) / (double)probe_side;
            if (!covered(&grid, x, y, reach2)) ++out->uncovered;
        }
    bucket_grid_free(&grid);
    return 0;
}
