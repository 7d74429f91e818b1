/*
 * region.c - the test model of a polygon domain and a grid of disks; see
 * region.h. Independent of the library: the even-odd rule by ray crossings
 * in double, distances by projection on each edge.
 */
#include "region.h"

#include <math.h>
#include <stdlib.h>

#include <check.h>

size_t region_vertices(const region *g)
{
    return g->nrings ? g->ends[g->nrings - 1] : 0;
}

void region_bounds(const region *g, double b[4])
{
    size_t i, n = region_vertices(g);

    b[0] = b[2] = g->xy[0];
    b[1] = b[3] = g->xy[1];
    for (i = 1; i < n; i++) {
        b[0] = fmin(b[0], g->xy[2 * i]);
        b[2] = fmax(b[2], g->xy[2 * i]);
        b[1] = fmin(b[1], g->xy[2 * i + 1]);
        b[3] = fmax(b[3], g->xy[2 * i + 1]);
    }
}

void region_edge(const region *g, size_t e, double *ax, double *ay, double *bx, double *by)
{
    size_t k = 0, start, next;

    while (g->ends[k] <= e)
        k++;
    start = k ? g->ends[k - 1] : 0;
    next = e + 1 < g->ends[k] ? e + 1 : start;
    *ax = g->xy[2 * e];
    *ay = g->xy[2 * e + 1];
    *bx = g->xy[2 * next];
    *by = g->xy[2 * next + 1];
}

static double segment_distance(double x, double y, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, t = 0.0;

    if (l2 > 0.0)
        t = fmax(0.0, fmin(1.0, ((x - ax) * dx + (y - ay) * dy) / l2));
    return hypot(x - (ax + t * dx), y - (ay + t * dy));
}

double region_outline_distance(const region *g, double x, double y)
{
    double best = INFINITY, ax, ay, bx, by;
    size_t e, n = region_vertices(g);

    for (e = 0; e < n; e++) {
        region_edge(g, e, &ax, &ay, &bx, &by);
        best = fmin(best, segment_distance(x, y, ax, ay, bx, by));
    }
    return best;
}

int region_contains(const region *g, double x, double y)
{
    double b[4], ax, ay, bx, by;
    size_t e, n = region_vertices(g);
    int odd = 0;

    if (!(x == x && y == y))
        return 0;
    for (e = 0; e < n; e++) {
        region_edge(g, e, &ax, &ay, &bx, &by);
        if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay))
            odd = !odd;
    }
    if (odd)
        return 1;
    region_bounds(g, b);
    return region_outline_distance(g, x, y) <= 1e-12 * fmax(b[2] - b[0], b[3] - b[1]);
}

/* Ring k alone, as a region of one ring. */
static region ring_alone(const region *g, size_t k, size_t *end)
{
    region r;
    size_t start = k ? g->ends[k - 1] : 0;

    *end = g->ends[k] - start;
    r.xy = g->xy + 2 * start;
    r.ends = end;
    r.nrings = 1;
    return r;
}

double region_area(const region *g)
{
    double sum = 0.0, ax, ay, bx, by;
    size_t e, j, k;

    /* Each ring's shoelace area, negative when its first vertex lies inside
     * an odd number of the other rings (a hole). */
    for (k = 0; k < g->nrings; k++) {
        size_t start = k ? g->ends[k - 1] : 0, depth = 0, len;
        double twice = 0.0;
        for (e = start; e < g->ends[k]; e++) {
            region_edge(g, e, &ax, &ay, &bx, &by);
            twice += ax * by - bx * ay;
        }
        for (j = 0; j < g->nrings; j++) {
            region r = ring_alone(g, j, &len);
            if (j != k)
                depth += (size_t)region_contains(&r, g->xy[2 * start], g->xy[2 * start + 1]);
        }
        sum += (depth % 2 ? -0.5 : 0.5) * fabs(twice);
    }
    return sum;
}

void grid_init(disk_grid *G, const double box[4], double cell)
{
    const size_t most = 1024;
    size_t i, cells;

    G->x0 = box[0];
    G->y0 = box[1];
    G->cell = cell;
    G->nx = (size_t)((box[2] - box[0]) / cell) + 1;
    G->ny = (size_t)((box[3] - box[1]) / cell) + 1;
    if (G->nx > most || G->ny > most) {
        G->cell = fmax(box[2] - box[0], box[3] - box[1]) / (double)(most - 1);
        G->nx = (size_t)((box[2] - box[0]) / G->cell) + 1;
        G->ny = (size_t)((box[3] - box[1]) / G->cell) + 1;
    }
    cells = G->nx * G->ny;
    G->len = calloc(cells, sizeof *G->len);
    G->cap = calloc(cells, sizeof *G->cap);
    G->items = calloc(cells, sizeof *G->items);
    ck_assert(G->len && G->cap && G->items);
    for (i = 0; i < cells; i++)
        G->items[i] = NULL;
    G->d = NULL;
    G->n = G->dcap = 0;
}

void grid_free(disk_grid *G)
{
    size_t i;

    for (i = 0; i < G->nx * G->ny; i++)
        free(G->items[i]);
    free(G->items);
    free(G->len);
    free(G->cap);
    free(G->d);
}

static size_t clamp_index(double v, size_t n)
{
    if (!(v > 0.0))
        return 0;
    return v >= (double)(n - 1) ? n - 1 : (size_t)v;
}

size_t grid_cell(const disk_grid *G, double x, double y)
{
    return clamp_index((y - G->y0) / G->cell, G->ny) * G->nx +
           clamp_index((x - G->x0) / G->cell, G->nx);
}

void grid_add(disk_grid *G, disk d)
{
    size_t i0 = clamp_index((d.x - d.r - G->x0) / G->cell, G->nx);
    size_t i1 = clamp_index((d.x + d.r - G->x0) / G->cell, G->nx);
    size_t j0 = clamp_index((d.y - d.r - G->y0) / G->cell, G->ny);
    size_t j1 = clamp_index((d.y + d.r - G->y0) / G->cell, G->ny);
    size_t i, j;

    if (G->n == G->dcap) {
        G->dcap = G->dcap ? 2 * G->dcap : 64;
        G->d = realloc(G->d, G->dcap * sizeof *G->d);
        ck_assert_ptr_nonnull(G->d);
    }
    for (j = j0; j <= j1; j++)
        for (i = i0; i <= i1; i++) {
            size_t c = j * G->nx + i;
            if (G->len[c] == G->cap[c]) {
                G->cap[c] = G->cap[c] ? 2 * G->cap[c] : 4;
                G->items[c] = realloc(G->items[c], G->cap[c] * sizeof *G->items[c]);
                ck_assert_ptr_nonnull(G->items[c]);
            }
            G->items[c][G->len[c]++] = G->n;
        }
    G->d[G->n++] = d;
}

int grid_covers(const disk_grid *G, double x, double y, long skip1, long skip2, double tol)
{
    size_t c = grid_cell(G, x, y), k;

    for (k = 0; k < G->len[c]; k++) {
        size_t i = G->items[c][k];
        double dx = x - G->d[i].x, dy = y - G->d[i].y, r = G->d[i].r * (1.0 + tol);
        if ((long)i != skip1 && (long)i != skip2 && dx * dx + dy * dy <= r * r)
            return 1;
    }
    return 0;
}

int grid_strictly_inside(const disk_grid *G, double x, double y, double shrink)
{
    size_t c = grid_cell(G, x, y), k;

    for (k = 0; k < G->len[c]; k++) {
        size_t i = G->items[c][k];
        double dx = x - G->d[i].x, dy = y - G->d[i].y, r = G->d[i].r * (1.0 - shrink);
        if (dx * dx + dy * dy < r * r)
            return 1;
    }
    return 0;
}

uint64_t ref_next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double ref_uniform(uint64_t *state)
{
    return (double)(ref_next(state) >> 11) * 0x1p-53;
}
