/*
 * shapes.c - polygons the domain suites share; see region.h.
 */
#include "region.h"

/* The outer ring counter-clockwise, the hole clockwise (either is allowed). */
static const double unit_l_xy[] = {
    0.0, 0.0, 1.0, 0.0, 1.0, 0.4, 0.4, 0.4, 0.4, 1.0, 0.0, 1.0,
    0.1, 0.1, 0.1, 0.25, 0.25, 0.25, 0.25, 0.1,
};
static const size_t unit_l_ends[] = {6, 10};

const region UNIT_L = {unit_l_xy, unit_l_ends, 2};
