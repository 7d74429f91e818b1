/*
 * cli_args.h - the program's options (struct options) and their parsing:
 * the option table, its handlers and the checks across options.
 */
#ifndef POISSONDISK_CLI_ARGS_H
#define POISSONDISK_CLI_ARGS_H

#include <stdint.h>
#include <stdio.h>

#include "cli_domain.h"
#include "cli_field.h"
#include "cli_outputs.h"
#include "cli_report.h"
#include "cli_sample.h"

enum action { ACT_SAMPLE, ACT_HELP, ACT_VERSION };

struct options {
    uint64_t seed;
    struct cli_where where;   /* --domain, --periodic, --count */
    struct cli_field field;   /* --radius-map, --rmin, --rmax */
    struct cli_domain domain; /* --polygon, --mask, --fixed */
    unsigned domain_values;   /* times --domain's values were stored: 1, the default */
    struct cli_refines refines;/* --radius, --refine, --max-points, --progress */
    struct cli_outputs out;   /* --format, --output, --svg, --png, --spectrum... */
    int verify;
    int stats;
    int partial;       /* on Ctrl-C, write the points made so far */
    enum action action;
};

/* Reads argv into *o (zeroed by the caller). Returns 0 to go on, CLI_STOP
 * (--help, --version: printed), or an exit status after a message. */
int cli_parse_args(int argc, char **argv, struct options *o);
/* The option table (cli_options.h): --help, usage errors. */
struct cli_table;
const struct cli_table *cli_program_table(void);

#endif
