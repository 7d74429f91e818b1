// torus_space.cpp - the torus's mesh for the Jones loop (see
// torus_space.hpp): the parts that do not change the loop's state.
#include "jones/torus_space.hpp"

namespace pds {

TorusSpace::TorusSpace(const Rectangle& /*domain: the torus holds its periods*/, double r, const Torus& torus, bool weighted,
                       const std::shared_ptr<const Polygon>& /*polygon: none on the torus*/)
    : copies_(torus, r, weighted) {
    is_copy_.assign(Delaunay::kGhosts, 0);
    original_.assign(Delaunay::kGhosts, 0);
    copy_hint_.assign(copies_.max_offsets(), 0);
}

std::size_t TorusSpace::vertices_for(std::size_t points) const {
    // The copies expected at the current margin, and one point's worth more.
    const double copies = static_cast<double>(points) * copies_.copies_per_point() * 1.25;
    return points + static_cast<std::size_t>(copies) + copies_.max_copies() + 1;
}

Point TorusSpace::first_point(Rng& rng) const {
    const Torus& t = copies_.torus();
    const double u = rng.next_double(), w = rng.next_double();
    return t.wrap(Point{Torus::snap(t.x0 + u * t.px), Torus::snap(t.y0 + w * t.py)});
}

template <class F>
void TorusSpace::for_each_neighbour_copy(const Delaunay& dt, VertexIndex v, double sx, double sy, const F& f) const {
    dt.for_each_neighbour(v, [&](VertexIndex n) {
        if (Delaunay::is_ghost(n) || is_real(n)) return;
        const Point& c = dt.point(n);
        const Point& o = dt.point(original_[n]);
        if (c.x - o.x == sx && c.y - o.y == sy) f(original_[n]);
    });
}

VertexIndex TorusSpace::copy_walk_start(const Delaunay& dt, VertexIndex v, const Point& c, int i, int j,
                                        VertexIndex hint) const {
    // A walk costs about its length in points. The last copy with this offset
    // lies anywhere along the edge (far, on a long thin torus); v itself is
    // one shift away (near, across a short period); and a neighbour of v that
    // is a copy shifted by (-i, -j) has its original right next to c. Start
    // at the nearest of these: only the walk's length depends on the choice.
    const Torus& t = copies_.torus();
    const auto distance2 = [&c](const Point& q) { return (q.x - c.x) * (q.x - c.x) + (q.y - c.y) * (q.y - c.y); };
    VertexIndex start = v;
    double best = distance2(dt.point(v));
    const auto consider = [&](VertexIndex u) {
        const double d = distance2(dt.point(u));
        if (d < best) start = u, best = d;
    };
    if (!Delaunay::is_ghost(hint)) consider(hint);
    for_each_neighbour_copy(dt, v, -i * t.px, -j * t.py, consider);  // shifts exact on the grid
    return start;
}

VertexIndex TorusSpace::walk_start(const Delaunay& dt, const Point& p, const Point& w, VertexIndex near) const {
    // p was drawn in near's cell; moved by whole periods to w, it is far
    // from near, but near's ring holds copies of points near w: start at the
    // original of the one shifted as p was.
    if (dt.weighted()) near = dt.visible(near);  // hidden since p was drawn: no ring
    if (p.x == w.x && p.y == w.y) return near;
    VertexIndex start = near;
    for_each_neighbour_copy(dt, near, p.x - w.x, p.y - w.y, [&](VertexIndex o) { start = o; });  // exact on the grid
    return start;
}

bool TorusSpace::new_rings_valid(const Delaunay& dt, VertexIndex from) const {
    const auto real = [this](VertexIndex u) { return is_real(u); };
    for (VertexIndex v = from; v < dt.vertex_count(); ++v)
        if (!copies_.ring_valid(dt, v, real)) return false;
    return true;
}

}  // namespace pds
