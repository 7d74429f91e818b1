/*
 * fuzz_progress.c - the progress callback of the fuzz harness and the
 * contract of pds_run around it (pds_set_progress, 1.2).
 *
 * The callback (user = the fz_state) checks each report: called only from
 * pds_run (never from pds_step, pds_verify, ...); `count` is pds_count(s);
 * `done` lies in [0,1], never falls within a run, and is count/n in count
 * mode; the radius never grows; the points can be read. It may try a call
 * that changes the sampler, which must return PDS_ESTATE and change nothing,
 * and it asks to stop at every k-th call. After the run (fz_run): a stop
 * asked for on a report between points ends the run with PDS_ECANCELED at
 * that count; a stop on the final report (done == 1) may instead give
 * PDS_DONE; every PDS_DONE comes after a final report with done == 1 at the
 * final count; at most about 100 reports per run plus one per second.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

/* One call that changes the sampler, from inside the callback: PDS_ESTATE. */
static void try_change(fz_state *st, size_t count)
{
    pds_sampler *s = st->s;
    const double r = pds_radius(s);
    size_t added = 99;
    const char *fn = "";
    double r2;
    int rc = 0;

    switch (st->prog.change) {
        case 1: fn = "pds_run"; rc = pds_run(s, 1, &added); break;
        case 2: fn = "pds_step"; rc = pds_step(s); break;
        case 3: fn = "pds_refine"; rc = pds_refine(s, r * 0.5); break;
        case 4: fn = "pds_set_domain"; rc = pds_set_domain(s, 0.0, 0.0, 1.0, 1.0); break;
        case 5: fn = "pds_set_periodic"; rc = pds_set_periodic(s, !st->periodic); break;
        case 6: fn = "pds_set_count"; rc = pds_set_count(s, 10); break;
        case 7: fn = "pds_set_progress"; rc = pds_set_progress(s, NULL, NULL); break;
        case 8: fn = "pds_set_progress"; rc = pds_set_progress(s, fz_progress_cb, st); break;
        case 9: { /* 1.3 */
            const double one = 1.0;
            fn = "pds_set_radius_map";
            rc = pds_set_radius_map(s, 1, 1, &one);
            break;
        }
        case 10:
            fn = "pds_set_radius_fn";
            rc = pds_set_radius_fn(s, fz_field_cb, &st->fns[st->fn_active], 1.0, 2.0);
            break;
        default: return;
    }
    fz_codes(st, fn, rc, FZ_BIT(PDS_ESTATE));
    FZ_CHECK(st->prog.change != 1 || added == 0, "pds_run from the callback: added %zu", added);
    FZ_CHECK(pds_count(s) == count, "%s from the callback changed the count from %zu to %zu",
             fn, count, pds_count(s));
    r2 = pds_radius(s);
    FZ_CHECK(memcmp(&r, &r2, sizeof r) == 0, "%s from the callback changed the radius from "
             "%.17g to %.17g", fn, r, r2);
}

int fz_progress_cb(void *user, size_t count, double done)
{
    fz_state *st = user;
    fz_progress *p = &st->prog;
    const double r = pds_radius(st->s);
    double xy[2];
    int stop;

    FZ_CHECK(p->on && p->in_run, "the progress callback was called outside pds_run");
    FZ_CHECK(pds_count(st->s) == count, "progress: count %zu, pds_count %zu", count,
             pds_count(st->s));
    FZ_CHECK(done >= 0.0 && done <= 1.0, "progress: done = %.17g", done);
    FZ_CHECK(count >= p->run_before, "progress: count %zu below the %zu at the run's start",
             count, p->run_before);
    if (p->run_calls > 0)
        FZ_CHECK(done >= p->last_done && count >= p->last_count, "progress: done %.17g at %zu "
                 "points after %.17g at %zu", done, count, p->last_done, p->last_count);
    if (st->target != 0)
        FZ_CHECK(fabs(done - (double)count / (double)st->target) <= 1e-15, "progress in count "
                 "mode: done %.17g at %zu of %zu points", done, count, st->target);
    FZ_CHECK(isfinite(r) && r > 0.0 && r <= p->run_radius, "progress: radius %.17g, %.17g at "
             "the run's start", r, p->run_radius);
    if (count > 0) {
        FZ_CHECK(pds_points(st->s, count - 1, 2, xy) == 1, "progress: pds_points(%zu, 2) "
                 "with %zu points", count - 1, count);
        FZ_CHECK(isfinite(xy[0]) && isfinite(xy[1]), "progress: the last point is (%g, %g)",
                 xy[0], xy[1]);
        if (st->seen > 0) {
            FZ_CHECK(pds_points(st->s, 0, 1, xy) == 1, "progress: pds_points(0, 1)");
            FZ_CHECK(memcmp(xy, st->pts, sizeof xy) == 0, "progress: point 0 moved");
        }
    }
    try_change(st, count);
    p->run_calls++;
    p->calls++;
    stop = p->cancel_every != 0 && p->calls % p->cancel_every == 0;
    p->last_stopped = stop;
    p->stops += (size_t)stop;
    p->last_done = done;
    p->last_count = count;
    return stop ? (int)(p->calls % 3) * 2 - 3 : 0; /* -3, -1 or 1: any nonzero value */
}

int fz_run(fz_state *st, size_t max_new, size_t *added)
{
    fz_progress *p = &st->prog;
    size_t now;
    double seconds;
    int rc;

    p->in_run = 1;
    p->run_calls = 0;
    p->stops = 0;
    p->last_stopped = 0;
    p->run_before = pds_count(st->s);
    p->run_radius = pds_radius(st->s);
    p->started = time(NULL);
    rc = pds_run(st->s, max_new, added);
    p->in_run = 0;
    if (st->s == NULL) return rc;
    FZ_CHECK(p->on || p->run_calls == 0, "pds_run called a removed callback");
    if (!p->on) return rc;
    now = pds_count(st->s);
    seconds = difftime(time(NULL), p->started);
    FZ_CHECK((double)p->run_calls <= 103.0 + seconds, "progress: %zu calls in one run of %.0f s",
             p->run_calls, seconds);
    if (rc == PDS_ECANCELED)
        FZ_CHECK(p->run_calls > 0 && p->last_stopped && now == p->last_count, "pds_run returned "
                 "PDS_ECANCELED at %zu points; the callback's last call (of %zu) was at %zu and "
                 "asked %s", now, p->run_calls, p->last_count, p->last_stopped ? "to stop" :
                 "to go on");
    else if (p->stops > 0) /* only a stop asked on the final report may be ignored */
        FZ_CHECK(rc == PDS_DONE && p->stops == 1 && p->last_stopped && p->last_done == 1.0,
                 "the callback asked to stop %zu times (the last call: %s, done %.17g) but "
                 "pds_run returned %d after %zu calls", p->stops, p->last_stopped ? "stop" :
                 "go on", p->last_done, rc, p->run_calls);
    if (rc == PDS_DONE)
        FZ_CHECK(p->run_calls > 0 && p->last_done == 1.0 && p->last_count == now, "pds_run "
                 "ended complete at %zu points without a final report (%zu calls, the last at "
                 "%zu points, done %.17g)", now, p->run_calls, p->last_count, p->last_done);
    return rc;
}
