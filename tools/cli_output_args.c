/*
 * cli_output_args.c - the values of the output options and the rules that
 * tie them together (see cli_outputs.h); the option table itself is in
 * poissondisk.c.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_outputs.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli_options.h"

#define MAX_SIZE 16384       /* --size: a 16384 x 16384 grey image is 256 MiB */
#define MAX_PATTERNS 100000u /* --patterns */

/* An integer from 1 to max. */
static int parse_count(const char *text, uint64_t max, unsigned *out)
{
    uint64_t v;

    if (cli_parse_u64(text, &v) != 0 || v == 0 || v > max)
        return CLI_BAD(0);
    *out = (unsigned)v;
    return CLI_OK;
}

int cli_outputs_option(struct cli_outputs *o, const char *name, const char *value)
{
    static const char *const file_options[] = { "--output", "--svg", "--png", "--spectrum",
                                                "--spectrum-plot", "--spectrum-csv",
                                                "--spectrum-from" };
    const char **slots[7];
    size_t k;

    if (strcmp(name, "--disks") == 0) {
        o->disks = 1;
        return CLI_OK;
    }
    if (strcmp(name, "--radii") == 0) {
        o->radii = 1;
        return CLI_OK;
    }
    if (strcmp(name, "--dot-radius") == 0)
        return cli_parse_double(value, &o->dot) == 0 && o->dot > 0 ? CLI_OK : CLI_BAD(0);
    if (strcmp(name, "--format") == 0)
        return cli_format_parse(value, &o->format) == 0 ? CLI_OK : CLI_BAD(0);
    if (strcmp(name, "--size") == 0)
        return parse_count(value, MAX_SIZE, &o->size);
    if (strcmp(name, "--patterns") == 0)
        return parse_count(value, MAX_PATTERNS, &o->patterns);
    slots[0] = &o->output;
    slots[1] = &o->svg;
    slots[2] = &o->png;
    slots[3] = &o->spectrum;
    slots[4] = &o->spectrum_plot;
    slots[5] = &o->spectrum_csv;
    slots[6] = &o->spectrum_from;
    for (k = 0; k < sizeof file_options / sizeof file_options[0]; k++)
        if (strcmp(name, file_options[k]) == 0) {
            if (value[0] == '\0')
                return CLI_BAD(0);
            *slots[k] = value;
            return CLI_OK;
        }
    return CLI_BAD(0); /* not an output option: the table's mistake */
}

const char *cli_outputs_check(const struct cli_outputs *o, const struct cli_refines *rf,
                              const struct cli_where *w, int verify, int stats, int partial,
                              char *msg, size_t size)
{
    int spectrum = cli_spectrum_wanted(o);

    if (o->spectrum_from != NULL) {
        /* Nothing is sampled: the options that make or write a pattern have no object. */
        const char *other = w->count > 0 ? "--count"
                          : rf->nrefine > 0 ? "--refine"
                          : rf->max_points > 0 ? "--max-points"
                          : verify ? "--verify"
                          : stats ? "--stats"
                          : partial ? "--partial"
                          : o->patterns > 1 ? "--patterns"
                          : o->format != CLI_FORMAT_TXT ? "--format"
                          : o->output != NULL ? "--output"
                          : o->radii ? "--radii"
                          : o->svg != NULL ? "--svg"
                          : o->png != NULL ? "--png"
                          : o->dot > 0 ? "--dot-radius" : NULL;
        if (other != NULL)
            snprintf(msg, size, "%s cannot be used with --spectrum-from: the patterns are read, "
                                "not made", other);
        else if (!spectrum)
            snprintf(msg, size, "--spectrum-from needs --spectrum, --spectrum-plot or "
                                "--spectrum-csv");
        return other != NULL || !spectrum ? msg : NULL;
    }
    if (o->disks && o->svg == NULL) {
        snprintf(msg, size, "--disks needs --svg");
        return msg;
    }
    if (o->dot > 0 && o->svg == NULL && o->png == NULL) {
        snprintf(msg, size, "--dot-radius needs --svg or --png");
        return msg;
    }
    if (o->patterns > 1 && !spectrum) {
        snprintf(msg, size, "--patterns needs --spectrum, --spectrum-plot or --spectrum-csv");
        return msg;
    }
    /* Binary data would garble a terminal; a redirection or --output is a choice. */
    if (cli_format_is_binary(o->format) && o->output == NULL && isatty(STDOUT_FILENO)) {
        snprintf(msg, size, "--format %s writes binary data: give --output FILE or redirect "
                            "standard output", o->format == CLI_FORMAT_NPY ? "npy" : "bin");
        return msg;
    }
    return NULL;
}
