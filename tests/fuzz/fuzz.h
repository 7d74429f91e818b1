/*
 * fuzz.h - shared declarations of the libFuzzer harness (see fuzz_api.c).
 *
 * fuzz_decode.c turns the fuzzer's bytes into hostile arguments;
 * fuzz_check.c holds the contract checks, which abort() on a violation so
 * libFuzzer reports the input, and fuzz_torus.c the model of the torus and
 * of count mode; fuzz_ops.c, fuzz_ops12.c and fuzz_misc.c make the calls and
 * fuzz_api.c, the entry point, chooses them from the input; fuzz_progress.c
 * is the progress callback, fuzz_replay.c the determinism check; fuzz_field.c
 * the radius fields of 1.3 (the maps, the harness's radius function, pds_radii
 * and the model of a point's radius).
 */
#ifndef PDS_FUZZ_H
#define PDS_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <time.h>

#include <poissondisk.h>

/* 1.1.1 judges radius and domain at the first point, not when they are set:
 * pds_create and pds_set_domain no longer return PDS_ERANGE, pds_step and
 * pds_run may. The checks follow the header this harness is compiled with. */
#ifndef FZ_SPEC_111 /* -DFZ_SPEC_111=1 tries the 1.1.1 checks on an older library */
#define FZ_SPEC_111 (PDS_VERSION_NUMBER >= 10101)
#endif

/* ---- decoding (fuzz_decode.c) ------------------------------------------------- */

typedef struct {
    const uint8_t *p;
    size_t n;
} fz_reader;

/* Past the end of the input every read gives zeros. */
unsigned fz_u8(fz_reader *r);
uint64_t fz_u64(fz_reader *r);
/* NaN, infinities, signed zeros, denormals, 1e+-300, DBL_MAX, raw bits... */
double fz_hostile(fz_reader *r);
/* A radius: hostile, a fraction of the domain's side (just below and above
 * 1 included), or near the precision limit 2^-26 of the largest |coordinate|
 * (of dom, or of an offset a later domain may have). */
double fz_radius(fz_reader *r, const double dom[4]);
/* A smaller (or equal, or slightly larger) radius for pds_refine. */
double fz_refine_radius(fz_reader *r, double current, const double dom[4]);
/* A rectangle: hostile values, offsets of 1e15, aspect ratios of 1e6, sides
 * just below and above the radius, or raw bits. May be empty or inverted. */
void fz_domain(fz_reader *r, double radius, double out[4]);
/* A size_t around n: 0, n-1, n, n+1, SIZE_MAX, ... */
size_t fz_size(fz_reader *r, size_t n);
/* A max_new for pds_run: 0 (no limit), small, or huge. */
size_t fz_max_new(fz_reader *r);
/* An n for pds_set_count: 0, small, around the budget, around the index
 * space (~3.58e8), far beyond it. */
size_t fz_count_n(fz_reader *r);
/* A flag for pds_set_periodic: 0, 1 and other nonzero ints. */
int fz_flag(fz_reader *r);

/* ---- the harness's model of one sampler (fuzz_check.c) -------------------------- */

/* The progress callback's settings and what it saw during the current pds_run. */
typedef struct {
    int on;                /* a callback is set on s */
    unsigned cancel_every; /* ask to stop at every k-th call (0: never) */
    unsigned change;       /* which changing call to try from inside (0: none) */
    size_t calls;          /* calls since it was set */
    int in_run;            /* fz_run is inside pds_run: the only place fn may run */
    size_t run_calls, run_before, last_count;
    double last_done, run_radius;
    size_t stops;          /* calls in this run that asked to stop */
    int last_stopped;      /* the latest call asked to stop */
    time_t started;
} fz_progress;

/* The harness's radius function (pds_set_radius_fn, fuzz_field.c): its user
 * data. The values follow `shape` over the domain between lo and hi (within
 * the declared [rmin, rmax]); a bad value (`bad`: out of bounds or not finite,
 * as the input chose) comes back inside a band of the domain, and everywhere
 * while `toggled` (set and cleared by an operation between calls). */
typedef struct fz_state fz_state;

/* A polygon or mask domain as the harness sees it (1.4). dom in fz_state is
 * then the domain's bounding box; rect is pds_set_domain's rectangle, which a
 * mask is spread over and nrings 0 goes back to. */
enum { FZ_SHAPE_NONE, FZ_SHAPE_POLYGON, FZ_SHAPE_MASK };
typedef struct {
    int kind;
    double *xy;          /* the cleaned rings; a mask: one square ring per inside pixel */
    size_t *ends, nrings, nv;
    double *u;           /* xy normalized to the box */
    unsigned char *pix;  /* a mask's pixels, w x h */
    size_t mw, mh;
    double rect[4];      /* the rectangle of pds_set_domain */
    double box[4];       /* the domain's bounding box */
    double frac;         /* the even-odd area over the box's */
    int area_known;      /* the library's area is the even-odd one (no spike tip) */
    size_t crossings;    /* pairs of edges that cross: the library splits them at the
                          * crossing points rounded, which moves its area by up to
                          * about an ulp of the coordinates times the edges' lengths */
    size_t v_lo, v_hi;   /* a mask: bounds on the outline's vertex count */
    int antenna;         /* a ring turns straight back along its last edge: pds_run
                          * never returns (found/NOTES), so no point is asked for
                          * unless PDS_FUZZ_STRICT is set */
    int fine;            /* edges or pixel sides below 2^-30 of the coordinates: a
                          * maximal run may fail pds_verify near the outline
                          * (found/NOTES, mask_fine_pixels_verify), so no point is
                          * asked for unless PDS_FUZZ_STRICT is set */
} fz_shape;

typedef struct {
    double rmin, rmax;  /* the declared bounds */
    double lo, hi;      /* the values span [lo, hi] */
    double dom[4];      /* the sampler's domain (followed by pds_set_domain) */
    unsigned shape;     /* constant, gradient, diagonal, step, smooth, checker, radial, spike */
    unsigned param;     /* frequency, cells, centre of the shape */
    int band;           /* a bad value for u = (x - x0) / (x1 - x0) in [band0, band1) */
    double band0, band1;
    double bad;         /* the value returned where it is bad */
    int toggled;        /* bad everywhere */
    unsigned change;    /* which changing call to try from inside (0: none) */
    fz_state *st;       /* NULL in the replay: no calls from inside */
    size_t calls, bad_calls; /* calls so far, and those that returned a bad value */
} fz_field_fn;

/* A successful pds_refine at `count` points: replayed by fz_replay_check. */
typedef struct {
    size_t count;
    double radius;
} fz_event;
#define FZ_MAX_EVENTS 64

struct fz_state {
    pds_sampler *s;
    double dom[4];  /* x0 y0 x1 y1 of s, as last set successfully */
    double radius;  /* what pds_radius(s) must return */
    double *pts;    /* the points read so far, x,y interleaved: they never change */
    double *tmp;    /* scratch for reading them again */
    size_t count;   /* what pds_count(s) must return */
    size_t seen;    /* how many points pts holds (fz_sync reads the new ones) */
    size_t cap;     /* capacity of pts and tmp, in points */
    int maximal;    /* s said the pattern is maximal at this radius (count mode: has n points) */
    int checked;    /* that maximal pattern's contract was checked */
    size_t budget;  /* points this input may still add (keeps it fast) */
    char msg[512];  /* pds_errmsg(s) after the last call on s */
    /* 1.2 */
    int periodic;   /* pds_set_periodic(s, nonzero) is in force */
    double per[2];  /* the periods on the torus (x1-x0, y1-y0 rounded down to q) */
    double per_scaled[2]; /* the same in units of 2^ilogb(largest |coordinate|): never inf */
    double q;       /* the torus's quantum 2^(e-50); 0 when not periodic */
    size_t target;  /* count mode: the n of pds_set_count; 0 otherwise */
    fz_progress prog;
    double c_radius; /* pds_create's arguments, for the replay */
    uint64_t c_seed;
    fz_event ev[FZ_MAX_EVENTS];
    size_t n_ev;     /* FZ_MAX_EVENTS + 1: too many to replay */
    int run_failed;  /* a step or run failed after the first point (ENOMEM, ERANGE) */
    /* 1.3: the radius field in force (set successfully and not replaced) */
    int field;       /* FZ_FIELD_NONE, _MAP or _FN */
    double f_rmin, f_rmax; /* the map's smallest and largest values, or the declared bounds */
    double *map;     /* a copy of the map (row-major, row 0 along y0) */
    size_t map_w, map_h;
    fz_field_fn fns[2]; /* the function's user data: a failed pds_set_radius_fn */
    int fn_active;   /* must not change the one in force, so the next is set in the other */
    double *rad;     /* the radii read with the points (pds_radii), like pts */
    double *rad_tmp;
    double rad_at;   /* pds_radius when rad was read (a refine scales them) */
    /* A bad value refused the first point (field_first_point_rng, fixed in 1.3:
     * a change before the first point then gives a fresh sampler's points). */
    int refused_first, known_rng;
    /* 1.4: a polygon or mask domain (fuzz_shape.c, fuzz_domains.c) */
    fz_shape shape;
    /* 1.5: a successful pds_set_threads before the first point selected the
     * parallel process (its points differ from the single-thread process's,
     * so the replay selects it too); later calls only change the count. */
    int parallel;
    /* 1.4: the fixed points in force (fuzz_fixed.c) */
    double *fix_xy, *fix_c; /* as given; fix_c all 0 when given as NULL */
    size_t nfix;
    int fix_c_null;
    double fix_ref;  /* the radius the run started with (clearances scale from it); 0 before */
};
enum { FZ_FIELD_NONE, FZ_FIELD_MAP, FZ_FIELD_FN };

/* Bit of a return code in an "allowed codes" mask (codes -6 .. 1). */
#define FZ_BIT(code) (1u << ((code) + 6))
#define FZ_OK (FZ_BIT(0))
#define FZ_MORE (FZ_BIT(1))

/* The largest |d[i]| of a box's four coordinates. */
double fz_max_abs4(const double d[4]);

/* PDS_FUZZ_STRICT is set in the environment: no tolerance for open bugs of
 * found/NOTES (none open now). */
int fz_strict(void);

/* Prints where and why, then abort(): libFuzzer saves the input. */
void fz_fail(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4), noreturn))
#endif
    ;
#define FZ_CHECK(cond, ...) \
    do { \
        if (!(cond)) fz_fail(__FILE__, __LINE__, __VA_ARGS__); \
    } while (0)

/* The code is among `allowed`, its texts are sane, and pds_errmsg(s) names
 * `fn` after a failure and is unchanged after a success. */
void fz_codes(fz_state *st, const char *fn, int rc, unsigned allowed);
/* pds_count(s) is st->count, pds_radius(s) st->radius, the points read before
 * are unchanged bit for bit, new ones are finite and inside the domain. */
void fz_sync(fz_state *st);
/* Every pair at least R apart (within 1e-12 relative; wrapped on the torus),
 * every point inside the domain. O(n sqrt n) by a sweep along the long side. */
void fz_check_pattern(const fz_state *st);
/* After "maximal": pds_verify 0, pds_free_area 0, no step or run adds a
 * point, and fz_check_pattern. In count mode after "complete" (n points):
 * pds_verify 0 or 1, pds_refine PDS_ESTATE, nothing added. */
void fz_check_maximal(fz_state *st);
/* pds_free_area(s): never negative or NaN, 0 when maximal, the domain's area
 * before the first point, at most that area later. */
void fz_check_free_area(fz_state *st);
/* A maximal pattern (not count mode): probes over the domain, its corners and
 * sides among them, each lie in some point's closed disk (wrapped on the torus).
 * O(64 n). */
void fz_check_coverage(const fz_state *st);
/* Forget the sampler's model (after pds_destroy or a new pds_create). */
void fz_reset(fz_state *st, pds_sampler *s, double radius);
/* Oler's bound on the number of points of any pattern at this radius. */
double fz_count_bound(const fz_state *st);
/* The radius is well above the precision limit (2^-26 .. 2^-25 of the
 * domain's largest |coordinate|, coordinates not all below 2^-900, and no
 * nonzero one below 2^-900 of the largest). */
int fz_precision_ok(const fz_state *st, double radius);
/* The radius is above half the shorter period of the torus (slack: relative). */
int fz_above_half_period(const fz_state *st, double radius, double slack);
/* The torus's longer side is above 1024 times its shorter (slack: relative). */
int fz_periods_too_unequal(const fz_state *st, double slack);
/* Point (x, y) lies in the domain: closed, or half-open and on the quantum grid
 * on the torus. */
int fz_inside(const fz_state *st, double x, double y);
/* Recompute the torus's periods and quantum after a change of domain or kind. */
void fz_set_torus(fz_state *st);
/* Count mode: pds_radius(s) read again after a change; before the first point
 * it must be the documented start radius. */
void fz_count_radius(fz_state *st);

/* ---- radius fields (fuzz_field.c) ------------------------------------------------ */

/* The smallest radius a new point may get: pds_radius scaled from the field's
 * rmax to its rmin; pds_radius without a field. */
double fz_smallest_radius(const fz_state *st);
/* A field whose values are not all equal: the weighted path (no dart grid). */
int fz_varying_field(const fz_state *st);
/* A varying field with a dart stage (1.3.2; on the torus since 1.14): rmax <= 16 rmin (8 before 1.15). */
int fz_field_has_darts(const fz_state *st);
/* The function in force may return a bad value now (band or toggle). */
int fz_field_may_fail(const fz_state *st);
/* ... and does, everywhere, now (toggled with a bad value, varying). */
int fz_field_fails_everywhere(const fz_state *st);
/* The harness's radius function (user: an fz_field_fn). */
double fz_field_cb(void *user, double x, double y);
/* Its value at (x, y) without the toggle and without side effects. */
double fz_field_value(const fz_field_fn *f, double x, double y);
/* fz_sync's part: the radii of points 0..n-1 (pds_radii) against the model. */
void fz_sync_radii(fz_state *st, size_t n, const double *xy);
/* The radius in force of point i (read by fz_sync). */
double fz_radius_of(const fz_state *st, size_t i);
/* A change before the first point succeeded (see known_rng). */
void fz_changed_before_first(fz_state *st);
/* Free what the field's model holds. */
void fz_field_reset(fz_state *st);

/* ---- progress and determinism (fuzz_progress.c) ---------------------------------- */

/* pds_run with the callback's bookkeeping around it; checks the reports after. */
int fz_run(fz_state *st, size_t max_new, size_t *added);
int fz_progress_cb(void *user, size_t count, double done);
/* Replays create, domain, kind, count and the refines in a second sampler
 * without callback in a few large runs: the points must be the same bytes. */
void fz_replay_check(fz_state *st);

/* ---- operations: one kind of public call each (fuzz_ops.c) ---------------------- */

/* The codes that moved between 1.1.0 and 1.1.1 (see FZ_SPEC_111). */
static inline unsigned fz_range_if_111(void) { return FZ_SPEC_111 ? FZ_BIT(PDS_ERANGE) : 0u; }
static inline unsigned fz_range_unless_111(void) { return FZ_SPEC_111 ? 0u : FZ_BIT(PDS_ERANGE); }

/* Points one input may add (with the read budget in fuzz_api.c: milliseconds). */
#define FZ_BUDGET 5000

/* Lowers the input's point budget once its domain is far thinner than R
 * (fuzz_ops.c): called before each operation, after the last one changed
 * the domain or radius. */
void fz_cap_thin_budget(fz_state *st);
void fz_op_create(fz_state *st, fz_reader *r, unsigned arg);
void fz_op_domain(fz_state *st, fz_reader *r);
void fz_op_refine(fz_state *st, fz_reader *r);
void fz_op_step(fz_state *st, unsigned arg);
void fz_op_run(fz_state *st, fz_reader *r, unsigned arg);
void fz_op_run_chunks(fz_state *st, unsigned arg);
void fz_op_run_to_end(fz_state *st, unsigned arg);
void fz_op_points(fz_state *st, fz_reader *r, unsigned arg);
void fz_op_verify(fz_state *st);
void fz_op_nulls(fz_state *st);
void fz_op_strerror(fz_state *st, fz_reader *r);
void fz_op_version(void);
/* pds_set_threads (1.5): the code (PDS_ESTATE once points of the single-thread
 * process exist), pds_threads after it; the first success selects the parallel
 * process (st->parallel); nothing else changes. */
void fz_op_threads(fz_state *st, fz_reader *r);
void fz_op_create_bad(fz_state *st, fz_reader *r);
/* 1.2 (fuzz_ops12.c) */
void fz_op_periodic(fz_state *st, fz_reader *r);
void fz_op_count(fz_state *st, fz_reader *r);
void fz_op_progress(fz_state *st, fz_reader *r);
/* 1.3 (fuzz_field.c) */
void fz_op_radius_map(fz_state *st, fz_reader *r);
void fz_op_radius_fn(fz_state *st, fz_reader *r);
void fz_op_radii(fz_state *st, fz_reader *r, unsigned arg);
void fz_op_field_bad(fz_state *st, fz_reader *r);

/* 1.4 (fuzz_shape.c: the model, nothing asked of the library) */
void fz_shape_free(fz_shape *sh);
/* Fill sh from the arguments; what the contract says: 1 accepted, 0 refused
 * (PDS_EINVAL), -1 either. */
int fz_shape_polygon(fz_shape *sh, const double *xy, const size_t *ends, size_t nrings);
int fz_shape_mask(fz_shape *sh, size_t w, size_t h, const unsigned char *pix, const double rect[4]);
/* In the closed domain (within 1e-12 of the box from an edge counts as on it). */
int fz_shape_inside(const fz_shape *sh, double x, double y);
void fz_shape_vertices(const fz_shape *sh, size_t *lo, size_t *hi);
double fz_shape_perimeter(const fz_shape *sh, int e);
void fz_shape_probes(const fz_shape *sh, void (*fn)(void *ctx, double x, double y), void *ctx);
/* 1.4 (fuzz_domains.c) */
void fz_op_polygon(fz_state *st, fz_reader *r);
void fz_op_mask(fz_state *st, fz_reader *r);
/* pds_set_domain succeeded with d: the rectangle, and a mask follows it. */
void fz_domain_set(fz_state *st, const double d[4]);
/* A box so long and thin (aspect above 1e8 / factor) that the library's polygon
 * index takes gigabytes (found/NOTES, polygon_index_aspect): not set unless strict. */
int fz_index_too_tall(const double box[4], double factor);
/* pds_set_domain(d) on a sampler with a mask may refuse the outline it makes. */
int fz_domain_may_refuse(const fz_state *st, const double d[4]);
/* The replay's sampler t gets the same domain; 0 when memory ran out. */
int fz_shape_apply(const fz_state *st, pds_sampler *t);
/* The domain's area in user units: NaN when not known (rings that cross). */
double fz_domain_area(const fz_state *st);
/* The count bound the library judges by, between lo and hi (Oler's on the
 * rectangle; a polygon's from its area, perimeter and vertices). */
void fz_lib_bound(const fz_state *st, double *lo, double *hi);
/* Probes of the polygon each in some point's disk (fz_check_coverage). */
void fz_shape_coverage(const fz_state *st);
/* Every nonzero coordinate of the domain within 2^-890 of the largest. */
int fz_shape_scalable(const fz_state *st);

/* 1.4 (fuzz_fixed.c): fixed points */
void fz_op_fixed(fz_state *st, fz_reader *r);
/* Before the first point: some fixed point lies outside the box (1), near its
 * sides (-1: either), or none (0). */
int fz_fixed_outside(const fz_state *st);
/* After pds_run or pds_step at the first point with `outside` as above: the
 * call refused a fixed point outside the box (1; checked against the model). */
int fz_fixed_refused(fz_state *st, const char *fn, int rc, int outside, size_t added);
/* A call that may add points begins: the clearances are adopted at this radius. */
void fz_fixed_run_starts(fz_state *st);
/* Every point read keeps every fixed point's clearance (part of fz_check_pattern). */
void fz_fixed_check_pattern(const fz_state *st);
/* (x, y) lies in some fixed point's closed clearance disk. */
int fz_fixed_covers(const fz_state *st, double x, double y);
/* The replay's sampler t gets the same fixed points; 0 when memory ran out. */
int fz_fixed_apply(const fz_state *st, pds_sampler *t);
void fz_fixed_reset(fz_state *st);

#endif /* PDS_FUZZ_H */
