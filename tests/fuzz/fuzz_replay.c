/*
 * fuzz_replay.c - the determinism check of the fuzz harness (see fuzz.h).
 *
 * The same seed gives the same points however the work is split, and a run
 * canceled by the progress callback continues exactly as an uninterrupted
 * one. So before a sampler is dropped, a second one is made with the same
 * pds_create arguments, domain, kind (torus or not), count and radius field,
 * and without a callback; it runs in one bounded pds_run to each count at
 * which the input refined, refines there, and runs to the first sampler's
 * count. Its points, radii and radius must be the first's, byte for byte,
 * whatever mix of steps, chunks, cancellations, out-of-memory failures,
 * thread counts and bad values from the radius function led the first there
 * (when the first selected the parallel process with pds_set_threads, the
 * second selects it too, on one thread, first of its calls: the points
 * depend on that choice, never on the count or on the order of the setters;
 * the second's
 * function never returns one where the first's did not: a point is added
 * only after a good value).
 * A constant field (rmin == rmax: a 1 x 1 or uniform map, a function with
 * equal bounds) must moreover give the plain sampler's points at that radius:
 * a third sampler, without a field, created with it, must agree too (1.3).
 * (After a first point a field refused, too: fixed in 1.3, found/NOTES.)
 */
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

/* Runs t to n points; 0 when memory ran out (the comparison is skipped). */
static int reach(pds_sampler *t, size_t n, const char *when)
{
    const size_t have = pds_count(t);
    size_t added = 0;
    int rc;
    if (n <= have) return 1;
    rc = pds_run(t, n - have, &added);
    if (rc == PDS_ENOMEM) return 0;
    FZ_CHECK((rc == PDS_DONE || rc == PDS_MORE) && pds_count(t) == n, "replay: pds_run(%zu) "
             "%s returned %d with %zu points, the first sampler had %zu: %s", n - have, when,
             rc, pds_count(t), n, pds_errmsg(t));
    return 1;
}

/* with_field: set the first's field; else a plain sampler at the constant
 * field's radius (pds_create with it). */
static void replay(fz_state *st, int with_field)
{
    const size_t n = st->count;
    const char *what = with_field ? "" : " (a plain sampler for the constant field)";
    fz_field_fn fn = st->fns[st->fn_active];
    pds_sampler *t = NULL;
    double *xy, r1, r2;
    size_t i;
    int rc, ok = 1;

    if (pds_create(&t, with_field ? st->c_radius : st->f_rmax, st->c_seed) != 0) return;
    if (st->parallel) {
        rc = pds_set_threads(t, 1);
        FZ_CHECK(rc == 0, "replay: pds_set_threads(1) returned %d", rc);
    }
    rc = pds_set_domain(t, st->dom[0], st->dom[1], st->dom[2], st->dom[3]);
    FZ_CHECK(rc == 0, "replay: pds_set_domain returned %d", rc);
    rc = pds_set_periodic(t, st->periodic);
    FZ_CHECK(rc == 0, "replay: pds_set_periodic returned %d", rc);
    if (!fz_shape_apply(st, t) || !fz_fixed_apply(st, t)) { /* 1.4; memory ran out */
        pds_destroy(t);
        return;
    }
    if (with_field && st->field == FZ_FIELD_MAP) {
        rc = pds_set_radius_map(t, st->map_w, st->map_h, st->map);
        if (rc == PDS_ENOMEM) ok = 0;
        else FZ_CHECK(rc == 0, "replay: pds_set_radius_map returned %d", rc);
    } else if (with_field && st->field == FZ_FIELD_FN) {
        /* The same function, never bad everywhere, nothing tried from inside. */
        fn.toggled = 0;
        fn.st = NULL;
        rc = pds_set_radius_fn(t, fz_field_cb, &fn, st->f_rmin, st->f_rmax);
        FZ_CHECK(rc == 0, "replay: pds_set_radius_fn returned %d", rc);
    }
    if (st->target != 0) {
        rc = pds_set_count(t, st->target);
        FZ_CHECK(rc == 0, "replay: pds_set_count returned %d", rc);
    } else { /* refines before pds_set_count were overridden by it, after it refused */
        for (i = 0; ok && i < st->n_ev; i++) {
            ok = reach(t, st->ev[i].count, "before a refine");
            if (!ok) break;
            rc = pds_refine(t, st->ev[i].radius);
            FZ_CHECK(rc == 0 || rc == PDS_ENOMEM, "replay%s: pds_refine(%.17g) at %zu points "
                     "returned %d: %s", what, st->ev[i].radius, st->ev[i].count, rc,
                     pds_errmsg(t));
            ok = rc == 0;
        }
    }
    if (ok) ok = reach(t, n, "to the end");
    if (ok) {
        xy = malloc(2 * n * sizeof *xy);
        FZ_CHECK(xy != NULL, "harness out of memory (%zu points)", n);
        FZ_CHECK(pds_points(t, 0, n, xy) == n, "replay: pds_points");
        for (i = 0; i < 2 * n; i++)
            FZ_CHECK(memcmp(&xy[i], &st->pts[i], sizeof *xy) == 0, "replay%s: point %zu is "
                     "(%.17g, %.17g) without the splits, callback and cancels, (%.17g, %.17g) "
                     "with them (%zu points, %zu refines)", what, i / 2, xy[i - i % 2],
                     xy[i - i % 2 + 1], st->pts[i - i % 2], st->pts[i - i % 2 + 1], n, st->n_ev);
        FZ_CHECK(pds_radii(t, 0, n, xy) == n, "replay: pds_radii");
        for (i = 0; i < n; i++)
            FZ_CHECK(memcmp(&xy[i], &st->rad[i], sizeof *xy) == 0, "replay%s: the radius of "
                     "point %zu is %.17g, %.17g with the splits", what, i, xy[i], st->rad[i]);
        /* Count mode: a failure while the radius was lowered may leave it lower than
         * where the last point was added (the points are still the same). */
        r1 = pds_radius(st->s);
        r2 = pds_radius(t);
        FZ_CHECK(memcmp(&r1, &r2, sizeof r1) == 0 || (st->target != 0 && st->run_failed),
                 "replay%s: radius %.17g, %.17g without the splits", what, r1, r2);
        free(xy);
    }
    pds_destroy(t);
}

void fz_replay_check(fz_state *st)
{
    if (st->s == NULL || st->count == 0 || st->n_ev > FZ_MAX_EVENTS) return;
    fz_sync(st); /* st->pts and st->rad: all n points */
    replay(st, 1);
    if (st->field != FZ_FIELD_NONE && st->f_rmin == st->f_rmax) replay(st, 0);
}
