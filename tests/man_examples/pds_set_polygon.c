/*
 * Sample an L-shaped plate with a square hole in it, keeping clear of a
 * bolt (a fixed point with a clearance of 0.2) and of a point an earlier
 * step placed (clearance 0: the radius).  Check that every point keeps
 * its distance from both, and print the count.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <poissondisk.h>

#define R 0.05

/* Ring 0, the L, counter-clockwise; ring 1, the hole (either way). */
static const double outline[] = {
    0.0, 0.0,  2.0, 0.0,  2.0, 1.0,  1.0, 1.0,  1.0, 2.0,  0.0, 2.0,
    0.3, 0.3,  0.7, 0.3,  0.7, 0.7,  0.3, 0.7,
};
static const size_t ring_ends[] = {6, 10};

/* The bolt, and the earlier point. */
static const double fixed[] = {1.5, 0.5,  0.5, 1.5};
static const double clearance[] = {0.2, 0.0};

int
main(void)
{
    pds_sampler *s;
    double *xy = NULL, c, dx, dy;
    size_t i, k, n;
    int rc;

    if ((rc = pds_create(&s, R, 1)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return 1;
    }
    /* The arrays are copied: they could be freed now. */
    if ((rc = pds_set_polygon(s, outline, ring_ends, 2)) != 0 ||
        (rc = pds_set_fixed(s, fixed, clearance, 2)) != 0 ||
        (rc = pds_run(s, 0, NULL)) != PDS_DONE ||
        (rc = pds_verify(s)) != PDS_DONE)
        goto fail;

    /* The sampled points only: the fixed points are not among them. */
    n = pds_count(s);
    xy = malloc(2 * n * sizeof(*xy));
    if (n == 0 || xy == NULL || pds_points(s, 0, n, xy) != n) {
        fprintf(stderr, "could not read the points\n");
        goto out;
    }
    for (i = 0; i < n; i++) {
        for (k = 0; k < 2; k++) {
            c = clearance[k] > 0.0 ? clearance[k] : R;
            dx = xy[2 * i] - fixed[2 * k];
            dy = xy[2 * i + 1] - fixed[2 * k + 1];
            /* Exact in the library; allow for rounding here. */
            if (sqrt(dx * dx + dy * dy) < c * (1 - 1e-12)) {
                fprintf(stderr, "point %zu too near fixed point %zu\n",
                    i, k);
                goto out;
            }
        }
    }
    printf("%zu points in the plate, maximal, clear of the bolt\n", n);
    free(xy);
    pds_destroy(s);
    return 0;
fail:
    fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
out:
    free(xy);
    pds_destroy(s);
    return 1;
}
