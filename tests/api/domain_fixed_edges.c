/*
 * domain_fixed_edges.c - fixed points at the edges of their contract:
 * clearances that leave no room (a run ends maximal with no point, and the
 * read-only calls say so), and a constant field (the plain sampler's points).
 *
 * Contract (poissondisk.h, pds_set_fixed, pds_verify, pds_free_area): fixed
 * points count for coverage, and pds_free_area counts the clearances once a
 * run has started. So a domain the clearances cover is maximal with no
 * point: pds_run and pds_step return PDS_DONE, pds_verify PDS_DONE, and
 * pds_free_area 0. A refine before the first point is a fresh start at the
 * new radius, where clearances of 0 (the radius) shrink and leave room.
 * Room too thin for any draw (at a corner of the domain, on a side, between
 * disks) gets a point: a representable one near its cell's piece ends.
 * A fixed point within rounding of the domain's bounding box counts as on it;
 * fixed points within 2^-40 R of each other count as one, the larger disk.
 * With a constant field the points are the plain sampler's at that radius,
 * byte for byte (pds_set_radius_map), fixed points or not.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

/* The unit square's corners with clearance 0: at R 1 their disks hold the
 * square (no point is farther than sqrt(1/2) from its nearest corner). */
static const double corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};

static void assert_maximal_without_points(pds_sampler *s)
{
    size_t added = 7;
    ck_assert_int_eq(pds_run(s, 0, &added), 0);
    ck_assert_uint_eq(added, 0);
    ck_assert_uint_eq(pds_count(s), 0);
    ck_assert_int_eq(pds_step(s), 0);
    ck_assert_int_eq(pds_verify(s), 0);
    ck_assert_double_eq(pds_free_area(s), 0.0);
}

START_TEST(corners_cover_the_square)
{
    pds_sampler *s = sampler_new(1.0, 3);
    ck_assert_int_eq(pds_set_fixed(s, corners, NULL, 4), 0);
    ck_assert_double_eq_tol(pds_free_area(s), 1.0, 1e-12); /* no run has started */
    assert_maximal_without_points(s);
    pds_destroy(s);
}
END_TEST

START_TEST(one_clearance_covers_a_polygon_and_a_mask)
{
    /* A triangle and a 3 x 2 mask, each inside one fixed point's disk. */
    static const double tri[6] = {0, 0, 4, 0, 0, 3};
    static const size_t ends[1] = {3};
    static const unsigned char pix[6] = {1, 0, 1, 1, 1, 0};
    const double centre[2] = {1, 1}, big[1] = {3.5};
    pds_sampler *s = sampler_new(0.2, 5);

    ck_assert_int_eq(pds_set_polygon(s, tri, ends, 1), 0);
    ck_assert_int_eq(pds_set_fixed(s, centre, big, 1), 0);
    assert_maximal_without_points(s);
    pds_destroy(s);

    s = sampler_new(0.2, 5);
    ck_assert_int_eq(pds_set_domain(s, 0, 0, 3, 2), 0);
    ck_assert_int_eq(pds_set_mask(s, 3, 2, pix), 0);
    ck_assert_int_eq(pds_set_fixed(s, centre, big, 1), 0);
    assert_maximal_without_points(s);
    pds_destroy(s);
}
END_TEST

/* At R 1e-5 an unbounded run is refused before the first point (the bound
 * is past the index space), a bounded one finds the square covered; after
 * that every run says maximal (before, an unbounded one said PDS_ERANGE). */
START_TEST(covered_at_a_radius_past_the_index_space)
{
    const double centre[2] = {0.5, 0.5}, c[1] = {1.0};
    pds_sampler *s = sampler_new(1e-5, 3);
    size_t added = 7;

    ck_assert_int_eq(pds_set_fixed(s, centre, c, 1), 0);
    ck_assert_int_eq(pds_run(s, 0, &added), PDS_ERANGE);
    ck_assert_int_eq(pds_run(s, 10, &added), 0);
    ck_assert_uint_eq(added, 0);
    ck_assert_int_eq(pds_run(s, 0, &added), 0);
    ck_assert_int_eq(pds_step(s), 0);
    ck_assert_int_eq(pds_verify(s), 0);
    pds_destroy(s);
}
END_TEST

START_TEST(a_refine_before_the_first_point_leaves_room)
{
    pds_sampler *s = sampler_new(1.0, 3);
    double xy[2 * 64];
    size_t n, i, k;

    ck_assert_int_eq(pds_set_fixed(s, corners, NULL, 4), 0);
    assert_maximal_without_points(s);
    ck_assert_int_eq(pds_refine(s, 0.3), 0);
    ck_assert_double_eq_tol(pds_free_area(s), 1.0, 1e-12); /* a fresh start */
    n = run_to_end(s);
    ck_assert_uint_gt(n, 0);
    ck_assert_uint_le(n, 64);
    ck_assert_uint_eq(pds_points(s, 0, n, xy), n);
    for (i = 0; i < n; i++)
        for (k = 0; k < 4; k++)
            ck_assert_double_ge(hypot(xy[2 * i] - corners[2 * k], xy[2 * i + 1] - corners[2 * k + 1]), 0.3);
    ck_assert_int_eq(pds_verify(s), 0);
    ck_assert_double_eq(pds_free_area(s), 0.0);
    pds_destroy(s);
}
END_TEST

/* One fixed point on a corner of a 1 x h box, its clearance short of the
 * opposite corner by a hair (the rounded distance, or less by 1e-15 up to
 * 4e-10 of it): that corner is the only room left, and too thin for any
 * draw. Maximal means a point there, and one exactly there is what can be
 * represented. In the rectangle, a polygon and a mask alike. */
START_TEST(a_clearance_short_of_a_corner_leaves_a_point_there)
{
    static const double shortfall[4] = {0.0, 1e-15, 1e-12, 4e-10};
    const double h = 0.83333333333333337, at[2] = {0.0, 0.0};
    const double square[8] = {0, 0, 1, 0, 1, h, 0, h};
    const size_t ends[1] = {4};
    const unsigned char pix[6] = {1, 1, 1, 1, 1, 1};
    size_t k, kind;

    for (kind = 0; kind < 3; kind++) {
        for (k = 0; k < 4; k++) {
            const double c = hypot(1.0, h) * (1.0 - shortfall[k]);
            pds_sampler *s = sampler_new(0.03, 1 + k);
            double xy[2];
            size_t added = 0;
            if (kind == 0) ck_assert_int_eq(pds_set_domain(s, 0, 0, 1, h), 0);
            if (kind == 1) ck_assert_int_eq(pds_set_polygon(s, square, ends, 1), 0);
            if (kind == 2) {
                ck_assert_int_eq(pds_set_domain(s, 0, 0, 1, h), 0);
                ck_assert_int_eq(pds_set_mask(s, 3, 2, pix), 0);
            }
            ck_assert_int_eq(pds_set_fixed(s, at, &c, 1), 0);
            ck_assert_int_eq(pds_run(s, 0, &added), 0);
            ck_assert_uint_eq(added, 1);
            ck_assert_uint_eq(pds_points(s, 0, 1, xy), 1);
            ck_assert_double_eq(xy[0], 1.0);
            ck_assert_double_eq(xy[1], h);
            ck_assert_int_eq(pds_verify(s), 0);
            pds_destroy(s);
        }
    }
}
END_TEST

/* Clearances that each reach a point T but for a hair (1e-16 to 1e-10 of
 * them): T's neighbourhood is room too thin for any draw, inside the square
 * or on its side, in the square as a rectangle and as a polygon. Every run
 * must end maximal and verified (before, some ended "maximal" with T free:
 * pds_verify PDS_EINTERNAL). */
START_TEST(room_a_hair_wide_between_clearances_gets_its_point)
{
    uint64_t state = 0x9e3779b97f4a7c15u;
    int trial, side;

    static const double square[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const size_t ends[1] = {4};

    for (side = 0; side < 4; side++) { /* 2, 3: the square as a polygon */
        for (trial = 0; trial < 200; trial++) {
            double t[2], xy[12], c[6];
            int k, nf;
            pds_sampler *s;
#define NEXT_U() ((double)((state = state * 6364136223846793005u + 1442695040888963407u) >> 11) * 0x1p-53)
            t[0] = NEXT_U();
            t[1] = side % 2 ? 0.0 : NEXT_U();
            nf = 3 + (int)(NEXT_U() * 3.0);
            for (k = 0; k < nf; k++) {
                const double a = 6.283185307179586 * (k + 0.3 * NEXT_U()) / nf, d = 0.2 + 0.6 * NEXT_U();
                double x = t[0] + d * cos(a), y = t[1] + d * sin(a);
                x = x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
                y = y < 0.0 ? 0.0 : y > 1.0 ? 1.0 : y;
                xy[2 * k] = x;
                xy[2 * k + 1] = y;
                c[k] = hypot(x - t[0], y - t[1]) * (1.0 - pow(10.0, -16.0 + 6.0 * NEXT_U()));
            }
#undef NEXT_U
            s = sampler_new(0.05, (uint64_t)trial);
            if (side >= 2) ck_assert_int_eq(pds_set_polygon(s, square, ends, 1), 0);
            ck_assert_int_eq(pds_set_fixed(s, xy, c, (size_t)nf), 0);
            ck_assert_int_eq(pds_run(s, 0, NULL), 0);
            ck_assert_msg(pds_verify(s) == 0, "side %d trial %d: %s", side, trial, pds_errmsg(s));
            pds_destroy(s);
        }
    }
}
END_TEST

/* Three fixed points on the bottom side, 0.3 and 5e-8 apart, in a domain
 * 1e20 wide at R 5e18: closer than 2^-40 R, they count as one disk (before:
 * PDS_EINTERNAL, "degenerate Delaunay triangle", the triangles around them
 * too thin for the floating-point centres). */
START_TEST(nearly_coincident_fixed_points_count_once)
{
    const double xy[6] = {0.4392156862745098, 0.0, 0.12549019607843137, 0.0, 0.12549024607843137, 0.0};
    const double c[3] = {0.14375, 4.2426406871192857, 1.4142135623730951};
    pds_sampler *s = sampler_new(5e18, 1);

    ck_assert_int_eq(pds_set_domain(s, -1e20, 0.0, 1e20, 1e20), 0);
    ck_assert_int_eq(pds_set_fixed(s, xy, c, 3), 0);
    ck_assert_msg(pds_run(s, 0, NULL) == 0, "%s", pds_errmsg(s));
    ck_assert_int_eq(pds_verify(s), 0);
    pds_destroy(s);
}
END_TEST

/* A few points and fixed points in a domain 10^7 R wide: their cells are
 * huge, and summed cell by cell their free areas could pass the domain's
 * area by rounding (by up to 1e-7 of it); the free area cannot. */
START_TEST(free_area_never_exceeds_the_domain)
{
    double xy[2 * 25];
    unsigned seed;
    int k;

    for (k = 0; k < 25; k++) { /* a 5 x 5 grid over the unit square, R/2 apart */
        xy[2 * k] = 0.05 * (k % 5);
        xy[2 * k + 1] = 0.05 * (k / 5);
    }
    for (seed = 53; seed < 93; seed++) {
        pds_sampler *s = sampler_new(0.1, seed);
        ck_assert_int_eq(pds_set_fixed(s, xy, NULL, 25), 0);
        ck_assert_int_eq(pds_set_domain(s, 0.0, -0.5, 2e6, 999999.5), 0);
        ck_assert_int_eq(pds_run(s, 75, NULL), PDS_MORE);
        ck_assert_msg(pds_free_area(s) <= 2e12, "seed %u: %.17g", seed, pds_free_area(s));
        pds_destroy(s);
    }
}
END_TEST

/* Fixed points on the corners of a mask's inside pixels, computed the
 * user's way (X1 * i / w): within rounding of the library's box, they count
 * as on it (before, 15 of these 38 masks refused one with PDS_EINVAL). A
 * thousandth of a pixel farther out is refused. */
START_TEST(fixed_points_on_a_masks_pixel_lines_are_inside)
{
    unsigned char pix[40 * 6];
    int w;

    for (w = 3; w <= 40; w++) {
        const double X1 = 0.00123456789 * (1 + w % 7), Y1 = 0.0031415926 * (1 + w % 5);
        const int h = 2 + w % 5, i = w / 3, j = h / 2;
        const double xy[8] = {X1 * i / w,       Y1 * j / h,       X1 * (i + 2) / w, Y1 * j / h,
                              X1 * (i + 2) / w, Y1 * (j + 1) / h, X1 * i / w,       Y1 * (j + 1) / h};
        const double out[2] = {X1 * (i + 2) / w + X1 / w / 1000, Y1 * j / h};
        pds_sampler *s = sampler_new(X1 / w / 10, 1);

        memset(pix, 0, sizeof pix);
        pix[j * w + i] = pix[j * w + i + 1] = 1;
        ck_assert_int_eq(pds_set_domain(s, 0, 0, X1, Y1), 0);
        ck_assert_int_eq(pds_set_mask(s, (size_t)w, (size_t)h, pix), 0);
        ck_assert_int_eq(pds_set_fixed(s, out, NULL, 1), 0);
        ck_assert_int_eq(pds_step(s), PDS_EINVAL);
        ck_assert_int_eq(pds_set_fixed(s, xy, NULL, 4), 0);
        ck_assert_msg(pds_run(s, 0, NULL) == 0, "w %d: %s", w, pds_errmsg(s));
        ck_assert_int_eq(pds_verify(s), 0);
        pds_destroy(s);
    }
}
END_TEST

/* A uniform map of 0.02, refined before the first point or not: the bytes
 * of a plain sampler created at 0.02 and refined alike. (Interpolated, the
 * map's value at a fixed point may be off by an ulp: the radius is the one
 * to take.) */
START_TEST(a_constant_field_gives_the_plain_points)
{
    static const double xy[10] = {0.69, 0.0039, 0.1098, 0.3098, 0.3569, 0.4549, 0.1059, 0.6, 0.2431, 0.1765};
    static const double c[5] = {0.7125, 0.0, 0.1414, 0.15, 0.1414};
    double map[4 * 7];
    static double a[2 * 20000], b[2 * 20000], ra[20000], rb[20000];
    size_t n, m, k;

    /* Refines by these factors round differently through the field's scale
     * (rmax to the radius in force) than the plain radius does. */
    static const double factor[5] = {1.0, 0.999, 0.7, 0.53, 0.37};
    for (k = 0; k < 4 * 7; k++) map[k] = 0.02;
    for (k = 0; k < 5; k++) {
        pds_sampler *field = sampler_new(0.3, 116), *plain = sampler_new(0.02, 116);
        ck_assert_int_eq(pds_set_radius_map(field, 4, 7, map), 0);
        ck_assert_int_eq(pds_set_fixed(field, xy, c, 5), 0);
        ck_assert_int_eq(pds_set_fixed(plain, xy, c, 5), 0);
        if (k > 0) { /* before the first point */
            ck_assert_int_eq(pds_refine(field, 0.02 * factor[k]), 0);
            ck_assert_int_eq(pds_refine(plain, 0.02 * factor[k]), 0);
        }
        n = run_to_end(field);
        m = run_to_end(plain);
        ck_assert_uint_eq(n, m);
        ck_assert_uint_le(n, 20000);
        ck_assert_uint_eq(pds_points(field, 0, n, a), n);
        ck_assert_uint_eq(pds_points(plain, 0, n, b), n);
        ck_assert_mem_eq(a, b, 2 * n * sizeof *a);
        ck_assert_uint_eq(pds_radii(field, 0, n, ra), n);
        ck_assert_uint_eq(pds_radii(plain, 0, n, rb), n);
        ck_assert_mem_eq(ra, rb, n * sizeof *ra);
        pds_destroy(field);
        pds_destroy(plain);
    }
}
END_TEST

Suite *domain_fixed_edges_suite(void)
{
    Suite *s = suite_create("domain_fixed_edges");
    TCase *tc = new_tcase(s, "no room left");
    tcase_add_test(tc, corners_cover_the_square);
    tcase_add_test(tc, one_clearance_covers_a_polygon_and_a_mask);
    tcase_add_test(tc, a_refine_before_the_first_point_leaves_room);
    tcase_add_test(tc, covered_at_a_radius_past_the_index_space);
    tcase_add_test(tc, a_clearance_short_of_a_corner_leaves_a_point_there);
    tcase_add_test(tc, room_a_hair_wide_between_clearances_gets_its_point);
    tc = new_tcase(s, "the bounding box");
    tcase_add_test(tc, fixed_points_on_a_masks_pixel_lines_are_inside);
    tcase_add_test(tc, free_area_never_exceeds_the_domain);
    tc = new_tcase(s, "nearly one point");
    tcase_add_test(tc, nearly_coincident_fixed_points_count_once);
    tc = new_tcase(s, "a constant field");
    tcase_add_test(tc, a_constant_field_gives_the_plain_points);
    return s;
}
