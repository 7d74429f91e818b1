// verify.cpp - the certificate described in verify.hpp.
#include "verify/verify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/expansion.hpp"
#include "core/circumcentre.hpp"
#include "verify/outline_filter.hpp"
#include "verify/verify_outline.hpp"
#include "mesh/mesh_invariants.hpp"
#include "core/roundoff.hpp"
#include "core/predicates.hpp"
#include "verify/radius_layers.hpp"
#include "verify/spatial_hash.hpp"
#include "domain/rectangle.hpp"

namespace pds {

namespace {

using E = Expansion;

// A variable radius: each point outside every earlier point's disk, by that
// disk's radius (rank: the order the points were added). The radii classes
// find each pair that could break it from the side of its smaller radius.
bool check_rule(const Delaunay& dt, const std::vector<std::size_t>& rank, std::size_t fixed, VerifyReport& rep) {
    const std::vector<Point>& pts = dt.points();
    for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
        if (!RadiusLayers::usable(dt.radius(static_cast<VertexIndex>(i)))) {
            rep.failure = "a point's radius is not a positive finite number";
            rep.vertex = static_cast<VertexIndex>(i);
            return false;
        }
    }
    const RadiusLayers layers(pts, Delaunay::kGhosts,
                              [&](std::size_t v) { return dt.radius(static_cast<VertexIndex>(v)); });
    for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
        const double ri = dt.radius(static_cast<VertexIndex>(i));
        VertexIndex inside = kNoVertex;  // the later point of a pair that breaks the rule
        layers.for_each_near(pts[i], ri, [&](std::uint32_t j, int, int, bool same) {
            if (j == i || inside != kNoVertex) return;
            if (rank[i] < fixed && rank[j] < fixed) return;  // two fixed points may overlap
            ++rep.pairs_examined;
            const bool j_first = rank[j] < rank[i];
            if (same && !j_first) return;  // j's own visit checks this pair
            if (compare_distance(pts[i], pts[j], j_first ? dt.radius(j) : ri) < 0)
                inside = static_cast<VertexIndex>(j_first ? i : j);
        });
        if (inside != kNoVertex) {
            rep.failure = "a point lies inside an earlier point's disk";
            rep.vertex = inside;
            return false;
        }
    }
    return true;
}

bool check_points(const Delaunay& dt, const Rectangle& domain, double r, const std::vector<std::size_t>* rank,
                  const Polygon* polygon, std::size_t fixed, VerifyReport& rep) {
    const std::vector<Point>& pts = dt.points();
    const Box& box = domain.bounds();
    for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
        // A fixed point may lie in a hole or outside the outline (an obstacle).
        const bool is_fixed = rank && (*rank)[i] < fixed;
        if (!domain.contains(pts[i]) || (polygon && !is_fixed && !polygon->contains(pts[i]))) {
            rep.failure = "a point lies outside the domain";
            rep.vertex = static_cast<VertexIndex>(i);
            return false;
        }
    }
    if (rank) return check_rule(dt, *rank, fixed, rep);
    const SpatialHash grid(pts, Delaunay::kGhosts, box, r);
    for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
        bool close = false;
        grid.for_each_near(pts[i], [&](std::uint32_t j, int, int) {
            ++rep.pairs_examined;
            if (j < i && compare_distance(pts[i], pts[j], r) < 0) close = true;
        });
        if (close) {
            rep.failure = "two points are closer than the radius";
            rep.vertex = static_cast<VertexIndex>(i);
            return false;
        }
    }
    return true;
}

bool check_mesh(const Delaunay& dt, VerifyReport& rep) {
    const MeshReport mesh = check_mesh_invariants(dt);
    if (!mesh.ok) rep.failure = mesh.failure;
    return mesh.ok;
}

// ---- maximality: Voronoi vertices ----------------------------------------------

// True when the circumcentre of the CCW triangle (a, b, c) lies in the closed box
// and is farther than r from the corners (an uncovered Voronoi vertex).
// Weighted: the power centre, uncovered when its power (the same to all three
// disks) is positive.
bool uncovered_vertex(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                      const Box& box) {
    const ExactCentre centre = exact_power_centre(a, ra, b, rb, c, rc);
    const E& den = centre.den;  // > 0
    // centre = a + (nx, ny) / den; inside the box iff x0*den <= a.x*den + nx <= x1*den.
    const auto within = [&](double lo, double at, double hi, const E& n) {
        const E pos = n + den.scaled(at);
        return (pos - den.scaled(lo)).sign() >= 0 && (den.scaled(hi) - pos).sign() >= 0;
    };
    if (!within(box.x0, a.x, box.x1, centre.nx) || !within(box.y0, a.y, box.y1, centre.ny)) return false;
    const E rr = E::product(ra, ra);
    return (centre.nx * centre.nx + centre.ny * centre.ny - rr * den * den).sign() > 0;
}

// The power centre of the disks lies in the closed polygon, exactly.
bool vertex_in_polygon(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                       const Polygon& polygon) {
    const ExactCentre centre = exact_power_centre(a, ra, b, rb, c, rc);
    return polygon.contains_exact(centre.nx + centre.den.scaled(a.x), centre.ny + centre.den.scaled(a.y), centre.den);
}

// Float filter for uncovered_vertex: 1 certainly uncovered, 0 certainly not,
// -1 undecided. at, err (if given): the vertex and its error bound, err < 0
// when it was too flat to bound.
int uncovered_vertex_fast(const Point& a, double r, const Point& b, double rb_, const Point& c, double rc_,
                          const Box& box, Point* at = nullptr, double* err_out = nullptr) {
    if (err_out) *err_out = -1.0;
    const Point rb{b.x - a.x, b.y - a.y}, rd{c.x - a.x, c.y - a.y};
    if (!(rb.x * rd.y - rb.y * rd.x > 0.0)) return -1;  // too flat to bound: decide exactly
    const RelativeCentre centre = relative_power_centre(rb, rd, (r - rb_) * (r + rb_), (r - rc_) * (r + rc_));
    const double vx = centre.x, vy = centre.y;
    // The vertex's own bound, plus the rounding of moving it back to a's frame.
    const double err = centre.err + 8.0 * kUnitRoundoff * (std::fabs(a.x) + std::fabs(a.y) + std::fabs(vx) + std::fabs(vy));
    const double cx = a.x + vx, cy = a.y + vy;
    if (at && err_out) {
        *at = Point{cx, cy};
        *err_out = err;
    }
    const auto side = [&](double v, double lo, double hi) {
        if (v < lo - err || v > hi + err) return 0;  // certainly outside
        if (v > lo + err && v < hi - err) return 1;  // certainly inside
        return -1;
    };
    const int in_x = side(cx, box.x0, box.x1), in_y = side(cy, box.y0, box.y1);
    if (in_x == 0 || in_y == 0) return 0;
    const double d2 = centre.d2, r2 = r * r;
    const double margin = 2.0 * r * err + err * err + 8.0 * kUnitRoundoff * r2;
    if (d2 < r2 - margin) return 0;
    if (in_x == 1 && in_y == 1 && d2 > r2 + margin) return 1;
    return -1;
}

bool voronoi_vertices_covered(const Delaunay& dt, const Box& box, double r, const Polygon* polygon,
                              VerifyReport& rep) {
    const auto rad = [&](VertexIndex v) { return dt.weighted() ? dt.radius(v) : r; };
    const QuadEdgeMesh& m = dt.mesh();
    std::optional<PolygonClearance> clearance;
    if (polygon) clearance.emplace(*polygon);
    for (std::size_t rec = 0; rec < m.record_count(); ++rec) {
        if (!m.is_live(rec)) continue;
        for (std::uint32_t k = 0; k < 4; k += 2) {
            const EdgeRef e = static_cast<EdgeRef>(4 * rec + k);
            const EdgeRef f = m.lnext(e), g = m.lnext(f);
            if (m.lnext(g) != e) continue;  // the outer face
            // Visit each triangle once: from its edge with the smallest reference.
            if (e > f || e > g) continue;
            const Point& a = dt.point(m.org(e));
            const Point& b = dt.point(m.org(f));
            const Point& c = dt.point(m.org(g));
            const double ra = rad(m.org(e)), rb = rad(m.org(f)), rc = rad(m.org(g));
            Point at{0.0, 0.0};
            double err = -1.0;
            int u = uncovered_vertex_fast(a, ra, b, rb, c, rc, box, &at, &err);
            if (u < 0) u = uncovered_vertex(a, ra, b, rb, c, rc, box) ? 1 : 0;
            // Outside the polygon, most such vertices are certainly so in floating point.
            if (u == 1 && polygon && ((err >= 0.0 && clearance->certainly_outside(at, err)) ||
                                      !vertex_in_polygon(a, ra, b, rb, c, rc, *polygon)))
                u = 0;
            if (u == 1) {
                rep.failure = dt.weighted() ? "a power-diagram vertex inside the domain lies outside its disks"
                                            : "a Voronoi vertex inside the domain is farther than R from its sites";
                return false;
            }
        }
    }
    return true;
}

// ---- maximality: the sides of the domain -------------------------------------------

bool sides_covered(const Delaunay& dt, const Rectangle& domain, double r, VerifyReport& rep) {
    // The domain type certifies its own boundary.
    if (const char* side = domain.uncovered_side(dt, r)) {
        rep.failure = std::string("the ") + side + " side of the domain is not covered";
        return false;
    }
    return true;
}

bool outline_covered(const Delaunay& dt, const Polygon& polygon, double r, VerifyReport& rep) {
    const VertexIndex v = uncovered_outline_cell(dt, polygon, r);
    if (v == kNoVertex) return true;
    rep.failure = "a point of the domain near its outline lies outside every disk";
    rep.vertex = v;
    return false;
}

}  // namespace

bool voronoi_vertex_uncovered(const Point& a, const Point& b, const Point& c, const Box& box, double r) {
    const int u = uncovered_vertex_fast(a, r, b, r, c, r, box);
    return u < 0 ? uncovered_vertex(a, r, b, r, c, r, box) : u == 1;
}

bool power_vertex_uncovered(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc,
                            const Box& box) {
    const int u = uncovered_vertex_fast(a, ra, b, rb, c, rc, box);
    return u < 0 ? uncovered_vertex(a, ra, b, rb, c, rc, box) : u == 1;
}

bool mesh_consistent(const Delaunay& dt, VerifyReport& rep) { return check_mesh(dt, rep); }

void name_point(VerifyReport& rep, PointIndex k) {
    rep.failure += " (point " + std::to_string(k) + ")";
}

VerifyReport verify_pattern(const Delaunay& dt, const Rectangle& domain, double radius,
                            const std::vector<std::size_t>* rank, const Polygon* polygon, std::size_t fixed) {
    VerifyReport rep;
    if (!check_points(dt, domain, radius, rank, polygon, fixed, rep) || !check_mesh(dt, rep)) {
        rep.valid = false;
        return rep;
    }
    VerifyReport gap;
    rep.maximal = dt.vertex_count() > Delaunay::kGhosts &&
                  voronoi_vertices_covered(dt, domain.bounds(), radius, polygon, gap) &&
                  (polygon ? outline_covered(dt, *polygon, radius, gap) : sides_covered(dt, domain, radius, gap));
    if (!rep.maximal) rep.failure = gap.failure.empty() ? "no points yet" : gap.failure;
    return rep;
}

}  // namespace pds
