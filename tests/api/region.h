/*
 * region.h - an independent model of the sampling domains of 1.4 (polygons
 * with holes, fixed points with clearances) for the public-API tests, sharing
 * nothing with the library: plain floating point, its own bucket grid.
 *
 *   region.c     the closed polygon by the even-odd rule, and a grid of disks
 *   coverage.c   maximality: is every point of the polygon in some disk?
 *   saturate.c   the reference sampler: dart throwing run to saturation
 *   shapes.c     polygons the domain suites share
 *
 * A "disk" is a sampled point with its radius or a fixed point with its
 * clearance; the covered set is the union of the closed disks.
 */
#ifndef PDS_TESTS_API_REGION_H
#define PDS_TESTS_API_REGION_H

#include <stddef.h>
#include <stdint.h>

/* Rings by the even-odd rule: ring k is vertices ends[k-1] .. ends[k]-1. */
typedef struct region {
    const double *xy;
    const size_t *ends;
    size_t nrings;
} region;

typedef struct disk {
    double x, y, r;
} disk;

/* The vertex count and the bounding box [b[0],b[2]] x [b[1],b[3]]. */
size_t region_vertices(const region *g);
void region_bounds(const region *g, double b[4]);

/* Edge e (0 .. vertices-1): from vertex e to the next vertex of its ring. */
void region_edge(const region *g, size_t e, double *ax, double *ay, double *bx, double *by);

/* The least distance from (x, y) to the outline. */
double region_outline_distance(const region *g, double x, double y);

/*
 * (x, y) lies in the closed polygon: an odd number of crossings of a ray to
 * +x, or within 1e-12 of the bounding box's size of the outline (a point the
 * library placed on the outline may round to either side here).
 */
int region_contains(const region *g, double x, double y);

/* The polygon's even-odd area for rings that do not cross: each ring's
 * shoelace area, negative when its first vertex lies in an odd number of the
 * other rings. */
double region_area(const region *g);

/*
 * A grid of disks over a box: each disk is listed in every cell its bounding
 * square overlaps, so a point's cell lists every disk that may hold it,
 * however large (a clearance wider than the box).
 */
typedef struct disk_grid {
    double x0, y0, cell;
    size_t nx, ny;
    size_t *len, *cap;
    size_t **items;
    disk *d;
    size_t n, dcap;
} disk_grid;

void grid_init(disk_grid *G, const double box[4], double cell);
void grid_free(disk_grid *G);
/* Appends a disk (index G->n before the call). */
void grid_add(disk_grid *G, disk d);
/* The cell of (x, y), clamped into the grid. */
size_t grid_cell(const disk_grid *G, double x, double y);
/* Some disk other than skip1 and skip2 (-1: none) holds (x, y): distance
 * at most r (1 + tol). */
int grid_covers(const disk_grid *G, double x, double y, long skip1, long skip2, double tol);
/* Some disk holds (x, y) strictly inside: distance below r (1 - shrink). */
int grid_strictly_inside(const disk_grid *G, double x, double y, double shrink);

/*
 * The closed polygon lies in the union of the closed disks (coverage.c).
 * Returns 1, or 0 and a witness in why (a vertex of the arrangement of the
 * outline and the circles that no other disk covers, within a relative tol).
 */
int region_covered(const region *g, const disk *d, size_t n, double tol, char *why,
                   size_t whylen);

/* splitmix64: the reference sampler's generator (not the library's). */
uint64_t ref_next(uint64_t *state);
double ref_uniform(uint64_t *state); /* in [0, 1) */

/*
 * Random sequential adsorption in the polygon, run to saturation
 * (saturate.c): every new point uniform over the polygon minus the open
 * disks of radius r of the points so far and of the fixed disks. Returns the
 * count and the points in a malloc'd array (*xy, free it).
 */
size_t saturate(const region *g, double r, const disk *fixed, size_t nfixed, uint64_t seed,
                double **xy);

/*
 * Shapes shared by the domain suites (shapes.c). UNIT_L: an L in the unit
 * square (its bounding box), the foot [0,1]x[0,0.4] and the leg
 * [0,0.4]x[0.4,1], with a square hole [0.1,0.25]^2 in the corner; area
 * 0.6175. The law test samples it at R = 0.1 (about 50 points).
 */
extern const region UNIT_L;
#define UNIT_L_AREA 0.6175

#endif /* PDS_TESTS_API_REGION_H */
