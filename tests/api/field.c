/*
 * field.c - a variable radius (1.3): pds_set_radius_map, pds_set_radius_fn,
 * pds_radii.
 *
 * Contract (poissondisk.h): point i carries r_i = r(p_i), evaluated once when
 * it is placed; a later point keeps out of every earlier closed disk,
 * |p_j - p_i| >= r_i for i < j; the pattern ends maximal (the disks cover
 * the domain). pds_radius is the largest radius in force, pds_refine scales
 * every radius. A constant field gives the plain sampler's points, byte for
 * byte. Checked independently: the rule and maximality by brute force (probes
 * on a grid), the map's interpolation against its definition, determinism
 * over splits, and every bad field refused with the sampler unchanged.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

/* A field's scale r0 and the domain's x range it spans. */
struct span {
    double r0, x0, width;
};

/* r0 (1 + t), t = (x - x0) / width in [0, 1]: 1:2 from left to right. */
static double gradient_over(void *user, double x, double y)
{
    const struct span *f = user;
    (void)y;
    return f->r0 * (1.0 + (x - f->x0) / f->width);
}

/* 1:2.5 across the middle (beyond sqrt 2, where power cells lose their sites). */
static double step_over(void *user, double x, double y)
{
    const struct span *f = user;
    (void)y;
    return (x - f->x0) / f->width < 0.5 ? f->r0 : 2.5 * f->r0;
}

/* The same over the unit square, user = &r0. */
static double gradient(void *user, double x, double y)
{
    (void)y;
    return *(const double *)user * (1.0 + x);
}

static double step_field(void *user, double x, double y)
{
    (void)y;
    return x < 0.5 ? *(const double *)user : 2.5 * *(const double *)user;
}

static double *radii_copy(const pds_sampler *s, size_t n)
{
    double *r = malloc((n ? n : 1) * sizeof *r);
    ck_assert_ptr_nonnull(r);
    ck_assert_uint_eq(pds_radii(s, 0, n, r), n);
    return r;
}

/* Later points outside earlier disks; every probe of a (k+1)^2 grid over d
 * in some closed disk. Brute force. */
static void assert_field_pattern(const double *xy, const double *r, size_t n, test_domain d, int k,
                                 const char *what)
{
    size_t i, j;
    int a, b;
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j) {
            const double dx = xy[2 * i] - xy[2 * j], dy = xy[2 * i + 1] - xy[2 * j + 1];
            ck_assert_msg(dx * dx + dy * dy >= r[i] * r[i] * (1 - 1e-12), "%s: point %zu inside point %zu's disk",
                          what, j, i);
        }
    for (a = 0; a <= k; ++a)
        for (b = 0; b <= k; ++b) {
            const double x = d.x0 + (d.x1 - d.x0) * a / k, y = d.y0 + (d.y1 - d.y0) * b / k;
            int in = 0;
            for (i = 0; i < n && !in; ++i) {
                const double dx = xy[2 * i] - x, dy = xy[2 * i + 1] - y;
                in = dx * dx + dy * dy <= r[i] * r[i] * (1 + 1e-12);
            }
            ck_assert_msg(in, "%s: the probe (%g, %g) is in no disk", what, x, y);
        }
}

START_TEST(function_field_rule_and_maximality)
{
    const test_domain doms[2] = {{0, 0, 1, 1}, {-1, 2, 2, 3.5}};
    int k;
    for (k = 0; k < 4; ++k) {
        const test_domain d = doms[k / 2];
        struct span f = {test_light() ? 0.06 : 0.03, d.x0, d.x1 - d.x0};
        pds_sampler *s = sampler_new_in(1.0, 10 + (uint64_t)k, d);
        size_t n, i;
        double *xy, *r;
        f.r0 *= f.width;
        ck_assert_int_eq(pds_set_radius_fn(s, k % 2 ? step_over : gradient_over, &f, f.r0, 2.5 * f.r0), 0);
        ck_assert_double_eq(pds_radius(s), 2.5 * f.r0);
        run_to_end(s);
        assert_maximal(s, "field");
        xy = points_copy(s, &n);
        r = radii_copy(s, n);
        assert_inside(xy, n, d, "field");
        for (i = 0; i < n; ++i)
            ck_assert_double_eq(r[i], (k % 2 ? step_over : gradient_over)(&f, xy[2 * i], xy[2 * i + 1]));
        assert_field_pattern(xy, r, n, d, (int)pick(300, 100), "field");
        free(xy);
        free(r);
        pds_destroy(s);
    }
}
END_TEST

START_TEST(map_interpolates_between_pixel_centres)
{
    /* A 3 x 2 map over [0,3] x [0,2]: pixel centres at x = 0.5, 1.5, 2.5 and
     * y = 0.5, 1.5, row 0 along y = 0. The radius of each point is the
     * bilinear value there, clamped beyond the outer centres. */
    const double map[6] = {0.05, 0.07, 0.09, 0.06, 0.10, 0.08};
    pds_sampler *s = sampler_new_in(1.0, 3, (test_domain){0, 0, 3, 2});
    size_t n, i;
    double *xy, *r;
    ck_assert_int_eq(pds_set_radius_map(s, 3, 2, map), 0);
    ck_assert_double_eq(pds_radius(s), 0.10);
    run_to_end(s);
    assert_maximal(s, "map");
    xy = points_copy(s, &n);
    r = radii_copy(s, n);
    for (i = 0; i < n; ++i) {
        const double u = fmin(fmax(xy[2 * i] - 0.5, 0.0), 2.0), v = fmin(fmax(xy[2 * i + 1] - 0.5, 0.0), 1.0);
        const int c = u >= 1.0 ? 1 : 0;
        const double fu = u - c;
        const double bottom = map[c] * (1 - fu) + map[c + 1] * fu, top = map[3 + c] * (1 - fu) + map[3 + c + 1] * fu;
        const double want = bottom * (1 - v) + top * v;
        ck_assert_msg(fabs(r[i] - want) <= 1e-14, "point %zu at (%g, %g): radius %.17g, want %.17g", i, xy[2 * i],
                      xy[2 * i + 1], r[i], want);
    }
    assert_field_pattern(xy, r, n, (test_domain){0, 0, 3, 2}, (int)pick(300, 120), "map");
    free(xy);
    free(r);
    pds_destroy(s);
}
END_TEST

START_TEST(constant_field_gives_the_plain_points)
{
    /* A 1 x 1 map, a uniform map and a function with rmin == rmax: the plain
     * sampler's points at that radius, byte for byte, refine included. */
    const double r = 0.021;
    double uniform[12];
    int k, i;
    for (i = 0; i < 12; ++i) uniform[i] = r;
    for (k = 0; k < 3; ++k) {
        pds_sampler *plain = sampler_new(r, 77), *field = sampler_new(1.0, 77);
        double rr = r;
        size_t n, j;
        double *radii;
        if (k == 0) ck_assert_int_eq(pds_set_radius_map(field, 1, 1, &r), 0);
        if (k == 1) ck_assert_int_eq(pds_set_radius_map(field, 4, 3, uniform), 0);
        if (k == 2) ck_assert_int_eq(pds_set_radius_fn(field, gradient, &rr, r, r), 0);
        ck_assert_double_eq(pds_radius(field), r);
        ck_assert_int_eq(pds_run(plain, 500, NULL), PDS_MORE);
        ck_assert_int_eq(pds_run(field, 500, NULL), PDS_MORE);
        ck_assert_int_eq(pds_refine(plain, 0.9 * r), 0);
        ck_assert_int_eq(pds_refine(field, 0.9 * r), 0);
        assert_same_future(field, plain, "constant field");
        n = pds_count(field);
        radii = radii_copy(field, n);
        for (j = 0; j < n; ++j) ck_assert_double_eq(radii[j], 0.9 * r);
        free(radii);
        pds_destroy(plain);
        pds_destroy(field);
    }
}
END_TEST

START_TEST(same_bytes_however_split)
{
    double r0 = 0.02;
    pds_sampler *whole = sampler_new(1.0, 5), *parts = sampler_new(1.0, 5);
    size_t added;
    int i;
    ck_assert_int_eq(pds_set_radius_fn(whole, step_field, &r0, r0, 2.5 * r0), 0);
    ck_assert_int_eq(pds_set_radius_fn(parts, step_field, &r0, r0, 2.5 * r0), 0);
    run_to_end(whole);
    for (i = 0; i < 30; ++i) ck_assert_int_eq(pds_step(parts), PDS_MORE);
    ck_assert_int_eq(pds_run(parts, 7, &added), PDS_MORE);
    ck_assert_double_gt(pds_free_area(parts), 0.0); /* a query changes nothing */
    ck_assert_int_eq(pds_verify(parts), PDS_MORE);
    ck_assert_int_eq(pds_run(parts, 300, &added), PDS_MORE);
    run_to_end(parts);
    assert_same_points(whole, parts, "split");
    pds_destroy(whole);
    pds_destroy(parts);
}
END_TEST

START_TEST(refine_scales_every_radius)
{
    double r0 = 0.03;
    pds_sampler *s = sampler_new(1.0, 9);
    size_t n0, n, i;
    double *r, *xy;
    ck_assert_int_eq(pds_set_radius_fn(s, gradient, &r0, r0, 2 * r0), 0);
    run_to_end(s);
    n0 = pds_count(s);
    ck_assert_int_eq(pds_refine(s, 0.5 * 2 * r0), 0);
    ck_assert_double_eq(pds_radius(s), r0);
    ck_assert_double_gt(pds_free_area(s), 0.0);
    ck_assert_int_eq(pds_verify(s), PDS_MORE);
    run_to_end(s);
    assert_maximal(s, "refined");
    xy = points_copy(s, &n);
    r = radii_copy(s, n);
    ck_assert_uint_gt(n, 3 * n0);
    for (i = 0; i < n; ++i)
        ck_assert(fabs(r[i] - 0.5 * gradient(&r0, xy[2 * i], xy[2 * i + 1])) <= 1e-15);
    free(xy);
    free(r);
    pds_destroy(s);
}
END_TEST

/* A field that misbehaves on demand: out of bounds while *bad is set, or
 * from call number bad_from on (0: never). */
struct flaky {
    double r0;
    int bad;
    int calls;
    int bad_from;
};

static double flaky_field(void *user, double x, double y)
{
    struct flaky *f = user;
    (void)x;
    (void)y;
    ++f->calls;
    if (f->bad_from > 0 && f->calls >= f->bad_from)
        return 10 * f->r0;
    return f->bad == 1 ? 10 * f->r0 : f->bad == 2 ? NAN : f->r0 * (1.0 + x);
}

START_TEST(a_bad_value_stops_the_run_and_keeps_the_points)
{
    struct flaky f = {0.03, 0, 0, 0};
    pds_sampler *s = sampler_new(1.0, 21), *twin = sampler_new(1.0, 21);
    struct flaky g = {0.03, 0, 0, 0};
    sampler_snapshot snap;
    size_t added = 99;
    int mode;
    ck_assert_int_eq(pds_set_radius_fn(s, flaky_field, &f, 0.03, 0.06), 0);
    ck_assert_int_eq(pds_set_radius_fn(twin, flaky_field, &g, 0.03, 0.06), 0);
    ck_assert_int_eq(pds_run(s, 40, NULL), PDS_MORE);
    ck_assert_int_eq(pds_run(twin, 40, NULL), PDS_MORE);
    for (mode = 1; mode <= 2; ++mode) {
        f.bad = mode;
        snapshot_take(s, &snap);
        assert_failed(s, pds_run(s, 0, &added), PDS_EINVAL, "bad value");
        ck_assert_uint_eq(added, 0);
        ck_assert_ptr_nonnull(strstr(pds_errmsg(s), "radius function returned"));
        snapshot_check(s, &snap, "bad value");
        assert_failed(s, pds_step(s), PDS_EINVAL, "bad value, step");
        snapshot_check(s, &snap, "bad value, step");
        snapshot_free(&snap);
    }
    /* Fixed: the sampler goes on exactly as if nothing had happened. */
    f.bad = 0;
    assert_same_future(s, twin, "after a bad value");
    pds_destroy(s);
    pds_destroy(twin);
}
END_TEST

/* With threads, after the field's dart stage: the free regions' darts ask
 * the field as each is accepted, an epoch at a time. A value refused in the
 * middle of an epoch's decision (its sixth call from here) stops the call
 * once the points of earlier epochs are added, and undoes that epoch's
 * decision; the next calls add nothing and change nothing; fixed, the run
 * goes on as one that never failed. */
START_TEST(a_bad_value_with_threads_stops_the_run_and_keeps_the_points)
{
    struct flaky f = {0.01, 0, 0, 0}, g = {0.01, 0, 0, 0}, h = {0.01, 0, 0, 0};
    pds_sampler *s = sampler_new(1.0, 22), *twin = sampler_new(1.0, 22), *whole = sampler_new(1.0, 22);
    sampler_snapshot snap;
    size_t added = 0, total;
    ck_assert_int_eq(pds_set_radius_fn(s, flaky_field, &f, 0.01, 0.02), 0);
    ck_assert_int_eq(pds_set_radius_fn(twin, flaky_field, &g, 0.01, 0.02), 0);
    ck_assert_int_eq(pds_set_radius_fn(whole, flaky_field, &h, 0.01, 0.02), 0);
    ck_assert_int_eq(pds_set_threads(s, 2), 0);
    ck_assert_int_eq(pds_set_threads(twin, 2), 0);
    ck_assert_int_eq(pds_set_threads(whole, 2), 0);
    ck_assert_int_eq(pds_run(whole, 0, NULL), PDS_DONE);
    total = pds_count(whole);
    /* Past the hand-over (the dart stage places about three in four). */
    ck_assert_int_eq(pds_run(s, total * 9 / 10, NULL), PDS_MORE);
    f.bad_from = f.calls + 6;
    assert_failed(s, pds_run(s, 0, &added), PDS_EINVAL, "bad value, threads");
    ck_assert_ptr_nonnull(strstr(pds_errmsg(s), "radius function returned"));
    ck_assert_uint_lt(pds_count(s), total);
    snapshot_take(s, &snap);
    assert_failed(s, pds_run(s, 0, &added), PDS_EINVAL, "bad value again, threads");
    ck_assert_uint_eq(added, 0);
    snapshot_check(s, &snap, "bad value again, threads");
    assert_failed(s, pds_step(s), PDS_EINVAL, "bad value, step, threads");
    snapshot_check(s, &snap, "bad value, step, threads");
    snapshot_free(&snap);
    f.bad_from = 0;
    ck_assert_int_eq(pds_run(twin, pds_count(s), NULL), PDS_MORE);
    assert_same_future(s, twin, "after a bad value, threads");
    ck_assert_uint_eq(pds_count(s), total);
    pds_destroy(s);
    pds_destroy(twin);
    pds_destroy(whole);
}
END_TEST

static double never_called(void *user, double x, double y)
{
    (void)x;
    (void)y;
    ++*(int *)user;
    return 1e300;
}

START_TEST(bad_fields_are_refused)
{
    pds_sampler *s = sampler_new(0.05, 1);
    const double zero[2] = {0.1, 0.0}, neg[2] = {0.1, -0.1}, nan2[2] = {0.1, NAN}, inf2[2] = {INFINITY, 0.1};
    const double ok[2] = {0.05, 0.1};
    int calls = 0;
    sampler_snapshot snap;
    snapshot_take(s, &snap);
    ck_assert_int_eq(pds_set_radius_map(NULL, 2, 1, ok), PDS_EINVAL);
    assert_failed(s, pds_set_radius_map(s, 2, 1, NULL), PDS_EINVAL, "NULL map");
    assert_failed(s, pds_set_radius_map(s, 0, 1, ok), PDS_EINVAL, "w 0");
    assert_failed(s, pds_set_radius_map(s, 2, 0, ok), PDS_EINVAL, "h 0");
    assert_failed(s, pds_set_radius_map(s, SIZE_MAX / 2, 4, ok), PDS_EINVAL, "w*h overflow");
    assert_failed(s, pds_set_radius_map(s, 2, 1, zero), PDS_EINVAL, "zero radius");
    assert_failed(s, pds_set_radius_map(s, 2, 1, neg), PDS_EINVAL, "negative radius");
    assert_failed(s, pds_set_radius_map(s, 2, 1, nan2), PDS_EINVAL, "NaN radius");
    assert_failed(s, pds_set_radius_map(s, 2, 1, inf2), PDS_EINVAL, "infinite radius");
    ck_assert_int_eq(pds_set_radius_fn(NULL, never_called, &calls, 0.1, 0.2), PDS_EINVAL);
    assert_failed(s, pds_set_radius_fn(s, NULL, &calls, 0.1, 0.2), PDS_EINVAL, "NULL function");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, 0.0, 0.2), PDS_EINVAL, "rmin 0");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, -0.1, 0.2), PDS_EINVAL, "rmin < 0");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, 0.3, 0.2), PDS_EINVAL, "rmin > rmax");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, NAN, 0.2), PDS_EINVAL, "rmin NaN");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, 0.1, INFINITY), PDS_EINVAL, "rmax inf");
    snapshot_check(s, &snap, "bad fields");
    ck_assert_double_eq(pds_radius(s), 0.05);
    ck_assert_int_eq(calls, 0);
    snapshot_free(&snap);
    /* Not with a count, either order. */
    ck_assert_int_eq(pds_set_count(s, 100), 0);
    assert_failed(s, pds_set_radius_map(s, 2, 1, ok), PDS_EINVAL, "map with a count");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, 0.1, 0.2), PDS_EINVAL, "fn with a count");
    pds_destroy(s);
    s = sampler_new(0.05, 1);
    ck_assert_int_eq(pds_set_radius_map(s, 2, 1, ok), 0);
    assert_failed(s, pds_set_count(s, 100), PDS_EINVAL, "count after a map");
    /* After the first point: PDS_ESTATE. */
    ck_assert_int_eq(pds_step(s), PDS_MORE);
    assert_failed(s, pds_set_radius_map(s, 2, 1, ok), PDS_ESTATE, "map after a point");
    assert_failed(s, pds_set_radius_fn(s, never_called, &calls, 0.1, 0.2), PDS_ESTATE, "fn after a point");
    pds_destroy(s);
}
END_TEST

START_TEST(smallest_radius_judged_at_the_first_point)
{
    /* rmin below double precision for the domain: PDS_ERANGE, nothing added;
     * the same field with a sane rmin runs. */
    double r0 = 1e-9;
    pds_sampler *s = sampler_new(1.0, 1);
    ck_assert_int_eq(pds_set_radius_fn(s, gradient, &r0, r0, 0.1), 0);
    assert_run_rejected(s, 10, "rmin below precision");
    assert_step_rejected(s, "rmin below precision");
    ck_assert_ptr_nonnull(strstr(pds_errmsg(s), "radius"));
    pds_destroy(s);
    {
        const double map[2] = {1e-9, 0.1};
        s = sampler_new(1.0, 1);
        ck_assert_int_eq(pds_set_radius_map(s, 2, 1, map), 0);
        assert_run_rejected(s, 0, "map rmin below precision");
        pds_destroy(s);
    }
}
END_TEST

START_TEST(radii_without_a_field_and_bad_arguments)
{
    pds_sampler *s = sampler_new(0.1, 4);
    double r[4] = {0, 0, 0, 0};
    size_t n;
    ck_assert_uint_eq(pds_radii(NULL, 0, 4, r), 0);
    ck_assert_uint_eq(pds_radii(s, 0, 4, NULL), 0);
    ck_assert_uint_eq(pds_radii(s, 0, 4, r), 0); /* no points yet */
    run_to_end(s);
    n = pds_count(s);
    ck_assert_uint_eq(pds_radii(s, n - 2, 4, r), 2);
    ck_assert_double_eq(r[0], 0.1);
    ck_assert_double_eq(r[1], 0.1);
    ck_assert_double_eq(r[2], 0.0);
    ck_assert_uint_eq(pds_radii(s, n, 4, r), 0);
    pds_destroy(s);
}
END_TEST

/* On the torus: distances wrap, so every check takes the nearest copy. */
static double wrapped2(double dx, double dy, double px, double py)
{
    dx = fabs(dx);
    dy = fabs(dy);
    if (dx > px / 2) dx = px - dx;
    if (dy > py / 2) dy = py - dy;
    return dx * dx + dy * dy;
}

static double stripes(void *user, double x, double y)
{
    (void)user;
    (void)y;
    /* 1:3 in stripes across the seam at x = -1 == 2 (continuous across it). */
    return 0.03 * (2.0 - cos(2.0 * 3.14159265358979323846 * (x + 1.0) / 3.0));
}

START_TEST(torus_field_rule_and_maximality)
{
    const test_domain d = {-1.0, 3.0, 2.0, 4.5};
    const double px = 3.0, py = 1.5;
    int seed;
    for (seed = 1; seed <= 2; ++seed) {
        pds_sampler *s = sampler_new_in(1.0, (uint64_t)seed, d);
        struct span f = {test_light() ? 0.06 : 0.03, -1.0, 3.0};
        size_t n, i, j;
        double *xy, *r;
        int a, b;
        ck_assert_int_eq(pds_set_periodic(s, 1), 0);
        ck_assert_int_eq(pds_set_radius_fn(s, seed == 1 ? stripes : step_over, &f, 0.03, seed == 1 ? 0.09 : 2.5 * f.r0), 0);
        run_to_end(s);
        assert_maximal(s, "torus field");
        xy = points_copy(s, &n);
        r = radii_copy(s, n);
        for (i = 0; i < n; ++i) {
            ck_assert(xy[2 * i] >= d.x0 && xy[2 * i] < d.x1 && xy[2 * i + 1] >= d.y0 && xy[2 * i + 1] < d.y1);
            for (j = i + 1; j < n; ++j)
                ck_assert_msg(wrapped2(xy[2 * i] - xy[2 * j], xy[2 * i + 1] - xy[2 * j + 1], px, py) >=
                                  r[i] * r[i] * (1 - 1e-12),
                              "torus: point %zu inside point %zu's disk", j, i);
        }
        const int ka = (int)pick(300, 60), kb = (int)pick(150, 30);
        for (a = 0; a < ka; ++a)
            for (b = 0; b < kb; ++b) {
                const double x = d.x0 + px * a / ka, y = d.y0 + py * b / kb;
                int in = 0;
                for (i = 0; i < n && !in; ++i)
                    in = wrapped2(xy[2 * i] - x, xy[2 * i + 1] - y, px, py) <= r[i] * r[i] * (1 + 1e-12);
                ck_assert_msg(in, "torus: the probe (%g, %g) is in no disk", x, y);
            }
        /* A refine goes on to a maximal pattern at the scaled field. */
        ck_assert_int_eq(pds_refine(s, 0.6 * pds_radius(s)), 0);
        run_to_end(s);
        assert_maximal(s, "torus field refined");
        free(xy);
        free(r);
        pds_destroy(s);
    }
}
END_TEST

START_TEST(torus_field_limits)
{
    /* rmax above half the shorter period: PDS_ERANGE at the first point. */
    double r0 = 0.2;
    pds_sampler *s = sampler_new(1.0, 1);
    ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    ck_assert_int_eq(pds_set_radius_fn(s, gradient, &r0, 0.2, 0.6), 0);
    assert_run_rejected(s, 0, "rmax above half a period");
    pds_destroy(s);
    /* A varying field on a torus longer than 16:1: PDS_ERANGE; 16:1 runs. */
    {
        double r1 = 0.01;
        s = sampler_new_in(1.0, 1, (test_domain){0, 0, 1.7, 0.1});
        ck_assert_int_eq(pds_set_periodic(s, 1), 0);
        ck_assert_int_eq(pds_set_radius_fn(s, gradient, &r1, 0.01, 0.02), 0);
        assert_run_rejected(s, 0, "a 17:1 torus with a field");
        ck_assert_ptr_nonnull(strstr(pds_errmsg(s), "16 times"));
        pds_destroy(s);
        s = sampler_new_in(1.0, 1, (test_domain){0, 0, 1.6, 0.1});
        ck_assert_int_eq(pds_set_periodic(s, 1), 0);
        ck_assert_int_eq(pds_set_radius_fn(s, gradient, &r1, 0.01, 0.04), 0);
        run_to_end(s);
        assert_maximal(s, "a 16:1 torus with a field");
        pds_destroy(s);
    }
}
END_TEST

Suite *field_suite(void)
{
    Suite *s = suite_create("field");
    TCase *t = new_tcase(s, "variable radius");
    tcase_add_test(t, function_field_rule_and_maximality);
    tcase_add_test(t, map_interpolates_between_pixel_centres);
    tcase_add_test(t, constant_field_gives_the_plain_points);
    tcase_add_test(t, same_bytes_however_split);
    tcase_add_test(t, refine_scales_every_radius);
    tcase_add_test(t, a_bad_value_stops_the_run_and_keeps_the_points);
    tcase_add_test(t, a_bad_value_with_threads_stops_the_run_and_keeps_the_points);
    tcase_add_test(t, bad_fields_are_refused);
    tcase_add_test(t, smallest_radius_judged_at_the_first_point);
    tcase_add_test(t, radii_without_a_field_and_bad_arguments);
    tcase_add_test(t, torus_field_rule_and_maximality);
    tcase_add_test(t, torus_field_limits);
    return s;
}
