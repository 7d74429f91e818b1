/*
 * cli_sample.c - the sampling run of the poissondisk program (see
 * cli_sample.h): configuration, the run at each radius of the --refine chain,
 * the progress line and the Ctrl-C answer.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_sample.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli_options.h"
#include "cli_progress.h"

int cli_library_error(const char *prog, const struct cli_where *w, int rc, const char *what,
                      double value, const char *msg)
{
    if (rc == PDS_ERANGE)
        return cli_range_error(prog, w, value, msg);
    fprintf(stderr, "%s: %s %g: %s\n", prog, what, value, msg);
    return rc == PDS_EINVAL ? CLI_EXIT_USAGE : CLI_EXIT_LIBRARY;
}

int cli_configure(const char *prog, pds_sampler *s, const struct cli_where *w, double radius)
{
    /* Set even as the default unit square, the library's own default; not with a
       polygon, which replaces it (box is then its bounding box, flat when the
       polygon is: pds_set_polygon names the ring). */
    const double *d = w->box;
    char domain[128];
    int polygon = w->shape != NULL && w->shape->polygon != NULL;
    int rc = polygon ? 0 : pds_set_domain(s, d[0], d[1], d[2], d[3]);
    if (rc < 0) {
        if (rc == PDS_ERANGE)
            return cli_range_error(prog, w, radius, pds_errmsg(s));
        fprintf(stderr, "%s: cannot set domain %s: %s\n", prog,
                cli_domain_text(domain, sizeof domain, w), pds_errmsg(s));
        return rc == PDS_EINVAL ? CLI_EXIT_USAGE : CLI_EXIT_LIBRARY;
    }
    if (w->periodic && (rc = pds_set_periodic(s, 1)) < 0) {
        fprintf(stderr, "%s: cannot make the domain periodic: %s\n", prog, pds_errmsg(s));
        return CLI_EXIT_LIBRARY;
    }
    /* Before the radius map, spread over the polygon's bounding box. */
    if (w->shape != NULL
        && (rc = cli_domain_configure(prog, s, w->shape, &w->shape->area)) != 0)
        return rc;
    if (w->field != NULL
        && (rc = pds_set_radius_map(s, w->field->w, w->field->h, w->field->r)) < 0) {
        fprintf(stderr, "%s: cannot use --radius-map %s: %s\n", prog, w->field->path,
                pds_errmsg(s));
        return rc == PDS_EINVAL ? CLI_EXIT_USAGE : CLI_EXIT_LIBRARY;
    }
    if (w->count > 0 && (rc = pds_set_count(s, w->count)) < 0) {
        fprintf(stderr, "%s: cannot ask for --count %zu: %s\n", prog, w->count, pds_errmsg(s));
        return rc == PDS_EINVAL ? CLI_EXIT_USAGE : CLI_EXIT_LIBRARY;
    }
    return 0;
}

/*
 * Runs at each radius in turn: the initial radius, then each --refine radius.
 * *maximal tells whether the last run reached maximality. Returns an exit
 * status; CLI_EXIT_INTERRUPTED when Ctrl-C stopped a run (the points so far stay).
 */
static int run_chain(const char *prog, pds_sampler *s, const struct cli_refines *rf,
                      const struct cli_where *w, struct cli_progress *bar, int *maximal)
{
    size_t total = 0, k;
    int rc;

    *maximal = 0;
    for (k = 0; k <= rf->nrefine; k++) {
        if (k > 0) {
            rc = pds_refine(s, rf->refine[k - 1]);
            if (rc < 0)
                return cli_library_error(prog, w, rc, "cannot refine to radius",
                                         rf->refine[k - 1], pds_errmsg(s));
        }
        /* Once the cap is used up, the later radii only lower the radius. */
        if (rf->max_points == 0 || total < rf->max_points) {
            size_t added = 0;
            size_t max_new = rf->max_points == 0 ? 0 : rf->max_points - total;
            bar->run = (unsigned)k + 1;
            rc = pds_run(s, max_new, &added);
            total += added;
            if (rc == PDS_ECANCELED)
                return CLI_EXIT_INTERRUPTED;
            if (rc != PDS_DONE && rc != PDS_MORE) /* PDS_EINVAL would be our bug */
                return cli_library_error(prog, w, rc == PDS_EINVAL ? PDS_EINTERNAL : rc,
                                         "sampling failed at radius", pds_radius(s),
                                         pds_errmsg(s));
            /* PDS_MORE: the cap stopped it, room left. In count mode PDS_DONE only
               says that N points exist: cli_print_stats asks the library when it
               matters. */
            *maximal = rc == PDS_DONE && w->count == 0;
        } else {
            /* No run at this radius: maximal only if nothing is left free. */
            *maximal = pds_free_area(s) == 0.0;
        }
    }
    return 0;
}

int cli_sample(const char *prog, pds_sampler *s, const struct cli_refines *rf,
               const struct cli_where *w, int *maximal)
{
    struct cli_progress bar;
    int status;

    *maximal = 0;
    memset(&bar, 0, sizeof bar);
    /* The callback is set even without the line: it is how Ctrl-C stops a run. */
    bar.f = rf->progress == 1 || (rf->progress == -1 && isatty(STDERR_FILENO)) ? stderr : NULL;
    bar.prog = prog;
    bar.target = w->count;
    bar.nruns = (unsigned)rf->nrefine + 1;
    /* The parallel process, if asked for: its points are the same for any count. */
    if (rf->threads >= 0 && pds_set_threads(s, (unsigned)rf->threads) < 0) {
        fprintf(stderr, "%s: cannot use --threads %d: %s\n", prog, rf->threads, pds_errmsg(s));
        return CLI_EXIT_USAGE;
    }
    if (pds_set_progress(s, cli_progress_report, &bar) < 0) {
        fprintf(stderr, "%s: cannot follow the progress: %s\n", prog, pds_errmsg(s));
        return CLI_EXIT_LIBRARY;
    }
    status = run_chain(prog, s, rf, w, &bar, maximal);
    cli_progress_clear(&bar);
    /* bar lives on this stack frame: the sampler must not keep pointing at it. */
    pds_set_progress(s, NULL, NULL);
    if (status == 0 && cli_interrupted()) /* after the run's last report, or before it */
        status = CLI_EXIT_INTERRUPTED;
    return status;
}
