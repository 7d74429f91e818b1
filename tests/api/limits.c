/*
 * limits.c - tiny, huge and far-off domains: what the radius and domain allow.
 *
 * Contract (spec 1.1.1): pds_create and pds_set_domain no
 * longer judge the radius against the domain. The pair is judged when first
 * used: at the first point (pds_step, pds_run), or at pds_refine once points
 * exist. PDS_ERANGE then comes before any point is added, when (a) R is below
 * 2^-26 of the domain's largest |coordinate|, (b) every coordinate is below
 * 2^-900, or (c) the points asked for cannot fit 32-bit mesh indices (about
 * 3.5e8): for an unbounded pds_run, a maximal pattern might not fit; for a
 * bounded one, count + max_new (capped by that bound) must fit; pds_step fails
 * only when the index space is full. A rejected call changes nothing, so
 * before the first point the domain may still be set again. The cases that
 * were argument errors in 1.0 (pds_create with a tiny radius, pds_set_domain
 * with a huge or unresolvable rectangle) moved here from args.c.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

/* pds_create(&s, r, seed) must now succeed, whatever the radius's size. */
static pds_sampler *created(double r, uint64_t seed)
{
    pds_sampler *s = NULL;
    int rc = pds_create(&s, r, seed);
    ck_assert_msg(rc == 0 && s != NULL, "pds_create(&s, %g, %llu) returned %d (%s): the radius "
                  "alone is never out of range", r, (unsigned long long)seed, rc,
                  pds_strerror(rc));
    return s;
}

/* Every point inside d and at least r apart. The distances are checked in a
 * frame scaled by a power of two (exact), so that squares of coordinates near
 * 1e-271 do not underflow to 0 and make every pair look far enough apart. */
static void assert_valid_points(const pds_sampler *s, test_domain d, double r, const char *what)
{
    const double big = fmax(fmax(fabs(d.x0), fabs(d.x1)), fmax(fabs(d.y0), fabs(d.y1)));
    const int k = -ilogb(big);
    size_t n, i;
    double *xy = points_copy(s, &n);

    assert_inside(xy, n, d, what);
    for (i = 0; i < 2 * n; i++)
        xy[i] = ldexp(xy[i], k);
    assert_min_distance(xy, n, ldexp(r, k), what);
    free(xy);
}

START_TEST(tiny_domain_maximal)
{
    /* R = 1e-5 in a square of side 1e-3 (5e-4 light): the unit square's
     * pattern shrunk 100 times, about 7000 points (1750). */
    const double r = 1e-5, side = test_light() ? 5e-4 : 1e-3;
    const test_domain d = {0.0, 0.0, side, side};
    uint64_t seed;

    for (seed = 1; seed <= 2; seed++) {
        pds_sampler *s = created(r, seed);
        char what[96];
        size_t n;
        snprintf(what, sizeof what, "R 1e-5 in [0,%g]^2, seed %llu", side,
                 (unsigned long long)seed);
        ck_assert_int_eq(pds_set_domain(s, d.x0, d.y0, d.x1, d.y1), 0);
        assert_rel_close(pds_free_area(s), side * side, 1e-12, what);
        n = run_to_end(s);
        ck_assert_msg(n > (size_t)(0.5 * side * side / (r * r)), "%s: only %zu points", what, n);
        assert_valid_points(s, d, r, what);
        assert_maximal(s, what);
        pds_destroy(s);
    }
}
END_TEST

/* A domain (and radius) rejected at the first point, and one that then works. */
struct far_case {
    const char *why;
    double r;
    test_domain rejected, accepted;
    const char *because; /* in pds_errmsg after every refused call */
};

static const struct far_case far_cases[] = {
    /* Doubles near 1e15 are 0.125 apart: R = 0.05 is not resolvable there. */
    {"R below 2^-26 of |coordinates| near 1e15", 0.05,
     {1e15, 0.0, 1e15 + 1.0, 1.0}, {0.0, 0.0, 1.0, 1.0}, "for double precision"},
    {"R below 2^-26 of |coordinates| near -1e9", 1.0,
     {-1e9, -1e9, -1e9 + 30.0, -1e9 + 30.0}, {-30.0, 0.0, 0.0, 30.0}, "for double precision"},
    {"R = 1e-9 below 2^-26 of |coordinates| near 1", 1e-9,
     {1.0, 1.0, 1.0 + 5e-8, 1.0 + 5e-8}, {0.0, 0.0, 5e-8, 5e-8}, "for double precision"},
    /* Every coordinate below 2^-900 (about 1.5e-271): the reason even for an
     * unbounded run, whose count bound (the area over R^2) underflows there. */
    {"coordinates below 2^-900", 1e-273,
     {0.0, 0.0, 1e-272, 1e-272}, {0.0, 0.0, 2e-271, 2e-271}, "too close to zero"},
};

START_TEST(far_domain_rejected_at_first_point)
{
    const struct far_case *c = &far_cases[_i];
    const test_domain bad = c->rejected, good = c->accepted;
    pds_sampler *s = created(c->r, 9);
    char what[160];
    size_t added = 0;
    int rc;

    snprintf(what, sizeof what, "%s: R %g in [%.17g,%.17g]x[%.17g,%.17g]", c->why, c->r, bad.x0,
             bad.x1, bad.y0, bad.y1);
    rc = pds_set_domain(s, bad.x0, bad.y0, bad.x1, bad.y1);
    ck_assert_msg(rc == 0, "%s: pds_set_domain returned %d (%s); the pair is judged at the first "
                  "point", what, rc, pds_errmsg(s));
    /* Precision rejects every way of adding a point, bounded or not, and
     * each says so. */
    assert_run_rejected(s, 0, what);
    ck_assert_msg(strstr(pds_errmsg(s), c->because) != NULL, "%s: pds_run(s, 0) said \"%s\"", what,
                  pds_errmsg(s));
    assert_run_rejected(s, 1, what);
    ck_assert_msg(strstr(pds_errmsg(s), c->because) != NULL, "%s: pds_run(s, 1) said \"%s\"", what,
                  pds_errmsg(s));
    assert_step_rejected(s, what);
    ck_assert_msg(strstr(pds_errmsg(s), c->because) != NULL, "%s: pds_step said \"%s\"", what,
                  pds_errmsg(s));
    ck_assert_int_eq(pds_verify(s), 1); /* the empty pattern is valid */
    /* Nothing was added, so the domain may still change, and then it works. */
    rc = pds_set_domain(s, good.x0, good.y0, good.x1, good.y1);
    ck_assert_msg(rc == 0, "%s: pds_set_domain to a good domain afterwards returned %d (%s)", what,
                  rc, pds_errmsg(s));
    rc = pds_run(s, 50, &added);
    ck_assert_msg(rc == PDS_MORE && added == 50, "%s: then pds_run(s, 50) returned %d, added %zu "
                  "(%s)", what, rc, added, pds_errmsg(s));
    assert_valid_points(s, good, c->r, what);
    pds_destroy(s);
}
END_TEST

/* ---- formerly argument errors (1.0): now judged at the first point -------------- */

START_TEST(create_tiny_radius)
{
    /* Positive and finite, but far too small for the unit square. Since 1.1.1
     * pds_create accepts them: the radius is judged with the domain at the
     * first point (pds_set_domain could still make it fit). The last one is
     * the smallest subnormal double, 2^-1074. */
    const double tiny[] = {1e-9, 1e-12, 1e-300, DBL_MIN, DBL_MIN * DBL_EPSILON};
    size_t i;

    for (i = 0; i < sizeof tiny / sizeof tiny[0]; i++) {
        char what[96];
        pds_sampler *s = NULL;
        int rc = pds_create(&s, tiny[i], 1);
        snprintf(what, sizeof what, "pds_create(&s, %g, 1), then the first point", tiny[i]);
        ck_assert_msg(rc == 0 && s != NULL, "%s: pds_create returned %d (%s)", what, rc,
                      pds_strerror(rc));
        ck_assert_msg(pds_radius(s) == tiny[i], "%s: radius %g", what, pds_radius(s));
        assert_run_rejected(s, 0, what);
        assert_run_rejected(s, 10, what);
        assert_step_rejected(s, what);
        ck_assert_msg(pds_free_area(s) == 1.0, "%s: free area %g", what, pds_free_area(s));
        pds_destroy(s);
    }
}
END_TEST

/* The domain the handle starts on, so "unchanged" is not the default. */
static const test_domain OLD_DOMAIN = {0.0, 0.0, 2.0, 3.0};

/*
 * Since 1.1.1 pds_set_domain accepts a rectangle too large or too far out for
 * the radius; the first pds_run / pds_step rejects it (PDS_ERANGE, nothing
 * added), and the domain can then be set again. Ends back on OLD_DOMAIN, so a
 * twin that never saw the bad domain must give the same points.
 */
static void check_domain_rejected_at_first_point(const test_domain *bad, size_t nbad,
                                                 int bounded_too, uint64_t seed)
{
    pds_sampler *a, *b;
    sampler_snapshot snap;
    size_t i, n;
    double *xy;

    twins_new(0.05, seed, &OLD_DOMAIN, 0, &a, &b);
    snapshot_take(a, &snap);
    for (i = 0; i < nbad; i++) {
        char what[160];
        test_domain d = bad[i];
        int rc = pds_set_domain(a, d.x0, d.y0, d.x1, d.y1);
        snprintf(what, sizeof what, "pds_set_domain(%g, %g, %g, %g) with R = 0.05, then the "
                 "first point", d.x0, d.y0, d.x1, d.y1);
        ck_assert_msg(rc == 0, "%s: pds_set_domain returned %d (%s)", what, rc, pds_errmsg(a));
        assert_run_rejected(a, 0, what);
        if (bounded_too) {
            assert_run_rejected(a, 5, what);
            assert_step_rejected(a, what);
        }
        ck_assert_int_eq(pds_set_domain(a, OLD_DOMAIN.x0, OLD_DOMAIN.y0, OLD_DOMAIN.x1,
                                        OLD_DOMAIN.y1), 0);
        snapshot_check(a, &snap, what);
    }
    snapshot_free(&snap);
    assert_same_future(a, b, "after domains rejected at the first point");
    xy = points_copy(a, &n);
    assert_inside(xy, n, OLD_DOMAIN, "after domains rejected at the first point");
    free(xy);
    pds_destroy(a);
    pds_destroy(b);
}

START_TEST(set_domain_too_large)
{
    /* R = 0.05 is moderate; a maximal pattern in these rectangles would need
     * far more points than the indices hold. The last one has finite corners,
     * but its width overflows to infinity. The first is still resolvable, so
     * only an unbounded run is refused there (limits.c runs a bounded one);
     * the others are also beyond double precision at R = 0.05. */
    static const test_domain huge[] = {
        {0.0, 0.0, 1e6, 1e6},
        {-1e12, -1e12, 1e12, 1e12},
        {-DBL_MAX, -DBL_MAX, DBL_MAX, DBL_MAX},
    };
    check_domain_rejected_at_first_point(huge, 1, 0, 13);
    check_domain_rejected_at_first_point(huge + 1, 2, 1, 13);
}
END_TEST

START_TEST(set_domain_unresolvable)
{
    /* Near 1e15 doubles are 0.125 apart, so a radius of 0.05 cannot be
     * resolved there even though the rectangle is small: PDS_ERANGE
     * ("double precision cannot resolve it") at the first point. */
    static const test_domain far[] = {{1e15, 0.0, 1e15 + 1.0, 1.0}};
    check_domain_rejected_at_first_point(far, 1, 1, 14);
}
END_TEST

/* ---- patterns too large to finish ----------------------------------------------- */

/* R = 1e-6 in the unit square: a maximal pattern (about 1.2e12 points by
 * Oler's bound) cannot fit the indices, but a bounded run or steps can. */
#define HUGE_R 1e-6

START_TEST(huge_bounded_run)
{
    pds_sampler *s = created(HUGE_R, 7);
    size_t added = 0;
    int rc;

    rc = pds_run(s, 1000, &added);
    ck_assert_msg(rc == PDS_MORE && added == 1000, "R 1e-6, pds_run(s, 1000) returned %d, added "
                  "%zu (%s)", rc, added, pds_errmsg(s));
    ck_assert_uint_eq(pds_count(s), 1000);
    assert_valid_points(s, UNIT_SQUARE, HUGE_R, "R 1e-6, 1000 points");
    ck_assert_int_eq(pds_verify(s), PDS_MORE);
    /* Now an unbounded run is judged: it could not end in a maximal pattern. */
    assert_run_rejected(s, 0, "R 1e-6 with 1000 points, pds_run(s, 0)");
    /* A bounded run whose end cannot fit either: count + 1e9 > the index space. */
    assert_run_rejected(s, 1000000000, "R 1e-6 with 1000 points, pds_run(s, 1e9)");
    /* The sampler is still usable. */
    rc = pds_run(s, 1000, &added);
    ck_assert_msg(rc == PDS_MORE && added == 1000, "R 1e-6, a second pds_run(s, 1000) returned "
                  "%d, added %zu (%s)", rc, added, pds_errmsg(s));
    ck_assert_int_eq(pds_step(s), PDS_MORE);
    ck_assert_uint_eq(pds_count(s), 2001);
    assert_valid_points(s, UNIT_SQUARE, HUGE_R, "R 1e-6, 2001 points");
    pds_destroy(s);
}
END_TEST

START_TEST(huge_unbounded_run_rejected)
{
    pds_sampler *s = created(HUGE_R, 8);
    size_t i;

    /* On a fresh sampler: PDS_ERANGE, nothing added, count 0. */
    assert_run_rejected(s, 0, "R 1e-6, fresh, pds_run(s, 0)");
    ck_assert_uint_eq(pds_count(s), 0);
    /* pds_step adds one point at a time: it fails only when the index space is full. */
    for (i = 0; i < 200; i++)
        ck_assert_int_eq(pds_step(s), PDS_MORE);
    ck_assert_uint_eq(pds_count(s), 200);
    assert_valid_points(s, UNIT_SQUARE, HUGE_R, "R 1e-6, 200 steps after a rejected run");
    pds_destroy(s);
}
END_TEST

START_TEST(huge_domain_bounded_run)
{
    /* The same through the domain: R = 0.05 in [0,1e6]^2 is resolvable, but a
     * maximal pattern would need about 4.6e14 points. */
    const test_domain d = {0.0, 0.0, 1e6, 1e6};
    pds_sampler *s = created(0.05, 10);
    size_t added = 0;
    int rc;

    ck_assert_int_eq(pds_set_domain(s, d.x0, d.y0, d.x1, d.y1), 0);
    assert_run_rejected(s, 0, "R 0.05 in [0,1e6]^2, pds_run(s, 0)");
    rc = pds_run(s, 300, &added);
    ck_assert_msg(rc == PDS_MORE && added == 300, "R 0.05 in [0,1e6]^2, pds_run(s, 300) returned "
                  "%d, added %zu (%s)", rc, added, pds_errmsg(s));
    assert_valid_points(s, d, 0.05, "R 0.05 in [0,1e6]^2, 300 points");
    pds_destroy(s);
}
END_TEST

START_TEST(refine_judges_precision_now_count_later)
{
    /* With points, pds_refine judges precision at once; the count limit waits
     * for the next unbounded run. */
    pds_sampler *s = sampler_new(0.05, 11);
    sampler_snapshot snap;
    size_t added = 0;
    int rc;

    ck_assert_int_eq(pds_run(s, 10, NULL), PDS_MORE);
    snapshot_take(s, &snap);
    assert_failed(s, pds_refine(s, 1e-9), PDS_ERANGE, "pds_refine(s, 1e-9) with 10 points");
    snapshot_check(s, &snap, "after pds_refine(s, 1e-9) was rejected");
    snapshot_free(&snap);
    rc = pds_refine(s, HUGE_R);
    ck_assert_msg(rc == 0, "pds_refine(s, 1e-6) with 10 points returned %d (%s): the count limit "
                  "is judged by the next unbounded run", rc, pds_errmsg(s));
    ck_assert_msg(pds_radius(s) == HUGE_R, "radius %.17g after pds_refine(s, 1e-6)",
                  pds_radius(s));
    assert_run_rejected(s, 0, "pds_run(s, 0) after pds_refine(s, 1e-6)");
    rc = pds_run(s, 100, &added);
    ck_assert_msg(rc == PDS_MORE && added == 100, "pds_run(s, 100) after pds_refine(s, 1e-6) "
                  "returned %d, added %zu (%s)", rc, added, pds_errmsg(s));
    assert_valid_points(s, UNIT_SQUARE, HUGE_R, "110 points after pds_refine(s, 1e-6)");
    pds_destroy(s);
}
END_TEST

Suite *limits_suite(void)
{
    Suite *suite = suite_create("limits");
    TCase *tc;

    tc = new_tcase(suite, "tiny_domain");
    tcase_add_test(tc, tiny_domain_maximal);
    tc = new_tcase(suite, "create_tiny_radius");
    tcase_add_test(tc, create_tiny_radius);
    tc = new_tcase(suite, "set_domain_too_large");
    tcase_add_test(tc, set_domain_too_large);
    tc = new_tcase(suite, "set_domain_unresolvable");
    tcase_add_test(tc, set_domain_unresolvable);
    tc = new_tcase(suite, "far_domain");
    tcase_add_loop_test(tc, far_domain_rejected_at_first_point, 0,
                        (int)(sizeof far_cases / sizeof far_cases[0]));
    tc = new_tcase(suite, "huge_pattern");
    tcase_add_test(tc, huge_bounded_run);
    tcase_add_test(tc, huge_unbounded_run_rejected);
    tcase_add_test(tc, huge_domain_bounded_run);
    tc = new_tcase(suite, "refine_limits");
    tcase_add_test(tc, refine_judges_precision_now_count_later);
    return suite;
}
