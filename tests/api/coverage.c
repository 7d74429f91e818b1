/*
 * coverage.c - is the closed polygon inside the union of closed disks?
 * (region_covered, region.h). Independent of the library's bookkeeping and of
 * pds_verify: the vertices of the arrangement of the outline and the circles,
 * in floating point, with a grid for the neighbours.
 *
 * The claim: the polygon D lies in the union U of the closed disks iff
 *   (a) every vertex of the outline lies in some disk,
 *   (b) every crossing of two circles i, j that lies in D lies in a third
 *       disk k (k != i, j), and
 *   (c) every crossing of a circle i with an edge (endpoints included) lies
 *       in another disk k != i.
 * "Only if" is plain: each such point is in D, and a point on circle i's
 * rim with uncovered points of D beside it must be held by another disk (up
 * to tangencies, a set of measure zero, which the tolerance absorbs).
 * "If": let C be a component of G = D \ U, which is open in D.
 *  - If C meets the outline, the uncovered part of the outline is open in
 *    it: a whole ring (then (a) fails) or a union of pieces, each ending at a
 *    point e of some circle i not inside another disk. e is a crossing of
 *    circle i with an edge, the edge's end included, so (c) fails at e.
 *  - Otherwise C lies inside D and is open in the plane; each point of its
 *    boundary is covered and a limit of uncovered points, so it is on a
 *    circle and inside no disk: the boundary is a union of arcs with C on
 *    their outer side. If no two circles met on it, each boundary component
 *    would be a whole circle S_i with no other disk near it. Take the point b
 *    of the closure of C with the largest x: it lies on some S_i, which lies
 *    in the closure, so b is S_i's rightmost point; near b nothing but disk i
 *    covers, and the outside of disk i near b is connected and meets C, so C
 *    holds points right of b: a contradiction. So two circles meet at some
 *    b on C's boundary, in D and inside no third disk: (b) fails at b.
 * Hence an uncovered component always shows itself at a vertex, and a
 * pattern with a hole in its coverage cannot pass (tested in domain_law.c
 * by removing one point).
 */
#include "region.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The crossings of circles a and b (0 or 2; tangency counts as 2 equal). */
static int circle_crossings(disk a, disk b, double q[4])
{
    double dx = b.x - a.x, dy = b.y - a.y, d2 = dx * dx + dy * dy, d = sqrt(d2), t, h2, h;

    if (d == 0.0 || d > a.r + b.r || d < fabs(a.r - b.r))
        return 0;
    t = (a.r * a.r - b.r * b.r + d2) / (2.0 * d);
    h2 = a.r * a.r - t * t;
    h = h2 > 0.0 ? sqrt(h2) : 0.0;
    q[0] = a.x + (t * dx - h * dy) / d;
    q[1] = a.y + (t * dy + h * dx) / d;
    q[2] = a.x + (t * dx + h * dy) / d;
    q[3] = a.y + (t * dy - h * dx) / d;
    return 2;
}

/* The crossings of circle c with the closed segment (a, b): 0 to 2 points. */
static int edge_crossings(disk c, double ax, double ay, double bx, double by, double q[4])
{
    double dx = bx - ax, dy = by - ay, fx = ax - c.x, fy = ay - c.y;
    double A = dx * dx + dy * dy, B = 2.0 * (fx * dx + fy * dy), C = fx * fx + fy * fy - c.r * c.r;
    double disc = B * B - 4.0 * A * C, s, t[2];
    const double slack = 1e-12; /* an end of the edge on the circle counts */
    int n = 0, k;

    if (A == 0.0 || disc < 0.0)
        return 0;
    s = sqrt(disc);
    t[0] = (-B - s) / (2.0 * A);
    t[1] = (-B + s) / (2.0 * A);
    for (k = 0; k < 2; k++)
        if (t[k] >= -slack && t[k] <= 1.0 + slack) {
            double u = fmax(0.0, fmin(1.0, t[k]));
            q[2 * n] = ax + u * dx;
            q[2 * n + 1] = ay + u * dy;
            n++;
        }
    return n;
}

int region_covered(const region *g, const disk *d, size_t n, double tol, char *why,
                   size_t whylen)
{
    double box[4], q[4], rmin = INFINITY, ax, ay, bx, by;
    size_t i, k, e, nv = region_vertices(g);
    size_t *seen;
    disk_grid G;
    int ok = 1, m;

    region_bounds(g, box);
    for (i = 0; i < n; i++)
        rmin = fmin(rmin, d[i].r);
    if (n == 0) {
        snprintf(why, whylen, "no disk at all");
        return 0;
    }
    grid_init(&G, box, rmin);
    for (i = 0; i < n; i++)
        grid_add(&G, d[i]);
    for (e = 0; e < nv && ok; e++)
        if (!grid_covers(&G, g->xy[2 * e], g->xy[2 * e + 1], -1, -1, tol)) {
            snprintf(why, whylen, "outline vertex %zu (%.17g, %.17g) is in no disk", e,
                     g->xy[2 * e], g->xy[2 * e + 1]);
            ok = 0;
        }
    for (i = 0; i < n && ok; i++)
        for (e = 0; e < nv && ok; e++) {
            region_edge(g, e, &ax, &ay, &bx, &by);
            m = edge_crossings(d[i], ax, ay, bx, by, q);
            for (k = 0; k < (size_t)m && ok; k++)
                if (!grid_covers(&G, q[2 * k], q[2 * k + 1], (long)i, -1, tol)) {
                    snprintf(why, whylen, "where circle %zu crosses edge %zu, (%.17g, %.17g), "
                             "no other disk covers", i, e, q[2 * k], q[2 * k + 1]);
                    ok = 0;
                }
        }
    /* Circle pairs: the candidates of disk i are in the cells its square
     * overlaps; seen[j] == i + 1 skips a j met in an earlier cell. */
    seen = calloc(n, sizeof *seen);
    for (i = 0; i < n && ok; i++) {
        const disk a = d[i];
        size_t c0 = grid_cell(&G, a.x - a.r, a.y - a.r), c1 = grid_cell(&G, a.x + a.r, a.y + a.r);
        size_t cx, cy;
        for (cy = c0 / G.nx; cy <= c1 / G.nx && ok; cy++)
            for (cx = c0 % G.nx; cx <= c1 % G.nx && ok; cx++) {
                size_t c = cy * G.nx + cx, t;
                for (t = 0; t < G.len[c] && ok; t++) {
                    size_t j = G.items[c][t];
                    if (j <= i || seen[j] == i + 1)
                        continue;
                    seen[j] = i + 1;
                    m = circle_crossings(a, d[j], q);
                    for (k = 0; k < (size_t)m && ok; k++)
                        if (region_contains(g, q[2 * k], q[2 * k + 1]) &&
                            !grid_covers(&G, q[2 * k], q[2 * k + 1], (long)i, (long)j, tol)) {
                            snprintf(why, whylen, "circles %zu and %zu cross at (%.17g, %.17g) "
                                     "in the domain, and no third disk covers it", i, j,
                                     q[2 * k], q[2 * k + 1]);
                            ok = 0;
                        }
                }
            }
    }
    free(seen);
    grid_free(&G);
    return ok;
}
