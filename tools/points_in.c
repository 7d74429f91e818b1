/*
 * points_in.c - read "x y" point patterns separated by blank lines (see
 * points_in.h).
 */
#define _POSIX_C_SOURCE 200809L

#include "points_in.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *skip_blanks(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n')
        s++;
    return s;
}

/* "x y" or "x,y" with optional blanks around: 0 and the two values, else -1. */
static int parse_point(const char *s, double *x, double *y)
{
    char *end;

    *x = strtod(s, &end);
    if (end == s)
        return -1;
    s = skip_blanks(end);
    if (*s == ',')
        s = skip_blanks(s + 1);
    *y = strtod(s, &end);
    if (end == s || *skip_blanks(end) != '\0' || !isfinite(*x) || !isfinite(*y))
        return -1;
    return 0;
}

/*
 * Makes room for need elements of size elem in the array p of *cap
 * elements: returns the (maybe moved) array, or NULL when out of memory (p
 * is then still valid).
 */
static void *grow(void *p, size_t *cap, size_t need, size_t elem)
{
    void *q;
    size_t cap2;

    if (need <= *cap)
        return p;
    cap2 = *cap ? 2 * *cap : 1024;
    while (cap2 < need)
        cap2 *= 2;
    if ((q = realloc(p, cap2 * elem)) == NULL)
        return NULL;
    *cap = cap2;
    return q;
}

long patterns_read(FILE *f, struct patterns_in *out)
{
    char *line = NULL;
    size_t linecap = 0, xycap = 0, firstcap = 0;
    long lineno = 0, rc = 0;
    int in_pattern = 0, seen_content = 0;

    memset(out, 0, sizeof *out);
    errno = 0;
    while (getline(&line, &linecap, f) >= 0) {
        const char *s = skip_blanks(line);
        double x, y, *xy;
        lineno++;
        if (*s == '\0') { /* a blank line ends the pattern */
            in_pattern = 0;
            continue;
        }
        if (*s == '#')
            continue;
        if (parse_point(s, &x, &y) != 0) {
            /* The header of the csv format, before any point. */
            if (!seen_content && strncmp(s, "x,y", 3) == 0 && *skip_blanks(s + 3) == '\0') {
                seen_content = 1;
                continue;
            }
            rc = lineno;
            break;
        }
        seen_content = 1;
        if (!in_pattern) {
            size_t *first = grow(out->first, &firstcap, out->npatterns + 2, sizeof *first);
            if (first == NULL) {
                rc = -1;
                break;
            }
            out->first = first;
            out->first[out->npatterns++] = out->npoints;
            in_pattern = 1;
        }
        if ((xy = grow(out->xy, &xycap, 2 * out->npoints + 2, sizeof *xy)) == NULL) {
            rc = -1;
            break;
        }
        out->xy = xy;
        out->xy[2 * out->npoints] = x;
        out->xy[2 * out->npoints + 1] = y;
        out->npoints++;
    }
    if (rc == 0 && ferror(f))
        rc = -1;
    free(line);
    if (rc != 0) {
        patterns_free(out);
        return rc;
    }
    if (out->first != NULL)
        out->first[out->npatterns] = out->npoints;
    return 0;
}

void patterns_free(struct patterns_in *p)
{
    free(p->xy);
    free(p->first);
    memset(p, 0, sizeof *p);
}
