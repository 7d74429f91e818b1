/*
 * pattern_layers.c - near pairs through one grid per power of two of the
 * radius (see pattern_layers.h).
 */
#include "pattern_layers.h"

#include <math.h>
#include <stdlib.h>

#define CLASSES 64
/* Cells at least REACH times as wide as the largest radius of their group:
   a maximal pattern's nearest neighbours are within twice the radius. */
#define REACH 2.0

struct layer {
    size_t count;               /* points in the group */
    double rmax;                /* their largest radius */
    double x0, y0, x1, y1;      /* their bounding box */
    double cw, ch;              /* the cell sides */
    long nx, ny;
    double reach;               /* a point outside the 3x3 block is at least this far */
    size_t *start;              /* the points of cell c: order[start[c] .. start[c+1]) */
    size_t *order;
};

static long cell_of(double v, double lo, double side, long n)
{
    long c;
    if (n <= 1)
        return 0;
    c = (long)floor((v - lo) / side);
    return c < 0 ? 0 : c >= n ? n - 1 : c;
}

static size_t cell_index(const struct layer *L, const double *p)
{
    return (size_t)(cell_of(p[1], L->y0, L->ch, L->ny) * L->nx
                    + cell_of(p[0], L->x0, L->cw, L->nx));
}

/* The group of a radius: the power of two of r / rmin. */
static int class_of(double r, double rmin)
{
    int e;
    frexp(r / rmin, &e);
    e -= 1;
    return e < 0 ? 0 : e >= CLASSES ? CLASSES - 1 : e;
}

/* The cells of a group: at least REACH rmax wide, and no more than about 4 per point. */
static int layer_build(struct layer *L, const double *xy, const unsigned char *cls, int c,
                       size_t n)
{
    double w = L->x1 - L->x0, h = L->y1 - L->y0, cell = REACH * L->rmax;
    double fewest = sqrt(w * h / (4.0 * (double)L->count + 16.0));
    size_t k, ncells;

    cell = cell > fewest ? cell : fewest;
    L->nx = (long)fmax(1.0, floor(w / cell));
    L->ny = (long)fmax(1.0, floor(h / cell));
    L->cw = w / (double)L->nx;
    L->ch = h / (double)L->ny;
    /* One cell across an axis excludes nothing along it. */
    L->reach = fmin(L->nx > 1 ? L->cw : HUGE_VAL, L->ny > 1 ? L->ch : HUGE_VAL);
    ncells = (size_t)L->nx * (size_t)L->ny;
    L->start = calloc(ncells + 1, sizeof *L->start);
    L->order = malloc(L->count * sizeof *L->order);
    if (L->start == NULL || L->order == NULL)
        return -1;
    for (k = 0; k < n; k++) /* counting sort of the group's points by cell */
        if (cls[k] == c)
            L->start[cell_index(L, xy + 2 * k) + 1]++;
    for (k = 0; k < ncells; k++)
        L->start[k + 1] += L->start[k];
    for (k = 0; k < n; k++)
        if (cls[k] == c)
            L->order[L->start[cell_index(L, xy + 2 * k)]++] = k;
    for (k = ncells; k > 0; k--) /* the fill moved each start to the next one's */
        L->start[k] = L->start[k - 1];
    L->start[0] = 0;
    return 0;
}

/* Point i against the 3x3 block around it in the grid of group c (at or above its own). */
static void search(const struct layer *L, const double *xy, const double *radii, size_t i,
                   int same, double *nn_d2, double *rule2)
{
    long cx = cell_of(xy[2 * i], L->x0, L->cw, L->nx);
    long cy = cell_of(xy[2 * i + 1], L->y0, L->ch, L->ny);
    long x, y;

    for (y = cy - 1; y <= cy + 1; y++) {
        for (x = cx - 1; x <= cx + 1; x++) {
            size_t c, k;
            if (x < 0 || y < 0 || x >= L->nx || y >= L->ny)
                continue;
            c = (size_t)(y * L->nx + x);
            for (k = L->start[c]; k < L->start[c + 1]; k++) {
                size_t j = L->order[k];
                double dx, dy, d2, r;
                if (j == i || (same && j < i)) /* a pair of one group: once */
                    continue;
                /* As the single-grid search computes it, from point i or from j:
                   the same value, a difference only changing sign. */
                dx = xy[2 * i] - xy[2 * j];
                dy = xy[2 * i + 1] - xy[2 * j + 1];
                d2 = dx * dx + dy * dy;
                nn_d2[i] = d2 < nn_d2[i] ? d2 : nn_d2[i];
                nn_d2[j] = d2 < nn_d2[j] ? d2 : nn_d2[j];
                r = radii[i < j ? i : j];
                d2 /= r * r;
                *rule2 = d2 < *rule2 ? d2 : *rule2;
            }
        }
    }
}

int pattern_layers_nearest(const double *xy, const double *radii, size_t n, double *nn_d2,
                           unsigned char *exact, double *rule2)
{
    struct layer L[CLASSES] = {{0}};
    double rmin = HUGE_VAL, below[CLASSES + 1];
    unsigned char *cls = malloc(n > 0 ? n : 1);
    size_t k;
    int c, rc = -1;

    *rule2 = HUGE_VAL;
    if (cls == NULL)
        return -1;
    for (k = 0; k < n; k++)
        rmin = radii[k] < rmin ? radii[k] : rmin;
    for (k = 0; k < n; k++) {
        struct layer *G;
        c = class_of(radii[k], rmin);
        cls[k] = (unsigned char)c;
        G = &L[c];
        if (G->count++ == 0) {
            G->x0 = G->x1 = xy[2 * k];
            G->y0 = G->y1 = xy[2 * k + 1];
        }
        G->x0 = fmin(G->x0, xy[2 * k]);
        G->x1 = fmax(G->x1, xy[2 * k]);
        G->y0 = fmin(G->y0, xy[2 * k + 1]);
        G->y1 = fmax(G->y1, xy[2 * k + 1]);
        G->rmax = fmax(G->rmax, radii[k]);
        nn_d2[k] = HUGE_VAL;
    }
    for (c = 0; c < CLASSES; c++)
        if (L[c].count > 0 && layer_build(&L[c], xy, cls, c, n) != 0)
            goto out;
    for (k = 0; k < n; k++)
        for (c = cls[k]; c < CLASSES; c++)
            if (L[c].count > 0)
                search(&L[c], xy, radii, k, c == cls[k], nn_d2, rule2);
    /* A point missed by point k is at least the reach of its own group or of k's
       away (the one whose grid was searched): the least reach at or above k's. */
    below[CLASSES] = HUGE_VAL;
    for (c = CLASSES - 1; c >= 0; c--)
        below[c] = fmin(below[c + 1], L[c].count > 0 ? L[c].reach : HUGE_VAL);
    for (k = 0; k < n; k++) {
        double sure = below[cls[k]] * (1.0 - 1e-9); /* a margin for the cell rounding */
        exact[k] = nn_d2[k] < sure * sure;
    }
    rc = 0;
out:
    for (c = 0; c < CLASSES; c++) {
        free(L[c].start);
        free(L[c].order);
    }
    free(cls);
    return rc;
}
