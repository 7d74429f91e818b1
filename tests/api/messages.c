/*
 * messages.c - pds_errmsg names the real cause.
 *
 * Contract (poissondisk.h): a failed call's message says why. With a radius
 * field two radii are judged at the first point: the smallest against the
 * domain's precision and size, the largest against a torus's period; the
 * message names the one at fault. A changing call from inside a user
 * callback is refused (PDS_ESTATE), and the message names that callback: the
 * progress callback or the radius function.
 */
#include <string.h>

#include "helpers.h"
#include "suites.h"

static void assert_says(const pds_sampler *s, const char *part, const char *what)
{
    ck_assert_msg(strstr(pds_errmsg(s), part) != NULL, "%s: \"%s\" does not say \"%s\"", what,
                  pds_errmsg(s), part);
}

static void assert_does_not_say(const pds_sampler *s, const char *part, const char *what)
{
    ck_assert_msg(strstr(pds_errmsg(s), part) == NULL, "%s: \"%s\" says \"%s\"", what,
                  pds_errmsg(s), part);
}

/* rmax over half the period, rmin fine: the largest radius is the cause. */
START_TEST(field_largest_radius_over_period)
{
    const double map[2] = {0.01, 0.6};
    pds_sampler *s = sampler_new(1.0, 1);

    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_ERANGE);
    assert_says(s, "largest radius", "rmax over half the period");
    assert_says(s, "half the shorter period", "rmax over half the period");
    assert_says(s, "0.6", "rmax over half the period");
    assert_does_not_say(s, "too small", "rmax over half the period");
    ck_assert_uint_eq(pds_count(s), 0);
    pds_destroy(s);
}
END_TEST

/* rmin below precision: the smallest radius is the cause. */
START_TEST(field_smallest_radius_below_precision)
{
    const double map[2] = {1e-12, 0.1};
    pds_sampler *s = sampler_new(1.0, 1);

    ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_ERANGE);
    assert_says(s, "smallest radius", "rmin below precision");
    assert_says(s, "too small", "rmin below precision");
    assert_says(s, "1e-12", "rmin below precision");
    pds_destroy(s);
}
END_TEST

/* A plain radius over the period: "the radius", no field named. */
START_TEST(radius_over_period)
{
    pds_sampler *s = sampler_new(0.6, 1);

    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_ERANGE);
    assert_says(s, "the radius is larger than half the shorter period", "R over half the period");
    assert_does_not_say(s, "field", "R over half the period");
    pds_destroy(s);
}
END_TEST

/* The radius function tries a changing call on its own sampler. */
struct meddler {
    pds_sampler *s;
    int rc;
    size_t calls;
};

static double meddling_field(void *user, double x, double y)
{
    struct meddler *m = user;
    (void)y;
    if (m->calls++ == 3) m->rc = pds_set_domain(m->s, 0.0, 0.0, 2.0, 2.0);
    return x < 0.5 ? 0.05 : 0.1;
}

static int go_on(void *user, size_t count, double done)
{
    (void)user;
    (void)count;
    (void)done;
    return 0;
}

START_TEST(change_from_radius_function)
{
    int with_progress;
    for (with_progress = 0; with_progress < 2; with_progress++) {
        struct meddler m = {NULL, 0, 0};
        pds_sampler *s = sampler_new(1.0, 2);
        m.s = s;
        ck_assert_int_eq(pds_set_radius_fn(s, meddling_field, &m, 0.05, 0.1), 0);
        if (with_progress) ck_assert_int_eq(pds_set_progress(s, go_on, NULL), 0);
        ck_assert_int_eq(pds_run(s, 10, NULL), PDS_MORE);
        ck_assert_int_eq(m.rc, PDS_ESTATE);
        assert_says(s, "pds_set_domain: not allowed from inside the radius function", "from the function");
        ck_assert_msg(pds_errmsg(s) == strstr(pds_errmsg(s), "pds_set_domain"), "%s", pds_errmsg(s));
        pds_destroy(s);
    }
}
END_TEST

/* The progress callback's own refusal still names it. */
static int meddling_progress(void *user, size_t count, double done)
{
    struct meddler *m = user;
    (void)count;
    (void)done;
    if (m->calls++ == 0) m->rc = pds_step(m->s);
    return 0;
}

START_TEST(change_from_progress_callback)
{
    struct meddler m = {NULL, 0, 0};
    pds_sampler *s = sampler_new(0.05, 2);
    m.s = s;
    ck_assert_int_eq(pds_set_progress(s, meddling_progress, &m), 0);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_DONE);
    ck_assert_int_eq(m.rc, PDS_ESTATE);
    assert_says(s, "pds_step: not allowed from inside the progress callback", "from the callback");
    pds_destroy(s);
}
END_TEST

Suite *messages_suite(void)
{
    Suite *s = suite_create("messages");
    TCase *tc = new_tcase(s, "field_largest_radius_over_period");
    tcase_add_test(tc, field_largest_radius_over_period);
    tc = new_tcase(s, "field_smallest_radius_below_precision");
    tcase_add_test(tc, field_smallest_radius_below_precision);
    tc = new_tcase(s, "radius_over_period");
    tcase_add_test(tc, radius_over_period);
    tc = new_tcase(s, "change_from_radius_function");
    tcase_add_test(tc, change_from_radius_function);
    tc = new_tcase(s, "change_from_progress_callback");
    tcase_add_test(tc, change_from_progress_callback);
    return s;
}
