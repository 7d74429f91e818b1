/*
 * shape_files.c - reading a whole file, telling GeoJSON from text, the ring
 * arrays and the messages (see shape_files.h). The formats themselves are in
 * geojson.c and json_check.c (JSON) and shape_text.c (lines).
 */
#include "shape_files_internal.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int shape_fail(char *msg, size_t size, const char *name, const char *where, const char *fmt, ...)
{
    va_list ap;
    int n;

    if (size == 0)
        return -1;
    n = where != NULL && where[0] != '\0' ? snprintf(msg, size, "%s: %s: ", name, where)
                                          : snprintf(msg, size, "%s: ", name);
    if (n >= 0 && (size_t)n < size) {
        va_start(ap, fmt);
        vsnprintf(msg + n, size - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

const char *shape_shown(const char *s, size_t len, char buf[64])
{
    size_t i, k = 0;

    buf[k++] = '"';
    for (i = 0; i < len && k < 44; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
            buf[k++] = (char)c;
        } else {
            snprintf(buf + k, 5, "\\x%02x", (unsigned)c);
            k += 4;
        }
    }
    if (i < len) {
        memcpy(buf + k, "...", 3);
        k += 3;
    }
    buf[k++] = '"';
    buf[k] = '\0';
    return buf;
}

/* Makes room for need elements of elem bytes in *p (*cap elements), doubling. */
static int reserve(void **p, size_t *cap, size_t need, size_t elem)
{
    size_t cap2 = *cap ? *cap : 256;
    void *q;

    if (need <= *cap)
        return 0;
    while (cap2 < need)
        cap2 *= 2;
    if (cap2 > (size_t)-1 / elem || (q = realloc(*p, cap2 * elem)) == NULL)
        return RB_NOMEM;
    *p = q;
    *cap = cap2;
    return 0;
}

int rb_vertex(struct ring_builder *b, double x, double y)
{
    void *p = b->xy;

    if (b->nvertices >= b->max_vertices)
        return RB_TOOMANY;
    if (reserve(&p, &b->xycap, b->nvertices + 1, 2 * sizeof *b->xy) != 0)
        return RB_NOMEM;
    b->xy = p;
    b->xy[2 * b->nvertices] = x;
    b->xy[2 * b->nvertices + 1] = y;
    b->nvertices++;
    return 0;
}

int rb_end_ring(struct ring_builder *b)
{
    void *p = b->ring_ends;

    if (b->nvertices == (b->nrings ? b->ring_ends[b->nrings - 1] : 0))
        return 0; /* no open ring */
    if (reserve(&p, &b->endcap, b->nrings + 1, sizeof *b->ring_ends) != 0)
        return RB_NOMEM;
    b->ring_ends = p;
    b->ring_ends[b->nrings++] = b->nvertices;
    return 0;
}

void rb_finish(struct ring_builder *b, struct shape_rings *out)
{
    void *p;

    /* Trim the doubling's slack; a failed shrink keeps the larger block. */
    if (b->nvertices > 0 && (p = realloc(b->xy, 2 * b->nvertices * sizeof *b->xy)) != NULL)
        b->xy = p;
    if (b->nrings > 0 && (p = realloc(b->ring_ends, b->nrings * sizeof *b->ring_ends)) != NULL)
        b->ring_ends = p;
    out->xy = b->xy;
    out->nvertices = b->nvertices;
    out->ring_ends = b->ring_ends;
    out->nrings = b->nrings;
    memset(b, 0, sizeof *b);
}

void rb_free(struct ring_builder *b)
{
    free(b->xy);
    free(b->ring_ends);
    memset(b, 0, sizeof *b);
}

int shape_unicode_start(const char *name, const char **text, size_t *len, char *msg,
                        size_t size)
{
    const unsigned char *t = (const unsigned char *)*text;

    if (*len >= 2 && ((t[0] == 0xff && t[1] == 0xfe) || (t[0] == 0xfe && t[1] == 0xff)))
        return shape_fail(msg, size, name, NULL, "the file is UTF-16 (it starts with its "
                          "byte-order mark): save it as UTF-8");
    if (*len >= 3 && t[0] == 0xef && t[1] == 0xbb && t[2] == 0xbf) {
        *text += 3;
        *len -= 3;
    }
    return 0;
}

/* Closes f and frees buf; returns -1. */
static int slurp_fail(FILE *f, char *buf)
{
    free(buf);
    fclose(f);
    return -1;
}

/*
 * Reads the whole file in doubling chunks (a pipe has no size to ask for),
 * at most max_bytes of it, so that the buffer never grows past max_bytes + 2.
 */
int shape_slurp(const char *path, size_t max_bytes, char **text, size_t *len, char *msg,
                size_t size)
{
    FILE *f = fopen(path, "rb");
    size_t cap = max_bytes < (1 << 16) ? max_bytes + 2 : 1 << 16, n = 0;
    char *buf, *q;

    *text = NULL;
    *len = 0;
    if (f == NULL)
        return shape_fail(msg, size, path, NULL, "cannot open: %s", strerror(errno));
    if ((buf = malloc(cap)) == NULL) {
        shape_fail(msg, size, path, NULL, "out of memory");
        return slurp_fail(f, buf);
    }
    for (;;) {
        n += fread(buf + n, 1, cap - 1 - n, f);
        if (n > max_bytes) {
            shape_fail(msg, size, path, NULL, "the file is larger than %zu bytes", max_bytes);
            return slurp_fail(f, buf);
        }
        if (n < cap - 1) {
            if (ferror(f)) {
                shape_fail(msg, size, path, NULL, "read error: %s", strerror(errno));
                return slurp_fail(f, buf);
            }
            if (feof(f))
                break;
            continue;
        }
        /* Full (so cap <= max_bytes + 1): grow, to max_bytes + 2 at most. */
        q = realloc(buf, cap > (max_bytes + 2) / 2 ? max_bytes + 2 : 2 * cap);
        if (q == NULL) {
            shape_fail(msg, size, path, NULL, "out of memory after %zu bytes", n);
            return slurp_fail(f, buf);
        }
        cap = cap > (max_bytes + 2) / 2 ? max_bytes + 2 : 2 * cap;
        buf = q;
    }
    fclose(f);
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return 0;
}

int shape_rings_parse_limit(const char *name, const char *text, size_t len, size_t max_vertices,
                            struct shape_rings *out, char *msg, size_t size)
{
    struct ring_builder b;
    size_t i;
    int rc;

    memset(out, 0, sizeof *out);
    memset(&b, 0, sizeof b);
    b.max_vertices = max_vertices;
    if (shape_unicode_start(name, &text, &len, msg, size) != 0)
        return -1;
    for (i = 0; i < len && strchr(" \t\r\n", text[i]) != NULL && text[i] != '\0';)
        i++;
    /* '[' cannot start a text line either: JSON, refused there as no GeoJSON object. */
    rc = i < len && (text[i] == '{' || text[i] == '[')
             ? geojson_rings(name, text, len, &b, msg, size)
             : text_rings(name, text, len, &b, msg, size);
    if (rc != 0) {
        rb_free(&b);
        return -1;
    }
    rb_finish(&b, out);
    return 0;
}

int shape_rings_parse(const char *name, const char *text, size_t len, struct shape_rings *out,
                      char *msg, size_t size)
{
    return shape_rings_parse_limit(name, text, len, SHAPE_MAX_VERTICES, out, msg, size);
}

int shape_rings_read(const char *path, struct shape_rings *out, char *msg, size_t size)
{
    char *text;
    size_t len;
    int rc;

    memset(out, 0, sizeof *out);
    if (shape_slurp(path, SHAPE_MAX_FILE_BYTES, &text, &len, msg, size) != 0)
        return -1;
    rc = shape_rings_parse(path, text, len, out, msg, size);
    free(text);
    return rc;
}

void shape_rings_free(struct shape_rings *r)
{
    free(r->xy);
    free(r->ring_ends);
    memset(r, 0, sizeof *r);
}

int fixed_points_parse(const char *name, const char *text, size_t len, struct fixed_points *out,
                       char *msg, size_t size)
{
    return fixed_points_parse_limit(name, text, len, SHAPE_MAX_VERTICES, out, msg, size);
}

int fixed_points_read(const char *path, struct fixed_points *out, char *msg, size_t size)
{
    char *text;
    size_t len;
    int rc;

    memset(out, 0, sizeof *out);
    if (shape_slurp(path, SHAPE_MAX_FILE_BYTES, &text, &len, msg, size) != 0)
        return -1;
    rc = fixed_points_parse(path, text, len, out, msg, size);
    free(text);
    return rc;
}

void fixed_points_free(struct fixed_points *p)
{
    free(p->xy);
    free(p->clearance);
    memset(p, 0, sizeof *p);
}
