// polygon_splits.cpp - see polygon_splits.hpp.
#include "domain/polygon_splits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

#include "core/predicates.hpp"

namespace pds {

namespace {

struct Split {
    std::uint32_t edge;
    Point p;
};

struct Segment {
    Point a, b;
};

bool same(const Point& p, const Point& q) { return p.x == q.x && p.y == q.y; }

Segment edge(const PolygonRings& rings, std::size_t i) { return Segment{rings.edge_start(i), rings.edge_end(i)}; }

// kNearEdge of the largest |coordinate|.
double near_edge_reach(const PolygonRings& rings) {
    const Box& box = rings.bounds();
    return kNearEdge * std::max({std::fabs(box.x0), std::fabs(box.y0), std::fabs(box.x1), std::fabs(box.y1)});
}

// Whether p lies on the segment from a to b, not at an end: exactly, or
// within `reach` of it and farther than that from both ends.
bool on_edge(const Point& p, const Point& a, const Point& b, double reach) {
    if (p.x < std::min(a.x, b.x) - reach || p.x > std::max(a.x, b.x) + reach || p.y < std::min(a.y, b.y) - reach ||
        p.y > std::max(a.y, b.y) + reach || same(p, a) || same(p, b))
        return false;
    if (on_segment(p, a, b)) return true;
    const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    if (!(length > 2.0 * reach)) return false;
    const double along_edge = ((p.x - a.x) * dx + (p.y - a.y) * dy) / length;
    const double off_edge = std::fabs((p.x - a.x) * dy - (p.y - a.y) * dx) / length;
    return off_edge <= reach && along_edge > reach && along_edge < length - reach;
}

// Position along the edge from a to b of a point on it: its coordinate along
// the axis the edge moves most on, signed the edge's way (exact order).
double along(const Point& p, const Point& a, const Point& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    if (std::fabs(dx) >= std::fabs(dy)) return dx > 0 ? p.x : -p.x;
    return dy > 0 ? p.y : -p.y;
}

// The rings with each split point inserted into its edge, in order along it.
void write_splits(const PolygonRings& rings, std::vector<Split>& splits, std::vector<double>& xy,
                  std::vector<std::size_t>& ends) {
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
                if (xy[xy.size() - 2] == p.x && xy[xy.size() - 1] == p.y) continue;  // the same point twice
                xy.push_back(p.x);
                xy.push_back(p.y);
            }
        }
        ends.push_back(xy.size() / 2);
    }
}

// Whether two segments cross: each passes strictly from one side of the
// other to the other (exact).
bool cross(const Segment& s, const Segment& t) {
    const Point &a = s.a, &b = s.b, &c = t.a, &d = t.b;
    if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
        std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
        return false;
    return orient2d(a, b, c) * orient2d(a, b, d) < 0 && orient2d(c, d, a) * orient2d(c, d, b) < 0;
}

// The segment with its ends in lexicographic order.
Segment ordered(Segment s) {
    if (s.b.x < s.a.x || (s.b.x == s.a.x && s.b.y < s.a.y)) std::swap(s.a, s.b);
    return s;
}

bool before(const Segment& s, const Segment& t) {
    return std::tie(s.a.x, s.a.y, s.b.x, s.b.y) < std::tie(t.a.x, t.a.y, t.b.x, t.b.y);
}

// Where two crossing segments meet, rounded, and kept inside both their
// boxes (rounding can leave them by an ulp). Computed from the segments in
// one order whatever their edges' order or direction: copies of a segment
// (a ring traced twice) are split at the same points, and still cancel.
Point crossing_point(Segment s, Segment t) {
    s = ordered(s);
    t = ordered(t);
    if (before(t, s)) std::swap(s, t);
    const Point a = s.a, b = s.b, c = t.a, d = t.b;
    const double ex = b.x - a.x, ey = b.y - a.y, fx = d.x - c.x, fy = d.y - c.y;
    const double r = ((c.x - a.x) * fy - (c.y - a.y) * fx) / (ex * fy - ey * fx);
    const double u = std::min(1.0, std::max(0.0, r));
    Point p{a.x + u * ex, a.y + u * ey};
    const double x_lo = std::max(std::min(a.x, b.x), std::min(c.x, d.x));
    const double x_hi = std::min(std::max(a.x, b.x), std::max(c.x, d.x));
    const double y_lo = std::max(std::min(a.y, b.y), std::min(c.y, d.y));
    const double y_hi = std::min(std::max(a.y, b.y), std::max(c.y, d.y));
    p.x = std::min(x_hi, std::max(x_lo, p.x));
    p.y = std::min(y_hi, std::max(y_lo, p.y));
    return p;
}

// The rings with each group of vertices joined by `pairs` moved to its least
// point (by x, then y), when each ring has one point in the group and it
// spans no more than twice `reach`. False, and nothing written, when no
// vertex moves or the moved rings are not rings (one flattened: below
// resolution, kept as given).
bool merge_groups(const PolygonRings& rings, const std::vector<std::uint32_t>& ring_of,
                  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, double reach,
                  std::vector<double>& xy, std::vector<std::size_t>& ends) {
    const std::vector<Point>& points = rings.points();
    std::vector<std::uint32_t> parent(rings.vertices());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<std::uint32_t>(i);
    const auto root = [&parent](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    std::vector<std::uint32_t> grouped;
    for (const auto& [v, w] : pairs) {
        const std::uint32_t a = root(v), b = root(w);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
        grouped.push_back(v);
        grouped.push_back(w);
    }
    // Each vertex once (a pair is found from both ends), its group's root
    // then its own parent, so the sort below reads groups without a search.
    std::sort(grouped.begin(), grouped.end());
    grouped.erase(std::unique(grouped.begin(), grouped.end()), grouped.end());
    for (const std::uint32_t v : grouped) parent[v] = root(v);
    std::sort(grouped.begin(), grouped.end(), [&](std::uint32_t i, std::uint32_t j) {
        return std::make_tuple(parent[i], ring_of[i], points[i].x, points[i].y) <
               std::make_tuple(parent[j], ring_of[j], points[j].x, points[j].y);
    });
    std::vector<Point> moved(points);
    bool any = false;
    for (std::size_t from = 0, to; from < grouped.size(); from = to) {
        const std::uint32_t group = parent[grouped[from]];
        Point least = points[grouped[from]];
        Box span{least.x, least.y, least.x, least.y};
        bool one_point_per_ring = true;
        for (to = from; to < grouped.size() && parent[grouped[to]] == group; ++to) {
            const Point& q = points[grouped[to]];
            if (to > from && ring_of[grouped[to - 1]] == ring_of[grouped[to]] && !same(points[grouped[to - 1]], q))
                one_point_per_ring = false;
            if (q.x < least.x || (q.x == least.x && q.y < least.y)) least = q;
            span = Box{std::min(span.x0, q.x), std::min(span.y0, q.y), std::max(span.x1, q.x), std::max(span.y1, q.y)};
        }
        if (!one_point_per_ring || span.x1 - span.x0 > 2 * reach || span.y1 - span.y0 > 2 * reach) continue;
        for (std::size_t k = from; k < to; ++k) {
            any = any || !same(moved[grouped[k]], least);
            moved[grouped[k]] = least;
        }
    }
    if (!any) return false;
    std::vector<double> merged_xy;
    std::vector<std::size_t> merged_ends;
    merged_xy.reserve(2 * moved.size());
    for (const Point& q : moved) merged_xy.insert(merged_xy.end(), {q.x, q.y});
    for (std::size_t k = 0; k < rings.rings(); ++k) merged_ends.push_back(rings.ring_begin(k + 1));
    try {
        PolygonRings(merged_xy.data(), merged_ends.data(), merged_ends.size());
    } catch (const DomainError&) {
        return false;
    }
    xy.swap(merged_xy);
    ends.swap(merged_ends);
    return true;
}

}  // namespace

bool merge_or_split_at_vertices(const PolygonRings& rings, const PolygonIndex& index, std::vector<double>& xy,
                                std::vector<std::size_t>& ends) {
    // Vertices are merged within twice the near-edge reach: a vertex within
    // that reach of an edge's line but also of its end (so not split into
    // it) is merged with the end.
    const double reach = near_edge_reach(rings), merging = 2.0 * reach;
    std::vector<std::uint32_t> ring_of(rings.vertices());
    for (std::size_t k = 0; k < rings.rings(); ++k)
        for (std::size_t i = rings.ring_begin(k); i < rings.ring_begin(k + 1); ++i)
            ring_of[i] = static_cast<std::uint32_t>(k);
    std::vector<Split> splits;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    std::vector<std::uint32_t> near;
    for (std::size_t v = 0; v < rings.vertices(); ++v) {
        const Point p = rings.points()[v];
        near.clear();
        // Every edge within the merging reach; a vertex that near starts one.
        index.edges_near(Box{p.x - merging, p.y - merging, p.x + merging, p.y + merging}, near);
        for (const std::uint32_t e : near) {
            const Point a = rings.edge_start(e);
            if (ring_of[e] != ring_of[v] && !same(a, p) && std::hypot(a.x - p.x, a.y - p.y) <= merging)
                pairs.emplace_back(static_cast<std::uint32_t>(v), e);
            if (on_edge(p, a, rings.edge_end(e), reach)) splits.push_back(Split{e, p});
        }
    }
    // Merged vertices are split into edges in the next round.
    if (!pairs.empty() && merge_groups(rings, ring_of, pairs, merging, xy, ends)) return true;
    if (splits.empty()) return false;
    write_splits(rings, splits, xy, ends);
    return true;
}

bool split_at_crossings(const PolygonRings& rings, const PolygonIndex& index, std::vector<double>& xy,
                        std::vector<std::size_t>& ends) {
    // Two edges that cross meet in a cell that lists both (a pair may be
    // found in several cells).
    const std::size_t most = kMaxCrossingsPerVertex * rings.vertices() + kMaxCrossingsBeyond;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    const auto distinct = [&pairs] {
        std::sort(pairs.begin(), pairs.end());
        pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    };
    for (std::size_t k = 0; k < index.columns() * index.rows(); ++k) {
        const PolygonIndex::EdgeList list = index.cell_edges(k);
        for (const std::uint32_t* e = list.begin(); e != list.end(); ++e)
            for (const std::uint32_t* f = e + 1; f != list.end(); ++f)
                if (cross(edge(rings, *e), edge(rings, *f)))
                    pairs.emplace_back(std::min(*e, *f), std::max(*e, *f));
        if (pairs.size() > 2 * most) distinct();
        if (pairs.size() > most)
            throw DomainError("the rings cross one another more than " + std::to_string(most) +
                              " times (4 per vertex and 65536)");
    }
    if (pairs.empty()) return false;
    distinct();
    const double reach = near_edge_reach(rings);
    std::vector<Split> splits;
    for (const auto& [e, f] : pairs) {
        const Segment s = edge(rings, e), t = edge(rings, f);
        Point p = crossing_point(s, t);
        // A crossing within reach of an end is that end, which then lies
        // within reach of the other edge, as split_at_vertices_on_edges
        // takes it: no edge shorter than the reach is made. (The nearest
        // end, the least one of equals: copies snap alike. Not for edges
        // that on_edge leaves alone: features below the reach are kept.)
        const Point crossing = p;
        const auto longer = [reach](const Segment& g) {
            return std::hypot(g.b.x - g.a.x, g.b.y - g.a.y) > 2.0 * reach;
        };
        double nearest = longer(s) && longer(t) ? reach : -1.0;
        bool snapped = false;
        for (const Point& q : {s.a, s.b, t.a, t.b}) {
            const double d = std::hypot(crossing.x - q.x, crossing.y - q.y);
            if (d < nearest || (d == nearest && (!snapped || std::tie(q.x, q.y) < std::tie(p.x, p.y)))) {
                nearest = d;
                p = q;
                snapped = true;
            }
        }
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;  // products beyond the doubles: left as given
        if (!same(p, s.a) && !same(p, s.b)) splits.push_back(Split{e, p});
        if (!same(p, t.a) && !same(p, t.b)) splits.push_back(Split{f, p});
    }
    if (splits.empty()) return false;
    write_splits(rings, splits, xy, ends);
    return true;
}

}  // namespace pds
