/*
 * cli_spectrum.c - the spectrum outputs of the poissondisk program (see
 * cli_outputs.h): the patterns averaged (made here, or read with
 * --spectrum-from), then the PNG, the CSV and the plot (spectrum_out.h).
 * The frequency grid reaches 2/R along each axis (spectrum.h). The sums
 * cost N points times the grid per pattern, seconds at small R: they stop
 * between chunks of points once Ctrl-C was caught (cli_progress.h), as the
 * sampling does at its next progress report.
 */
#include "cli_outputs.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_progress.h"
#include "points_in.h"
#include "spectrum.h"
#include "spectrum_out.h"

#define FMAX_TIMES_R 2.0 /* the grid reaches this many times 1/R */
#define CHUNK_POINTS 4096

/* Adds every point of s to the spectrum as one pattern. Returns 0, or
   CLI_EXIT_INTERRUPTED once Ctrl-C was caught (the sums are then partial). */
static int add_sampler(struct spectrum *sp, const pds_sampler *s)
{
    static double xy[2 * CHUNK_POINTS];
    size_t first = 0, got;

    while ((got = pds_points(s, first, CHUNK_POINTS, xy)) > 0) {
        if (cli_interrupted())
            return CLI_EXIT_INTERRUPTED;
        spectrum_add(sp, xy, got);
        first += got;
    }
    spectrum_end_pattern(sp);
    return cli_interrupted() ? CLI_EXIT_INTERRUPTED : 0;
}

/* Writes the three outputs asked for. Returns 0 or an exit status. */
static int write_all(const char *prog, const struct spectrum *sp, const struct cli_outputs *o,
                     double radius)
{
    struct spectrum_ring *rings = NULL;
    size_t n = spectrum_rings(sp, &rings);
    const char *failed = NULL;

    if (n == 0 && (o->spectrum_csv != NULL || o->spectrum_plot != NULL)) {
        fprintf(stderr, "%s: out of memory for the spectrum's rings\n", prog);
        return CLI_EXIT_LIBRARY;
    }
    errno = 0;
    if (o->spectrum != NULL && spectrum_write_png(sp, o->spectrum, o->size) != 0)
        failed = o->spectrum;
    else if (o->spectrum_csv != NULL && spectrum_write_csv(rings, n, radius, o->spectrum_csv))
        failed = o->spectrum_csv;
    else if (o->spectrum_plot != NULL
             && spectrum_write_plot(rings, n, radius, sp->patterns, o->spectrum_plot) != 0)
        failed = o->spectrum_plot;
    free(rings);
    if (failed != NULL) {
        fprintf(stderr, "%s: cannot write %s: %s\n", prog, failed, strerror(errno));
        return CLI_EXIT_LIBRARY;
    }
    return 0;
}

/* Makes the pattern of seed like the first one and adds it. Returns an exit status. */
static int add_pattern(const char *prog, struct spectrum *sp, const struct cli_where *w,
                       const struct cli_refines *rf, uint64_t seed)
{
    pds_sampler *s = NULL;
    int maximal, rc, status;

    rc = pds_create(&s, w->count > 0 ? 1.0 : rf->radius, seed);
    if (rc < 0)
        return cli_library_error(prog, w, rc, "cannot create a sampler with radius",
                                 rf->radius, pds_strerror(rc));
    status = cli_configure(prog, s, w, rf->radius);
    if (status == 0)
        status = cli_sample(prog, s, rf, w, &maximal);
    if (status == 0)
        status = add_sampler(sp, s);
    pds_destroy(s);
    return status;
}

int cli_write_spectrum(const char *prog, const pds_sampler *s, const struct cli_outputs *o,
                       const struct cli_where *w, const struct cli_refines *rf, uint64_t seed)
{
    struct spectrum sp;
    /* With a radius map, the smallest radius: the grid then reaches past every ring. */
    double radius = w->field != NULL ? cli_field_smallest(w->field, pds_radius(s))
                                     : pds_radius(s);
    unsigned k;
    int status = 0;

    if (!cli_spectrum_wanted(o))
        return 0;
    if (spectrum_init(&sp, w->box, FMAX_TIMES_R / radius) != 0) {
        fprintf(stderr, "%s: out of memory for the spectrum\n", prog);
        return CLI_EXIT_LIBRARY;
    }
    status = add_sampler(&sp, s);
    for (k = 1; k < o->patterns && status == 0; k++)
        status = add_pattern(prog, &sp, w, rf, seed + k);
    if (status == CLI_EXIT_INTERRUPTED)
        fprintf(stderr, "%s: interrupted while making pattern %u of %u for the spectrum; "
                        "no spectrum written\n", prog, k, o->patterns);
    if (status == 0)
        status = write_all(prog, &sp, o, radius);
    spectrum_free(&sp);
    return status;
}

int cli_spectrum_from_file(const char *prog, const struct cli_outputs *o,
                           const struct cli_where *w, double radius)
{
    struct patterns_in in;
    struct spectrum sp;
    const char *name = o->spectrum_from;
    int from_stdin = strcmp(name, "-") == 0;
    FILE *f = from_stdin ? stdin : fopen(name, "r");
    size_t p;
    long rc;
    int status;

    if (f == NULL) {
        fprintf(stderr, "%s: cannot read %s: %s\n", prog, name, strerror(errno));
        return CLI_EXIT_LIBRARY;
    }
    rc = patterns_read(f, &in);
    if (!from_stdin)
        fclose(f);
    if (rc != 0) {
        if (rc < 0)
            fprintf(stderr, "%s: cannot read %s: %s\n", prog, name, strerror(errno));
        else
            fprintf(stderr, "%s: %s, line %ld: not a point (\"x y\" or \"x,y\")\n", prog, name,
                    rc);
        return CLI_EXIT_LIBRARY;
    }
    if (in.npatterns == 0) {
        fprintf(stderr, "%s: %s holds no point\n", prog, name);
        return CLI_EXIT_LIBRARY;
    }
    if (spectrum_init(&sp, w->box, FMAX_TIMES_R / radius) != 0) {
        patterns_free(&in);
        fprintf(stderr, "%s: out of memory for the spectrum\n", prog);
        return CLI_EXIT_LIBRARY;
    }
    for (p = 0; p < in.npatterns; p++) {
        spectrum_add(&sp, in.xy + 2 * in.first[p], in.first[p + 1] - in.first[p]);
        spectrum_end_pattern(&sp);
    }
    patterns_free(&in);
    status = write_all(prog, &sp, o, radius);
    spectrum_free(&sp);
    return status;
}
