// verify.cpp - the certificate described in verify.hpp.
#include "verify/verify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/expansion.hpp"
#include "core/circumcentre.hpp"
#include "mesh/mesh_invariants.hpp"
#include "core/roundoff.hpp"
#include "core/predicates.hpp"
#include "verify/radius_layers.hpp"
#include "verify/spatial_hash.hpp"

namespace pds {

namespace {

using E = Expansion;

// A variable radius: each point outside every earlier point's disk, by that
// disk's radius (rank: the order the points were added). The radii classes
// find each pair that could break it from the side of its smaller radius.
bool check_rule(const Delaunay& dt, const std::vector<std::size_t>& rank, VerifyReport& rep) {
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

bool check_points(const Delaunay& dt, const Box& box, double r, const std::vector<std::size_t>* rank,
                  VerifyReport& rep) {
    const std::vector<Point>& pts = dt.points();
    for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
        if (!box.contains(pts[i])) {
            rep.failure = "a point lies outside the domain";
            rep.vertex = static_cast<VertexIndex>(i);
            return false;
        }
    }
    if (rank) return check_rule(dt, *rank, rep);
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

// Float filter for uncovered_vertex: 1 certainly uncovered, 0 certainly not,
// -1 undecided.
int uncovered_vertex_fast(const Point& a, double r, const Point& b, double rb_, const Point& c, double rc_,
                          const Box& box) {
    const Point rb{b.x - a.x, b.y - a.y}, rd{c.x - a.x, c.y - a.y};
    if (!(rb.x * rd.y - rb.y * rd.x > 0.0)) return -1;  // too flat to bound: decide exactly
    const RelativeCentre centre = relative_power_centre(rb, rd, (r - rb_) * (r + rb_), (r - rc_) * (r + rc_));
    const double vx = centre.x, vy = centre.y;
    // The vertex's own bound, plus the rounding of moving it back to a's frame.
    const double err = centre.err + 8.0 * kUnitRoundoff * (std::fabs(a.x) + std::fabs(a.y) + std::fabs(vx) + std::fabs(vy));
    const double cx = a.x + vx, cy = a.y + vy;
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

bool voronoi_vertices_covered(const Delaunay& dt, const Box& box, double r, VerifyReport& rep) {
    const auto rad = [&](VertexIndex v) { return dt.weighted() ? dt.radius(v) : r; };
    const QuadEdgeMesh& m = dt.mesh();
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
            int u = uncovered_vertex_fast(a, ra, b, rb, c, rc, box);
            if (u < 0) u = uncovered_vertex(a, ra, b, rb, c, rc, box) ? 1 : 0;
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

// A site seen from a side of the domain: position along the side, exact
// squared distance to the side's line.
struct SideSite {
    double along;
    E h2;
    E c;   // along^2 + h2 - r^2: the constant of the line g(x) = -2 along x + c
    E r2;  // the disk's squared radius
};

// x where the lines of sites i < j (by `along`) meet: (cj - ci) / (2 (aj - ai)).
Rational meeting_point(const SideSite& i, const SideSite& j) {
    return make_rational(j.c - i.c, E::diff(j.along, i.along).scaled(2.0));
}

// (x - along)^2 + h2 <= r^2 at x = num/den (den > 0).
bool covers_at(const SideSite& s, const Rational& x) {
    const E diff = x.num - x.den.scaled(s.along);
    const E den2 = x.den * x.den;
    return (s.r2 * den2 - diff * diff - s.h2 * den2).sign() >= 0;
}

// Is the segment [lo, hi] of a side covered by the disks of `sites`?
bool side_covered(std::vector<SideSite>& sites, double lo, double hi) {
    if (sites.empty()) return false;
    std::sort(sites.begin(), sites.end(), [](const SideSite& a, const SideSite& b) {
        if (a.along != b.along) return a.along < b.along;
        return (a.c - b.c).sign() < 0;
    });
    // Lower envelope of the lines g_i (the least power along the side: x^2
    // plus the line), by increasing position; a line is dropped when its
    // neighbours meet before it would appear.
    std::vector<const SideSite*> env;
    for (const SideSite& s : sites) {
        if (!env.empty() && env.back()->along == s.along) continue;  // same position, farther
        while (env.size() >= 2 &&
               compare(meeting_point(*env[env.size() - 2], *env.back()),
                       meeting_point(*env.back(), s)) >= 0)
            env.pop_back();
        env.push_back(&s);
    }
    // On each envelope piece the power is convex, so checking the
    // piece's ends (clipped to [lo, hi]) decides it.
    const Rational lo_r = make_rational(E(lo), E(1.0)), hi_r = make_rational(E(hi), E(1.0));
    for (std::size_t k = 0; k < env.size(); ++k) {
        Rational a = lo_r, b = hi_r;
        if (k > 0) {
            const Rational m = meeting_point(*env[k - 1], *env[k]);
            if (compare(m, a) > 0) a = m;
        }
        if (k + 1 < env.size()) {
            const Rational m = meeting_point(*env[k], *env[k + 1]);
            if (compare(m, b) < 0) b = m;
        }
        if (compare(a, b) > 0) continue;  // this piece lies outside [lo, hi]
        if (!covers_at(*env[k], a) || !covers_at(*env[k], b)) return false;
    }
    return true;
}

bool sides_covered(const Delaunay& dt, const Box& box, double r, VerifyReport& rep) {
    const std::vector<Point>& pts = dt.points();
    // For each side: the coordinate along it, and the line's fixed coordinate.
    struct Side {
        bool horizontal;
        double line, lo, hi;
        const char* name;
    };
    const Side sides[4] = {{true, box.y0, box.x0, box.x1, "bottom"},
                           {true, box.y1, box.x0, box.x1, "top"},
                           {false, box.x0, box.y0, box.y1, "left"},
                           {false, box.x1, box.y0, box.y1, "right"}};
    for (const Side& side : sides) {
        std::vector<SideSite> near;
        for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
            const double across = side.horizontal ? pts[i].y : pts[i].x;
            const double ri = dt.weighted() ? dt.radius(static_cast<VertexIndex>(i)) : r;
            if (std::fabs(across - side.line) > 2.0 * ri) continue;  // cheap prefilter
            const E h = E::diff(across, side.line);
            E h2 = h * h;
            E r2 = E::product(ri, ri);
            if ((h2 - r2).sign() > 0) continue;  // cannot reach the side
            const double along = side.horizontal ? pts[i].x : pts[i].y;
            E c = E::product(along, along) + h2 - r2;
            near.push_back(SideSite{along, std::move(h2), std::move(c), std::move(r2)});
        }
        if (!side_covered(near, side.lo, side.hi)) {
            rep.failure = std::string("the ") + side.name + " side of the domain is not covered";
            return false;
        }
    }
    return true;
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

VerifyReport verify_pattern(const Delaunay& dt, const Box& domain, double radius,
                            const std::vector<std::size_t>* rank) {
    VerifyReport rep;
    if (!check_points(dt, domain, radius, rank, rep) || !check_mesh(dt, rep)) {
        rep.valid = false;
        return rep;
    }
    VerifyReport gap;
    rep.maximal = dt.vertex_count() > Delaunay::kGhosts &&
                  voronoi_vertices_covered(dt, domain, radius, gap) &&
                  sides_covered(dt, domain, radius, gap);
    if (!rep.maximal) rep.failure = gap.failure.empty() ? "no points yet" : gap.failure;
    return rep;
}

}  // namespace pds
