/*
 * shape_files_test.h - what the two halves of the shape-file test share:
 * shape_files_test.c (the accepted forms, real files, size) and
 * shape_files_bad.c (every error, truncations, random byte changes).
 */
#ifndef PDS_TESTS_TOOLS_SHAPE_FILES_TEST_H
#define PDS_TESTS_TOOLS_SHAPE_FILES_TEST_H

#include <stddef.h>

#include <check.h>

#include "shape_files_internal.h"

/* The text parsed as a polygon file named name: must succeed. */
struct shape_rings rings_ok(const char *name, const char *text, size_t len);

/* r must hold exactly the n vertices xy and the nrings ring ends. */
void assert_rings(const struct shape_rings *r, const double *xy, size_t n, const size_t *ends,
                  size_t nrings, const char *what);

/* A failed read left *r / *p empty, and msg names the file on one line. */
void assert_rings_empty(const struct shape_rings *r, const char *what);
void assert_points_empty(const struct fixed_points *p, const char *what);
void assert_message(const char *msg, const char *name, const char *what);

/* text[len] in a block of exactly len + 1 bytes (so that Valgrind sees a read past it). */
char *exact_copy(const char *text, size_t len);

Suite *shape_files_bad_suite(void);
/* The --stats line's nearest neighbours (pattern_stats_test.c). */
Suite *pattern_stats_suite(void);

#endif
