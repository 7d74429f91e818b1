/*
 * shape_files_internal.h - what shape_files.c (files), shape_text.c (lines),
 * geojson.c and json_check.c (JSON) share: the growing ring arrays, the
 * messages, the JSON check, and the readers with their vertex limit as a
 * parameter, so that the tests can reach the limit without a gigabyte file.
 * Not for the program's other files.
 */
#ifndef POISSONDISK_SHAPE_FILES_INTERNAL_H
#define POISSONDISK_SHAPE_FILES_INTERNAL_H

#include <stddef.h>

#include "shape_files.h"

/* JSON's white space and digits (RFC 8259), for json_check.c and geojson.c. */
static inline int json_is_ws(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

static inline int json_is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Rings being read: the arrays grow by doubling, so reading stays linear. */
struct ring_builder {
    double *xy;
    size_t nvertices, xycap;       /* xycap counts vertices */
    size_t *ring_ends;
    size_t nrings, endcap;
    size_t max_vertices;
};

#define RB_NOMEM (-1)   /* out of memory */
#define RB_TOOMANY (-2) /* the vertex would exceed max_vertices */

/* Appends a vertex to the open ring: 0, RB_NOMEM or RB_TOOMANY. */
int rb_vertex(struct ring_builder *b, double x, double y);
/* Closes the open ring, if it has a vertex: 0 or RB_NOMEM. */
int rb_end_ring(struct ring_builder *b);
/* Moves the arrays into *out (trimmed) and empties b. */
void rb_finish(struct ring_builder *b, struct shape_rings *out);
void rb_free(struct ring_builder *b);

/*
 * Writes "NAME: WHERE: WHAT" (WHERE left out when empty or NULL), WHAT from
 * fmt, into msg (size bytes); returns -1.
 */
int shape_fail(char *msg, size_t size, const char *name, const char *where, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* s[0..len) as a message shows it: in quotes, unprintable bytes as \xNN, cut
   to about 40 characters with "...". Returns buf. */
const char *shape_shown(const char *s, size_t len, char buf[64]);

/* Skips a UTF-8 byte-order mark at *text (*len bytes): 0; -1 with the message when
   the text starts with a UTF-16 one. */
int shape_unicode_start(const char *name, const char **text, size_t *len, char *msg,
                        size_t size);

/* Reads the file at path into *text (len bytes and a '\0'; free it): 0, or -1 with the
   message (it cannot be opened or read, holds more than max_bytes, out of memory). */
int shape_slurp(const char *path, size_t max_bytes, char **text, size_t *len, char *msg,
                size_t size);

/* The readers, with the limit on vertices (or points) given. */
int shape_rings_parse_limit(const char *name, const char *text, size_t len, size_t max_vertices,
                            struct shape_rings *out, char *msg, size_t size);
int fixed_points_parse_limit(const char *name, const char *text, size_t len, size_t max_points,
                             struct fixed_points *out, char *msg, size_t size);

/* The two polygon formats: 0 with the rings in b (empty before), or -1 with the message. */
int text_rings(const char *name, const char *text, size_t len, struct ring_builder *b,
               char *msg, size_t size);
int geojson_rings(const char *name, const char *text, size_t len, struct ring_builder *b,
                  char *msg, size_t size);

/* 0 when text (len bytes) is one JSON value with blanks only around it, else -1 with
   "NAME: line L column C: WHAT" (json_check.c). */
int json_check(const char *name, const char *text, size_t len, char *msg, size_t size);

#endif /* POISSONDISK_SHAPE_FILES_INTERNAL_H */
