/*
 * shape_files_bad.c - what the shape-file readers refuse: each malformed
 * GeoJSON, ring text and fixed-point text gives -1, an empty *out, and a
 * message naming the file, where, and what; every prefix of a valid GeoJSON
 * file is refused; thousands of deterministic random byte changes never
 * crash, and whatever they are given is either refused that way or read
 * into consistent arrays. Each buffer is allocated to its exact size, so
 * Valgrind sees any read past it.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shape_files_test.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

struct bad {
    const char *text;
    const char *want[3]; /* substrings of the message (NULL: none) */
};

#define POLY(c) "{\"type\":\"Polygon\",\"coordinates\":" c "}"
#define TRI "[[0,0],[1,0],[1,1]]"
#define FEATURE(g) "{\"type\":\"Feature\",\"geometry\":" g "}"
#define COLLECTION(f) "{\"type\":\"FeatureCollection\",\"features\":[" f "]}"

static const struct bad bad_geojson[] = {
    /* syntax */
    {"{\"type\":\"Polygon\",\"coordinates\":[" TRI "]", {"line 1 column 54:", "ends inside an object", "truncated"}},
    {"{", {"line 1 column 2:", "ends inside an object"}},
    {"{\"type\":\"Polygon\"", {"ends inside an object"}},
    {"{\"type\":\"Poly", {"line 1 column 9:", "ends inside this string"}},
    {POLY("[" TRI "]") " x", {"line 1 column 56:", "'x' after the end of the JSON value"}},
    {POLY("[" TRI "]") "{}", {"'{' after the end"}},
    {POLY("[" TRI ",]"), {"expected a value, found ']'"}},
    {"{\"type\":\"Polygon\",\n\"coordinates\":[[[0,0],[1,0],[01,1]]]}", {"line 2 column 30:", "leading zero"}},
    {POLY("[[[0,0],[1,0],[1.,1]]]"), {"column 48:", "malformed number"}},
    {POLY("[[[0,0],[1,0],[1e,1]]]"), {"malformed number"}},
    {POLY("[[[0,0],[1,0],[-,1]]]"), {"malformed number"}},
    {POLY("[[[0,0],[1,0],[+1,1]]]"), {"expected a value, found '+'"}},
    {POLY("[[[0,0],[1,0],[NaN,1]]]"), {"expected a value, found 'N'"}},
    {POLY("[[[0,0],[1,0],[.5,1]]]"), {"expected a value, found '.'"}},
    {POLY("[" TRI "]") ",", {"',' after the end"}},
    {"{\"type\":\"Polygon\" \"coordinates\":[" TRI "]}", {"expected ',' or '}' in an object, found '\"'"}},
    {"{\"type\" \"Polygon\"}", {"expected ':' after the member name"}},
    {"{type:\"Polygon\"}", {"line 1 column 2:", "expected a member name"}},
    {"{\"type\":\"Poly\\qgon\"}", {"invalid escape", "'q'"}},
    {"{\"type\":\"Poly\\u00G0gon\"}", {"\\u needs 4 hexadecimal digits"}},
    {"{\"type\":\"Poly\ngon\"}", {"raw control character (0x0a) in a string"}},
    {"{\"type\":\"Polygon\",\"x\":tru}", {"expected a value, found 't'"}},
    {"{\"type\":\"Polygon\",\"x\":nul", {"ends inside \"null\""}},
    {"{\"type\":\"Polygon\",\"x\":[1 2]}", {"expected ',' or ']' in an array, found '2'"}},
    {"{\"a\":[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]}",
     {"nest deeper than 64"}},
    /* structure */
    {"{\"type\":\"LineString\",\"coordinates\":[[0,0],[1,1]]}", {"geometry type \"LineString\" is not a Polygon or MultiPolygon"}},
    {COLLECTION(FEATURE(POLY("[" TRI "]")) "," FEATURE("{\"type\":\"Point\",\"coordinates\":[0,0]}")),
     {"feature 2: geometry type \"Point\" is not a Polygon or MultiPolygon"}},
    {"{\"type\":\"Polygon\"}", {"the Polygon has no \"coordinates\" member"}},
    {"{\"type\":\"MultiPolygon\",\"bbox\":[0,0,1,1]}", {"the MultiPolygon has no \"coordinates\""}},
    {"{\"coordinates\":[" TRI "]}", {"the top-level object has no \"type\" member"}},
    {"{\"type\":7,\"coordinates\":[" TRI "]}", {"\"type\" is a number, not a string"}},
    {"{\"type\":\"Polygon\",\"type\":\"Polygon\",\"coordinates\":[" TRI "]}", {"the member \"type\" appears twice"}},
    {"{\"type\":\"Polygon\",\"coordinates\":[],\"coordinates\":[" TRI "]}", {"\"coordinates\" appears twice"}},
    {POLY("[[[0,0],[1],[1,1]]]"), {"ring 1 vertex 2: a position needs 2 numbers (x and y), found 1"}},
    {POLY("[[[0,0],[1,\"a\"],[1,1]]]"), {"ring 1 vertex 2: a position holds numbers only, found a string"}},
    {POLY("[[[0,0],[1,0,null],[1,1]]]"), {"ring 1 vertex 2: a position holds numbers only, found null"}},
    {POLY("[[[0,0],1,[1,1]]]"), {"ring 1 vertex 2: expected a position", "found a number"}},
    {POLY("[" TRI ",[[0,0],[1,0],[1,-1e400]]]"), {"ring 2 vertex 3: \"-1e400\" is not a finite number"}},
    {COLLECTION(FEATURE(POLY("[" TRI "]")) "," FEATURE("{\"type\":\"MultiPolygon\",\"coordinates\":[[" TRI "],[" TRI ",[[0,0],[1,0],[1e999,1]]]]}")),
     {"feature 2 polygon 2 ring 2 vertex 3: \"1e999\" is not a finite number"}},
    {"{\"type\":\"FeatureCollection\",\"features\":[]}", {"the FeatureCollection has no features"}},
    {"{\"type\":\"FeatureCollection\"}", {"the FeatureCollection has no \"features\" member"}},
    {"{\"type\":\"FeatureCollection\",\"features\":{}}", {"\"features\": expected an array, found an object"}},
    {COLLECTION("[]"), {"feature 1: expected a Feature object, found an array"}},
    {COLLECTION(POLY("[" TRI "]")), {"feature 1: type \"Polygon\" where a \"Feature\" was expected"}},
    {COLLECTION("{\"geometry\":null}"), {"feature 1: the feature has no \"type\" member"}},
    {COLLECTION("{\"type\":\"Feature\"}"), {"feature 1: the Feature has no \"geometry\" member"}},
    {COLLECTION(FEATURE("[]")), {"feature 1: \"geometry\": expected an object or null, found an array"}},
    {COLLECTION(FEATURE("null")), {"no polygon rings in the file"}},
    {POLY("[]"), {"no polygon rings"}},
    {POLY("{}"), {"expected an array of rings, found an object"}},
    {POLY("[[1,2]]"), {"ring 1 vertex 1: expected a position", "found a number"}},
    {POLY("[1]"), {"ring 1: expected an array of positions, found a number"}},
    {POLY("[[[0,0],[1,0]]]"), {"ring 1: 2 positions, a ring needs at least 3"}},
    {POLY("[" TRI ",[]]"), {"ring 2: 0 positions, a ring needs at least 3"}},
    {"{\"type\":\"MultiPolygon\",\"coordinates\":\"x\"}", {"expected an array of polygons, found a string"}},
    {"{\"type\":\"MultiPolygon\",\"coordinates\":[[" TRI "],7]}", {"polygon 2: expected an array of rings, found a number"}},
    {"{\"type\":\"GeometryCollection\",\"geometries\":[" POLY("[" TRI "]") ",{\"type\":\"LineString\"}]}",
     {"geometry 2: geometry type \"LineString\""}},
    {"{\"type\":\"GeometryCollection\",\"geometries\":[true]}", {"geometry 1: expected a geometry object, found a boolean"}},
    {"{\"type\":\"GeometryCollection\"}", {"has no \"geometries\" member"}},
    {"{\"type\":\"Feature\",\"geometry\":{\"type\":\"Poly\\u0067on\",\"coordinates\":[]}}",
     {"geometry type \"Poly\\x5cu0067on\" is not a Polygon"}},
    {"[" POLY("[" TRI "]") "]", {"the file holds a JSON array, not a GeoJSON object"}},
    {" [1, 2]", {"a JSON array, not a GeoJSON object"}},
    {"\xff\xfe{", {"the file is UTF-16", "save it as UTF-8"}},
    {"\xfe\xff", {"the file is UTF-16"}},
    /* neither: blank and empty files are text */
    {"", {"no vertices"}},
    {" \n\t\r\n", {"no vertices"}},
};

static const struct bad bad_text[] = {
    {"0 0\n1\n", {"line 2: expected 2 numbers \"x y\", found 1 column"}},
    {"0 0\n1 2 3\n", {"line 2:", "found 3 columns"}},
    {"0 0\n1,2\n", {"line 2:", "found 1 column"}},
    {"0 0\n1 x\n", {"line 2: \"x\" is not a number"}},
    {"0 0\n1 2x\n", {"line 2: \"2x\" is not a number"}},
    {"0 0\n1 1e999\n", {"line 2: \"1e999\" is not a finite number"}},
    {"0 0\r\n\r\n1 inf\r\n", {"line 3: \"inf\" is not a finite number"}},
    {"0 0\n\n# c\n-nan 1", {"line 4: \"-nan\" is not a finite number"}},
    {"# only a comment\n\n", {"no vertices"}},
    {"1 2\n3 \x01\n", {"line 2: \"\\x01\" is not a number"}},
    {"\xfe\xff\0" "1", {"the file is UTF-16"}},
};

static const struct bad bad_fixed[] = {
    {"1\n", {"line 1: expected \"x y\" or \"x y clearance\", found 1 column"}},
    {"1 2\n\n1 2 3 4\n", {"line 3:", "found 4 columns"}},
    {"1 2 0\n", {"line 1: the clearance \"0\" is not > 0"}},
    {"# c\n1 2 -0.5\n", {"line 2: the clearance \"-0.5\" is not > 0"}},
    {"1 2 -0\n", {"the clearance \"-0\" is not > 0"}},
    {"1 2 nan\n", {"line 1: \"nan\" is not a finite number"}},
    {"1 2 1e999\n", {"\"1e999\" is not a finite number"}},
    {"1 e 3\n", {"line 1: \"e\" is not a number"}},
    {"1e400 2\n", {"line 1: \"1e400\" is not a finite number"}},
    {"\xff\xfe" "1\0 2\0", {"the file is UTF-16"}},
};

enum kind { RINGS, FIXED };

/* text must be refused with every wanted substring; *out must be empty. */
static void assert_refused(enum kind k, const char *name, const char *text, size_t len,
                           const char *const want[3])
{
    struct shape_rings r;
    struct fixed_points p;
    char msg[512], *copy = exact_copy(text, len);
    int rc = k == RINGS ? shape_rings_parse(name, copy, len, &r, msg, sizeof msg)
                        : fixed_points_parse(name, copy, len, &p, msg, sizeof msg);
    size_t i;

    free(copy);
    ck_assert_msg(rc == -1, "%s was accepted: %s", name, text);
    if (k == RINGS)
        assert_rings_empty(&r, text);
    else
        assert_points_empty(&p, text);
    assert_message(msg, name, text);
    for (i = 0; i < 3 && want[i] != NULL; i++)
        ck_assert_msg(strstr(msg, want[i]) != NULL, "for %s\nthe message \"%s\" lacks \"%s\"",
                      text, msg, want[i]);
}

START_TEST(geojson_errors)
{
    size_t i;
    for (i = 0; i < COUNT(bad_geojson); i++)
        assert_refused(RINGS, "bad.geojson", bad_geojson[i].text, strlen(bad_geojson[i].text),
                           bad_geojson[i].want);
}
END_TEST

START_TEST(text_errors)
{
    size_t i;
    for (i = 0; i < COUNT(bad_text); i++)
        assert_refused(RINGS, "bad.txt", bad_text[i].text, strlen(bad_text[i].text), bad_text[i].want);
    for (i = 0; i < COUNT(bad_fixed); i++)
        assert_refused(FIXED, "fixed.txt", bad_fixed[i].text, strlen(bad_fixed[i].text),
                       bad_fixed[i].want);
}
END_TEST

START_TEST(nul_bytes_and_small_messages)
{
    static const char poly[] = POLY("[" TRI "]");
    static const char *const in_string[] = {"raw control character (0x00)", NULL, NULL};
    static const char *const in_value[] = {"expected a value, found byte 0x00", NULL, NULL};
    static const char *const in_text[] = {"line 2: \"1\\x002\" is not a number", NULL, NULL};
    struct shape_rings r;
    char msg[16];
    size_t i;

    assert_refused(RINGS, "nul", "{\"type\":\"Pol\0ygon\"}", 19, in_string);
    assert_refused(RINGS, "nul", "{\"type\":\0}", 10, in_value);
    assert_refused(RINGS, "nul", "0 0\n1\0002 3\n", 10, in_text);
    assert_refused(FIXED, "nul", "0 0\n1\0002 3\n", 10, in_text);
    /* A short message buffer: cut, terminated, nothing written past it; none at all. */
    memset(msg, 'x', sizeof msg);
    ck_assert_int_eq(shape_rings_parse("short", poly, strlen(poly) - 1, &r, msg, 8), -1);
    ck_assert_msg(strcmp(msg, "short: ") == 0, "\"%s\"", msg);
    for (i = 8; i < sizeof msg; i++)
        ck_assert_int_eq(msg[i], 'x');
    ck_assert_int_eq(shape_rings_parse("none", poly, strlen(poly) - 1, &r, NULL, 0), -1);
    assert_rings_empty(&r, "no message buffer");
}
END_TEST

/* 64 nested arrays and objects pass the syntax check, 65 do not. */
START_TEST(nesting_limit)
{
    static const char *const within[] = {"has no \"type\" member", NULL, NULL};
    static const char *const beyond[] = {"line 1 column 69: arrays and objects nest deeper than 64",
                                         NULL, NULL};
    char text[256];
    size_t k, n = 0;

    n += (size_t)sprintf(text + n, "{\"a\":");
    for (k = 0; k < 63; k++)
        text[n++] = '[';
    for (k = 0; k < 63; k++)
        text[n++] = ']';
    text[n++] = '}';
    assert_refused(RINGS, "depth", text, n, within);
    n = 0;
    n += (size_t)sprintf(text + n, "{\"a\":");
    for (k = 0; k < 64; k++)
        text[n++] = '[';
    for (k = 0; k < 64; k++)
        text[n++] = ']';
    text[n++] = '}';
    assert_refused(RINGS, "depth", text, n, beyond);
}
END_TEST

START_TEST(vertex_limit)
{
    static const char text[] = "0 0\n1 0\n1 1\n\n5 5\n6 5\n6 6\n";
    static const char json[] = POLY("[" TRI ",[[5,5],[6,5],[6,6]]]");
    static const char fixed[] = "0 0\n1 0\n1 1 2\n";
    struct shape_rings r;
    struct fixed_points p;
    char msg[256];

    ck_assert_int_eq(shape_rings_parse_limit("lim", text, strlen(text), 6, &r, msg, sizeof msg), 0);
    shape_rings_free(&r);
    ck_assert_int_eq(shape_rings_parse_limit("lim", text, strlen(text), 5, &r, msg, sizeof msg), -1);
    assert_rings_empty(&r, "text over the limit");
    ck_assert_msg(strstr(msg, "lim: line 7: more than 5 vertices") != NULL, "%s", msg);
    ck_assert_int_eq(shape_rings_parse_limit("lim", json, strlen(json), 6, &r, msg, sizeof msg), 0);
    shape_rings_free(&r);
    ck_assert_int_eq(shape_rings_parse_limit("lim", json, strlen(json), 5, &r, msg, sizeof msg), -1);
    assert_rings_empty(&r, "GeoJSON over the limit");
    ck_assert_msg(strstr(msg, "lim: ring 2 vertex 3: more than 5 vertices") != NULL, "%s", msg);
    ck_assert_int_eq(fixed_points_parse_limit("lim", fixed, strlen(fixed), 3, &p, msg, sizeof msg), 0);
    fixed_points_free(&p);
    ck_assert_int_eq(fixed_points_parse_limit("lim", fixed, strlen(fixed), 2, &p, msg, sizeof msg), -1);
    assert_points_empty(&p, "fixed points over the limit");
    ck_assert_msg(strstr(msg, "lim: line 3: more than 2 points") != NULL, "%s", msg);
}
END_TEST

/* A valid file with every JSON construct: each of its prefixes must be refused. */
static const char sample[] =
    "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\",\"properties\":"
    "{\"s\":\"a\\\"b\\\\c\\/\\u00e9\\n\",\"t\":true,\"f\":false,\"n\":null,\"o\":{},\"a\":[]},"
    "\"geometry\":{\"type\":\"MultiPolygon\",\"coordinates\":[[[[0,0],[1.5,0,9],[1,1e1],"
    "[0,0]]],[[[-2E-1,3],[4,5],[6,7.25e+2]],[[1,1],[2,1],[2,2]]]]}},\n {\"type\":\"Feature\","
    "\"geometry\":{\"type\":\"GeometryCollection\",\"geometries\":[{\"type\":\"Polygon\","
    "\"coordinates\":[[[10,10],[11,10],[11,11]]]}]}}]}";

START_TEST(every_prefix_refused)
{
    struct shape_rings r;
    char msg[512], *copy;
    size_t len;

    r = rings_ok("sample", sample, strlen(sample));
    ck_assert_uint_eq(r.nrings, 4);
    shape_rings_free(&r);
    for (len = 0; len < strlen(sample); len++) {
        copy = exact_copy(sample, len);
        ck_assert_msg(shape_rings_parse("prefix", copy, len, &r, msg, sizeof msg) == -1,
                      "the first %zu bytes were accepted", len);
        free(copy);
        assert_rings_empty(&r, "a prefix");
        assert_message(msg, "prefix", "a prefix");
        ck_assert_msg(len == 0 || strstr(msg, "truncated") != NULL,
                      "the first %zu bytes: %s", len, msg);
    }
}
END_TEST

/* A failed parse left *r empty; an accepted one holds consistent arrays. */
static void assert_consistent(int rc, const struct shape_rings *r, const char *msg, size_t n)
{
    size_t i;

    if (rc != 0) {
        ck_assert_msg(rc == -1, "mutation %zu returned %d", n, rc);
        assert_rings_empty(r, "a mutation");
        assert_message(msg, "mutant", "a mutation");
        return;
    }
    ck_assert_msg(r->nrings > 0 && r->ring_ends[r->nrings - 1] == r->nvertices,
                  "mutation %zu: ring ends do not end at the vertex count", n);
    for (i = 0; i < r->nrings; i++)
        ck_assert_msg(r->ring_ends[i] > (i ? r->ring_ends[i - 1] : 0),
                      "mutation %zu: ring %zu is empty", n, i + 1);
    for (i = 0; i < 2 * r->nvertices; i++)
        ck_assert_msg(isfinite(r->xy[i]), "mutation %zu: a non-finite coordinate", n);
}

START_TEST(random_byte_changes)
{
    /* Bytes that matter to the grammar, drawn half of the time; any byte otherwise. */
    static const char special[] = "{}[]\":,\\0123456789eE.-+ \n#tfnu";
    static const char text[] = "# rings\n0 0\n1 0 # c\n1 1\n\n2 2\r\n3 2\r\n2 3\n";
    static const char fixed[] = "0 0\n1 0 0.5\n# c\n\n1 1 2\n";
    const char *base[3];
    size_t blen[3], n;
    uint64_t state = 0x9e3779b97f4a7c15u;

    base[0] = sample, base[1] = text, base[2] = fixed;
    blen[0] = strlen(sample), blen[1] = strlen(text), blen[2] = strlen(fixed);
    for (n = 0; n < 4000; n++) {
        size_t which = n % 4 == 3 ? 1 + n / 4 % 2 : 0, len = blen[which], k, changes;
        char *copy = exact_copy(base[which], len), msg[512];
        struct shape_rings r;
        struct fixed_points p;
        int rc;
        state = state * 6364136223846793005u + 1442695040888963407u;
        changes = 1 + (size_t)(state >> 62);
        for (k = 0; k < changes; k++) {
            size_t at;
            state = state * 6364136223846793005u + 1442695040888963407u;
            at = (size_t)(state >> 33) % len;
            copy[at] = (char)((state >> 16 & 1) ? special[(state >> 20) % (sizeof special - 1)]
                                                : (char)(state >> 24));
        }
        if (which == 2) {
            rc = fixed_points_parse("mutant", copy, len, &p, msg, sizeof msg);
            if (rc == 0)
                fixed_points_free(&p);
            else
                assert_points_empty(&p, "a mutation");
        } else {
            rc = shape_rings_parse("mutant", copy, len, &r, msg, sizeof msg);
            assert_consistent(rc, &r, msg, n);
            if (rc == 0)
                shape_rings_free(&r);
        }
        free(copy);
    }
}
END_TEST

Suite *shape_files_bad_suite(void)
{
    Suite *s = suite_create("shape_files_bad");
    TCase *tc = tcase_create("errors");
    tcase_set_timeout(tc, 60); /* a hang guard; 4 s is tight on a busy machine */

    tcase_add_test(tc, geojson_errors);
    tcase_add_test(tc, text_errors);
    tcase_add_test(tc, nul_bytes_and_small_messages);
    tcase_add_test(tc, nesting_limit);
    tcase_add_test(tc, vertex_limit);
    suite_add_tcase(s, tc);
    tc = tcase_create("robustness");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, every_prefix_refused);
    tcase_add_test(tc, random_byte_changes);
    suite_add_tcase(s, tc);
    return s;
}
