/*
 * poissondisk - command-line front end to libpoissondisk.
 *
 * Generates a maximal Poisson-disk pattern and writes one "x y" line per
 * point to stdout, in insertion order, with %.17g so every value reads back
 * as exactly the same double. Optional refinements (--refine) continue
 * the same pattern at smaller radii; --max-points caps the total. --count
 * lets the library choose the radius for an exact number of points instead,
 * and --periodic makes the pattern tile the plane; --radius-map gives each
 * point a radius of its own, from a grey-scale image (cli_field.c: black
 * dense, white sparse, as a stippling). --polygon and --mask shape the
 * domain, --fixed gives points already there (cli_domain.c). --format and --output
 * choose how and where the points go; --svg, --png and the --spectrum
 * options draw and analyse the pattern (cli_outputs.c, cli_spectrum.c).
 *
 * The options live in one table (cli_args.c); cli_options.c makes
 * the parsing, the defaults, the usage line and the --help text from it, so
 * they cannot disagree. Arguments are read left to right; --help or
 * --version prints and ends the program there, without sampling. The
 * sampling itself, radius after radius, is in cli_sample.c.
 *
 * The library is used through the public header only, like any client, so it
 * doubles as a worked example of the C API. It is plain C99 plus
 * clock_gettime(), isatty() and sigaction() from POSIX.
 *
 * While sampling (cli_sample.c), a progress callback is always set: it
 * draws the progress line when wanted (cli_progress.c) and stops the run
 * with PDS_ECANCELED once Ctrl-C was pressed. Ctrl-C is caught from the
 * first point until the points are written, and the points are written
 * last, after --verify, the pictures and the spectrum (which may make more
 * patterns): a Ctrl-C at any time before leaves standard output empty
 * unless --partial asks for the points made so far.
 *
 * Exit status: 0 success, 1 library or output failure, 2 bad arguments,
 * including values only the library can judge (PDS_EINVAL, PDS_ERANGE),
 * 130 interrupted by SIGINT.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "poissondisk.h"

#include "cli_args.h"
#include "cli_options.h"
#include "cli_outputs.h"
#include "cli_progress.h"
#include "cli_report.h"
#include "cli_sample.h"

#define PROG "poissondisk"

enum { EXIT_LIBRARY = CLI_EXIT_LIBRARY, EXIT_INTERRUPTED = CLI_EXIT_INTERRUPTED };

static double now_seconds(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

int main(int argc, char **argv)
{
    /* Full buffering in large blocks: 10^6 lines must not mean 10^6 writes. */
    static char outbuf[1 << 20];
    struct options o;
    pds_sampler *s = NULL;
    int status, rc, maximal = 0, verified = 0;
    double t0, seconds;

    memset(&o, 0, sizeof o);
    o.action = ACT_SAMPLE;
    o.refines.progress = -1;
    o.refines.threads = -1; /* no --threads: the single-thread process */
    setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);

    status = cli_parse_args(argc, argv, &o);
    if (status == CLI_STOP) {
        /* --help or --version: print, and never go on to sample. */
        if (o.action == ACT_HELP)
            cli_print_help(cli_program_table(), stdout);
        else
            printf(PROG " %s\n", pds_version_string());
        status = fflush(stdout) == 0 && !ferror(stdout) ? EXIT_SUCCESS : EXIT_LIBRARY;
        goto done;
    }
    if (status != 0)
        goto done;
    if (o.out.spectrum_from != NULL) { /* nothing to sample */
        status = cli_spectrum_from_file(PROG, &o.out, &o.where, o.refines.radius);
        goto done;
    }
    /* Every input file is read before the sampler exists, the outputs long after:
       a malformed file leaves no output behind. */
    if (o.domain.polygon != NULL || o.domain.mask != NULL || o.domain.fixed != NULL) {
        if ((status = cli_domain_load(PROG, &o.domain, o.where.box)) != 0)
            goto done;
        o.where.shape = &o.domain;
    }
    if (o.field.path != NULL) {
        if ((status = cli_field_load(PROG, &o.field)) != 0)
            goto done;
        o.where.field = &o.field;
        /* The radius of the sampler, and what --refine refines from: the largest. */
        o.refines.radius = o.field.hi;
        if (o.refines.nrefine > 0 && o.refines.refine[0] > o.field.hi) {
            status = cli_usage_error(cli_program_table(), "--refine %g is larger than the largest radius of "
                                     "--radius-map %s, %g", o.refines.refine[0], o.field.path,
                                     o.field.hi);
            goto done;
        }
    }

    t0 = now_seconds();
    /* In count mode the library ignores the radius given here. */
    rc = pds_create(&s, o.where.count > 0 ? 1.0 : o.refines.radius, o.seed);
    if (rc < 0) {
        /* No handle, so no pds_errmsg(): the code's text is all there is. */
        status = cli_library_error(PROG, &o.where, rc, "cannot create a sampler with radius",
                                   o.refines.radius, pds_strerror(rc));
        goto done;
    }
    if ((status = cli_configure(PROG, s, &o.where, o.refines.radius)) != 0)
        goto done;
    /* The radius the clearances are taken at (count mode has chosen its first). */
    o.domain.radius0 = pds_radius(s);

    /* Caught until the points are written; a second Ctrl-C ends the program at once. */
    cli_interrupt_begin();
    status = cli_sample(PROG, s, &o.refines, &o.where, &maximal);
    seconds = now_seconds() - t0;

    /* Verify before writing, so a failed check leaves no plausible output. */
    if (status == 0 && o.verify) {
        rc = pds_verify(s);
        if (rc != PDS_DONE && rc != PDS_MORE) {
            fprintf(stderr, PROG ": verification failed: %s\n", pds_errmsg(s));
            status = EXIT_LIBRARY;
        } else {
            verified = 1;
            maximal = rc == PDS_DONE; /* exact, so it overrides the running answer */
        }
    }
    /* The files first, the spectrum's patterns too: the points are the last output. */
    if (status == 0 && !cli_interrupted())
        status = cli_write_pictures(PROG, s, &o.out, &o.where);
    if (status == 0 && !cli_interrupted())
        status = cli_write_spectrum(PROG, s, &o.out, &o.where, &o.refines, o.seed);
    /* From here on Ctrl-C ends the program at once; one caught before still counts. */
    cli_interrupt_end();
    if ((status == 0 || status == EXIT_INTERRUPTED) && cli_interrupted()) {
        status = EXIT_INTERRUPTED;
        fprintf(stderr, PROG ": interrupted after %zu points%s\n", pds_count(s),
                o.partial ? "; writing them" : "");
        if (o.partial && cli_write_points(PROG, s, &o.out, &o.where) != 0)
            status = EXIT_LIBRARY;
        goto done;
    }
    if (status != 0 || (status = cli_write_points(PROG, s, &o.out, &o.where)) != 0)
        goto done;

    if (o.stats)
        cli_print_stats(PROG, s, &o.where, maximal, verified, seconds);

done:
    pds_destroy(s);
    cli_field_free(&o.field);
    cli_domain_free(&o.domain);
    free(o.refines.refine);
    return status;
}
