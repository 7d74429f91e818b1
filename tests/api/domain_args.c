/*
 * domain_args.c - pds_set_polygon and pds_set_mask: what they refuse, and
 * when (pds_set_fixed: domain_fixed.c).
 *
 * Contract (poissondisk.h, 1.4): a polygon with a NULL array, a ring of fewer
 * than 3 distinct vertices or all on one line, a coordinate not finite,
 * decreasing ring ends or an outline enclosing nothing is PDS_EINVAL, the
 * message naming the ring (and the vertex, counted from 0), and so are rings
 * that cross one another more than 4 times per vertex and 65536 (1.7.5); a mask with a
 * NULL raster, a size that overflows or no pixel inside is PDS_EINVAL; a
 * polygon or a mask with pds_set_periodic is PDS_EINVAL, either way round;
 * both are PDS_ESTATE once points exist; nrings 0, w or h 0 go back. A failed call leaves the sampler as it was: it
 * gives the points of a twin that never saw the call.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "region.h"
#include "suites.h"

static void assert_says(const pds_sampler *s, const char *part, const char *what)
{
    ck_assert_msg(strstr(pds_errmsg(s), part) != NULL, "%s: \"%s\" does not say \"%s\"", what,
                  pds_errmsg(s), part);
}

static pds_sampler *in_unit_l(double r, uint64_t seed)
{
    pds_sampler *s = sampler_new(r, seed);
    ck_assert_int_eq(pds_set_polygon(s, UNIT_L.xy, UNIT_L.ends, UNIT_L.nrings), 0);
    return s;
}

/* The failed call left a (set to the unit L) as its twin b. */
static void assert_unchanged(pds_sampler *a, pds_sampler *b, const char *what)
{
    ck_assert_uint_eq(pds_count(a), 0);
    assert_rel_close(pds_free_area(a), UNIT_L_AREA, 1e-12, what);
    assert_same_future(a, b, what);
}

/* A bad polygon: ring 0 a valid square, ring 1 at fault. */
struct bad_polygon {
    const char *name;
    double xy[16];
    size_t ends[2], nrings;
    const char *says[2]; /* parts the message must hold */
};

static const struct bad_polygon bad_polygons[] = {
    {"ring 1 with 2 distinct vertices (4 given)",
     {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.2, 0.5, 0.5, 0.5, 0.5, 0.2, 0.2},
     {4, 8}, 2, {"ring 1", NULL}},
    {"ring 1 all on one line",
     {0, 0, 1, 0, 1, 1, 0, 1, 0.1, 0.1, 0.2, 0.2, 0.4, 0.4, 0.3, 0.3},
     {4, 8}, 2, {"ring 1", NULL}},
    {"NaN at ring 1 vertex 2",
     {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.2, 0.5, 0.2, NAN, 0.5, 0.2, 0.5},
     {4, 8}, 2, {"ring 1", "vertex 2"}},
    {"infinite y at ring 1 vertex 3",
     {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.2, 0.5, 0.2, 0.5, 0.5, 0.2, INFINITY},
     {4, 8}, 2, {"ring 1", "vertex 3"}},
    {"ring ends decreasing at ring 1",
     {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.2, 0.5, 0.2, 0.5, 0.5, 0.2, 0.5},
     {5, 4}, 2, {"ring 1", NULL}},
    {"one ring tracing a square twice, enclosing nothing",
     {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1},
     {8, 0}, 1, {"nothing", NULL}},
    {"two rings the same square, enclosing nothing",
     {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1},
     {4, 8}, 2, {"nothing", NULL}},
};
#define N_BAD_POLYGONS (sizeof bad_polygons / sizeof bad_polygons[0])

START_TEST(polygon_refused)
{
    const struct bad_polygon *p = &bad_polygons[_i];
    pds_sampler *a = in_unit_l(0.05, 7), *b = in_unit_l(0.05, 7);
    int k;

    assert_failed(a, pds_set_polygon(a, p->xy, p->ends, p->nrings), PDS_EINVAL, p->name);
    ck_assert_msg(strncmp(pds_errmsg(a), "pds_set_polygon", 15) == 0, "%s: \"%s\"", p->name,
                  pds_errmsg(a));
    for (k = 0; k < 2; k++)
        if (p->says[k])
            assert_says(a, p->says[k], p->name);
    /* Still usable: a valid polygon is taken (the same L again). */
    ck_assert_int_eq(pds_set_polygon(a, UNIT_L.xy, UNIT_L.ends, UNIT_L.nrings), 0);
    assert_unchanged(a, b, p->name);
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* A ring of 1500 random vertices crosses itself about 225,000 times: more
 * than the 4 per vertex and 65536 the library splits. */
START_TEST(polygon_crossing_itself_too_often_refused)
{
    enum { n = 1500 };
    static double xy[2 * n];
    const size_t ends[] = {n};
    pds_sampler *a = in_unit_l(0.05, 7), *b = in_unit_l(0.05, 7);
    uint64_t x = 12345;
    size_t k;

    for (k = 0; k < 2 * n; k++) {
        x = x * 6364136223846793005u + 1442695040888963407u;
        xy[k] = (double)(x >> 11) * 0x1p-53;
    }
    assert_failed(a, pds_set_polygon(a, xy, ends, 1), PDS_EINVAL, "a scribble of 1500 vertices");
    assert_says(a, "cross one another more than 71536 times", "a scribble of 1500 vertices");
    ck_assert_int_eq(pds_set_polygon(a, UNIT_L.xy, UNIT_L.ends, UNIT_L.nrings), 0);
    assert_unchanged(a, b, "a scribble of 1500 vertices");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(polygon_null_arguments)
{
    pds_sampler *a = in_unit_l(0.05, 8), *b = in_unit_l(0.05, 8);

    assert_failed(NULL, pds_set_polygon(NULL, UNIT_L.xy, UNIT_L.ends, 2), PDS_EINVAL,
                  "pds_set_polygon(NULL, ...)");
    assert_failed(a, pds_set_polygon(a, NULL, UNIT_L.ends, 2), PDS_EINVAL, "xy NULL");
    assert_failed(a, pds_set_polygon(a, UNIT_L.xy, NULL, 2), PDS_EINVAL, "ring_ends NULL");
    assert_unchanged(a, b, "pds_set_polygon with NULL arrays");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(polygon_nrings_0_goes_back)
{
    /* The L's bounding box is the unit square, the default rectangle, so
     * going back gives the plain sampler's points. */
    pds_sampler *a = in_unit_l(0.05, 9), *b = sampler_new(0.05, 9);

    ck_assert_int_eq(pds_set_polygon(a, NULL, NULL, 0), 0);
    assert_rel_close(pds_free_area(a), 1.0, 1e-15, "free area after nrings 0");
    assert_same_future(a, b, "pds_set_polygon(s, NULL, NULL, 0)");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(mask_refused)
{
    static const unsigned char none[6] = {0, 0, 0, 0, 0, 0}, one[1] = {1};
    pds_sampler *a = in_unit_l(0.05, 10), *b = in_unit_l(0.05, 10);
    const size_t half = SIZE_MAX / 2 + 1;

    assert_failed(NULL, pds_set_mask(NULL, 1, 1, one), PDS_EINVAL, "pds_set_mask(NULL, ...)");
    assert_failed(a, pds_set_mask(a, 3, 2, NULL), PDS_EINVAL, "inside NULL, 3 x 2");
    assert_failed(a, pds_set_mask(a, 3, 2, none), PDS_EINVAL, "no pixel inside");
    /* Never read: the size is judged first. */
    assert_failed(a, pds_set_mask(a, half, 2, one), PDS_EINVAL, "w * h overflowing");
    assert_failed(a, pds_set_mask(a, 3, SIZE_MAX, one), PDS_EINVAL, "w * h overflowing");
    assert_unchanged(a, b, "pds_set_mask refused");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(mask_empty_goes_back)
{
    static const unsigned char corner[4] = {1, 0, 0, 0};
    pds_sampler *a = sampler_new(0.05, 11), *b = sampler_new(0.05, 11);

    ck_assert_int_eq(pds_set_mask(a, 2, 2, corner), 0);
    assert_rel_close(pds_free_area(a), 0.25, 1e-15, "free area of one pixel in four");
    ck_assert_int_eq(pds_set_mask(a, 0, 5, NULL), 0);
    assert_rel_close(pds_free_area(a), 1.0, 1e-15, "free area after w 0");
    ck_assert_int_eq(pds_set_mask(a, 2, 2, corner), 0);
    ck_assert_int_eq(pds_set_mask(a, 5, 0, NULL), 0);
    assert_same_future(a, b, "pds_set_mask with h 0");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

START_TEST(periodic_refused_either_way)
{
    static const unsigned char corner[4] = {1, 0, 0, 1};
    pds_sampler *a = sampler_new(0.05, 15), *b = in_unit_l(0.05, 15);

    /* Periodic first: neither a polygon nor a mask. */
    ck_assert_int_eq(pds_set_periodic(a, 1), 0);
    assert_failed(a, pds_set_polygon(a, UNIT_L.xy, UNIT_L.ends, 2), PDS_EINVAL,
                  "pds_set_polygon on a torus");
    assert_failed(a, pds_set_mask(a, 2, 2, corner), PDS_EINVAL, "pds_set_mask on a torus");
    ck_assert_int_eq(pds_set_periodic(a, 0), 0);
    /* Polygon first: no torus; the sampler keeps its polygon. */
    ck_assert_int_eq(pds_set_polygon(a, UNIT_L.xy, UNIT_L.ends, 2), 0);
    assert_failed(a, pds_set_periodic(a, 1), PDS_EINVAL, "pds_set_periodic with a polygon");
    assert_unchanged(a, b, "pds_set_periodic with a polygon");
    pds_destroy(a);
    pds_destroy(b);
    /* Mask first, likewise. */
    a = sampler_new(0.05, 16);
    ck_assert_int_eq(pds_set_mask(a, 2, 2, corner), 0);
    assert_failed(a, pds_set_periodic(a, 1), PDS_EINVAL, "pds_set_periodic with a mask");
    assert_rel_close(pds_free_area(a), 0.5, 1e-15, "the mask kept");
    run_to_end(a);
    ck_assert_int_eq(pds_verify(a), PDS_DONE);
    pds_destroy(a);
}
END_TEST

START_TEST(estate_once_points_exist)
{
    static const unsigned char corner[4] = {1, 0, 0, 1};
    pds_sampler *a = in_unit_l(0.05, 17), *b = in_unit_l(0.05, 17);
    sampler_snapshot snap;

    ck_assert_int_eq(pds_step(a), PDS_MORE);
    ck_assert_int_eq(pds_step(b), PDS_MORE);
    snapshot_take(a, &snap);
    assert_failed(a, pds_set_polygon(a, UNIT_L.xy, UNIT_L.ends, 2), PDS_ESTATE,
                  "pds_set_polygon after a point");
    assert_failed(a, pds_set_polygon(a, NULL, NULL, 0), PDS_ESTATE,
                  "pds_set_polygon(s, NULL, NULL, 0) after a point");
    assert_failed(a, pds_set_mask(a, 2, 2, corner), PDS_ESTATE, "pds_set_mask after a point");
    snapshot_check(a, &snap, "pds_set_polygon and pds_set_mask after a point");
    snapshot_free(&snap);
    assert_same_future(a, b, "pds_set_polygon and pds_set_mask after a point");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

Suite *domain_args_suite(void)
{
    Suite *s = suite_create("domain_args");
    TCase *tc = new_tcase(s, "refused");
    tcase_add_loop_test(tc, polygon_refused, 0, (int)N_BAD_POLYGONS);
    tcase_add_test(tc, polygon_crossing_itself_too_often_refused);
    tcase_add_test(tc, polygon_null_arguments);
    tcase_add_test(tc, mask_refused);
    tcase_add_test(tc, periodic_refused_either_way);
    tc = new_tcase(s, "states");
    tcase_add_test(tc, polygon_nrings_0_goes_back);
    tcase_add_test(tc, mask_empty_goes_back);
    tcase_add_test(tc, estate_once_points_exist);
    return s;
}
