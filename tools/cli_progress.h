/*
 * cli_progress.h - the progress line and Ctrl-C for the command-line program.
 *
 * While pds_run works, the library calls cli_progress_report() (a
 * pds_progress_fn) about a hundred times plus once a second. It redraws one
 * line on a stream when the line is wanted, and it always answers whether
 * SIGINT has arrived, so that the run stops with PDS_ECANCELED at its next
 * report: the signal handler itself only sets a flag, the one thing a
 * handler may safely do. Knows nothing of the options; plain C99 + POSIX.
 */
#ifndef POISSONDISK_CLI_PROGRESS_H
#define POISSONDISK_CLI_PROGRESS_H

#include <stddef.h>
#include <stdio.h>

struct cli_progress {
    FILE *f;          /* where the line is drawn; NULL: no line, Ctrl-C only */
    const char *prog; /* the line's prefix */
    size_t target;    /* the count asked for (--count), or 0 */
    unsigned run;     /* 1-based run of the chain (the radius, then each --refine), shown when nruns > 1 */
    unsigned nruns;
    int width;        /* characters drawn last, so that the line can be wiped */
};

/*
 * The progress callback, user = struct cli_progress *. Redraws the line
 * ("\r", percent, points) and returns nonzero once SIGINT has arrived.
 */
int cli_progress_report(void *user, size_t count, double done);

/* Wipes the line (blanks over it, the cursor back at its start) if one is drawn. */
void cli_progress_clear(struct cli_progress *p);

/*
 * Catch SIGINT until cli_interrupt_end(): the first one only sets the flag
 * (and puts the default action back, so a second Ctrl-C ends the program at
 * once). A SIGINT ignored when the program started (nohup, a background job
 * of a shell without job control) stays ignored. Returns 0, or -1 when the
 * handler cannot be installed (Ctrl-C then just ends the program).
 */
int cli_interrupt_begin(void);
void cli_interrupt_end(void);

/* Nonzero once SIGINT arrived while caught. */
int cli_interrupted(void);

#endif /* POISSONDISK_CLI_PROGRESS_H */
