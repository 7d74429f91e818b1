/*
 * Grow a pattern in stages: ten points one at a time, the rest in
 * batches with a progress line, then keep every point and continue
 * at half the radius until the pattern is maximal again.
 */
#include <stdio.h>

#include <poissondisk.h>

int
main(void)
{
    pds_sampler *s;
    size_t added, total = 0;
    int i, rc;

    if ((rc = pds_create(&s, 0.04, 1)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return 1;
    }

    /* pds_step: 1 (PDS_MORE) for a new point, 0 (PDS_DONE) at the end. */
    for (i = 0; i < 10; i++) {
        if ((rc = pds_step(s)) < 0)
            goto fail;
        total += (size_t)rc;
    }

    /* pds_run: 1 (PDS_MORE) while a batch is full and room is left. */
    while ((rc = pds_run(s, 200, &added)) == 1) {
        total += added;
        printf("%zu points, free area %.3g\n", pds_count(s),
            pds_free_area(s));
    }
    if (rc < 0)
        goto fail;
    total += added;
    if (pds_free_area(s) != 0.0 || pds_step(s) != 0) {
        fprintf(stderr, "maximal, yet room is left\n");
        goto out;
    }
    printf("%zu points, maximal at radius %g\n", pds_count(s),
        pds_radius(s));

    /* Refine: old points keep their indices, new ones follow. */
    if ((rc = pds_refine(s, pds_radius(s) / 2)) != 0 ||
        (rc = pds_run(s, 0, &added)) != 0)
        goto fail;
    total += added;
    printf("%zu points, maximal at radius %g\n", pds_count(s),
        pds_radius(s));

    if (total != pds_count(s)) {
        fprintf(stderr, "added %zu points, have %zu\n", total,
            pds_count(s));
        goto out;
    }
    pds_destroy(s);
    return 0;
fail:
    fprintf(stderr, "%s: %s\n", pds_strerror(rc), pds_errmsg(s));
out:
    pds_destroy(s);
    return 1;
}
