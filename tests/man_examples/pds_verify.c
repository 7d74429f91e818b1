/*
 * Re-check patterns for a few seeds, independently of the sampler:
 * part way through, a pattern must be valid with room left (1); at
 * the end, valid and maximal (0).  The header names 1 PDS_MORE and
 * 0 PDS_DONE since 1.1.1; this program also builds with older ones.
 */
#include <inttypes.h>
#include <stdio.h>

#include <poissondisk.h>

/* Returns 0 when every call gives the expected answer. */
static int
check(uint64_t seed)
{
    pds_sampler *s;
    int rc;

    if ((rc = pds_create(&s, 0.03, seed)) != 0) {
        fprintf(stderr, "pds_create: %s\n", pds_strerror(rc));
        return -1;
    }
    if ((rc = pds_run(s, 300, NULL)) != 1 ||  /* 300 added, room left */
        (rc = pds_verify(s)) != 1 ||          /* valid, room left */
        (rc = pds_run(s, 0, NULL)) != 0 ||    /* maximal */
        (rc = pds_verify(s)) != 0) {          /* valid and maximal */
        /* For PDS_EINTERNAL, the message names the failed check. */
        if (rc < 0)
            fprintf(stderr, "seed %" PRIu64 ": %s: %s\n", seed,
                pds_strerror(rc), pds_errmsg(s));
        else
            fprintf(stderr, "seed %" PRIu64 ": unexpected %d\n",
                seed, rc);
        pds_destroy(s);
        return -1;
    }
    pds_destroy(s);
    return 0;
}

int
main(void)
{
    uint64_t seed;
    int failed = 0;

    for (seed = 1; seed <= 5; seed++)
        if (check(seed) != 0)
            failed = 1;
    if (!failed)
        printf("5 patterns valid and maximal\n");
    return failed;
}
