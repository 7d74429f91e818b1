/*
 * chunked.h - the cost of splitting a run into one-point calls (chunked.c).
 */
#ifndef PDS_BENCH_CHUNKED_H
#define PDS_BENCH_CHUNKED_H

#include <stddef.h>
#include <stdio.h>

/*
 * Times, at about target points (R = sqrt(0.6966 / target)), one unbounded
 * pds_run against pds_run(s, 1, ...) and pds_step repeated until the pattern
 * is maximal, seeds 1..repeats, and prints the medians and ratios to out.
 * Returns 0, or 1 when a run failed or the three ways gave different points.
 */
int chunked_bench(FILE *out, size_t target, int repeats);

#endif /* PDS_BENCH_CHUNKED_H */
