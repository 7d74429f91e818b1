// plane_space.hpp - the Jones loop's mesh in the domain's rectangle
// (jones_loop.hpp): a point is one vertex, a cell is its Voronoi (or power)
// cell clipped to the rectangle, and the first point is uniform in it.
//
// A space is what the loop asks of where its points live: the region the
// mesh covers, the box cells are clipped to (here, through the domain type,
// domain/rectangle.hpp), whether a point is inside,
// which newer points may cover a candidate, how a point is inserted, and
// the certificate. Its functions take the loop (a friend) when they change
// the mesh, so the loop's own code never asks which space it runs in.
#ifndef PDS_PLANE_SPACE_HPP
#define PDS_PLANE_SPACE_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/poll.hpp"
#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "core/torus.hpp"
#include "domain/rectangle.hpp"
#include "jones/mesh_build.hpp"
#include "jones/mesh_cells.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/torus_copies.hpp"
#include "verify/verify.hpp"

namespace pds {

class PlaneSpace {
public:
    static constexpr bool kPeriodic = false;
    // Its cells can be measured by several threads at once (no scratch).
    static constexpr bool kMeasuresSideBySide = true;
    // An insertion measures the new cell only: the other sites' bounds stay
    // as they were (insert_point), so they may be scanned meanwhile.
    static constexpr bool kBoundsStayWhileInserting = true;

    PlaneSpace(const Rectangle& domain, double /*r*/, const Torus& /*torus*/, bool /*weighted*/,
               const std::shared_ptr<const Polygon>& /*polygon: none*/)
        : domain_(domain) {}

    Box mesh_region() const { return domain_.bounds(); }
    Box clip_box() const { return domain_.bounds(); }
    // The outline cutter of worker w (none in a rectangle); set_workers
    // makes room for n workers' cutters.
    OutlineClip* outline_clip(unsigned /*w*/ = 0) const { return nullptr; }
    void set_workers(unsigned) {}
    const TorusCopies& copies() const { return no_copies_; }
    bool is_copy(VertexIndex) const { return false; }
    VertexIndex original(VertexIndex v) const { return v; }
    std::size_t vertices_for(std::size_t points) const { return points; }
    void reserve(std::size_t) {}
    bool has_room_for(std::size_t) const { return true; }
    template <class Loop>
    std::size_t count(const Loop& loop) const {
        return loop.dt_.vertex_count() - Delaunay::kGhosts;
    }

    Point first_point(Rng& rng) const { return domain_.uniform_point(rng); }
    // Calls fn on the domain's corners in box b until it returns true: exact
    // points that a free region too thin for the draws may still hold
    // (JonesLoop::give_up).
    template <class Fn>
    bool any_corner_in(const Box& b, Fn&& fn) const {
        const Box& d = domain_.bounds();
        const Point corners[4] = {{d.x0, d.y0}, {d.x1, d.y0}, {d.x1, d.y1}, {d.x0, d.y1}};
        for (const Point& c : corners)
            if (b.contains(c) && fn(c)) return true;
        return false;
    }
    Point snap(const Point& p) const { return p; }
    bool inside(const Point& p) const { return domain_.contains(p); }
    Point wrap(const Point& p) const { return p; }
    // Whether newer point q covers candidate p (radius() its disk's radius);
    // the box test skips most without the exact predicate.
    template <class Radius>
    bool covers(const Point& q, const Point& p, double reach, const Radius& radius) const {
        if (std::fabs(p.x - q.x) > reach || std::fabs(p.y - q.y) > reach) return false;
        return compare_distance(p, q, radius()) < 0;
    }

    template <class Loop>
    void adopt(Loop& loop, const std::vector<Point>& points, const std::uint32_t* order,
               const std::vector<double>* values, const Poll& poll, MeshBuild build) {
        if (values) loop.rule_.assign_values(*values);  // within the reserved room
        const auto radius_of = [&](std::uint32_t k) { return loop.rule_.radius_of(loop.rule_.value(k)); };
        std::size_t inserted = 0;
        const auto set = [&](std::uint32_t k, VertexIndex v) {
            loop.order_.set(k, v);
            if (++inserted % Poll::kEvery == 0) poll();
        };
        // Whole: without a field; with fixed points (set_fixed, first in the
        // order) when every other point has the ghosts' radius, those whole
        // (their regular mesh is the Delaunay one), then the fixed ones
        // inserted. build_whole() declines small hand-overs.
        const std::size_t fixed = loop.fixed_, n = points.size();
        bool whole = build == MeshBuild::whole && fixed <= n;
        if (whole && loop.dt_.weighted()) {
            whole = fixed > 0;
            for (std::size_t i = fixed; whole && i < n; ++i) whole = radius_of(order[i]) == loop.dt_.radius(0);
        }
        if (whole && loop.dt_.build_whole(points, order + fixed, n - fixed, loop.threads_,
                                          [&](std::uint32_t k, VertexIndex v) { loop.order_.set(k, v); })) {
            loop.dt_.insert_in_order(points, order, fixed, radius_of, set);
        } else {
            loop.dt_.insert_in_order(points, order, n, radius_of, set);
        }
        loop.tree_.resize(points.size());
        loop.measure_all_cells(poll);
    }
    template <class Loop>
    void insert_point(Loop& loop, const Point& p, VertexIndex near, double value) {
        // Room was reserved: nothing here allocates. The neighbours' cells
        // only shrank: their weights stay valid upper bounds and are
        // tightened when next selected (re-measuring them here, even only
        // the source cell, costs more than the rejections it saves). Only
        // the new cell is measured.
        const VertexIndex v = loop.rule_.insert(loop.dt_, p, value, near);
        loop.tree_.push_back(loop.rule_.hidden(loop.dt_, v) ? 0.0 : loop.cells().measure(v).area);
        loop.record_new_point(v, value);
    }
    template <class Loop>
    bool cell_valid(const Loop&, VertexIndex, const CellMeasure&) const {
        return true;
    }
    template <class Loop>
    void settle(Loop&) {}
    template <class Loop>
    void widen_margin(Loop&) {}
    bool pending() const { return false; }

    VerifyReport verify(const Delaunay& dt, double r, const std::vector<std::size_t>* rank, std::size_t fixed) const {
        return verify_pattern(dt, domain_, r, rank, nullptr, fixed);
    }

private:
    Rectangle domain_;
    TorusCopies no_copies_;  // off
};

}  // namespace pds

#endif
