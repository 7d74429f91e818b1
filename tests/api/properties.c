/*
 * properties.c - the Poisson-disk guarantees, checked over seeds and domains.
 *
 * For every finished pattern: all points in the closed domain; every pair at
 * least R apart (brute force, independent of the library); maximal (free area
 * exactly 0, pds_step 0, pds_verify 0); and the count between two bounds that
 * follow from those properties alone:
 *   disks of radius R/2 around the points are disjoint and lie in the domain
 *   grown by R/2:   N * pi (R/2)^2 <= (w + R)(h + R);
 *   disks of radius R around the points cover the domain (maximal):
 *                   N * pi R^2 >= w h.
 * The same after pds_refine, with the old points unchanged. Finally the mean
 * count at R = 0.0083 is compared with the calibration of the paper's code,
 * which checks the law (random sequential adsorption), not just the geometry.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

#define PI 3.14159265358979323846

struct config {
    const char *name;
    test_domain d;
    double r;       /* radius natively */
    double r_light; /* radius under PDS_TEST_LIGHT */
};

static const struct config configs[] = {
    {"unit square, R 0.02", {0.0, 0.0, 1.0, 1.0}, 0.02, 0.06},
    {"unit square, R 0.01", {0.0, 0.0, 1.0, 1.0}, 0.01, 0.1},
    {"thin [0,4]x[0,0.5]", {0.0, 0.0, 4.0, 0.5}, 0.03, 0.08},
    {"tall [0,0.3]x[-5,5]", {0.0, -5.0, 0.3, 5.0}, 0.05, 0.1},
    {"offset [1000,1001]x[-3,-2]", {1000.0, -3.0, 1001.0, -2.0}, 0.02, 0.06},
    {"around 0 [-0.5,0.5]x[-0.25,0.25]", {-0.5, -0.25, 0.5, 0.25}, 0.015, 0.05},
    {"large [0,100]x[0,100], R 2", {0.0, 0.0, 100.0, 100.0}, 2.0, 6.0},
    {"thinner than R [0,1]x[0,0.001]", {0.0, 0.0, 1.0, 0.001}, 0.01, 0.03},
};
#define N_CONFIGS ((int)(sizeof configs / sizeof configs[0]))

static const uint64_t seeds[] = {1, 2, 3, 0xC0FFEE, 5, 6, 7, (uint64_t)1 << 63};
#define N_SEEDS_NATIVE ((int)(sizeof seeds / sizeof seeds[0]))
#define N_SEEDS_LIGHT 1

static int n_seeds(void)
{
    return test_light() ? N_SEEDS_LIGHT : N_SEEDS_NATIVE;
}

/* All checks of a finished pattern at the sampler's current radius. */
static void check_pattern(pds_sampler *s, test_domain d, const char *what)
{
    const double r = pds_radius(s);
    const double w = d.x1 - d.x0, h = d.y1 - d.y0;
    double *xy;
    size_t n;

    xy = points_copy(s, &n);
    assert_inside(xy, n, d, what);
    assert_min_distance(xy, n, r, what);
    assert_maximal(s, what);
    ck_assert_msg((double)n * PI * r * r / 4.0 <= (w + r) * (h + r),
                  "%s: %zu points do not fit R/2 disks into the grown domain", what, n);
    ck_assert_msg((double)n * PI * r * r >= w * h,
                  "%s: %zu disks of radius %g cannot cover the domain", what, n, r);
    free(xy);
}

/* Loop index i: configuration i % N_CONFIGS, seed i / N_CONFIGS. */
START_TEST(maximal_pattern)
{
    const struct config *c = &configs[_i % N_CONFIGS];
    const uint64_t seed = seeds[_i / N_CONFIGS];
    const double r = test_light() ? c->r_light : c->r;
    pds_sampler *s = sampler_new_in(r, seed, c->d);
    char what[128];

    snprintf(what, sizeof what, "%s (R %g), seed %llu", c->name, r, (unsigned long long)seed);
    run_to_end(s);
    check_pattern(s, c->d, what);
    pds_destroy(s);
}
END_TEST

/* Loop index i: domain i % 2, seed i / 2. Refines mid-run, then when maximal. */
#define N_RADII 4
START_TEST(refine_cascade)
{
    static const test_domain domains[2] = {{0.0, 0.0, 1.0, 1.0},
                                           {1000.0, -3.0, 1001.0, -2.0}};
    static const double native[N_RADII] = {0.04, 0.02, 0.013, 0.009};
    static const double light[N_RADII] = {0.1, 0.06, 0.045, 0.035};
    const double *radii = test_light() ? light : native;
    const test_domain d = domains[_i % 2];
    const uint64_t seed = seeds[_i / 2];
    pds_sampler *s = sampler_new_in(radii[0], seed, d);
    int k;

    /* The first refine comes before the pattern is maximal (15 points). */
    ck_assert_int_eq(pds_run(s, 15, NULL), 1);
    for (k = 1; k < N_RADII; k++) {
        char what[128];
        size_t nold;
        double *old = points_copy(s, &nold);
        ck_assert_int_eq(pds_refine(s, radii[k]), 0);
        run_to_end(s);
        snprintf(what, sizeof what, "domain %d, seed %llu, refined from %g to %g", _i % 2,
                 (unsigned long long)seed, radii[k - 1], radii[k]);
        assert_prefix_kept(s, old, nold, what);
        check_pattern(s, d, what);
        free(old);
    }
    pds_destroy(s);
}
END_TEST

/*
 * The count law. At R = 0.0083 in the unit square the paper's code gives a
 * mean of 10221 points over many runs; the mean of 20 seeds has a standard
 * error of at most about 8 (the spread per run is a few tens of points). The
 * window +-60 is 7.5 such errors: a correct sampler fails it essentially never,
 * while a sampler that is maximal and R-separated but does not place each
 * point uniformly over the free area (a different law) can shift the mean by
 * more than that.
 */
#define CALIB_R 0.0083
#define CALIB_MEAN 10221.0
#define CALIB_WINDOW 60.0
#define CALIB_SEEDS 20

START_TEST(calibration_mean_count)
{
    double sum = 0.0, mean;
    int i;

    for (i = 0; i < CALIB_SEEDS; i++) {
        pds_sampler *s = sampler_new(CALIB_R, 1000 + (uint64_t)i);
        sum += (double)run_to_end(s);
        ck_assert_msg(pds_free_area(s) == 0.0, "seed %d: free area %.17g after the run",
                      1000 + i, pds_free_area(s));
        pds_destroy(s);
    }
    mean = sum / CALIB_SEEDS;
    ck_assert_msg(fabs(mean - CALIB_MEAN) <= CALIB_WINDOW,
                  "mean count over %d seeds at R = %g is %.1f, expected %.0f +- %.0f",
                  CALIB_SEEDS, CALIB_R, mean, CALIB_MEAN, CALIB_WINDOW);
}
END_TEST

Suite *properties_suite(void)
{
    Suite *suite = suite_create("properties");
    TCase *tc;

    tc = new_tcase(suite, "maximal_patterns");
    tcase_add_loop_test(tc, maximal_pattern, 0, N_CONFIGS * n_seeds());
    tc = new_tcase(suite, "refine_cascade");
    tcase_add_loop_test(tc, refine_cascade, 0, 2 * n_seeds());
    /* Twenty patterns of ~10^4 points: too slow under Valgrind, and the law
     * does not depend on the memory checks. */
    if (!test_light()) {
        tc = new_tcase(suite, "calibration");
        tcase_add_test(tc, calibration_mean_count);
    }
    return suite;
}
