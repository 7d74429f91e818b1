/*
 * suites.h - the public-API test suites, one per file, collected by main.c.
 *
 * Each suite tests one area of the contract in include/poissondisk.h:
 *   codes_suite        pds_strerror, pds_errmsg texts, version functions   (codes.c)
 *   args_suite         every invalid argument: code, message, no change    (args.c)
 *   state_suite        what is allowed when (set_domain, refine, run)      (state.c)
 *   semantics_suite    step/run/refine/points/free_area/verify meaning     (semantics.c)
 *   determinism_suite  same seed -> same bytes; no shared state            (determinism.c)
 *   properties_suite   distance, containment, maximality over seeds        (properties.c)
 *   lifecycle_suite    create/destroy cycles, destroy mid-run (Valgrind)   (lifecycle.c)
 *   golden_suite       pinned fingerprints of the points some seeds give  (golden.c)
 *   splits_suite       same bytes however calls split the work, refine too (splits.c)
 *   limits_suite       tiny, huge and far-off domains; when ERANGE comes   (limits.c)
 *   slivers_suite      rectangles far thinner than R: free area, the law   (slivers.c)
 *   count_suite        pds_set_count: exactly n points, spacing, splits    (count.c)
 *   progress_suite     pds_set_progress: reports, cancel and resume        (progress.c)
 *   periodic_suite     pds_set_periodic: the torus, spacing, law, state    (periodic.c)
 *   field_suite        a variable radius: rule, maximality, map, splits    (field.c)
 *   field_range_suite  a field on domains at the ends of the double range  (field_range.c)
 *   messages_suite     pds_errmsg names the radius or callback at fault    (messages.c)
 *   documented_suite   measured facts the man pages state                  (documented.c)
 *   field_bound_suite  how an unbounded run with a radius map is judged    (field_bound.c)
 *   domain_args_suite  pds_set_polygon, pds_set_mask: refusals, states     (domain_args.c)
 *   domain_points_suite  polygons: inside, spaced, maximal; runs           (domain_points.c)
 *   domain_raster_suite  a mask as the domain; a radius map with a polygon (domain_raster.c)
 *   domain_law_suite   the law in a polygon against dart throwing         (domain_law.c)
 *   domain_fixed_suite pds_set_fixed: refusals, clearances, runs, the law  (domain_fixed.c)
 *   domain_fixed_edges_suite  no room left; a constant field             (domain_fixed_edges.c)
 *   domain_fixed_count_suite  count mode around fixed points            (domain_fixed_count.c)
 *   threads_suite      pds_set_threads: arguments; the same bytes for any count (threads.c)
 */
#ifndef PDS_TESTS_API_SUITES_H
#define PDS_TESTS_API_SUITES_H

#include <check.h>

Suite *codes_suite(void);
Suite *args_suite(void);
Suite *state_suite(void);
Suite *semantics_suite(void);
Suite *determinism_suite(void);
Suite *properties_suite(void);
Suite *lifecycle_suite(void);
Suite *golden_suite(void);
Suite *splits_suite(void);
Suite *limits_suite(void);
Suite *slivers_suite(void);
Suite *count_suite(void);
Suite *progress_suite(void);
Suite *periodic_suite(void);
Suite *field_suite(void);
Suite *field_range_suite(void);
Suite *messages_suite(void);
Suite *documented_suite(void);
Suite *field_bound_suite(void);
Suite *domain_args_suite(void);
Suite *domain_points_suite(void);
Suite *domain_raster_suite(void);
Suite *domain_law_suite(void);
Suite *domain_fixed_suite(void);
Suite *domain_fixed_edges_suite(void);
Suite *domain_fixed_count_suite(void);
Suite *threads_suite(void);

#endif /* PDS_TESTS_API_SUITES_H */
