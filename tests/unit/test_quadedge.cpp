// test_quadedge.cpp - the edge algebra on hand-built meshes.
#include "mesh_checks.hpp"
#include "mesh/quadedge.hpp"
#include "suites.hpp"

using Q = pds::QuadEdgeMesh;

START_TEST(isolated_edge) {
    Q m;
    m.reserve(4);
    const pds::EdgeRef e = m.make_edge(7, 9);
    ck_assert_uint_eq(m.org(e), 7);
    ck_assert_uint_eq(m.dest(e), 9);
    ck_assert_uint_eq(m.onext(e), e);              // alone at its origin
    ck_assert_uint_eq(m.onext(Q::sym(e)), Q::sym(e));
    ck_assert_uint_eq(m.onext(Q::rot(e)), Q::rot_inv(e));  // one face on both sides
    ck_assert_uint_eq(m.lnext(e), Q::sym(e));
    check_quadedge_algebra(m);
}
END_TEST

START_TEST(splice_is_an_involution) {
    Q m;
    m.reserve(4);
    const pds::EdgeRef a = m.make_edge(0, 1), b = m.make_edge(0, 2);
    m.splice(a, b);
    ck_assert_uint_eq(m.onext(a), b);
    ck_assert_uint_eq(m.onext(b), a);
    check_quadedge_algebra(m);
    m.splice(a, b);
    ck_assert_uint_eq(m.onext(a), a);
    ck_assert_uint_eq(m.onext(b), b);
    check_quadedge_algebra(m);
}
END_TEST

START_TEST(triangle_by_connect) {
    Q m;
    m.reserve(4);
    const pds::EdgeRef a = m.make_edge(0, 1), b = m.make_edge(1, 2);
    m.splice(Q::sym(a), b);
    const pds::EdgeRef c = m.connect(b, a);  // 2 -> 0
    ck_assert_uint_eq(m.org(c), 2);
    ck_assert_uint_eq(m.dest(c), 0);
    ck_assert_uint_eq(m.lnext(a), b);
    ck_assert_uint_eq(m.lnext(b), c);
    ck_assert_uint_eq(m.lnext(c), a);
    // The other side is the same triangle the other way round.
    ck_assert_uint_eq(m.lnext(Q::sym(a)), Q::sym(c));
    check_quadedge_algebra(m);
}
END_TEST

START_TEST(swap_and_delete) {
    // Square 0-1-2-3 with diagonal 0-2, swapped to 1-3, then deleted.
    Q m;
    m.reserve(8);
    pds::EdgeRef s[4];
    for (std::uint32_t i = 0; i < 4; ++i) s[i] = m.make_edge(i, (i + 1) % 4);
    for (int i = 0; i < 4; ++i) m.splice(Q::sym(s[i]), s[(i + 1) % 4]);
    const pds::EdgeRef d = m.connect(s[1], s[0]);  // 2 -> 0
    ck_assert_uint_eq(m.lnext(m.lnext(m.lnext(d))), d);
    m.swap(d);
    const std::uint32_t o = m.org(d), t = m.dest(d);
    ck_assert((o == 1 && t == 3) || (o == 3 && t == 1));
    ck_assert_uint_eq(m.lnext(m.lnext(m.lnext(d))), d);
    ck_assert_uint_eq(m.lnext(m.lnext(m.lnext(Q::sym(d)))), Q::sym(d));
    check_quadedge_algebra(m);
    ck_assert_uint_eq(m.live_count(), 5);
    const std::size_t records = m.record_count();
    m.delete_edge(d);
    ck_assert_uint_eq(m.live_count(), 4);
    ck_assert_uint_eq(m.lnext(m.lnext(m.lnext(m.lnext(s[0])))), s[0]);  // one square face again
    check_quadedge_algebra(m);
    // The freed record is reused before any new one.
    const pds::EdgeRef again = m.make_edge(0, 2);
    ck_assert_uint_eq(again >> 2, d >> 2);
    ck_assert_uint_eq(m.record_count(), records);
}
END_TEST

Suite* quadedge_suite() {
    Suite* s = suite_create("quadedge");
    TCase* t = tcase_create("operators");
    tcase_add_test(t, isolated_edge);
    tcase_add_test(t, splice_is_an_involution);
    tcase_add_test(t, triangle_by_connect);
    tcase_add_test(t, swap_and_delete);
    suite_add_tcase(s, t);
    return s;
}
