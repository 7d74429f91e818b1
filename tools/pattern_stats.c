/*
 * pattern_stats.c - nearest-neighbour distances through a grid of cells
 * (see pattern_stats.h).
 */
#include "pattern_stats.h"
#include "pattern_kdtree.h"
#include "pattern_layers.h"

#include <math.h>
#include <stdlib.h>

struct grid {
    const double *xy;
    double x0, y0, w, h, cw, ch; /* the domain and the cell sides */
    long nx, ny;
    size_t *start;               /* the points of cell c: order[start[c] .. start[c+1]) */
    size_t *order;
    int periodic;
};

static long cell_of(double v, double lo, double side, long n)
{
    long c = (long)floor((v - lo) / side);
    return c < 0 ? 0 : c >= n ? n - 1 : c;
}

/* The difference a - b, on a torus the shortest one over the periods. */
static double diff(double a, double b, double period, int periodic)
{
    double d = a - b;
    if (periodic) {
        if (d > period / 2)
            d -= period;
        else if (d < -period / 2)
            d += period;
    }
    return d;
}

/*
 * The least squared distance from point i to another point j in cell (cx,
 * cy), below best; with radii (not NULL), in units of the radius of the
 * earlier point of the pair: d^2 / radii[min(i, j)]^2.
 */
static double nearest_in_cell(const struct grid *g, const double *radii, size_t i, long cx,
                              long cy, double best)
{
    size_t c, k;

    if (g->periodic) {
        cx = ((cx % g->nx) + g->nx) % g->nx;
        cy = ((cy % g->ny) + g->ny) % g->ny;
    } else if (cx < 0 || cy < 0 || cx >= g->nx || cy >= g->ny) {
        return best;
    }
    c = (size_t)(cy * g->nx + cx);
    for (k = g->start[c]; k < g->start[c + 1]; k++) {
        size_t j = g->order[k];
        double dx, dy, d2;
        if (j == i)
            continue;
        dx = diff(g->xy[2 * i], g->xy[2 * j], g->w, g->periodic);
        dy = diff(g->xy[2 * i + 1], g->xy[2 * j + 1], g->h, g->periodic);
        d2 = dx * dx + dy * dy;
        if (radii != NULL) {
            double r = radii[i < j ? i : j];
            d2 /= r * r;
        }
        if (d2 < best)
            best = d2;
    }
    return best;
}

/*
 * The nearest neighbour of point i, searched ring by ring around its cell:
 * its distance; with radii, the least distance in units of the earlier
 * point's radius (rmax the largest radius). Off the torus a ring visits only
 * the cells inside the grid, and once the rings have passed the grid's
 * edges along one axis the distance still to come grows by the other
 * axis's side alone (a thin domain: one row of cells, far taller than wide).
 */
static double nearest(const struct grid *g, size_t i, const double *radii, double rmax)
{
    long cx = cell_of(g->xy[2 * i], g->x0, g->cw, g->nx);
    long cy = cell_of(g->xy[2 * i + 1], g->y0, g->ch, g->ny);
    long widest = g->nx > g->ny ? g->nx : g->ny, ring, a, lo, hi;
    double best = HUGE_VAL, side, reach;
    int more_x, more_y;

    for (ring = 0;; ring++) {
        if (ring == 0) {
            best = nearest_in_cell(g, radii, i, cx, cy, best);
        } else {
            lo = g->periodic ? -ring : (-ring > -cx ? -ring : -cx);
            hi = g->periodic ? ring : (ring < g->nx - 1 - cx ? ring : g->nx - 1 - cx);
            for (a = lo; a <= hi; a++) {
                best = nearest_in_cell(g, radii, i, cx + a, cy - ring, best);
                best = nearest_in_cell(g, radii, i, cx + a, cy + ring, best);
            }
            lo = g->periodic ? -ring + 1 : (-ring + 1 > -cy ? -ring + 1 : -cy);
            hi = g->periodic ? ring - 1 : (ring - 1 < g->ny - 1 - cy ? ring - 1 : g->ny - 1 - cy);
            for (a = lo; a <= hi; a++) {
                best = nearest_in_cell(g, radii, i, cx - ring, cy + a, best);
                best = nearest_in_cell(g, radii, i, cx + ring, cy + a, best);
            }
        }
        /* Every cell seen: on a torus once 2 ring + 1 spans the grid. */
        if (g->periodic ? 2 * ring + 1 >= widest : ring >= widest)
            break;
        /* Whether the next ring has cells in the grid along each axis. */
        more_x = g->periodic || cx - ring > 0 || cx + ring < g->nx - 1;
        more_y = g->periodic || cy - ring > 0 || cy + ring < g->ny - 1;
        if (!more_x && !more_y)
            break;
        side = !more_x ? g->ch : !more_y ? g->cw : (g->cw < g->ch ? g->cw : g->ch);
        /* Every cell of the next ring is at least ring cell sides away (with
           radii: at least that over rmax in units of a radius). */
        reach = (double)ring * side / (radii != NULL ? rmax : 1.0);
        if (best <= reach * reach)
            break;
    }
    return sqrt(best);
}

/* Sorts the n points into a grid of about one point per cell, cells at least r wide. */
static int grid_build(struct grid *g_out, const double *xy, size_t n, const double box[4],
                      int periodic, double r)
{
    struct grid g;
    double cell;
    size_t k, ncells;

    g.xy = xy;
    g.x0 = box[0];
    g.y0 = box[1];
    g.w = box[2] - box[0];
    g.h = box[3] - box[1];
    g.periodic = periodic;
    /* About one point per cell, but cells at least r wide. */
    cell = sqrt(g.w * g.h / (double)n);
    cell = cell > r ? cell : r;
    g.nx = (long)fmax(1.0, fmin(floor(g.w / cell), 4.0 * (double)n));
    g.ny = (long)fmax(1.0, fmin(floor(g.h / cell), 4.0 * (double)n));
    g.cw = g.w / (double)g.nx;
    g.ch = g.h / (double)g.ny;
    ncells = (size_t)g.nx * (size_t)g.ny;
    g.start = calloc(ncells + 1, sizeof *g.start);
    g.order = malloc(n * sizeof *g.order);
    if (g.start == NULL || g.order == NULL) {
        free(g.start);
        free(g.order);
        return -1;
    }
    /* Counting sort of the points by cell. */
    for (k = 0; k < n; k++)
        g.start[cell_of(xy[2 * k + 1], g.y0, g.ch, g.ny) * g.nx
                + cell_of(xy[2 * k], g.x0, g.cw, g.nx) + 1]++;
    for (k = 0; k < ncells; k++)
        g.start[k + 1] += g.start[k];
    for (k = 0; k < n; k++) {
        size_t c = (size_t)(cell_of(xy[2 * k + 1], g.y0, g.ch, g.ny) * g.nx
                            + cell_of(xy[2 * k], g.x0, g.cw, g.nx));
        g.order[g.start[c]++] = k;
    }
    for (k = ncells; k > 0; k--) /* the fill moved each start to the next one's */
        g.start[k] = g.start[k - 1];
    g.start[0] = 0;
    *g_out = g;
    return 0;
}

/* Whether some cell holds over 64 points: the points crowd into a small part
   of the box (islands far apart), and the rings would read them all. */
static int crowded(const struct grid *g)
{
    size_t c, ncells = (size_t)g->nx * (size_t)g->ny;
    for (c = 0; c < ncells; c++)
        if (g->start[c + 1] - g->start[c] > 64)
            return 1;
    return 0;
}

int pattern_nn_stats(const double *xy, size_t n, const double box[4], int periodic, double r,
                     double *min_dist, double *mean_nn)
{
    struct grid g;
    double sum = 0.0, least = HUGE_VAL;
    size_t k;

    *min_dist = *mean_nn = NAN;
    if (n < 2)
        return 1;
    if (grid_build(&g, xy, n, box, periodic, r) != 0)
        return -1;
    if (!periodic && crowded(&g)) {
        struct pattern_kdtree t;
        free(g.start);
        free(g.order);
        if (pattern_kdtree_build(&t, xy, n) != 0)
            return -1;
        for (k = 0; k < n; k++) {
            double d = sqrt(pattern_kdtree_nearest2(&t, k));
            sum += d;
            least = d < least ? d : least;
        }
        pattern_kdtree_free(&t);
    } else {
        for (k = 0; k < n; k++) {
            double d = nearest(&g, k, NULL, 1.0);
            sum += d;
            least = d < least ? d : least;
        }
        free(g.start);
        free(g.order);
    }
    *min_dist = least;
    *mean_nn = sum / (double)n;
    return 0;
}

int pattern_field_stats(const double *xy, const double *radii, size_t n, const double box[4],
                        double rmin, double rmax, double *min_rule, double *mean_nn)
{
    struct grid g;
    double sum = 0.0, rule2, *nn_d2;
    unsigned char *exact;
    size_t k;
    int built = 0, rc = -1;

    *min_rule = *mean_nn = NAN;
    if (n < 2)
        return 1;
    nn_d2 = malloc(n * sizeof *nn_d2);
    exact = malloc(n);
    if (nn_d2 == NULL || exact == NULL
        || pattern_layers_nearest(xy, radii, n, nn_d2, exact, &rule2) != 0)
        goto out;
    /* The near pairs by groups of radii decide nearly everything in O(N); the
       rest (a point far from all others, a pattern breaking the rule by no
       margin) is searched in one grid ring by ring, exact at any cost. */
    if (rule2 >= 3.99) {
        if (grid_build(&g, xy, n, box, 0, rmin) != 0)
            goto out;
        built = 1;
        rule2 = HUGE_VAL;
        for (k = 0; k < n; k++) {
            double rule = nearest(&g, k, radii, rmax);
            rule2 = rule * rule < rule2 ? rule * rule : rule2;
        }
    }
    for (k = 0; k < n; k++) {
        double d;
        if (exact[k]) {
            d = sqrt(nn_d2[k]);
        } else {
            if (!built && grid_build(&g, xy, n, box, 0, rmin) != 0)
                goto out;
            built = 1;
            d = nearest(&g, k, NULL, 1.0);
        }
        sum += d / radii[k];
    }
    *min_rule = sqrt(rule2);
    *mean_nn = sum / (double)n;
    rc = 0;
out:
    if (built) {
        free(g.start);
        free(g.order);
    }
    free(nn_d2);
    free(exact);
    return rc;
}
