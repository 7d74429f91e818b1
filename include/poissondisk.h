/*
 * poissondisk.h - exact maximal Poisson-disk sampling (Jones 2006).
 *
 * This header is the specification of the library's C interface. It is plain
 * C99, includes only <stddef.h> and <stdint.h>, and compiles as C++ too.
 *
 * A sampler generates points in an axis-aligned rectangle (the unit square by
 * default) such that
 *   - every pair of points is at least the radius R apart (decided exactly);
 *   - when the sampler reports "maximal", no point of the rectangle is farther
 *     than R from every sample (no room is left for another point);
 *   - each new point is uniform over the area where a point may still go, so
 *     the pattern follows the random-sequential-adsorption (dart throwing run
 *     to saturation) law, and every prefix of the points is itself a
 *     Poisson-disk set.
 *
 * Conventions shared by every function:
 *   - A call that can fail returns int: 0 on success, a documented positive
 *     value for a non-error outcome, a negative PDS_E* code on error.
 *   - A failed call leaves the sampler as it was, and pds_errmsg() tells why;
 *     the one exception is PDS_EINTERNAL (a bug), after which the sampler keeps
 *     its points but refuses every change with PDS_ESTATE.
 *   - The library never prints, aborts, exits or touches errno, and keeps no
 *     global state: distinct samplers may be used from distinct threads at
 *     once; one sampler must be used by one thread at a time. It starts no
 *     thread of its own unless pds_set_threads asks for more than one.
 *   - Coordinates are returned as interleaved x,y doubles into caller-owned
 *     buffers; no memory allocated by the library crosses this interface.
 *   - Version numbers in the comments say in which release a name appeared.
 *   - The same seed gives the same points however the work is split: one
 *     pds_run, many bounded pds_run calls or pds_step calls all agree, and
 *     so does everything after a pds_refine that follows any of them.
 *   - Small calls are cheap: memory grows geometrically, so a loop of
 *     pds_run(s, 1, NULL) or pds_step costs O(1) amortized per point.
 *   - The radius and the domain are judged together when they are first used
 *     (the first point, or pds_refine once points exist), so they may be
 *     given in any order.
 */
#ifndef POISSONDISK_H
#define POISSONDISK_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Version of this header; pds_version_number() gives the library's. (1.0) */
#define PDS_VERSION_MAJOR 1
#define PDS_VERSION_MINOR 16
#define PDS_VERSION_PATCH 0
#define PDS_VERSION_NUMBER \
    (PDS_VERSION_MAJOR * 10000 + PDS_VERSION_MINOR * 100 + PDS_VERSION_PATCH)

/* Error codes: fixed values, never renumbered, only appended. (1.0) */
#define PDS_EINVAL (-1)    /* an argument is invalid: NULL, NaN, infinite, out of its domain */
#define PDS_ENOMEM (-2)    /* memory could not be allocated                        */
#define PDS_ESTATE (-3)    /* the call is not allowed in the sampler's current state:
                              pds_set_domain after the first point, or any change
                              after an earlier PDS_EINTERNAL                         */
#define PDS_ERANGE (-4)    /* the radius is too small for the domain: the points
                              asked for would not fit in the index type or address
                              space, or double precision cannot resolve them         */
#define PDS_EINTERNAL (-5) /* an internal invariant failed (a bug); the sampler
                              refuses further changes (PDS_ESTATE) but can still be
                              read and destroyed                                     */
#define PDS_ECANCELED (-6) /* the progress callback asked pds_run to stop; the points
                              so far are kept and a later pds_run continues exactly
                              where an uninterrupted run would be (1.2)              */

/* Named non-error results of pds_step, pds_run and pds_verify. (1.1.1) */
#define PDS_DONE 0 /* the pattern is maximal: no room is left for another point */
#define PDS_MORE 1 /* pds_step: a point was added; pds_run: max_new points were
                      added and room is left; pds_verify: valid, room is left */

/* Export control: symbols are visible only when the library is being built. */
#if defined(PDS_BUILDING_LIBRARY) && defined(__GNUC__)
#define PDS_API __attribute__((visibility("default")))
#else
#define PDS_API
#endif

/* In C++ the functions are declared noexcept: none of them ever throws. */
#if defined(__cplusplus) && __cplusplus >= 201103L
#define PDS_NOEXCEPT noexcept
#else
#define PDS_NOEXCEPT
#endif

/* The opaque sampler handle. (1.0) */
typedef struct pds_sampler pds_sampler;

/*
 * pds_create - make a sampler for the unit square [0,1]x[0,1].
 *   out     receives the new sampler; set to NULL on failure. Must not be NULL.
 *   radius  the minimum distance R between points; finite and > 0.
 *   seed    any value; the same seed and version give byte-identical points.
 * Returns 0, PDS_EINVAL (out NULL, radius not finite or <= 0), PDS_ENOMEM. The
 * radius is judged against the domain at the first point (see pds_run), so a
 * radius meant for a smaller domain set later is fine (since 1.1.1; 1.0 and
 * 1.1.0 returned PDS_ERANGE here).
 * The caller owns *out and releases it with pds_destroy(). (1.0)
 */
PDS_API int pds_create(pds_sampler **out, double radius, uint64_t seed) PDS_NOEXCEPT;

/* pds_destroy - release a sampler and everything it holds. NULL is a no-op. (1.0) */
PDS_API void pds_destroy(pds_sampler *s) PDS_NOEXCEPT;

/*
 * pds_set_domain - sample the closed rectangle [x0,x1]x[y0,y1] instead.
 * All four values finite, x0 < x1 and y0 < y1. Allowed only before the first
 * point. Returns 0, PDS_EINVAL (NULL, non-finite, empty or inverted rectangle),
 * PDS_ESTATE (points exist already). The radius is judged against it at the
 * first point (since 1.1.1; earlier versions returned PDS_ERANGE here). (1.0)
 */
PDS_API int pds_set_domain(pds_sampler *s, double x0, double y0, double x1, double y1) PDS_NOEXCEPT;

/*
 * pds_step - add one point, uniform over the free area.
 * Returns PDS_MORE (1) when a point was added, PDS_DONE (0) when the pattern
 * is maximal (nothing added), or PDS_EINVAL (NULL), PDS_ERANGE (at the first
 * point: the radius is below double precision for the domain; or the index
 * space is full), PDS_ENOMEM (as for pds_run), PDS_ESTATE (sampler broken by
 * an earlier PDS_EINTERNAL), PDS_EINTERNAL. (1.0)
 */
PDS_API int pds_step(pds_sampler *s) PDS_NOEXCEPT;

/*
 * pds_run - add points until the pattern is maximal or max_new were added.
 *   max_new  the most points to add in this call; 0 means no limit.
 *   added    if not NULL, receives how many points this call added (also on error).
 * Returns PDS_DONE (0) when the pattern is maximal (in count mode: when the
 * count asked for is reached, see pds_set_count), PDS_MORE (1) when max_new
 * points were added and room is left (decided exactly), or:
 *   PDS_EINVAL     s is NULL;
 *   PDS_ERANGE     nothing added: at the first point, the radius is below
 *                  double precision for the domain (2^-26 of its largest
 *                  |coordinate|), or a nonzero coordinate of the domain is
 *                  below 2^-900 times the largest (or all are below 2^-900);
 *                  or the points asked for cannot fit the
 *                  index type (about 3.5e8 points): for max_new == 0, a
 *                  maximal pattern might not fit (Oler's bound
 *                  2A/(sqrt(3)R^2) + P/(2R) + 1); for max_new > 0, the
 *                  current count plus max_new (or that bound, if smaller);
 *   PDS_ENOMEM     memory for the call is reserved before its first point,
 *                  so normally nothing was added. Only the exact-arithmetic
 *                  fallback (for cells rounding cannot classify, rare)
 *                  allocates while points are added, and so does the final
 *                  "room left?" decision; if that fails, the points added
 *                  before stay, *added counts them, and the sampler is
 *                  exactly where an undisturbed run would be after them: a
 *                  later call gives the same points as if nothing had failed;
 *                  On a periodic domain (pds_set_periodic) the copies of
 *                  points near the edges also allocate as points are added,
 *                  with the same promise when that fails;
 *   PDS_ECANCELED  the progress callback (pds_set_progress) returned
 *                  nonzero: the points so far stay, *added counts them, and
 *                  a later call continues exactly as an uninterrupted run;
 *   PDS_ESTATE, PDS_EINTERNAL: see the codes. After PDS_EINTERNAL the
 *                  points added before the failure stay, and *added counts
 *                  them. (1.0; PDS_ERANGE and the PDS_ENOMEM wording 1.1.1;
 *                  PDS_ECANCELED and count mode 1.2)
 */
PDS_API int pds_run(pds_sampler *s, size_t max_new, size_t *added) PDS_NOEXCEPT;

/*
 * pds_refine - continue with a smaller radius, keeping every point.
 *   radius  finite, 0 < radius <= pds_radius(s); equal is a no-op.
 * Allowed at any time. The existing points keep their indices and new points
 * follow them; running to the end gives a pattern maximal at the new radius.
 * Returns 0, PDS_EINVAL (NULL, non-finite, <= 0 or larger than the current
 * radius), PDS_ERANGE (points exist and the radius is below double precision
 * for the domain; the count limit is judged by the next pds_run), PDS_ENOMEM
 * (nothing changed that a later call could see: retrying gives the same
 * points), PDS_ESTATE. (1.0)
 */
PDS_API int pds_refine(pds_sampler *s, double radius) PDS_NOEXCEPT;

/* pds_count - number of points so far; 0 for NULL. (1.0) */
PDS_API size_t pds_count(const pds_sampler *s) PDS_NOEXCEPT;

/*
 * pds_points - copy points first .. first+count-1, clipped to pds_count(s),
 * into xy as interleaved x,y pairs (xy must hold 2*count doubles). Points come
 * in insertion order. Returns how many points were copied: 0 when s or xy is
 * NULL or first >= pds_count(s). (1.0)
 */
PDS_API size_t pds_points(const pds_sampler *s, size_t first, size_t count, double *xy) PDS_NOEXCEPT;

/* pds_radius - the current radius R; NaN for NULL. (1.0) */
PDS_API double pds_radius(const pds_sampler *s) PDS_NOEXCEPT;

/*
 * pds_free_area - area of the domain farther than R from every point, where a
 * new point could still go; exactly 0 once the pattern is maximal; the whole
 * domain's area before the first point; NaN for NULL (or when memory runs
 * out). Cost: O(1) when the pattern is maximal, otherwise O(N): the sampler
 * keeps only upper bounds of the cells' areas while it runs, and this call
 * measures the cells not yet known to be covered; early in a run, while
 * points come from the dart stage, it first triangulates them, O(N log N).
 * It changes nothing, so calling it never changes later points. (1.0)
 */
PDS_API double pds_free_area(const pds_sampler *s) PDS_NOEXCEPT;

/*
 * pds_verify - re-check the current pattern from scratch, independently of
 * the sampler's bookkeeping: every pair at least R apart (exact arithmetic,
 * through a spatial hash), the triangulation valid and Delaunay, and
 * maximality decided exactly (every Voronoi vertex inside the domain within R
 * of its site, every side of the domain covered). O(N) expected time.
 * Returns PDS_DONE (0) when the pattern is valid and maximal, PDS_MORE (1) when
 * it is valid and room is left, PDS_EINTERNAL when a check fails (a bug:
 * please report it; the message says which check and names the point by its
 * index in insertion order; the sampler stays usable), PDS_EINVAL (NULL),
 * PDS_ENOMEM. Works on a sampler made read-only by an earlier error. (1.0)
 */
PDS_API int pds_verify(pds_sampler *s) PDS_NOEXCEPT;

/*
 * pds_set_periodic - sample the domain as a flat torus (a tileable pattern).
 *   periodic  nonzero: distances wrap in x and in y, with periods
 *             x1-x0 and y1-y0; 0: back to the plain rectangle (the default).
 * Every pair is at least R apart across the wrap too, maximality is decided
 * on the torus, and each new point is uniform over the torus's free area:
 * copies of the pattern shifted by whole periods tile the plane with a
 * maximal Poisson-disk set, with no density excess at the edges. Points lie
 * in [x0,x1) x [y0,y1).
 * Exactness needs the shifted copies to be exact doubles, so every periodic
 * point is a multiple of the quantum q = 2^(e-50), where 2^e <= (largest
 * |coordinate| of the domain) < 2^(e+1) (about 1e-15 of the domain), and so
 * is each period: a period that is not (e.g. 0.1) is rounded down to one,
 * moving x1 or y1 inwards by less than q. Integers and short binary
 * fractions are exact.
 * The radius must not exceed half the shorter period (x1-x0 or y1-y0 as
 * given), and the longer period must not exceed 1024 times the shorter
 * (the copies that make the torus grow with that ratio; 1.2.1): judged with
 * the other limits at the first point (PDS_ERANGE), as for pds_set_domain. pds_verify and pds_free_area work on the torus.
 * Allowed only before the first point. Returns 0, PDS_EINVAL (NULL),
 * PDS_ESTATE (points exist already). (1.2)
 */
PDS_API int pds_set_periodic(pds_sampler *s, int periodic) PDS_NOEXCEPT;

/*
 * pds_set_count - let the sampler choose the radius so that running to the
 * end gives exactly n points, as evenly spread as it can.
 * Method: the radius starts above R(n), the radius at which a maximal
 * pattern holds n points on average, n = 0.547 4A/(pi R^2) + 0.23 P/R for a
 * rectangle of area A and perimeter P (no P term on the torus), by a factor
 * 1.015 + 10/n (on the torus at most half the shorter period; never above
 * DBL_MAX, which only a domain with sides near DBL_MAX reaches). With fixed
 * points (pds_set_fixed), A is the area their clearances leave in the
 * domain and P adds the clearances' outline there, both estimated on a
 * 256 x 256 lattice when the first point is placed; a clearance of 0 is the
 * start itself, so the start is the radius that gives itself. Until that
 * point pds_radius() gives the start without them; the clearances scale
 * from the start (since 1.10; before, the start ignored them, so around
 * large clearances the radius was lowered by 1% many times, and the
 * clearances with it). Each time the pattern becomes maximal with m < n
 * points, the radius is lowered (as pds_refine) by the factor sqrt(m/n)
 * kept between 0.99 and 0.999, and the run goes on; it stops at the n-th
 * point. Afterwards pds_radius() is the last radius: every pair is at least
 * that far apart; and if the radius was lowered at least once, no room is
 * left for a point at pds_radius()/0.99 (the pattern is maximal at the
 * previous radius, and in general not at the last one, so pds_verify
 * returns PDS_MORE). It is not lowered when the run reaches n points before
 * its first maximal pattern: when the torus caps the start, and on thin
 * domains (shorter side not many times R(n)), where the two-dimensional
 * estimate is too low: a 1000 x 1 torus at n = 3000 keeps its start, 0.4907,
 * to the end, maximal at no radius. For n >= 1000, pds_radius() was at least
 * 0.98 R(n) on squares and rectangles up to 64:1, lower on thinner ones
 * (0.945-0.958 on a 1024 x 1 rectangle at n = 1000).
 * pds_run and pds_step return PDS_DONE once n points exist; pds_refine is
 * refused (PDS_ESTATE) while a count is set. The radius given to pds_create
 * is ignored. Works with pds_set_domain and pds_set_periodic; the same seed
 * gives the same points however the work is split.
 * Allowed only before the first point. Returns 0, PDS_EINVAL (NULL, n == 0),
 * PDS_ESTATE (points exist already). A count the index type cannot hold, or
 * a domain on which the lowest radius the method can reach, 0.98
 * sqrt(A / (pi n)) (lowered only while a maximal pattern of fewer than n
 * points covers the area A, by at most 1% a step), is below double
 * precision, is PDS_ERANGE at the first point: a run that has started
 * never meets that limit. (1.2)
 */
PDS_API int pds_set_count(pds_sampler *s, size_t n) PDS_NOEXCEPT;

/*
 * Progress callback: `count` points exist, `done` estimates the fraction of
 * the whole pattern made so far (monotone within a run, in [0,1]; exact in
 * count mode: count/n; otherwise from the expected size of a maximal pattern,
 * and 1 once the pattern is complete). Return 0 to go on, nonzero to stop
 * pds_run with PDS_ECANCELED; the final call (done == 1, the pattern
 * complete) has nothing left to stop: its return is ignored and pds_run
 * returns PDS_DONE. (1.2)
 */
typedef int (*pds_progress_fn)(void *user, size_t count, double done);

/*
 * pds_set_progress - have pds_run report progress and accept cancellation.
 *   fn    called between points: when `done` has grown by 1% since the last
 *         call, or a second has passed, and once when the run ends with the
 *         pattern complete; so at most about 100 calls per run plus one per
 *         second of work, whatever a point costs. Calls come also during
 *         the steps that add no point: a field's count estimate (see
 *         pds_radius_fn) and the hand-over from the dart stage to the
 *         Jones loop (0.44-0.57 s per million points on our benchmark
 *         machine, up to about 1 s on a slow one); a stop asked for in the
 *         hand-over takes effect when it ends.
 *         NULL removes the callback (user must then be NULL too).
 *   user  passed back to fn unchanged.
 * A nonzero return from fn makes pds_run return PDS_ECANCELED at once (but
 * see the hand-over and the final call above): the
 * points so far are kept (*added counts them), the sampler stays valid, and
 * a later pds_run continues to exactly the pattern an uninterrupted run gives.
 * pds_step never calls fn. fn must not call functions that change the same
 * sampler (pds_run, pds_step, pds_refine, pds_set_*): such a call returns
 * PDS_ESTATE and changes nothing; pds_destroy from fn is undefined behaviour.
 * Reading the sampler (pds_count, pds_points, pds_radius) is allowed.
 * Allowed at any time. Returns 0, PDS_EINVAL (s NULL, or fn NULL with user
 * not NULL), PDS_ESTATE (called from inside the callback). (1.2)
 */
PDS_API int pds_set_progress(pds_sampler *s, pds_progress_fn fn, void *user) PDS_NOEXCEPT;

/*
 * A variable radius (1.3). Each point p_i carries the radius r_i = r(p_i) of
 * a field r, evaluated once, when the point is placed. A later point keeps
 * out of every earlier point's closed disk: |p_j - p_i| >= r_i for i < j
 * (distance exactly r_i allowed). Each new point is uniform over the free
 * region F, the domain minus the union of the disks B(p_i, r_i); the pattern
 * is maximal when F is empty. Inside a cell of the power diagram of the
 * disks (weights r_i^2) the union is the cell's own disk, so the Jones
 * construction is exact on the power diagram: no approximation. With a
 * constant field the points are those of the plain sampler at that radius,
 * byte for byte.
 * pds_radius() is then the largest radius in force, rmax (the map's largest
 * value, or the function's declared bound), and pds_refine(s, R) scales
 * every radius, old points' too, by R / pds_radius(s). The smallest radius,
 * rmin, is judged against the domain at the first point as pds_create's
 * radius is (PDS_ERANGE, nothing added). Works with pds_set_domain,
 * pds_step, pds_run in any batches (the same seed gives the same points),
 * pds_verify, pds_free_area, pds_set_progress and pds_set_periodic (the
 * field is evaluated at points of the fundamental domain; rmax must not
 * exceed half the shorter period, and a varying field needs the longer
 * period at most 16 times the shorter, PDS_ERANGE at the first point); not with
 * pds_set_count (PDS_EINVAL, either way round). In a rectangle, polygon,
 * mask or torus a varying field with rmax at most 16 times rmin opens with
 * dart throwing, a grid per layer of radii (since 1.3.2; around fixed
 * points since 1.11; on the torus since 1.14, each point recorded once and
 * a dart near a seam tested at its copies a period away; up to 16 times
 * since 1.15, 8 before); for a wider field, or in a polygon spread thin
 * over its box, the Jones loop runs from the first point. The grids' pages
 * are touched only where points land: a smooth field fills them, but a
 * fine-grained one (small radii scattered among large ones, as a noise
 * image) touches new pages for nearly each of its lone small points, so
 * the darts hand over to the Jones loop, whose memory follows the points,
 * once the pages touched pass 256 bytes for each point the pattern is
 * expected to hold, above 16 MiB (since 1.15; the count expected from a
 * map's values, or from a function's at the points so far; decided by the
 * points so far, so the points still do not depend on the thread count).
 * Either way the law is the same.
 * With a varying field the count limit is judged at the first point on a
 * bound that holds for every seed: Oler's bound at rmin (as for a constant
 * radius rmin), or for a map, when smaller, the sum of Oler's bounds over
 * the cells between its pixel centres, each at its least corner value (since
 * 1.3.4: one small value in a map of large ones is then no obstacle); once points exist
 * an unbounded pds_run is not judged again (a maximal pattern returns
 * PDS_DONE). Memory is not reserved for that bound, which one small value
 * can make far larger than the pattern, but grows with the run: PDS_ENOMEM
 * (or PDS_ERANGE past the index space) may then come after some points were
 * added, which stay; *added counts them. A function's values are known
 * only where it is asked, so it is judged at rmin, which refuses some small
 * patterns (one small value among large ones); bounded runs (max_new > 0)
 * are judged on the count plus max_new and make such a pattern.
 * Allowed only before the first point; the last field set wins.
 */

/*
 * pds_set_radius_map - a radius field from a w x h map over the domain.
 *   r  w*h radii in user units, row-major, row 0 along y = y0 and column 0
 *      along x = x0; each finite and > 0. Copied: the array may be freed.
 * The field is bilinear between pixel centres ((i + 1/2) (x1-x0)/w, ...)
 * and constant beyond the outermost centres (clamped). A 1 x 1 map is a
 * constant radius.
 * Returns 0, PDS_EINVAL (s or r NULL, w or h 0, w*h overflowing, a value
 * not finite or <= 0, a count set), PDS_ENOMEM, PDS_ESTATE (points exist
 * already). (1.3)
 */
PDS_API int pds_set_radius_map(pds_sampler *s, size_t w, size_t h, const double *r) PDS_NOEXCEPT;

/*
 * A radius function: the radius at user point (x, y) of the domain, in
 * [rmin, rmax]. Called once per point, when it is placed (with
 * pds_set_threads, when its dart is accepted: a pds_refine before the
 * point is added drops it, its value asked in vain; a value refused there
 * leaves out the points that epoch accepted before it), and not at all
 * when rmin == rmax (the field is then constant); with a progress callback
 * set, also 4096 times over a grid at the first pds_run, for the estimate of
 * the final count (values out of bounds there count as rmax, no error),
 * with progress calls during them and a stop honoured (the values asked so
 * far are kept for the next pds_run). It
 * must not call functions that change the same sampler (they return
 * PDS_ESTATE). (1.3)
 */
typedef double (*pds_radius_fn)(void *user, double x, double y);

/*
 * pds_set_radius_fn - a radius field from a function.
 *   fn          the field; user is passed back to it unchanged.
 *   rmin, rmax  finite, 0 < rmin <= rmax: the bounds of its values.
 * A value outside [rmin, rmax], or not finite, stops pds_run or pds_step
 * with PDS_EINVAL before the point is added: the points so far are kept,
 * the sampler stays valid, and the message gives the value and where.
 * Returns 0, PDS_EINVAL (s or fn NULL, bad bounds, a count set),
 * PDS_ESTATE (points exist already). (1.3)
 */
PDS_API int pds_set_radius_fn(pds_sampler *s, pds_radius_fn fn, void *user, double rmin,
                              double rmax) PDS_NOEXCEPT;

/*
 * pds_radii - copy the radii in force of points first .. first+count-1 (in
 * the order they were added) into r (count doubles). Without a field each
 * is pds_radius(s). Returns the number copied: min(count, pds_count(s) -
 * first), or 0 for s or r NULL or first >= pds_count(s). (1.3)
 */
PDS_API size_t pds_radii(const pds_sampler *s, size_t first, size_t count, double *r) PDS_NOEXCEPT;

/*
 * Domains users have (1.4): a polygon with holes, an image mask, and fixed
 * points (obstacles, an earlier pattern, points a mesher placed). The
 * domain is closed: its outline belongs to it. Each new point is uniform
 * over the free region, the domain minus every point's disk and every fixed
 * point's clearance disk, so the pattern is random sequential adsorption
 * conditioned on the fixed points; it is maximal when every point of the
 * domain, outline included, lies within R of a sampled point or within a
 * fixed point's clearance (decided exactly; pds_verify re-checks it, and
 * that every point lies in the closed domain). Works with a radius field,
 * pds_set_count (N points in the domain), pds_refine, progress and cancel,
 * pds_step and bounded runs (the same points however calls are split);
 * not with pds_set_periodic (PDS_EINVAL, either way round).
 */

/*
 * pds_set_polygon - the domain is a polygon: the region inside its rings by
 * the even-odd rule (a point is inside when a ray from it crosses the rings
 * an odd number of times), outer boundaries and holes alike.
 *   xy         the vertices, x then y, in user units; ring k holds vertices
 *              ring_ends[k-1] .. ring_ends[k]-1 (ring_ends[-1] read as 0).
 *   ring_ends  nrings increasing ends; the last is the vertex count, at
 *              most 2^28.
 * Rings may run either way round, repeat their first vertex at the end,
 * hold collinear runs, and touch each other at vertices. Rings that cross
 * one another or themselves (a bow tie) are taken by the even-odd rule too:
 * their edges are split where they cross, at the crossing point rounded to
 * doubles, so along crossing edges the domain may differ from the exact
 * region by slivers about an ulp of the coordinates wide; everything else
 * holds as for rings that do not cross. Likewise a vertex closer to an edge
 * than 2^-44 times the largest |coordinate| is taken as on it (two edges
 * that close along a stretch share it, and cancel there), and vertices of
 * different rings closer than 2^-43 times it to each other are moved to one
 * of them (two rings meeting at a corner a few ulps apart). The copy is kept:
 * the arrays may be freed. The domain's bounding box replaces the rectangle
 * of pds_set_domain, and a radius map is spread over that box; memory and
 * time follow the polygon, not the box (islands far apart, a thin ring are
 * sampled in the cells they meet). A polygon replaces an earlier polygon or
 * mask; nrings == 0 (xy and ring_ends may be NULL) goes back to the
 * rectangle.
 * Returns 0, PDS_EINVAL (s NULL, xy or ring_ends NULL with nrings > 0, a
 * ring with fewer than 3 distinct vertices or all on one line, a
 * non-finite coordinate, decreasing ends, an outline that encloses nothing,
 * rings that cross one another more than 4 times per vertex and 65536,
 * coordinates beyond 2^500 beside a nonzero one below about 2^-1522 of the
 * largest, which no one scale reads exactly,
 * periodic set; the message names the ring and vertex, counted from 0),
 * PDS_ENOMEM, PDS_ESTATE (points exist already). (1.4)
 */
PDS_API int pds_set_polygon(pds_sampler *s, const double *xy, const size_t *ring_ends,
                            size_t nrings) PDS_NOEXCEPT;

/*
 * pds_set_mask - the domain is the union of a w x h raster's inside pixels,
 * spread over the rectangle of pds_set_domain (set before or after): taken
 * exactly, as the rectilinear polygon their squares make.
 *   inside  w*h bytes, row-major, row 0 along y = y0 and column 0 along
 *           x = x0 (as pds_set_radius_map); nonzero is inside. Copied.
 * Memory and time follow the inside pixels, not the rectangle. A mask
 * replaces an earlier polygon or mask; w == 0 or h == 0 (inside may be NULL)
 * goes back to the rectangle.
 * Returns 0, PDS_EINVAL (s NULL, inside NULL with w*h > 0, w*h overflowing,
 * no pixel inside, pixel lines that round together in the rectangle, a
 * rectangle whose corners no one scale reads exactly, as for
 * pds_set_polygon, periodic set), PDS_ENOMEM, PDS_ESTATE (points exist already). While a mask
 * is set, pds_set_domain re-spreads it and may refuse a rectangle the same
 * way (PDS_EINVAL, nothing changed). A radius map is spread over the
 * bounding box of the inside pixels. (1.4)
 */
PDS_API int pds_set_mask(pds_sampler *s, size_t w, size_t h, const unsigned char *inside) PDS_NOEXCEPT;

/*
 * pds_set_fixed - points that are there before the first: every sampled
 * point keeps at least a fixed point's clearance from it. Fixed points are
 * not checked against each other, count for coverage, and are not returned
 * by pds_points or pds_radii, nor counted by pds_count. An obstacle is a
 * fixed point with a large clearance (or a hole of a polygon).
 *   xy         n points, x then y, in user units, inside the domain's
 *              bounding box (the polygon's, the mask's or the rectangle's).
 *   clearance  n clearances in user units, or NULL; 0 (or NULL) means the
 *              radius in force at the point when the first point is placed
 *              (R, or the field's value there). pds_refine and count mode
 *              scale every radius in force, the clearances too.
 * Copied: the arrays may be freed. n == 0 removes them (xy may be NULL).
 * With one radius a run with fixed points opens with dart throwing, the
 * fixed points its first points and its darts kept out of the clearances:
 * without pds_set_threads in the single-thread process (since 1.11; before,
 * the Jones loop from the first point, about twice the time of a plain run,
 * and other points), with it in the parallel process, its points the same
 * for every thread count (since 1.9; see pds_set_threads). A radius field
 * opens with its layered dart grids around fixed points too, where it does
 * without them (since 1.11; see pds_set_radius_map), with threads then
 * going on with darts in the free regions (since 1.13). A polygon spread thin over its box (islands far apart) and
 * clearances whose boxes together span many times the domain's box run
 * the Jones loop from the first point, with threads or not. Many
 * scattered fixed points open with darts too, inserted at the hand-over
 * along a space-filling curve (since 1.12; before, without threads, more
 * than about the square root of the points ran the Jones loop alone).
 * pds_free_area counts the clearances once a run has started. Clearances
 * that cover the domain leave a maximal pattern with no point (pds_run and
 * pds_verify return PDS_DONE, pds_free_area 0); in count mode the radius
 * goes down with them until points fit (PDS_ERANGE, nothing added, if they
 * still cover it at the precision limit).
 * Returns 0, PDS_EINVAL (s NULL, xy NULL with n > 0, a coordinate not
 * finite, a clearance not finite or < 0, periodic set; the message names
 * the point, from 0), PDS_ENOMEM, PDS_ESTATE (points exist already). A
 * fixed point outside the bounding box is PDS_EINVAL at the first point
 * (pds_run or pds_step, nothing added); within a few rounding steps of it
 * (a mask's pixel line computed another way) counts as on it. Fixed points
 * within 2^-40 R of each other count as one, the larger disk. (1.4)
 */
PDS_API int pds_set_fixed(pds_sampler *s, const double *xy, const double *clearance,
                          size_t n) PDS_NOEXCEPT;

/*
 * pds_set_threads - run s with the parallel dart process, on n threads.
 *   n  1 to 1024; 0 means one per online core (as
 *      std::thread::hardware_concurrency() counts them; 1 if it cannot tell).
 * The first call, before the first point, selects the parallel opening: in a
 * one-radius rectangle, polygon, mask or torus (with or without
 * pds_set_count or pds_refine) the run opens with darts tied to space (each
 * cell its own random stream), decided in order of time by the threads
 * together, and goes on with such darts in the free regions left. Its points
 * depend on the seed and the settings, never on n: the same seed gives the
 * same points, byte for byte, for every n and whatever n was at each call;
 * threads change only the speed. They are not the points of a sampler that
 * never called pds_set_threads, which runs the single-thread process of 1.4
 * (the faster one on one core). With pds_set_fixed
 * and one radius the parallel process runs too, its darts kept out of the
 * clearances. A radius
 * field in a rectangle, polygon or mask, with fixed points or not, or on
 * the torus, opens with the single-thread process's layered dart grids and
 * then goes on with darts in the free regions, drawn by the threads
 * together, each point keeping the later ones out of its own disk, on the
 * torus out of its copies across the seams too (since 1.13; on the torus
 * since 1.14; before, the single-thread process's points). A field with
 * rmax over 16 rmin (8 before 1.15) runs on one thread either way, on any
 * domain, as do a polygon spread thin over its box (islands far apart), an
 * outline too large to raster over the dart grid, and fixed points whose
 * clearances' boxes together span many times the domain's box (the Jones
 * loop alone, with threads or not); polygons and masks had the
 * single-thread process's points before 1.8, the torus and fixed points
 * before 1.9 (fixed points had other points with threads in 1.9, whose
 * hand-over inserted every point one by one, and without threads before
 * 1.11, from the Jones loop alone). The default is the
 * single-thread process: the library starts
 * no thread unless asked. Once selected, n may change at any time, also
 * between the calls of one run (from the next call that adds points).
 * Threads start and end inside the calls that add points; the progress
 * callback and the radius function are called only from the caller's
 * thread (the function at a point when its dart is accepted, up to one
 * epoch of darts before the call that returns it). A thread that cannot be started is done without: the run goes on
 * with fewer, and the same points.
 * Returns 0, PDS_EINVAL (s NULL, n > 1024), PDS_ESTATE (points exist already
 * from the single-thread process; called from inside the progress callback
 * or the radius function, or after an earlier PDS_EINTERNAL). (1.5)
 */
PDS_API int pds_set_threads(pds_sampler *s, unsigned n) PDS_NOEXCEPT;

/* pds_threads - the number of threads in force (0 resolved to the core
 * count): 1 until pds_set_threads is called; 0 for NULL. (1.5) */
PDS_API unsigned pds_threads(const pds_sampler *s) PDS_NOEXCEPT;

/* pds_strerror - static English text for any code, including unknown ones. (1.0) */
PDS_API const char *pds_strerror(int code) PDS_NOEXCEPT;

/*
 * pds_errmsg - the most recent failure on s in words, starting with the name of
 * the function that failed, or "no error" if none yet; successful calls do not
 * clear it. The text stays valid until the next call on s. For NULL, a static
 * text. (1.0)
 */
PDS_API const char *pds_errmsg(const pds_sampler *s) PDS_NOEXCEPT;

/* pds_version_number - MAJOR*10000 + MINOR*100 + PATCH of the library. (1.0) */
PDS_API unsigned pds_version_number(void) PDS_NOEXCEPT;

/* pds_version_string - "MAJOR.MINOR.PATCH" of the library, static. (1.0) */
PDS_API const char *pds_version_string(void) PDS_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif /* POISSONDISK_H */
