/*
 * fuzz_field.c - the variable radius of 1.3 in the fuzz harness (see fuzz.h):
 * pds_set_radius_map, pds_set_radius_fn with a harness-owned function,
 * pds_radii, and the model of a point's radius.
 *
 * The contract modelled (poissondisk.h, the paragraph before
 * pds_set_radius_map):
 *   - a map: PDS_EINVAL for s or r NULL, w or h 0, w*h overflowing, a value
 *     not finite or <= 0; a function: PDS_EINVAL for s or fn NULL, bounds not
 *     finite, rmin <= 0 or rmin > rmax; both: PDS_EINVAL with a count set
 *     (and pds_set_count with a field, either order), PDS_ESTATE once points
 *     exist (either check may come first when both apply); the last field set
 *     wins, and a failed call leaves the one in force;
 *   - pds_radius is then the field's rmax (the map's largest value, the
 *     declared rmax) until a refine, which scales every radius by
 *     R / pds_radius;
 *   - the smallest radius is judged for precision at the first point, rmax on
 *     the torus against half the shorter period (PDS_ERANGE, fuzz_ops.c), and
 *     the scaled smallest one by pds_refine;
 *   - point i carries r_i = r(p_i): the function's value at the point, or the
 *     map's bilinear value between pixel centres, clamped beyond the outer
 *     ones; pds_radii gives min(count, n - first) of them, each in
 *     [rmin, rmax] scaled; a later point lies outside every earlier closed
 *     disk (fz_check_pattern), and a maximal pattern's disks cover the domain
 *     (fz_check_coverage);
 *   - a value out of [rmin, rmax] or not finite stops pds_run and pds_step
 *     with PDS_EINVAL before the point is added: the points so far stay, and
 *     the sampler goes on exactly as if nothing had failed (the replay);
 *   - a field with rmin == rmax (a 1 x 1 or uniform map, a function with
 *     equal bounds) gives the plain sampler's points at that radius, byte for
 *     byte (fuzz_replay.c); such a function is not called (1.3 header on the
 *     field branch), so it cannot fail;
 *   - the function gets points of the domain, and a changing call from inside
 *     it returns PDS_ESTATE and changes nothing;
 *   - the torus takes a field (PDS_ERANGE at the first point when rmax is
 *     above half the shorter period);
 *   - a varying field judges Oler's bound at rmin (which may exceed the
 *     pattern by any factor) at the first point only: the harness does not
 *     make unbounded runs unless the pattern is maximal or the bound is
 *     within the budget, and PDS_ERANGE is allowed where the bound at rmin
 *     exceeds the index space.
 * The two bugs this harness found in 1.3 are fixed (found/NOTES; their
 * reproducers are corpus/regress_field_*).
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))
#define PICK(r, table) ((table)[fz_u8(r) % N_OF(table)])
#define BELOW_1 0x1.fffffffffffffp-1
#define ABOVE_1 0x1.0000000000001p+0
#define PI 3.14159265358979323846

/* rmax / rmin: equal (constant), an ulp apart, gentle to extreme; below 1 inverted. */
static const double kRatio[] = {
    1.0, 1.0, ABOVE_1, 1.1, 1.5, 2.0, 2.5, 4.0, 10.0, 100.0, 1e4, 1e8, 1e300, 0.5, BELOW_1, 3.0,
};

/* ---- the model ------------------------------------------------------------------- */

int fz_varying_field(const fz_state *st)
{
    return st->field != FZ_FIELD_NONE && st->f_rmin != st->f_rmax;
}

int fz_field_has_darts(const fz_state *st)
{
    return fz_varying_field(st) && st->f_rmax <= 16.0 * st->f_rmin;
}

/* The field's smallest value scaled to the radius in force R (radius_field.hpp:
 * value / rmax * R, the value itself before a refine). */
static double scaled(const fz_state *st, double value, double R)
{
    return R == st->f_rmax ? value : value / st->f_rmax * R;
}

double fz_smallest_radius(const fz_state *st)
{
    return fz_varying_field(st) ? scaled(st, st->f_rmin, st->radius) : st->radius;
}

static const fz_field_fn *active_fn(const fz_state *st)
{
    return &st->fns[st->fn_active];
}

static int is_bad(const fz_field_fn *f, double v)
{
    return !(v >= f->rmin && v <= f->rmax); /* NaN too */
}

int fz_field_may_fail(const fz_state *st)
{
    const fz_field_fn *f = active_fn(st);
    return st->field == FZ_FIELD_FN && fz_varying_field(st) && (f->band || f->toggled) &&
           is_bad(f, f->bad);
}

int fz_field_fails_everywhere(const fz_state *st)
{
    const fz_field_fn *f = active_fn(st);
    return st->field == FZ_FIELD_FN && fz_varying_field(st) && f->toggled && is_bad(f, f->bad);
}

/* Where (x, y) lies in the domain, in [0, 1] (0 when the side overflows). */
static double unit(double c, double lo, double hi)
{
    /* [-DBL_MAX, DBL_MAX] is wider than DBL_MAX: halved, it is not (exact
     * there, far from subnormals) */
    const double t = isinf(hi - lo) ? (0.5 * c - 0.5 * lo) / (0.5 * hi - 0.5 * lo) : (c - lo) / (hi - lo);
    return t >= 0.0 ? (t <= 1.0 ? t : 1.0) : 0.0; /* NaN -> 0 */
}

double fz_field_value(const fz_field_fn *f, double x, double y)
{
    const double u = unit(x, f->dom[0], f->dom[2]), v = unit(y, f->dom[1], f->dom[3]);
    double t, w;
    unsigned k;

    if (f->band && u >= f->band0 && u < f->band1) return f->bad;
    switch (f->shape % 8) {
        case 0: t = 1.0; break;
        case 1: t = u; break;
        case 2: t = 0.5 * (u + v); break;
        case 3: t = u < 0.5 ? 0.0 : 1.0; break; /* a step: exactly lo and hi */
        case 4:
            k = 1 + f->param % 4;
            t = 0.5 + 0.5 * sin(2.0 * PI * k * u) * cos(2.0 * PI * k * v);
            break;
        case 5:
            k = 1 + f->param % 8;
            t = (double)(((unsigned)(u * k) + (unsigned)(v * k)) & 1u);
            break;
        case 6: t = 2.0 * hypot(u - 0.5, v - 0.5); break;
        default: /* a small disk of lo in a field of hi */
            t = hypot(u - (f->param % 16) / 15.0, v - (f->param / 16 % 16) / 15.0) < 0.1 ? 0.0 : 1.0;
            break;
    }
    if (t <= 0.0) return f->lo;
    if (t >= 1.0) return f->hi;
    w = f->lo + (f->hi - f->lo) * t;
    return w < f->lo ? f->lo : w > f->hi ? f->hi : w;
}

/* One changing call from inside the radius function: PDS_ESTATE, nothing changes. */
static void try_change(fz_field_fn *f)
{
    fz_state *st = f->st;
    pds_sampler *s = st->s;
    const size_t count = pds_count(s);
    const double r = pds_radius(s), one = 1.0;
    const unsigned threads = pds_threads(s);
    size_t added = 99;
    const char *fn = "";
    double r2;
    int rc = 0;

    switch (f->change) {
        case 1: fn = "pds_run"; rc = pds_run(s, 1, &added); break;
        case 2: fn = "pds_step"; rc = pds_step(s); break;
        case 3: fn = "pds_refine"; rc = pds_refine(s, r * 0.5); break;
        case 4: fn = "pds_set_domain"; rc = pds_set_domain(s, 0.0, 0.0, 1.0, 1.0); break;
        case 5: fn = "pds_set_periodic"; rc = pds_set_periodic(s, !st->periodic); break;
        case 6: fn = "pds_set_count"; rc = pds_set_count(s, 10); break;
        case 7: fn = "pds_set_radius_fn"; rc = pds_set_radius_fn(s, fz_field_cb, f, 1.0, 2.0); break;
        case 8: fn = "pds_set_radius_map"; rc = pds_set_radius_map(s, 1, 1, &one); break;
        case 9: fn = "pds_set_progress"; rc = pds_set_progress(s, NULL, NULL); break;
        case 10: fn = "pds_set_threads"; rc = pds_set_threads(s, 2); break; /* 1.5 */
        default: return;
    }
    fz_codes(st, fn, rc, FZ_BIT(PDS_ESTATE));
    FZ_CHECK(f->change != 1 || added == 0, "pds_run from the radius function: added %zu", added);
    FZ_CHECK(pds_count(s) == count, "%s from the radius function changed the count from %zu to "
             "%zu", fn, count, pds_count(s));
    r2 = pds_radius(s);
    FZ_CHECK(memcmp(&r, &r2, sizeof r) == 0, "%s from the radius function changed the radius "
             "from %.17g to %.17g", fn, r, r2);
    FZ_CHECK(f->change != 10 || pds_threads(s) == threads, "pds_set_threads from the radius "
             "function changed the count from %u to %u", threads, pds_threads(s));
}

double fz_field_cb(void *user, double x, double y)
{
    fz_field_fn *f = user;
    double v;

    f->calls++;
    FZ_CHECK(f->dom[0] <= x && x <= f->dom[2] && f->dom[1] <= y && y <= f->dom[3],
             "the radius function was called at (%.17g, %.17g), outside the domain "
             "[%.17g,%.17g]x[%.17g,%.17g]", x, y, f->dom[0], f->dom[2], f->dom[1], f->dom[3]);
    FZ_CHECK(f->rmin != f->rmax, "the radius function was called though rmin == rmax (%.17g)",
             f->rmin);
    if (f->st != NULL && f->change != 0 && f->calls % 61 == 1) try_change(f);
    v = f->toggled ? f->bad : fz_field_value(f, x, y);
    if (is_bad(f, v)) f->bad_calls++;
    return v;
}

/* A map's value at (x, y) by the header's definition: bilinear between pixel
 * centres x0 + (i + 1/2) (x1 - x0) / w, clamped beyond the outer ones. */
static void pixel(double t, size_t n, size_t *i, double *frac)
{
    double u = t * (double)n - 0.5;
    u = u < 0.0 ? 0.0 : u > (double)(n - 1) ? (double)(n - 1) : u;
    *i = (size_t)u;
    if (*i + 1 >= n) *i = n >= 2 ? n - 2 : 0;
    *frac = n >= 2 ? u - (double)*i : 0.0;
}

static double map_value(const fz_state *st, double x, double y)
{
    const size_t w = st->map_w, h = st->map_h;
    const double *m = st->map;
    size_t i, j, i1, j1;
    double fx, fy, v;

    pixel(unit(x, st->dom[0], st->dom[2]), w, &i, &fx);
    pixel(unit(y, st->dom[1], st->dom[3]), h, &j, &fy);
    i1 = w >= 2 ? i + 1 : i;
    j1 = h >= 2 ? j + 1 : j;
    v = (1 - fy) * ((1 - fx) * m[j * w + i] + fx * m[j * w + i1]) +
        fy * ((1 - fx) * m[j1 * w + i] + fx * m[j1 * w + i1]);
    return v < st->f_rmin ? st->f_rmin : v > st->f_rmax ? st->f_rmax : v;
}

double fz_radius_of(const fz_state *st, size_t i)
{
    return fz_varying_field(st) ? st->rad[i] : st->radius;
}

void fz_sync_radii(fz_state *st, size_t n, const double *xy)
{
    const double R = st->radius;
    const int varying = fz_varying_field(st);
    const double low = varying ? scaled(st, st->f_rmin, R) : R;
    size_t i, got;

    got = pds_radii(st->s, 0, n, st->rad_tmp);
    FZ_CHECK(got == n, "pds_radii(0, %zu) copied %zu", n, got);
    for (i = 0; i < n; i++) {
        const double r = st->rad_tmp[i];
        const double x = xy[2 * i], y = xy[2 * i + 1];
        double want;
        if (!varying) { /* no field, or a constant one: pds_radius itself */
            FZ_CHECK(memcmp(&r, &R, sizeof r) == 0, "pds_radii: point %zu has %.17g, pds_radius "
                     "is %.17g (%s)", i, r, R, st->field ? "constant field" : "no field");
            continue;
        }
        FZ_CHECK(r <= R && r >= low * (1.0 - 1e-14), "pds_radii: point %zu at (%.17g, %.17g) "
                 "has %.17g, outside [%.17g, %.17g] (field [%.17g, %.17g] scaled to %.17g)", i,
                 x, y, r, low, R, st->f_rmin, st->f_rmax, R);
        if (i < st->seen) { /* read before: the same, or scaled by a refine */
            if (st->rad_at == R)
                FZ_CHECK(memcmp(&r, &st->rad[i], sizeof r) == 0, "pds_radii: point %zu's "
                         "radius changed from %.17g to %.17g", i, st->rad[i], r);
            else
                FZ_CHECK(fabs(r - st->rad[i] / st->rad_at * R) <= 1e-14 * r, "pds_radii: point "
                         "%zu's radius %.17g at R %.17g became %.17g at R %.17g", i,
                         st->rad[i], st->rad_at, r, R);
            continue;
        }
        if (st->field == FZ_FIELD_FN) {
            const double v = fz_field_value(active_fn(st), x, y);
            FZ_CHECK(!is_bad(active_fn(st), v), "point %zu was added at (%.17g, %.17g), where "
                     "the radius function returns %.17g, outside [%.17g, %.17g]", i, x, y, v,
                     st->f_rmin, st->f_rmax);
            want = scaled(st, v, R);
            FZ_CHECK(R == st->f_rmax ? r == want : fabs(r - want) <= 1e-14 * want,
                     "pds_radii: point %zu at (%.17g, %.17g) has %.17g, the function's value "
                     "%.17g scaled to R %.17g is %.17g", i, x, y, r, v, R, want);
        } else {
            const double v = map_value(st, x, y);
            want = scaled(st, v, R);
            FZ_CHECK(fabs(r - want) <= 1e-9 * R, "pds_radii: point %zu at (%.17g, %.17g) has "
                     "%.17g, the %zu x %zu map's bilinear value is %.17g (scaled: %.17g)", i, x,
                     y, r, st->map_w, st->map_h, v, want);
        }
    }
    {
        double *t = st->rad;
        st->rad = st->rad_tmp;
        st->rad_tmp = t;
    }
    st->rad_at = R;
}

void fz_changed_before_first(fz_state *st)
{
    /* (fixed in 1.3: the generator goes back to the seed, field_first_point_rng.) The
     * fixed points' clearances are adopted again by the next run (fuzz_fixed.c). */
    if (st->count > 0) return;
    st->fix_ref = 0.0;
    st->maximal = st->checked = 0; /* (maximal with no point: the clearances covered it) */
}

void fz_field_reset(fz_state *st)
{
    free(st->map);
    st->map = NULL;
    st->map_w = st->map_h = 0;
    st->field = FZ_FIELD_NONE;
    st->f_rmin = st->f_rmax = 0.0;
    memset(st->fns, 0, sizeof st->fns);
    st->fn_active = 0;
    st->rad_at = 0.0;
    st->refused_first = st->known_rng = 0;
}

/* A field set successfully: pds_radius is its rmax, earlier refines are gone. */
static void field_set(fz_state *st, double rmin, double rmax)
{
    st->f_rmin = rmin;
    st->f_rmax = rmax;
    st->radius = rmax;
    st->maximal = st->checked = 0;
    st->n_ev = 0; /* refines before it set the radius it replaced */
    fz_changed_before_first(st);
}

/* The codes for setting a field with arguments `bad` or not. */
static unsigned field_codes(const fz_state *st, int bad, unsigned ok)
{
    if (st->s == NULL) return FZ_BIT(PDS_EINVAL);
    if (st->count > 0) /* either check may come first */
        return FZ_BIT(PDS_ESTATE) | (bad || st->target ? FZ_BIT(PDS_EINVAL) : 0u);
    if (bad || st->target) return FZ_BIT(PDS_EINVAL);
    return ok;
}

/* ---- the operations -------------------------------------------------------------- */

/* A valid radius for maps and functions: mostly a fraction of the domain. */
static double base_radius(fz_reader *r, const fz_state *st)
{
    return fz_radius(r, st->dom);
}

void fz_op_radius_map(fz_state *st, fz_reader *r)
{
    static const size_t kHuge[][2] = {
        {SIZE_MAX / 2, 4}, {(size_t)1 << 32, (size_t)1 << 32}, {SIZE_MAX, SIZE_MAX},
        {SIZE_MAX, 2}, {3, SIZE_MAX / 2}, {(size_t)1 << 33, (size_t)1 << 31},
        /* w*h fits, w*h doubles do not: no such array can exist either */
        {(size_t)1 << 62, 1}, {(size_t)1 << 61, 2}, {1, SIZE_MAX / 4}, {SIZE_MAX / 8 + 1, 1},
    };
    const unsigned dims = fz_u8(r), vsel = fz_u8(r);
    const int null_s = (dims & 0xf0) == 0xf0;
    size_t w, h, n = 0, k;
    int overflow = 0, null_map = 0, bad = 0, rc;
    double lo, hi, *m;

    switch (dims % 8) {
        case 0: w = h = 1; break;
        case 1: w = 1 + fz_u8(r) % 8; h = 1 + fz_u8(r) % 8; break;
        case 2: w = 1 + fz_u8(r) % 64; h = 1 + fz_u8(r) % 64; break;
        case 3: /* up to 512 x 512 (2 MB): memory stays far below the limits */
            w = (size_t)64 << fz_u8(r) % 4;
            h = (size_t)64 << fz_u8(r) % 4;
            break;
        case 4: /* empty */
            w = fz_u8(r) & 1 ? 0 : 1 + fz_u8(r) % 4;
            h = w == 0 ? fz_u8(r) % 4 : 0;
            break;
        case 5: {
            const unsigned sel = fz_u8(r) % N_OF(kHuge);
            w = kHuge[sel][fz_u8(r) & 1];
            h = kHuge[sel][w == kHuge[sel][0] ? 1 : 0];
            overflow = 1;
            break;
        }
        case 6: w = 1 + fz_u8(r) % 8; h = 1 + fz_u8(r) % 8; null_map = 1; break;
        default: /* a line */
            k = 1 + fz_u8(r) % 256;
            if (fz_u8(r) & 1) {
                w = k;
                h = 1;
            } else {
                w = 1;
                h = k;
            }
            break;
    }
    if (!overflow && w != 0 && h != 0) n = w * h;
    /* Exactly the n values the call may read: ASan sees any read past them. */
    m = malloc((n ? n : 4) * sizeof *m);
    FZ_CHECK(m != NULL, "harness out of memory (a %zu x %zu map)", w, h);
    lo = base_radius(r, st);
    hi = lo * PICK(r, kRatio);
    if (hi < lo) { /* a map has no declared bounds: just the other way round */
        const double t = lo;
        lo = hi;
        hi = t;
    }
    for (k = 0; k < (n ? n : 4); k++) {
        const size_t i = n ? k % w : 0, j = n ? k / w : 0;
        double t;
        switch (vsel % 8) {
            case 0: t = 0.0; break;                                          /* uniform: constant */
            case 1: t = w > 1 ? (double)i / (double)(w - 1) : 0.0; break;    /* gradient in x */
            case 2: t = h > 1 ? (double)j / (double)(h - 1) : 0.0; break;    /* gradient in y */
            case 3: t = (double)((i + j) & 1); break;                        /* checker */
            case 4: t = (double)((k * 2654435761u) >> 8 & 255) / 255.0; break; /* noise */
            case 5: t = k == (size_t)(vsel / 8) % (n ? n : 4) ? 1.0 : 0.0; break; /* spike */
            case 6: t = 1.0; break;
            default: t = h > 1 && w > 1 ? (double)(i + j) / (double)(w + h - 2) : 0.5; break;
        }
        m[k] = t <= 0.0 ? lo : t >= 1.0 ? hi : lo + (hi - lo) * t;
        if (m[k] > hi) m[k] = hi;
    }
    if (vsel / 64 == 0) { /* a hostile value at the first, the last or another cell */
        const unsigned where = fz_u8(r);
        const double v = fz_hostile(r);
        const size_t cells = n ? n : 4;
        k = where % 3 == 0 ? 0 : where % 3 == 1 ? cells - 1 : (size_t)where * 7919u % cells;
        m[k] = v;
    }
    for (k = 0; k < n; k++)
        if (!(isfinite(m[k]) && m[k] > 0.0)) bad = 1;
    bad |= w == 0 || h == 0 || overflow || null_map;
    rc = pds_set_radius_map(null_s ? NULL : st->s, w, h, null_map ? NULL : m);
    if (null_s) {
        fz_state none;
        memset(&none, 0, sizeof none);
        fz_codes(&none, "pds_set_radius_map", rc, FZ_BIT(PDS_EINVAL));
    } else {
        /* w*h fits but w*h doubles do not: no such array can exist; EINVAL, or
         * ENOMEM from a library that would try */
        const int bytes_only = overflow && w * h / w == h;
        fz_codes(st, "pds_set_radius_map", rc,
                 field_codes(st, bad, FZ_OK | FZ_BIT(PDS_ENOMEM)) |
                 (bytes_only && st->s && st->count == 0 && !st->target ? FZ_BIT(PDS_ENOMEM) : 0u));
    }
    if (rc == 0 && !null_s) {
        double mn = m[0], mx = m[0];
        for (k = 1; k < n; k++) {
            if (m[k] < mn) mn = m[k];
            if (m[k] > mx) mx = m[k];
        }
        /* The model's own copy: the library copied it, and m goes now (ASan
         * sees a later read through a kept pointer). */
        free(st->map);
        st->map = malloc(n * sizeof *st->map);
        FZ_CHECK(st->map != NULL, "harness out of memory (a %zu x %zu map)", w, h);
        memcpy(st->map, m, n * sizeof *st->map);
        st->map_w = w;
        st->map_h = h;
        st->field = FZ_FIELD_MAP;
        field_set(st, mn, mx);
    }
    free(m);
    fz_sync(st);
}

/* A value that is out of [rmin, rmax] or not finite. */
static double bad_value(const fz_field_fn *f, unsigned kind)
{
    switch (kind % 11) {
        case 0: return NAN;
        case 1: return INFINITY;
        case 2: return -INFINITY;
        case 3: return 0.0;
        case 4: return -f->rmin;
        case 5: return nextafter(f->rmax, INFINITY);
        case 6: return nextafter(f->rmin, 0.0);
        case 7: return 2.0 * f->rmax;
        case 8: return 0.5 * f->rmin;
        case 9: return -DBL_MAX;
        default: return -0.0;
    }
}

/* Band widths (of u in [0, 1]) where the function returns its bad value. */
static const double kBand[] = {0.01, 0.1, 0.5, 1e-6, 0.3, 1.0};

void fz_op_radius_fn(fz_state *st, fz_reader *r)
{
    const unsigned sel = fz_u8(r);
    const double rmin = base_radius(r, st);
    const double rmax = sel % 8 == 7 ? fz_hostile(r) : rmin * PICK(r, kRatio);
    const int null_s = sel / 8 % 32 == 31, null_fn = sel / 8 % 32 == 30;
    const int valid = isfinite(rmin) && isfinite(rmax) && rmin > 0.0 && rmin <= rmax;
    const int slot = 1 - st->fn_active;
    fz_field_fn *f = &st->fns[slot];
    unsigned b, range;
    int rc;

    memset(f, 0, sizeof *f);
    f->rmin = rmin;
    f->rmax = rmax;
    memcpy(f->dom, st->dom, sizeof f->dom);
    f->shape = fz_u8(r);
    f->param = fz_u8(r);
    range = fz_u8(r);
    f->lo = rmin;
    f->hi = rmax;
    if (valid && range % 8 == 1) f->lo = f->hi = rmax; /* constant inside wider bounds */
    if (valid && range % 8 == 2) { /* inside the bounds, touching neither */
        f->lo = rmin + (rmax - rmin) * 0.25;
        f->hi = rmin + (rmax - rmin) * 0.75;
        if (!(f->lo >= rmin && f->hi <= rmax && f->lo <= f->hi)) f->lo = f->hi = rmin;
    }
    b = fz_u8(r);
    if (b % 4 == 3) { /* a band of bad values */
        f->band = 1;
        f->band0 = fz_u8(r) / 256.0;
        f->band1 = f->band0 + PICK(r, kBand);
    }
    f->bad = bad_value(f, b / 4);
    f->change = fz_u8(r) % 12; /* 10: pds_set_threads (1.5; none before); 11: none */
    f->st = st;
    if (getenv("PDS_FUZZ_TRACE") != NULL)
        fprintf(stderr, "fuzz:   radius function [%.17g, %.17g], values [%.17g, %.17g], shape %u "
                "param %u, band %d [%g, %g) bad %g\n", rmin, rmax, f->lo, f->hi, f->shape % 8,
                f->param, f->band, f->band0, f->band1, f->bad);
    rc = pds_set_radius_fn(null_s ? NULL : st->s, null_fn ? NULL : fz_field_cb, f, rmin, rmax);
    if (null_s) {
        fz_state none;
        memset(&none, 0, sizeof none);
        fz_codes(&none, "pds_set_radius_fn", rc, FZ_BIT(PDS_EINVAL));
    } else {
        fz_codes(st, "pds_set_radius_fn", rc, field_codes(st, !valid || null_fn, FZ_OK));
    }
    if (rc == 0 && !null_s) {
        st->fn_active = slot;
        st->field = FZ_FIELD_FN;
        free(st->map);
        st->map = NULL;
        field_set(st, rmin, rmax);
    }
    FZ_CHECK(f->calls == 0, "pds_set_radius_fn called the function %zu times", f->calls);
    fz_sync(st);
}

/* Bad values from now on, everywhere (or no longer): the run stops and goes on. */
void fz_op_field_bad(fz_state *st, fz_reader *r)
{
    fz_field_fn *f = &st->fns[st->fn_active];
    const unsigned sel = fz_u8(r);
    f->toggled = sel % 4 != 0;
    f->bad = bad_value(f, sel / 4);
}

void fz_op_radii(fz_state *st, fz_reader *r, unsigned arg)
{
    size_t n, first, count, expect = 0, got, i;
    const pds_sampler *s;
    int null_buf;
    double *buf = NULL;

    fz_sync(st); /* st->rad: the radii of all points */
    n = st->count;
    first = fz_size(r, n);
    count = fz_size(r, n);
    s = (arg & 1) ? NULL : st->s;
    null_buf = (arg & 2) != 0;
    if (s != NULL && !null_buf && first < n) expect = count < n - first ? count : n - first;
    if (!null_buf) {
        buf = malloc(expect ? expect * sizeof(double) : 1);
        FZ_CHECK(buf != NULL, "harness out of memory");
    }
    got = pds_radii(s, first, count, buf);
    FZ_CHECK(got == expect, "pds_radii(%s, %zu, %zu, %s) with %zu points copied %zu, expected "
             "%zu", s ? "s" : "NULL", first, count, buf ? "r" : "NULL", n, got, expect);
    for (i = 0; i < expect; i++)
        FZ_CHECK(memcmp(&buf[i], &st->rad[first + i], sizeof(double)) == 0, "pds_radii(%zu, "
                 "%zu): radius %zu is %.17g, read before as %.17g", first, count, first + i,
                 buf[i], st->rad[first + i]);
    free(buf);
}
