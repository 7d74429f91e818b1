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
 * With a radius field (1.3) n is the bound at the field's smallest radius,
 * which is what the library reserves by, so a field with a tiny rmin is held
 * to bounded calls as a tiny radius is. Since 1.3.2 a varying field with
 * rmax <= 16 rmin (8 before 1.15; on a torus since 1.14) opens with a dart
 * stage whose layered grids are sized by rmin (fz_field_has_darts), so it is
 * held out of that band as a constant radius is; other varying fields (wider
 * ones) run the Jones loop from the first point and get bounded calls between
 * FZ_GRID_MAX and FZ_NO_GRID too: there nothing may be allocated by area.
 * Two more limits: with the parallel opening selected (1.5), whose first
 * point costs an epoch over every cell, bounded calls stop at FZ_GRID_MAX / 10;
 * a domain far thinner than R costs milliseconds a point (fz_cap_thin_budget).
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

/* A rectangle (or a shape's box) whose shorter side is below 2^-12 R (in
 * count mode: of its longer side) costs the library milliseconds a point
 * under ASan: its cells' coverage is decided exactly (the float filters
 * cannot resolve the height; found/NOTES, thin_domain_slow). Such an input
 * may add a sixteenth of the points. */
void fz_cap_thin_budget(fz_state *st)
{
    const double w = st->dom[2] - st->dom[0], h = st->dom[3] - st->dom[1];
    const double shorter = w < h ? w : h, longer = w < h ? h : w;
    const double r = st->target != 0 ? longer : st->radius;
    if (st->s != NULL && shorter < 0x1p-12 * r && st->budget > FZ_BUDGET / 16) st->budget = FZ_BUDGET / 16;
}

static int work_allowed(const fz_state *st)
{
    const double n = fz_count_bound(st);
    double lo, hi;
    if (st->s == NULL || st->budget == 0) return WORK_NONE;
    /* found/NOTES: polygon_antenna_hang, mask_fine_pixels_verify */
    if ((st->shape.antenna || st->shape.fine) && !fz_strict()) return WORK_NONE;
    /* found/NOTES, thin_domain_slow: count mode with fixed points lowers the
     * radius in hundreds of steps, each measuring every cell exactly. */
    if (st->target != 0 && st->nfix > 0 && !fz_strict()) {
        const double w = st->dom[2] - st->dom[0], h = st->dom[3] - st->dom[1];
        if ((w < h ? w : h) < 0x1p-12 * (w < h ? h : w)) return WORK_NONE;
    }
    fz_lib_bound(st, &lo, &hi);
    /* Count mode ends at n points; the dart stage's grid still follows the bound. */
    if (st->target != 0 && (double)st->target <= FZ_TO_END_MAX &&
        st->target - st->count <= st->budget)
        return WORK_TO_END;
    if (st->target == 0 && n <= FZ_TO_END_MAX && n <= (double)st->budget) return WORK_TO_END;
    /* (A polygon's dart grid covers its box: n; the library's own bound, lo,
     * decides whether there is one.) */
    /* The parallel opening's first point costs an epoch over every cell
     * (a quarter second natively at 1.4e6): bounded calls only up to a tenth. */
    if (st->parallel && n > FZ_GRID_MAX / 10 && lo < FZ_NO_GRID) return WORK_NONE;
    if (n <= FZ_GRID_MAX || lo >= FZ_NO_GRID || (fz_varying_field(st) && !fz_field_has_darts(st)))
        return WORK_BOUNDED;
    return WORK_NONE;
}


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

/* The lowest radius the run may reach: in count mode the library lowers the
 * radius only while a maximal pattern holds m < n points, whose disks cover the
 * area A, so it stays above 0.99 sqrt(A / (pi n)); it judges 0.98 of that at
 * the first point (found/NOTES, count_below_precision). */
static double lowest_radius(const fz_state *st)
{
    double area, low;
    if (st->target == 0) return fz_smallest_radius(st); /* a field's rmin, scaled */
    /* Around fixed points the start comes from the room they leave (1.10),
     * and their disks cover part of A: no bound (lenient). */
    if (st->nfix > 0) return NAN;
    /* sqrt(w) sqrt(h), not sqrt(w h): the area of a domain 1e-204 wide
     * underflows, the library's (in its scaled frame) does not; and the
     * halves' sides, as a side from -DBL_MAX to DBL_MAX overflows. */
    area = 2.0 * sqrt(0.5 * st->dom[2] - 0.5 * st->dom[0]) * sqrt(0.5 * st->dom[3] - 0.5 * st->dom[1]);
    if (st->shape.kind != FZ_SHAPE_NONE) /* NaN (lenient) when the library's area is not known */
        area = st->shape.area_known && fz_shape_scalable(st) ? area * sqrt(st->shape.frac) : NAN;
    low = 0.98 * area / sqrt(3.14159265358979323846 * (double)st->target);
    if (isnan(low)) return low; /* lenient: fz_precision_ok(NaN) is false */
    return low < st->radius ? low : st->radius;
}

/* The radius is below 2^-27 of the domain's largest |coordinate|: below the
 * precision limit 2^-26 of it whatever the binade (the library's limit is
 * 2^-26 times the power of two below that coordinate). */
static int below_precision(const fz_state *st, double radius)
{
    double m = 0.0;
    int i;
    for (i = 0; i < 4; i++)
        if (fabs(st->dom[i]) > m) m = fabs(st->dom[i]);
    return radius < 0x1p-27 * m * (1.0 - 1e-9);
}

/* PDS_ERANGE from pds_step or pds_run (nothing added): allowed when the precision
 * limit is near the lowest radius of the run, when `want` points might not fit
 * the index space, or on the torus above half the shorter period or with a
 * longer side above 1024 times the shorter; required there at the first point,
 * and when the lowest radius (a field's rmin) is well below the precision limit. */
static void check_range(fz_state *st, const char *fn, int rc, double want, size_t before)
{
    /* Count mode lowers the radius while fixed points' clearances (they scale
     * with it) keep the pattern under n: a clearance of 1e8 domains reaches
     * the precision limit first (fuzz_fixed.c). */
    const int may = !fz_precision_ok(st, lowest_radius(st)) || want >= 3e8 ||
                    fz_above_half_period(st, st->radius, -1e-9) || fz_periods_too_unequal(st, -1e-9) ||
                    (st->target != 0 && st->nfix > 0);
    if (!FZ_SPEC_111) return;
    if (rc == PDS_ERANGE)
        FZ_CHECK(may, "%s returned PDS_ERANGE for %.3g points at R %.17g%s: %s", fn, want,
                 st->radius, st->periodic ? " on the torus" : "", pds_errmsg(st->s));
    if (before == 0 && fz_above_half_period(st, st->radius, 1e-9))
        FZ_CHECK(rc == PDS_ERANGE, "%s returned %d at R %.17g, above half the shorter period "
                 "of the torus [%.17g,%.17g)x[%.17g,%.17g)", fn, rc, st->radius, st->dom[0],
                 st->dom[2], st->dom[1], st->dom[3]);
    if (before == 0 && below_precision(st, lowest_radius(st)))
        FZ_CHECK(rc == PDS_ERANGE, "%s returned %d at the first point with the lowest radius "
                 "%.17g (R %.17g%s) below 2^-27 of the domain [%.17g,%.17g]x[%.17g,%.17g]", fn,
                 rc, lowest_radius(st), st->radius, st->field ? ", a field" : "", st->dom[0],
                 st->dom[2], st->dom[1], st->dom[3]);
    if (before == 0 && fz_periods_too_unequal(st, 1e-9))
        FZ_CHECK(rc == PDS_ERANGE, "%s returned %d on the torus [%.17g,%.17g)x[%.17g,%.17g), "
                 "whose longer side is above 1024 times the shorter", fn, rc, st->dom[0],
                 st->dom[2], st->dom[1], st->dom[3]);
}

/* Count mode: the radius may have been lowered; it never grows. */
static void reread_radius(fz_state *st, const char *fn)
{
    const double r = pds_radius(st->s);
    if (st->target == 0) return;
    FZ_CHECK(r <= st->radius, "%s: the radius went from %.17g to %.17g", fn, st->radius, r);
    st->radius = r;
}

/* After pds_run or pds_step with a radius function: PDS_EINVAL only after it
 * returned a bad value, with the library's message saying so; while it returns
 * one everywhere, nothing is added (the first point's limits and running out of
 * memory may still come first, and a maximal pattern needs no value). */
static void check_field_failure(fz_state *st, const char *fn, int rc, int fails,
                                size_t bad_before, size_t added)
{
    if (rc == PDS_EINVAL) {
        if (st->count == 0) st->refused_first = 1; /* st->count: before the call */
        FZ_CHECK(st->fns[st->fn_active].bad_calls > bad_before, "%s returned PDS_EINVAL, but "
                 "the radius function returned no bad value: %s", fn, pds_errmsg(st->s));
        FZ_CHECK(strstr(pds_errmsg(st->s), "radius function") != NULL, "%s: PDS_EINVAL for a "
                 "bad radius value says \"%s\"", fn, pds_errmsg(st->s));
    }
    if (fails)
        FZ_CHECK(added == 0 && (rc == PDS_EINVAL || rc == PDS_ERANGE || rc == PDS_ENOMEM ||
                                (rc == PDS_DONE && (st->count > 0 || st->nfix > 0))),
                 "%s returned %d and added %zu while the radius function returns %.17g "
                 "everywhere (bounds [%.17g, %.17g]): %s", fn, rc, added,
                 st->fns[st->fn_active].bad, st->f_rmin, st->f_rmax, pds_errmsg(st->s));
}

/* pds_run; sync_now reads the points back (O(n): not after every small chunk). */
static int call_run(fz_state *st, size_t max_new, int want_added, int sync_now)
{
    size_t added = (size_t)-7, now;
    const size_t before = st->count;
    /* A radius function that may return a bad value: PDS_EINVAL (fuzz_field.c). */
    const int may_fail = fz_field_may_fail(st), fails = fz_field_fails_everywhere(st);
    const size_t bad_before = st->fns[st->fn_active].bad_calls;
    const int outside = fz_fixed_outside(st); /* a fixed point outside the box: EINVAL (1.4) */
    int rc;
    unsigned cancel;
    double want, want_lo, lo, hi;

    fz_fixed_run_starts(st);
    rc = fz_run(st, max_new, want_added ? &added : NULL);
    cancel = st->prog.on ? FZ_BIT(PDS_ECANCELED) : 0u;

    if (st->s == NULL) {
        fz_codes(st, "pds_run", rc, FZ_BIT(PDS_EINVAL));
        FZ_CHECK(!want_added || added == 0, "pds_run(NULL) set added to %zu", added);
        return rc;
    }
    fz_codes(st, "pds_run", rc, FZ_OK | FZ_MORE | FZ_BIT(PDS_ENOMEM) | fz_range_if_111() |
             cancel | (may_fail || outside ? FZ_BIT(PDS_EINVAL) : 0u));
    now = pds_count(st->s);
    if (!fz_fixed_refused(st, "pds_run", rc, outside, now - before))
        check_field_failure(st, "pds_run", rc, fails, bad_before, now - before);
    FZ_CHECK(now >= before, "pds_run: the count fell from %zu to %zu", before, now);
    if (want_added)
        FZ_CHECK(added == now - before, "pds_run returned %d, added %zu, count grew by %zu", rc,
                 added, now - before);
    added = now - before;
    /* Only PDS_ENOMEM in the exact fallback and a cancel keep the points added before. */
    FZ_CHECK(rc >= 0 || rc == PDS_ENOMEM || rc == PDS_ECANCELED || rc == PDS_EINVAL ||
             added == 0, "pds_run failed (%d: %s) and added %zu", rc, pds_errmsg(st->s), added);
    FZ_CHECK(rc != 1 || (max_new != 0 && added == max_new),
             "pds_run(max_new %zu) returned 1 after adding %zu", max_new, added);
    FZ_CHECK(rc > 0 || max_new == 0 || added <= max_new, "pds_run(max_new %zu) added %zu",
             max_new, added);
    FZ_CHECK(!st->maximal || rc == 0,
             "pds_run(max_new %zu) returned %d on a %s pattern: %s", max_new, rc,
             st->target ? "complete" : "maximal", pds_errmsg(st->s));
    /* Count mode: PDS_DONE exactly when the n-th point exists. */
    if (st->target != 0 && (rc == 0 || rc == 1))
        FZ_CHECK((rc == 0) == (now == st->target), "count mode: pds_run returned %d at %zu of "
                 "%zu points", rc, now, st->target);
    /* 1.1.1: PDS_ERANGE only for precision or when the points asked for (capped
     * by the bound; in count mode by n) cannot fit ~3.5e8 indices; and then it
     * must come. */
    /* A polygon: the library's bound lies between lo and hi (fz_lib_bound). */
    fz_lib_bound(st, &lo, &hi);
    want = st->target != 0 ? (double)st->target : hi;
    want_lo = st->target != 0 ? (double)st->target : lo;
    if (max_new != 0 && (double)before + (double)max_new < want)
        want = (double)before + (double)max_new;
    if (max_new != 0 && (double)before + (double)max_new < want_lo)
        want_lo = (double)before + (double)max_new;
    check_range(st, "pds_run", rc, want, before);
    /* (A field may make the pattern maximal far below its bound: PDS_DONE, checked
     * by fz_check_maximal.) */
    /* (A varying field judges the bound at rmin at the first point only.) */
    if (FZ_SPEC_111 && want_lo >= 1e9 && !st->maximal && !fz_varying_field(st))
        FZ_CHECK(rc == PDS_ERANGE, "pds_run(max_new %zu) returned %d for %.3g points", max_new, rc, want);
    if (before + added > 0 && (rc == PDS_ENOMEM || rc == PDS_ERANGE)) st->run_failed = 1;
    reread_radius(st, "pds_run");
    account(st, added);
    /* (Fixed points' clearances may cover the domain.) */
    FZ_CHECK(rc != 0 || st->count > 0 || st->nfix > 0, "pds_run(max_new %zu): maximal without a point",
             max_new);
    if (rc == 0) st->maximal = 1;
    if (sync_now || rc == 0) fz_sync(st);
    if (rc == 0) fz_check_maximal(st);
    return rc;
}

static int call_step(fz_state *st, int sync_now)
{
    const int may_fail = fz_field_may_fail(st), fails = fz_field_fails_everywhere(st);
    const size_t bad_before = st->fns[st->fn_active].bad_calls;
    const int outside = fz_fixed_outside(st);
    int rc;
    fz_fixed_run_starts(st);
    rc = pds_step(st->s);
    if (st->s == NULL) {
        fz_codes(st, "pds_step", rc, FZ_BIT(PDS_EINVAL));
        return rc;
    }
    fz_codes(st, "pds_step", rc, FZ_OK | FZ_MORE | FZ_BIT(PDS_ENOMEM) | fz_range_if_111() |
             (may_fail || outside ? FZ_BIT(PDS_EINVAL) : 0u));
    if (!fz_fixed_refused(st, "pds_step", rc, outside, rc == 1 ? 1 : 0))
        check_field_failure(st, "pds_step", rc, fails, bad_before, rc == 1 ? 1 : 0);
    check_range(st, "pds_step", rc, (double)st->count + 1.0, st->count);
    FZ_CHECK(rc != 0 || st->count > 0 || st->nfix > 0, "pds_step: maximal without a point");
    if (st->target != 0 && (rc == 0 || rc == 1))
        FZ_CHECK((rc == 0) == (st->count == st->target), "count mode: pds_step returned %d at "
                 "%zu of %zu points", rc, st->count, st->target);
    if (st->count > 0 && (rc == PDS_ENOMEM || rc == PDS_ERANGE)) st->run_failed = 1;
    reread_radius(st, "pds_step");
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

    fz_replay_check(st);
    pds_destroy(st->s);
    fz_reset(st, NULL, 1.0);
    rc = pds_create(&s, radius, seed);
    fz_codes(st, "pds_create", rc,
             valid ? FZ_OK | FZ_BIT(PDS_ENOMEM) | fz_range_unless_111() : FZ_BIT(PDS_EINVAL));
    FZ_CHECK(rc == 0 ? s != NULL : s == NULL, "pds_create returned %d and *out %p", rc,
             (void *)s);
    fz_reset(st, s, rc == 0 ? radius : 1.0);
    st->c_seed = seed;
    fz_sync(st);
}

void fz_op_domain(fz_state *st, fz_reader *r)
{
    double d[4];
    int valid, rc;
    unsigned allowed;

    fz_domain(r, st->s ? st->radius : 1.0, d);
    /* A mask's outline over a rectangle of extreme aspect: the library's index
     * would take gigabytes (found/NOTES). */
    if (st->s != NULL && st->count == 0 && st->shape.kind == FZ_SHAPE_MASK && d[0] < d[2] &&
        d[1] < d[3] && fz_index_too_tall(d, 8.0))
        return;
    rc = pds_set_domain(st->s, d[0], d[1], d[2], d[3]);
    valid = isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && isfinite(d[3]) &&
            d[0] < d[2] && d[1] < d[3];
    if (st->s == NULL)
        allowed = FZ_BIT(PDS_EINVAL);
    else if (!valid) /* either check may come first once points exist */
        allowed = FZ_BIT(PDS_EINVAL) | (st->count > 0 ? FZ_BIT(PDS_ESTATE) : 0u);
    else if (st->count > 0)
        allowed = FZ_BIT(PDS_ESTATE);
    else /* a mask spread over it may degenerate: the header allows EINVAL then */
        allowed = FZ_OK | FZ_BIT(PDS_ENOMEM) | fz_range_unless_111() |
                  (fz_domain_may_refuse(st, d) || st->shape.kind == FZ_SHAPE_MASK ? FZ_BIT(PDS_EINVAL) : 0u);
    fz_codes(st, "pds_set_domain", rc, allowed);
    /* The domain (or a mask's rectangle) in force; the radius function sees
     * it (fuzz_field.c); count mode's start radius follows it (fuzz_domains.c). */
    if (rc == 0) fz_domain_set(st, d);
    /* A refusal changes nothing: the mask keeps its rectangle. */
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
    else if (!isfinite(nr) || !(nr > 0.0) || nr > old) /* count mode: either check first */
        allowed = FZ_BIT(PDS_EINVAL) | (st->target ? FZ_BIT(PDS_ESTATE) : 0u);
    else if (st->target != 0)
        allowed = FZ_BIT(PDS_ESTATE); /* the sampler chooses the radius */
    else if (nr == old)
        allowed = FZ_OK; /* a no-op */
    else
        allowed = FZ_OK | FZ_BIT(PDS_ENOMEM) | FZ_BIT(PDS_ERANGE);
    fz_codes(st, "pds_refine", rc, allowed);
    if (st->s == NULL) return;
    /* 1.1.1: judged only once points exist, and then only for precision. */
    if (FZ_SPEC_111 && rc == PDS_ERANGE) { /* a field: its smallest radius, scaled */
        const double low = fz_varying_field(st) ? st->f_rmin / st->f_rmax * nr : nr;
        FZ_CHECK(st->count > 0 && !fz_precision_ok(st, low * (1.0 - 1e-9)), "pds_refine(%.17g) "
                 "with %zu points (lowest radius %.17g): PDS_ERANGE: %s", nr, st->count, low,
                 pds_errmsg(st->s));
    }
    if (rc == 0 && nr < old) {
        fz_changed_before_first(st);
        st->radius = nr;
        st->maximal = st->checked = 0;
        if (st->n_ev < FZ_MAX_EVENTS) {
            st->ev[st->n_ev].count = st->count;
            st->ev[st->n_ev].radius = nr;
        }
        if (st->n_ev <= FZ_MAX_EVENTS) st->n_ev++;
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

/* An unbounded run must fail at once (PDS_ERANGE): the pattern cannot fit.
 * (A varying field: bounded runs, which are judged alike at every point.) */
static int unbounded_fails(const fz_state *st)
{
    double lo, hi;
    if (st->target == 0 && fz_varying_field(st)) return 0;
    fz_lib_bound(st, &lo, &hi);
    return st->target != 0 ? (double)st->target >= 1e9 : lo >= FZ_NO_GRID;
}

void fz_op_run(fz_state *st, fz_reader *r, unsigned arg)
{
    size_t m = fz_max_new(r);
    const int w = work_allowed(st);
    const int huge = m == 0 || m >= FZ_HUGE;

    if (st->s == NULL || st->maximal || w == WORK_TO_END)
        call_run(st, m, arg & 1, 1);
    else if (huge && unbounded_fails(st))
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

/* arg & 2: after PDS_ECANCELED, run again (resume) until the end. */
void fz_op_run_to_end(fz_state *st, unsigned arg)
{
    int tries = 0, rc;
    do {
        const int w = work_allowed(st);
        if (st->s == NULL || st->maximal || w == WORK_TO_END || unbounded_fails(st))
            rc = call_run(st, 0, arg & 1, 1);
        else if (w == WORK_BOUNDED)
            rc = call_run(st, st->budget, arg & 1, 1);
        else
            return;
    } while (rc == PDS_ECANCELED && (arg & 2) && ++tries < 300);
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
    /* Count mode: complete is not maximal, and maximal (between two radii) not complete. */
    FZ_CHECK(rc != 1 || !st->maximal || st->target != 0,
             "pds_verify: room left in a pattern reported maximal");
    fz_sync(st);
    if (rc == 0) {
        FZ_CHECK(st->count > 0 || st->nfix > 0, "pds_verify: maximal without a point");
        if (st->target == 0 || st->count == st->target) {
            st->maximal = 1;
            fz_check_maximal(st);
        }
    }
}
