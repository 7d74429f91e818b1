/*
 * domain_fixed_count.c - count mode (pds_set_count) around fixed points.
 *
 * Contract (poissondisk.h, pds_set_count and pds_set_fixed, 1.10): the start
 * is the radius at which a maximal pattern of the room the clearances leave
 * (area and outline estimated on a lattice when the first point is placed)
 * holds n points, times 1.015 + 10/n; a clearance of 0 is the radius, so the
 * start is the radius that gives itself. Then, as without fixed points, the
 * radius goes down (as pds_refine, the clearances with it) each time the
 * pattern is maximal with fewer than n, by 0.1% to 1% a step. Clearances
 * that cover the domain leave a maximal pattern with no point: the radius
 * goes down until points fit, or the run stops at the precision limit with
 * PDS_ERANGE and nothing added.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "helpers.h"
#include "suites.h"

/* Count mode lowers the radius, and the clearances with it, until points
 * fit: a clearance of 10^12 still covers the square at the precision limit,
 * so the run stops there, with nothing added and a message that says why. */
START_TEST(count_mode_under_a_clearance_past_the_precision_limit)
{
    const double centre[2] = {0.5, 0.5}, c[1] = {1e12};
    pds_sampler *s = sampler_new(0.1, 3);
    size_t added = 7;

    ck_assert_int_eq(pds_set_count(s, 53), 0);
    ck_assert_int_eq(pds_set_fixed(s, centre, c, 1), 0);
    ck_assert_int_eq(pds_run(s, 0, &added), PDS_ERANGE);
    ck_assert_uint_eq(added, 0);
    ck_assert_uint_eq(pds_count(s), 0);
    ck_assert_ptr_nonnull(strstr(pds_errmsg(s), "clearances covered the domain"));
    pds_destroy(s);
}
END_TEST

/* The radii of a count-mode run of n points around fixed points (clearances
 * c, or NULL: the radius), by the default process (threads 0) or the
 * parallel one: set_count's start (before the first point), the start (set
 * at the first point) and the last radius. The run must end with n points. */
struct count_radii {
    double set_count, start, end;
};

static struct count_radii count_run(const double *xy, const double *c, size_t nf, size_t n, unsigned threads,
                                    uint64_t seed)
{
    pds_sampler *s = sampler_new(0.1, seed);
    struct count_radii r;

    ck_assert_int_eq(pds_set_count(s, n), 0);
    ck_assert_int_eq(pds_set_fixed(s, xy, c, nf), 0);
    if (threads != 0) ck_assert_int_eq(pds_set_threads(s, threads), 0);
    r.set_count = pds_radius(s);
    ck_assert_int_eq(pds_step(s), PDS_MORE);
    r.start = pds_radius(s);
    ck_assert_int_eq(pds_run(s, 0, NULL), PDS_DONE);
    ck_assert_uint_eq(pds_count(s), n);
    r.end = pds_radius(s);
    pds_destroy(s);
    return r;
}

/* Count mode starts from the room the clearances leave: around a disk of
 * 0.3 in the unit square (28% of it) the first maximal pattern holds a
 * little fewer than n points, so the radius is lowered by a step or a few
 * (the pattern maximal at the one before), not by the 15 or more steps of a
 * start from the whole square. Each process (default, parallel), three
 * seeds. */
START_TEST(count_mode_starts_from_the_room_left)
{
    const double centre[2] = {0.5, 0.5}, c[1] = {0.3};
    unsigned threads;
    uint64_t seed;

    for (threads = 0; threads <= 2; threads += 2)
        for (seed = 1; seed <= 3; seed++) {
            const struct count_radii r = count_run(centre, c, 1, 2000, threads, seed);
            ck_assert_msg(r.end < r.start && r.end > 0.96 * r.start,
                          "threads %u seed %llu: the radius went from %.9g to %.9g", threads,
                          (unsigned long long)seed, r.start, r.end);
        }
}
END_TEST

/* Around 1600 fixed points of clearance 0 (the radius) on a lattice 0.025
 * apart, for 400 points: at set_count's start, 0.0446, their disks cover
 * the square. The start is then the radius whose room gives itself, found
 * below it: 0.01556. Before, count mode lowered the radius by 1% a step
 * (93 refines) to the first radius at which a point fits, just under
 * 0.025 / sqrt 2 = 0.0177 (measured 0.01752). Any radius that leaves room
 * leaves over 1500 gaps here, so the run ends at 400 points, not maximal,
 * at its start. */
START_TEST(count_mode_starts_below_radius_clearances_that_cover)
{
    double at[2 * 1600];
    int i;
    unsigned threads;

    for (i = 0; i < 1600; i++) {
        at[2 * i] = 0.0125 + 0.025 * (i % 40);
        at[2 * i + 1] = 0.0125 + 0.025 * (i / 40);
    }
    for (threads = 0; threads <= 2; threads += 2) {
        const struct count_radii r = count_run(at, NULL, 1600, 400, threads, 3);
        ck_assert(r.set_count > 0.025 / sqrt(2.0)); /* their disks cover the square */
        ck_assert_msg(r.start < 0.0165, "threads %u: the start %.9g is not the one the room gives", threads,
                      r.start);
        ck_assert(r.end <= r.start);
    }
}
END_TEST

/* Count mode with a fixed point whose clearance covers the whole domain at
 * the first radius: maximal with no point, so the radius goes down with the
 * clearance until points fit (before, a crash: the stages were dropped).
 * The n-th point ends the run, maximal or not at the last radius (a corner
 * may be left free): pds_verify finds the pattern valid either way. */
START_TEST(count_mode_past_a_covering_clearance)
{
    const double xy[2] = {0.5, 0.5}, c[1] = {1.0};
    size_t n;
    int rc;

    for (n = 1; n <= 5; n += 2) {
        pds_sampler *s = sampler_new(1.0, 4);
        ck_assert_int_eq(pds_set_count(s, n), 0);
        ck_assert_int_eq(pds_set_fixed(s, xy, c, 1), 0);
        run_to_end(s);
        ck_assert_uint_eq(pds_count(s), n);
        rc = pds_verify(s);
        ck_assert_msg(rc == PDS_DONE || rc == PDS_MORE, "n %zu: pds_verify %d: %s", n, rc, pds_errmsg(s));
        pds_destroy(s);
    }
}
END_TEST

Suite *domain_fixed_count_suite(void)
{
    Suite *s = suite_create("domain_fixed_count");
    TCase *tc = new_tcase(s, "the start");
    tcase_add_test(tc, count_mode_starts_from_the_room_left);
    tcase_add_test(tc, count_mode_starts_below_radius_clearances_that_cover);
    tc = new_tcase(s, "covered");
    tcase_add_test(tc, count_mode_past_a_covering_clearance);
    tcase_add_test(tc, count_mode_under_a_clearance_past_the_precision_limit);
    return s;
}
