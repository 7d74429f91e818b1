/*
 * pgm.c - read a P2 or P5 grey-scale image (see pgm.h).
 */
#include "pgm.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#define MAX_NUMBER 1000000000UL /* larger header values are refused before they overflow */

struct reader {
    FILE *f;
    char *msg;
    size_t size;
    int last; /* the character that ended the last number (EOF, a blank or '#') */
};

static int fail(struct reader *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static int fail(struct reader *r, const char *fmt, ...)
{
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(r->msg, r->size, fmt, ap);
    va_end(ap);
    return -1;
}

/* The end of the file: a read error, or what was being read is missing. */
static int fail_eof(struct reader *r, const char *what)
{
    if (ferror(r->f))
        return fail(r, "read error: %s", strerror(errno));
    return fail(r, "the file ends before %s (truncated?)", what);
}

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* A character as the messages show it. */
static const char *shown(int c, char buf[8])
{
    if (c >= 0x21 && c <= 0x7e)
        snprintf(buf, 8, "'%c'", c);
    else
        snprintf(buf, 8, "0x%02x", (unsigned)c & 0xffu);
    return buf;
}

/*
 * The next decimal number, after white space and comments. Returns 0 and
 * *out, or -1 with a message naming what (e.g. "the width") when the file
 * ends, holds something else, or the number exceeds max.
 */
static int number(struct reader *r, const char *what, unsigned long max, unsigned long *out)
{
    unsigned long v = 0;
    char buf[8];
    int c, big = 0;

    for (;;) {
        c = getc(r->f);
        if (c == '#') {
            while ((c = getc(r->f)) != EOF && c != '\n' && c != '\r')
                ;
        }
        if (c == EOF)
            return fail_eof(r, what);
        if (!is_space(c))
            break;
    }
    if (c < '0' || c > '9')
        return fail(r, "expected %s, a decimal number, found %s", what, shown(c, buf));
    do {
        unsigned long d = (unsigned long)(c - '0');
        if (big || d > max || v > (max - d) / 10) /* v * 10 + d > max, no overflow */
            big = 1;
        else
            v = 10 * v + d;
    } while ((c = getc(r->f)) >= '0' && c <= '9');
    if (big)
        return fail(r, "%s is too large (at most %lu)", what, max);
    if (c != EOF && !is_space(c) && c != '#')
        return fail(r, "expected white space after %s, found %s", what, shown(c, buf));
    if (c == '#') /* a comment right after the number: let the next call skip it */
        ungetc(c, r->f);
    r->last = c;
    *out = v;
    return 0;
}

/* The P5 raster: one or two bytes per pixel, in rows. */
static int read_raw(struct reader *r, struct pgm *p)
{
    size_t bytes = p->maxval < 256 ? 1 : 2, row, k;
    unsigned char *line = malloc(p->width * bytes);

    if (line == NULL)
        return fail(r, "out of memory for a row of %zu pixels", p->width);
    for (row = 0; row < p->height; row++) {
        unsigned short *out = p->pix + row * p->width;
        size_t got = fread(line, bytes, p->width, r->f);
        if (got < p->width) {
            free(line);
            if (ferror(r->f))
                return fail(r, "read error: %s", strerror(errno));
            return fail(r, "the file ends after %zu of %zu pixels (truncated)",
                        row * p->width + got, p->width * p->height);
        }
        for (k = 0; k < p->width; k++) {
            unsigned v = bytes == 1 ? line[k] : (unsigned)line[2 * k] << 8 | line[2 * k + 1];
            if (v > p->maxval) {
                free(line);
                return fail(r, "the pixel at row %zu, column %zu is %u, above maxval %u",
                            row + 1, k + 1, v, p->maxval);
            }
            out[k] = (unsigned short)v;
        }
    }
    free(line);
    return 0;
}

/* The P2 raster: decimal numbers. */
static int read_plain(struct reader *r, struct pgm *p)
{
    size_t n = p->width * p->height, k;
    char what[128];
    unsigned long v;

    for (k = 0; k < n; k++) {
        snprintf(what, sizeof what, "the pixel at row %zu, column %zu (%zu of %zu)",
                 k / p->width + 1, k % p->width + 1, k + 1, n);
        if (number(r, what, MAX_NUMBER, &v) != 0)
            return -1;
        if (v > p->maxval)
            return fail(r, "the pixel at row %zu, column %zu is %lu, above maxval %u",
                        k / p->width + 1, k % p->width + 1, v, p->maxval);
        p->pix[k] = (unsigned short)v;
    }
    return 0;
}

int pgm_read(FILE *f, struct pgm *out, char *msg, size_t size)
{
    struct reader r;
    unsigned long w, h, maxval;
    char buf[8];
    int c0, c1, c;

    memset(out, 0, sizeof *out);
    r.f = f;
    r.msg = msg;
    r.size = size;
    c0 = getc(f);
    c1 = c0 == EOF ? EOF : getc(f);
    if (c0 == EOF && ferror(f))
        return fail(&r, "read error: %s", strerror(errno));
    if (c0 == EOF)
        return fail(&r, "the file is empty");
    if (c0 == 'P' && c1 != EOF && strchr("1346", c1) != NULL)
        return fail(&r, "a %s image (P%c), not a grey-scale PGM (P2 or P5)",
                    c1 == '1' || c1 == '4' ? "PBM" : "PPM", c1);
    if (c0 == 'P' && c1 == '7')
        return fail(&r, "a PAM image (P7), not a grey-scale PGM (P2 or P5)");
    if (c0 != 'P' || (c1 != '2' && c1 != '5'))
        return fail(&r, "not a PGM image: it does not start with P2 or P5");
    if ((c = getc(f)) != EOF && !is_space(c) && c != '#')
        return fail(&r, "not a PGM image: P%c followed by %s", c1, shown(c, buf));
    if (c == '#')
        ungetc(c, f);
    if (number(&r, "the width", MAX_NUMBER, &w) != 0
        || number(&r, "the height", MAX_NUMBER, &h) != 0
        || number(&r, "maxval", MAX_NUMBER, &maxval) != 0)
        return -1;
    if (w == 0 || h == 0)
        return fail(&r, "the image is empty (%lu x %lu pixels)", w, h);
    if (maxval == 0 || maxval > 65535)
        return fail(&r, "maxval %lu is out of range (1 to 65535)", maxval);
    if ((size_t)w > PGM_MAX_PIXELS / (size_t)h)
        return fail(&r, "the image is too large: %lu x %lu pixels, at most %zu in all", w, h,
                    PGM_MAX_PIXELS);
    out->width = w;
    out->height = h;
    out->maxval = (unsigned)maxval;
    out->pix = malloc(out->width * out->height * sizeof *out->pix);
    if (out->pix == NULL) {
        memset(out, 0, sizeof *out);
        return fail(&r, "out of memory for %lu x %lu pixels", w, h);
    }
    /* In P5 the one white-space character after maxval was read by number(); a
       comment there ends with the line break that delimits the raster. */
    if (c1 == '5' && r.last == '#')
        while ((c = getc(f)) != EOF && c != '\n' && c != '\r')
            ;
    if ((c1 == '5' ? read_raw(&r, out) : read_plain(&r, out)) != 0) {
        pgm_free(out);
        return -1;
    }
    return 0;
}

void pgm_free(struct pgm *p)
{
    free(p->pix);
    memset(p, 0, sizeof *p);
}
