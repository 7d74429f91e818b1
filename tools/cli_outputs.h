/*
 * cli_outputs.h - the files the poissondisk program writes besides its
 * messages: the points in a format (--format, --output, --radii), the pictures
 * of the pattern (--svg, --disks, --png, --size, --dot-radius) and its spectrum (--spectrum,
 * --spectrum-plot, --spectrum-csv, --patterns, --spectrum-from). Each
 * function reports its own failure on stderr ("PROG: cannot write FILE:
 * reason") and returns an exit status. Public API only; plain C99.
 */
#ifndef POISSONDISK_CLI_OUTPUTS_H
#define POISSONDISK_CLI_OUTPUTS_H

#include <stddef.h>
#include <stdint.h>

#include "poissondisk.h"

#include "cli_report.h"
#include "cli_sample.h"
#include "out_formats.h"

#define CLI_DEFAULT_SIZE 512 /* --size */

/* What the command line asks to be written; NULL names: not wanted. */
struct cli_outputs {
    enum cli_format format;    /* --format, txt by default */
    const char *output;        /* --output FILE; NULL: standard output */
    int radii;                 /* --radii: each point's radius as a third value */
    const char *svg;           /* --svg FILE */
    int disks;                 /* --disks: the SVG shows disks of radius R/2 */
    const char *png;           /* --png FILE */
    unsigned size;             /* --size PX: the PNG pictures' side */
    double dot;                /* --dot-radius D: the dots' radius; 0: the default */
    const char *spectrum;      /* --spectrum FILE.png: the periodogram */
    const char *spectrum_plot; /* --spectrum-plot FILE.svg: power and anisotropy */
    const char *spectrum_csv;  /* --spectrum-csv FILE */
    const char *spectrum_from; /* --spectrum-from FILE: patterns to read, not make */
    unsigned patterns;         /* --patterns K: the spectrum's average, from seed on */
};

/*
 * The command line (cli_output_args.c). cli_outputs_option stores the
 * value of the output option name ("--format", "--svg", ...; value NULL for
 * the flags --disks and --radii) and returns CLI_OK, or CLI_BAD(0) when the value is not
 * what the option takes. cli_outputs_check is called once all is read:
 * NULL, or why the options cannot go together (written into msg).
 */
int cli_outputs_option(struct cli_outputs *o, const char *name, const char *value);
const char *cli_outputs_check(const struct cli_outputs *o, const struct cli_refines *rf,
                              const struct cli_where *w, int verify, int stats, int partial,
                              char *msg, size_t size);

/* Nonzero when any of the three spectrum outputs is asked for. */
int cli_spectrum_wanted(const struct cli_outputs *o);

/*
 * Writes the points of s in the chosen format (with --radii, each with its
 * radius) to --output, or to standard output. Returns 0 or CLI_EXIT_LIBRARY.
 */
int cli_write_points(const char *prog, const pds_sampler *s, const struct cli_outputs *o,
                     const struct cli_where *w);

/*
 * Writes --svg and --png of s. With a radius map (w->field) the disks of
 * --disks have each point's own radius (pds_radii), and the dots the
 * smallest radius's size unless --dot-radius. Returns 0 or CLI_EXIT_LIBRARY.
 */
int cli_write_pictures(const char *prog, const pds_sampler *s, const struct cli_outputs *o,
                       const struct cli_where *w);

/*
 * Writes the spectrum outputs (cli_spectrum.c): of s and, with --patterns K,
 * of K-1 more patterns made like s with the seeds seed+1 .. seed+K-1 (the
 * same radii, domain and options). The R of the frequency axis is
 * pds_radius(s), with a radius map the smallest radius. Returns 0, CLI_EXIT_INTERRUPTED (Ctrl-C
 * while making them: no spectrum file written) or another exit status.
 */
int cli_write_spectrum(const char *prog, const pds_sampler *s, const struct cli_outputs *o,
                       const struct cli_where *w, const struct cli_refines *rf, uint64_t seed);

/*
 * --spectrum-from: the spectrum outputs of the patterns read from the file
 * ("-": standard input), with radius the R of the frequency axis. Returns 0
 * or CLI_EXIT_LIBRARY (the file cannot be read, holds no point, or a line
 * is not a point).
 */
int cli_spectrum_from_file(const char *prog, const struct cli_outputs *o,
                           const struct cli_where *w, double radius);

#endif /* POISSONDISK_CLI_OUTPUTS_H */
