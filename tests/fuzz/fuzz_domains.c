/*
 * fuzz_domains.c - the domains users have (1.4) in the fuzz harness:
 * pds_set_polygon and pds_set_mask with decoded shapes, and what the rest of
 * the harness asks of the domain once one is set (its area, the count bound
 * the library judges by, the coverage probes, the replay's copy).
 *
 * The contract modelled (poissondisk.h, pds_set_polygon, pds_set_mask):
 *   - PDS_EINVAL for s NULL, xy or ring_ends NULL with rings, decreasing
 *     ends, a coordinate not finite, a ring with fewer than 3 distinct
 *     vertices or all on one line, an outline enclosing nothing, a mask
 *     NULL, overflowing or without an inside pixel, and periodic set (either
 *     order: pds_set_periodic refuses a shape too); PDS_ESTATE once points
 *     exist; nrings 0 or w*h 0 goes back to the rectangle;
 *   - the domain's bounding box replaces the rectangle (a field is spread
 *     over it); pds_set_domain then changes nothing but a mask's rectangle;
 *   - every point lies in the closed domain (fz_sync), and a maximal
 *     pattern covers it (fz_shape_coverage); pds_free_area starts at its
 *     area, and count mode's start radius follows its area and perimeter.
 * The decision whether given rings are valid is the harness's own
 * (fuzz_shape.c); near the edge of each rule either answer is allowed.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))
#define PICK(r, table) ((table)[fz_u8(r) % N_OF(table)])
#define PI 3.14159265358979323846
#define MAX_V 128

/* Units and offsets of the decoded coordinates (small integers / 8 times a unit). */
static const double kUnit[] = {1.0, 1e-3, 1e3, 1e-6, 1e6, 0.125, 1e-300, 1e300, 0x1p-900, 1e15, 3.0, 1e-150};
static const double kShapeOffset[] = {0.0,  0.0,       0.0,     1e15, -1e15,  1e8,  12345.678, 1e300,
                                      -1e300, 1e-300, 0x1p52, 0.25, 1e15 + 0.5, -0.5, 1.0,      1e6};

static double sbyte(fz_reader *r) { return (double)(int8_t)fz_u8(r) / 8.0; }

/* One ring into xy from vertex n on; returns the new count. */
static size_t decode_ring(fz_reader *r, double *xy, size_t n, double unit, double ox, double oy,
                          const double centre[2])
{
    const unsigned rb = fz_u8(r), flags = fz_u8(r);
    const size_t nv = 3 + rb % 10, first = n;
    const unsigned mode = rb / 16 % 4;
    double cx = centre[0], cy = centre[1], x0, y0, x1, y1;
    size_t k;

    if (mode == 0) { /* a star around a centre of its own */
        cx = sbyte(r);
        cy = sbyte(r);
    }
    x0 = sbyte(r), y0 = sbyte(r);
    x1 = x0 + 1.0 + fz_u8(r) % 32 / 4.0, y1 = y0 + 1.0 + fz_u8(r) % 32 / 4.0;
    for (k = 0; k < nv; k++) {
        double x, y;
        if (mode == 0 || mode == 3) { /* a star; mode 3 around ring 0's centre (a hole) */
            const double a = 2.0 * PI * (double)k / (double)nv, rad = (1 + fz_u8(r) % 32) / 8.0;
            x = cx + rad * cos(a);
            y = cy + rad * sin(a);
        } else if (mode == 1) { /* small integers anywhere: rings that cross */
            x = sbyte(r);
            y = sbyte(r);
        } else { /* along a rectangle's sides: exact, collinear runs, touching corners */
            const double t = (double)(4 * k) / (double)nv;
            const int side = (int)t;
            const double f = t - side;
            x = side == 0 ? x0 + f * (x1 - x0) : side == 1 ? x1 : side == 2 ? x1 - f * (x1 - x0) : x0;
            y = side == 0 ? y0 : side == 1 ? y0 + f * (y1 - y0) : side == 2 ? y1 : y1 - f * (y1 - y0);
        }
        xy[2 * n] = ox + unit * x;
        xy[2 * n + 1] = oy + unit * y;
        n++;
        if ((flags & 4) && k == 1) { /* a repeated vertex */
            xy[2 * n] = xy[2 * n - 2], xy[2 * n + 1] = xy[2 * n - 1];
            n++;
        }
        if ((flags & 8) && k == 2) { /* a collinear run: the midpoint of the edge back */
            xy[2 * n] = 0.5 * (xy[2 * n - 2] + xy[2 * n - 4]);
            xy[2 * n + 1] = 0.5 * (xy[2 * n - 1] + xy[2 * n - 3]);
            n++;
        }
    }
    if (flags & 1) /* the other way round */
        for (k = 0; k < (n - first) / 2; k++) {
            const size_t a = first + k, b = n - 1 - k;
            double t = xy[2 * a];
            xy[2 * a] = xy[2 * b], xy[2 * b] = t;
            t = xy[2 * a + 1];
            xy[2 * a + 1] = xy[2 * b + 1], xy[2 * b + 1] = t;
        }
    if ((flags & 0xe0) == 0xe0) { /* a hostile coordinate: NaN, inf, 1e300, 2^-1074 ... */
        const size_t at = first + fz_u8(r) % (n - first); /* read before the value */
        xy[2 * at + (flags >> 4 & 1)] = fz_hostile(r);
    }
    if (flags & 16) { /* traced twice: encloses nothing by itself */
        const size_t len = n - first;
        memcpy(xy + 2 * n, xy + 2 * first, 2 * len * sizeof *xy);
        n += len;
    }
    if (flags & 2) { /* the closing vertex repeated */
        xy[2 * n] = xy[2 * first], xy[2 * n + 1] = xy[2 * first + 1];
        n++;
    }
    return n;
}

/* A polygon set: the model's domain becomes its box; nrings 0: the rectangle. */
static void shape_changed(fz_state *st)
{
    const double *d = st->shape.kind == FZ_SHAPE_NONE ? st->shape.rect : st->shape.box;
    memcpy(st->dom, d, sizeof st->dom);
    memcpy(st->fns[0].dom, d, sizeof st->dom);
    memcpy(st->fns[1].dom, d, sizeof st->dom);
    fz_changed_before_first(st);
    fz_set_torus(st);
    fz_count_radius(st);
}

int fz_index_too_tall(const double box[4], double factor)
{
    const double w = box[2] * 0.5 - box[0] * 0.5, h = box[3] * 0.5 - box[1] * 0.5;
    const double aspect = (w > h ? w / h : h / w) * factor;
    return !fz_strict() && !(aspect <= 1e8); /* found/NOTES: polygon_index_aspect */
}

/* The codes for setting a shape whose arguments the contract says `verdict` of. */
static unsigned shape_codes(const fz_state *st, int verdict)
{
    const unsigned ok = FZ_OK | FZ_BIT(PDS_ENOMEM);
    if (st->s == NULL) return FZ_BIT(PDS_EINVAL);
    if (st->count > 0) return FZ_BIT(PDS_ESTATE);
    if (verdict == 0) return FZ_BIT(PDS_EINVAL);
    return verdict < 0 ? ok | FZ_BIT(PDS_EINVAL) : ok;
}

void fz_op_polygon(fz_state *st, fz_reader *r)
{
    double xy[2 * MAX_V];
    size_t ends[3], nrings, n = 0, k;
    const unsigned b = fz_u8(r), bad = b / 16;
    const double unit = PICK(r, kUnit), ox = PICK(r, kShapeOffset), oy = PICK(r, kShapeOffset);
    double centre[2];
    fz_shape sh;
    int verdict, rc;

    nrings = b % 8 == 0 ? 0 : 1 + b % 3;
    centre[0] = sbyte(r);
    centre[1] = sbyte(r);
    for (k = 0; k < nrings; k++) {
        n = decode_ring(r, xy, n, unit, ox, oy, centre);
        ends[k] = n;
    }
    if (nrings >= 2 && bad == 13) { /* decreasing ends */
        const size_t t = ends[0];
        ends[0] = ends[1], ends[1] = t;
    }
    memset(&sh, 0, sizeof sh);
    if (nrings == 0)
        verdict = 1;
    else if (bad == 14 || bad == 15 || st->periodic)
        verdict = 0;
    else
        verdict = fz_shape_polygon(&sh, xy, ends, nrings);
    if (sh.u != NULL && fz_index_too_tall(sh.box, 1.0)) { /* the library's index would take GBs */
        fz_shape_free(&sh);
        return;
    }
    if (getenv("PDS_FUZZ_TRACE") != NULL) { /* the rings, for a reproducer */
        size_t v;
        for (k = 0, v = 0; k < nrings; k++) {
            fprintf(stderr, "fuzz:   ring %zu (ends %zu):", k, ends[k]);
            for (; v < ends[k] && v < n; v++) fprintf(stderr, " %.17g,%.17g", xy[2 * v], xy[2 * v + 1]);
            fputc('\n', stderr);
        }
    }
    rc = pds_set_polygon(st->s, bad == 15 ? NULL : xy, bad == 14 ? NULL : ends, nrings);
    fz_codes(st, "pds_set_polygon", rc, shape_codes(st, verdict));
    if (rc == 0 && st->s != NULL) {
        double rect[4];
        memcpy(rect, st->shape.rect, sizeof rect);
        fz_shape_free(&st->shape);
        st->shape = sh;
        if (nrings == 0) st->shape.kind = FZ_SHAPE_NONE;
        memcpy(st->shape.rect, rect, sizeof rect);
        shape_changed(st);
    } else {
        fz_shape_free(&sh);
    }
    fz_sync(st);
}

void fz_op_mask(fz_state *st, fz_reader *r)
{
    unsigned char pix[64];
    const unsigned b = fz_u8(r), fill = fz_u8(r);
    size_t w = 1 + b % 8, h = 1 + b / 8 % 8, i, j;
    int verdict = 1, null_pix = 0, rc;
    fz_shape sh;

    memset(&sh, 0, sizeof sh);
    for (j = 0; j < h; j++) {
        const unsigned bits = fill % 4 == 0 ? 0u : fill % 4 == 1 ? 0xffu : fz_u8(r);
        for (i = 0; i < w; i++) pix[j * w + i] = (bits >> i & 1) ? (unsigned char)(fill | 1) : 0;
    }
    if (b / 64 == 3) { /* back to the rectangle, NULL, or a size that overflows */
        switch (fill / 4 % 4) {
            case 0: w = 0; break;
            case 1: h = 0; break;
            case 2: null_pix = 1; break;
            default: w = SIZE_MAX / 2, h = 3; break;
        }
    }
    if (w == 0 || h == 0)
        verdict = 1;
    else if (null_pix || w > 8 || st->periodic)
        verdict = 0;
    else
        verdict = fz_shape_mask(&sh, w, h, pix, st->shape.rect);
    if (w != 0 && h != 0 && verdict != 0 && fz_index_too_tall(st->shape.rect, 8.0)) {
        fz_shape_free(&sh);
        return;
    }
    rc = pds_set_mask(st->s, w, h, null_pix ? NULL : pix);
    fz_codes(st, "pds_set_mask", rc, shape_codes(st, verdict));
    if (rc == 0 && st->s != NULL) {
        double rect[4];
        memcpy(rect, st->shape.rect, sizeof rect);
        fz_shape_free(&st->shape);
        st->shape = sh;
        if (w == 0 || h == 0) st->shape.kind = FZ_SHAPE_NONE;
        memcpy(st->shape.rect, rect, sizeof rect);
        shape_changed(st);
    } else {
        fz_shape_free(&sh);
    }
    fz_sync(st);
}

int fz_domain_may_refuse(const fz_state *st, const double d[4])
{
    fz_shape sh;
    int verdict;
    if (st->shape.kind != FZ_SHAPE_MASK) return 0;
    verdict = fz_shape_mask(&sh, st->shape.mw, st->shape.mh, st->shape.pix, d);
    fz_shape_free(&sh);
    return verdict != 1;
}

void fz_domain_set(fz_state *st, const double d[4])
{
    memcpy(st->shape.rect, d, sizeof st->shape.rect);
    if (st->shape.kind == FZ_SHAPE_MASK) {
        fz_shape sh;
        fz_shape_mask(&sh, st->shape.mw, st->shape.mh, st->shape.pix, d);
        fz_shape_free(&st->shape);
        st->shape = sh;
    }
    if (st->shape.kind == FZ_SHAPE_POLYGON) return; /* the polygon's box stays */
    shape_changed(st);
}

int fz_shape_apply(const fz_state *st, pds_sampler *t)
{
    const fz_shape *sh = &st->shape;
    int rc = 0;
    if (sh->kind == FZ_SHAPE_POLYGON) {
        rc = pds_set_polygon(t, sh->xy, sh->ends, sh->nrings);
    } else if (sh->kind == FZ_SHAPE_MASK) {
        rc = pds_set_domain(t, sh->rect[0], sh->rect[1], sh->rect[2], sh->rect[3]);
        FZ_CHECK(rc == 0, "replay: pds_set_domain(the mask's rectangle) returned %d", rc);
        rc = pds_set_mask(t, sh->mw, sh->mh, sh->pix);
    }
    if (rc == PDS_ENOMEM) return 0;
    FZ_CHECK(rc == 0, "replay: setting the %s again returned %d: %s",
             sh->kind == FZ_SHAPE_MASK ? "mask" : "polygon", rc, pds_errmsg(t));
    return 1;
}

double fz_domain_area(const fz_state *st)
{
    const double w = st->dom[2] - st->dom[0], h = st->dom[3] - st->dom[1];
    /* The torus's area is its periods', rounded down to the quantum (fuzz_torus.c):
     * at 1e15 a side of 0.5 x 5e5 loses 2.5e-7 of it. */
    if (st->periodic && st->per[0] > 0.0 && st->per[1] > 0.0) return st->per[0] * st->per[1];
    if (st->shape.kind == FZ_SHAPE_NONE) return w * h;
    return st->shape.area_known ? st->shape.frac * w * h : NAN;
}

int fz_shape_scalable(const fz_state *st)
{
    const double m = fz_max_abs4(st->dom);
    size_t i;
    if (st->shape.kind == FZ_SHAPE_NONE) return 1;
    for (i = 0; i < 2 * st->shape.nv; i++)
        if (st->shape.xy[i] != 0.0 && fabs(st->shape.xy[i]) < 0x1p-890 * m) return 0;
    return m >= 0x1p-890;
}

void fz_lib_bound(const fz_state *st, double *lo, double *hi)
{
    const double oler = fz_count_bound(st);
    const fz_shape *sh = &st->shape;
    size_t vlo, vhi;
    int e;
    double w, h, r, rho, cells, edge;

    *lo = *hi = oler;
    if (sh->kind == FZ_SHAPE_NONE || fz_max_abs4(st->dom) == 0.0) return;
    /* In the box's scale: user sides may overflow, scaled ones do not. */
    e = ilogb(fz_max_abs4(st->dom));
    w = ldexp(st->dom[2], -e) - ldexp(st->dom[0], -e);
    h = ldexp(st->dom[3], -e) - ldexp(st->dom[1], -e);
    r = ldexp(fz_smallest_radius(st), -e);
    if (r > 2.0 * hypot(w, h)) r = 2.0 * hypot(w, h); /* the library caps R at twice the diagonal */
    rho = 0.5 * r;
    cells = (w / rho) * (h / rho) / PI;
    edge = 2.0 * fz_shape_perimeter(sh, e) / (PI * rho);
    fz_shape_vertices(sh, &vlo, &vhi);
    {
        const double a_lo = sh->area_known ? sh->frac * (1.0 - 1e-9) : 0.0;
        const double a_hi = sh->area_known ? sh->frac * (1.0 + 1e-9) : (double)sh->nrings;
        const double plo = (a_lo * cells + edge * (1.0 - 1e-9) + (double)vlo) + 1.0;
        const double phi = (a_hi * cells + edge * (1.0 + 1e-9) + (double)vhi) * (1.0 + 1e-8) + 1.0;
        if (fz_shape_scalable(st)) { /* else the library falls back to the box */
            *lo = plo;
            *hi = phi;
        } else {
            *lo = plo < oler ? plo : oler;
            *hi = phi > oler ? phi : oler;
        }
    }
}

/* ---- coverage ------------------------------------------------------------------ */

typedef struct {
    const fz_state *st;
    size_t *order; /* point indices sorted by x */
    double slack;  /* an absolute slack: probes along edges round off them */
    size_t probes;
} cover_ctx;

static const double *g_pts; /* for the sort only */
static int by_x(const void *a, const void *b)
{
    const double xa = g_pts[2 * *(const size_t *)a], xb = g_pts[2 * *(const size_t *)b];
    return (xa > xb) - (xa < xb);
}

static void probe(void *ctx, double x, double y)
{
    cover_ctx *c = ctx;
    const fz_state *st = c->st;
    const double R = st->radius; /* bounds every point's radius */
    size_t lo = 0, hi = st->seen, i;
    c->probes++;
    while (lo < hi) { /* the first point with x >= x - R - slack */
        const size_t mid = lo + (hi - lo) / 2;
        if (st->pts[2 * c->order[mid]] < x - R - c->slack) lo = mid + 1;
        else hi = mid;
    }
    for (i = lo; i < st->seen; i++) {
        const size_t p = c->order[i];
        const double r = fz_radius_of(st, p);
        const double dx = fabs(x - st->pts[2 * p]) / r, dy = fabs(y - st->pts[2 * p + 1]) / r;
        const double reach = 1.0 + 1e-9 + c->slack / r;
        if (st->pts[2 * p] > x + R + c->slack) break;
        if (dx * dx + dy * dy <= reach * reach) return;
    }
    if (fz_fixed_covers(st, x, y)) return;
    FZ_CHECK(0, "the maximal pattern leaves the probe (%.17g, %.17g) of the %s in no disk (%zu "
             "points, R %.17g, box [%.17g,%.17g]x[%.17g,%.17g], %zu rings)", x, y,
             st->shape.kind == FZ_SHAPE_MASK ? "mask" : "polygon", st->seen, R, st->dom[0],
             st->dom[2], st->dom[1], st->dom[3], st->shape.nrings);
}

void fz_shape_coverage(const fz_state *st)
{
    cover_ctx c;
    size_t i;
    if (st->seen == 0 && st->nfix == 0) return;
    c.st = st;
    c.order = malloc((st->seen + 1) * sizeof *c.order);
    FZ_CHECK(c.order != NULL, "harness out of memory");
    for (i = 0; i < st->seen; i++) c.order[i] = i;
    g_pts = st->pts;
    qsort(c.order, st->seen, sizeof *c.order, by_x);
    c.slack = 8.0 * fz_max_abs4(st->dom) * 0x1p-52;
    c.probes = 0;
    fz_shape_probes(&st->shape, probe, &c);
    free(c.order);
}
