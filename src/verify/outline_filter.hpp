// outline_filter.hpp - a floating-point filter in front of the verifier's
// exact test of a cell the outline may cut (verify_outline.cpp,
// polygon_coverage.hpp).
//
// The exact test works on expansions and takes tens of microseconds a cell;
// in a thin or ragged domain nearly every cell is cut, and verifying took
// thirty times as long as sampling. The filter decides the same question in
// doubles with error bounds, and answers only "certainly covered" or "not
// certain"; the exact test decides the rest.
//
// What it checks, a superset of the exact test's points (so whatever it
// certifies, the exact test would too):
//   - every vertex of the site's power cell clipped to the domain's box (the
//     cell pipeline's, with their error bounds) lies certainly within the
//     radius, or certainly where the polygon holds no point (outside its
//     box, in clean outside cells of its grid, or in a square no edge
//     meets around a point the polygon does not hold);
//   - for every outline edge near the cell, the part of it inside the cell
//     (the edge clipped by the cell's bisectors, each bound widened by its
//     error) has both ends certainly within the radius: distance is convex
//     along the edge, so the whole part is.
#ifndef PDS_OUTLINE_FILTER_HPP
#define PDS_OUTLINE_FILTER_HPP

#include <cstdint>
#include <vector>

#include "cells/cell_stream.hpp"
#include "core/point.hpp"
#include "domain/polygon.hpp"

namespace pds {

// Whether a polygon certainly holds no point near a given one, in floating
// point: for points known to within an error bound (a Voronoi vertex, say).
class PolygonClearance {
public:
    explicit PolygonClearance(const Polygon& polygon) : polygon_(polygon) {}
    // True when the polygon certainly holds no point within e of q: q is
    // outside its box, in clean outside cells of its grid, or in a square no
    // edge meets around it that the polygon does not hold. False: not certain.
    bool certainly_outside(const Point& q, double e);

private:
    const Polygon& polygon_;
    std::vector<std::uint32_t> near_;  // scratch: the edges near q
};

// One cell at a time, relative to its site c with radius rc: ring[k] are
// its Delaunay (regular) neighbours with radii ring_radii[k].
class OutlineFilter {
public:
    explicit OutlineFilter(const Polygon& polygon) : polygon_(polygon), clearance_(polygon) {}
    void begin_cell(const Point& c, double rc) {
        c_ = c;
        rc_ = rc;
        vertices_certain_ = true;
    }

    // A vertex of the clipped cell (relative to c): false once one is not
    // certainly harmless.
    void vertex(const cell_stream::Vtx& v);
    bool vertices_certain() const { return vertices_certain_; }

    // The outline edges near the cell: whether each one's part inside the
    // cell is certainly within the radius.
    bool edges_certain(const std::vector<Point>& ring, const std::vector<double>& ring_radii,
                       const std::vector<std::uint32_t>& edges) const;

private:
    // Whether the point p (relative to c) with error e is certainly within rc.
    bool certainly_within(double px, double py, double e) const;

    const Polygon& polygon_;
    PolygonClearance clearance_;
    Point c_{0.0, 0.0};
    double rc_ = 0.0;
    bool vertices_certain_ = true;
};

}  // namespace pds

#endif
