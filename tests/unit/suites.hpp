// suites.hpp - the internal unit suites (one per file) and small shared helpers.
#ifndef PDS_TEST_SUITES_HPP
#define PDS_TEST_SUITES_HPP

#include <check.h>

#include <cstdlib>

Suite* expansion_suite();
Suite* predicates_suite();
Suite* quadedge_suite();
Suite* delaunay_suite();
Suite* delaunay_build_suite();
Suite* delaunay_sides_suite();
Suite* regular_suite();
Suite* angle_suite();
Suite* tree_suite();
Suite* hash_map_suite();
Suite* free_area_suite();
Suite* power_cells_suite();
Suite* verify_suite();
Suite* outline_filter_suite();
Suite* verify_field_suite();
Suite* dart_stage_suite();
Suite* field_dart_stage_suite();
Suite* curve_order_suite();
Suite* space_time_stage_suite();
Suite* space_time_polygon_suite();
Suite* space_time_torus_suite();
Suite* space_time_fixed_suite();
Suite* dart_stage_fixed_suite();
Suite* worker_pool_suite();
Suite* ring_prefetcher_suite();
Suite* active_scan_suite();
Suite* time_order_suite();
Suite* room_growth_suite();
Suite* poisson_gaps_suite();
Suite* region_darts_suite();
Suite* side_insertions_suite();
Suite* sampler_suite();
Suite* law_suite();
Suite* law_torus_suite();
Suite* law_comb_suite();
Suite* field_suite();
Suite* out_of_memory_suite();
Suite* torus_suite();
Suite* rectangle_suite();
Suite* free_room_suite();
Suite* progress_suite();
Suite* polygon_suite();
Suite* polygon_domain_suite();
Suite* polygon_slabs_suite();
Suite* polygon_crossings_suite();
Suite* polygon_raster_suite();
Suite* outline_clip_suite();
Suite* fixed_points_suite();

// Under Valgrind (PDS_TEST_LIGHT set) loops shrink; every behaviour still runs.
inline bool test_light() { return std::getenv("PDS_TEST_LIGHT") != nullptr; }

#endif
