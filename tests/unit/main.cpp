// main.cpp - runs every internal unit suite; exit status non-zero on any failure.
#include <cstdlib>

#include "suites.hpp"

int main() {
    // Every case's hang guard: 60 s, not Check's 4 s, which is too tight
    // for a 2-core machine busy with other jobs (or Valgrind); only cases
    // that need longer set their own. A value in the environment wins.
    setenv("CK_DEFAULT_TIMEOUT", "60", 0);
    SRunner* runner = srunner_create(expansion_suite());
    srunner_add_suite(runner, predicates_suite());
    srunner_add_suite(runner, quadedge_suite());
    srunner_add_suite(runner, delaunay_suite());
    srunner_add_suite(runner, delaunay_build_suite());
    srunner_add_suite(runner, delaunay_sides_suite());
    srunner_add_suite(runner, regular_suite());
    srunner_add_suite(runner, angle_suite());
    srunner_add_suite(runner, tree_suite());
    srunner_add_suite(runner, hash_map_suite());
    srunner_add_suite(runner, free_area_suite());
    srunner_add_suite(runner, power_cells_suite());
    srunner_add_suite(runner, verify_suite());
    srunner_add_suite(runner, outline_filter_suite());
    srunner_add_suite(runner, verify_field_suite());
    srunner_add_suite(runner, dart_stage_suite());
    srunner_add_suite(runner, field_dart_stage_suite());
    srunner_add_suite(runner, curve_order_suite());
    srunner_add_suite(runner, worker_pool_suite());
    srunner_add_suite(runner, ring_prefetcher_suite());
    srunner_add_suite(runner, active_scan_suite());
    srunner_add_suite(runner, time_order_suite());
    srunner_add_suite(runner, room_growth_suite());
    srunner_add_suite(runner, space_time_stage_suite());
    srunner_add_suite(runner, space_time_polygon_suite());
    srunner_add_suite(runner, space_time_torus_suite());
    srunner_add_suite(runner, space_time_fixed_suite());
    srunner_add_suite(runner, dart_stage_fixed_suite());
    srunner_add_suite(runner, poisson_gaps_suite());
    srunner_add_suite(runner, region_darts_suite());
    srunner_add_suite(runner, side_insertions_suite());
    srunner_add_suite(runner, sampler_suite());
    srunner_add_suite(runner, law_suite());
    srunner_add_suite(runner, law_torus_suite());
    srunner_add_suite(runner, law_comb_suite());
    srunner_add_suite(runner, field_suite());
    srunner_add_suite(runner, out_of_memory_suite());
    srunner_add_suite(runner, torus_suite());
    srunner_add_suite(runner, rectangle_suite());
    srunner_add_suite(runner, free_room_suite());
    srunner_add_suite(runner, progress_suite());
    srunner_add_suite(runner, polygon_suite());
    srunner_add_suite(runner, polygon_domain_suite());
    srunner_add_suite(runner, polygon_slabs_suite());
    srunner_add_suite(runner, polygon_crossings_suite());
    srunner_add_suite(runner, polygon_raster_suite());
    srunner_add_suite(runner, outline_clip_suite());
    srunner_add_suite(runner, fixed_points_suite());
    srunner_run_all(runner, CK_NORMAL);
    const int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
