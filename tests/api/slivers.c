/*
 * slivers.c - rectangles far thinner than the radius: their free area and the
 * law of their points.
 *
 * In a rectangle w wide and 1 long with w << R, every disk spans the width,
 * so the free area is w times the length of [0, 1] outside the intervals
 * [y - R, y + R] of the points: exact, whatever the points. Each cell is R
 * long and only w wide, so its area is far below R^2 times any small
 * constant; these tests catch a free area that is not the cells' own (a
 * floor of the order of R^2, or fan triangles dropped where their short
 * sides' squared lengths underflow), and a draw that chooses among such
 * cells alike instead of by their areas.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}


typedef struct {
    double at, r;
} disk_on_line;

static int by_start(const void *a, const void *b)
{
    const disk_on_line *p = a, *q = b;
    const double x = p->at - p->r, y = q->at - q->r;
    return by_value(&x, &y);
}

/* The length of [0, 1] within some disk's radius of its centre (sorted here
 * by where the disks start). */
static double covered_length(disk_on_line *c, size_t n)
{
    double total = 0.0, lo = 0.0, hi = -1.0;
    size_t i;
    qsort(c, n, sizeof c[0], by_start);
    for (i = 0; i < n; i++) {
        const double a = fmax(c[i].at - c[i].r, 0.0), b = fmin(c[i].at + c[i].r, 1.0);
        if (a > hi) {
            if (hi > lo) total += hi - lo;
            lo = a;
        }
        if (b > hi) hi = b;
    }
    if (hi > lo) total += hi - lo;
    return total;
}

static const double sliver_widths[] = {1e-20, 1e-120, 1e-200, 1e-250};

/* _i: the width (sliver_widths), whether the rectangle lies along y or x, and
 * whether the radius is R or a map from R/2 to 2R (power cells). */
START_TEST(free_area_of_a_sliver_is_its_free_length)
{
    const double w = sliver_widths[_i / 4], r = 0.01;
    const int along_x = _i % 2, field = _i / 2 % 2;
    const double map[4] = {0.5 * r, 2.0 * r, 2.0 * r, 0.5 * r};
    const test_domain d = {0.0, 0.0, along_x ? 1.0 : w, along_x ? w : 1.0};
    pds_sampler *s = sampler_new_in(r, 7 + (uint64_t)_i, d);
    disk_on_line disks[30];
    size_t n = 0, added = 0, k;

    if (field) ck_assert(pds_set_radius_map(s, 2, 2, map) == 0);
    for (k = 0; k < 30; k++) {
        double xy[2], expected, got;
        int rc = pds_run(s, 1, &added);
        ck_assert_msg(rc == 1 && added == 1, "width %g: pds_run(s, 1) returned %d, added %zu", w, rc,
                      added);
        ck_assert(pds_points(s, n, 1, xy) == 1 && pds_radii(s, n, 1, &disks[n].r) == 1);
        disks[n++].at = along_x ? xy[0] : xy[1];
        expected = w * (1.0 - covered_length(disks, n));
        got = pds_free_area(s);
        ck_assert_msg(fabs(got - expected) <= 1e-9 * w, "width %g, %zu points: pds_free_area %.17g, the "
                      "free length times the width %.17g (the whole area %g)", w, n, got, expected, w);
    }
    n += run_to_end(s);
    ck_assert_msg(pds_free_area(s) == 0.0 && pds_verify(s) == 0, "width %g, maximal with %zu points: free "
                  "area %g, pds_verify %d", w, n, pds_free_area(s), pds_verify(s));
    /* Between 1/(2 rmax) and 1/rmin + 1 points fit along a maximal line. */
    ck_assert_msg(n > (field ? 25 : 50) && n <= (field ? 201 : 101), "width %g: %zu points along a line of "
                  "length 1", w, n);
    pds_destroy(s);
}
END_TEST

/*
 * Two fixed points at y = 0.05 and 0.3 split the sliver at y = 0.175: the
 * lower cell keeps 0.155 of free length, the upper 0.805. The first point
 * must fall below 0.175 with probability 0.155 / 0.96 = 0.161 (a draw that
 * chose among the two cells alike gives 1/2).
 */
START_TEST(a_sliver_draws_its_first_point_by_area)
{
    const double w = 1e-200, r = 0.01, p = 0.155 / 0.96;
    const double fixed[4] = {0.5e-200, 0.05, 0.5e-200, 0.3};
    const test_domain d = {0.0, 0.0, w, 1.0};
    const size_t seeds = 1000;
    size_t seed, low = 0, added;
    double sd, z;

    for (seed = 1; seed <= seeds; seed++) {
        pds_sampler *s = sampler_new_in(r, seed, d);
        double xy[2];
        ck_assert(pds_set_fixed(s, fixed, NULL, 2) == 0);
        ck_assert_msg(pds_run(s, 1, &added) == 1 && added == 1, "seed %zu: no first point", seed);
        ck_assert(pds_points(s, 0, 1, xy) == 1);
        ck_assert_msg(fabs(xy[1] - 0.05) >= r && fabs(xy[1] - 0.3) >= r, "seed %zu: y %.17g within R of a "
                      "fixed point", seed, xy[1]);
        low += xy[1] < 0.175;
        pds_destroy(s);
    }
    sd = sqrt(p * (1.0 - p) / (double)seeds);
    z = ((double)low / (double)seeds - p) / sd;
    ck_assert_msg(fabs(z) < 5.0, "%zu of %zu first points below y = 0.175, expected %.1f (z = %.1f)", low,
                  seeds, p * (double)seeds, z);
}
END_TEST

Suite *slivers_suite(void)
{
    Suite *suite = suite_create("slivers");
    TCase *tc = new_tcase(suite, "slivers");
    tcase_add_loop_test(tc, free_area_of_a_sliver_is_its_free_length, 0,
                        (int)(4 * sizeof sliver_widths / sizeof sliver_widths[0]));
    tcase_add_test(tc, a_sliver_draws_its_first_point_by_area);
    return suite;
}
