// torus_space_loop.hpp - the torus space's functions that change the Jones
// loop's mesh and tree (torus_space.hpp): inserting a point with its copies,
// the hand-over, widening and narrowing the margin. Templates over the loop
// type, included by torus_space.hpp and compiled with the loop
// (jones_loop.cpp).
#ifndef PDS_TORUS_SPACE_LOOP_HPP
#define PDS_TORUS_SPACE_LOOP_HPP

#include "jones/torus_space.hpp"

namespace pds {

template <class Radius>
bool TorusSpace::covers(const Point& q, const Point& p, double reach, const Radius& radius) const {
    // The copy of q nearest p is the nearest in x and in y; if it is at
    // least R away, so is every other. Near a tie (p half a period from q,
    // up to rounding) both candidates are checked.
    const Torus& t = copies_.torus();
    const auto offsets = [](double d, double period, int* first, int* last) {
        const double f = d / period;
        *first = *last = static_cast<int>(std::nearbyint(f));
        constexpr double kTie = 0.49;
        if (f - *first > kTie) *last = *first + 1;
        if (*first - f > kTie) *first = *last - 1;
    };
    int i0, i1, j0, j1;
    offsets(p.x - q.x, t.px, &i0, &i1);
    offsets(p.y - q.y, t.py, &j0, &j1);
    for (int i = i0; i <= i1; ++i) {
        for (int j = j0; j <= j1; ++j) {
            const Point c = t.shifted(q, i, j);
            if (std::fabs(p.x - c.x) > reach || std::fabs(p.y - c.y) > reach) continue;
            if (compare_distance(p, c, radius()) < 0) return true;
        }
    }
    return false;
}

template <class Loop>
void TorusSpace::make_room_for_copies(Loop& loop, std::size_t copies) {
    // Geometric growth, so copies cost O(1) amortized; all before any change.
    Delaunay& dt = loop.dt_;
    const std::size_t need = dt.vertex_count() + copies + 1;
    if (dt.has_room_for(need) && loop.tree_.capacity() >= need && is_copy_.capacity() >= need &&
        original_.capacity() >= need && loop.order_.capacity() > loop.count())
        return;
    const std::size_t want = std::max(need, dt.vertex_count() + dt.vertex_count() / 4);
    loop.quiet_helper();  // it reads the mesh's arrays, which may move
    dt.reserve(want);
    loop.tree_.reserve(want);
    is_copy_.reserve(want);
    original_.reserve(want);
    loop.order_.reserve(std::max(loop.count() + 1, loop.order_.capacity()));
}

template <class Loop>
VertexIndex TorusSpace::insert_vertex(Loop& loop, const Point& p, VertexIndex near,
                                      std::optional<VertexIndex> copy_of, double radius) {
    Delaunay& dt = loop.dt_;
    const VertexIndex v = !dt.weighted() ? dt.insert(p, near)
                                         : dt.insert(p, copy_of ? dt.radius(*copy_of) : radius, near);
    record_vertex(loop, v, copy_of);
    return v;
}

template <class Loop>
void TorusSpace::record_vertex(Loop& loop, VertexIndex v, std::optional<VertexIndex> copy_of) {
    is_copy_.push_back(copy_of ? 1 : 0);
    original_.push_back(copy_of ? *copy_of : v);
    loop.tree_.push_back(0.0);
}

template <class Loop>
VertexIndex TorusSpace::insert_with_copies(Loop& loop, const Point& p, VertexIndex near, double radius) {
    const VertexIndex v = insert_vertex(loop, p, near, std::nullopt, radius);
    // The hint of each offset is the copy with that offset inserted last.
    copies_.for_each_copy(p, copies_.margin(), -1.0, [&](const Point& c, int i, int j) {
        VertexIndex& hint = copy_hint_[copies_.offset_slot(i, j)];
        hint = insert_vertex(loop, c, copy_walk_start(loop.dt_, v, c, i, j, hint), v);
    });
    return v;
}

template <class Loop>
void TorusSpace::adopt(Loop& loop, const std::vector<Point>& points, const std::uint32_t* order,
                       const std::vector<double>* values, const Poll& poll, MeshBuild build) {
    // The points along the curve (or built whole, side by side, when the
    // stage asks for it and the mesh is not weighted), then their copies in
    // the same order (so each offset's walks stay short); then the margin
    // is settled. Room first, so a failure changes nothing; the margin is
    // settled by the first next() (settle()), which may allocate. A field's
    // points come with their values: each is inserted with its radius.
    const std::size_t n = points.size();
    std::size_t copies = 0;
    for (std::size_t i = 0; i < n; ++i)
        copies_.for_each_copy(points[order[i]], copies_.margin(), -1.0, [&](const Point&, int, int) { ++copies; });
    make_room_for_copies(loop, n + copies);
    if (values) loop.rule_.assign_values(*values);  // within the reserved room
    const auto adopted = [&](std::uint32_t k, VertexIndex v) {
        record_vertex(loop, v);
        loop.order_.set(k, v);
    };
    if (values || build != MeshBuild::whole || !loop.dt_.build_whole(points, order, n, loop.threads_, adopted)) {
        VertexIndex previous = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double radius = values ? loop.rule_.radius_of((*values)[order[i]]) : 0.0;
            previous = insert_vertex(loop, points[order[i]], previous, std::nullopt, radius);
            loop.order_.set(order[i], previous);
            if ((i + 1) % Poll::kEvery == 0) poll();
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if ((i + 1) % Poll::kEvery == 0) poll();
        copies_.for_each_copy(points[order[i]], copies_.margin(), -1.0, [&](const Point& c, int a, int b) {
            VertexIndex& hint = copy_hint_[copies_.offset_slot(a, b)];
            hint = insert_vertex(loop, c, hint, loop.order_.vertex(order[i]));
        });
    }
    widen_pending_ = true;
}

template <class Loop>
void TorusSpace::insert_point(Loop& loop, const Point& p, VertexIndex near, double value) {
    make_room_for_copies(loop, copies_.max_copies());  // may throw; nothing changed yet
    const VertexIndex from = static_cast<VertexIndex>(loop.dt_.vertex_count());
    const Point w = wrap(p);
    const VertexIndex v = insert_with_copies(loop, w, walk_start(loop.dt_, p, w, near), loop.rule_.radius_of(value));
    loop.order_.push(v);
    loop.record_new_point(v, value);
    const CellMeasure m = loop.cells().measure(v);
    if (cell_valid(loop, v, m) && new_rings_valid(loop.dt_, from + 1)) loop.tree_.set(site_of(v), m.area);
    else widen_margin(loop);  // if it fails, the next call finishes it (settle)
    if (loop.rule_.kWeighted) maybe_narrow_margin(loop);
}

template <class Loop>
bool TorusSpace::cell_valid(const Loop& loop, VertexIndex v, const CellMeasure& m) const {
    // The cheap test first: every circumdisk around v has radius at most
    // m.reach and passes through v, so it lies within 2 reach of v; most
    // cells are far enough inside E for that to settle it. (Weighted: the
    // conflict disks, centred within reach of v, have radii at most
    // sqrt(reach^2 + rmax^2).)
    const Box e = copies_.region();
    const Point& p = loop.dt_.point(v);
    const double extent = copies_.weighted() ? m.reach + std::sqrt(m.reach * m.reach + copies_.rmax() * copies_.rmax())
                                             : 2.0 * m.reach;
    const double need = extent * (1.0 + 0x1.0p-40) + 0x1.0p-40;
    if (p.x - e.x0 > need && e.x1 - p.x > need && p.y - e.y0 > need && e.y1 - p.y > need) return true;
    return copies_.ring_valid(loop.dt_, v, [this](VertexIndex u) { return is_real(u); });
}

template <class Loop>
void TorusSpace::widen_margin(Loop& loop) {
    widen_pending_ = true;
    while (!loop.measure_all_cells()) {
        const double old = copies_.margin(), now = copies_.next_margin();
        if (!(now > old)) throw std::logic_error("torus: the widest margin leaves a cell invalid");
        std::size_t added = 0;
        for (PointIndex k = 0; k < loop.count(); ++k)
            copies_.for_each_copy(loop.point(k), now, old, [&](const Point&, int, int) { ++added; });
        make_room_for_copies(loop, added);
        for (PointIndex k = 0; k < loop.count(); ++k)
            copies_.for_each_copy(loop.point(k), now, old, [&](const Point& c, int i, int j) {
                VertexIndex& hint = copy_hint_[copies_.offset_slot(i, j)];
                hint = insert_vertex(loop, c, hint, loop.order_.vertex(k));
            });
        copies_.set_margin(now);
    }
    widen_pending_ = false;
}

template <class Loop>
void TorusSpace::maybe_narrow_margin(Loop& loop) {
    // Not while the free regions' darts run: their pending darts and active
    // cells name vertices a rebuilt mesh would renumber. A wider margin
    // costs only copies; the narrowing is looked at again once they end.
    if (loop.count() < next_narrowing_ || loop.regions_.on()) return;
    next_narrowing_ = 2 * loop.count();
    const Delaunay& dt = loop.dt_;
    double need = 0.0;
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count() && std::isfinite(need); ++v)
        if (is_real(v) && !dt.is_hidden(v)) need = std::max(need, copies_.ring_overshoot(dt, v));
    const double margin = std::max(copies_.first_margin(), 2.0 * need);
    if (std::isfinite(margin) && margin <= 0.5 * copies_.margin()) rebuild_with_margin(loop, margin);
}

template <class Loop>
void TorusSpace::rebuild_with_margin(Loop& loop, double margin) {
    // The vertices again in their order, without the copies beyond the new
    // margin; each walk starts at an older kept neighbour. Built aside.
    const Delaunay& dt = loop.dt_;
    const Box e = copies_.region(margin);
    const auto kept = [&](VertexIndex v) {
        const Point& p = dt.point(v);
        return is_real(v) || (p.x >= e.x0 && p.x <= e.x1 && p.y >= e.y0 && p.y <= e.y1);
    };
    std::vector<VertexIndex> renumbered(dt.vertex_count(), 0);
    std::size_t vertices = Delaunay::kGhosts;
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v)
        if (kept(v)) renumbered[v] = static_cast<VertexIndex>(vertices++);
    Delaunay fresh(copies_.largest_region(), true, loop.rule_.rmax());
    fresh.reserve(std::max<std::size_t>(vertices, loop.vertices_for(loop.order_.capacity()) + Delaunay::kGhosts));
    std::vector<std::uint8_t> is_copy(Delaunay::kGhosts, 0);
    std::vector<VertexIndex> original(Delaunay::kGhosts, 0);
    is_copy.reserve(vertices);
    original.reserve(vertices);
    for (VertexIndex v = Delaunay::kGhosts; v < dt.vertex_count(); ++v) {
        if (!kept(v)) continue;
        VertexIndex near = 0;
        if (!dt.is_hidden(v))
            dt.for_each_neighbour(v, [&](VertexIndex n) {
                if (n < v && !Delaunay::is_ghost(n) && kept(n)) near = renumbered[n];
            });
        fresh.insert(dt.point(v), dt.radius(v), near);
        is_copy.push_back(is_copy_[v]);
        original.push_back(renumbered[original_[v]]);
    }
    // Nothing below allocates beyond what is reserved.
    const std::size_t n = loop.count();
    for (std::size_t k = 0; k < n; ++k) loop.order_.set(k, renumbered[loop.order_.vertex(k)]);
    loop.dt_ = std::move(fresh);
    is_copy_ = std::move(is_copy);
    original_ = std::move(original);
    std::fill(copy_hint_.begin(), copy_hint_.end(), 0);
    copies_.set_margin(margin);
    loop.tree_.resize(loop.dt_.vertex_count() - Delaunay::kGhosts);
    loop.forget_candidates();
    if (!loop.measure_all_cells()) widen_margin(loop);
}

}  // namespace pds

#endif
