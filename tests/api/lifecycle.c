/*
 * lifecycle.c - creating and destroying samplers in every state.
 *
 * Contract: pds_destroy releases "everything it holds", whatever the state.
 * These tests only pass or crash on their own; their real check is Valgrind
 * (make check-valgrind: --leak-check=full, errors on any leak kind), which
 * sees a sampler destroyed empty, mid-run, after a refine, after failures and
 * when maximal.
 */
#include <stdint.h>

#include "helpers.h"
#include "suites.h"

START_TEST(create_destroy_cycles)
{
    size_t i, cycles = pick(2000, 100);

    for (i = 0; i < cycles; i++) {
        pds_sampler *s = sampler_new(0.05 + 0.001 * (double)(i % 7), (uint64_t)i);
        /* Every third one dies empty, the others after a few points. */
        if (i % 3 != 0)
            ck_assert_int_eq(pds_run(s, 1 + i % 5, NULL), 1);
        pds_destroy(s);
    }
}
END_TEST

START_TEST(destroy_in_every_state)
{
    pds_sampler *s;
    size_t added;

    s = sampler_new(0.02, 1); /* just created */
    pds_destroy(s);

    s = sampler_new_in(0.02, 2, (test_domain){0.0, 0.0, 2.0, 1.0}); /* domain set */
    pds_destroy(s);

    s = sampler_new(0.02, 3); /* mid-run */
    ck_assert_int_eq(pds_run(s, 500, &added), 1);
    ck_assert_uint_eq(added, 500);
    pds_destroy(s);

    s = sampler_new(0.03, 4); /* refined mid-run, then more points */
    ck_assert_int_eq(pds_run(s, 100, NULL), 1);
    ck_assert_int_eq(pds_refine(s, 0.02), 0);
    ck_assert_int_eq(pds_run(s, 100, NULL), 1);
    pds_destroy(s);

    s = sampler_new(0.05, 5); /* after failures (a message may be held) */
    ck_assert_int_eq(pds_step(s), 1);
    ck_assert_int_eq(pds_refine(s, 1.0), PDS_EINVAL);
    ck_assert_int_eq(pds_set_domain(s, 0, 0, 2, 2), PDS_ESTATE);
    ck_assert_int_eq(pds_refine(s, 1e-9), PDS_ERANGE);
    ck_assert_ptr_nonnull(pds_errmsg(s));
    pds_destroy(s);

    s = sampler_new(0.05, 6); /* maximal and verified */
    run_to_end(s);
    ck_assert_int_eq(pds_verify(s), 0);
    pds_destroy(s);
}
END_TEST

START_TEST(failed_create_leaves_nothing)
{
    /* Also a radius too small for the domain: created (1.1.1), refused at the
     * first point, then destroyed; under Valgrind nothing may leak. */
    size_t i, added, cycles = pick(200, 20);

    for (i = 0; i < cycles; i++) {
        pds_sampler *s = NULL;
        ck_assert_int_eq(pds_create(&s, -1.0, (uint64_t)i), PDS_EINVAL);
        ck_assert_ptr_null(s);
        pds_destroy(s);
        ck_assert_int_eq(pds_create(&s, 1e-9, (uint64_t)i), 0);
        ck_assert_int_eq(pds_run(s, 0, &added), PDS_ERANGE);
        ck_assert_int_eq(pds_step(s), PDS_ERANGE);
        ck_assert_uint_eq(pds_count(s), 0);
        pds_destroy(s);
    }
}
END_TEST

Suite *lifecycle_suite(void)
{
    Suite *suite = suite_create("lifecycle");
    TCase *tc;

    tc = new_tcase(suite, "create_destroy_cycles");
    tcase_add_test(tc, create_destroy_cycles);
    tc = new_tcase(suite, "destroy_in_every_state");
    tcase_add_test(tc, destroy_in_every_state);
    tc = new_tcase(suite, "failed_create");
    tcase_add_test(tc, failed_create_leaves_nothing);
    return suite;
}
