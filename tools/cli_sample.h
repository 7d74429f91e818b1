/*
 * cli_sample.h - the sampling run of the poissondisk program: set the sampler
 * up from the command line, then run at each radius in turn (the radius, then
 * each --refine radius) under the --max-points cap, with the progress callback
 * set, which stops the run once Ctrl-C was caught (cli_progress.c). Library
 * failures become a message and an exit status. Knows nothing of the option
 * table; public API only, plain C99.
 */
#ifndef POISSONDISK_CLI_SAMPLE_H
#define POISSONDISK_CLI_SAMPLE_H

#include <stddef.h>

#include "poissondisk.h"

#include "cli_report.h"

/* Named results of pds_run/pds_verify (1.1.1); the values are those of 1.0. */
#ifndef PDS_DONE
#define PDS_DONE 0
#endif
#ifndef PDS_MORE
#define PDS_MORE 1
#endif

/* Exit statuses besides CLI_EXIT_USAGE (cli_options.h). 130 = 128 + SIGINT,
   what a shell reports for a command ended by Ctrl-C. */
enum { CLI_EXIT_LIBRARY = 1, CLI_EXIT_INTERRUPTED = 130 };

/* The radii the command line asks for, each run in turn ("--refine" chain). */
struct cli_refines {
    double radius;     /* --radius; the library ignores it in count mode and with a
                          radius map */
    double *refine;    /* the --refine radii in command-line order */
    size_t nrefine;
    size_t max_points; /* 0: no cap (the option itself rejects 0) */
    int progress;      /* the progress line: -1 when stderr is a terminal, 0 never,
                          1 always */
    int threads;       /* --threads: 0 (one per online core) to 1024; -1 when not
                          given (the single-thread process) */
};

/*
 * Reports a failed library call ("PROG: WHAT VALUE: MSG") and gives the exit
 * status. An argument the library rejects (PDS_EINVAL) or a radius that does
 * not suit the domain (PDS_ERANGE) came from the command line: status 2;
 * anything else: 1.
 */
int cli_library_error(const char *prog, const struct cli_where *w, int rc, const char *what,
                      double value, const char *msg);

/*
 * Sets the domain, --periodic, the polygon, mask and fixed points
 * (cli_domain.h; w->shape->area measured), the radius map and --count on a
 * new sampler.
 * Returns 0 or an exit status.
 */
int cli_configure(const char *prog, pds_sampler *s, const struct cli_where *w, double radius);

/*
 * Runs at every radius, drawing the progress line when wanted. *maximal
 * tells whether the last run reached maximality. Returns 0,
 * CLI_EXIT_INTERRUPTED when Ctrl-C stopped the run or had come before it (the
 * points so far stay in the sampler), or another exit status after a
 * message. Ctrl-C is caught while the caller holds cli_interrupt_begin(); on
 * return the sampler has no progress callback.
 */
int cli_sample(const char *prog, pds_sampler *s, const struct cli_refines *rf,
               const struct cli_where *w, int *maximal);

#endif /* POISSONDISK_CLI_SAMPLE_H */
