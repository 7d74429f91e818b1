/*
 * Make the same pattern twice in the rectangle [0,2]x[0,1] and check
 * that one seed gives the same points, and that the domain is fixed
 * once the first point exists.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <poissondisk.h>

/* A maximal pattern in [0,2]x[0,1], or NULL after a message. */
static pds_sampler *
make_pattern(double radius, uint64_t seed)
{
    pds_sampler *s;
    int rc;

    rc = pds_create(&s, radius, seed);
    if (rc != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return NULL;
    }
    /* Options such as the domain go before the first point. */
    if ((rc = pds_set_domain(s, 0.0, 0.0, 2.0, 1.0)) != 0 ||
        (rc = pds_run(s, 0, NULL)) != 0) {
        fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
        pds_destroy(s);
        return NULL;
    }
    return s;
}

int
main(void)
{
    pds_sampler *a, *b;
    double *pa = NULL, *pb = NULL;
    size_t n;
    int ok = 0;

    a = make_pattern(0.05, 7);
    b = make_pattern(0.05, 7);
    if (a == NULL || b == NULL)
        goto out;

    n = pds_count(a);
    pa = malloc(2 * n * sizeof(*pa));
    pb = malloc(2 * n * sizeof(*pb));
    if (pa == NULL || pb == NULL) {
        fprintf(stderr, "out of memory\n");
        goto out;
    }
    if (pds_count(b) != n || pds_points(a, 0, n, pa) != n ||
        pds_points(b, 0, n, pb) != n ||
        memcmp(pa, pb, 2 * n * sizeof(*pa)) != 0) {
        fprintf(stderr, "same seed, different points\n");
        goto out;
    }

    if (pds_set_domain(a, 0.0, 0.0, 1.0, 1.0) != PDS_ESTATE) {
        fprintf(stderr, "domain changed after the first point\n");
        goto out;
    }
    printf("%zu points, the same in both samplers\n", n);
    ok = 1;
out:
    free(pa);
    free(pb);
    pds_destroy(a);    /* NULL is allowed */
    pds_destroy(b);
    return ok ? 0 : 1;
}
