/*
 * Watch the free area shrink to zero, then read the pattern back the
 * way a language binding would: through a small fixed buffer, then
 * all at once; check that every point lies in the domain and that no
 * two points are closer than the radius.
 */
#include <stdio.h>
#include <stdlib.h>

#include <poissondisk.h>

#define X0 (-1.0)
#define Y0 0.0
#define X1 1.0
#define Y1 0.5
#define CHUNK 64    /* points per pds_points() call */

int
main(void)
{
    pds_sampler *s;
    double buf[2 * CHUNK], *xy = NULL;
    double area = (X1 - X0) * (Y1 - Y0), r, dx, dy;
    size_t first, got, i, j, n;
    int rc;

    if ((rc = pds_create(&s, 0.05, 3)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return 1;
    }
    if ((rc = pds_set_domain(s, X0, Y0, X1, Y1)) != 0 ||
        (rc = pds_run(s, 100, NULL)) != 1) {
        fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
        goto fail;
    }
    printf("%zu points, %.1f%% of the area free\n", pds_count(s),
        100 * pds_free_area(s) / area);
    if ((rc = pds_run(s, 0, NULL)) != 0) {
        fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
        goto fail;
    }
    if (pds_free_area(s) != 0.0) {
        fprintf(stderr, "maximal, but free area %g\n",
            pds_free_area(s));
        goto fail;
    }

    /* In pieces: the last call is clipped, the one after returns 0. */
    n = pds_count(s);
    for (first = 0; (got = pds_points(s, first, CHUNK, buf)) > 0;
        first += got) {
        for (i = 0; i < got; i++) {
            if (buf[2 * i] < X0 || buf[2 * i] > X1 ||
                buf[2 * i + 1] < Y0 || buf[2 * i + 1] > Y1) {
                fprintf(stderr, "point %zu outside\n", first + i);
                goto fail;
            }
        }
    }
    if (first != n) {
        fprintf(stderr, "read %zu points of %zu\n", first, n);
        goto fail;
    }

    /*
     * All at once.  The library decides distances exactly; this plain
     * check allows for the rounding of dx * dx + dy * dy.
     */
    xy = malloc(2 * n * sizeof(*xy));
    if (xy == NULL || pds_points(s, 0, n, xy) != n) {
        fprintf(stderr, "could not read the points\n");
        goto fail;
    }
    r = pds_radius(s);
    for (i = 0; i < n; i++) {
        for (j = i + 1; j < n; j++) {
            dx = xy[2 * i] - xy[2 * j];
            dy = xy[2 * i + 1] - xy[2 * j + 1];
            if (dx * dx + dy * dy < r * r * (1 - 1e-12)) {
                fprintf(stderr, "points %zu and %zu too close\n", i, j);
                goto fail;
            }
        }
    }
    printf("%zu points, all in the domain and %g apart\n", n, r);
    free(xy);
    pds_destroy(s);
    return 0;
fail:
    free(xy);
    pds_destroy(s);
    return 1;
}
