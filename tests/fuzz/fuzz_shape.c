/*
 * fuzz_shape.c - the harness's own model of a polygon or mask domain (1.4,
 * see fuzz.h): what the contract says of given rings, whether a point lies in
 * the closed domain, its area, and the probes of a maximal pattern's coverage.
 * Nothing here asks the library.
 *
 * Coordinates are normalized to the domain's bounding box, u = (x - x0) /
 * (x1 - x0) (halves first, so nothing overflows): the rings' vertices are
 * exact doubles and so are the library's points, so their differences keep
 * ~1e-16 of the box, and a point within 1e-12 of the box from an edge is
 * taken as on it (the library decides exactly; this test only rounds).
 *   - inside: closed, by the even-odd rule (a ray's crossings), or on an edge;
 *   - area: exact for straight edges: between consecutive vertex (and
 *     crossing) abscissae the edges do not cross, so the inside of a slab is
 *     trapezoids, measured at the slab's middle;
 *   - a mask is one square ring per inside pixel (shared sides cancel in
 *     pairs), its grid lines x0 + (x1 - x0) * (i / w).
 */
#include "fuzz.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TOL 1e-12

static double norm(double c, double lo, double hi)
{
    return (c * 0.5 - lo * 0.5) / (hi * 0.5 - lo * 0.5);
}

void fz_shape_free(fz_shape *sh)
{
    free(sh->xy);
    free(sh->ends);
    free(sh->pix);
    free(sh->u);
    sh->xy = sh->u = NULL;
    sh->ends = NULL;
    sh->pix = NULL;
    sh->nrings = sh->nv = sh->mw = sh->mh = 0;
    sh->kind = FZ_SHAPE_NONE;
}

/* Ring k's cleaned vertices in sh->u (normalized): consecutive repeats and a
 * repeated closing vertex dropped, as the header allows them. */
static size_t ring_start(const fz_shape *sh, size_t k) { return k ? sh->ends[k - 1] : 0; }

typedef struct {
    double ax, ay, bx, by; /* a is the endpoint with the smaller x (then y) */
} edge;

/* Every edge of nonzero length, in normalized coordinates. */
static size_t edges_of(const fz_shape *sh, edge *out)
{
    size_t k, i, m = 0;
    for (k = 0; k < sh->nrings; k++) {
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        for (i = s; i < e; i++) {
            const size_t j = i + 1 < e ? i + 1 : s;
            double ax = sh->u[2 * i], ay = sh->u[2 * i + 1], bx = sh->u[2 * j], by = sh->u[2 * j + 1];
            if (ax == bx && ay == by) continue;
            if (bx < ax || (bx == ax && by < ay)) {
                double t = ax;
                ax = bx;
                bx = t;
                t = ay;
                ay = by;
                by = t;
            }
            out[m].ax = ax;
            out[m].ay = ay;
            out[m].bx = bx;
            out[m].by = by;
            m++;
        }
    }
    return m;
}

static int by_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double orient(double ax, double ay, double bx, double by, double cx, double cy)
{
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/* The even-odd area over the box's area; *crossings counts the pairs of edges
 * that cross. */
static double slab_area(const fz_shape *sh, size_t *crossings)
{
    const size_t nv = sh->nv;
    edge *ed = malloc((nv + 1) * sizeof *ed);
    double *xs, *ys, total = 0.0;
    size_t m, nx = 0, i, j;

    FZ_CHECK(ed != NULL, "harness out of memory");
    m = edges_of(sh, ed);
    xs = malloc((2 * m + m * m + 1) * sizeof *xs);
    ys = malloc((m + 1) * sizeof *ys);
    FZ_CHECK(xs != NULL && ys != NULL, "harness out of memory");
    *crossings = 0;
    for (i = 0; i < m; i++) {
        xs[nx++] = ed[i].ax;
        xs[nx++] = ed[i].bx;
    }
    if (sh->kind == FZ_SHAPE_POLYGON) /* a mask's squares never cross */
        for (i = 0; i < m; i++)
            for (j = i + 1; j < m; j++) {
                const edge *p = &ed[i], *q = &ed[j];
                const double o1 = orient(p->ax, p->ay, p->bx, p->by, q->ax, q->ay);
                const double o2 = orient(p->ax, p->ay, p->bx, p->by, q->bx, q->by);
                const double o3 = orient(q->ax, q->ay, q->bx, q->by, p->ax, p->ay);
                const double o4 = orient(q->ax, q->ay, q->bx, q->by, p->bx, p->by);
                if (((o1 > 1e-14 && o2 < -1e-14) || (o1 < -1e-14 && o2 > 1e-14)) &&
                    ((o3 > 1e-14 && o4 < -1e-14) || (o3 < -1e-14 && o4 > 1e-14))) {
                    xs[nx++] = q->ax + (q->bx - q->ax) * (o1 / (o1 - o2));
                    ++*crossings;
                }
            }
    qsort(xs, nx, sizeof *xs, by_double);
    for (i = 0; i + 1 < nx; i++) {
        const double x0 = xs[i], x1 = xs[i + 1], xm = 0.5 * (x0 + x1);
        size_t ny = 0, k;
        double len = 0.0;
        if (!(x1 > x0)) continue;
        for (j = 0; j < m; j++) {
            const edge *e = &ed[j];
            if (e->ax <= x0 && e->bx >= x1) /* canonical endpoints: equal edges, equal values */
                ys[ny++] = e->ay + (e->by - e->ay) * ((xm - e->ax) / (e->bx - e->ax));
        }
        qsort(ys, ny, sizeof *ys, by_double);
        for (k = 0; k + 1 < ny; k += 2) len += ys[k + 1] - ys[k];
        total += len * (x1 - x0);
    }
    free(ed);
    free(xs);
    free(ys);
    return total;
}

/* Whether a ring turns straight back at a vertex (a zero-width spike): the
 * library drops such tips as it reads the rings, so its perimeter (and the
 * count mode's radius) is not the harness's. */
static int has_spike_tip(const fz_shape *sh)
{
    size_t r, s = 0;
    for (r = 0; r < sh->nrings; s = sh->ends[r], r++) {
        const size_t e = sh->ends[r], n = e - s;
        size_t v;
        for (v = 0; v < n && n >= 3; v++) {
            const double *p = &sh->xy[2 * (s + (v + n - 1) % n)], *q = &sh->xy[2 * (s + v)],
                         *t = &sh->xy[2 * (s + (v + 1) % n)];
            const double ax = q[0] - p[0], ay = q[1] - p[1], bx = t[0] - q[0], by = t[1] - q[1];
            if ((ax != 0.0 || ay != 0.0) && (bx != 0.0 || by != 0.0) && ax * by - ay * bx == 0.0 &&
                ax * bx + ay * by < 0.0)
                return 1;
        }
    }
    return 0;
}

/* Whether a vertex lies within `reach` of an edge of another ring, or of an
 * edge of its own ring that does not end at it (the library then merges or
 * splits there, moving the outline by about that much); *perimeter gets the
 * edges' total length. */
static int has_near_features(const fz_shape *sh, double reach, double *perimeter)
{
    size_t r, s = 0, v, t;
    int near = 0;
    *perimeter = 0.0;
    for (r = 0; r < sh->nrings; s = sh->ends[r], r++)
        for (t = s; t < sh->ends[r]; t++) {
            const size_t u = t + 1 < sh->ends[r] ? t + 1 : s;
            const double ax = sh->xy[2 * t], ay = sh->xy[2 * t + 1], dx = sh->xy[2 * u] - ax,
                         dy = sh->xy[2 * u + 1] - ay, len2 = dx * dx + dy * dy;
            *perimeter += sqrt(len2);
            for (v = 0; v < sh->nv && !near; v++) {
                if (v == t || v == u) continue;
                const double px = sh->xy[2 * v] - ax, py = sh->xy[2 * v + 1] - ay;
                double w = len2 > 0.0 ? (px * dx + py * dy) / len2 : 0.0;
                w = w < 0.0 ? 0.0 : (w > 1.0 ? 1.0 : w);
                if (hypot(px - w * dx, py - w * dy) <= reach) near = 1;
            }
        }
    return near;
}

/* The box, the normalized copy and the measures, from xy and ends. */
static void measure(fz_shape *sh)
{
    size_t i;
    double m = 0.0; /* the largest |coordinate| */
    sh->box[0] = sh->box[2] = sh->xy[0];
    sh->box[1] = sh->box[3] = sh->xy[1];
    for (i = 0; i < sh->nv; i++) {
        const double x = sh->xy[2 * i], y = sh->xy[2 * i + 1];
        if (x < sh->box[0]) sh->box[0] = x;
        if (x > sh->box[2]) sh->box[2] = x;
        if (y < sh->box[1]) sh->box[1] = y;
        if (y > sh->box[3]) sh->box[3] = y;
    }
    free(sh->u);
    sh->u = malloc((2 * sh->nv + 2) * sizeof *sh->u);
    FZ_CHECK(sh->u != NULL, "harness out of memory");
    for (i = 0; i < sh->nv; i++) {
        sh->u[2 * i] = norm(sh->xy[2 * i], sh->box[0], sh->box[2]);
        sh->u[2 * i + 1] = norm(sh->xy[2 * i + 1], sh->box[1], sh->box[3]);
    }
    sh->frac = slab_area(sh, &sh->crossings);
    sh->area_known = !has_spike_tip(sh) && sh->box[0] < sh->box[2] && sh->box[1] < sh->box[3];
    for (i = 0; i < 2 * sh->nv; i++)
        if (fabs(sh->xy[i]) > m) m = fabs(sh->xy[i]);
    if (sh->crossings > 0) { /* the library's rounded crossings (snapped to an end within 2^-44
                              * of the largest |coordinate|) move its area: checked while that
                              * stays below 1e-10 of it */
        const double size = fmin(sh->box[2] * 0.5 - sh->box[0] * 0.5, sh->box[3] * 0.5 - sh->box[1] * 0.5);
        if (!((double)sh->crossings * 0x1p-44 * (0.5 * m / size) <= 1e-10 * sh->frac)) sh->area_known = 0;
    }
    if (sh->area_known) { /* vertices merged (2^-43 of the largest |coordinate|) or taken
                           * as on an edge (2^-44) move the area by the perimeter times
                           * that at most: checked while that stays below 1e-10 of it */
        double perimeter;
        const double area = sh->frac * (sh->box[2] - sh->box[0]) * (sh->box[3] - sh->box[1]);
        if (has_near_features(sh, 0x1p-42 * m, &perimeter) && !(perimeter * 0x1p-42 * m <= 1e-10 * area))
            sh->area_known = 0;
    }
}

/* Copies of the rings (cleaned as the header allows: consecutive repeats and a
 * closing repeat dropped). Returns what the contract says: 1 accepted, 0
 * refused (PDS_EINVAL), -1 either (near the edge of the rules: found/NOTES). */
int fz_shape_polygon(fz_shape *sh, const double *xy, const size_t *ends, size_t nrings)
{
    size_t k, v, start = 0, total = 0, out = 0;
    int verdict = 1;

    memset(sh, 0, sizeof *sh);
    sh->kind = FZ_SHAPE_POLYGON;
    for (k = 0; k < nrings; start = ends[k++])
        if (ends[k] < start) return 0;
    total = ends[nrings - 1];
    for (v = 0; v < 2 * total; v++)
        if (!isfinite(xy[v])) return 0;
    sh->xy = malloc((2 * total + 2) * sizeof *sh->xy);
    sh->ends = malloc(nrings * sizeof *sh->ends);
    FZ_CHECK(sh->xy != NULL && sh->ends != NULL, "harness out of memory");
    start = 0;
    for (k = 0; k < nrings; start = ends[k++]) {
        const size_t first = out;
        size_t distinct = 0, i, j;
        for (v = start; v < ends[k]; v++) {
            if (out > first && xy[2 * v] == sh->xy[2 * out - 2] && xy[2 * v + 1] == sh->xy[2 * out - 1])
                continue;
            sh->xy[2 * out] = xy[2 * v];
            sh->xy[2 * out + 1] = xy[2 * v + 1];
            out++;
        }
        while (out > first + 1 && sh->xy[2 * out - 2] == sh->xy[2 * first] &&
               sh->xy[2 * out - 1] == sh->xy[2 * first + 1])
            out--;
        for (i = first; i < out; i++) { /* distinct anywhere in the ring */
            for (j = first; j < i; j++)
                if (sh->xy[2 * i] == sh->xy[2 * j] && sh->xy[2 * i + 1] == sh->xy[2 * j + 1]) break;
            distinct += j == i;
        }
        if (distinct < 3) return 0;
        sh->ends[k] = out;
    }
    sh->nrings = nrings;
    sh->nv = out;
    measure(sh);
    /* All on one line: refused, but a float test cannot tell near-collinear. */
    for (k = 0; k < nrings; k++) {
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        const double *u = sh->u;
        double most = 0.0;
        for (v = s + 2; v < e; v++) {
            const double o = fabs(orient(u[2 * s], u[2 * s + 1], u[2 * s + 2], u[2 * s + 3], u[2 * v],
                                         u[2 * v + 1]));
            if (o > most) most = o;
        }
        if (!(most > 1e-9)) verdict = -1;
    }
    /* A ring whose edges are all below 2^-32 of the largest |coordinate| (edges of
     * a few ulps, far below the precision limit 2^-26 of it): the library finds
     * no side of it (its probes, 2^-20 of an edge away, round onto the edge) and
     * leaves it out of the area, refusing the outline when no ring is left
     * (found/NOTES, polygon_below_resolution). */
    for (k = 0; k < nrings; k++) {
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        double m = 0.0, longest = 0.0;
        for (v = 0; v < 2 * sh->nv; v++)
            if (fabs(sh->xy[v]) > m) m = fabs(sh->xy[v]);
        for (v = s; v < e; v++) {
            const size_t n2 = v + 1 < e ? v + 1 : s;
            const double l = hypot(sh->xy[2 * n2] * 0.5 - sh->xy[2 * v] * 0.5,
                                   sh->xy[2 * n2 + 1] * 0.5 - sh->xy[2 * v + 1] * 0.5);
            if (l > longest) longest = l;
        }
        if (longest < 0x1p-30 * m) {
            sh->area_known = 0;
            sh->fine = 1;
            if (!fz_strict()) verdict = -1;
        }
    }
    for (k = 0; k < nrings; k++) { /* a zero-width spike: b - a and c - b opposite */
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        const double *u = sh->u;
        for (v = s; v < e; v++) {
            const size_t b = v + 1 < e ? v + 1 : s, c = b + 1 < e ? b + 1 : s;
            const double abx = u[2 * b] - u[2 * v], aby = u[2 * b + 1] - u[2 * v + 1];
            const double bcx = u[2 * c] - u[2 * b], bcy = u[2 * c + 1] - u[2 * b + 1];
            /* (or nearly: a spike 1e-16 wide hangs pds_run too, found/NOTES) */
            if (fabs(abx * bcy - aby * bcx) <= 1e-9 * hypot(abx, aby) * hypot(bcx, bcy) &&
                abx * bcx + aby * bcy < 0.0)
                sh->antenna = 1;
        }
    }
    /* The library's area of a ring with a nearly zero-width spike is not the
     * even-odd area (found/NOTES, polygon_near_spike_area). */
    if (sh->antenna) sh->area_known = 0;
    { /* Every |coordinate| below 2^-500: the library's predicates underflow and call
       * a star "on one line" (found/NOTES, polygon_tiny_collinear). Beyond 2^500
       * the library reads the rings a power of two away, unless a nonzero
       * coordinate would not stay a normal number there: then they overflow
       * (polygon_huge_mixed_magnitudes; the first point refuses such a domain). */
        double m = 0.0, lo = HUGE_VAL;
        for (v = 0; v < 2 * sh->nv; v++) {
            if (fabs(sh->xy[v]) > m) m = fabs(sh->xy[v]);
            if (sh->xy[v] != 0.0 && fabs(sh->xy[v]) < lo) lo = fabs(sh->xy[v]);
        }
        if (m < 0x1p-500 && !fz_strict() && verdict == 1) verdict = -1;
        if (m > 0x1p500 && lo < 0x1p-1000 * m && !fz_strict() && verdict == 1) verdict = -1;
    }
    if (!(sh->box[0] < sh->box[2] && sh->box[1] < sh->box[3])) return verdict == 1 ? 0 : -1;
    if (sh->frac == 0.0 && verdict == 1) return 0; /* encloses nothing: a ring traced twice */
    if (!(sh->frac > 1e-6)) return -1;
    if (!sh->area_known && !fz_strict()) return -1;
    return verdict;
}

/* grid line i of n over [lo, hi], in units of a power of two near the
 * larger end, so that hi - lo cannot overflow (as the library reads them) */
static double grid(double lo, double hi, size_t i, size_t n)
{
    const double m = fabs(lo) > fabs(hi) ? fabs(lo) : fabs(hi);
    const int k = m > 0.0 ? ilogb(m) : 0;
    const double a = ldexp(lo, -k), b = ldexp(hi, -k);
    if (i == 0) return lo;
    if (i == n) return hi;
    return ldexp(a + (b - a) * ((double)i / (double)n), k);
}

int fz_shape_mask(fz_shape *sh, size_t w, size_t h, const unsigned char *pix, const double rect[4])
{
    size_t i, j, n = 0, out = 0;
    int verdict = 1;

    memset(sh, 0, sizeof *sh);
    sh->kind = FZ_SHAPE_MASK;
    memcpy(sh->rect, rect, sizeof sh->rect);
    for (i = 0; i < w * h; i++) n += pix[i] != 0;
    if (n == 0) return 0;
    sh->pix = malloc(w * h);
    sh->xy = malloc(8 * n * sizeof *sh->xy);
    sh->ends = malloc(n * sizeof *sh->ends);
    FZ_CHECK(sh->pix != NULL && sh->xy != NULL && sh->ends != NULL, "harness out of memory");
    memcpy(sh->pix, pix, w * h);
    sh->mw = w;
    sh->mh = h;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            const double x0 = grid(rect[0], rect[2], i, w), x1 = grid(rect[0], rect[2], i + 1, w);
            const double y0 = grid(rect[1], rect[3], j, h), y1 = grid(rect[1], rect[3], j + 1, h);
            double *p = sh->xy + 2 * out;
            if (!pix[j * w + i]) continue;
            /* Lines that round together or overflow: the outline degenerates (found/NOTES). */
            if (!(x0 < x1 && y0 < y1) || !isfinite(x1 - x0) || !isfinite(y1 - y0)) verdict = -1;
            p[0] = x0, p[1] = y0, p[2] = x1, p[3] = y0, p[4] = x1, p[5] = y1, p[6] = x0, p[7] = y1;
            out += 4;
            sh->ends[sh->nrings++] = out;
        }
    sh->nv = out;
    measure(sh);
    { /* The library's outline touches only at corners, so its area is the
       * pixels' unless their lines lie within rounding of one another: a pixel
       * side below 2^30 ulps of the rectangle's coordinates (found/NOTES,
       * mask_rounded_lines_count_radius). */
        double m = 0.0;
        for (i = 0; i < 4; i++)
            if (fabs(rect[i]) > m) m = fabs(rect[i]);
        sh->area_known = (rect[2] - rect[0]) / (double)w >= 0x1p-22 * m &&
                         (rect[3] - rect[1]) / (double)h >= 0x1p-22 * m;
        /* Pixel sides below 2^-30 of the coordinates: the outline's sides are
         * probed within rounding, as polygon_below_resolution's. */
        if ((rect[2] - rect[0]) / (double)w < 0x1p-30 * m || (rect[3] - rect[1]) / (double)h < 0x1p-30 * m) {
            sh->fine = 1;
            if (verdict == 1 && !fz_strict()) verdict = -1;
        }
        { /* Corners beyond 2^500 beside a nonzero one no scale keeps exact: refused
           * (found/NOTES, mask_magnitudes_beyond_any_scale), as such a polygon. */
            double lo = HUGE_VAL;
            for (i = 0; i < 4; i++)
                if (rect[i] != 0.0 && fabs(rect[i]) < lo) lo = fabs(rect[i]);
            if (m > 0x1p500 && lo < 0x1p-1000 * m && verdict == 1 && !fz_strict()) verdict = -1;
        }
    }
    sh->v_lo = 4;
    sh->v_hi = 4 * n;
    return verdict;
}

/* The distance from (px, py) to the segment, squared (normalized units). */
static double seg_dist2(double px, double py, double ax, double ay, double bx, double by)
{
    const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0.0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0.0, ex, ey;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    ex = px - (ax + t * dx);
    ey = py - (ay + t * dy);
    return ex * ex + ey * ey;
}

/* 1 inside or within tol of an edge, 0 outside; *margin: the distance to the nearest edge. */
static int locate(const fz_shape *sh, double x, double y, double tol, double *margin)
{
    const double px = norm(x, sh->box[0], sh->box[2]), py = norm(y, sh->box[1], sh->box[3]);
    const double *u = sh->u;
    double best = INFINITY;
    int odd = 0;
    size_t k, i;

    if (!(px >= -tol && px <= 1.0 + tol && py >= -tol && py <= 1.0 + tol)) return 0;
    for (k = 0; k < sh->nrings; k++) {
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        for (i = s; i < e; i++) {
            const size_t j = i + 1 < e ? i + 1 : s;
            const double ax = u[2 * i], ay = u[2 * i + 1], bx = u[2 * j], by = u[2 * j + 1];
            const double d2 = seg_dist2(px, py, ax, ay, bx, by);
            if (d2 < best) best = d2;
            if ((ay > py) != (by > py) && px < ax + (py - ay) / (by - ay) * (bx - ax)) odd = !odd;
        }
    }
    if (margin) *margin = sqrt(best);
    return odd || best <= tol * tol;
}

int fz_shape_inside(const fz_shape *sh, double x, double y)
{
    return locate(sh, x, y, TOL, NULL);
}

/* The library's vertex count (polygon: the cleaned rings). */
void fz_shape_vertices(const fz_shape *sh, size_t *lo, size_t *hi)
{
    *lo = sh->kind == FZ_SHAPE_MASK ? sh->v_lo : sh->nv;
    *hi = sh->kind == FZ_SHAPE_MASK ? sh->v_hi : sh->nv;
}

/* The outline's length (a mask: the sides between inside and outside pixels),
 * with every coordinate scaled by 2^-e. */
double fz_shape_perimeter(const fz_shape *sh, int e)
{
    double sum = 0.0;
    size_t k, i, j;
    if (sh->kind == FZ_SHAPE_MASK) {
        const size_t w = sh->mw, h = sh->mh;
        const double *r = sh->rect;
        for (j = 0; j < h; j++)
            for (i = 0; i < w; i++) {
                const double pw = ldexp(grid(r[0], r[2], i + 1, w), -e) - ldexp(grid(r[0], r[2], i, w), -e);
                const double ph = ldexp(grid(r[1], r[3], j + 1, h), -e) - ldexp(grid(r[1], r[3], j, h), -e);
                if (!sh->pix[j * w + i]) continue;
                sum += (j == 0 || !sh->pix[(j - 1) * w + i]) ? pw : 0.0;
                sum += (j + 1 == h || !sh->pix[(j + 1) * w + i]) ? pw : 0.0;
                sum += (i == 0 || !sh->pix[j * w + i - 1]) ? ph : 0.0;
                sum += (i + 1 == w || !sh->pix[j * w + i + 1]) ? ph : 0.0;
            }
        return sum;
    }
    for (k = 0; k < sh->nrings; k++) {
        const size_t s = ring_start(sh, k), end = sh->ends[k];
        for (i = s; i < end; i++) {
            const size_t n = i + 1 < end ? i + 1 : s;
            sum += hypot(ldexp(sh->xy[2 * n], -e) - ldexp(sh->xy[2 * i], -e),
                         ldexp(sh->xy[2 * n + 1], -e) - ldexp(sh->xy[2 * i + 1], -e));
        }
    }
    return sum;
}

/* Whether a polygon's edge from (ax, ay) to (bx, by) is traced an even
 * number of times (a ring traced twice): by the even-odd rule its sides are
 * alike, so its points need not be the domain's (the library skips such
 * edges; both sides inside, they are covered anyway). */
static int edge_cancelled(const fz_shape *sh, double ax, double ay, double bx, double by)
{
    size_t k, i, same = 0;
    if (sh->kind != FZ_SHAPE_POLYGON) return 0;
    for (k = 0; k < sh->nrings; k++) {
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        for (i = s; i < e; i++) {
            const size_t j = i + 1 < e ? i + 1 : s;
            const double px = sh->xy[2 * i], py = sh->xy[2 * i + 1], qx = sh->xy[2 * j], qy = sh->xy[2 * j + 1];
            if ((px == ax && py == ay && qx == bx && qy == by) || (px == bx && py == by && qx == ax && qy == ay))
                same++;
        }
    }
    return same % 2 == 0;
}

/* Whether the point at t along the edge a -> b belongs to the closed domain,
 * the closure of the even-odd inside: a point beside it, 1e-9 of the box to
 * either hand (at t = 0, taken 1e-6 along the edge: a spike's tip), is
 * inside and off every edge. Where collinear edges overlap in part, the part
 * traced twice has the same side on both hands, and often inside on neither
 * (a ring's side along a hole's side): such points are not the domain's. */
static int touches_inside(const fz_shape *sh, double ax, double ay, double bx, double by, double t)
{
    const double ua = norm(ax, sh->box[0], sh->box[2]), va = norm(ay, sh->box[1], sh->box[3]);
    const double ub = norm(bx, sh->box[0], sh->box[2]), vb = norm(by, sh->box[1], sh->box[3]);
    const double len = hypot(ub - ua, vb - va), at = t > 1e-6 ? t : 1e-6;
    const double hw = sh->box[2] * 0.5 - sh->box[0] * 0.5, hh = sh->box[3] * 0.5 - sh->box[1] * 0.5;
    int side;
    if (!(len > 0.0)) return 1; /* a repeated vertex: probed as before */
    for (side = -1; side <= 1; side += 2) {
        /* the unit normal in the box's units, back to the user's */
        const double nu = -(vb - va) / len * side, nv = (ub - ua) / len * side;
        const double x = ax * (1.0 - at) + bx * at + 2e-9 * hw * nu;
        const double y = ay * (1.0 - at) + by * at + 2e-9 * hh * nv;
        double margin;
        if (locate(sh, x, y, 0.0, &margin) && margin > TOL) return 1;
    }
    return 0;
}

/* Probes of the closed domain: every vertex, points along every edge (but
 * those traced twice, and points of the edges outside the closed domain),
 * and a grid of points well inside. fn returns 0 to stop. */
void fz_shape_probes(const fz_shape *sh, void (*fn)(void *ctx, double x, double y), void *ctx)
{
    size_t k, i, a, b;
    for (k = 0; k < sh->nrings; k++) {
        const size_t s = ring_start(sh, k), e = sh->ends[k];
        for (i = s; i < e; i++) {
            const size_t j = i + 1 < e ? i + 1 : s;
            const double ax = sh->xy[2 * i], ay = sh->xy[2 * i + 1];
            const double bx = sh->xy[2 * j], by = sh->xy[2 * j + 1];
            if (edge_cancelled(sh, ax, ay, bx, by)) continue;
            if (touches_inside(sh, ax, ay, bx, by, 0.0)) fn(ctx, ax, ay);
            for (a = 1; a < 4; a++) {
                const double t = (double)a / 4.0, x = ax * (1.0 - t) + bx * t, y = ay * (1.0 - t) + by * t;
                if (touches_inside(sh, ax, ay, bx, by, t)) fn(ctx, x, y);
            }
        }
    }
    for (a = 0; a < 8; a++)
        for (b = 0; b < 8; b++) {
            const double x = grid(sh->box[0], sh->box[2], 2 * a + 1, 16);
            const double y = grid(sh->box[1], sh->box[3], 2 * b + 1, 16);
            double margin;
            if (locate(sh, x, y, 0.0, &margin) && margin > 1e-9) fn(ctx, x, y);
        }
}
