/*
 * helpers.c - shared helpers of the public-API tests; see helpers.h.
 */
#include "helpers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const test_domain UNIT_SQUARE = {0.0, 0.0, 1.0, 1.0};

int test_light(void)
{
    const char *v = getenv("PDS_TEST_LIGHT");
    return v != NULL && v[0] != '\0';
}

size_t pick(size_t native, size_t light)
{
    return test_light() ? light : native;
}

TCase *new_tcase(Suite *suite, const char *name)
{
    TCase *tc = tcase_create(name);
    /* Check's default of 4 s is too tight for the calibration runs on a slow
     * machine; a hang still fails instead of blocking (in fork mode). */
    tcase_set_timeout(tc, 120.0);
    suite_add_tcase(suite, tc);
    return tc;
}

pds_sampler *sampler_new(double radius, uint64_t seed)
{
    pds_sampler *s = NULL;
    int rc = pds_create(&s, radius, seed);
    ck_assert_msg(rc == 0, "pds_create(R=%.17g, seed=%llu) returned %d (%s)", radius,
                  (unsigned long long)seed, rc, pds_strerror(rc));
    ck_assert_ptr_nonnull(s);
    return s;
}

pds_sampler *sampler_new_in(double radius, uint64_t seed, test_domain d)
{
    pds_sampler *s = sampler_new(radius, seed);
    int rc = pds_set_domain(s, d.x0, d.y0, d.x1, d.y1);
    ck_assert_msg(rc == 0, "pds_set_domain([%g,%g]x[%g,%g]) with R=%g returned %d (%s)",
                  d.x0, d.x1, d.y0, d.y1, radius, rc, pds_errmsg(s));
    return s;
}

void twins_new(double radius, uint64_t seed, const test_domain *d, size_t npoints,
               pds_sampler **a, pds_sampler **b)
{
    pds_sampler *pair[2];
    int i;

    for (i = 0; i < 2; i++) {
        pds_sampler *s = d ? sampler_new_in(radius, seed, *d) : sampler_new(radius, seed);
        if (npoints == TO_END) {
            run_to_end(s);
        } else if (npoints > 0) {
            size_t added = 0;
            int rc = pds_run(s, npoints, &added);
            ck_assert_msg(rc == 1 && added == npoints,
                          "twins_new: pds_run(s, %zu) returned %d and added %zu; the "
                          "test needs room for more points",
                          npoints, rc, added);
        }
        pair[i] = s;
    }
    *a = pair[0];
    *b = pair[1];
}

size_t run_to_end(pds_sampler *s)
{
    size_t added = (size_t)-1;
    size_t before = pds_count(s);
    int rc = pds_run(s, 0, &added);
    ck_assert_msg(rc == 0, "pds_run(s, 0, &added) returned %d (%s), expected 0 (maximal)",
                  rc, pds_errmsg(s));
    ck_assert_msg(added == pds_count(s) - before,
                  "pds_run reported %zu added, but the count went from %zu to %zu", added,
                  before, pds_count(s));
    return added;
}

double *points_copy(const pds_sampler *s, size_t *n)
{
    size_t count = pds_count(s);
    /* One spare pair so that an empty sampler still gives a non-NULL buffer. */
    double *xy = malloc((2 * count + 2) * sizeof *xy);
    size_t copied;

    ck_assert_ptr_nonnull(xy);
    copied = pds_points(s, 0, count, xy);
    ck_assert_msg(copied == count, "pds_points copied %zu of %zu points", copied, count);
    *n = count;
    return xy;
}

void assert_points_equal(const double *a, size_t na, const double *b, size_t nb,
                         const char *what)
{
    size_t i;

    ck_assert_msg(na == nb, "%s: %zu points vs %zu points", what, na, nb);
    if (na == 0 || memcmp(a, b, 2 * na * sizeof *a) == 0)
        return;
    for (i = 0; i < na; i++)
        if (memcmp(a + 2 * i, b + 2 * i, 2 * sizeof *a) != 0)
            break;
    ck_abort_msg("%s: point %zu differs: (%.17g, %.17g) vs (%.17g, %.17g)", what, i,
                 a[2 * i], a[2 * i + 1], b[2 * i], b[2 * i + 1]);
}

void assert_prefix_kept(const pds_sampler *s, const double *prefix, size_t nprefix,
                        const char *what)
{
    size_t n;
    double *xy;

    ck_assert_msg(pds_count(s) >= nprefix, "%s: only %zu points, expected at least %zu",
                  what, pds_count(s), nprefix);
    xy = points_copy(s, &n);
    assert_points_equal(xy, nprefix, prefix, nprefix, what);
    free(xy);
}

void assert_same_points(const pds_sampler *a, const pds_sampler *b, const char *what)
{
    size_t na, nb;
    double *pa = points_copy(a, &na);
    double *pb = points_copy(b, &nb);

    assert_points_equal(pa, na, pb, nb, what);
    free(pa);
    free(pb);
}

void assert_same_future(pds_sampler *a, pds_sampler *b, const char *what)
{
    ck_assert_msg(pds_radius(a) == pds_radius(b), "%s: radius %.17g vs twin's %.17g", what,
                  pds_radius(a), pds_radius(b));
    run_to_end(a);
    run_to_end(b);
    assert_same_points(a, b, what);
}

void assert_rel_close(double got, double want, double tol, const char *what)
{
    ck_assert_msg(fabs(got - want) <= tol * fabs(want), "%s: %.17g, expected %.17g (within %g)",
                  what, got, want, tol);
}

void assert_inside(const double *xy, size_t n, test_domain d, const char *what)
{
    size_t i;

    for (i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        /* Written so that NaN coordinates fail too. */
        ck_assert_msg(x >= d.x0 && x <= d.x1 && y >= d.y0 && y <= d.y1,
                      "%s: point %zu (%.17g, %.17g) outside [%.17g,%.17g]x[%.17g,%.17g]",
                      what, i, x, y, d.x0, d.x1, d.y0, d.y1);
    }
}

void assert_min_distance(const double *xy, size_t n, double r, const char *what)
{
    double r2 = r * r;
    size_t i, j;

    for (i = 0; i < n; i++) {
        double xi = xy[2 * i], yi = xy[2 * i + 1];
        for (j = i + 1; j < n; j++) {
            double dx = xy[2 * j] - xi, dy = xy[2 * j + 1] - yi;
            double d2 = dx * dx + dy * dy;
            if (!(d2 >= r2))
                ck_abort_msg("%s: points %zu (%.17g, %.17g) and %zu (%.17g, %.17g) are "
                             "%.17g apart, less than R = %.17g",
                             what, i, xi, yi, j, xy[2 * j], xy[2 * j + 1], sqrt(d2), r);
        }
    }
}

void assert_maximal(pds_sampler *s, const char *what)
{
    double area = pds_free_area(s);
    int rc;

    ck_assert_msg(area == 0.0, "%s: free area %.17g, expected exactly 0 when maximal", what,
                  area);
    rc = pds_step(s);
    ck_assert_msg(rc == 0, "%s: pds_step on a maximal pattern returned %d", what, rc);
    rc = pds_verify(s);
    ck_assert_msg(rc == 0, "%s: pds_verify returned %d (%s), expected 0 (valid, maximal)",
                  what, rc, pds_errmsg(s));
}

void assert_failed(const pds_sampler *s, int rc, int expected, const char *what)
{
    const char *msg;

    ck_assert_msg(rc == expected, "%s: returned %d (%s), expected %d (%s)", what, rc,
                  pds_strerror(rc), expected, pds_strerror(expected));
    if (s == NULL)
        return;
    msg = pds_errmsg(s);
    ck_assert_msg(msg != NULL, "%s: pds_errmsg returned NULL after a failure", what);
    ck_assert_msg(msg[0] != '\0', "%s: pds_errmsg is empty after a failure", what);
    ck_assert_msg(strcmp(msg, "no error") != 0, "%s: pds_errmsg says \"no error\" after a failure",
                  what);
}

/* Count, radius and points unchanged (not the free area: costly or
 * infinite on the domains these calls reject). */
static void check_unchanged(const pds_sampler *s, size_t count, double radius, const double *xy,
                            const char *what)
{
    ck_assert_msg(pds_radius(s) == radius, "%s: radius changed from %.17g to %.17g", what,
                  radius, pds_radius(s));
    ck_assert_msg(pds_count(s) == count, "%s: count changed from %zu to %zu", what, count,
                  pds_count(s));
    assert_prefix_kept(s, xy, count, what);
}

void assert_run_rejected(pds_sampler *s, size_t max_new, const char *what)
{
    size_t count, added = 777;
    double radius = pds_radius(s);
    double *xy = points_copy(s, &count);

    assert_failed(s, pds_run(s, max_new, &added), PDS_ERANGE, what);
    ck_assert_msg(added == 0, "%s: PDS_ERANGE, yet %zu points reported added", what, added);
    check_unchanged(s, count, radius, xy, what);
    free(xy);
}

void assert_step_rejected(pds_sampler *s, const char *what)
{
    size_t count;
    double radius = pds_radius(s);
    double *xy = points_copy(s, &count);

    assert_failed(s, pds_step(s), PDS_ERANGE, what);
    check_unchanged(s, count, radius, xy, what);
    free(xy);
}

void snapshot_take(const pds_sampler *s, sampler_snapshot *snap)
{
    snap->count = pds_count(s);
    snap->radius = pds_radius(s);
    snap->free_area = pds_free_area(s);
    snap->xy = points_copy(s, &snap->count);
}

void snapshot_check(const pds_sampler *s, const sampler_snapshot *snap, const char *what)
{
    size_t n;
    double *xy;

    ck_assert_msg(pds_count(s) == snap->count, "%s: count changed from %zu to %zu", what,
                  snap->count, pds_count(s));
    ck_assert_msg(pds_radius(s) == snap->radius, "%s: radius changed from %.17g to %.17g",
                  what, snap->radius, pds_radius(s));
    ck_assert_msg(pds_free_area(s) == snap->free_area,
                  "%s: free area changed from %.17g to %.17g", what, snap->free_area,
                  pds_free_area(s));
    xy = points_copy(s, &n);
    assert_points_equal(xy, n, snap->xy, snap->count, what);
    free(xy);
}

void snapshot_free(sampler_snapshot *snap)
{
    free(snap->xy);
    snap->xy = NULL;
}
