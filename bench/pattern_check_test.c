/*
 * pattern_check_test.c - bench --self-test: the checks themselves, on
 * patterns whose answers are known. Every benchmarked method passes the
 * minimum-distance check, so without this nothing would show that the check
 * can fail; and the probe estimate is compared with an area known exactly.
 */
#include "pattern_check_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "pattern_check.h"

static int failures;

static void expect(FILE *log, int condition, const char *what) {
    if (!condition) {
        fprintf(log, "pattern_check self-test FAILED: %s\n", what);
        ++failures;
    }
}

static struct pattern_check run_on(const double *xy, size_t n, double radius, int periodic,
                                   uint32_t probe_side) {
    struct pattern_check c;
    if (pattern_check(xy, n, radius, periodic, probe_side, &c) != 0) {
        c.min_distance = 0.0;
        c.min_distance_ok = -1; /* matches neither expectation */
        c.probes = c.uncovered = 0;
    }
    return c;
}

/* In the unit square. */
static struct pattern_check run(const double *xy, size_t n, double radius, uint32_t probe_side) {
    return run_on(xy, n, radius, 0, probe_side);
}

/* The (side+1)^2 lattice i/side, j/side, without the points skip says. */
static size_t lattice(double *xy, int side, int (*skip)(int i, int j)) {
    size_t n = 0;
    int i, j;
    for (j = 0; j <= side; ++j)
        for (i = 0; i <= side; ++i) {
            if (skip != NULL && skip(i, j)) continue;
            xy[2 * n] = (double)i / (double)side;
            xy[2 * n + 1] = (double)j / (double)side;
            ++n;
        }
    return n;
}

/* Two neighbours, (5,5) and (6,5): a hole opens around (0.55, 0.5), at least
 * 0.11 from every remaining point. (One missing point would leave a single
 * uncovered point: its four neighbours' disks meet there.) */
static int two_middle_points(int i, int j) { return j == 5 && (i == 5 || i == 6); }

int pattern_check_self_test(FILE *log) {
    const double r = 0.1;
    /* Bucket cells are 1/9 wide at R = 0.1: c is a cell corner. */
    const double c = 1.0 / 9.0;
    double pair[4], grid[2 * 11 * 11], p, expected;
    struct pattern_check got;
    size_t n;

    failures = 0;

    pair[0] = 0.3, pair[1] = 0.5, pair[2] = 0.3 + 0.999 * r, pair[3] = 0.5;
    got = run(pair, 2, r, 4);
    expect(log, got.min_distance_ok == 0, "a pair 0.999 R apart fails");
    expect(log, fabs(got.min_distance / r - 0.999) < 1e-9, "and its distance is reported");

    pair[2] = 0.3 + 1.001 * r;
    got = run(pair, 2, r, 4);
    expect(log, got.min_distance_ok == 1, "a pair 1.001 R apart passes");

    /* Across a cell corner, both diagonals: the forward-only pair scan must
     * still reach the up-left neighbour. */
    pair[0] = c - 0.03, pair[1] = c + 0.03, pair[2] = c + 0.03, pair[3] = c - 0.03;
    got = run(pair, 2, r, 4);
    expect(log, got.min_distance_ok == 0, "a close pair across a cell corner fails");
    pair[0] = c + 0.03, pair[1] = c + 0.03, pair[2] = c - 0.03, pair[3] = c - 0.03;
    got = run(pair, 2, r, 4);
    expect(log, got.min_distance_ok == 0, "a close pair across the other diagonal fails");

    pair[0] = 0.5, pair[1] = 0.5, pair[2] = 1.2, pair[3] = 0.5;
    got = run(pair, 2, r, 4);
    expect(log, got.min_distance_ok == 0, "a point outside the square fails");

    /* One disk of radius R in the middle: uncovered exactly 1 - pi R^2. */
    got = run(pair, 1, r, 512);
    expected = 1.0 - 3.141592653589793 * r * r;
    p = got.probes > 0 ? (double)got.uncovered / (double)got.probes : -1.0;
    expect(log, got.probes == 512 * 512, "a 512^2 lattice has 512^2 probes");
    expect(log, fabs(p - expected) < 5.0 * sqrt(expected * (1.0 - expected) / (512.0 * 512.0)),
           "one disk leaves 1 - pi R^2 uncovered");

    /* No points: all uncovered, and no pair to fail. */
    got = run(pair, 0, r, 64);
    expect(log, got.probes == 64 * 64 && got.uncovered == got.probes && got.min_distance_ok == 1,
           "an empty pattern is all uncovered");

    /* A square lattice of spacing R covers the square (covering radius 0.71 R)
     * with every neighbour exactly R away: passes, nothing uncovered. */
    n = lattice(grid, 10, NULL);
    got = run(grid, n, r, 256);
    expect(log, got.min_distance_ok == 1 && fabs(got.min_distance / r - 1.0) < 1e-12,
           "a lattice of spacing R passes");
    expect(log, got.uncovered == 0, "a lattice of spacing R covers the square");
    n = lattice(grid, 10, two_middle_points);
    got = run(grid, n, r, 256);
    expect(log, got.uncovered > 0, "a lattice missing two points leaves a hole");

    /* The unit torus: a pair 0.04 apart only across the seam, a disk that
     * wraps around the corner, a point on the excluded side x = 1. */
    pair[0] = 0.02, pair[1] = 0.5, pair[2] = 0.98, pair[3] = 0.5;
    got = run(pair, 2, r, 4);
    expect(log, got.min_distance_ok == 1, "a pair 0.96 apart passes in the square");
    got = run_on(pair, 2, r, 1, 4);
    expect(log, got.min_distance_ok == 0 && fabs(got.min_distance - 0.04) < 1e-12,
           "on the torus the pair is 0.04 apart across the seam and fails");
    pair[0] = 0.02, pair[1] = 0.03;
    got = run_on(pair, 1, r, 1, 512);
    p = got.probes > 0 ? (double)got.uncovered / (double)got.probes : -1.0;
    expect(log, fabs(p - expected) < 5.0 * sqrt(expected * (1.0 - expected) / (512.0 * 512.0)),
           "on the torus a disk at the corner leaves 1 - pi R^2 uncovered");
    pair[0] = 1.0, pair[1] = 0.5;
    got = run_on(pair, 1, r, 1, 4);
    expect(log, got.min_distance_ok == 0, "on the torus a point at x = 1 fails");

    fprintf(log, "pattern_check self-test: %s\n", failures == 0 ? "passed" : "FAILED");
    return failures == 0 ? 0 : 1;
}
