/*
 * field_bound.c - how an unbounded pds_run with a radius map is judged.
 *
 * Contract (poissondisk.h): with a varying field the count limit is judged
 * at the first point on a bound on the pattern's size that holds for every
 * seed: Oler's bound at rmin, or for a map the sum of Oler's bounds over the
 * cells between its pixel centres, each at its smallest corner value,
 * whichever is smaller. A map whose small values are few therefore runs to
 * the end, while a map small everywhere is still refused (PDS_ERANGE,
 * nothing added), and a function, known only where asked, is judged at
 * rmin.
 */
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

#define SIDE 64

static double *one_small_value(double large, double small)
{
    double *map = malloc(SIDE * SIDE * sizeof *map);
    size_t k;
    ck_assert_ptr_nonnull(map);
    for (k = 0; k < SIDE * SIDE; k++) map[k] = large;
    map[SIDE * 20 + 30] = small;
    return map;
}

/* One value at 1e-5 among 0.05: Oler at 1e-5 says 1.2e10 points, the map's
   bound about 1e7; the pattern has a few hundred. */
START_TEST(one_small_pixel_runs_to_the_end)
{
    int periodic;
    for (periodic = 0; periodic < 2; periodic++) {
        double *map = one_small_value(0.05, 1e-5);
        pds_sampler *s = sampler_new(1.0, 3);
        size_t added = 0;
        ck_assert_int_eq(pds_set_periodic(s, periodic), 0);
        ck_assert_int_eq(pds_set_radius_map(s, SIDE, SIDE, map), 0);
        ck_assert_msg(pds_run(s, 0, &added) == PDS_DONE, "periodic %d: %s", periodic, pds_errmsg(s));
        ck_assert_msg(added > 100 && added < 5000, "periodic %d: %zu points", periodic, added);
        ck_assert_int_eq(pds_verify(s), PDS_DONE);
        free(map);
        pds_destroy(s);
    }
}
END_TEST

/* Small everywhere: refused before any point, as a radius of 1e-5 is. */
START_TEST(small_everywhere_is_refused)
{
    double *map = one_small_value(1e-5, 2e-5);
    pds_sampler *s = sampler_new(1.0, 3);
    size_t added = 7;
    ck_assert_int_eq(pds_set_radius_map(s, SIDE, SIDE, map), 0);
    ck_assert_int_eq(pds_run(s, 0, &added), PDS_ERANGE);
    ck_assert_uint_eq(added, 0);
    ck_assert_uint_eq(pds_count(s), 0);
    free(map);
    pds_destroy(s);
}
END_TEST

static double small_pixel_fn(void *user, double x, double y)
{
    (void)user;
    return (x > 0.47 && x < 0.48 && y > 0.31 && y < 0.32) ? 1e-5 : 0.05;
}

/* The same field as a function: judged at rmin, refused. */
START_TEST(function_judged_at_rmin)
{
    pds_sampler *s = sampler_new(1.0, 3);
    ck_assert_int_eq(pds_set_radius_fn(s, small_pixel_fn, NULL, 1e-5, 0.05), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_ERANGE);
    ck_assert_uint_eq(pds_count(s), 0);
    /* Bounded runs make it (judged on the count asked for). */
    ck_assert_int_eq(pds_run(s, 100, NULL), PDS_MORE);
    pds_destroy(s);
}
END_TEST

Suite *field_bound_suite(void)
{
    Suite *s = suite_create("field_bound");
    TCase *tc = new_tcase(s, "one_small_pixel_runs_to_the_end");
    tcase_add_test(tc, one_small_pixel_runs_to_the_end);
    tc = new_tcase(s, "small_everywhere_is_refused");
    tcase_add_test(tc, small_everywhere_is_refused);
    tc = new_tcase(s, "function_judged_at_rmin");
    tcase_add_test(tc, function_judged_at_rmin);
    return s;
}
