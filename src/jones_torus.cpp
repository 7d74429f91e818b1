// jones_torus.cpp - the Jones stage on the torus (see jones_stage.hpp and
// torus_copies.hpp): room for the copies, inserting a point with its copies,
// where a walk for a wrapped point starts, widening the margin until every
// real cell is a true torus cell, and the test of one cell. The loop itself
// is in jones_stage.cpp; these run only when the stage has copies.
#include <algorithm>
#include <stdexcept>

#include "jones_stage.hpp"

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

VertexIndex JonesStage::insert_vertex(const Point& p, VertexIndex near, std::optional<VertexIndex> copy_of) {
    const VertexIndex v = dt_.insert(p, near);
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

VertexIndex JonesStage::insert_with_copies(const Point& p, VertexIndex near) {
    const VertexIndex v = insert_vertex(p, near);
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
    // cells are far enough inside E for that to settle it.
    const Box e = copies_.region();
    const Point& p = dt_.point(v);
    const double need = 2.0 * m.reach * (1.0 + 0x1.0p-40) + 0x1.0p-40;
    if (p.x - e.x0 > need && e.x1 - p.x > need && p.y - e.y0 > need && e.y1 - p.y > need) return true;
    return copies_.ring_valid(dt_, v, [this](VertexIndex u) { return is_real(u); });
}

void JonesStage::settle() {
    if (widen_pending_) widen_margin();
}

}  // namespace pds
