/*
 * pattern_stats_test.c - the --stats line's nearest neighbours
 * (tools/pattern_stats.h) against every pair: points filling their box
 * (the grid's rings), points crowded into two islands far apart and points
 * on one line with equal coordinates (the 2-d tree), each exact.
 */
#include <math.h>
#include <stdlib.h>

#include "pattern_kdtree.h"
#include "pattern_stats.h"
#include "shape_files_test.h"

/* x y in [0, 1)^2 from a small linear congruential generator. */
static double next_unit(unsigned long long *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 9007199254740992.0;
}

/* The least squared distance from point i to another, over every pair. */
static double brute_nearest2(const double *xy, size_t n, size_t i)
{
    double best = HUGE_VAL;
    size_t j;
    for (j = 0; j < n; j++) {
        double dx = xy[2 * i] - xy[2 * j], dy = xy[2 * i + 1] - xy[2 * j + 1];
        if (j != i && dx * dx + dy * dy < best)
            best = dx * dx + dy * dy;
    }
    return best;
}

static void brute(const double *xy, size_t n, double *least, double *mean)
{
    size_t i;
    double sum = 0.0;
    *least = HUGE_VAL;
    for (i = 0; i < n; i++) {
        double d = sqrt(brute_nearest2(xy, n, i));
        sum += d;
        *least = d < *least ? d : *least;
    }
    *mean = sum / (double)n;
}

/* kind 0: uniform over the box; 1: two islands of side 1 at (0, 0) and
   (1000, 1000); 2: on the line y = 0.5, x a multiple of 1/64 (repeats). */
static size_t make_points(int kind, size_t n, double *xy, double box[4])
{
    unsigned long long state = 12345 + (unsigned long long)kind;
    size_t k;
    for (k = 0; k < n; k++) {
        double u = next_unit(&state), v = next_unit(&state);
        double shift = kind == 1 && k % 2 ? 1000.0 : 0.0;
        xy[2 * k] = kind == 2 ? floor(u * 64.0) / 64.0 : shift + u;
        xy[2 * k + 1] = kind == 2 ? 0.5 + 1e-9 * (double)(k % 3) : shift + v;
    }
    box[0] = box[1] = 0.0;
    box[2] = box[3] = kind == 1 ? 1001.0 : 1.0;
    return n;
}

START_TEST(nearest_neighbours_exact_however_the_points_spread)
{
    const size_t n = getenv("PDS_TEST_LIGHT") ? 800 : 3000;
    double *xy = malloc(2 * n * sizeof *xy), box[4], least, mean, want_least, want_mean;
    ck_assert_ptr_nonnull(xy);
    make_points(_i, n, xy, box);
    ck_assert_int_eq(pattern_nn_stats(xy, n, box, 0, 0.001, &least, &mean), 0);
    brute(xy, n, &want_least, &want_mean);
    ck_assert_msg(least == want_least, "kind %d: least %.17g, every pair %.17g", _i, least, want_least);
    ck_assert_msg(fabs(mean - want_mean) <= 1e-12 * want_mean, "kind %d: mean %.17g, every pair %.17g", _i,
                  mean, want_mean);
    free(xy);
}
END_TEST

START_TEST(the_tree_finds_each_points_nearest)
{
    const size_t n = getenv("PDS_TEST_LIGHT") ? 500 : 2000;
    double *xy = malloc(2 * n * sizeof *xy), box[4];
    struct pattern_kdtree t;
    size_t i, wrong = 0;
    ck_assert_ptr_nonnull(xy);
    make_points(_i, n, xy, box);
    ck_assert_int_eq(pattern_kdtree_build(&t, xy, n), 0);
    for (i = 0; i < n; i++)
        if (pattern_kdtree_nearest2(&t, i) != brute_nearest2(xy, n, i))
            wrong++;
    ck_assert_msg(wrong == 0, "kind %d: %zu of %zu nearest distances wrong", _i, wrong, n);
    pattern_kdtree_free(&t);
    free(xy);
}
END_TEST

Suite *pattern_stats_suite(void)
{
    Suite *s = suite_create("pattern_stats");
    TCase *tc = tcase_create("nearest");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, nearest_neighbours_exact_however_the_points_spread, 0, 3);
    tcase_add_loop_test(tc, the_tree_finds_each_points_nearest, 0, 3);
    suite_add_tcase(s, tc);
    return s;
}
