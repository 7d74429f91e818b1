/*
 * out_formats.c - write the points as txt, csv, json, bin or npy (see
 * out_formats.h).
 */
#include "out_formats.h"

#include <stdint.h>
#include <string.h>

/* Points fetched per pds_points() call: bounded memory for any N. */
#define CHUNK_POINTS 4096

static const char *const format_names[] = { "txt", "csv", "json", "bin", "npy" };

int cli_format_parse(const char *name, enum cli_format *out)
{
    size_t k;

    for (k = 0; k < sizeof format_names / sizeof format_names[0]; k++)
        if (strcmp(name, format_names[k]) == 0) {
            *out = (enum cli_format)k;
            return 0;
        }
    return -1;
}

int cli_format_is_binary(enum cli_format fmt)
{
    return fmt == CLI_FORMAT_BIN || fmt == CLI_FORMAT_NPY;
}

/* v as 8 little-endian bytes, whatever the host's byte order. */
static void put_le64(unsigned char *p, double v)
{
    uint64_t bits;
    int i;

    memcpy(&bits, &v, sizeof bits);
    for (i = 0; i < 8; i++)
        p[i] = (unsigned char)(bits >> (8 * i));
}

/*
 * The NumPy 1.0 preamble: magic, version, header length (little-endian
 * uint16), then a Python dict literal padded with blanks and ended by a
 * newline so that the data starts on a multiple of 64 bytes.
 */
static int write_npy_header(FILE *f, size_t n, int columns)
{
    char dict[128];
    unsigned char pre[10] = { 0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, 0, 0 };
    int len = snprintf(dict, sizeof dict, "{'descr': '<f8', 'fortran_order': False, "
                                          "'shape': (%zu, %d), }", n, columns);
    size_t total = (10 + (size_t)len + 1 + 63) / 64 * 64; /* +1: the newline */
    size_t hlen = total - 10;

    pre[8] = (unsigned char)(hlen & 0xff);
    pre[9] = (unsigned char)(hlen >> 8);
    if (fwrite(pre, 1, sizeof pre, f) != sizeof pre || fputs(dict, f) < 0)
        return -1;
    for (len++; (size_t)len < hlen; len++)
        if (fputc(' ', f) == EOF)
            return -1;
    return fputc('\n', f) == EOF ? -1 : 0;
}

/* What comes before the first point. */
static int write_head(FILE *f, enum cli_format fmt, const pds_sampler *s, const double *box,
                      int periodic, int radii)
{
    switch (fmt) {
    case CLI_FORMAT_CSV:
        return fputs(radii ? "x,y,r\n" : "x,y\n", f) < 0 ? -1 : 0;
    case CLI_FORMAT_JSON:
        return fprintf(f, "{\"radius\": %.17g, \"domain\": [%.17g, %.17g, %.17g, %.17g], "
                          "\"periodic\": %s, \"count\": %zu, \"points\": [",
                       pds_radius(s), box[0], box[1], box[2], box[3],
                       periodic ? "true" : "false", pds_count(s)) < 0 ? -1 : 0;
    case CLI_FORMAT_NPY:
        return write_npy_header(f, pds_count(s), radii ? 3 : 2);
    default:
        return 0;
    }
}

/*
 * One point as text; index is its rank in the output (json puts commas
 * between); r its radius, written when radii is nonzero.
 */
static int write_text_point(FILE *f, enum cli_format fmt, double x, double y, double r,
                            int radii, size_t index)
{
    switch (fmt) {
    case CLI_FORMAT_TXT:
        return (radii ? fprintf(f, "%.17g %.17g %.17g\n", x, y, r)
                      : fprintf(f, "%.17g %.17g\n", x, y)) < 0 ? -1 : 0;
    case CLI_FORMAT_CSV:
        return (radii ? fprintf(f, "%.17g,%.17g,%.17g\n", x, y, r)
                      : fprintf(f, "%.17g,%.17g\n", x, y)) < 0 ? -1 : 0;
    case CLI_FORMAT_JSON:
        return (radii ? fprintf(f, "%s[%.17g, %.17g, %.17g]", index > 0 ? ", " : "", x, y, r)
                      : fprintf(f, "%s[%.17g, %.17g]", index > 0 ? ", " : "", x, y)) < 0 ? -1
                                                                                      : 0;
    default:
        return -1;
    }
}

/* A chunk of points in bin or npy: one write for the chunk (one fwrite a
 * point took a tenth of a 10^6-point run's output). */
static int write_raw_chunk(FILE *f, const double *xy, const double *r, size_t got, int radii)
{
    static unsigned char raw[24 * CHUNK_POINTS];
    size_t per = radii ? 24 : 16, k;

    for (k = 0; k < got; k++) {
        put_le64(raw + per * k, xy[2 * k]);
        put_le64(raw + per * k + 8, xy[2 * k + 1]);
        if (radii)
            put_le64(raw + per * k + 16, r[k]);
    }
    return fwrite(raw, per, got, f) == got ? 0 : -1;
}

int cli_format_write(FILE *f, enum cli_format fmt, const pds_sampler *s, const double box[4],
                     int periodic, int radii)
{
    static double xy[2 * CHUNK_POINTS], r[CHUNK_POINTS];
    size_t first = 0, got, k;

    if (write_head(f, fmt, s, box, periodic, radii) != 0)
        return -1;
    while ((got = pds_points(s, first, CHUNK_POINTS, xy)) > 0) {
        if (radii && pds_radii(s, first, got, r) != got)
            return -1;
        if (fmt == CLI_FORMAT_BIN || fmt == CLI_FORMAT_NPY) {
            if (write_raw_chunk(f, xy, r, got, radii) != 0)
                return -1;
        } else {
            for (k = 0; k < got; k++)
                if (write_text_point(f, fmt, xy[2 * k], xy[2 * k + 1], radii ? r[k] : 0.0, radii,
                                     first + k) != 0)
                    return -1;
        }
        first += got;
    }
    if (fmt == CLI_FORMAT_JSON && fputs("]}\n", f) < 0)
        return -1;
    return fflush(f) == 0 && !ferror(f) ? 0 : -1;
}
