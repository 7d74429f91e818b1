/*
 * shape_files.h - read the polygon and fixed-point files of --polygon and
 * --fixed, so that the poissondisk program needs no JSON or GIS library.
 *
 * Both are UTF-8 or ASCII text: a UTF-8 byte-order mark at the start is
 * skipped, a UTF-16 one refused. A polygon file is GeoJSON when its first
 * non-blank character is '{' ('[' too, then refused: GeoJSON is an object),
 * else plain text:
 *
 *  - GeoJSON (RFC 7946; tools/geojson.c, tools/json_check.c): a Polygon, a
 *    MultiPolygon, a GeometryCollection of those, a Feature whose geometry
 *    is one of those, or a FeatureCollection of such Features. Every ring
 *    of every polygon is
 *    kept, in file order, as written (the repeated closing position stays;
 *    outer rings and holes are not told apart: the rings combine by the
 *    even-odd rule). A position's elements past x and y (altitude) must be
 *    numbers and are ignored. Members other than "type", "coordinates",
 *    "geometry", "features" and "geometries" are ignored (properties, bbox,
 *    crs, id...); names and type values are compared as written, escapes
 *    unresolved. A Feature whose geometry is null adds nothing.
 *  - Plain text: "x y" per line, separated by blanks; a line of blanks only
 *    ends the ring (several in a row count as one); '#' starts a comment
 *    that runs to the end of the line, and a line holding only a comment is
 *    skipped (it does not end the ring). CRLF line ends are accepted.
 *
 * A fixed-point file is text: "x y" or "x y clearance" per line, '#'
 * comments and blank lines skipped. A file without points is valid.
 *
 * Numbers are read with strtod in the C locale (the program never calls
 * setlocale); JSON numbers must follow JSON's grammar first.
 *
 * Every error is a message, never a crash. A message starts with the file's
 * name, then where (numbers count from 1):
 *   "line N" for plain text and fixed points,
 *   "line N column M" for JSON syntax (column in bytes),
 *   "feature K", "geometry G" (in a GeometryCollection) and
 *   "polygon K ring J vertex V" ("ring J vertex V" in a Polygon) for the
 *   GeoJSON structure,
 * then what is wrong. The errors: a file that cannot be opened or read (with
 * strerror), a file over SHAPE_MAX_FILE_BYTES, UTF-16, out of memory;
 *  - polygon text: a line that is not exactly two finite numbers; no vertex;
 *  - GeoJSON syntax: anything that is not one strict RFC 8259 value (bad
 *    escape, raw control character in a string, malformed number or
 *    literal, a missing ',' ':' ']' or '}'), the file ending inside it, more
 *    than SHAPE_JSON_MAX_DEPTH nested arrays and objects, anything but
 *    blanks after it;
 *  - GeoJSON structure: a top-level array; a missing or non-string "type"; a member among the
 *    five above given twice in one object; a geometry that is not a
 *    Polygon, MultiPolygon or GeometryCollection (its type named); missing
 *    or non-array "coordinates", "geometries" or "features"; a feature that
 *    is not a Feature or has no "geometry"; a FeatureCollection without
 *    features; a position with fewer than 2 numbers or a non-number in it;
 *    a non-finite coordinate (1e999 overflows); a ring of fewer than 3
 *    positions; no ring at all;
 *  - fixed points: a line of other than 2 or 3 numbers, a non-finite
 *    number, a clearance not > 0;
 *  - more than SHAPE_MAX_VERTICES vertices or points.
 * Whether a ring encloses anything (3 distinct vertices, a non-empty
 * interior) is the library's check, not the reader's. Plain C99.
 */
#ifndef POISSONDISK_SHAPE_FILES_H
#define POISSONDISK_SHAPE_FILES_H

#include <stddef.h>

/* The most vertices a polygon file (or points a fixed-point file) may hold: the
   coordinates then take 1 GiB. */
#define SHAPE_MAX_VERTICES ((size_t)1 << 26)
/* The largest file read: 2 GiB. */
#define SHAPE_MAX_FILE_BYTES ((size_t)1 << 31)
/* The deepest nesting of JSON arrays and objects (GeoJSON needs 8 at most
   outside GeometryCollections): the parser recurses, its stack stays small. */
#define SHAPE_JSON_MAX_DEPTH 64

/* A polygonal domain as the library will take it: vertices x y interleaved; ring k is
   vertices [k ? ring_ends[k-1] : 0, ring_ends[k]); rings combine by the even-odd rule. */
struct shape_rings {
    double *xy;          /* 2 * nvertices */
    size_t nvertices;
    size_t *ring_ends;   /* nrings entries, increasing, the last == nvertices */
    size_t nrings;
};

/* Reads FILE: GeoJSON (first non-blank character '{') or plain text. 0 and *out filled
   (release with shape_rings_free), or -1 with msg (size bytes, no newline) and *out empty. */
int shape_rings_read(const char *path, struct shape_rings *out, char *msg, size_t size);

/* The same from memory: text holds len bytes and text[len] == '\0' (the numbers are
   read with strtod); name is used in the messages only. */
int shape_rings_parse(const char *name, const char *text, size_t len,
                      struct shape_rings *out, char *msg, size_t size);

void shape_rings_free(struct shape_rings *r);

/* Fixed points: "x y [clearance]" per line. clearance[i] == 0 means "not given" (the library
   then uses the radius at that point). */
struct fixed_points { double *xy; double *clearance; size_t n; };

/* Reads FILE. 0 and *out filled (n may be 0: no fixed points; release with
   fixed_points_free), or -1 with msg (size bytes, no newline) and *out empty. */
int fixed_points_read(const char *path, struct fixed_points *out, char *msg, size_t size);

/* The same from memory, as shape_rings_parse. */
int fixed_points_parse(const char *name, const char *text, size_t len,
                       struct fixed_points *out, char *msg, size_t size);

void fixed_points_free(struct fixed_points *p);

#endif /* POISSONDISK_SHAPE_FILES_H */
