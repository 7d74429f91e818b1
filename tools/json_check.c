/*
 * json_check.c - is a text one strict JSON value (RFC 8259)? The first pass
 * of the GeoJSON reader (geojson.c): after it, the walk over the structure
 * needs no syntax checks. A message names the line and the column (in bytes,
 * from 1) of the first error. Strings: the escapes are checked (\uXXXX
 * for 4 hexadecimal digits only, not decoded); raw bytes from 0x80 up pass
 * unchecked, control characters below 0x20 are refused. Numbers follow the
 * JSON grammar (no leading zeros, '+', '.5', NaN or Infinity). Arrays and
 * objects nest at most SHAPE_JSON_MAX_DEPTH deep: the check recurses once
 * per level, so its stack stays small.
 */
#include "shape_files_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

struct json {
    const char *name, *text;
    size_t len;
    char *msg;
    size_t size;
};

static size_t ws(const struct json *j, size_t p)
{
    while (p < j->len && json_is_ws(j->text[p]))
        p++;
    return p;
}

/* The character at p as a message shows it. */
static const char *found(const struct json *j, size_t p, char buf[16])
{
    unsigned char c = p < j->len ? (unsigned char)j->text[p] : 0;

    if (p >= j->len)
        return "the end of the file";
    if (c > 0x20 && c < 0x7f)
        snprintf(buf, 16, "'%c'", c);
    else
        snprintf(buf, 16, "byte 0x%02x", (unsigned)c);
    return buf;
}

static int syntax(const struct json *j, size_t p, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* A syntax error at byte p: "NAME: line L column C: WHAT". */
static int syntax(const struct json *j, size_t p, const char *fmt, ...)
{
    size_t line = 1, col = 1, i;
    char where[64], what[192];
    va_list ap;

    for (i = 0; i < p && i < j->len; i++, col++)
        if (j->text[i] == '\n') {
            line++;
            col = 0;
        }
    snprintf(where, sizeof where, "line %zu column %zu", line, col);
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return shape_fail(j->msg, j->size, j->name, where, "%s", what);
}

static int check_string(const struct json *j, size_t *pp)
{
    size_t p = *pp + 1, k;
    char buf[16];

    for (;;) {
        unsigned char c;
        if (p >= j->len)
            return syntax(j, *pp, "the file ends inside this string (truncated?)");
        c = (unsigned char)j->text[p];
        if (c == '"')
            break;
        if (c < 0x20)
            return syntax(j, p, "a raw control character (0x%02x) in a string", (unsigned)c);
        if (c != '\\') {
            p++;
            continue;
        }
        if (p + 1 >= j->len)
            return syntax(j, *pp, "the file ends inside this string (truncated?)");
        c = (unsigned char)j->text[p + 1];
        if (c != 'u') {
            if (c == 0 || strchr("\"\\/bfnrt", c) == NULL)
                return syntax(j, p, "invalid escape: '\\' followed by %s", found(j, p + 1, buf));
            p += 2;
            continue;
        }
        for (k = 2; k < 6; k++) {
            c = p + k < j->len ? (unsigned char)j->text[p + k] : 0;
            if (p + k >= j->len)
                return syntax(j, *pp, "the file ends inside this string (truncated?)");
            if (!json_is_digit((char)c) && !(c >= 'a' && c <= 'f') && !(c >= 'A' && c <= 'F'))
                return syntax(j, p, "invalid escape: \\u needs 4 hexadecimal digits");
        }
        p += 6;
    }
    *pp = p + 1;
    return 0;
}

/* -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)? */
static int check_number(const struct json *j, size_t *pp)
{
    const char *t = j->text;
    size_t p = *pp, n = j->len;

    if (t[p] == '-')
        p++;
    if (p < n && t[p] == '0') {
        if (++p < n && json_is_digit(t[p]))
            return syntax(j, *pp, "malformed number: a leading zero");
    } else if (p < n && json_is_digit(t[p])) {
        while (p < n && json_is_digit(t[p]))
            p++;
    } else {
        goto malformed;
    }
    if (p < n && t[p] == '.') {
        if (++p >= n || !json_is_digit(t[p]))
            goto malformed;
        while (p < n && json_is_digit(t[p]))
            p++;
    }
    if (p < n && (t[p] == 'e' || t[p] == 'E')) {
        if (++p < n && (t[p] == '+' || t[p] == '-'))
            p++;
        if (p >= n || !json_is_digit(t[p]))
            goto malformed;
        while (p < n && json_is_digit(t[p]))
            p++;
    }
    *pp = p;
    return 0;
malformed:
    if (p >= n)
        return syntax(j, *pp, "the file ends inside this number (truncated?)");
    return syntax(j, *pp, "malformed number");
}

static int check_value(const struct json *j, size_t *pp, int depth)
{
    static const char *const literals[] = {"true", "false", "null"};
    size_t p = ws(j, *pp), i;
    char buf[16], c, close;

    if (p >= j->len)
        return syntax(j, p, "the file ends where a value should be (truncated?)");
    c = j->text[p];
    if (c == '"') {
        if (check_string(j, &p) != 0)
            return -1;
    } else if (c == '-' || json_is_digit(c)) {
        if (check_number(j, &p) != 0)
            return -1;
    } else if (c == 't' || c == 'f' || c == 'n') {
        const char *lit = literals[c == 't' ? 0 : c == 'f' ? 1 : 2];
        size_t k = strlen(lit);
        for (i = 0; i < k; i++)
            if (p + i >= j->len)
                return syntax(j, p, "the file ends inside \"%s\" (truncated?)", lit);
            else if (j->text[p + i] != lit[i])
                return syntax(j, p, "expected a value, found %s", found(j, p, buf));
        p += k;
    } else if (c == '[' || c == '{') {
        const char *what = c == '[' ? "an array" : "an object";
        close = c == '[' ? ']' : '}';
        if (depth >= SHAPE_JSON_MAX_DEPTH)
            return syntax(j, p, "arrays and objects nest deeper than %d", SHAPE_JSON_MAX_DEPTH);
        p = ws(j, p + 1);
        if (p < j->len && j->text[p] == close) {
            *pp = p + 1;
            return 0;
        }
        for (;;) {
            if (c == '{') {
                if (p >= j->len)
                    return syntax(j, p, "the file ends inside %s (truncated?)", what);
                if (j->text[p] != '"')
                    return syntax(j, p, "expected a member name (a string), found %s",
                                  found(j, p, buf));
                if (check_string(j, &p) != 0)
                    return -1;
                p = ws(j, p);
                if (p >= j->len)
                    return syntax(j, p, "the file ends inside %s (truncated?)", what);
                if (j->text[p++] != ':')
                    return syntax(j, p - 1, "expected ':' after the member name, found %s",
                                  found(j, p - 1, buf));
            }
            if (check_value(j, &p, depth + 1) != 0)
                return -1;
            p = ws(j, p);
            if (p >= j->len)
                return syntax(j, p, "the file ends inside %s (truncated?)", what);
            if (j->text[p] == close)
                break;
            if (j->text[p] != ',')
                return syntax(j, p, "expected ',' or '%c' in %s, found %s", close, what,
                              found(j, p, buf));
            p = ws(j, p + 1);
        }
        p++;
    } else {
        return syntax(j, p, "expected a value, found %s", found(j, p, buf));
    }
    *pp = p;
    return 0;
}

int json_check(const char *name, const char *text, size_t len, char *msg, size_t size)
{
    struct json j;
    size_t p = 0;
    char buf[16];

    j.name = name;
    j.text = text;
    j.len = len;
    j.msg = msg;
    j.size = size;
    if (check_value(&j, &p, 0) != 0)
        return -1;
    if ((p = ws(&j, p)) < len)
        return syntax(&j, p, "%s after the end of the JSON value", found(&j, p, buf));
    return 0;
}
