/*
 * domain_check.h - the checks every pattern in a polygon gets (domain_check.c),
 * through the public API and the independent model of region.h: each point
 * in the closed polygon, each later point outside every earlier point's
 * closed disk (|p_j - p_i| >= r_i for i < j, r_i from pds_radii) and at least
 * each fixed point's clearance from it, and, when maximal, the polygon
 * covered by the disks and the clearances (region_covered), pds_verify and
 * pds_free_area agreeing.
 */
#ifndef PDS_TESTS_API_DOMAIN_CHECK_H
#define PDS_TESTS_API_DOMAIN_CHECK_H

#include <stddef.h>

#include "poissondisk.h"
#include "region.h"

/* The points of s and their radii, malloc'd (free both); *n their count. */
void domain_pattern(const pds_sampler *s, double **xy, double **r, size_t *n);

/* Inside, spaced, clear of the fixed disks (clearances resolved). */
void assert_domain_rules(const double *xy, const double *r, size_t n, const region *g,
                         const disk *fixed, size_t nfixed, const char *what);

/* The disks of the points and the fixed disks cover the closed polygon. */
void assert_domain_covered(const double *xy, const double *r, size_t n, const region *g,
                           const disk *fixed, size_t nfixed, const char *what);

/* All of the above on a sampler run to the end, and pds_verify PDS_DONE,
 * pds_free_area 0. */
void assert_domain_pattern(pds_sampler *s, const region *g, const disk *fixed, size_t nfixed,
                           const char *what);

#endif /* PDS_TESTS_API_DOMAIN_CHECK_H */
