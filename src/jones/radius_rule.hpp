// radius_rule.hpp - how far a point keeps the others, as the Jones loop
// (jones_loop.hpp) asks it: the test of a candidate in its cell, the radius
// of a newer disk, and what a point carries beyond its position.
//
//   OneRadius  every disk has radius R: cells are Voronoi cells, a candidate
//              is at least R from its site and no Delaunay neighbour is
//              strictly closer.
//   PowerRule  a variable radius (point_radii.hpp): the mesh is the regular
//              triangulation of the disks and the cells are power cells
//              (free_area.hpp); each new point gets its radius from the
//              field as it is added, and a candidate must keep out of each
//              newer disk by that disk's radius. A disk can lose its whole
//              power cell to later, larger ones (hidden, delaunay.hpp): its
//              weight is dropped when it is next selected. A refine changes
//              every radius, and so the power diagram: the mesh is rebuilt
//              (around fixed points of one radius, the others whole and the
//              fixed ones inserted, rebuild_whole).
#ifndef PDS_RADIUS_RULE_HPP
#define PDS_RADIUS_RULE_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/predicates.hpp"
#include "mesh/delaunay.hpp"
#include "radius/point_radii.hpp"

namespace pds {

class OneRadius {
public:
    static constexpr bool kWeighted = false;

    explicit OneRadius(const PointRadii* /*radii*/) {}
    double rmax() const { return 0.0; }
    void reserve(std::size_t) {}
    bool has_room_for(std::size_t) const { return true; }
    double value(PointIndex) const { return 0.0; }
    template <class Space>
    double value_at(const Space&, const Point&) const {
        return 0.0;
    }
    double radius_of(double) const { return 0.0; }
    void push_value(double) {}
    void assign_values(const std::vector<double>&) {}
    VertexIndex insert(Delaunay& dt, const Point& p, double /*value*/, VertexIndex near) const {
        return dt.insert(p, near);
    }
    bool hidden(const Delaunay&, VertexIndex) const { return false; }
    double newer_radius(const Delaunay&, VertexIndex, double r) const { return r; }
    // Exact: at least R from the site, and in its Voronoi cell (no Delaunay
    // neighbour strictly closer), hence at least R from every point.
    bool acceptable(const Delaunay& dt, const Point& p, VertexIndex v, double r) const {
        const Point& c = dt.point(v);
        if (compare_distance(p, c, r) < 0) return false;
        bool ok = true;
        dt.for_each_neighbour(v, [&](VertexIndex n) {
            if (ok && !Delaunay::is_ghost(n) && compare_closer(p, c, dt.point(n)) > 0) ok = false;
        });
        return ok;
    }
    bool retry_in_piece(const Delaunay&, VertexIndex) const { return true; }
    // Every new point's radius is r (the free regions' darts decide theirs by it).
    bool new_radius_is(double) const { return true; }
    template <class Loop>
    void rescale(Loop&, const PointRadii*) {}
};

class PowerRule {
public:
    static constexpr bool kWeighted = true;

    explicit PowerRule(const PointRadii* radii) : radii_(*radii) {}
    double rmax() const { return radii_.rmax(); }
    void reserve(std::size_t points) { values_.reserve(points); }
    bool has_room_for(std::size_t points) const { return values_.capacity() >= points; }
    // Point k's field value.
    double value(PointIndex k) const { return values_[k]; }
    // The field's value at a point about to be added, moved into the domain;
    // may throw FieldError, before anything changes.
    template <class Space>
    double value_at(const Space& space, const Point& p) const {
        return radii_.value_at(space.wrap(p));
    }
    double radius_of(double value) const { return radii_.radius_of(value); }
    void push_value(double value) { values_.push_back(value); }
    void assign_values(const std::vector<double>& values) { values_.assign(values.begin(), values.end()); }
    VertexIndex insert(Delaunay& dt, const Point& p, double value, VertexIndex near) const {
        return dt.insert(p, radius_of(value), near);
    }
    bool hidden(const Delaunay& dt, VertexIndex v) const { return dt.is_hidden(v); }
    double newer_radius(const Delaunay& dt, VertexIndex v, double) const { return dt.radius(v); }
    // Exact: in the site's power cell and outside its disk, hence outside
    // every disk.
    bool acceptable(const Delaunay& dt, const Point& p, VertexIndex v, double) const {
        const Point& c = dt.point(v);
        const double rc = dt.radius(v);
        if (compare_distance(p, c, rc) < 0) return false;
        bool ok = true;
        dt.for_each_neighbour(v, [&](VertexIndex n) {
            if (ok && !Delaunay::is_ghost(n) && compare_power(p, c, rc, dt.point(n), dt.radius(n)) > 0) ok = false;
        });
        return ok;
    }
    // Whether v's site lies in its own power cell; if not, its fan's pieces
    // reach outside the cell (free_area.hpp) and a draw outside rejects the
    // whole selection.
    // Every new point's radius is r: a constant field (one radius with
    // fixed points, whose clearances are the other disks).
    bool new_radius_is(double r) const { return radii_.constant() && radii_.rmin() == r; }
    bool retry_in_piece(const Delaunay& dt, VertexIndex v) const {
        const Point& c = dt.point(v);
        const double rc = dt.radius(v);
        bool inside = true;
        dt.for_each_neighbour(v, [&](VertexIndex n) {
            if (inside && compare_power(c, c, rc, dt.point(n), dt.radius(n)) > 0) inside = false;
        });
        return inside;
    }
    // A refine: every radius scales with the new largest, so the mesh is
    // built anew (allocates; on std::bad_alloc nothing has changed).
    template <class Loop>
    void rescale(Loop& loop, const PointRadii* radii) {
        const PointRadii old = radii_;
        radii_ = *radii;
        try {
            rebuild_mesh(loop);
        } catch (...) {
            radii_ = old;
            throw;
        }
    }

private:
    template <class Loop>
    void rebuild_mesh(Loop& loop) const {
        // The vertices again in their order, with their new radii: each keeps
        // its number (so the point order and the tree stay), and with equal
        // radii the mesh comes out record for record as before (the scaling
        // changes no decision). Each walk starts at an older neighbour in the
        // old mesh, which is close. Built aside: a failure changes nothing.
        const Delaunay& dt = loop.dt_;
        Delaunay fresh(loop.space_.mesh_region(), true, radii_.rmax());
        fresh.reserve(std::max<std::size_t>(dt.vertex_count(),
                                            loop.vertices_for(loop.order_.capacity()) + Delaunay::kGhosts));
        std::vector<double> value_of_vertex(dt.vertex_count(), 0.0);
        for (std::size_t k = 0; k < loop.count(); ++k) value_of_vertex[loop.order_.vertex(k)] = values_[k];
        if (rebuild_whole(loop, fresh, value_of_vertex)) return;
        for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
            VertexIndex near = v - 1;
            if (!dt.is_hidden(v))
                dt.for_each_neighbour(v, [&](VertexIndex n) {
                    if (n < v && !Delaunay::is_ghost(n)) near = n;
                });
            // A copy has its original's radius.
            fresh.insert(dt.point(v), radii_.radius_of(value_of_vertex[loop.space_.original(v)]), near);
        }
        loop.dt_ = std::move(fresh);
    }

    // The plane's mesh when every point but the fixed ones (the first
    // loop.fixed_) has the ghosts' radius (one radius around fixed points):
    // those built whole (their regular mesh is their Delaunay mesh), side
    // by side, then the fixed ones inserted. The vertices are numbered
    // anew, the others first, so the point order is rewritten. False, and
    // nothing changed, where it does not apply. Allocates before it changes
    // anything.
    template <class Loop>
    bool rebuild_whole(Loop& loop, Delaunay& fresh, const std::vector<double>& value_of_vertex) const {
        using Space = std::decay_t<decltype(loop.space_)>;
        if (Space::kPeriodic) return false;
        const Delaunay& dt = loop.dt_;
        const std::size_t n = loop.count(), fixed = loop.fixed_;
        if (fixed == 0 || fixed > n || n - fixed < Delaunay::kBuildWholeFrom ||
            dt.vertex_count() != n + Delaunay::kGhosts)
            return false;  // (build_whole() would decline so few)
        std::vector<char> is_fixed(dt.vertex_count(), 0);
        for (std::size_t k = 0; k < fixed; ++k) is_fixed[loop.order_.vertex(k)] = 1;
        // The others in their order: vertex kGhosts + i for others[i].
        std::vector<Point> others;
        others.reserve(n - fixed);
        std::vector<VertexIndex> renumbered(dt.vertex_count(), 0);
        for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
            if (is_fixed[v]) continue;
            if (!(radii_.radius_of(value_of_vertex[v]) == fresh.radius(0))) return false;
            renumbered[v] = static_cast<VertexIndex>(Delaunay::kGhosts + others.size());
            others.push_back(dt.point(v));
        }
        std::vector<std::uint32_t> order(others.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
        if (!fresh.build_whole(others, order.data(), others.size(), loop.threads_)) return false;
        // The fixed ones in their order, each walk from a renumbered neighbour.
        for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
            if (!is_fixed[v]) continue;
            VertexIndex near = Delaunay::kGhosts;
            if (!dt.is_hidden(v))
                dt.for_each_neighbour(v, [&](VertexIndex w) {
                    if (!Delaunay::is_ghost(w) && !is_fixed[w]) near = renumbered[w];
                });
            renumbered[v] = fresh.insert(dt.point(v), radii_.radius_of(value_of_vertex[v]), near);
        }
        // Every point's vertex recorded (those past the table were kGhosts + k).
        const std::size_t recorded = std::min(loop.order_.handed_over(), n);
        for (std::size_t k = 0; k < recorded; ++k) loop.order_.set(k, renumbered[loop.order_.vertex(k)]);
        loop.order_.resize(n);  // within its capacity
        for (std::size_t k = recorded; k < n; ++k) loop.order_.set(k, renumbered[k + Delaunay::kGhosts]);
        loop.dt_ = std::move(fresh);
        return true;
    }

    PointRadii radii_;
    std::vector<double> values_;  // per point, the field's value
};

}  // namespace pds

#endif
