/*
 * fuzz_fixed.c - fixed points (pds_set_fixed, 1.4) in the fuzz harness: the
 * call with decoded points and clearances, and what the rest of the harness
 * asks of a pattern that has them.
 *
 * The contract modelled (poissondisk.h, pds_set_fixed):
 *   - PDS_EINVAL for s NULL, xy NULL with n > 0, a coordinate not finite, a
 *     clearance not finite or < 0 (the message names the first such point),
 *     periodic set (and pds_set_periodic refuses while fixed points are
 *     set); PDS_ESTATE once points exist; n == 0 removes them;
 *   - a fixed point outside the domain's bounding box is PDS_EINVAL at the
 *     first point (nothing added; the message names the fixed point);
 *   - every sampled point keeps the fixed point's clearance from it: the
 *     given one, or 0 for the radius in force at the point (between the
 *     field's smallest and largest), both in units of the radius the run
 *     started with and scaled since as pds_radius is (refine, count mode);
 *   - the fixed points count for coverage: a maximal pattern may hold no
 *     point at all when their clearances cover the domain.
 * The harness's model cannot say where the library rounds (its internal
 * frame): near the box's sides either answer is allowed, and distances get
 * a slack of a few ulps of the domain's coordinates.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))
#define MAX_FIXED 64

/* A few ulps of the domain's largest coordinate: the library's frame rounds. */
static double slack(const fz_state *st) { return 16.0 * fz_max_abs4(st->dom) * 0x1p-52; }

static const double kClearanceFactor[] = {0.5, 1.0, 2.0, 0.01, 1e-6, 3.0, 0.999, 1.001};

/* One point's position: in the box, on its corners and sides, beside or on
 * the points before it, a polygon's vertex, just outside, or hostile. */
static void decode_point(const fz_state *st, fz_reader *r, double *xy, size_t k)
{
    const double x0 = st->dom[0], y0 = st->dom[1], x1 = st->dom[2], y1 = st->dom[3];
    const double w = x1 - x0, h = y1 - y0;
    const unsigned kind = fz_u8(r) % 10, a = fz_u8(r), b = fz_u8(r);
    double x = x0 + w * (a / 255.0), y = y0 + h * (b / 255.0);
    switch (kind) {
        case 1: /* a corner of the box */
            x = a & 1 ? x1 : x0;
            y = a & 2 ? y1 : y0;
            break;
        case 2: /* on a side */
            if (a & 1) x = a & 2 ? x1 : x0;
            else y = a & 2 ? y1 : y0;
            break;
        case 3: /* the point before it again */
            if (k > 0) x = xy[2 * k - 2], y = xy[2 * k - 1];
            break;
        case 4: /* on the line through the point before it */
            if (k > 0) {
                y = xy[2 * k - 1];
                if (b & 1) x = xy[2 * k - 2], y = y0 + h * (b / 255.0);
            }
            break;
        case 5: /* beside the point before it, a millionth of R away */
            if (k > 0) x = xy[2 * k - 2] + st->radius * 1e-6 * (a % 3), y = xy[2 * k - 1];
            break;
        case 6: /* a vertex of the polygon or mask */
            if (st->shape.kind != FZ_SHAPE_NONE && st->shape.nv > 0) {
                const size_t v = (a * 256u + b) % st->shape.nv;
                x = st->shape.xy[2 * v];
                y = st->shape.xy[2 * v + 1];
            }
            break;
        case 7: /* just outside the box */
            x = a & 1 ? x1 + w * 1e-3 : x0 - w * 1e-3;
            break;
        case 8: /* a hostile coordinate */
            if (a & 1) x = fz_hostile(r);
            else y = fz_hostile(r);
            break;
        default: break; /* anywhere in the box */
    }
    xy[2 * k] = x;
    xy[2 * k + 1] = y;
}

static double decode_clearance(const fz_state *st, fz_reader *r)
{
    const unsigned kind = fz_u8(r) % 8;
    const double R = st->radius, diag = hypot(st->dom[2] - st->dom[0], st->dom[3] - st->dom[1]);
    switch (kind) {
        case 0: return 0.0; /* the radius at the point */
        case 1: return R * (fz_u8(r) % 64) / 16.0;
        case 2: return R * kClearanceFactor[fz_u8(r) % N_OF(kClearanceFactor)];
        case 3: return diag * (1 + fz_u8(r) % 4); /* covers the domain */
        case 4: return -R;
        case 5: return fz_hostile(r);
        case 6: return diag * 0.1;
        default: return R;
    }
}

void fz_op_fixed(fz_state *st, fz_reader *r)
{
    double xy[2 * MAX_FIXED], c[MAX_FIXED];
    const unsigned b = fz_u8(r), flags = fz_u8(r);
    const size_t n = b % 8 == 7 ? 7 + fz_u8(r) % (MAX_FIXED - 6) : b % 8;
    const int xy_null = flags % 16 == 15, c_null = flags & 16;
    size_t k, first_bad = (size_t)-1;
    unsigned allowed;
    int rc;

    for (k = 0; k < n; k++) {
        decode_point(st, r, xy, k);
        c[k] = c_null ? 0.0 : decode_clearance(st, r);
    }
    for (k = 0; k < n && first_bad == (size_t)-1; k++)
        if (!isfinite(xy[2 * k]) || !isfinite(xy[2 * k + 1]) || (!c_null && !(isfinite(c[k]) && c[k] >= 0.0)))
            first_bad = k;
    if (getenv("PDS_FUZZ_TRACE") != NULL) {
        fprintf(stderr, "fuzz:   %zu fixed points%s%s:", n, xy_null ? " (xy NULL)" : "",
                c_null ? " (no clearances)" : "");
        for (k = 0; k < n; k++) fprintf(stderr, " %.17g,%.17g,%.17g", xy[2 * k], xy[2 * k + 1], c[k]);
        fputc('\n', stderr);
    }
    rc = pds_set_fixed(st->s, xy_null ? NULL : xy, c_null ? NULL : c, n);
    if (st->s == NULL)
        allowed = FZ_BIT(PDS_EINVAL);
    else if (st->count > 0)
        allowed = FZ_BIT(PDS_ESTATE);
    else if (n > 0 && (xy_null || st->periodic || first_bad != (size_t)-1))
        allowed = FZ_BIT(PDS_EINVAL);
    else
        allowed = FZ_OK | FZ_BIT(PDS_ENOMEM);
    fz_codes(st, "pds_set_fixed", rc, allowed);
    if (st->s == NULL) return;
    if (rc == PDS_EINVAL && !xy_null && !st->periodic && first_bad != (size_t)-1) {
        char want[64];
        snprintf(want, sizeof want, "point %zu:", first_bad);
        FZ_CHECK(strstr(pds_errmsg(st->s), want) != NULL, "pds_set_fixed: the first bad point is %zu, "
                 "the message says \"%s\"", first_bad, pds_errmsg(st->s));
    }
    if (rc == 0) {
        fz_fixed_reset(st);
        if (n > 0) {
            st->fix_xy = malloc(2 * n * sizeof *st->fix_xy);
            st->fix_c = malloc(n * sizeof *st->fix_c);
            FZ_CHECK(st->fix_xy != NULL && st->fix_c != NULL, "harness out of memory");
            memcpy(st->fix_xy, xy, 2 * n * sizeof *xy);
            memcpy(st->fix_c, c, n * sizeof *c);
            st->nfix = n;
            st->fix_c_null = c_null;
        }
        fz_changed_before_first(st);
    }
    fz_sync(st);
}

int fz_fixed_outside(const fz_state *st)
{
    const double *d = st->dom;
    const double tol = 1e-9 * (fz_max_abs4(d) + (d[2] - d[0]) + (d[3] - d[1]));
    int verdict = 0;
    size_t k;
    if (st->s == NULL || st->count > 0 || st->nfix == 0) return 0;
    if (!(tol < INFINITY)) return -1;
    for (k = 0; k < st->nfix && verdict != 1; k++) {
        const double x = st->fix_xy[2 * k], y = st->fix_xy[2 * k + 1];
        if (x < d[0] - tol || x > d[2] + tol || y < d[1] - tol || y > d[3] + tol)
            verdict = 1;
        else if (x < d[0] + tol || x > d[2] - tol || y < d[1] + tol || y > d[3] - tol)
            verdict = -1;
    }
    return verdict;
}

int fz_fixed_refused(fz_state *st, const char *fn, int rc, int outside, size_t added)
{
    const int named = strstr(pds_errmsg(st->s), "outside the domain's bounding box") != NULL &&
                      strstr(pds_errmsg(st->s), "fixed point") != NULL;
    if (outside == 1)
        FZ_CHECK(added == 0 && (rc == PDS_EINVAL || rc == PDS_ERANGE || rc == PDS_ENOMEM),
                 "%s returned %d and added %zu with a fixed point outside the box [%.17g,%.17g]x"
                 "[%.17g,%.17g]: %s", fn, rc, added, st->dom[0], st->dom[2], st->dom[1], st->dom[3],
                 pds_errmsg(st->s));
    if (rc != PDS_EINVAL || !named) return 0;
    FZ_CHECK(outside != 0 && added == 0, "%s: \"%s\", but every fixed point lies inside the box "
             "[%.17g,%.17g]x[%.17g,%.17g] (%zu added)", fn, pds_errmsg(st->s), st->dom[0], st->dom[2],
             st->dom[1], st->dom[3], added);
    return 1;
}

void fz_fixed_run_starts(fz_state *st)
{
    if (st->nfix > 0 && st->count == 0 && st->fix_ref == 0.0) st->fix_ref = st->radius;
}

/* The clearance of fixed point k now: at least *lo, at most *hi. In count
 * mode the run starts, at its first point, from the room the clearances
 * leave (1.10): at most the radius read before it, at least the radius now;
 * so a given clearance, scaled from that start, lies between its scaling
 * from the radius read before and itself. */
static void clearance_bounds(const fz_state *st, size_t k, double *lo, double *hi)
{
    const double ref = st->fix_ref > 0.0 ? st->fix_ref : st->radius;
    const double scale = st->radius / ref;
    if (st->fix_c[k] > 0.0) {
        *lo = *hi = st->fix_c[k] * scale;
        if (st->target != 0) *hi = st->fix_c[k];
    } else if (st->field != FZ_FIELD_NONE) { /* the field's value there, scaled as the points' */
        *hi = st->radius;
        *lo = st->radius * (st->f_rmin / st->f_rmax);
    } else {
        *lo = *hi = st->radius;
    }
}

void fz_fixed_check_pattern(const fz_state *st)
{
    const double eps = slack(st);
    size_t i, k;
    if (st->nfix == 0 || st->seen == 0) return;
    for (k = 0; k < st->nfix; k++) {
        const double fx = st->fix_xy[2 * k], fy = st->fix_xy[2 * k + 1];
        double lo, hi;
        clearance_bounds(st, k, &lo, &hi);
        for (i = 0; i < st->seen; i++) {
            const double d = hypot(st->pts[2 * i] - fx, st->pts[2 * i + 1] - fy);
            FZ_CHECK(d >= lo * (1.0 - 1e-9) - eps, "point %zu (%.17g, %.17g) lies %.17g from fixed point "
                     "%zu (%.17g, %.17g), whose clearance is %.17g (given %.17g, R %.17g, the run "
                     "started at R %.17g)", i, st->pts[2 * i], st->pts[2 * i + 1], d, k, fx, fy, lo,
                     st->fix_c[k], st->radius, st->fix_ref);
        }
    }
}

int fz_fixed_covers(const fz_state *st, double x, double y)
{
    const double eps = slack(st);
    size_t k;
    for (k = 0; k < st->nfix; k++) {
        double lo, hi;
        clearance_bounds(st, k, &lo, &hi);
        if (hypot(x - st->fix_xy[2 * k], y - st->fix_xy[2 * k + 1]) <= hi * (1.0 + 1e-9) + eps) return 1;
    }
    return 0;
}

int fz_fixed_apply(const fz_state *st, pds_sampler *t)
{
    int rc;
    if (st->nfix == 0) return 1;
    rc = pds_set_fixed(t, st->fix_xy, st->fix_c_null ? NULL : st->fix_c, st->nfix);
    if (rc == PDS_ENOMEM) return 0;
    FZ_CHECK(rc == 0, "replay: pds_set_fixed returned %d: %s", rc, pds_errmsg(t));
    return 1;
}

void fz_fixed_reset(fz_state *st)
{
    free(st->fix_xy);
    free(st->fix_c);
    st->fix_xy = st->fix_c = NULL;
    st->nfix = 0;
    st->fix_c_null = 0;
    st->fix_ref = 0.0;
}
