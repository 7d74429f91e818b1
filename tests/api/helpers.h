/*
 * helpers.h - shared helpers of the public-API tests (helpers.c).
 *
 * The tests see only include/poissondisk.h. The helpers wrap the checks that
 * nearly every test repeats: create a sampler or fail the test, copy all its
 * points, compare two point arrays byte for byte, check the Poisson-disk
 * properties by brute force, and check that a failed call left the sampler
 * exactly as it was. Every assertion message names the situation ("what") so
 * a failure inside a helper still says which call broke.
 */
#ifndef PDS_TESTS_API_HELPERS_H
#define PDS_TESTS_API_HELPERS_H

#include <stddef.h>
#include <stdint.h>

#include <check.h>

#include "poissondisk.h"

/* An axis-aligned closed rectangle [x0,x1]x[y0,y1]. */
typedef struct test_domain {
    double x0, y0, x1, y1;
} test_domain;

/* The default domain of pds_create(). */
extern const test_domain UNIT_SQUARE;

/*
 * True when env PDS_TEST_LIGHT is set (make check-valgrind sets it): heavy
 * loops shrink (fewer seeds, larger radii) so the run under Valgrind stays short.
 */
int test_light(void);

/* pick(native, light): the value for the current mode. */
size_t pick(size_t native, size_t light);

/* A new TCase added to suite, with a timeout that fits the slowest test. */
TCase *new_tcase(Suite *suite, const char *name);

/* pds_create() that must succeed; the domain variant also calls pds_set_domain(). */
pds_sampler *sampler_new(double radius, uint64_t seed);
pds_sampler *sampler_new_in(double radius, uint64_t seed, test_domain d);

/*
 * Two samplers with the same radius, seed and domain (d NULL: the unit square,
 * no pds_set_domain call), each advanced by the same pds_run(s, npoints, ...)
 * (npoints 0: nothing; TO_END: until maximal). One goes through the calls
 * under test, the other stays the reference ("twin").
 */
#define TO_END ((size_t)-1)
void twins_new(double radius, uint64_t seed, const test_domain *d, size_t npoints,
               pds_sampler **a, pds_sampler **b);

/* pds_run(s, 0, ...) that must return 0 (maximal); returns how many were added. */
size_t run_to_end(pds_sampler *s);

/*
 * All points of s, copied into a new malloc'd array of 2*n doubles (never
 * NULL, free() it). Asserts pds_points() copied exactly pds_count(s) points.
 */
double *points_copy(const pds_sampler *s, size_t *n);

/* Byte-for-byte equality of two point arrays (count and every double). */
void assert_points_equal(const double *a, size_t na, const double *b, size_t nb,
                         const char *what);

/* The first nprefix points of s are exactly prefix[0 .. 2*nprefix-1]. */
void assert_prefix_kept(const pds_sampler *s, const double *prefix, size_t nprefix,
                        const char *what);

/* Both samplers hold byte-identical points. */
void assert_same_points(const pds_sampler *a, const pds_sampler *b, const char *what);

/*
 * Runs both samplers to the end and asserts they produce the same points and
 * radius: "a behaves exactly like its twin b" after whatever a went through.
 */
void assert_same_future(pds_sampler *a, pds_sampler *b, const char *what);

/* |got - want| <= tol * |want|. */
void assert_rel_close(double got, double want, double tol, const char *what);

/* Every point lies in the closed rectangle d. */
void assert_inside(const double *xy, size_t n, test_domain d, const char *what);

/* Every pair satisfies dx*dx + dy*dy >= r*r: brute force, O(n^2). */
void assert_min_distance(const double *xy, size_t n, double r, const char *what);

/* The sampler is maximal: free area exactly 0, pds_step 0, pds_verify 0. */
void assert_maximal(pds_sampler *s, const char *what);

/*
 * A call returned rc; it must equal the negative code expected, and when s is
 * not NULL, pds_errmsg(s) must be a non-empty text other than "no error".
 */
void assert_failed(const pds_sampler *s, int rc, int expected, const char *what);

/*
 * The radius and domain cannot be sampled as asked (spec 1.1.1: judged at the
 * first point, or at pds_refine once points exist): pds_run(s, max_new, &added)
 * / pds_step(s) must return PDS_ERANGE with a message, report 0 added, and
 * leave the count, radius and points as they were.
 */
void assert_run_rejected(pds_sampler *s, size_t max_new, const char *what);
void assert_step_rejected(pds_sampler *s, const char *what);

/* What a failed call must not change: count, radius, free area, points. */
typedef struct sampler_snapshot {
    size_t count;
    double radius;
    double free_area;
    double *xy;
} sampler_snapshot;

void snapshot_take(const pds_sampler *s, sampler_snapshot *snap);
void snapshot_check(const pds_sampler *s, const sampler_snapshot *snap, const char *what);
void snapshot_free(sampler_snapshot *snap);

#endif /* PDS_TESTS_API_HELPERS_H */
