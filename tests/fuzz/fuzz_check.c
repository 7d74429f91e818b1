/*
 * fuzz_check.c - the contract checks of the fuzz harness (see fuzz.h).
 *
 * Distances are checked in the user's coordinates as (dx/R)^2 + (dy/R)^2 >= 1
 * with a 1e-12 relative tolerance: the library decides exactly, the quotients
 * here round, and a real bug (a pair at 0.98 R) is far outside the tolerance.
 * Dividing by R first keeps the squares finite for coordinates near 1e300.
 * On the torus a difference d is wrapped to min(|d|, |p - |d||) with the
 * period p of the model (fuzz_torus.c): both are multiples of the quantum
 * there, so the wrapped difference is exact before the division.
 * With a radius field (1.3) a pair i < j is checked against r_i, point i's
 * radius read with pds_radii (fuzz_field.c); pds_radius bounds them all.
 */
#include "fuzz.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fz_fail(const char *file, int line, const char *fmt, ...)
{
    va_list args;
    fprintf(stderr, "\nfuzz contract violation at %s:%d: ", file, line);
    va_start(args, fmt);
    vfprintf(stderr, fmt, args);
    va_end(args);
    fputc('\n', stderr);
    abort();
}

double fz_max_abs4(const double d[4])
{
    double m = 0.0;
    int i;
    for (i = 0; i < 4; i++)
        if (fabs(d[i]) > m) m = fabs(d[i]);
    return m;
}

int fz_strict(void)
{
    static int strict = -1;
    if (strict < 0) strict = getenv("PDS_FUZZ_STRICT") != NULL;
    return strict;
}

void fz_codes(fz_state *st, const char *fn, int rc, unsigned allowed)
{
    static int tracing = -1;
    const char *text = pds_strerror(rc);
    if (tracing < 0) tracing = getenv("PDS_FUZZ_TRACE") != NULL;
    if (tracing) fprintf(stderr, "fuzz:   %s -> %d\n", fn, rc);
    FZ_CHECK(rc != PDS_EINTERNAL, "%s: PDS_EINTERNAL: %s", fn, st->s ? pds_errmsg(st->s) : "");
    FZ_CHECK(rc >= -6 && rc <= 1 && (allowed & FZ_BIT(rc)), "%s returned %d (%s), not a code "
             "the contract allows here%s%s", fn, rc, text ? text : "(null)",
             st->s ? ": " : "", st->s ? pds_errmsg(st->s) : "");
    FZ_CHECK(text != NULL && text[0] != '\0', "pds_strerror(%d) is empty", rc);
    if (st->s != NULL) {
        const char *msg = pds_errmsg(st->s);
        FZ_CHECK(msg != NULL && msg[0] != '\0', "pds_errmsg after %s is empty", fn);
        if (rc < 0)
            FZ_CHECK(strncmp(msg, fn, strlen(fn)) == 0, "%s failed (%d) but pds_errmsg says "
                     "\"%s\"", fn, rc, msg);
        else
            FZ_CHECK(strcmp(msg, st->msg) == 0, "%s succeeded (%d) but pds_errmsg changed "
                     "from \"%s\" to \"%s\"", fn, rc, st->msg, msg);
        strncpy(st->msg, msg, sizeof st->msg - 1);
        st->msg[sizeof st->msg - 1] = '\0';
    }
}

static void grow(fz_state *st, size_t n)
{
    size_t cap = st->cap ? st->cap : 64;
    while (cap < n) cap *= 2;
    if (cap == st->cap) return;
    st->pts = realloc(st->pts, 2 * cap * sizeof(double));
    st->tmp = realloc(st->tmp, 2 * cap * sizeof(double));
    st->rad = realloc(st->rad, cap * sizeof(double));
    st->rad_tmp = realloc(st->rad_tmp, cap * sizeof(double));
    FZ_CHECK(st->pts != NULL && st->tmp != NULL && st->rad != NULL && st->rad_tmp != NULL,
             "harness out of memory (%zu points)", n);
    st->cap = cap;
}

void fz_sync(fz_state *st)
{
    size_t n, got, i;
    double *t;
    double r;

    if (st->s == NULL) return;
    n = pds_count(st->s);
    r = pds_radius(st->s);
    FZ_CHECK(n == st->count, "pds_count is %zu, expected %zu", n, st->count);
    FZ_CHECK(memcmp(&r, &st->radius, sizeof r) == 0, "pds_radius is %.17g, expected %.17g", r,
             st->radius);
    if (n == 0) return;
    grow(st, n);
    got = pds_points(st->s, 0, n, st->tmp);
    FZ_CHECK(got == n, "pds_points(0, %zu) copied %zu", n, got);
    /* The count never shrinks (checked above); nothing read before may move. */
    for (i = 0; i < 2 * st->seen; i++)
        FZ_CHECK(memcmp(&st->tmp[i], &st->pts[i], sizeof(double)) == 0, "point %zu changed "
                 "from %.17g to %.17g (coordinate %zu)", i / 2, st->pts[i], st->tmp[i], i % 2);
    for (i = st->seen; i < n; i++) { /* the earlier ones are unchanged */
        const double x = st->tmp[2 * i], y = st->tmp[2 * i + 1];
        FZ_CHECK(isfinite(x) && isfinite(y), "point %zu is (%g, %g)", i, x, y);
        FZ_CHECK(fz_inside(st, x, y), "point %zu (%.17g, %.17g) outside [%.17g,%.17g%sx"
                 "[%.17g,%.17g%s%s", i, x, y, st->dom[0], st->dom[2], st->periodic ? ")" : "]",
                 st->dom[1], st->dom[3], st->periodic ? ") or off the quantum grid" : "]",
                 st->shape.kind == FZ_SHAPE_POLYGON ? " or its polygon"
                 : st->shape.kind == FZ_SHAPE_MASK ? " or its mask" : "");
    }
    fz_sync_radii(st, n, st->tmp);
    t = st->pts;
    st->pts = st->tmp;
    st->tmp = t;
    st->seen = n;
}

typedef struct {
    double key, across; /* the coordinates along and across the sweep */
    size_t id;          /* the point's index (a copy shifted by a period shares it) */
} swept;

static int by_key(const void *a, const void *b)
{
    const double ka = ((const swept *)a)->key, kb = ((const swept *)b)->key;
    return (ka > kb) - (ka < kb);
}

/* The exponent of the domain's largest |coordinate| (0 for none finite and nonzero). */
static int domain_exponent(const double d[4])
{
    double m = 0.0;
    int k;
    for (k = 0; k < 4; k++)
        if (isfinite(d[k]) && fabs(d[k]) > m) m = fabs(d[k]);
    return m > 0.0 ? ilogb(m) : 0;
}

void fz_check_pattern(const fz_state *st)
{
    const size_t n = st->seen;
    /* In units of 2^ilogb(largest |coordinate|), exactly: there differences
     * and periods near 2 DBL_MAX do not overflow (inf - inf was NaN). */
    const int ex = domain_exponent(st->dom);
    const double r = ldexp(st->radius, -ex);
    /* Sweep along the long side: few points lie in a window R wide across it. */
    const int ax = (st->dom[2] * 0.5 - st->dom[0] * 0.5) >= (st->dom[3] * 0.5 - st->dom[1] * 0.5) ? 0 : 1;
    const double lo = ldexp(st->dom[ax], -ex);
    const double p_along = st->periodic ? st->per_scaled[ax] : 0.0;
    const double p_across = st->periodic ? st->per_scaled[1 - ax] : 0.0;
    swept *p;
    size_t i, j, m = n;

    fz_fixed_check_pattern(st);
    if (n < 2) return;
    /* On the torus, copies shifted by one period along the sweep of the points
     * within R of its start meet the points near its end. */
    p = malloc(2 * n * sizeof *p);
    FZ_CHECK(p != NULL, "harness out of memory (%zu points)", n);
    for (i = 0; i < n; i++) {
        const double x = ldexp(st->pts[2 * i], -ex), y = ldexp(st->pts[2 * i + 1], -ex);
        FZ_CHECK(fz_inside(st, st->pts[2 * i], st->pts[2 * i + 1]), "point %zu outside the domain", i);
        p[i].key = ax == 0 ? x : y;
        p[i].across = ax == 0 ? y : x;
        p[i].id = i;
        if (p_along > 0.0 && (p[i].key - lo) / r <= 1.0 + 1e-9) {
            p[m] = p[i];
            p[m].key += p_along;
            m++;
        }
    }
    qsort(p, m, sizeof *p, by_key);
    for (i = 0; i < m; i++) {
        for (j = i + 1; j < m; j++) {
            const double u = (p[j].key - p[i].key) / r;
            double d = fabs(p[j].across - p[i].across), v;
            if (u > 1.0) break; /* this pair and every later one are >= R apart */
            if (p[i].id == p[j].id) continue; /* a point and its own copy: a period apart */
            if (p_across > 0.0 && fabs(p_across - d) < d) d = fabs(p_across - d);
            v = d / r;
            /* A field: the earlier point's disk (r bounds every radius). */
            {
                const size_t e = p[i].id < p[j].id ? p[i].id : p[j].id;
                const double re = ldexp(fz_radius_of(st, e), -ex);
                double ue = u, ve = v;
                if (re != r) {
                    ue = (p[j].key - p[i].key) / re;
                    ve = d / re;
                }
                FZ_CHECK(ue * ue + ve * ve >= 1.0 - 1e-12, "points %zu (%.17g, %.17g) and %zu "
                         "(%.17g, %.17g) are %.17g r apart%s (r = %.17g, the radius of point "
                         "%zu; R = %.17g, %zu points)", p[i].id, st->pts[2 * p[i].id],
                         st->pts[2 * p[i].id + 1], p[j].id, st->pts[2 * p[j].id],
                         st->pts[2 * p[j].id + 1], sqrt(ue * ue + ve * ve),
                         st->periodic ? " on the torus" : "", fz_radius_of(st, e), e, st->radius, n);
            }
        }
    }
    free(p);
}

void fz_check_free_area(fz_state *st)
{
    const double a = pds_free_area(st->s), area = fz_domain_area(st); /* NaN: not known */

    if (st->s == NULL) {
        FZ_CHECK(isnan(a), "pds_free_area(NULL) is %g, not NaN", a);
        return;
    }
    FZ_CHECK(!isnan(a) && a >= 0.0, "pds_free_area is %g", a);
    /* In count mode "complete" means n points, maximal only at an earlier radius. */
    if (st->maximal && st->target == 0)
        FZ_CHECK(a == 0.0, "pds_free_area is %g on a maximal pattern", a);
    /* (A domain whose coordinates cannot be scaled, a nonzero one below 2^-890 of the
     * largest, gets no point (PDS_ERANGE): its free area is not judged.) */
    if (isfinite(area) && area > 1e-290 && fz_precision_ok(st, INFINITY)) {
        if (st->count == 0 && st->nfix == 0)
            FZ_CHECK(fabs(a - area) <= 1e-9 * area, "pds_free_area is %.17g before the first "
                     "point, the domain's area is %.17g", a, area);
        else if (st->count == 0) /* the clearances count once a run has started */
            FZ_CHECK(a <= area * (1.0 + 1e-9) && (st->fix_ref > 0.0 || fabs(a - area) <= 1e-9 * area),
                     "pds_free_area is %.17g before the first point with %zu fixed points (the "
                     "domain's area %.17g)", a, st->nfix, area);
        else
            FZ_CHECK(a <= area * (1.0 + 1e-9), "pds_free_area %.17g exceeds the domain's area "
                     "%.17g", a, area);
    }
}

void fz_check_maximal(fz_state *st)
{
    size_t added = 1;
    int rc;

    if (st->checked) return;
    rc = pds_verify(st->s);
    fz_codes(st, "pds_verify", rc, FZ_OK | FZ_MORE | FZ_BIT(PDS_ENOMEM));
    /* Count mode: n points; maximal at the radius before the last (PDS_MORE). */
    FZ_CHECK(rc == 0 || rc == PDS_ENOMEM || (st->target != 0 && rc == 1),
             "pds_verify is %d on a pattern reported %s", rc,
             st->target ? "complete" : "maximal");
    FZ_CHECK(st->target == 0 || st->count == st->target, "count mode: complete at %zu points, "
             "n = %zu", st->count, st->target);
    fz_check_free_area(st);
    rc = pds_step(st->s);
    fz_codes(st, "pds_step", rc, FZ_OK | FZ_BIT(PDS_ENOMEM));
    rc = fz_run(st, (size_t)st->count % 3, &added); /* 0 (no limit), 1 or 2 */
    fz_codes(st, "pds_run", rc, FZ_OK | FZ_BIT(PDS_ENOMEM));
    FZ_CHECK(added == 0, "pds_run added %zu points to a %s pattern", added,
             st->target ? "complete" : "maximal");
    if (st->target != 0) {
        rc = pds_refine(st->s, st->radius * 0.5);
        fz_codes(st, "pds_refine", rc, FZ_BIT(PDS_ESTATE));
    }
    fz_sync(st);
    fz_check_pattern(st);
    if (st->target == 0) fz_check_coverage(st);
    st->checked = 1;
}

/* The squared distance in units of r from (x, y) to point i, wrapped on the torus. */
static double dist2(const fz_state *st, double x, double y, size_t i, double r)
{
    double dx = fabs(x - st->pts[2 * i]), dy = fabs(y - st->pts[2 * i + 1]);
    if (st->periodic) {
        if (fabs(st->per[0] - dx) < dx) dx = fabs(st->per[0] - dx);
        if (fabs(st->per[1] - dy) < dy) dy = fabs(st->per[1] - dy);
    }
    dx /= r;
    dy /= r;
    return dx * dx + dy * dy;
}

void fz_check_coverage(const fz_state *st)
{
    /* Corners, sides and the centre, then pseudo-random probes. */
    static const double kFixed[3] = {0.0, 0.5, 1.0};
    const double x0 = st->dom[0], y0 = st->dom[1];
    double w = st->dom[2] - x0, h = st->dom[3] - y0;
    uint64_t rng = 0x9e3779b97f4a7c15u ^ (uint64_t)st->seen;
    size_t k, i;

    if (st->shape.kind != FZ_SHAPE_NONE) { /* the polygon's own probes */
        fz_shape_coverage(st);
        return;
    }
    if (st->periodic) { /* the torus's periods; the far sides are the near ones */
        w = st->per[0];
        h = st->per[1];
    }
    if ((st->seen == 0 && st->nfix == 0) || !(w > 0.0 && h > 0.0 && isfinite(w) && isfinite(h))) return;
    for (k = 0; k < 64; k++) {
        double tx, ty, x, y;
        int covered = 0;
        if (k < 9) {
            tx = kFixed[k % 3];
            ty = kFixed[k / 3];
        } else {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            tx = (double)(rng >> 11) * 0x1p-53;
            ty = (double)(rng & 0xfffff) / 1048575.0;
        }
        x = x0 + w * tx;
        y = y0 + h * ty;
        if (x > st->dom[2]) x = st->dom[2];
        if (y > st->dom[3]) y = st->dom[3];
        for (i = 0; i < st->seen && !covered; i++) {
            const double r = fz_radius_of(st, i);
            covered = dist2(st, x, y, i, r) <= 1.0 + 1e-9;
        }
        if (!covered) covered = fz_fixed_covers(st, x, y);
        FZ_CHECK(covered, "the maximal pattern leaves the probe (%.17g, %.17g) in no disk%s "
                 "(%zu points, R %.17g, domain [%.17g,%.17g]x[%.17g,%.17g])", x, y,
                 st->periodic ? " on the torus" : "", st->seen, st->radius, st->dom[0],
                 st->dom[2], st->dom[1], st->dom[3]);
    }
}

void fz_reset(fz_state *st, pds_sampler *s, double radius)
{
    const char *msg;
    st->s = s;
    st->dom[0] = st->dom[1] = 0.0;
    st->dom[2] = st->dom[3] = 1.0;
    st->radius = radius;
    st->count = st->seen = 0;
    st->maximal = st->checked = 0;
    st->periodic = 0;
    st->per[0] = st->per[1] = st->q = st->per_scaled[0] = st->per_scaled[1] = 0.0;
    st->target = 0;
    memset(&st->prog, 0, sizeof st->prog);
    st->c_radius = radius;
    st->c_seed = 0;
    st->n_ev = 0;
    st->run_failed = 0;
    st->parallel = 0;
    fz_field_reset(st);
    fz_fixed_reset(st);
    fz_shape_free(&st->shape);
    st->shape.rect[0] = st->shape.rect[1] = 0.0;
    st->shape.rect[2] = st->shape.rect[3] = 1.0;
    msg = s ? pds_errmsg(s) : "";
    FZ_CHECK(s == NULL || strcmp(msg, "no error") == 0, "a new sampler's pds_errmsg is \"%s\"",
             msg);
    strncpy(st->msg, msg, sizeof st->msg - 1);
    st->msg[sizeof st->msg - 1] = '\0';
}

/* hi - lo in units of r; a span past the largest double (both ends near it,
 * opposite signs) is halved first, exactly, as the library scales it. */
static double span_in_radii(double lo, double hi, double r)
{
    const double d = hi - lo;
    return isinf(d) ? 2.0 * ((0.5 * hi - 0.5 * lo) / r) : d / r;
}

double fz_count_bound(const fz_state *st)
{
    /* Overflow gives inf (a huge bound), never NaN: the domain is non-empty.
     * A field: at its smallest radius, as the library bounds it. */
    const double r = fz_smallest_radius(st);
    const double w = span_in_radii(st->dom[0], st->dom[2], r);
    const double h = span_in_radii(st->dom[1], st->dom[3], r);
    return 1.1547005383792515 * w * h + (w + h) + 1.0;
}

int fz_precision_ok(const fz_state *st, double radius)
{
    double m = 0.0;
    int i;
    for (i = 0; i < 4; i++)
        if (fabs(st->dom[i]) > m) m = fabs(st->dom[i]);
    /* A nonzero coordinate far below the largest would underflow when the
     * library scales the domain (found by this harness): refused since 1.1.1. */
    for (i = 0; i < 4; i++)
        if (st->dom[i] != 0.0 && fabs(st->dom[i]) < 0x1p-890 * m) return 0;
    if (!fz_shape_scalable(st)) return 0; /* a polygon's vertex too */
    return m >= 0x1p-890 && radius >= 0x1p-24 * m;
}
