/*
 * bridson.h - baseline: Bridson's "Fast Poisson disk sampling in arbitrary
 * dimensions" (SIGGRAPH 2007 sketch), plain, in the unit square.
 */
#ifndef BENCH_BRIDSON_H
#define BENCH_BRIDSON_H

#include <stddef.h>
#include <stdint.h>

/* Candidates tried around an active point before it is retired (Bridson's k). */
#define BRIDSON_CANDIDATES 30

/*
 * Fills *xy (interleaved x,y, malloc'd, the caller frees it) and *count.
 * Returns 0, or -1 when memory runs out (then *xy is NULL).
 */
int bridson_sample(double radius, uint64_t seed, double **xy, size_t *count);

#endif /* BENCH_BRIDSON_H */
