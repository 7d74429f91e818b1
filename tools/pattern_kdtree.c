/*
 * pattern_kdtree.c - a 2-d tree for nearest neighbours (see pattern_kdtree.h).
 */
#include "pattern_kdtree.h"

#include <math.h>
#include <stdlib.h>

static double coord(const struct pattern_kdtree *t, size_t k, int axis)
{
    return t->xy[2 * t->order[k] + (size_t)axis];
}

static void swap_at(size_t *order, size_t a, size_t b)
{
    size_t tmp = order[a];
    order[a] = order[b];
    order[b] = tmp;
}

/* Puts the median of order[lo, hi) along axis at mid, the lesser before it
   and the greater after (a three-way partition: equal coordinates, as on a
   line of points, cost no more than others). */
static void select_median(struct pattern_kdtree *t, size_t lo, size_t hi, size_t mid, int axis)
{
    while (hi - lo > 1) {
        size_t a = lo, b = lo + (hi - lo) / 2, c = hi - 1, less = lo, more = hi, k = lo;
        double pivot;
        /* The median of three as the pivot. */
        if (coord(t, a, axis) > coord(t, b, axis))
            swap_at(t->order, a, b);
        if (coord(t, b, axis) > coord(t, c, axis))
            swap_at(t->order, b, c);
        if (coord(t, a, axis) > coord(t, b, axis))
            swap_at(t->order, a, b);
        pivot = coord(t, b, axis);
        /* [lo, less) < pivot, [less, k) == pivot, [more, hi) > pivot. */
        while (k < more) {
            double v = coord(t, k, axis);
            if (v < pivot)
                swap_at(t->order, k++, less++);
            else if (v > pivot)
                swap_at(t->order, k, --more);
            else
                k++;
        }
        if (mid < less)
            hi = less;
        else if (mid >= more)
            lo = more;
        else
            return;
    }
}

static void build(struct pattern_kdtree *t, size_t lo, size_t hi, int axis)
{
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        select_median(t, lo, hi, mid, axis);
        build(t, lo, mid, !axis);
        lo = mid + 1;
        axis = !axis;
    }
}

int pattern_kdtree_build(struct pattern_kdtree *t, const double *xy, size_t n)
{
    size_t k;

    t->xy = xy;
    t->n = n;
    t->order = malloc((n > 0 ? n : 1) * sizeof *t->order);
    if (t->order == NULL)
        return -1;
    for (k = 0; k < n; k++)
        t->order[k] = k;
    build(t, 0, n, 0);
    return 0;
}

static void search(const struct pattern_kdtree *t, size_t lo, size_t hi, int axis, size_t i,
                   double *best)
{
    const double px = t->xy[2 * i], py = t->xy[2 * i + 1];

    while (hi > lo) {
        size_t mid = lo + (hi - lo) / 2, j = t->order[mid];
        double split = coord(t, mid, axis), off = (axis ? py : px) - split;
        if (j != i) {
            double dx = t->xy[2 * j] - px, dy = t->xy[2 * j + 1] - py, d2 = dx * dx + dy * dy;
            if (d2 < *best)
                *best = d2;
        }
        /* The near side first; the far side only if the splitting line is
           nearer than the best so far. */
        if (off < 0) {
            search(t, lo, mid, !axis, i, best);
            if (off * off >= *best)
                return;
            lo = mid + 1;
        } else {
            search(t, mid + 1, hi, !axis, i, best);
            if (off * off >= *best)
                return;
            hi = mid;
        }
        axis = !axis;
    }
}

double pattern_kdtree_nearest2(const struct pattern_kdtree *t, size_t i)
{
    double best = HUGE_VAL;
    search(t, 0, t->n, 0, i, &best);
    return best;
}

void pattern_kdtree_free(struct pattern_kdtree *t)
{
    free(t->order);
    t->order = NULL;
}
