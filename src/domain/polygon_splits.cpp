// polygon_splits.cpp - see polygon_splits.hpp.
#include "domain/polygon_splits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>


namespace pds {

namespace {

struct Split {
    std::uint32_t edge;
    Point p;
};

// Whether p lies on the segment from a to b, not at an end (exact).
bool strictly_inside(const Point& p, const Point& a, const Point& b) {
    if ((p.x == a.x && p.y == a.y) || (p.x == b.x && p.y == b.y)) return false;
    return on_segment(p, a, b);
}

// Position along the edge from a to b of a point on it: its coordinate along
// the axis the edge moves most on, signed the edge's way (exact order).
double along(const Point& p, const Point& a, const Point& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    if (std::fabs(dx) >= std::fabs(dy)) return dx > 0 ? p.x : -p.x;
    return dy > 0 ? p.y : -p.y;
}

}  // namespace

bool split_at_vertices_on_edges(const PolygonRings& rings, const PolygonIndex& index, std::vector<double>& xy,
                                std::vector<std::size_t>& ends) {
    std::vector<Split> splits;
    std::vector<std::uint32_t> near;
    for (std::size_t v = 0; v < rings.vertices(); ++v) {
        const Point p = rings.points()[v];
        near.clear();
        index.edges_near(Box{p.x, p.y, p.x, p.y}, near);  // every edge through p is among them
        for (const std::uint32_t e : near)
            if (strictly_inside(p, rings.edge_start(e), rings.edge_end(e))) splits.push_back(Split{e, p});
    }
    if (splits.empty()) return false;
    std::sort(splits.begin(), splits.end(), [&](const Split& s, const Split& t) {
        if (s.edge != t.edge) return s.edge < t.edge;
        const Point a = rings.edge_start(s.edge), b = rings.edge_end(s.edge);
        return along(s.p, a, b) < along(t.p, a, b);
    });
    xy.clear();
    ends.clear();
    std::size_t next = 0;  // the first split not yet written
    for (std::size_t k = 0; k < rings.rings(); ++k) {
        for (std::size_t i = rings.ring_begin(k); i < rings.ring_begin(k + 1); ++i) {
            xy.push_back(rings.points()[i].x);
            xy.push_back(rings.points()[i].y);
            for (; next < splits.size() && splits[next].edge == i; ++next) {
                const Point& p = splits[next].p;
                if (xy[xy.size() - 2] == p.x && xy[xy.size() - 1] == p.y) continue;  // the same vertex twice
                xy.push_back(p.x);
                xy.push_back(p.y);
            }
        }
        ends.push_back(xy.size() / 2);
    }
    return true;
}

}  // namespace pds
