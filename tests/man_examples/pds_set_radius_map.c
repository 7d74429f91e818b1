/*
 * Sample the unit square with a radius that grows from left to right,
 * from 0.02 at x = 0 to 0.06 at x = 1: dense on the left, sparse on
 * the right.  Check the rule each point obeys against the earlier
 * ones, and print the count and the radii of the first points.
 */
#include <stdio.h>
#include <stdlib.h>

#include <poissondisk.h>

#define RMIN 0.02
#define RMAX 0.06

/* The field: a gradient in x, within [RMIN, RMAX] over the domain. */
static double
gradient(void *user, double x, double y)
{
    (void)user;
    (void)y;
    return RMIN + (RMAX - RMIN) * x;
}

int
main(void)
{
    pds_sampler *s;
    double *xy = NULL, *r = NULL, dx, dy;
    size_t i, j, n;
    int rc;

    if ((rc = pds_create(&s, RMAX, 7)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return 1;
    }
    if ((rc = pds_set_radius_fn(s, gradient, NULL, RMIN, RMAX)) != 0 ||
        (rc = pds_run(s, 0, NULL)) != PDS_DONE ||
        (rc = pds_verify(s)) != PDS_DONE)
        goto fail;

    n = pds_count(s);
    xy = malloc(2 * n * sizeof(*xy));
    r = malloc(n * sizeof(*r));
    if (n == 0 || xy == NULL || r == NULL ||
        pds_points(s, 0, n, xy) != n || pds_radii(s, 0, n, r) != n) {
        fprintf(stderr, "could not read the pattern\n");
        goto out;
    }
    /*
     * Point j keeps out of the disk of every earlier point i.  The
     * library decides exactly; this plain check allows for rounding.
     */
    for (j = 0; j < n; j++) {
        for (i = 0; i < j; i++) {
            dx = xy[2 * j] - xy[2 * i];
            dy = xy[2 * j + 1] - xy[2 * i + 1];
            if (dx * dx + dy * dy < r[i] * r[i] * (1 - 1e-12)) {
                fprintf(stderr, "point %zu inside the disk of %zu\n",
                    j, i);
                goto out;
            }
        }
    }
    printf("%zu points, maximal; largest radius %g\n", n,
        pds_radius(s));
    for (i = 0; i < 3 && i < n; i++)
        printf("point %zu at (%.3f, %.3f), radius %.4f\n", i,
            xy[2 * i], xy[2 * i + 1], r[i]);
    free(xy);
    free(r);
    pds_destroy(s);
    return 0;
fail:
    fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
out:
    free(xy);
    free(r);
    pds_destroy(s);
    return 1;
}
