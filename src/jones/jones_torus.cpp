// jones_torus.cpp - the Jones stage on the torus (see jones_stage.hpp and
// torus_copies.hpp): room for the copies, inserting a point with its copies,
// where a walk for a wrapped point starts, widening the margin until every
// real cell is a true torus cell (and narrowing it as a pattern with a
// variable radius fills), the test of one cell, and whether a candidate is
// still free across the wrap. The loop itself
// is in jones_stage.cpp; these run only when the stage has copies.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "jones/jones_stage.hpp"

namespace pds {

void JonesStage::make_room_for_copies(std::size_t copies) {
    // Geometric growth, so copies cost O(1) amortized; all before any change.
    const std::size_t need = dt_.vertex_count() + copies + 1;
    if (dt_.has_room_for(need) && tree_.capacity() >= need && is_copy_.capacity() >= need &&
        original_.capacity() >= need && order_.capacity() > count())
        return;
    const std::size_t want = std::max(need, dt_.vertex_count() + dt_.vertex_count() / 4);
    dt_.reserve(want);
    tree_.reserve(want);
    is_copy_.reserve(want);
    original_.reserve(want);
    order_.reserve(std::max(count() + 1, order_.capacity()));
}

VertexIndex JonesStage::insert_vertex(const Point& p, VertexIndex near, std::optional<VertexIndex> copy_of,
                                      double radius) {
    const VertexIndex v = !dt_.weighted() ? dt_.insert(p, near)
                                          : dt_.insert(p, copy_of ? dt_.radius(*copy_of) : radius, near);
    is_copy_.push_back(copy_of ? 1 : 0);
    original_.push_back(copy_of ? *copy_of : v);
    tree_.push_back(0.0);
    return v;
}

template <class F>
void JonesStage::for_each_neighbour_copy(VertexIndex v, double sx, double sy, const F& f) const {
    dt_.for_each_neighbour(v, [&](VertexIndex n) {
        if (Delaunay::is_ghost(n) || is_real(n)) return;
        const Point& c = dt_.point(n);
        const Point& o = dt_.point(original_[n]);
        if (c.x - o.x == sx && c.y - o.y == sy) f(original_[n]);
    });
}

VertexIndex JonesStage::insert_with_copies(const Point& p, VertexIndex near, double radius) {
    const VertexIndex v = insert_vertex(p, near, std::nullopt, radius);
    // The hint of each offset is the copy with that offset inserted last.
    copies_.for_each_copy(p, copies_.margin(), -1.0, [&](const Point& c, int i, int j) {
        VertexIndex& hint = copy_hint_[copies_.offset_slot(i, j)];
        hint = insert_vertex(c, copy_walk_start(v, c, i, j, hint), v);
    });
    return v;
}

VertexIndex JonesStage::copy_walk_start(VertexIndex v, const Point& c, int i, int j, VertexIndex hint) const {
    // A walk costs about its length in points. The last copy with this offset
    // lies anywhere along the edge (far, on a long thin torus); v itself is
    // one shift away (near, across a short period); and a neighbour of v that
    // is a copy shifted by (-i, -j) has its original right next to c. Start
    // at the nearest of these: only the walk's length depends on the choice.
    const Torus& t = copies_.torus();
    const auto distance2 = [&c](const Point& q) { return (q.x - c.x) * (q.x - c.x) + (q.y - c.y) * (q.y - c.y); };
    VertexIndex start = v;
    double best = distance2(dt_.point(v));
    const auto consider = [&](VertexIndex u) {
        const double d = distance2(dt_.point(u));
        if (d < best) start = u, best = d;
    };
    if (!Delaunay::is_ghost(hint)) consider(hint);
    for_each_neighbour_copy(v, -i * t.px, -j * t.py, consider);  // shifts exact on the grid
    return start;
}

VertexIndex JonesStage::walk_start(const Point& p, const Point& w, VertexIndex near) const {
    // p was drawn in near's cell; moved by whole periods to w, it is far
    // from near, but near's ring holds copies of points near w: start at the
    // original of the one shifted as p was.
    if (dt_.weighted()) near = dt_.visible(near);  // hidden since p was drawn: no ring
    if (p.x == w.x && p.y == w.y) return near;
    VertexIndex start = near;
    for_each_neighbour_copy(near, p.x - w.x, p.y - w.y, [&](VertexIndex o) { start = o; });  // exact on the grid
    return start;
}

bool JonesStage::new_rings_valid(VertexIndex from) const {
    const auto real = [this](VertexIndex u) { return is_real(u); };
    for (VertexIndex v = from; v < dt_.vertex_count(); ++v)
        if (!copies_.ring_valid(dt_, v, real)) return false;
    return true;
}

void JonesStage::widen_margin() {
    // Interrupted by std::bad_alloc, it leaves the copies as they were
    // (room is made before each round) and the widening pending.
    widen_pending_ = true;
    while (!measure_all_cells()) {
        const double old = copies_.margin(), now = copies_.next_margin();
        if (!(now > old)) throw std::logic_error("torus: the widest margin leaves a cell invalid");
        std::size_t added = 0;
        for (PointIndex k = 0; k < count(); ++k)
            copies_.for_each_copy(point(k), now, old, [&](const Point&, int, int) { ++added; });
        make_room_for_copies(added);
        for (PointIndex k = 0; k < count(); ++k)
            copies_.for_each_copy(point(k), now, old, [&](const Point& c, int i, int j) {
                VertexIndex& hint = copy_hint_[copies_.offset_slot(i, j)];
                hint = insert_vertex(c, hint, order_.vertex(k));
            });
        copies_.set_margin(now);
    }
    widen_pending_ = false;
}

bool JonesStage::cell_valid(VertexIndex v, const CellMeasure& m) const {
    // The cheap test first: every circumdisk around v has radius at most
    // m.reach and passes through v, so it lies within 2 reach of v; most
    // cells are far enough inside E for that to settle it. (Weighted: the
    // conflict disks, centred within reach of v, have radii at most
    // sqrt(reach^2 + rmax^2).)
    const Box e = copies_.region();
    const Point& p = dt_.point(v);
    const double extent = copies_.weighted() ? m.reach + std::sqrt(m.reach * m.reach + copies_.rmax() * copies_.rmax())
                                             : 2.0 * m.reach;
    const double need = extent * (1.0 + 0x1.0p-40) + 0x1.0p-40;
    if (p.x - e.x0 > need && e.x1 - p.x > need && p.y - e.y0 > need && e.y1 - p.y > need) return true;
    return copies_.ring_valid(dt_, v, [this](VertexIndex u) { return is_real(u); });
}

void JonesStage::maybe_narrow_margin() {
    if (count() < next_narrowing_) return;
    next_narrowing_ = 2 * count();
    double need = 0.0;
    for (VertexIndex v = Delaunay::kGhosts; v < dt_.vertex_count() && std::isfinite(need); ++v)
        if (is_real(v) && !dt_.is_hidden(v)) need = std::max(need, copies_.ring_overshoot(dt_, v));
    const double margin = std::max(copies_.first_margin(), 2.0 * need);
    if (std::isfinite(margin) && margin <= 0.5 * copies_.margin()) rebuild_with_margin(margin);
}

void JonesStage::rebuild_with_margin(double margin) {
    // The vertices again in their order, without the copies beyond the new
    // margin; each walk starts at an older kept neighbour. Built aside.
    const Box e = copies_.region(margin);
    const auto kept = [&](VertexIndex v) {
        const Point& p = dt_.point(v);
        return is_real(v) || (p.x >= e.x0 && p.x <= e.x1 && p.y >= e.y0 && p.y <= e.y1);
    };
    std::vector<VertexIndex> renumbered(dt_.vertex_count(), 0);
    std::size_t vertices = Delaunay::kGhosts;
    for (VertexIndex v = Delaunay::kGhosts; v < dt_.vertex_count(); ++v)
        if (kept(v)) renumbered[v] = static_cast<VertexIndex>(vertices++);
    Delaunay fresh(copies_.largest_region(), true, radii_->rmax());
    fresh.reserve(std::max<std::size_t>(vertices, vertices_for(order_.capacity()) + Delaunay::kGhosts));
    std::vector<std::uint8_t> is_copy(Delaunay::kGhosts, 0);
    std::vector<VertexIndex> original(Delaunay::kGhosts, 0);
    is_copy.reserve(vertices);
    original.reserve(vertices);
    for (VertexIndex v = Delaunay::kGhosts; v < dt_.vertex_count(); ++v) {
        if (!kept(v)) continue;
        VertexIndex near = 0;
        if (!dt_.is_hidden(v))
            dt_.for_each_neighbour(v, [&](VertexIndex n) {
                if (n < v && !Delaunay::is_ghost(n) && kept(n)) near = renumbered[n];
            });
        fresh.insert(dt_.point(v), dt_.radius(v), near);
        is_copy.push_back(is_copy_[v]);
        original.push_back(renumbered[original_[v]]);
    }
    // Nothing below allocates beyond what is reserved.
    const std::size_t n = count();
    for (std::size_t k = 0; k < n; ++k) order_.set(k, renumbered[order_.vertex(k)]);
    dt_ = std::move(fresh);
    is_copy_ = std::move(is_copy);
    original_ = std::move(original);
    std::fill(copy_hint_.begin(), copy_hint_.end(), 0);
    copies_.set_margin(margin);
    tree_.resize(dt_.vertex_count() - Delaunay::kGhosts);
    drop_queue();
    has_first_ = false;
    if (!measure_all_cells()) widen_margin();
}

bool JonesStage::still_free_on_torus(const Point& p) const {
    const double reach = kBoxReach * r_;
    // The copy of each new point nearest p is the nearest in x and in y;
    // if it is at least R away, so is every other. Near a tie (p half a
    // period from q, up to rounding) both candidates are checked.
    const Torus& t = copies_.torus();
    const auto offsets = [](double d, double period, int* first, int* last) {
        const double f = d / period;
        *first = *last = static_cast<int>(std::nearbyint(f));
        constexpr double kTie = 0.49;
        if (f - *first > kTie) *last = *first + 1;
        if (*first - f > kTie) *first = *last - 1;
    };
    for (VertexIndex v : since_batch_) {
        const Point& q = dt_.point(v);
        int i0, i1, j0, j1;
        offsets(p.x - q.x, t.px, &i0, &i1);
        offsets(p.y - q.y, t.py, &j0, &j1);
        for (int i = i0; i <= i1; ++i) {
            for (int j = j0; j <= j1; ++j) {
                const Point c = t.shifted(q, i, j);
                if (std::fabs(p.x - c.x) > reach || std::fabs(p.y - c.y) > reach) continue;
                if (compare_distance(p, c, radii_ ? dt_.radius(v) : r_) < 0) return false;
            }
        }
    }
    return true;
}

void JonesStage::adopt_on_torus(const std::vector<Point>& points, const std::uint32_t* order, const Poll& poll) {
    // The points along the curve, then their copies in the same order (so
    // each offset's walks stay short); then the margin is settled. Room
    // first, so a failure changes nothing; the margin is settled by the first
    // next() (settle()), which may allocate.
    const std::size_t n = points.size();
    std::size_t copies = 0;
    for (std::size_t i = 0; i < n; ++i)
        copies_.for_each_copy(points[order[i]], copies_.margin(), -1.0, [&](const Point&, int, int) { ++copies; });
    make_room_for_copies(n + copies);
    VertexIndex previous = 0;
    for (std::size_t i = 0; i < n; ++i) {
        previous = insert_vertex(points[order[i]], previous);
        order_.set(order[i], previous);
        if ((i + 1) % Poll::kEvery == 0) poll();
    }
    for (std::size_t i = 0; i < n; ++i) {
        if ((i + 1) % Poll::kEvery == 0) poll();
        copies_.for_each_copy(points[order[i]], copies_.margin(), -1.0, [&](const Point& c, int a, int b) {
            VertexIndex& hint = copy_hint_[copies_.offset_slot(a, b)];
            hint = insert_vertex(c, hint, order_.vertex(order[i]));
        });
    }
    widen_pending_ = true;
}

void JonesStage::insert_point_on_torus(const Point& p, VertexIndex near, double value) {
    make_room_for_copies(copies_.max_copies());  // may throw; nothing changed yet
    const VertexIndex from = static_cast<VertexIndex>(dt_.vertex_count());
    const Point w = copies_.torus().wrap(p);
    const VertexIndex v = insert_with_copies(w, walk_start(p, w, near), radii_ ? radii_->radius_of(value) : 0.0);
    if (radii_) values_.push_back(value);
    order_.push(v);
    since_batch_.push_back(v);
    draw_failures_ = 0;
    const CellMeasure m = cells().measure(v);
    if (cell_valid(v, m) && new_rings_valid(from + 1)) tree_.set(site_of(v), m.area);
    else widen_margin();  // if it fails, the next call finishes it (settle)
    if (radii_) maybe_narrow_margin();
}

void JonesStage::settle() {
    if (widen_pending_) widen_margin();
}

}  // namespace pds
