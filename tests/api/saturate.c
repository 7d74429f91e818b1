/*
 * saturate.c - the reference sampler of the domain law test: plain dart
 * throwing in a polygon, run to saturation (saturate, region.h).
 *
 * A dart is uniform in the polygon's bounding box; it is kept when it lies in
 * the closed polygon, at least r from every point kept so far and at least
 * its clearance from every fixed point. That is random sequential adsorption
 * conditioned on the fixed points, the law the library promises.
 *
 * Plain darts in the box would need ever more throws as the free region
 * shrinks, and a budget of misses would stop early and bias the count low.
 * So the box is cut into squares, and a square is dropped once it certainly
 * holds no free point: it lies in one closed disk, or it misses the polygon
 * (no edge meets it and its centre is outside). A dart uniform over the
 * squares left is uniform over the box restricted to them, and the dropped
 * squares would have rejected every dart, so each kept dart is still uniform
 * over the free region: the law is unchanged, only rejections are skipped
 * (after Ebeida et al. 2011). Each round throws as many darts as there are
 * squares, then splits the survivors in four. When no square is left the
 * free region is empty up to a set of measure zero: saturation, which the
 * law test confirms with region_covered on every reference pattern.
 */
#include "region.h"

#include <math.h>
#include <stdlib.h>

#include <check.h>

typedef struct square {
    double x, y;
    int outline; /* an edge may meet it (else it lies wholly in the polygon) */
} square;

typedef struct squares {
    square *v;
    size_t n, cap;
} squares;

static void push(squares *s, square q)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 256;
        s->v = realloc(s->v, s->cap * sizeof *s->v);
        ck_assert_ptr_nonnull(s->v);
    }
    s->v[s->n++] = q;
}

/* The segment (a, b) meets the closed square [x, x+h] x [y, y+h]
 * (Liang-Barsky clipping). */
static int segment_meets(double ax, double ay, double bx, double by, double x, double y,
                         double h)
{
    double t0 = 0.0, t1 = 1.0, p[4], q[4];
    int k;

    p[0] = -(bx - ax), q[0] = ax - x;
    p[1] = bx - ax, q[1] = x + h - ax;
    p[2] = -(by - ay), q[2] = ay - y;
    p[3] = by - ay, q[3] = y + h - ay;
    for (k = 0; k < 4; k++) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0)
                return 0;
        } else {
            double t = q[k] / p[k];
            if (p[k] < 0.0)
                t0 = fmax(t0, t);
            else
                t1 = fmin(t1, t);
        }
    }
    return t0 <= t1;
}

static int meets_outline(const region *g, double x, double y, double h)
{
    double ax, ay, bx, by;
    size_t e, n = region_vertices(g);

    for (e = 0; e < n; e++) {
        region_edge(g, e, &ax, &ay, &bx, &by);
        if (segment_meets(ax, ay, bx, by, x, y, h))
            return 1;
    }
    return 0;
}

/* The square lies in one closed disk: its four corners do (disks are convex). */
static int covered_square(const disk_grid *G, double x, double y, double h)
{
    size_t c = grid_cell(G, x + 0.5 * h, y + 0.5 * h), k;

    for (k = 0; k < G->len[c]; k++) {
        const disk d = G->d[G->items[c][k]];
        const double r2 = d.r * d.r;
        int corner, in = 1;
        for (corner = 0; corner < 4 && in; corner++) {
            double dx = x + (corner & 1) * h - d.x, dy = y + (corner >> 1) * h - d.y;
            in = dx * dx + dy * dy <= r2;
        }
        if (in)
            return 1;
    }
    return 0;
}

/* The square may still hold a free point of the polygon. */
static int alive(const region *g, const disk_grid *G, square *q, double h)
{
    if (q->outline) {
        q->outline = meets_outline(g, q->x, q->y, h);
        if (!q->outline && !region_contains(g, q->x + 0.5 * h, q->y + 0.5 * h))
            return 0;
    }
    return !covered_square(G, q->x, q->y, h);
}

size_t saturate(const region *g, double r, const disk *fixed, size_t nfixed, uint64_t seed,
                double **xy)
{
    double box[4], h = r / sqrt(2.0);
    uint64_t rng = seed;
    squares act = {NULL, 0, 0}, next = {NULL, 0, 0};
    disk_grid G;
    size_t i, j, nfix, level, count = 0, cap = 64;
    double *out = malloc(cap * 2 * sizeof *out);

    ck_assert_ptr_nonnull(out);
    region_bounds(g, box);
    grid_init(&G, box, r);
    for (i = 0; i < nfixed; i++)
        grid_add(&G, fixed[i]);
    nfix = G.n;
    for (j = 0; box[1] + (double)j * h < box[3]; j++)
        for (i = 0; box[0] + (double)i * h < box[2]; i++) {
            square q;
            q.x = box[0] + (double)i * h;
            q.y = box[1] + (double)j * h;
            q.outline = 1;
            if (alive(g, &G, &q, h))
                push(&act, q);
        }
    /* 40 halvings take a square from r / sqrt 2 to 1e-12 r: what survives
     * is a tangency or a crossing met exactly, measure zero. */
    for (level = 0; act.n > 0 && level < 40; level++) {
        size_t darts = act.n, k;
        for (k = 0; k < darts && act.n > 0; k++) {
            size_t pick = (size_t)(ref_uniform(&rng) * (double)act.n);
            square *q = &act.v[pick < act.n ? pick : act.n - 1];
            double x = q->x + ref_uniform(&rng) * h, y = q->y + ref_uniform(&rng) * h;
            /* The box's far sides belong to it; a dart past them is outside. */
            if (x <= box[2] && y <= box[3] && region_contains(g, x, y) &&
                !grid_strictly_inside(&G, x, y, 0.0)) {
                disk d;
                d.x = x, d.y = y, d.r = r;
                grid_add(&G, d);
                if (count == cap) {
                    cap *= 2;
                    out = realloc(out, cap * 2 * sizeof *out);
                    ck_assert_ptr_nonnull(out);
                }
                out[2 * count] = x;
                out[2 * count + 1] = y;
                count++;
            }
            if (!alive(g, &G, q, h))
                *q = act.v[--act.n];
        }
        h *= 0.5;
        next.n = 0;
        for (k = 0; k < act.n; k++) {
            int c;
            for (c = 0; c < 4; c++) {
                square child = act.v[k];
                child.x += (c & 1) * h;
                child.y += (c >> 1) * h;
                if (child.x <= box[2] && child.y <= box[3] && alive(g, &G, &child, h))
                    push(&next, child);
            }
        }
        {
            squares t = act;
            act = next;
            next = t;
        }
    }
    (void)nfix;
    free(act.v);
    free(next.v);
    grid_free(&G);
    *xy = out;
    return count;
}
