/*
 * fuzz_ops.c - the operations of the fuzz harness: each makes one kind of
 * public-API call with decoded arguments and checks the outcome against the
 * contract for that call in that situation (see fuzz_api.c, fuzz.h).
 *
 * Bounded work: an input must run in milliseconds. Oler's bound n on the
 * count at the current radius decides what a call that adds points may do:
 *   - run to the end (pds_run(s, 0), huge max_new, step until 0) only when
 *     n <= FZ_TO_END_MAX and the input's point budget covers it;
 *   - otherwise a few steps or runs bounded by the budget, but only when
 *     n <= FZ_GRID_MAX or n >= FZ_NO_GRID. In between no point is added (the
 *     other calls still happen): the dart stage allocates a zero-filled grid
 *     of about 16 bytes * 2A/R^2 whenever the maximal pattern fits 32-bit
 *     indices (up to ~3.5e8 points, ~10 GB). As untouched virtual memory that
 *     is legitimate, but ASan writes its shadow (1/8 of it, up to 1.2 GB)
 *     when it is freed, on every such input, and libFuzzer's -malloc_limit_mb
 *     would report it. Beyond FZ_NO_GRID the maximal pattern cannot fit: 1.1.1 must
 *     run bounded calls there without such a grid, and refuse unbounded ones
 *     with PDS_ERANGE. So make fuzz's -rss_limit_mb=4096 -malloc_limit_mb=4096
 *     only catch a library that allocates by area where it should not.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

#define FZ_TO_END_MAX 5e3
#define FZ_GRID_MAX 2e6
#define FZ_NO_GRID 4e9
#define FZ_HUGE ((size_t)1 << 31) /* max_new beyond any pattern the library accepts */

enum { WORK_NONE, WORK_BOUNDED, WORK_TO_END };

static int work_allowed(const fz_state *st)
{
    const double n = fz_count_bound(st);
    if (st->s == NULL || st->budget == 0) return WORK_NONE;
    if (n <= FZ_TO_END_MAX && n <= (double)st->budget) return WORK_TO_END;
    if (n <= FZ_GRID_MAX || n >= FZ_NO_GRID) return WORK_BOUNDED;
    return WORK_NONE;
}

static unsigned range_if_111(void) { return FZ_SPEC_111 ? FZ_BIT(PDS_ERANGE) : 0u; }
static unsigned range_unless_111(void) { return FZ_SPEC_111 ? 0u : FZ_BIT(PDS_ERANGE); }

/* The points added by a successful or failed call that adds points. */
static void account(fz_state *st, size_t added)
{
    st->count += added;
    st->budget -= added < st->budget ? added : st->budget;
    if (added > 0) {
        FZ_CHECK(!st->maximal, "%zu points added to a pattern reported maximal", added);
        st->checked = 0;
    }
}

/* pds_run; sync_now reads the points back (O(n): not after every small chunk). */
static int call_run(fz_state *st, size_t max_new, int want_added, int sync_now)
{
    size_t added = (size_t)-7, now;
    const size_t before = st->count;
    const int rc = pds_run(st->s, max_new, want_added ? &added : NULL);
    double want;

    if (st->s == NULL) {
        fz_codes(st, "pds_run", rc, FZ_BIT(PDS_EINVAL));
        FZ_CHECK(!want_added || added == 0, "pds_run(NULL) set added to %zu", added);
        return rc;
    }
    fz_codes(st, "pds_run", rc, FZ_OK | FZ_MORE | FZ_BIT(PDS_ENOMEM) | range_if_111());
    now = pds_count(st->s);
    FZ_CHECK(now >= before, "pds_run: the count fell from %zu to %zu", before, now);
    if (want_added)
        FZ_CHECK(added == now - before, "pds_run returned %d, added %zu, count grew by %zu", rc,
                 added, now - before);
    added = now - before;
    /* Only PDS_ENOMEM in the exact fallback may keep the points added before it. */
    FZ_CHECK(rc >= 0 || rc == PDS_ENOMEM || added == 0, "pds_run failed (%d) and added %zu",
             rc, added);
    FZ_CHECK(rc != 1 || (max_new != 0 && added == max_new),
             "pds_run(max_new %zu) returned 1 after adding %zu", max_new, added);
    FZ_CHECK(rc != 0 || max_new == 0 || added <= max_new, "pds_run(max_new %zu) added %zu",
             max_new, added);
    FZ_CHECK(!st->maximal || rc == 0, "pds_run returned %d on a maximal pattern", rc);
    /* 1.1.1: PDS_ERANGE only for precision or when the points asked for (capped
     * by the bound) cannot fit ~3.5e8 indices; and then it must come. */
    want = fz_count_bound(st);
    if (max_new != 0 && (double)before + (double)max_new < want)
        want = (double)before + (double)max_new;
    if (FZ_SPEC_111 && rc == PDS_ERANGE)
        FZ_CHECK(!fz_precision_ok(st, st->radius) || want >= 3e8,
                 "pds_run(max_new %zu) returned PDS_ERANGE for %.3g points at R %.17g: %s",
                 max_new, want, st->radius, pds_errmsg(st->s));
    if (FZ_SPEC_111 && want >= 1e9)
        FZ_CHECK(rc == PDS_ERANGE, "pds_run(max_new %zu) returned %d for %.3g points", max_new,
                 rc, want);
    account(st, added);
    if (rc == 0) st->maximal = 1;
    if (sync_now || rc == 0) fz_sync(st);
    if (rc == 0) fz_check_maximal(st);
    return rc;
}

static int call_step(fz_state *st, int sync_now)
{
    const int rc = pds_step(st->s);
    if (st->s == NULL) {
        fz_codes(st, "pds_step", rc, FZ_BIT(PDS_EINVAL));
        return rc;
    }
    fz_codes(st, "pds_step", rc, FZ_OK | FZ_MORE | FZ_BIT(PDS_ENOMEM) | range_if_111());
    if (FZ_SPEC_111 && rc == PDS_ERANGE)
        FZ_CHECK(!fz_precision_ok(st, st->radius), "pds_step: PDS_ERANGE at R %.17g: %s",
                 st->radius, pds_errmsg(st->s));
    FZ_CHECK(rc != 0 || st->count > 0, "pds_step: maximal without a point");
    account(st, rc == 1 ? 1 : 0);
    FZ_CHECK(pds_count(st->s) == st->count, "pds_step returned %d, count %zu, expected %zu", rc,
             pds_count(st->s), st->count);
    if (rc == 0) st->maximal = 1;
    if (sync_now || rc == 0) fz_sync(st);
    if (rc == 0) fz_check_maximal(st);
    return rc;
}

void fz_op_create(fz_state *st, fz_reader *r, unsigned arg)
{
    static const double unit[4] = {0.0, 0.0, 1.0, 1.0};
    static int not_a_sampler;
    const double radius = fz_radius(r, unit);
    const uint64_t seed = (arg & 1) ? fz_u64(r) : fz_u8(r);
    pds_sampler *s = (pds_sampler *)(void *)&not_a_sampler; /* must become NULL on failure */
    const int valid = isfinite(radius) && radius > 0.0;
    int rc;

    pds_destroy(st->s);
    fz_reset(st, NULL, 1.0);
    rc = pds_create(&s, radius, seed);
    fz_codes(st, "pds_create", rc,
             valid ? FZ_OK | FZ_BIT(PDS_ENOMEM) | range_unless_111() : FZ_BIT(PDS_EINVAL));
    FZ_CHECK(rc == 0 ? s != NULL : s == NULL, "pds_create returned %d and *out %p", rc,
             (void *)s);
    fz_reset(st, s, rc == 0 ? radius : 1.0);
    fz_sync(st);
}

void fz_op_domain(fz_state *st, fz_reader *r)
{
    double d[4];
    int valid, rc;
    unsigned allowed;

    fz_domain(r, st->s ? st->radius : 1.0, d);
    rc = pds_set_domain(st->s, d[0], d[1], d[2], d[3]);
    valid = isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && isfinite(d[3]) &&
            d[0] < d[2] && d[1] < d[3];
    if (st->s == NULL)
        allowed = FZ_BIT(PDS_EINVAL);
    else if (!valid) /* either check may come first once points exist */
        allowed = FZ_BIT(PDS_EINVAL) | (st->count > 0 ? FZ_BIT(PDS_ESTATE) : 0u);
    else if (st->count > 0)
        allowed = FZ_BIT(PDS_ESTATE);
    else
        allowed = FZ_OK | FZ_BIT(PDS_ENOMEM) | range_unless_111();
    fz_codes(st, "pds_set_domain", rc, allowed);
    if (rc == 0) memcpy(st->dom, d, sizeof d);
    fz_sync(st);
}

void fz_op_refine(fz_state *st, fz_reader *r)
{
    const double old = st->radius;
    const double nr = fz_refine_radius(r, st->s ? old : 1.0, st->dom);
    const int rc = pds_refine(st->s, nr);
    unsigned allowed;

    if (st->s == NULL)
        allowed = FZ_BIT(PDS_EINVAL);
    else if (!isfinite(nr) || !(nr > 0.0) || nr > old)
        allowed = FZ_BIT(PDS_EINVAL);
    else if (nr == old)
        allowed = FZ_OK; /* a no-op */
    else
        allowed = FZ_OK | FZ_BIT(PDS_ENOMEM) | FZ_BIT(PDS_ERANGE);
    fz_codes(st, "pds_refine", rc, allowed);
    if (st->s == NULL) return;
    /* 1.1.1: judged only once points exist, and then only for precision. */
    if (FZ_SPEC_111 && rc == PDS_ERANGE)
        FZ_CHECK(st->count > 0 && !fz_precision_ok(st, nr), "pds_refine(%.17g) with %zu "
                 "points: PDS_ERANGE: %s", nr, st->count, pds_errmsg(st->s));
    if (rc == 0 && nr < old) {
        st->radius = nr;
        st->maximal = st->checked = 0;
    }
    fz_sync(st);
}

void fz_op_step(fz_state *st, unsigned arg)
{
    const int w = work_allowed(st);
    size_t k = arg + 1u, i;

    if (st->s != NULL && !st->maximal && w == WORK_NONE) return;
    if (w == WORK_TO_END && arg == 15) {
        while (call_step(st, 0) == 1) {}
        fz_sync(st);
        return;
    }
    if (w == WORK_BOUNDED && k > st->budget) k = st->budget;
    for (i = 0; i < k; i++)
        if (call_step(st, 1) != 1) break;
}

void fz_op_run(fz_state *st, fz_reader *r, unsigned arg)
{
    size_t m = fz_max_new(r);
    const int w = work_allowed(st);
    const int huge = m == 0 || m >= FZ_HUGE;

    if (st->s == NULL || st->maximal || w == WORK_TO_END)
        call_run(st, m, arg & 1, 1);
    else if (huge && fz_count_bound(st) >= FZ_NO_GRID)
        call_run(st, m, arg & 1, 1); /* must fail at once (PDS_ERANGE) */
    else if (w == WORK_BOUNDED)
        call_run(st, huge || m > st->budget ? st->budget : m, arg & 1, 1);
}

/* Small chunks to the end (when affordable): the splits of the determinism contract. */
void fz_op_run_chunks(fz_state *st, unsigned arg)
{
    static const size_t chunk[8] = {1, 1, 2, 7, 7, 64, 1000, 3};
    const size_t k = chunk[arg % 8];
    const int w = work_allowed(st);
    int i;

    if (w == WORK_TO_END) {
        while (call_run(st, k, arg & 8, 0) == 1) {}
    } else if (w == WORK_BOUNDED) {
        for (i = 0; i < 4 && st->budget >= k; i++)
            if (call_run(st, k, arg & 8, 0) != 1) break;
    }
    fz_sync(st);
}

void fz_op_run_to_end(fz_state *st, unsigned arg)
{
    const int w = work_allowed(st);
    if (st->s == NULL || st->maximal || w == WORK_TO_END || fz_count_bound(st) >= FZ_NO_GRID)
        call_run(st, 0, arg & 1, 1);
    else if (w == WORK_BOUNDED)
        call_run(st, st->budget, arg & 1, 1);
}

void fz_op_points(fz_state *st, fz_reader *r, unsigned arg)
{
    const size_t n = st->count;
    const size_t first = fz_size(r, n), count = fz_size(r, n);
    const pds_sampler *s = (arg & 1) ? NULL : st->s;
    const int null_buf = (arg & 2) != 0;
    size_t expect = 0, got;
    double *xy = NULL;

    if (s != NULL && !null_buf && first < n) expect = count < n - first ? count : n - first;
    /* Exactly the size the clipped range needs: ASan sees any write past it. */
    if (!null_buf) {
        xy = malloc(expect ? 2 * expect * sizeof(double) : 1);
        FZ_CHECK(xy != NULL, "harness out of memory");
    }
    got = pds_points(s, first, count, xy);
    FZ_CHECK(got == expect, "pds_points(%s, %zu, %zu, %s) with %zu points copied %zu, expected "
             "%zu", s ? "s" : "NULL", first, count, xy ? "xy" : "NULL", n, got, expect);
    if (expect > 0)
        FZ_CHECK(memcmp(xy, st->pts + 2 * first, 2 * expect * sizeof(double)) == 0,
                 "pds_points(%zu, %zu) differs from the points read before", first, count);
    free(xy);
}

void fz_op_verify(fz_state *st)
{
    const int rc = pds_verify(st->s);
    if (st->s == NULL) {
        fz_codes(st, "pds_verify", rc, FZ_BIT(PDS_EINVAL));
        return;
    }
    fz_codes(st, "pds_verify", rc, FZ_OK | FZ_MORE | FZ_BIT(PDS_ENOMEM));
    FZ_CHECK(rc != 1 || !st->maximal, "pds_verify: room left in a pattern reported maximal");
    fz_sync(st);
    if (rc == 0) {
        FZ_CHECK(st->count > 0, "pds_verify: maximal without a point");
        st->maximal = 1;
        fz_check_maximal(st);
    }
}

void fz_op_nulls(fz_state *st)
{
    double xy[2];
    size_t added = 5;
    FZ_CHECK(pds_count(NULL) == 0, "pds_count(NULL)");
    FZ_CHECK(isnan(pds_radius(NULL)), "pds_radius(NULL) not NaN");
    FZ_CHECK(pds_points(NULL, 0, 1, xy) == 0, "pds_points(NULL)");
    FZ_CHECK(pds_step(NULL) == PDS_EINVAL, "pds_step(NULL)");
    FZ_CHECK(pds_run(NULL, 3, &added) == PDS_EINVAL && added == 0, "pds_run(NULL)");
    FZ_CHECK(pds_refine(NULL, 0.5) == PDS_EINVAL, "pds_refine(NULL)");
    FZ_CHECK(pds_set_domain(NULL, 0, 0, 1, 1) == PDS_EINVAL, "pds_set_domain(NULL)");
    FZ_CHECK(pds_verify(NULL) == PDS_EINVAL, "pds_verify(NULL)");
    FZ_CHECK(pds_create(NULL, 0.1, 1) == PDS_EINVAL, "pds_create(NULL)");
    FZ_CHECK(pds_errmsg(NULL) != NULL && pds_errmsg(NULL)[0] != '\0', "pds_errmsg(NULL)");
    pds_destroy(NULL);
    fz_check_free_area(st);
}

void fz_op_strerror(fz_state *st, fz_reader *r)
{
    const int code = (int)(uint32_t)fz_u64(r);
    const char *t = pds_strerror(code);
    int c;
    FZ_CHECK(t != NULL && t[0] != '\0', "pds_strerror(%d) is empty", code);
    for (c = -7; c <= 3; c++) {
        t = pds_strerror(c);
        FZ_CHECK(t != NULL && t[0] != '\0', "pds_strerror(%d) is empty", c);
    }
    if (st->s != NULL) fz_codes(st, "pds_errmsg", 0, FZ_OK); /* reading it changes nothing */
}

void fz_op_version(void)
{
    char want[32];
    snprintf(want, sizeof want, "%u.%u.%u", (unsigned)PDS_VERSION_MAJOR,
             (unsigned)PDS_VERSION_MINOR, (unsigned)PDS_VERSION_PATCH);
    FZ_CHECK(pds_version_number() == PDS_VERSION_NUMBER, "pds_version_number %u",
             pds_version_number());
    FZ_CHECK(strcmp(pds_version_string(), want) == 0, "pds_version_string %s",
             pds_version_string());
}

void fz_op_create_bad(fz_state *st, fz_reader *r)
{
    static int not_a_sampler;
    pds_sampler *t = (pds_sampler *)(void *)&not_a_sampler;
    const double radius = fz_hostile(r);
    const int rc = pds_create(&t, radius, fz_u8(r));
    const int valid = isfinite(radius) && radius > 0.0;
    fz_state none;
    memset(&none, 0, sizeof none);
    fz_codes(&none, "pds_create", rc,
             valid ? FZ_OK | FZ_BIT(PDS_ENOMEM) | range_unless_111() : FZ_BIT(PDS_EINVAL));
    FZ_CHECK(rc == 0 ? t != NULL : t == NULL, "pds_create returned %d and *out %p", rc,
             (void *)t);
    pds_destroy(t);
    FZ_CHECK(pds_create(NULL, radius, 1) == PDS_EINVAL, "pds_create(NULL, %g)", radius);
    (void)st;
}
