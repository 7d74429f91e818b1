/*
 * shape_files_test.c - the program's polygon and fixed-point readers
 * (tools/shape_files.h) on their own: every accepted form gives exactly the
 * coordinates and ring ends written; the files in tests/tools/data/ read
 * through the path functions; a file that cannot be opened or read; outlines
 * of 10^6 vertices. The errors are in shape_files_bad.c.
 *
 * make check-tools builds and runs it from the top of the repository (the
 * data files' paths are relative), then again under Valgrind with CK_FORK=no.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "shape_files_test.h"

#define DATA "tests/tools/data/"
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

char *exact_copy(const char *text, size_t len)
{
    char *s = malloc(len + 1);
    ck_assert_ptr_nonnull(s);
    memcpy(s, text, len);
    s[len] = '\0';
    return s;
}

void assert_message(const char *msg, const char *name, const char *what)
{
    ck_assert_msg(strncmp(msg, name, strlen(name)) == 0 && msg[strlen(name)] == ':',
                  "%s: the message \"%s\" does not start with \"%s:\"", what, msg, name);
    ck_assert_msg(strchr(msg, '\n') == NULL, "%s: the message \"%s\" has a line break", what, msg);
}

void assert_rings_empty(const struct shape_rings *r, const char *what)
{
    ck_assert_msg(r->xy == NULL && r->nvertices == 0 && r->ring_ends == NULL && r->nrings == 0,
                  "%s: a failed read left *out filled", what);
}

void assert_points_empty(const struct fixed_points *p, const char *what)
{
    ck_assert_msg(p->xy == NULL && p->clearance == NULL && p->n == 0,
                  "%s: a failed read left *out filled", what);
}

struct shape_rings rings_ok(const char *name, const char *text, size_t len)
{
    struct shape_rings r;
    char msg[256], *copy = exact_copy(text, len);
    int rc = shape_rings_parse(name, copy, len, &r, msg, sizeof msg);

    free(copy);
    ck_assert_msg(rc == 0, "%s was refused: %s", name, msg);
    return r;
}

void assert_rings(const struct shape_rings *r, const double *xy, size_t n, const size_t *ends,
                  size_t nrings, const char *what)
{
    size_t i;

    ck_assert_msg(r->nvertices == n, "%s: %zu vertices, expected %zu", what, r->nvertices, n);
    ck_assert_msg(r->nrings == nrings, "%s: %zu rings, expected %zu", what, r->nrings, nrings);
    for (i = 0; i < 2 * n; i++)
        ck_assert_msg(r->xy[i] == xy[i], "%s: vertex %zu %s = %.17g, expected %.17g", what,
                      i / 2 + 1, i % 2 ? "y" : "x", r->xy[i], xy[i]);
    for (i = 0; i < nrings; i++)
        ck_assert_msg(r->ring_ends[i] == ends[i], "%s: ring %zu ends at %zu, expected %zu", what,
                      i + 1, r->ring_ends[i], ends[i]);
}

/* Parses text (NUL-terminated) as a polygon and compares with the expected arrays. */
#define CHECK_TEXT(text, xy, ends)                                                          \
    do {                                                                                    \
        struct shape_rings r_ = rings_ok(#xy, text, strlen(text));                          \
        assert_rings(&r_, xy, COUNT(xy) / 2, ends, COUNT(ends), #xy);                       \
        shape_rings_free(&r_);                                                              \
    } while (0)

/* The same through the path function. */
#define CHECK_FILE(path, xy, ends)                                                          \
    do {                                                                                    \
        struct shape_rings r_;                                                              \
        char msg_[256];                                                                     \
        ck_assert_msg(shape_rings_read(path, &r_, msg_, sizeof msg_) == 0, "%s", msg_);     \
        assert_rings(&r_, xy, COUNT(xy) / 2, ends, COUNT(ends), path);                      \
        shape_rings_free(&r_);                                                              \
        ck_assert_ptr_null(r_.xy);                                                          \
    } while (0)

START_TEST(geojson_polygon_with_hole)
{
    /* An outer ring with altitudes and a hole; bbox ignored; closing vertices kept. */
    static const double xy[] = {-10.5, -10.5, 10.5, -10.5, 10.5, 10.5, -10.5, 10.5, -10.5, -10.5,
                                -2, -2, -2, 3.25, 4, 3.25, -2, -2};
    static const size_t ends[] = {5, 9};
    CHECK_FILE(DATA "polygon_hole.geojson", xy, ends);
}
END_TEST

START_TEST(geojson_feature_collection)
{
    /* A Polygon feature, then a MultiPolygon one whose members come before "type";
       properties with escapes, nested "type" members, a crs, exponents. */
    static const double xy[] = {6.1, 46.2, 6.9, 46.4, 6.8, 46.5, 6.1, 46.2,
                                0, 0, 1, 0, 1, 1, 0, 0,
                                -150, 0.002, -149, 0.002, -149.5, 12.5, -150, 0.002,
                                -149.9, 1, -149.6, 1, -149.6, 2, -149.9, 1};
    static const size_t ends[] = {4, 8, 12, 16};
    CHECK_FILE(DATA "features.geojson", xy, ends);
}
END_TEST

START_TEST(geojson_multipolygon_feature_collection_of_geometries)
{
    static const double multi[] = {0, 0, 1, 0, 0, 1, 5, 5, 6, 5, 6, 6, 5, 5, 5.2, 5.1, 5.8, 5.1,
                                   5.8, 5.7};
    static const size_t multi_ends[] = {3, 7, 10};
    static const double feature[] = {1, 1, 2, 1, 2, 2};
    static const size_t feature_ends[] = {3};
    static const double collection[] = {0, 0, 1, 0, 0, 1, 2, 2, 3, 2, 2, 3};
    static const size_t collection_ends[] = {3, 6};

    CHECK_TEXT("{\"type\":\"MultiPolygon\",\"coordinates\":[[[[0,0],[1,0],[0,1]]],"
               "[[[5,5],[6,5],[6,6],[5,5]],[[5.2,5.1],[5.8,5.1],[5.8,5.7]]]]}",
               multi, multi_ends);
    /* "type" and "coordinates" inside properties are not the feature's; brackets and
       escaped quotes in skipped strings. */
    CHECK_TEXT(" \r\n\t{\"type\":\"Feature\",\"properties\":{\"type\":\"x\",\"coordinates\":1,"
               "\"s\":\"}]\\\"[\\\\\",\"t\":[\"{\"]},"
               "\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[1,1],[2,1],[2,2]]]}}\r\n \n",
               feature, feature_ends);
    /* A null geometry adds nothing; an empty GeometryCollection neither; a byte-order mark. */
    CHECK_TEXT("\xef\xbb\xbf{\"type\":\"FeatureCollection\",\"features\":["
               "{\"type\":\"Feature\",\"geometry\":null,\"properties\":{}},"
               "{\"type\":\"Feature\",\"geometry\":{\"type\":\"GeometryCollection\",\"geometries\":["
               "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,1]]]},"
               "{\"type\":\"GeometryCollection\",\"geometries\":[]},"
               "{\"type\":\"MultiPolygon\",\"coordinates\":[[],[[[2,2],[3,2],[2,3]]]]}]}}]}",
               collection, collection_ends);
}
END_TEST

START_TEST(geojson_numbers)
{
    static const double xy[] = {-0.0, 0.5, 100, -0.25, -1250, 123456789012345678901234567890.0,
                                1, 0, 1e-300, -2.5e-320, 1.7976931348623157e308, 7};
    static const size_t ends[] = {6};
    static const char text[] = "{\"type\":\"Polygon\",\"coordinates\":[[[-0,0.5],"
        "[1e2,-2.5E-1,1e999],[-1.25e+3,123456789012345678901234567890],[0.1e1,-0],"
        "[1E-300,-2.5e-320],[1.7976931348623157e308,7]]]}";
    struct shape_rings r = rings_ok("numbers", text, strlen(text));

    assert_rings(&r, xy, COUNT(xy) / 2, ends, COUNT(ends), "numbers");
    ck_assert_msg(signbit(r.xy[0]) && signbit(r.xy[7]), "-0 lost its sign");
    shape_rings_free(&r);
}
END_TEST

START_TEST(text_forms)
{
    /* Comments after numbers, comment lines inside a ring, tabs, runs of blank lines,
       a blank line of spaces, no final line break. */
    static const double xy[] = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 2, 1, 1.5, 2.5, 10, -10, 11, -10,
                                11, -9};
    static const size_t ends[] = {4, 7, 10};
    static const double crlf[] = {0, 0, 1, 0, 1, 1, 2, 2, -3e-2, 2, 2, 3};
    static const size_t crlf_ends[] = {3, 6};
    static const double one[] = {0, 0, 1, 0, 1, 1};
    static const size_t one_ends[] = {3};

    CHECK_FILE(DATA "rings.txt", xy, ends);
    CHECK_TEXT("0 0\r\n1 0\r\n1 1\r\n\r\n\r\n# c\r\n2 2\r\n -3E-2\t2 #\r\n2 3", crlf, crlf_ends);
    CHECK_TEXT("\xef\xbb\xbf\n\n# leading blank lines\n0 0\n# not a separator\n1 0\n1 1\n\n\n", one,
               one_ends);
}
END_TEST

START_TEST(fixed_forms)
{
    static const double xy[] = {0.25, 0.5, 0.75, 0.5, -1e-3, 200};
    static const double clearance[] = {0, 0.1, 3};
    static const char *const empty[] = {"", "\n\n", "# nothing here\r\n  \t\n#\n"};
    struct fixed_points p;
    char msg[256];
    size_t i;

    ck_assert_msg(fixed_points_read(DATA "fixed.txt", &p, msg, sizeof msg) == 0, "%s", msg);
    ck_assert_uint_eq(p.n, 3);
    for (i = 0; i < 6; i++)
        ck_assert_msg(p.xy[i] == xy[i], "fixed point %zu: %.17g, expected %.17g", i / 2 + 1,
                      p.xy[i], xy[i]);
    for (i = 0; i < 3; i++)
        ck_assert_msg(p.clearance[i] == clearance[i], "fixed point %zu: clearance %.17g, "
                      "expected %.17g", i + 1, p.clearance[i], clearance[i]);
    fixed_points_free(&p);
    ck_assert_ptr_null(p.xy);
    /* CRLF, and a UTF-8 byte-order mark. */
    ck_assert_msg(fixed_points_parse("crlf", "\xef\xbb\xbf" "1 2\r\n3 4 5\r\n", 15, &p, msg,
                                     sizeof msg) == 0, "%s", msg);
    ck_assert_msg(p.n == 2 && p.xy[3] == 4 && p.clearance[0] == 0 && p.clearance[1] == 5,
                  "CRLF fixed points read wrong");
    fixed_points_free(&p);
    for (i = 0; i < COUNT(empty); i++) { /* no fixed points is no error */
        ck_assert_msg(fixed_points_parse("empty", empty[i], strlen(empty[i]), &p, msg, sizeof msg)
                      == 0, "%s", msg);
        ck_assert_msg(p.n == 0, "an empty file gave %zu points", p.n);
        fixed_points_free(&p);
    }
}
END_TEST

START_TEST(unreadable_files)
{
    static const char *const missing = DATA "no such file.geojson";
    struct shape_rings r;
    struct fixed_points p;
    char msg[256];

    ck_assert_int_eq(shape_rings_read(missing, &r, msg, sizeof msg), -1);
    assert_rings_empty(&r, missing);
    assert_message(msg, missing, "a missing file");
    ck_assert_msg(strstr(msg, "cannot open") && strstr(msg, strerror(ENOENT)), "%s", msg);
    ck_assert_int_eq(fixed_points_read(missing, &p, msg, sizeof msg), -1);
    assert_points_empty(&p, missing);
    ck_assert_msg(strstr(msg, strerror(ENOENT)) != NULL, "%s", msg);
    /* A directory opens but cannot be read. */
    ck_assert_int_eq(shape_rings_read("tests/tools/data", &r, msg, sizeof msg), -1);
    assert_rings_empty(&r, "a directory");
    assert_message(msg, "tests/tools/data", "a directory");
    ck_assert_msg(strstr(msg, "read error") != NULL, "%s", msg);
}
END_TEST

/* The size limit, through the reading itself: a file of exactly the limit is read,
   one byte more is refused, across the doubling of the buffer too (the file is cut
   shorter each time). */
START_TEST(file_size_limit)
{
    static const size_t sizes[] = {200000, 65537, 65536, 65535, 65534, 100, 99, 1, 0};
    char path[] = "/tmp/shape_files_test_XXXXXX", msg[256], *text;
    size_t i, k, len;
    int fd = mkstemp(path);
    FILE *f;

    ck_assert_msg(fd >= 0, "mkstemp: %s", strerror(errno));
    ck_assert_ptr_nonnull(f = fdopen(fd, "wb"));
    for (i = 0; i < 200000; i++)
        putc('0' + (int)(i % 10), f);
    ck_assert_int_eq(fclose(f), 0);
    for (k = 0; k < COUNT(sizes); k++) {
        ck_assert_msg(truncate(path, (off_t)sizes[k]) == 0, "truncate: %s", strerror(errno));
        ck_assert_msg(shape_slurp(path, sizes[k], &text, &len, msg, sizeof msg) == 0, "%s", msg);
        ck_assert_msg(len == sizes[k] && text[len] == '\0', "%zu bytes read of %zu", len, sizes[k]);
        for (i = 0; i < len; i++)
            ck_assert_int_eq(text[i], '0' + (int)(i % 10));
        free(text);
        if (sizes[k] == 0)
            continue;
        ck_assert_int_eq(shape_slurp(path, sizes[k] - 1, &text, &len, msg, sizeof msg), -1);
        ck_assert_msg(text == NULL && len == 0, "a refused file left text");
        assert_message(msg, path, "a file over the limit");
        ck_assert_msg(strstr(msg, "the file is larger than") != NULL, "%s", msg);
    }
    remove(path);
}
END_TEST

/* big vertices in rings of 1000: vertex i is (i, i % 1000 + 0.5), all exact. */
static void assert_big(const struct shape_rings *r, size_t big, const char *what)
{
    size_t i;

    ck_assert_msg(r->nvertices == big && r->nrings == big / 1000, "%s: %zu vertices, %zu rings",
                  what, r->nvertices, r->nrings);
    for (i = 0; i < big; i++)
        if (r->xy[2 * i] != (double)i || r->xy[2 * i + 1] != (double)(i % 1000) + 0.5)
            ck_abort_msg("%s: vertex %zu is (%.17g, %.17g)", what, i + 1, r->xy[2 * i],
                         r->xy[2 * i + 1]);
    for (i = 0; i < r->nrings; i++)
        ck_assert_uint_eq(r->ring_ends[i], 1000 * (i + 1));
}

/* 10^6 vertices (10^5 with PDS_TEST_LIGHT set, as under Valgrind). */
START_TEST(million_vertices)
{
    char path[] = "/tmp/shape_files_test_XXXXXX", msg[256], *json, *s;
    struct shape_rings r;
    FILE *f;
    size_t i, big = getenv("PDS_TEST_LIGHT") != NULL ? 100000 : 1000000;
    int fd = mkstemp(path);

    ck_assert_msg(fd >= 0, "mkstemp: %s", strerror(errno));
    ck_assert_ptr_nonnull(f = fdopen(fd, "w"));
    for (i = 0; i < big; i++)
        fprintf(f, "%zu %zu.5\n%s", i, i % 1000, i % 1000 == 999 ? "\n" : "");
    ck_assert_int_eq(fclose(f), 0);
    ck_assert_msg(shape_rings_read(path, &r, msg, sizeof msg) == 0, "%s", msg);
    remove(path);
    assert_big(&r, big, "vertices of text");
    shape_rings_free(&r);

    /* The same as one GeoJSON Polygon, in memory. */
    ck_assert_ptr_nonnull(json = s = malloc(32 * big));
    s += sprintf(s, "{\"type\":\"Polygon\",\"coordinates\":[");
    for (i = 0; i < big; i++)
        s += sprintf(s, "%s[%zu,%zu.5]%s", i % 1000 ? "," : i ? ",[" : "[", i, i % 1000,
                     i % 1000 == 999 ? "]" : "");
    s += sprintf(s, "]}");
    ck_assert_int_eq(shape_rings_parse("big.geojson", json, (size_t)(s - json), &r, msg,
                                       sizeof msg), 0);
    free(json);
    assert_big(&r, big, "vertices of GeoJSON");
    shape_rings_free(&r);
}
END_TEST

static Suite *shape_files_suite(void)
{
    Suite *s = suite_create("shape_files");
    TCase *tc = tcase_create("accepted");
    tcase_set_timeout(tc, 60); /* a hang guard; 4 s is tight on a busy machine */

    tcase_add_test(tc, geojson_polygon_with_hole);
    tcase_add_test(tc, geojson_feature_collection);
    tcase_add_test(tc, geojson_multipolygon_feature_collection_of_geometries);
    tcase_add_test(tc, geojson_numbers);
    tcase_add_test(tc, text_forms);
    tcase_add_test(tc, fixed_forms);
    tcase_add_test(tc, unreadable_files);
    tcase_add_test(tc, file_size_limit);
    suite_add_tcase(s, tc);
    tc = tcase_create("size");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, million_vertices);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *runner = srunner_create(shape_files_suite());
    int failed;

    srunner_add_suite(runner, shape_files_bad_suite());
    srunner_add_suite(runner, pattern_stats_suite());
    srunner_run_all(runner, CK_NORMAL);
    failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
