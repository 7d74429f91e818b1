/*
 * domain_check.c - the checks of a pattern in a polygon; see domain_check.h.
 */
#include "domain_check.h"

#include <math.h>
#include <stdlib.h>

#include "helpers.h"

void domain_pattern(const pds_sampler *s, double **xy, double **r, size_t *n)
{
    *xy = points_copy(s, n);
    *r = malloc((*n + 1) * sizeof **r);
    ck_assert_ptr_nonnull(*r);
    ck_assert_uint_eq(pds_radii(s, 0, *n, *r), *n);
}

void assert_domain_rules(const double *xy, const double *r, size_t n, const region *g,
                         const disk *fixed, size_t nfixed, const char *what)
{
    double box[4], rmin = INFINITY;
    disk_grid G;
    size_t i, k;

    for (i = 0; i < n; i++) {
        ck_assert_msg(region_contains(g, xy[2 * i], xy[2 * i + 1]),
                      "%s: point %zu (%.17g, %.17g) is outside the polygon", what, i, xy[2 * i],
                      xy[2 * i + 1]);
        ck_assert_msg(r[i] > 0.0, "%s: point %zu has radius %g", what, i, r[i]);
        rmin = fmin(rmin, r[i]);
        for (k = 0; k < nfixed; k++) {
            const double d = hypot(xy[2 * i] - fixed[k].x, xy[2 * i + 1] - fixed[k].y);
            /* The library decides exactly; allow the rounding of hypot here. */
            ck_assert_msg(d >= fixed[k].r * (1.0 - 1e-12),
                          "%s: point %zu (%.17g, %.17g) is %.17g from fixed point %zu, "
                          "closer than its clearance %.17g",
                          what, i, xy[2 * i], xy[2 * i + 1], d, k, fixed[k].r);
        }
    }
    if (n == 0)
        return;
    region_bounds(g, box);
    grid_init(&G, box, rmin);
    /* Before point j joins, no earlier disk may hold it: the rule itself. */
    for (i = 0; i < n; i++) {
        disk d;
        if (grid_strictly_inside(&G, xy[2 * i], xy[2 * i + 1], 1e-12)) {
            grid_free(&G);
            ck_abort_msg("%s: point %zu (%.17g, %.17g) lies inside an earlier point's disk",
                         what, i, xy[2 * i], xy[2 * i + 1]);
        }
        d.x = xy[2 * i], d.y = xy[2 * i + 1], d.r = r[i];
        grid_add(&G, d);
    }
    grid_free(&G);
}

void assert_domain_covered(const double *xy, const double *r, size_t n, const region *g,
                           const disk *fixed, size_t nfixed, const char *what)
{
    disk *d = malloc((n + nfixed + 1) * sizeof *d);
    char why[256];
    size_t i;
    int ok;

    ck_assert_ptr_nonnull(d);
    for (i = 0; i < n; i++)
        d[i].x = xy[2 * i], d[i].y = xy[2 * i + 1], d[i].r = r[i];
    for (i = 0; i < nfixed; i++)
        d[n + i] = fixed[i];
    ok = region_covered(g, d, n + nfixed, 1e-9, why, sizeof why);
    free(d);
    ck_assert_msg(ok, "%s: not maximal: %s", what, why);
}

void assert_domain_pattern(pds_sampler *s, const region *g, const disk *fixed, size_t nfixed,
                           const char *what)
{
    double *xy, *r;
    size_t n;
    int rc = pds_verify(s);

    ck_assert_msg(rc == PDS_DONE, "%s: pds_verify returned %d (%s)", what, rc, pds_errmsg(s));
    ck_assert_msg(pds_free_area(s) == 0.0, "%s: free area %.17g when maximal", what,
                  pds_free_area(s));
    domain_pattern(s, &xy, &r, &n);
    assert_domain_rules(xy, r, n, g, fixed, nfixed, what);
    assert_domain_covered(xy, r, n, g, fixed, nfixed, what);
    free(xy);
    free(r);
}
