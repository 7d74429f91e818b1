/*
 * golden.c - the exact bytes a seed gives, pinned.
 *
 * The header promises byte-identical points for the same seed and version
 * with every compiler. These fingerprints (count and a 64-bit FNV-1a hash of
 * the coordinates' bit patterns, taken in an endian-independent way) were
 * recorded with the library as released; any change in arithmetic, in the
 * order of floating-point operations, in the generator or in how the work is
 * split changes them. A deliberate change to the sampler that alters its
 * output must update them, and say so in the release notes: the same seed
 * then gives other points (still with the same law).
 *
 * History: re-pinned for 1.1.0, whose dart stage (src/dart_grid.hpp) draws
 * the opening points from the generator in a different way. Varying fields
 * pinned from 1.3.2 on, whose field dart stage changed their points. The
 * parallel opening (pds_set_threads) pinned from 1.5.0 on: one fingerprint
 * for every thread count; re-pinned for 1.6.0, whose hand-over builds the
 * mesh whole (the same mesh, other edge records, so other later draws), and
 * for 1.7.0, whose dart process goes on after the hand-over in the cells'
 * free regions. Polygons pinned from 1.8.0 on, whose parallel process runs
 * in polygons too (before, their threads gave the default process's points,
 * the first fingerprint below). The torus and fixed points pinned from
 * 1.9.0 on, likewise; fixed points with threads re-pinned for 1.10.0, whose
 * hand-over builds the mesh of the other points whole, then inserts them.
 * Fixed points without threads re-pinned for 1.11.0, whose single-thread
 * process opens with darts kept out of the clearances (before, the Jones
 * loop alone), and pinned in calls of 97 points too. Many fixed points
 * pinned from 1.12.0 on, whose hand-over inserts them along the curve
 * (before, in the caller's order; without threads, more than about the
 * square root of the points ran the Jones loop alone). Fields with threads
 * pinned from 1.13.0 on, whose darts go on in the free regions after the
 * field's dart stage (before, their threads gave the default process's
 * points, the first fingerprint below). Fields on the torus pinned from
 * 1.14.0 on, whose single-thread process opens with the field's dart stage
 * (before, the Jones loop alone) and whose threads carry its darts on in the
 * free regions. The parallel process re-pinned for 1.16.0, whose opening
 * finds the cells that draw darts in an epoch by gaps along each row (before,
 * each active cell drew its own count).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "helpers.h"
#include "region.h"
#include "suites.h"

struct golden {
    double radius;
    uint64_t seed;
    int rectangle;   /* [-1,2] x [3,4.5] instead of the unit square */
    double refine;   /* then refine to this radius and run again; 0: none */
    size_t chunk;    /* run in calls of at most this many points; 0: one call */
    unsigned threads; /* pds_set_threads(s, threads - 1) first; 0: no call */
    size_t count;
    uint64_t hash;
};

static const struct golden cases[] = {
    {0.01, 1, 0, 0.0, 0, 0, 7048, 0x24f25a7990fba47cull},
    {0.01, 1, 0, 0.0, 97, 0, 7048, 0x24f25a7990fba47cull}, /* split: same bytes */
    {0.02, 7, 1, 0.015, 0, 0, 13531, 0x72b45bb3f3220347ull},
    {0.05, 12345678901234567ull, 0, 0.0, 0, 0, 304, 0x06bd299d7a5890dcull},
    /* The parallel opening: other points, the same on 1, 2 and 3 threads. */
    {0.01, 1, 0, 0.0, 0, 2, 7042, 0xe6ecfef1dee01ea7ull},
    {0.01, 1, 0, 0.0, 97, 3, 7042, 0xe6ecfef1dee01ea7ull},
    {0.01, 1, 0, 0.0, 0, 4, 7042, 0xe6ecfef1dee01ea7ull},
    {0.02, 7, 1, 0.015, 0, 3, 13489, 0x29af3e5e4090946full},
    {0.002, 3, 0, 0.0, 0, 3, 174559, 0xa5f2372727fd9747ull},
};

static uint64_t fingerprint(const double *v, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    size_t i;
    int k;
    for (i = 0; i < n; ++i) {
        uint64_t bits;
        memcpy(&bits, &v[i], sizeof bits);
        for (k = 0; k < 64; k += 8) {
            h ^= (bits >> k) & 0xffu;
            h *= 1099511628211ull;
        }
    }
    return h;
}

static void run_all(pds_sampler *s, size_t chunk)
{
    int rc;
    do
        rc = pds_run(s, chunk, NULL);
    while (rc == 1);
    ck_assert_int_eq(rc, 0);
}

/* s's points against a pinned count and fingerprint; destroys s. */
static void assert_pinned(pds_sampler *s, size_t count, uint64_t hash, const char *what, int i)
{
    const size_t n = pds_count(s);
    double *xy = malloc(2 * n * sizeof *xy + 1);

    ck_assert_ptr_nonnull(xy);
    ck_assert_uint_eq(pds_points(s, 0, n, xy), n);
    ck_assert_msg(n == count && fingerprint(xy, 2 * n) == hash,
                  "%s %d: %zu points, fingerprint 0x%016llx; pinned %zu, 0x%016llx", what, i, n,
                  (unsigned long long)fingerprint(xy, 2 * n), count, (unsigned long long)hash);
    free(xy);
    pds_destroy(s);
}

START_TEST(pinned_outputs)
{
    const struct golden *g = &cases[_i];
    pds_sampler *s = NULL;

    ck_assert_int_eq(pds_create(&s, g->radius, g->seed), 0);
    if (g->rectangle)
        ck_assert_int_eq(pds_set_domain(s, -1.0, 3.0, 2.0, 4.5), 0);
    if (g->threads > 0)
        ck_assert_int_eq(pds_set_threads(s, g->threads - 1), 0);
    run_all(s, g->chunk);
    if (g->refine > 0.0) {
        ck_assert_int_eq(pds_refine(s, g->refine), 0);
        run_all(s, g->chunk);
    }
    assert_pinned(s, g->count, g->hash, "case", _i);
}
END_TEST

/* A varying field in a rectangle, and on the torus of the same box: a 4 x 3
 * radius map (1:3, so it opens with the field's dart stage), whole and in
 * calls of 37 points; by the default process and by the parallel one on 1, 2
 * and 3 threads (threads 0: no pds_set_threads). */
struct golden_field {
    int torus;
    unsigned threads;
    size_t chunk;
    size_t count;
    uint64_t hash;
};

static const struct golden_field field_cases[] = {
    {0, 0, 0, 11486, 0xd923e04fabc74ff9ull},
    {0, 0, 37, 11486, 0xd923e04fabc74ff9ull}, /* split: same bytes */
    {0, 1, 0, 11494, 0xe22997052b4d3471ull},
    {0, 2, 0, 11494, 0xe22997052b4d3471ull},
    {0, 3, 37, 11494, 0xe22997052b4d3471ull},
    {1, 0, 0, 11304, 0x8985e608bcbb08d1ull},
    {1, 0, 37, 11304, 0x8985e608bcbb08d1ull}, /* split: same bytes */
    {1, 1, 0, 11337, 0x0f4453bd6a19a355ull},
    {1, 2, 0, 11337, 0x0f4453bd6a19a355ull},
    {1, 3, 37, 11337, 0x0f4453bd6a19a355ull},
};

START_TEST(pinned_field_outputs)
{
    static const double map[12] = {0.01, 0.012, 0.015, 0.02, 0.013, 0.017, 0.022, 0.027, 0.016, 0.021, 0.026, 0.03};
    const struct golden_field *g = &field_cases[_i];
    pds_sampler *s = NULL;

    ck_assert_int_eq(pds_create(&s, 0.03, 5), 0);
    ck_assert_int_eq(pds_set_domain(s, -1.0, 3.0, 2.0, 4.5), 0);
    ck_assert_int_eq(pds_set_radius_map(s, 4, 3, map), 0);
    if (g->torus)
        ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    if (g->threads != 0)
        ck_assert_int_eq(pds_set_threads(s, g->threads), 0);
    run_all(s, g->chunk);
    assert_pinned(s, g->count, g->hash, "field case", _i);
}
END_TEST

/* Domains users have: the unit L with a hole (shapes.c) at R 0.01, seed 3,
 * the torus [0,1.5)x[0,1) at R 0.01, seed 4, and the unit square with three
 * fixed points at R 0.01, seed 5; each by the default process and by the
 * parallel one (pds_set_threads), which is the same on 1, 2 and 3 threads,
 * whole and in calls of 97 points (the default process's too, with fixed
 * points); and 64 scattered fixed points at R 0.01, seed 6 (clearances R
 * and 0.02 in turn). */
enum { THE_L, TORUS, FIXED, MANY_FIXED };
struct golden_domain {
    int kind;
    size_t chunk;
    unsigned threads; /* pds_set_threads(s, threads - 1) first; 0: no call */
    size_t count;
    uint64_t hash;
};

static const struct golden_domain domain_cases[] = {
    {THE_L, 0, 0, 4425, 0x13dfd6af50dd8c00ull},
    {THE_L, 0, 2, 4414, 0x6a093b216918f6ecull},
    {THE_L, 97, 3, 4414, 0x6a093b216918f6ecull},
    {THE_L, 0, 4, 4414, 0x6a093b216918f6ecull},
    {TORUS, 0, 0, 10454, 0x08bf749a26c343acull},
    {TORUS, 0, 2, 10463, 0xc5dbe4a58f5c9e3bull},
    {TORUS, 97, 3, 10463, 0xc5dbe4a58f5c9e3bull},
    {TORUS, 0, 4, 10463, 0xc5dbe4a58f5c9e3bull},
    {FIXED, 0, 0, 6229, 0x1952eaf901c02256ull},
    {FIXED, 97, 0, 6229, 0x1952eaf901c02256ull},
    {FIXED, 0, 2, 6228, 0x728d2c44840205f6ull},
    {FIXED, 97, 3, 6228, 0x728d2c44840205f6ull},
    {FIXED, 0, 4, 6228, 0x728d2c44840205f6ull},
    {MANY_FIXED, 0, 0, 6796, 0xf5585b2ad66df151ull},
    {MANY_FIXED, 97, 0, 6796, 0xf5585b2ad66df151ull},
    {MANY_FIXED, 0, 2, 6822, 0x8c689386d2884e81ull},
    {MANY_FIXED, 97, 3, 6822, 0x8c689386d2884e81ull},
};

START_TEST(pinned_domain_outputs)
{
    const struct golden_domain *g = &domain_cases[_i];
    pds_sampler *s = NULL;

    static const double fixed_xy[6] = {0.3, 0.3, 0.7, 0.6, 0.72, 0.62};
    static const double fixed_c[3] = {0.0, 0.2, 0.01};

    ck_assert_int_eq(pds_create(&s, 0.01, (uint64_t)(3 + g->kind)), 0);
    if (g->kind == TORUS) {
        ck_assert_int_eq(pds_set_domain(s, 0.0, 0.0, 1.5, 1.0), 0);
        ck_assert_int_eq(pds_set_periodic(s, 1), 0);
    } else if (g->kind == FIXED) {
        ck_assert_int_eq(pds_set_fixed(s, fixed_xy, fixed_c, 3), 0);
    } else if (g->kind == MANY_FIXED) {
        double xy[128], c[64];
        int k;
        for (k = 0; k < 64; ++k) {
            /* Scattered: the golden ratio's sequences, in no spatial order. */
            xy[2 * k] = fmod(0.1 + 0.6180339887 * k, 1.0);
            xy[2 * k + 1] = fmod(0.2 + 0.7548776662 * k, 1.0);
            c[k] = k % 2 ? 0.02 : 0.0;
        }
        ck_assert_int_eq(pds_set_fixed(s, xy, c, 64), 0);
    } else {
        ck_assert_int_eq(pds_set_polygon(s, UNIT_L.xy, UNIT_L.ends, UNIT_L.nrings), 0);
    }
    if (g->threads > 0)
        ck_assert_int_eq(pds_set_threads(s, g->threads - 1), 0);
    run_all(s, g->chunk);
    assert_pinned(s, g->count, g->hash, "domain case", _i);
}
END_TEST

Suite *golden_suite(void)
{
    Suite *s = suite_create("golden");
    TCase *tc = tcase_create("pinned outputs");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, pinned_outputs, 0, (int)(sizeof cases / sizeof cases[0]));
    tcase_add_loop_test(tc, pinned_field_outputs, 0, (int)(sizeof field_cases / sizeof field_cases[0]));
    tcase_add_loop_test(tc, pinned_domain_outputs, 0, (int)(sizeof domain_cases / sizeof domain_cases[0]));
    suite_add_tcase(s, tc);
    return s;
}
