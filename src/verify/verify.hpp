// verify.hpp - an independent certificate for a pattern.
//
// Re-derives everything the sampler promises, from the points and the mesh
// only (not from the free areas or the tree), with exact arithmetic:
//   - every point inside the domain, every pair at least R apart (through a
//     spatial hash, so the check does not trust the triangulation);
//   - the quad-edge mesh consistent, its faces counterclockwise triangles, and
//     every edge locally Delaunay (hence the mesh is the Delaunay triangulation);
//   - maximality: every Voronoi vertex (triangle circumcentre) inside the domain
//     within R of its sites, and every side of the domain covered by the disks
//     (decided on the lower envelope of the distance parabolas along the side,
//     independently of the mesh).
// O(N) expected time for the first three (with a variable radius, a constant
// times the radii's binary orders of magnitude a point: radius_layers.hpp),
// O(N + S log S) for maximality with S the points within R of a side. May
// allocate; never called mid-mutation.
#ifndef PDS_VERIFY_HPP
#define PDS_VERIFY_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/delaunay.hpp"
#include "core/indices.hpp"
#include "core/point.hpp"
#include "domain/polygon.hpp"
#include "domain/rectangle.hpp"

namespace pds {

struct VerifyReport {
    bool valid = true;     // false: a guarantee is broken (the text says which)
    bool maximal = false;  // meaningful when valid
    std::string failure;
    // The mesh vertex a failure is about, if any: the caller names it in the
    // user's point order (indices.hpp), which only it knows.
    VertexIndex vertex = kNoVertex;
    // The candidate pairs the spacing check examined (each a distance test or
    // less): the measure of its work, which tests bound.
    std::uint64_t pairs_examined = 0;
};

// Checks the pattern of dt's real vertices. A failure about one point sets
// rep.vertex; the caller maps it to the user's order and calls name_point.
// A weighted mesh (a variable radius): radius is the largest, rank[v] is
// vertex v's place in the order the points were added (the spacing rule
// depends on it), and maximality is judged on the power diagram.
// polygon: a polygonal domain inside the rectangle (verify_outline.cpp): points
// must lie in it, and maximality is judged in it.
// fixed: on a weighted mesh, the points of rank below it are fixed points,
// whose disks are not checked against each other.
VerifyReport verify_pattern(const Delaunay& dt, const Rectangle& domain, double radius,
                            const std::vector<std::size_t>* rank = nullptr, const Polygon* polygon = nullptr,
                            std::size_t fixed = 0);
// Exact: the circumcentre of the counterclockwise triangle (a, b, c) lies in
// the closed box and farther than r from the corners.
bool voronoi_vertex_uncovered(const Point& a, const Point& b, const Point& c, const Box& box, double r);
// The same for the power centre of the disks (a, ra), (b, rb), (c, rc): in
// the box and of positive power (outside the three disks).
bool power_vertex_uncovered(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                            const Box& box);
// The quad-edge mesh consistent and Delaunay (else rep.failure says why).
bool mesh_consistent(const Delaunay& dt, VerifyReport& rep);
// Appends " (point k)" to the failure: k in the user's order.
void name_point(VerifyReport& rep, PointIndex k);

}  // namespace pds

#endif
