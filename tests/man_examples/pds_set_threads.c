/*
 * Select the parallel process before the first point, make the same
 * pattern on one thread and on every core, and check that the points
 * are the same bytes: the count changes only the speed.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <poissondisk.h>

/* The pattern of seed 7 at radius 0.01 of the parallel process on
 * `threads` threads (0: one per core), in a new array of *n points;
 * NULL on failure. pds_set_threads comes before the first point: after
 * points of the single-thread process it fails with PDS_ESTATE. */
static double *
pattern(unsigned threads, size_t *n, unsigned *used)
{
    pds_sampler *s;
    double *xy = NULL;
    int rc;

    if ((rc = pds_create(&s, 0.01, 7)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return NULL;
    }
    if ((rc = pds_set_domain(s, 0.0, 0.0, 2.0, 1.0)) != 0 ||
        (rc = pds_set_threads(s, threads)) != 0 ||
        (rc = pds_run(s, 0, NULL)) != PDS_DONE) {
        fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
        pds_destroy(s);
        return NULL;
    }
    *used = pds_threads(s);
    *n = pds_count(s);
    xy = malloc(2 * *n * sizeof(*xy));
    if (xy != NULL && pds_points(s, 0, *n, xy) != *n) {
        free(xy);
        xy = NULL;
    }
    pds_destroy(s);
    return xy;
}

int
main(void)
{
    double *one, *all;
    size_t n1 = 0, n2 = 0;
    unsigned t1 = 0, t2 = 0;
    int same;

    one = pattern(1, &n1, &t1);
    all = pattern(0, &n2, &t2);
    if (one == NULL || all == NULL) {
        free(one);
        free(all);
        return 1;
    }
    same = n1 == n2 && memcmp(one, all, 2 * n1 * sizeof(*one)) == 0;
    printf("%zu points on %u thread, %zu on %u: %s\n", n1, t1, n2, t2,
        same ? "the same bytes" : "DIFFERENT");
    free(one);
    free(all);
    return same ? 0 : 1;
}
