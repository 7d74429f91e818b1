/*
 * Fill the unit square with a maximal Poisson-disk pattern and print
 * it, one "x y" line per point, in the order the points were made.
 */
#include <stdio.h>
#include <stdlib.h>

#include <poissondisk.h>

int
main(void)
{
    pds_sampler *s;
    double *xy;
    size_t i, n;
    int rc;

    rc = pds_create(&s, 0.1, 42);    /* radius 0.1, seed 42 */
    if (rc != 0) {
        /* No sampler to ask, so describe the code itself. */
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return 1;
    }

    rc = pds_run(s, 0, NULL);        /* 0: no limit, until maximal */
    if (rc != 0) {
        fprintf(stderr, "pds_run: %s\n", pds_errmsg(s));
        pds_destroy(s);
        return 1;
    }

    /* A maximal pattern in a non-empty domain has a point at least. */
    n = pds_count(s);
    xy = malloc(2 * n * sizeof(*xy));
    if (xy == NULL || pds_points(s, 0, n, xy) != n) {
        fprintf(stderr, "could not read the points\n");
        free(xy);
        pds_destroy(s);
        return 1;
    }
    for (i = 0; i < n; i++)
        printf("%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);

    free(xy);
    pds_destroy(s);
    return 0;
}
