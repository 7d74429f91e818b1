/*
 * documented.c - behaviours the man pages state as measured facts, pinned
 * so the pages cannot drift from the code again.
 *
 *   pds_set_periodic(3): the radius is judged against half the period as
 *     given, so R = 0.05 on a 0.1 torus (rounded down by under 1e-15) is
 *     accepted and gives a valid, maximal pattern.
 *   pds_set_count(3): the start comes from a two-dimensional estimate; on a
 *     thin domain it is off: a 1024 x 1 rectangle at n = 1000 ends near
 *     0.95 R(n), and a 1000 x 1 torus at n = 3000 reaches n at its starting
 *     radius, never lowered, not maximal.
 *   pds_progress_fn: a nonzero return at the final report (done == 1, the
 *     pattern complete) stops nothing: pds_run returns PDS_DONE.
 */
#include <math.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

START_TEST(radius_half_of_a_rounded_period)
{
    const test_domain d = {0.0, 0.0, 0.1, 0.1};
    pds_sampler *s = sampler_new_in(0.05, 4, d);

    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_DONE);
    ck_assert_uint_ge(pds_count(s), 1);
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    pds_destroy(s);
}
END_TEST

/* R(n) of pds_set_count: n = 0.547 4A/(pi R^2) + 0.23 P/R, no P on a torus. */
static double r_of_n(double w, double h, int torus, double n)
{
    const double a = 0.547 * 4.0 * w * h / 3.14159265358979323846, b = torus ? 0.0 : 0.23 * 2.0 * (w + h);
    return (b + sqrt(b * b + 4.0 * a * n)) / (2.0 * n);
}

static pds_sampler *count_run(double w, double h, int torus, size_t n, uint64_t seed)
{
    const test_domain d = {0.0, 0.0, w, h};
    pds_sampler *s = sampler_new_in(1.0, seed, d);
    ck_assert_int_eq(pds_set_periodic(s, torus), 0);
    ck_assert_int_eq(pds_set_count(s, n), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_DONE);
    ck_assert_uint_eq(pds_count(s), n);
    return s;
}

START_TEST(count_on_a_thin_rectangle)
{
    uint64_t seed;
    for (seed = 1; seed <= 4; seed++) {
        pds_sampler *s = count_run(1024.0, 1.0, 0, 1000, seed);
        const double ratio = pds_radius(s) / r_of_n(1024.0, 1.0, 0, 1000.0);
        ck_assert_msg(ratio > 0.93 && ratio < 0.97, "seed %d: R = %.4f R(n)", (int)seed, ratio);
        pds_destroy(s);
    }
}
END_TEST

START_TEST(count_on_a_thin_torus_never_lowered)
{
    pds_sampler *s = count_run(1000.0, 1.0, 1, 3000, 1);
    const double start = (1.015 + 10.0 / 3000.0) * r_of_n(1000.0, 1.0, 1, 3000.0);

    /* The starting radius, under the cap of half the period, kept to the end. */
    ck_assert_msg(start < 0.5, "the start %.4f is capped", start);
    ck_assert_msg(fabs(pds_radius(s) - start) < 1e-9 * start, "R = %.6f, start %.6f", pds_radius(s), start);
    ck_assert_int_eq(pds_verify(s), PDS_MORE);
    pds_destroy(s);
}
END_TEST

static int stop_at_the_end(void *user, size_t count, double done)
{
    size_t *finals = user;
    (void)count;
    if (done == 1.0) ++*finals;
    return done == 1.0;
}

START_TEST(stop_at_final_report)
{
    size_t finals = 0, added = 0;
    pds_sampler *s = sampler_new(0.05, 8);

    ck_assert_int_eq(pds_set_progress(s, stop_at_the_end, &finals), 0);
    ck_assert_int_eq(pds_run(s, 0, &added), PDS_DONE);
    ck_assert_uint_eq(finals, 1);
    ck_assert_uint_eq(added, pds_count(s));
    ck_assert_int_eq(pds_verify(s), PDS_DONE);
    /* Again: complete at once, one more final report, still PDS_DONE. */
    ck_assert_int_eq(pds_run(s, 0, &added), PDS_DONE);
    ck_assert_uint_eq(added, 0);
    ck_assert_uint_eq(finals, 2);
    pds_destroy(s);
}
END_TEST

Suite *documented_suite(void)
{
    Suite *s = suite_create("documented");
    TCase *tc = new_tcase(s, "radius_half_of_a_rounded_period");
    tcase_add_test(tc, radius_half_of_a_rounded_period);
    tc = new_tcase(s, "count_on_a_thin_rectangle");
    tcase_add_test(tc, count_on_a_thin_rectangle);
    tc = new_tcase(s, "count_on_a_thin_torus_never_lowered");
    tcase_add_test(tc, count_on_a_thin_torus_never_lowered);
    tc = new_tcase(s, "stop_at_final_report");
    tcase_add_test(tc, stop_at_final_report);
    return s;
}
