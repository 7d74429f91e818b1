/*
 * main.c - runs every public-API suite; exit status non-zero on any failure.
 *
 * Built by the Makefile into build/tests/api against build/libpoissondisk.so.
 * Env: CK_FORK=no runs in one process (for Valgrind); PDS_TEST_LIGHT=1 shrinks
 * the heavy loops (see test_light() in helpers.c); CK_RUN_SUITE / CK_RUN_CASE
 * select one suite / TCase by name.
 */
#include <stdio.h>
#include <stdlib.h>

#include "helpers.h"
#include "suites.h"

int main(void)
{
    SRunner *runner = srunner_create(codes_suite());
    int failed;

    srunner_add_suite(runner, args_suite());
    srunner_add_suite(runner, state_suite());
    srunner_add_suite(runner, semantics_suite());
    srunner_add_suite(runner, determinism_suite());
    srunner_add_suite(runner, properties_suite());
    srunner_add_suite(runner, lifecycle_suite());
    srunner_add_suite(runner, golden_suite());
    srunner_add_suite(runner, splits_suite());
    srunner_add_suite(runner, limits_suite());
    srunner_add_suite(runner, slivers_suite());
    srunner_add_suite(runner, count_suite());
    srunner_add_suite(runner, progress_suite());
    srunner_add_suite(runner, periodic_suite());
    srunner_add_suite(runner, field_suite());
    srunner_add_suite(runner, field_range_suite());
    srunner_add_suite(runner, messages_suite());
    srunner_add_suite(runner, documented_suite());
    srunner_add_suite(runner, field_bound_suite());
    srunner_add_suite(runner, domain_args_suite());
    srunner_add_suite(runner, domain_points_suite());
    srunner_add_suite(runner, domain_raster_suite());
    srunner_add_suite(runner, domain_law_suite());
    srunner_add_suite(runner, domain_fixed_suite());
    srunner_add_suite(runner, domain_fixed_edges_suite());
    srunner_add_suite(runner, domain_fixed_count_suite());
    srunner_add_suite(runner, threads_suite());

    if (test_light())
        printf("PDS_TEST_LIGHT is set: heavy loops shrunk, calibration skipped\n");
    srunner_run_all(runner, CK_NORMAL);
    failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
