// polygon_exact.cpp - where a point with rational coordinates lies against
// the outline, exactly (polygon.hpp, contains_exact).
//
// The same even-odd ray cast as polygon_index.cpp's, to the right, with
// every comparison made on expansions: the point is (X/W, Y/W) with W > 0,
// so each sign is that of a polynomial in X, Y, W and the vertices. The
// edges are those of the index rows around the point's height: its
// estimate may sit a row off, and a ray crosses only edges of its own row.
#include <cstdint>
#include <vector>

#include "domain/polygon.hpp"

namespace pds {

namespace {

using E = Expansion;

// Sign of a.y - Y/W (times W > 0).
int height_sign(double ay, const E& Y, const E& W) { return (W * E(ay) - Y).sign(); }

// Sign of orient2d(a, b, (X/W, Y/W)) (times W > 0).
int orient_exact(const Point& a, const Point& b, const E& X, const E& Y, const E& W) {
    const E dx = E::diff(b.x, a.x), dy = E::diff(b.y, a.y);
    return (dx * (Y - W * E(a.y)) - dy * (X - W * E(a.x))).sign();
}

// The point lies on the closed segment ab (it is on its line).
bool within_segment(const Point& a, const Point& b, const E& X, const E& Y, const E& W) {
    const int xa = (X - W * E(a.x)).sign(), xb = (X - W * E(b.x)).sign();
    const int ya = (Y - W * E(a.y)).sign(), yb = (Y - W * E(b.y)).sign();
    return xa * xb <= 0 && ya * yb <= 0;
}

}  // namespace

bool Polygon::contains_exact(const Expansion& X, const Expansion& Y, const Expansion& W) const {
    const double x = X.estimate() / W.estimate(), y = Y.estimate() / W.estimate();
    const Box& b = bounds();
    if (!(y >= b.y0 - b.height()) || !(y <= b.y1 + b.height())) return false;  // far off (or not finite)
    if (!(x >= b.x0 - b.width()) || !(x <= b.x1 + b.width())) return false;
    // Most points lie amid grid cells of one clean place: their estimate,
    // a cell away from any other place, settles it.
    const PolygonIndex& index = *index_;
    const std::size_t col = index.column_of(x), row = index.row_of(y);
    if (b.contains(Point{x, y}) && col > 0 && row > 0 && col + 1 < index.columns() && row + 1 < index.rows()) {
        const PolygonIndex::Place place = index.cell_place(col, row);
        bool same = place != PolygonIndex::kOnOutline;
        for (std::size_t r = row - 1; r <= row + 1 && same; ++r)
            for (std::size_t c = col - 1; c <= col + 1 && same; ++c) same = index.cell_place(c, r) == place;
        if (same) return place == PolygonIndex::kInside;
    }
    std::vector<std::uint32_t> edges;
    index_->edges_in_rows(y, y, edges);
    bool odd = false;
    for (std::uint32_t e : edges) {
        const Point a = rings_->edge_start(e), c = rings_->edge_end(e);
        const int sa = height_sign(a.y, Y, W), sc = height_sign(c.y, Y, W);
        if ((sa > 0) == (sc > 0)) {
            // Not straddling: on the segment only at its height (an end, or horizontal).
            if ((sa == 0 || sc == 0) && !index.cancelled(e) && orient_exact(a, c, X, Y, W) == 0 &&
                within_segment(a, c, X, Y, W))
                return true;
            continue;
        }
        const Point& lo = sa > 0 ? c : a;
        const Point& hi = sa > 0 ? a : c;
        const int side = orient_exact(lo, hi, X, Y, W);
        if (side == 0 && index.cancelled(e)) continue;  // as PolygonIndex: the parity stands
        if (side == 0) return true;  // on the edge: the closed domain holds it
        if (side > 0) odd = !odd;    // the edge lies to the right of the point
    }
    return odd;
}

}  // namespace pds
