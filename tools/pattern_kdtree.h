/*
 * pattern_kdtree.h - nearest neighbours of points however unevenly they
 * spread over their box (islands far apart, a thin ring), for the --stats
 * line (pattern_stats.h): a 2-d tree split at medians, searched with the
 * usual pruning, O(N log N) for any pattern. The grid of pattern_stats.c
 * is faster for points that fill their box; this takes over where one of
 * its cells would hold many points. Plain C99.
 */
#ifndef POISSONDISK_PATTERN_KDTREE_H
#define POISSONDISK_PATTERN_KDTREE_H

#include <stddef.h>

struct pattern_kdtree {
    const double *xy; /* the points, x y interleaved */
    size_t *order;    /* node m of [lo, hi) is order[(lo + hi) / 2] */
    size_t n;
};

/* Builds the tree over the n points xy (kept, not copied). Returns 0, or -1
   when out of memory. */
int pattern_kdtree_build(struct pattern_kdtree *t, const double *xy, size_t n);
/* The least squared distance from point i to another point of the tree. */
double pattern_kdtree_nearest2(const struct pattern_kdtree *t, size_t i);
void pattern_kdtree_free(struct pattern_kdtree *t);

#endif /* POISSONDISK_PATTERN_KDTREE_H */
