/*
 * fuzz_torus.c - the model's view of the 1.2 domain kinds (see fuzz.h): the
 * torus's quantum and periods, where points may lie, and the start radius of
 * count mode. All from the header's words, not from the library's code:
 *   - q = 2^(e-50) with 2^e <= largest |coordinate| < 2^(e+1); every periodic
 *     point is a multiple of q, and so is each period: x1-x0 rounded down to
 *     one (exactly: the difference is taken as a two-sum);
 *   - points lie in [x0,x1) x [y0,y1) on the torus;
 *   - count mode starts at (1.015 + 10/n) R(n), with n = 0.547 4A/(pi R^2)
 *     + 0.23 P/R (no P term on the torus), at most half the shorter period.
 * Sizes are computed with the domain scaled by 2^-e, so nothing overflows.
 */
#include "fuzz.h"

#include <float.h>
#include <math.h>

#define PI 3.14159265358979323846

/* The domain can be scaled without losing a coordinate (else: PDS_ERANGE). */
static int scalable(const double d[4])
{
    const double m = fz_max_abs4(d);
    int i;
    if (!(m >= 0x1p-890) || !isfinite(m)) return 0;
    for (i = 0; i < 4; i++)
        if (d[i] != 0.0 && fabs(d[i]) < 0x1p-890 * m) return 0;
    return 1;
}

/* The largest multiple of 2^-50 at most hi - lo (|lo|, |hi| < 2). */
static double grid_floor_difference(double lo, double hi)
{
    const double s = hi - lo, bv = s - hi;
    const double err = (hi - (s - bv)) + (-lo - bv); /* s + err == hi - lo exactly */
    double p = floor(s * 0x1p50) * 0x1p-50;           /* <= s */
    if (p == s && err < 0.0) p -= 0x1p-50;
    return p;
}

void fz_set_torus(fz_state *st)
{
    const double *d = st->dom;
    int e, a;

    st->q = st->per[0] = st->per[1] = st->per_scaled[0] = st->per_scaled[1] = 0.0;
    if (!st->periodic || !scalable(d)) return; /* no point will exist */
    e = ilogb(fz_max_abs4(d));
    st->q = ldexp(1.0, e - 50);
    for (a = 0; a < 2; a++) { /* back in the user's scale; inf near DBL_MAX (then lenient) */
        st->per_scaled[a] = grid_floor_difference(ldexp(d[a], -e), ldexp(d[a + 2], -e));
        st->per[a] = ldexp(st->per_scaled[a], e);
    }
}

int fz_inside(const fz_state *st, double x, double y)
{
    const double *d = st->dom;
    if (!st->periodic)
        return d[0] <= x && x <= d[2] && d[1] <= y && y <= d[3] &&
               (st->shape.kind == FZ_SHAPE_NONE || fz_shape_inside(&st->shape, x, y));
    if (!(d[0] <= x && x < d[2] && d[1] <= y && y < d[3])) return 0;
    if (st->q >= DBL_MIN) { /* x / q is exact: a power of two, below 2^52 */
        const double u = x / st->q, v = y / st->q;
        if (floor(u) != u || floor(v) != v) return 0;
    }
    return 1;
}

/* Half the shorter side as given, without overflow. */
static double half_shorter(const double d[4])
{
    const double hw = d[2] * 0.5 - d[0] * 0.5, hh = d[3] * 0.5 - d[1] * 0.5;
    return hw < hh ? hw : hh;
}

int fz_above_half_period(const fz_state *st, double radius, double slack)
{
    return st->periodic && radius > half_shorter(st->dom) * (1.0 + slack);
}

int fz_periods_too_unequal(const fz_state *st, double slack)
{
    const double hw = st->dom[2] * 0.5 - st->dom[0] * 0.5, hh = st->dom[3] * 0.5 - st->dom[1] * 0.5;
    const double shorter = hw < hh ? hw : hh, longer = hw < hh ? hh : hw;
    /* A varying radius field: 16 (1.3). */
    return st->periodic && longer > (fz_varying_field(st) ? 16.0 : 1024.0) * shorter * (1.0 + slack);
}

void fz_count_radius(fz_state *st)
{
    const double got = pds_radius(st->s);
    const double *d = st->dom;

    if (st->s == NULL || st->target == 0) return;
    /* A polygon: its area and perimeter, when the harness knows the library's. */
    const int shaped = st->shape.kind != FZ_SHAPE_NONE;
    if (shaped && !(st->shape.area_known && fz_shape_scalable(st))) {
        st->radius = got;
        return;
    }
    if (st->count == 0 && scalable(d)) {
        const int e = ilogb(fz_max_abs4(d));
        /* The area is the torus's: its periods rounded down to the quantum;
         * the sides as given when one rounds to 0 (no point can exist). */
        /* (scaled: periods near 2 DBL_MAX overflow in the user's units) */
        const int torus = st->periodic && st->per_scaled[0] > 0.0 && st->per_scaled[1] > 0.0;
        const double w = torus ? st->per_scaled[0] : ldexp(d[2], -e) - ldexp(d[0], -e);
        const double h = torus ? st->per_scaled[1] : ldexp(d[3], -e) - ldexp(d[1], -e);
        const double n = (double)st->target;
        const double area = shaped ? st->shape.frac * w * h : w * h;
        const double perimeter = shaped ? fz_shape_perimeter(&st->shape, e) : 2.0 * (w + h);
        const double a = 0.547 * 4.0 * area / PI, b = st->periodic ? 0.0 : 0.23 * perimeter;
        double want = ldexp((b + sqrt(b * b + 4.0 * a * n)) / (2.0 * n) * (1.015 + 10.0 / n), e);
        if (st->periodic && want > half_shorter(d)) want = half_shorter(d);
        if (want > DBL_MAX) want = DBL_MAX; /* sides near DBL_MAX: the start is capped */
        /* (want is 0 only on a torus so thin that its area underflows: PDS_ERANGE) */
        FZ_CHECK(isfinite(got) && fabs(got - want) <= 1e-9 * want,
                 "count mode (n %zu%s): pds_radius is %.17g, the documented start %.17g "
                 "(domain [%.17g,%.17g]x[%.17g,%.17g], periods %.17g, %.17g)",
                 st->target, st->periodic ? ", torus" : "", got, want, d[0], d[2], d[1], d[3],
                 st->per[0], st->per[1]);
    }
    st->radius = got;
}
