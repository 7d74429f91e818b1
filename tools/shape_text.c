/*
 * shape_text.c - the line-based files (see shape_files.h): polygon rings as
 * "x y" lines separated by blank lines, and fixed points "x y [clearance]".
 */
#include "shape_files_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* One line of text: where its columns are (the first three kept) and how many there are. */
struct line {
    size_t start[3], end[3];
    size_t ncols;
    int comment; /* the line holds a '#' */
};

/* Splits text[pos, '\n' or len) into *l; returns the position after the line. */
static size_t split_line(const char *text, size_t len, size_t pos, struct line *l)
{
    l->ncols = 0;
    l->comment = 0;
    while (pos < len && text[pos] != '\n') {
        size_t s;
        if (is_blank(text[pos])) {
            pos++;
            continue;
        }
        if (text[pos] == '#') {
            l->comment = 1;
            while (pos < len && text[pos] != '\n')
                pos++;
            break;
        }
        for (s = pos; pos < len && text[pos] != '\n' && text[pos] != '#' && !is_blank(text[pos]);)
            pos++;
        if (l->ncols < 3) {
            l->start[l->ncols] = s;
            l->end[l->ncols] = pos;
        }
        l->ncols++;
    }
    return pos < len ? pos + 1 : pos;
}

/* "line N" in buf, for a message (written only then: formatting costs more than reading). */
static const char *at_line(char buf[32], size_t lineno)
{
    snprintf(buf, 32, "line %zu", lineno);
    return buf;
}

/* Column k of line lineno as a finite number: 0 and *v, or -1 with the message. */
static int column_number(const char *name, const char *text, const struct line *l, size_t k,
                         size_t lineno, double *v, char *msg, size_t size)
{
    char where[32], buf[64];
    const char *s = text + l->start[k];
    char *end;
    size_t n = l->end[k] - l->start[k];

    *v = strtod(s, &end);
    if (end != s + n)
        return shape_fail(msg, size, name, at_line(where, lineno), "%s is not a number",
                          shape_shown(s, n, buf));
    if (!isfinite(*v))
        return shape_fail(msg, size, name, at_line(where, lineno), "%s is not a finite number",
                          shape_shown(s, n, buf));
    return 0;
}

int text_rings(const char *name, const char *text, size_t len, struct ring_builder *b,
               char *msg, size_t size)
{
    size_t pos = 0, lineno = 0;
    struct line l;
    char where[32];

    while (pos < len) {
        double x, y;
        int rc;
        pos = split_line(text, len, pos, &l);
        lineno++;
        if (l.ncols == 0) {
            if (!l.comment && rb_end_ring(b) != 0) /* a blank line ends the ring */
                return shape_fail(msg, size, name, NULL, "out of memory");
            continue;
        }
        if (l.ncols != 2)
            return shape_fail(msg, size, name, at_line(where, lineno),
                              "expected 2 numbers \"x y\", found %zu %s", l.ncols,
                              l.ncols == 1 ? "column" : "columns");
        if (column_number(name, text, &l, 0, lineno, &x, msg, size) != 0
            || column_number(name, text, &l, 1, lineno, &y, msg, size) != 0)
            return -1;
        if ((rc = rb_vertex(b, x, y)) != 0)
            return shape_fail(msg, size, name, at_line(where, lineno),
                              rc == RB_TOOMANY ? "more than %zu vertices"
                                               : "out of memory after %zu vertices",
                              rc == RB_TOOMANY ? b->max_vertices : b->nvertices);
    }
    if (rb_end_ring(b) != 0)
        return shape_fail(msg, size, name, NULL, "out of memory");
    if (b->nvertices == 0)
        return shape_fail(msg, size, name, NULL, "no vertices (an \"x y\" line per vertex)");
    return 0;
}

int fixed_points_parse_limit(const char *name, const char *text, size_t len, size_t max_points,
                             struct fixed_points *out, char *msg, size_t size)
{
    size_t pos = 0, lineno = 0, cap = 0, n = 0;
    double *xy = NULL, *clearance = NULL;
    struct line l;
    char where[32], buf[64];

    memset(out, 0, sizeof *out);
    if (shape_unicode_start(name, &text, &len, msg, size) != 0)
        return -1;
    while (pos < len) {
        double x, y, c = 0;
        pos = split_line(text, len, pos, &l);
        lineno++;
        if (l.ncols == 0)
            continue;
        if (l.ncols != 2 && l.ncols != 3) {
            shape_fail(msg, size, name, at_line(where, lineno),
                       "expected \"x y\" or \"x y clearance\", found %zu %s", l.ncols,
                       l.ncols == 1 ? "column" : "columns");
            goto fail;
        }
        if (column_number(name, text, &l, 0, lineno, &x, msg, size) != 0
            || column_number(name, text, &l, 1, lineno, &y, msg, size) != 0
            || (l.ncols == 3 && column_number(name, text, &l, 2, lineno, &c, msg, size) != 0))
            goto fail;
        if (l.ncols == 3 && !(c > 0)) {
            shape_fail(msg, size, name, at_line(where, lineno),
                       "the clearance %s is not > 0 (leave it out for the default)",
                       shape_shown(text + l.start[2], l.end[2] - l.start[2], buf));
            goto fail;
        }
        if (n >= max_points) {
            shape_fail(msg, size, name, at_line(where, lineno), "more than %zu points",
                       max_points);
            goto fail;
        }
        if (n == cap) {
            size_t cap2 = cap ? 2 * cap : 256;
            double *p = realloc(xy, 2 * cap2 * sizeof *xy), *q;
            if (p != NULL)
                xy = p;
            q = p == NULL ? NULL : realloc(clearance, cap2 * sizeof *clearance);
            if (q == NULL) {
                shape_fail(msg, size, name, at_line(where, lineno), "out of memory");
                goto fail;
            }
            clearance = q;
            cap = cap2;
        }
        xy[2 * n] = x;
        xy[2 * n + 1] = y;
        clearance[n++] = c; /* 0: not given */
    }
    out->xy = xy;
    out->clearance = clearance;
    out->n = n;
    return 0;
fail:
    free(xy);
    free(clearance);
    return -1;
}

