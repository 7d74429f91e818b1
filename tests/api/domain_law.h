/*
 * domain_law.h - the law comparison in the unit L (domain_law.c), shared by
 * the suites with and without fixed points.
 */
#ifndef PDS_TESTS_API_DOMAIN_LAW_H
#define PDS_TESTS_API_DOMAIN_LAW_H

#include <stddef.h>
#include <stdint.h>

#include "poissondisk.h"
#include "region.h"

/* The radius of the law tests: about 50 points in the unit L. */
#define LAW_R 0.1

/* What the sampler gets besides the unit L (setup, NULL for nothing), and
 * the fixed disks that gives, clearances resolved at LAW_R, which the
 * reference and the checks use. */
typedef struct law_case {
    const char *name;
    void (*setup)(pds_sampler *s);
    const disk *fixed;
    size_t nfixed;
    unsigned threads; /* > 0: the parallel process on that many threads */
} law_case;

/* The library's patterns against the reference's (statistics, tests). */
void law_compare(const law_case *c);

/* For seeds 1..seeds, a reference and a library pattern: each maximal by
 * region_covered, and not maximal with any one point removed. */
void law_removals_found(const law_case *c, uint64_t seeds);

#endif /* PDS_TESTS_API_DOMAIN_LAW_H */
