/*
 * fuzz_decode.c - the fuzzer's bytes as hostile arguments (see fuzz.h).
 *
 * Most values come from small tables indexed by one byte, so a mutation of
 * one byte moves between meaningful cases (a radius just below the domain's
 * side, an offset of 1e15, NaN) instead of through random bit patterns; raw
 * bits are one choice among others.
 */
#include "fuzz.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))
#define PICK(r, table) ((table)[fz_u8(r) % N_OF(table)])

/* Just below and just above 1. */
#define BELOW_1 0x1.fffffffffffffp-1
#define ABOVE_1 0x1.0000000000001p+0

unsigned fz_u8(fz_reader *r)
{
    if (r->n == 0) return 0;
    r->n--;
    return *r->p++;
}

uint64_t fz_u64(fz_reader *r)
{
    uint64_t v = 0;
    int i;
    for (i = 0; i < 8; i++) v |= (uint64_t)fz_u8(r) << (8 * i);
    return v;
}

static double raw_double(fz_reader *r)
{
    uint64_t bits = fz_u64(r);
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

static const double kHostile[] = {
    NAN,     INFINITY, -INFINITY, 0.0,     -0.0,     0x1p-1074, 0x1.8p-1030, DBL_MIN,
    1e-300,  -1e-300,  1e300,     -1e300,  DBL_MAX,  -DBL_MAX,  1.0,         -1.0,
    0.5,     2.0,      1e15,      -1e15,   1e15 + 0.5, 0x1p-26, 0x1p-900,    0x1p-901,
    1e-5,    1e-6,     1e6,       3.0,     0.1,      -0.1,      1e-3,        0x1p53,
};

double fz_hostile(fz_reader *r)
{
    unsigned sel = fz_u8(r);
    if (sel % 8 == 7) return raw_double(r);
    return kHostile[sel / 8 % N_OF(kHostile)];
}

/* One side of the rectangle, or its diagonal (may overflow to inf). */
static double side(const double dom[4], unsigned which)
{
    const double w = dom[2] - dom[0], h = dom[3] - dom[1];
    switch (which % 4) {
        case 0: return w;
        case 1: return h;
        case 2: return w < h ? w : h;
        default: return sqrt(w * w + h * h);
    }
}

static double max_abs(const double dom[4])
{
    double m = 0.0;
    int i;
    for (i = 0; i < 4; i++)
        if (fabs(dom[i]) > m) m = fabs(dom[i]);
    return m;
}

/* Lower-left corners: 0, a 1e15 offset (coordinates carry only ~53 bits), extremes. */
static const double kOffset[] = {
    0.0,     1e15,  -1e15, 1.0,    -0.5,       1e300,  -1e300,        1e-300,
    0x1p-890, 1e8,  0x1p52, -0x1p52, 12345.678, 1e15 + 0.5, -DBL_MAX / 2, 0.25,
};

/* R / side: one point (>= 1), a few, thousands, then counts only bounded
 * runs may approach. */
static const double kFactor[] = {
    BELOW_1, 1.0,  ABOVE_1, 2.0,   1e10, 0.5,  0.3,  0.1,  0.05, 0.02, 0.01,
    7e-3,    5e-3, 3e-3,    2e-3,  1e-3, 1e-4, 1e-5, 1e-6, 1e-8, 1e-12,
};

/* R / largest |coordinate|, around the precision limit 2^-26 .. 2^-25. */
static const double kPrecision[] = {
    0x1p-26 * BELOW_1, 0x1p-26, 0x1p-26 * ABOVE_1, 0x1p-25 * BELOW_1, 0x1p-25, 0x1p-25 * ABOVE_1,
    0x1p-27,           0x1p-24, 0x1p-20,           0x1p-12,
};

double fz_radius(fz_reader *r, const double dom[4])
{
    unsigned sel = fz_u8(r) % 6;
    double s;
    switch (sel) {
        case 0:
            return fz_hostile(r);
        case 1:
            s = side(dom, fz_u8(r));
            return s * PICK(r, kFactor);
        case 2:
            return raw_double(r);
        case 3:
            return max_abs(dom) * PICK(r, kPrecision);
        case 4:
            /* Near the precision limit of a domain set later at that offset. */
            s = PICK(r, kOffset);
            return s * PICK(r, kPrecision);
        default:
            /* A smooth scale: side * 2^-k * (1 + b/256). */
            s = side(dom, fz_u8(r));
            s = ldexp(s, -(int)(fz_u8(r) % 24));
            return s * (1.0 + fz_u8(r) / 256.0);
    }
}

/* new R / current R for pds_refine: equal (a no-op), larger (EINVAL), smaller. */
static const double kRefine[] = {
    1.0, ABOVE_1, 2.0, BELOW_1, 0.999, 0.9, 0.7, 0.5, 0.3, 0.1, 0.03, 0.01, 1e-3, 1e-6, 1e-9,
};

double fz_refine_radius(fz_reader *r, double current, const double dom[4])
{
    unsigned sel = fz_u8(r) % 4;
    switch (sel) {
        case 0:
        case 1:
            return current * PICK(r, kRefine);
        case 2:
            return fz_radius(r, dom);
        default:
            return nextafter(current, (fz_u8(r) & 1) ? INFINITY : 0.0);
    }
}

/* Width / R: just below and above 1 and 1/sqrt 2 (side or diagonal equal to R). */
static const double kSpan[] = {
    BELOW_1, 1.0,   ABOVE_1, 0.7071067811865475, 0.7071067811865476, 0.5, 2.0, 3.0,
    10.0,    30.0,  100.0,   300.0,              1e-3,               1e6, 1e-300, 1e300,
};

/* Height / width. */
static const double kAspect[] = {1.0, 1e6, 1e-6, 2.0, 0.5, 1e3, 1e-3, 1e12};

/* Absolute widths, for domains chosen before the radius. */
static const double kWidth[] = {1.0, 1e-3, 1e3, 1e6, 1e-6, 1e-300, 1e300, 0x1p-900, 3.0, 1e15};

void fz_domain(fz_reader *r, double radius, double out[4])
{
    unsigned sel = fz_u8(r);
    double w, h;
    int i;

    switch (sel % 4) {
        case 0:
            for (i = 0; i < 4; i++) out[i] = fz_hostile(r);
            return;
        case 2:
            for (i = 0; i < 4; i++) out[i] = raw_double(r);
            return;
        case 1:
            out[0] = PICK(r, kOffset);
            out[1] = PICK(r, kOffset);
            w = radius * PICK(r, kSpan);
            break;
        default:
            out[0] = PICK(r, kOffset);
            out[1] = PICK(r, kOffset);
            w = PICK(r, kWidth);
            break;
    }
    h = w * PICK(r, kAspect);
    if (sel & 4) { /* tall instead of wide */
        double t = w;
        w = h;
        h = t;
    }
    /* The sum rounds: at an offset of 1e15 a small side may vanish (EINVAL). */
    out[2] = out[0] + w;
    out[3] = out[1] + h;
    if (sel & 8) { /* inverted x */
        double t = out[0];
        out[0] = out[2];
        out[2] = t;
    }
}

size_t fz_size(fz_reader *r, size_t n)
{
    switch (fz_u8(r) % 11) {
        case 0: return 0;
        case 1: return 1;
        case 2: return 2;
        case 3: return n - 1; /* SIZE_MAX when n == 0 */
        case 4: return n;
        case 5: return n + 1;
        case 6: return n / 2;
        case 7: return SIZE_MAX;
        case 8: return SIZE_MAX - 1;
        case 9: return SIZE_MAX / 2 + 1;
        default: return fz_u8(r);
    }
}

size_t fz_max_new(fz_reader *r)
{
    switch (fz_u8(r) % 12) {
        case 0: return 0;
        case 1: return 1;
        case 2: return 2;
        case 3: return 7;
        case 4: return 64;
        case 5: return 1000;
        case 6: return SIZE_MAX;
        case 7: return (size_t)UINT32_MAX;
        case 8: return (size_t)UINT32_MAX + 1;
        case 9: return (size_t)1 << 31;
        case 10: return fz_u8(r) + 1;
        default: {
            size_t v = fz_u8(r);
            return (v << 8 | fz_u8(r)) % 4096 + 1;
        }
    }
}

/* n for pds_set_count. The index space holds (2^30 - 1)/3 - ghosts, about
 * 357913941 points; 3e15 is where R(n) of any domain falls below 2^-26 of it. */
static const size_t kCount[] = {
    0,         1,          2,          3,         5,        10,         37,
    100,       500,        1000,       4999,      5000,     20000,      100000,
    2000000,   357913900,  357913941,  400000000, 1000000000, (size_t)1e12, (size_t)3e15,
    (size_t)1e17, SIZE_MAX, SIZE_MAX / 2, (size_t)UINT32_MAX, (size_t)UINT32_MAX + 1,
};

size_t fz_count_n(fz_reader *r)
{
    const unsigned sel = fz_u8(r);
    if (sel % 4 == 3) return fz_u8(r) % 64 + 1; /* small counts, where steps are many */
    return kCount[sel / 4 % N_OF(kCount)];
}

int fz_flag(fz_reader *r)
{
    static const int kFlag[] = {1, 0, -1, 2, INT_MAX, INT_MIN, 1, 0};
    return PICK(r, kFlag);
}
