/*
 * fuzz_replay.c - the determinism check of the fuzz harness (see fuzz.h).
 *
 * The same seed gives the same points however the work is split, and a run
 * canceled by the progress callback continues exactly as an uninterrupted
 * one. So before a sampler is dropped, a second one is made with the same
 * pds_create arguments, domain, kind (torus or not) and count, and without a
 * callback; it runs in one bounded pds_run to each count at which the input
 * refined, refines there, and runs to the first sampler's count. Its points
 * and radius must be the first's, byte for byte, whatever mix of steps,
 * chunks, cancellations and out-of-memory failures led the first there.
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

void fz_replay_check(fz_state *st)
{
    const size_t n = st->count;
    pds_sampler *t = NULL;
    double *xy, r1, r2;
    size_t i;
    int rc, ok = 1;

    if (st->s == NULL || n == 0 || st->n_ev > FZ_MAX_EVENTS) return;
    fz_sync(st); /* st->pts: all n points */
    if (pds_create(&t, st->c_radius, st->c_seed) != 0) return; /* out of memory */
    rc = pds_set_domain(t, st->dom[0], st->dom[1], st->dom[2], st->dom[3]);
    FZ_CHECK(rc == 0, "replay: pds_set_domain returned %d", rc);
    rc = pds_set_periodic(t, st->periodic);
    FZ_CHECK(rc == 0, "replay: pds_set_periodic returned %d", rc);
    if (st->target != 0) {
        rc = pds_set_count(t, st->target);
        FZ_CHECK(rc == 0, "replay: pds_set_count returned %d", rc);
    } else { /* refines before pds_set_count were overridden by it, after it refused */
        for (i = 0; ok && i < st->n_ev; i++) {
            ok = reach(t, st->ev[i].count, "before a refine");
            if (!ok) break;
            rc = pds_refine(t, st->ev[i].radius);
            FZ_CHECK(rc == 0 || rc == PDS_ENOMEM, "replay: pds_refine(%.17g) at %zu points "
                     "returned %d: %s", st->ev[i].radius, st->ev[i].count, rc, pds_errmsg(t));
            ok = rc == 0;
        }
    }
    if (ok) ok = reach(t, n, "to the end");
    if (ok) {
        xy = malloc(2 * n * sizeof *xy);
        FZ_CHECK(xy != NULL, "harness out of memory (%zu points)", n);
        FZ_CHECK(pds_points(t, 0, n, xy) == n, "replay: pds_points");
        for (i = 0; i < 2 * n; i++)
            FZ_CHECK(memcmp(&xy[i], &st->pts[i], sizeof *xy) == 0, "replay: point %zu is "
                     "(%.17g, %.17g) without the splits, callback and cancels, (%.17g, %.17g) "
                     "with them (%zu points, %zu refines)", i / 2, xy[i - i % 2],
                     xy[i - i % 2 + 1], st->pts[i - i % 2], st->pts[i - i % 2 + 1], n, st->n_ev);
        /* Count mode: a failure while the radius was lowered may leave it lower than
         * where the last point was added (the points are still the same). */
        r1 = pds_radius(st->s);
        r2 = pds_radius(t);
        FZ_CHECK(memcmp(&r1, &r2, sizeof r1) == 0 || (st->target != 0 && st->run_failed),
                 "replay: radius %.17g, %.17g without the splits", r1, r2);
        free(xy);
    }
    pds_destroy(t);
}
