// verify_torus.cpp - the periodic certificate (see verify_torus.hpp).
#include "verify/verify_torus.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/predicates.hpp"
#include "verify/radius_layers.hpp"
#include "verify/spatial_hash.hpp"

namespace pds {

namespace {

bool point_less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
bool point_equal(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }


bool check_real_points(const Delaunay& dt, const Torus& t, const std::vector<VertexIndex>& real,
                       VerifyReport& rep) {
    for (VertexIndex v : real) {
        const Point& p = dt.point(v);
        const bool inside = p.x >= t.x0 && p.x - t.px < t.x0 && p.y >= t.y0 && p.y - t.py < t.y0;
        const bool on_grid = Torus::snap(p.x) == p.x && Torus::snap(p.y) == p.y;
        if (!inside || !on_grid) {
            rep.failure = inside ? "a point is off the torus grid" : "a point lies outside the fundamental domain";
            rep.vertex = v;
            return false;
        }
    }
    return true;
}

// A variable radius: each point outside every copy of every earlier point's
// disk (rank: the order the points were added), each pair that could break
// it found from the side of its smaller radius (radius_layers.hpp).
bool check_rule(const Delaunay& dt, const Torus& t, const std::vector<VertexIndex>& real,
                const std::vector<Point>& pts, const std::vector<std::size_t>& rank, VerifyReport& rep) {
    for (VertexIndex v : real) {
        if (!RadiusLayers::usable(dt.radius(v))) {
            rep.failure = "a point's radius is not a positive finite number";
            rep.vertex = v;
            return false;
        }
    }
    const RadiusLayers layers(pts, 0, t, [&](std::size_t k) { return dt.radius(real[k]); });
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double ri = dt.radius(real[i]);
        VertexIndex inside = kNoVertex;  // the later point of a pair that breaks the rule
        layers.for_each_near(pts[i], ri, [&](std::uint32_t j, int sx, int sy, bool same) {
            // A point's own copies are not earlier than it.
            if (j == i || inside != kNoVertex) return;
            ++rep.pairs_examined;
            const bool j_first = rank[real[j]] < rank[real[i]];
            if (same && !j_first) return;  // j's own visit checks this pair
            if (compare_distance(pts[i], t.shifted(pts[j], sx, sy), j_first ? dt.radius(real[j]) : ri) < 0)
                inside = j_first ? real[i] : real[j];
        });
        if (inside != kNoVertex) {
            rep.failure = "a point lies inside an earlier point's disk on the torus";
            rep.vertex = inside;
            return false;
        }
    }
    return true;
}

bool check_distances(const Delaunay& dt, const Torus& t, const std::vector<VertexIndex>& real, double r,
                     const std::vector<std::size_t>* rank, VerifyReport& rep) {
    std::vector<Point> pts;
    pts.reserve(real.size());
    for (VertexIndex v : real) pts.push_back(dt.point(v));
    if (rank) return check_rule(dt, t, real, pts, *rank, rep);
    const SpatialHash grid(pts, 0, t, r);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        bool close = false;
        grid.for_each_near(pts[i], [&](std::uint32_t j, int sx, int sy) {
            if (close || (j == i && sx == 0 && sy == 0)) return;
            ++rep.pairs_examined;
            close = compare_distance(pts[i], t.shifted(pts[j], sx, sy), r) < 0;
        });
        if (close) {
            rep.failure = "two points are closer than the radius on the torus";
            rep.vertex = real[i];
            return false;
        }
    }
    return true;
}

bool check_copies(const Delaunay& dt, const TorusCopies& copies, const std::vector<std::uint8_t>& is_copy,
                  const std::vector<VertexIndex>& real, VerifyReport& rep) {
    std::vector<Point> expected, present;
    for (VertexIndex v : real)
        copies.for_each_copy(dt.point(v), copies.margin(), -1.0,
                             [&](const Point& c, int, int) { expected.push_back(c); });
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v)
        if (is_copy[v] != 0) present.push_back(dt.point(v));
    std::sort(expected.begin(), expected.end(), point_less);
    std::sort(present.begin(), present.end(), point_less);
    if (expected.size() != present.size() ||
        !std::equal(expected.begin(), expected.end(), present.begin(), point_equal)) {
        rep.failure = "the mesh's copies are not the copies of the points within the margin";
        return false;
    }
    return true;
}

}  // namespace

VerifyReport verify_torus(const Delaunay& dt, const TorusCopies& copies, const std::vector<std::uint8_t>& is_copy,
                          double radius, const std::vector<std::size_t>* rank) {
    VerifyReport rep;
    const Torus& t = copies.torus();
    std::vector<VertexIndex> real;
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v)
        if (is_copy[v] == 0) real.push_back(v);
    const auto is_real = [&](VertexIndex v) { return !Delaunay::is_ghost(v) && is_copy[v] == 0; };
    if (!check_real_points(dt, t, real, rep) || !check_distances(dt, t, real, radius, rank, rep) ||
        !check_copies(dt, copies, is_copy, real, rep) || !mesh_consistent(dt, rep)) {
        rep.valid = false;
        return rep;
    }
    for (VertexIndex v : real) {
        if (!copies.ring_valid(dt, v, is_real)) {
            rep.valid = false;
            rep.failure = "a triangle around a point reaches beyond the copies in the mesh";
            rep.vertex = v;
            return rep;
        }
    }
    rep.maximal = !real.empty();
    const Box everywhere = copies.clip_box();
    for (VertexIndex v : real) {
        if (!rep.maximal) break;
        if (dt.weighted() && dt.is_hidden(v)) continue;  // no cell
        const Point& c = dt.point(v);
        VertexIndex first = 0, prev = 0;
        int n = 0;
        const auto triangle = [&](VertexIndex a, VertexIndex b) {
            if (!rep.maximal) return;
            const bool uncovered = dt.weighted() ? power_vertex_uncovered(c, dt.radius(v), dt.point(a), dt.radius(a),
                                                                          dt.point(b), dt.radius(b), everywhere)
                                                 : voronoi_vertex_uncovered(c, dt.point(a), dt.point(b), everywhere, radius);
            if (uncovered) rep.maximal = false;
        };
        dt.for_each_neighbour(v, [&](VertexIndex nb) {
            if (n++ == 0) first = nb;
            else triangle(prev, nb);
            prev = nb;
        });
        if (n >= 2) triangle(prev, first);
    }
    if (!rep.maximal)
        rep.failure = real.empty()      ? "no points yet"
                      : dt.weighted() ? "a power-diagram vertex lies outside its disks"
                                      : "a Voronoi vertex is farther than R from its site";
    return rep;
}

}  // namespace pds
