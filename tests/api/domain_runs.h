/*
 * domain_runs.h - how runs behave in the unit L (domain_runs.c): the same
 * points however the calls split or a progress callback cancels them, count
 * mode, refine. Run by domain_points.c on the polygon alone and by
 * domain_fixed.c with fixed points.
 */
#ifndef PDS_TESTS_API_DOMAIN_RUNS_H
#define PDS_TESTS_API_DOMAIN_RUNS_H

#include <stddef.h>

#include "poissondisk.h"
#include "region.h"

/*
 * What a test adds to a sampler in the unit L before its first point: setup
 * (NULL: nothing), and fixed(r0, r, out), the disks a pattern must keep out
 * of and which count for coverage, for a run that started at radius r0 and
 * is now at r (pds_refine and count mode scale the clearances by r / r0);
 * at most 8, NULL: none.
 */
typedef struct domain_extra {
    const char *name;
    void (*setup)(pds_sampler *s);
    size_t (*fixed)(double r0, double r, disk *out);
} domain_extra;

/* A sampler in the unit L at radius r with e's setup. */
pds_sampler *extra_new(const domain_extra *e, double r, uint64_t seed);

void check_splits(const domain_extra *e);
void check_cancel(const domain_extra *e);
void check_count(const domain_extra *e);
void check_refine(const domain_extra *e);

#endif /* PDS_TESTS_API_DOMAIN_RUNS_H */
