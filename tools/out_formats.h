/*
 * out_formats.h - the point formats of the poissondisk program (--format).
 *
 *   txt   one "x y" line per point (%.17g: each value reads back as the same
 *         double); the format of every release
 *   csv   a header line "x,y", then one "x,y" line per point (%.17g)
 *   json  one object: radius, domain [x0, y0, x1, y1], periodic, count and
 *         points [[x, y], ...] (%.17g)
 *   bin   raw little-endian IEEE-754 doubles x0 y0 x1 y1 ..., nothing else
 *   npy   NumPy format 1.0, dtype '<f8', C order, shape (N, 2):
 *         numpy.load() reads it as is
 *
 * With radii (--radii) each point carries its radius (pds_radii) as a third
 * value: "x y r" lines, csv header "x,y,r", json [x, y, r], bin x y r
 * triples, npy shape (N, 3).
 *
 * Points are always written in insertion order, fetched from the sampler a
 * bounded number at a time, so any N needs the same memory. Public API only;
 * plain C99.
 */
#ifndef POISSONDISK_OUT_FORMATS_H
#define POISSONDISK_OUT_FORMATS_H

#include <stdio.h>

#include "poissondisk.h"

enum cli_format { CLI_FORMAT_TXT, CLI_FORMAT_CSV, CLI_FORMAT_JSON, CLI_FORMAT_BIN, CLI_FORMAT_NPY };

/* The format named NAME ("txt", "csv", ...): 0, or -1 for an unknown name. */
int cli_format_parse(const char *name, enum cli_format *out);

/* Nonzero for the formats that are not text (bin, npy). */
int cli_format_is_binary(enum cli_format fmt);

/*
 * Writes every point of s to f in format fmt, each with its radius when
 * radii is nonzero. box (x0 y0 x1 y1) and periodic are only recorded (json).
 * Returns 0, or -1 on a write error (errno tells which); f is flushed but
 * not closed.
 */
int cli_format_write(FILE *f, enum cli_format fmt, const pds_sampler *s, const double box[4],
                     int periodic, int radii);

#endif /* POISSONDISK_OUT_FORMATS_H */
