/*
 * pattern_check.h - judge a finished pattern in the unit square, the same way
 * for every method: the minimum pair distance, and the fraction of the
 * square left uncovered (farther than R from every point), estimated on a
 * fixed set of probe points. Never part of a timed region.
 */
#ifndef BENCH_PATTERN_CHECK_H
#define BENCH_PATTERN_CHECK_H

#include <stddef.h>
#include <stdint.h>

/* Probes per target point, and the cap on the probe lattice's side (2^26
 * probes) that keeps the check of a 10^7-point pattern to a few seconds. */
#define PATTERN_PROBES_PER_POINT 16
#define PATTERN_PROBE_SIDE_MAX 8192

struct pattern_check {
    double min_distance; /* smallest distance between two points; HUGE_VAL if fewer than 2 */
    int min_distance_ok; /* every pair at least R apart (up to 1e-12 relative rounding)
                            and every point inside the square */
    uint64_t probes;     /* probes looked at */
    uint64_t uncovered;  /* probes farther than R from every point */
};

/* Side of the probe lattice for a target size: about 16 probes per point, capped. */
uint32_t pattern_probe_side(size_t target_points);

/*
 * Checks the n points xy (interleaved x,y) at radius R (periodic: on the unit
 * torus [0,1)^2, distances wrapped) with a probe_side^2
 * jittered lattice: one probe uniform in each lattice cell, from a fixed seed,
 * so every method at the same target size meets the same probes.
 * Returns 0, or -1 when memory runs out.
 */
int pattern_check(const double *xy, size_t n, double radius, int periodic, uint32_t probe_side,
                  struct pattern_check *out);

#endif /* BENCH_PATTERN_CHECK_H */
