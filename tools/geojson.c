/*
 * geojson.c - the rings of a GeoJSON file (see shape_files.h).
 *
 * Two passes: json_check.c first checks that the whole text is one strict
 * JSON value (syntax errors name a line and column); this file then walks
 * the text, now known to be valid, and takes the rings. JSON members come
 * in any order ("coordinates" may precede "type"), so the walk first notes
 * where an object's members of interest start, then reads them once the
 * type is known. Each byte is so scanned once per level of
 * FeatureCollection, Feature, geometry and coordinates: a few times, linear
 * in all. The walk recurses only into GeometryCollections, at most
 * SHAPE_JSON_MAX_DEPTH deep (json_check refuses deeper nesting).
 */
#include "shape_files_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct json {
    const char *name, *text;
    size_t len;
    char *msg;
    size_t size;
    struct ring_builder *b;
};

static size_t ws(const struct json *j, size_t p)
{
    while (p < j->len && json_is_ws(j->text[p]))
        p++;
    return p;
}


#define NONE ((size_t)-1)
enum { M_TYPE, M_COORDINATES, M_GEOMETRY, M_FEATURES, M_GEOMETRIES, M_COUNT };
static const char *const member_names[M_COUNT] = {"type", "coordinates", "geometry", "features",
                                                  "geometries"};

static int fail(const struct json *j, const char *where, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static int fail(const struct json *j, const char *where, const char *fmt, ...)
{
    char what[256];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return shape_fail(j->msg, j->size, j->name, where, "%s", what);
}

/* The end of the string whose opening quote is at p: the closing quote. */
static size_t string_end(const struct json *j, size_t p)
{
    for (p++; j->text[p] != '"'; p += j->text[p] == '\\' ? 2 : 1)
        ;
    return p;
}

/* The bytes that matter when skipping an array or an object of valid JSON. */
static const unsigned char bracket_or_quote[256] = {['"'] = 1, ['['] = 1, [']'] = 1, ['{'] = 1,
                                                    ['}'] = 1};

/* The position after the value at p. Inside an array or an object only strings and
   brackets matter (the text is valid JSON): a tight loop, as every coordinate is
   skipped this way a few times. */
static size_t skip(const struct json *j, size_t p)
{
    const char *t = j->text;
    int depth = 0;

    if (t[p] == '"')
        return string_end(j, p) + 1;
    if (t[p] != '[' && t[p] != '{') { /* a number or a literal */
        while (p < j->len && !json_is_ws(t[p]) && t[p] != ',' && t[p] != ']' && t[p] != '}')
            p++;
        return p;
    }
    for (;;) {
        while (!bracket_or_quote[(unsigned char)t[p]])
            p++;
        if (t[p] == '"')
            p = string_end(j, p);
        else if (t[p] == '[' || t[p] == '{')
            depth++;
        else if (--depth == 0)
            return p + 1;
        p++;
    }
}

/* The next element after the one ending at p (after blanks and a comma). */
static size_t next(const struct json *j, size_t p)
{
    p = ws(j, p);
    return j->text[p] == ',' ? ws(j, p + 1) : p;
}

static const char *kind(char c)
{
    return c == '{' ? "an object" : c == '[' ? "an array" : c == '"' ? "a string"
         : c == 'n' ? "null" : c == 't' || c == 'f' ? "a boolean" : "a number";
}

/* Where each member of interest of the object at p starts (NONE: absent), and *end,
   the position after the object. */
static int scan_members(const struct json *j, size_t p, const char *where, size_t at[M_COUNT],
                        size_t *end)
{
    size_t k;

    for (k = 0; k < M_COUNT; k++)
        at[k] = NONE;
    for (p = ws(j, p + 1); j->text[p] != '}'; p = next(j, skip(j, p))) {
        size_t k0 = p + 1, k1 = string_end(j, p);
        p = ws(j, ws(j, k1 + 1) + 1); /* past ':' to the value */
        for (k = 0; k < M_COUNT; k++)
            if (k1 - k0 == strlen(member_names[k])
                && memcmp(j->text + k0, member_names[k], k1 - k0) == 0) {
                if (at[k] != NONE)
                    return fail(j, where, "the member \"%s\" appears twice in one object",
                                member_names[k]);
                at[k] = p;
            }
    }
    *end = p + 1;
    return 0;
}

/* The type's value (a string): 0 and its span, or -1 with the message. */
static int type_of(const struct json *j, const size_t at[M_COUNT], const char *where,
                   const char *what, const char **s, size_t *n)
{
    size_t p = at[M_TYPE];

    if (p == NONE)
        return fail(j, where, "%s has no \"type\" member", what);
    if (j->text[p] != '"')
        return fail(j, where, "\"type\" is %s, not a string", kind(j->text[p]));
    *s = j->text + p + 1;
    *n = string_end(j, p) - p - 1;
    return 0;
}

static int is(const char *s, size_t n, const char *name)
{
    return n == strlen(name) && memcmp(s, name, n) == 0;
}

/* where, then polygon K (if K > 0) ring J (if J > 0) vertex V (if V > 0). */
static const char *locate(char *buf, size_t size, const char *where, size_t polygon, size_t ring,
                          size_t vertex)
{
    int n = snprintf(buf, size, "%s", where);
    if (polygon > 0 && n >= 0 && (size_t)n < size)
        n += snprintf(buf + n, size - (size_t)n, "%spolygon %zu", n ? " " : "", polygon);
    if (ring > 0 && n >= 0 && (size_t)n < size)
        n += snprintf(buf + n, size - (size_t)n, "%sring %zu", n ? " " : "", ring);
    if (vertex > 0 && n >= 0 && (size_t)n < size)
        snprintf(buf + n, size - (size_t)n, "%svertex %zu", n ? " " : "", vertex);
    return buf;
}

/* The rings of one polygon, an array at p; polygon: its number in a MultiPolygon, or 0.
   *end: the position after the array. */
static int walk_rings(const struct json *j, size_t p, const char *where, size_t polygon,
                      size_t *end)
{
    const char *t = j->text;
    char loc[320], buf[64];
    size_t ring = 0;

    if (t[p] != '[')
        return fail(j, locate(loc, sizeof loc, where, polygon, 0, 0),
                    "expected an array of rings, found %s", kind(t[p]));
    for (p = ws(j, p + 1); t[p] != ']'; p = next(j, p + 1)) {
        size_t vertex = 0;
        ring++;
        if (t[p] != '[')
            return fail(j, locate(loc, sizeof loc, where, polygon, ring, 0),
                        "expected an array of positions, found %s", kind(t[p]));
        for (p = ws(j, p + 1); t[p] != ']'; p = next(j, p + 1)) {
            size_t q, e = p, k = 0;
            double xy[2];
            int rc;
            vertex++;
            if (t[p] != '[')
                return fail(j, locate(loc, sizeof loc, where, polygon, ring, vertex),
                            "expected a position (an array of 2 or more numbers), found %s",
                            kind(t[p]));
            for (q = ws(j, p + 1); t[q] != ']'; q = next(j, e), k++) {
                if (t[q] != '-' && !json_is_digit(t[q]))
                    return fail(j, locate(loc, sizeof loc, where, polygon, ring, vertex),
                                "a position holds numbers only, found %s", kind(t[q]));
                e = skip(j, q);
                if (k < 2 && !isfinite(xy[k] = strtod(t + q, NULL)))
                    return fail(j, locate(loc, sizeof loc, where, polygon, ring, vertex),
                                "%s is not a finite number", shape_shown(t + q, e - q, buf));
            }
            if (k < 2)
                return fail(j, locate(loc, sizeof loc, where, polygon, ring, vertex),
                            "a position needs 2 numbers (x and y), found %zu", k);
            if ((rc = rb_vertex(j->b, xy[0], xy[1])) != 0)
                return fail(j, locate(loc, sizeof loc, where, polygon, ring, vertex),
                            rc == RB_TOOMANY ? "more than %zu vertices in the file"
                                             : "out of memory (%zu vertices)",
                            j->b->max_vertices);
            p = q;
        }
        if (vertex < 3)
            return fail(j, locate(loc, sizeof loc, where, polygon, ring, 0),
                        "%zu %s, a ring needs at least 3", vertex,
                        vertex == 1 ? "position" : "positions");
        if (rb_end_ring(j->b) != 0)
            return fail(j, where, "out of memory");
    }
    *end = p + 1;
    return 0;
}

/* A geometry object at p: a Polygon, a MultiPolygon or a GeometryCollection of those.
   *end: the position after the object. */
static int walk_geometry(const struct json *j, size_t p, const char *where, size_t *end)
{
    const char *t = j->text, *type;
    size_t at[M_COUNT], n, k = 0, c, e;
    char loc[320], buf[64];

    if (scan_members(j, p, where, at, end) != 0
        || type_of(j, at, where, "the geometry", &type, &n) != 0)
        return -1;
    if (is(type, n, "Polygon") || is(type, n, "MultiPolygon")) {
        int multi = is(type, n, "MultiPolygon");
        if ((c = at[M_COORDINATES]) == NONE)
            return fail(j, where, "the %s has no \"coordinates\" member",
                        multi ? "MultiPolygon" : "Polygon");
        if (!multi)
            return walk_rings(j, c, where, 0, &e);
        if (t[c] != '[')
            return fail(j, where, "\"coordinates\": expected an array of polygons, found %s",
                        kind(t[c]));
        for (c = ws(j, c + 1); t[c] != ']'; c = next(j, e))
            if (walk_rings(j, c, where, ++k, &e) != 0)
                return -1;
        return 0;
    }
    if (is(type, n, "GeometryCollection")) {
        if ((c = at[M_GEOMETRIES]) == NONE)
            return fail(j, where, "the GeometryCollection has no \"geometries\" member");
        if (t[c] != '[')
            return fail(j, where, "\"geometries\": expected an array, found %s", kind(t[c]));
        for (c = ws(j, c + 1); t[c] != ']'; c = next(j, e)) {
            snprintf(loc, sizeof loc, "%s%sgeometry %zu", where, where[0] ? " " : "", ++k);
            if (t[c] != '{')
                return fail(j, loc, "expected a geometry object, found %s", kind(t[c]));
            if (walk_geometry(j, c, loc, &e) != 0)
                return -1;
        }
        return 0;
    }
    return fail(j, where, "geometry type %s is not a Polygon or MultiPolygon",
                shape_shown(type, n, buf));
}

/* A Feature object at p: its geometry's rings (none when the geometry is null).
   *end: the position after the object. */
static int walk_feature(const struct json *j, size_t p, const char *where, size_t *end)
{
    const char *type;
    size_t at[M_COUNT], n, g, e;
    char buf[64];

    if (scan_members(j, p, where, at, end) != 0
        || type_of(j, at, where, "the feature", &type, &n) != 0)
        return -1;
    if (!is(type, n, "Feature"))
        return fail(j, where, "type %s where a \"Feature\" was expected",
                    shape_shown(type, n, buf));
    if ((g = at[M_GEOMETRY]) == NONE)
        return fail(j, where, "the Feature has no \"geometry\" member");
    if (j->text[g] == 'n')
        return 0;
    if (j->text[g] != '{')
        return fail(j, where, "\"geometry\": expected an object or null, found %s",
                    kind(j->text[g]));
    return walk_geometry(j, g, where, &e);
}

int geojson_rings(const char *name, const char *text, size_t len, struct ring_builder *b,
                  char *msg, size_t size)
{
    struct json j;
    const char *type;
    size_t p, at[M_COUNT], n, f, k = 0, e;
    char where[64];

    j.name = name;
    j.text = text;
    j.len = len;
    j.msg = msg;
    j.size = size;
    j.b = b;
    if (json_check(name, text, len, msg, size) != 0)
        return -1;
    p = ws(&j, 0); /* shape_files.c saw a '{' or a '[' there */
    if (text[p] == '[')
        return fail(&j, "", "the file holds a JSON array, not a GeoJSON object");
    if (scan_members(&j, p, "", at, &e) != 0
        || type_of(&j, at, "", "the top-level object", &type, &n) != 0)
        return -1;
    if (is(type, n, "FeatureCollection")) {
        if ((f = at[M_FEATURES]) == NONE)
            return fail(&j, "", "the FeatureCollection has no \"features\" member");
        if (text[f] != '[')
            return fail(&j, "", "\"features\": expected an array, found %s", kind(text[f]));
        for (f = ws(&j, f + 1); text[f] != ']'; f = next(&j, e)) {
            snprintf(where, sizeof where, "feature %zu", ++k);
            if (text[f] != '{')
                return fail(&j, where, "expected a Feature object, found %s", kind(text[f]));
            if (walk_feature(&j, f, where, &e) != 0)
                return -1;
        }
        if (k == 0)
            return fail(&j, "", "the FeatureCollection has no features");
    } else if (is(type, n, "Feature")) {
        if (walk_feature(&j, p, "", &e) != 0)
            return -1;
    } else if (walk_geometry(&j, p, "", &e) != 0) {
        return -1;
    }
    if (b->nrings == 0)
        return fail(&j, "", "no polygon rings in the file");
    return 0;
}
