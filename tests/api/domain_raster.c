/*
 * domain_raster.c - rasters over a domain: an image mask as the domain, and a
 * radius map spread over a polygon's bounding box.
 *
 * Contract (poissondisk.h, 1.4): a mask's domain is the union of its inside
 * pixels' closed squares over the rectangle of pds_set_domain (set before or
 * after), row 0 along y0 and column 0 along x0, taken exactly; a radius map
 * with a polygon is spread over the polygon's bounding box (pds_set_radius_map:
 * bilinear between pixel centres, constant beyond them). Checked: each point
 * in an inside pixel by looking the pixel up, maximality on the L polygon the
 * pixels make (region_covered), each radius against the map where the map is
 * constant, the rule and coverage with each point's radius; bounded calls
 * on a mask at a radius whose maximal pattern would not fit the index.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "domain_check.h"
#include "helpers.h"
#include "region.h"
#include "suites.h"

/* A 4 x 4 raster, row 0 first: the two bottom rows full, the two top rows
 * only in their left half. Over [1,3] x [-1,1] (pixels of 0.5) that is the
 * L below, with its foot along y = -1; read upside down, the foot would be
 * at the top and points would fall outside it. */
static const unsigned char l_mask[16] = {
    1, 1, 1, 1,
    1, 1, 1, 1,
    1, 1, 0, 0,
    1, 1, 0, 0,
};
static const test_domain mask_box = {1.0, -1.0, 3.0, 1.0};
static const double l_mask_xy[] = {1, -1, 3, -1, 3, 0, 2, 0, 2, 1, 1, 1};
static const size_t l_mask_ends[] = {6};
static const region l_mask_polygon = {l_mask_xy, l_mask_ends, 1};

/* (x, y) lies in the closed square of some inside pixel. */
static int in_inside_pixel(double x, double y)
{
    const double side = 0.5, slack = 1e-12;
    int i, j;

    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++) {
            double px = mask_box.x0 + side * i, py = mask_box.y0 + side * j;
            if (l_mask[4 * j + i] && x >= px - slack && x <= px + side + slack &&
                y >= py - slack && y <= py + side + slack)
                return 1;
        }
    return 0;
}

static pds_sampler *masked(double r, uint64_t seed, int domain_first)
{
    pds_sampler *s = sampler_new(r, seed);

    if (domain_first)
        ck_assert_int_eq(pds_set_domain(s, mask_box.x0, mask_box.y0, mask_box.x1, mask_box.y1),
                         0);
    ck_assert_int_eq(pds_set_mask(s, 4, 4, l_mask), 0);
    if (!domain_first)
        ck_assert_int_eq(pds_set_domain(s, mask_box.x0, mask_box.y0, mask_box.x1, mask_box.y1),
                         0);
    return s;
}

START_TEST(mask_points_in_inside_pixels)
{
    uint64_t seed;

    for (seed = 1; seed <= pick(4, 1); seed++) {
        pds_sampler *s = masked(0.05, seed, 1);
        double *xy;
        size_t n, i;
        char what[64];
        snprintf(what, sizeof what, "the L mask, seed %llu", (unsigned long long)seed);
        assert_rel_close(pds_free_area(s), 3.0, 1e-12, "the mask's area: 12 pixels of 0.25");
        run_to_end(s);
        xy = points_copy(s, &n);
        for (i = 0; i < n; i++)
            ck_assert_msg(in_inside_pixel(xy[2 * i], xy[2 * i + 1]),
                          "%s: point %zu (%.17g, %.17g) is in no inside pixel", what, i,
                          xy[2 * i], xy[2 * i + 1]);
        assert_domain_pattern(s, &l_mask_polygon, NULL, 0, what);
        free(xy);
        pds_destroy(s);
    }
}
END_TEST

/* At R 2e-5 over [1,3] x [-1,1] a maximal pattern (~10^10 points) would not
 * fit the index: bounded calls throw darts on a grid that keeps only its
 * taken cells, and only over the mask's pixels. The first points come
 * without a pass over the grid's 10^10 cells (that pass took minutes). */
START_TEST(mask_with_a_tiny_radius_steps)
{
    pds_sampler *s = masked(2e-5, 4, 1);
    double *xy;
    size_t n, i, added = 0;

    ck_assert_int_eq(pds_step(s), PDS_MORE);
    ck_assert_int_eq(pds_run(s, 999, &added), PDS_MORE);
    ck_assert_uint_eq(added, 999);
    xy = points_copy(s, &n);
    ck_assert_uint_eq(n, 1000);
    for (i = 0; i < n; i++)
        ck_assert_msg(in_inside_pixel(xy[2 * i], xy[2 * i + 1]), "point %zu (%.17g, %.17g) is in no inside pixel",
                      i, xy[2 * i], xy[2 * i + 1]);
    free(xy);
    pds_destroy(s);
}
END_TEST

/* The mask over its rectangle times 2^e, at R 0.05 * 2^e: the points of the
 * unit case times 2^e, to the bit, also where the outline's coordinates
 * would overflow or underflow the predicates' products (beyond 2^+-500). */
START_TEST(mask_at_any_power_of_two)
{
    static const int exps[] = {1000, -890, 600, 3};
    pds_sampler *base = masked(0.05, 3, 1);
    const size_t n = run_to_end(base);
    size_t k, i, m;
    double *p0 = points_copy(base, &m), *p;

    for (k = 0; k < sizeof exps / sizeof exps[0]; k++) {
        const int e = exps[k];
        pds_sampler *s = sampler_new(ldexp(0.05, e), 3);
        ck_assert_int_eq(pds_set_domain(s, ldexp(mask_box.x0, e), ldexp(mask_box.y0, e), ldexp(mask_box.x1, e),
                                        ldexp(mask_box.y1, e)),
                         0);
        ck_assert_msg(pds_set_mask(s, 4, 4, l_mask) == 0, "2^%d: %s", e, pds_errmsg(s));
        ck_assert_msg(run_to_end(s) == n, "2^%d: %zu points, at unit scale %zu", e, pds_count(s), n);
        p = points_copy(s, &m);
        for (i = 0; i < 2 * n; i++)
            ck_assert_msg(p[i] == ldexp(p0[i], e), "2^%d: coordinate %zu is %.17g, not %.17g", e, i, p[i],
                          ldexp(p0[i], e));
        ck_assert_int_eq(pds_verify(s), PDS_DONE);
        free(p);
        pds_destroy(s);
    }
    free(p0);
    pds_destroy(base);
}
END_TEST

/* A mask or polygon reaching -2^1023 on one side and 0.25 on another is
 * taken (read at 2^1020, which keeps 0.25 a normal number; it was refused
 * as "on one line"), and its first point is refused as the rectangle's is:
 * 0.25 lies below 2^-900 times the largest coordinate (PDS_ERANGE). */
START_TEST(mask_from_a_quarter_to_the_largest_double)
{
    static const unsigned char full[20] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    static const double box[4] = {0.25, -0x1p1023, 6.1745829209798319e304, -8.9761165084696184e307};
    const double xy[6] = {box[0], box[1], box[2], box[1], box[0], box[3]};
    const size_t ends[1] = {3};
    pds_sampler *rect = sampler_new(6.1745829209798322e303, 1), *mask = sampler_new(6.1745829209798322e303, 1),
                *poly = sampler_new(6.1745829209798322e303, 1);

    ck_assert_int_eq(pds_set_domain(rect, box[0], box[1], box[2], box[3]), 0);
    ck_assert_int_eq(pds_set_domain(mask, box[0], box[1], box[2], box[3]), 0);
    ck_assert_msg(pds_set_mask(mask, 5, 4, full) == 0, "%s", pds_errmsg(mask));
    ck_assert_msg(pds_set_polygon(poly, xy, ends, 1) == 0, "%s", pds_errmsg(poly));
    ck_assert_int_eq(pds_run(rect, 0, NULL), PDS_ERANGE);
    ck_assert_int_eq(pds_run(mask, 0, NULL), PDS_ERANGE);
    ck_assert_int_eq(pds_run(poly, 0, NULL), PDS_ERANGE);
    ck_assert_uint_eq(pds_count(mask) + pds_count(poly), 0);
    pds_destroy(rect);
    pds_destroy(mask);
    pds_destroy(poly);
}
END_TEST

/* Coordinates from 1.8e-307 to 3e296, which no power of two reads exactly
 * (the smallest lies below 2^-1522 of the largest): the mask is refused with
 * a message that says so (it said "on one line"); the rectangle alone is
 * refused at its first point. */
START_TEST(mask_from_near_the_least_normal_to_3e296)
{
    static const unsigned char ring[16] = {1, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 1, 1, 1};
    static const double box[4] = {1.1864819587706575e-296, 1.7800591067267698e-307, 3.0133197055701197e296,
                                  3.0135153699541016e296};
    pds_sampler *rect = sampler_new(1e295, 1), *mask = sampler_new(1e295, 1);

    ck_assert_int_eq(pds_set_domain(rect, box[0], box[1], box[2], box[3]), 0);
    ck_assert_int_eq(pds_set_domain(mask, box[0], box[1], box[2], box[3]), 0);
    ck_assert_int_eq(pds_set_mask(mask, 4, 4, ring), PDS_EINVAL);
    ck_assert_msg(strstr(pds_errmsg(mask), "no one scale reads exactly") != NULL, "%s", pds_errmsg(mask));
    ck_assert_int_eq(pds_run(rect, 0, NULL), PDS_ERANGE);
    pds_destroy(rect);
    pds_destroy(mask);
}
END_TEST

/* An edge whose ends are 0 and a subnormal number (1e-310 beside 1): its
 * side is probed at offsets growing from 2^-48 of its coordinates, which
 * rounds to 0 there, and the probing never ended. Now pds_set_polygon
 * returns, and the first point is refused as the rectangle's is (a nonzero
 * coordinate below 2^-900 times the largest: PDS_ERANGE). */
START_TEST(polygon_with_an_edge_of_subnormal_length)
{
    const double xy[] = {0.0, 0.0, 0.0, 1e-310, 1.0, 1.0, 1.0, 0.0};
    const size_t ends[1] = {4};
    pds_sampler *s = sampler_new(0.1, 1);

    ck_assert_msg(pds_set_polygon(s, xy, ends, 1) == 0, "%s", pds_errmsg(s));
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_ERANGE);
    ck_assert_uint_eq(pds_count(s), 0);
    pds_destroy(s);
}
END_TEST

/* Pixels 2^-38 of their coordinates wide and a million times taller (a
 * mask over a thin strip at 1e15, R some 8000 pixels wide): every outline
 * edge keeps its side, and the run ends maximal. The sides used to be
 * probed at 2^-20 of an edge's length, which jumped over the columns beside
 * a tall edge and fell on a short one: a whole ring was dropped, and the
 * run stopped with half its points. */
START_TEST(mask_of_pixels_far_taller_than_wide)
{
    static const unsigned char pix[64] = {
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 3, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 3, 3, 3, 3, 3, 3, 0,
        0, 3, 0, 0, 0, 0, 3, 0, 0, 3, 0, 3, 3, 0, 3, 0, 0, 3, 0, 3, 3, 0, 3, 0, 0, 3, 0, 0, 0, 0, 3, 0,
    };
    uint64_t seed;

    for (seed = 1; seed <= 3; seed++) {
        pds_sampler *s = sampler_new(29802322.387695309, seed);
        int rc;

        ck_assert_int_eq(pds_set_domain(s, 1e15, 1e15, 1000000000029802.4, 1000029802322387.8), 0);
        ck_assert_msg(pds_set_mask(s, 8, 8, pix) == 0, "%s", pds_errmsg(s));
        ck_assert_int_eq(pds_run(s, 0, NULL), 0);
        rc = pds_verify(s);
        ck_assert_msg(rc == 0, "seed %d, %zu points: %s", (int)seed, pds_count(s), pds_errmsg(s));
        pds_destroy(s);
    }
}
END_TEST

/* A 4 x 4 square polygon at 1e15 (sides of 32 ulps) and a ring mask over
 * [1e15, 1e15 + 1] x [1e15, 1e15 + 1000]: taken as their rectangles are
 * (they were refused as "enclosing nothing": the probes that tell an edge's
 * side fell within rounding of it), then judged at the first point as the
 * rectangle is: PDS_ERANGE below 2^-26 of the coordinates, one point at a
 * radius above it. */
START_TEST(shapes_of_a_few_ulps_judged_as_their_rectangles)
{
    static const double xy[8] = {1e15, 1e15, 1e15 + 4, 1e15, 1e15 + 4, 1e15 + 4, 1e15, 1e15 + 4};
    static const size_t ends[1] = {4};
    static const unsigned char ring[16] = {1, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 1, 1, 1};
    static const double radii[2] = {3.0, 1e8};
    int k;

    for (k = 0; k < 2; k++) {
        pds_sampler *poly = sampler_new(radii[k], 1), *mask = sampler_new(radii[k], 1);
        const int want = k == 0 ? PDS_ERANGE : 0;

        ck_assert_msg(pds_set_polygon(poly, xy, ends, 1) == 0, "%s", pds_errmsg(poly));
        ck_assert_int_eq(pds_set_domain(mask, 1e15, 1e15, 1e15 + 1, 1e15 + 1000), 0);
        ck_assert_msg(pds_set_mask(mask, 4, 4, ring) == 0, "%s", pds_errmsg(mask));
        ck_assert_int_eq(pds_run(poly, 0, NULL), want);
        ck_assert_int_eq(pds_run(mask, 0, NULL), want);
        ck_assert_uint_eq(pds_count(poly), (size_t)k);
        ck_assert_uint_eq(pds_count(mask), (size_t)k);
        if (k == 1) {
            ck_assert_msg(pds_verify(poly) == 0, "%s", pds_errmsg(poly));
            ck_assert_msg(pds_verify(mask) == 0, "%s", pds_errmsg(mask));
        }
        pds_destroy(poly);
        pds_destroy(mask);
    }
}
END_TEST

START_TEST(mask_domain_before_or_after)
{
    pds_sampler *a = masked(0.05, 9, 1), *b = masked(0.05, 9, 0);

    assert_same_future(a, b, "pds_set_domain before or after pds_set_mask");
    pds_destroy(a);
    pds_destroy(b);
}
END_TEST

/* The unit L moved to [2,3] x [5,6]: a map spread over that box, not over
 * the unit square pds_create set. */
static const double far_l_xy[] = {
    2.0, 5.0, 3.0, 5.0, 3.0, 5.4, 2.4, 5.4, 2.4, 6.0, 2.0, 6.0,
    2.1, 5.1, 2.1, 5.25, 2.25, 5.25, 2.25, 5.1,
};
static const size_t far_l_ends[] = {6, 10};
static const region far_l = {far_l_xy, far_l_ends, 2};

START_TEST(radius_map_over_the_polygon_box)
{
    /* 2 x 1: pixel centres at x = 2.25 and 2.75; left of the first the
     * field is 0.02, right of the second 0.04, bilinear between. */
    const double map[2] = {0.02, 0.04};
    uint64_t seed;

    for (seed = 1; seed <= pick(3, 1); seed++) {
        pds_sampler *s = sampler_new(1.0, seed);
        double *xy, *r;
        size_t n, i, left = 0, right = 0;
        char what[64];
        snprintf(what, sizeof what, "a radius map over the far L, seed %llu",
                 (unsigned long long)seed);
        ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
        ck_assert_int_eq(pds_set_polygon(s, far_l.xy, far_l.ends, far_l.nrings), 0);
        run_to_end(s);
        ck_assert_msg(pds_radius(s) == 0.04, "%s: pds_radius %.17g", what, pds_radius(s));
        domain_pattern(s, &xy, &r, &n);
        for (i = 0; i < n; i++) {
            const double x = xy[2 * i];
            const double want = x <= 2.25 ? 0.02 : x >= 2.75 ? 0.04 : 0.02 + 0.04 * (x - 2.25);
            ck_assert_msg(fabs(r[i] - want) <= 1e-12 * want,
                          "%s: point %zu at x %.17g has radius %.17g, the map gives %.17g",
                          what, i, x, r[i], want);
            left += x <= 2.25;
            right += x >= 2.75;
        }
        ck_assert_msg(left > 0 && right > 0, "%s: %zu points left, %zu right", what, left,
                      right);
        assert_domain_pattern(s, &far_l, NULL, 0, what);
        free(xy);
        free(r);
        pds_destroy(s);
    }
}
END_TEST

/* A ring 0.02 wide of radius 1 (64-gons) fills 1/25 of its box; under a map
 * from 0.004 to 0.008 its darts come from the finest layer's raster. */
START_TEST(radius_map_over_a_thin_ring)
{
    const double map[2] = {0.004, 0.008};
    double xy[256];
    const size_t ends[2] = {64, 128};
    const region ring = {xy, ends, 2};
    double *pts, *r;
    size_t n, k;
    pds_sampler *s = sampler_new(1.0, 3);

    for (k = 0; k < 64; k++) {
        const double t = 2.0 * acos(-1.0) * (double)k / 64.0;
        xy[2 * k] = cos(t), xy[2 * k + 1] = sin(t);
        xy[128 + 2 * k] = 0.98 * cos(t), xy[128 + 2 * k + 1] = 0.98 * sin(t);
    }
    ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
    ck_assert_int_eq(pds_set_polygon(s, ring.xy, ring.ends, ring.nrings), 0);
    run_to_end(s);
    domain_pattern(s, &pts, &r, &n);
    ck_assert_msg(n > 2000 && n < 8000, "a radius map over a thin ring: %zu points", n);
    assert_domain_pattern(s, &ring, NULL, 0, "a radius map over a thin ring");
    free(pts);
    free(r);
    pds_destroy(s);
}
END_TEST

Suite *domain_raster_suite(void)
{
    Suite *s = suite_create("domain_raster");
    TCase *tc = new_tcase(s, "mask");
    tcase_add_test(tc, mask_points_in_inside_pixels);
    tcase_add_test(tc, mask_domain_before_or_after);
    tcase_add_test(tc, mask_with_a_tiny_radius_steps);
    tcase_add_test(tc, mask_at_any_power_of_two);
    tcase_add_test(tc, mask_from_a_quarter_to_the_largest_double);
    tcase_add_test(tc, mask_from_near_the_least_normal_to_3e296);
    tcase_add_test(tc, polygon_with_an_edge_of_subnormal_length);
    tcase_add_test(tc, mask_of_pixels_far_taller_than_wide);
    tcase_add_test(tc, shapes_of_a_few_ulps_judged_as_their_rectangles);
    tc = new_tcase(s, "radius map");
    tcase_add_test(tc, radius_map_over_the_polygon_box);
    tcase_add_test(tc, radius_map_over_a_thin_ring);
    return s;
}
