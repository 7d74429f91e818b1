/*
 * field_range.c - a radius field on domains at the ends of the double range.
 *
 * Contract (poissondisk.h): the domain is any finite rectangle; a field's
 * value at a point is its map's bilinear interpolation there, or its
 * function's value at a point of the domain; every point's radius is a
 * number in [rmin, rmax]. A domain from -1.7e308 to 1.7e308 has sides wider
 * than the largest double, so a fraction of them computed as (x - x0) /
 * (x1 - x0) is inf / inf: the map must still give finite radii, and the
 * function must only ever be asked at finite points of the domain.
 */
#include <math.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

static const test_domain WIDEST = {-1.7e308, -1.7e308, 1.7e308, 1.7e308};

/* Every one of the n points has a radius in [lo, hi]. */
static void assert_radii_between(const pds_sampler *s, size_t n, double lo, double hi)
{
    double *r = malloc(n * sizeof *r);
    size_t i;

    ck_assert_ptr_nonnull(r);
    ck_assert_uint_eq(pds_radii(s, 0, n, r), n);
    for (i = 0; i < n; i++)
        ck_assert_msg(r[i] >= lo && r[i] <= hi, "point %zu has radius %g", i, r[i]);
    free(r);
}

/* A map of two values over the widest domain: a full, valid pattern. */
START_TEST(test_map_over_widest_domain)
{
    const double map[2] = {1e306, 3e306};
    pds_sampler *s = sampler_new_in(1.0, 5, WIDEST);
    size_t n, added = 0;

    ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
    ck_assert_int_eq(pds_run(s, 0, &added), PDS_DONE);
    n = pds_count(s);
    /* The sides are 340 rmin long: thousands of points, not one. */
    ck_assert_msg(n > 1000, "only %zu points over a domain 340 rmin wide", n);
    assert_radii_between(s, n, 1e306, 3e306);
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    ck_assert(pds_free_area(s) == 0.0);
    pds_destroy(s);
}
END_TEST

/* Where a radius function was asked, and whether any point was outside. */
struct asked {
    size_t calls, outside;
};

static double watched(void *user, double x, double y)
{
    struct asked *a = user;
    a->calls++;
    if (!(x >= WIDEST.x0 && x <= WIDEST.x1 && y >= WIDEST.y0 && y <= WIDEST.y1)) a->outside++;
    return x < 0.0 ? 1e306 : 3e306;
}

static int quiet(void *user, size_t count, double done)
{
    (void)user;
    (void)count;
    (void)done;
    return 0;
}

/* With a progress callback the function is also asked for the estimate of
   the count: every one of those points, too, lies in the domain. */
START_TEST(test_function_asked_inside_widest_domain)
{
    struct asked a = {0, 0};
    pds_sampler *s = sampler_new_in(1.0, 5, WIDEST);
    size_t added = 0;

    ck_assert_int_eq(pds_set_radius_fn(s, watched, &a, 1e306, 3e306), 0);
    ck_assert_int_eq(pds_set_progress(s, quiet, NULL), 0);
    ck_assert_int_eq(pds_run(s, 50, &added), PDS_MORE);
    ck_assert_uint_eq(added, 50);
    ck_assert_msg(a.calls >= 50, "the function was asked %zu times for 50 points", a.calls);
    ck_assert_msg(a.outside == 0, "%zu of %zu calls were outside the domain", a.outside, a.calls);
    pds_destroy(s);
}
END_TEST

/* The same map on the torus over the widest domain (rmax under half the period). */
START_TEST(test_map_on_widest_torus)
{
    const double map[4] = {1e306, 3e306, 2e306, 1e306};
    pds_sampler *s = sampler_new_in(1.0, 9, WIDEST);
    size_t n;

    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    ck_assert_int_eq(pds_set_radius_map(s, 2, 2, map), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_DONE);
    n = pds_count(s);
    ck_assert_msg(n > 1000, "only %zu points on a torus 340 rmin wide", n);
    assert_radii_between(s, n, 1e306, 3e306);
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    pds_destroy(s);
}
END_TEST

Suite *field_range_suite(void)
{
    Suite *s = suite_create("field_range");
    TCase *tc = new_tcase(s, "map_over_widest_domain");
    tcase_add_test(tc, test_map_over_widest_domain);
    tc = new_tcase(s, "function_asked_inside_widest_domain");
    tcase_add_test(tc, test_function_asked_inside_widest_domain);
    tc = new_tcase(s, "map_on_widest_torus");
    tcase_add_test(tc, test_map_on_widest_torus);
    return s;
}
