// polygon_locate.cpp - PolygonIndex's ray casts: where a point lies, read
// from its cell, or by a short ray to the nearest clean cell, or by the
// row's ray; and what that costs on average, which decides whether a finer
// index should locate points (see polygon_index.hpp).
#include <algorithm>
#include <cstdint>

#include "core/predicates.hpp"
#include "domain/polygon_index.hpp"

namespace pds {

namespace {

double min_x(const Point& a, const Point& b) { return std::min(a.x, b.x); }
double max_x(const Point& a, const Point& b) { return std::max(a.x, b.x); }

// A short ray goes at most this many cells.
constexpr std::size_t kReach = 32;
// The directions right, left, up, down as steps of column and row.
constexpr std::ptrdiff_t kStepColumn[4] = {1, -1, 0, 0}, kStepRow[4] = {0, 0, 1, -1};
// An index whose located points read more edges than this on average gets
// a finer one for locating, with this many times the cells (at most kMaxCells).
constexpr double kCostlyEdgesRead = 2.0;
constexpr double kFinerForLocation = 16.0;

// The four directions a short ray may take, as rotations that turn it to +x
// (exact: they only swap and negate coordinates, and keep orientations).
Point turned(const Point& p, int dir) {
    switch (dir) {
        case 1:
            return Point{-p.x, -p.y};  // left
        case 2:
            return Point{p.y, -p.x};  // up
        case 3:
            return Point{-p.y, p.x};  // down
        default:
            return p;  // right
    }
}

// Moves cell (c, r) one step in direction dir.
void step(std::size_t& c, std::size_t& r, int dir) {
    c = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + kStepColumn[dir]);
    r = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(r) + kStepRow[dir]);
}

}  // namespace

PolygonIndex::Place PolygonIndex::locate(const Point& p) const {
    if (!box_.contains(p)) return kOutside;
    const std::size_t r = row_of(p.y), c = column_of(p.x);
    const Place clean = cell_place(c, r);
    return clean != kOnOutline ? clean : cast_short_ray(p, r, c);
}

bool PolygonIndex::nearest_clean(std::size_t row, std::size_t col, int& dir, std::size_t& steps) const {
    dir = -1;
    steps = kReach + 1;
    for (int d = 0; d < 4; ++d) {
        std::ptrdiff_t c = static_cast<std::ptrdiff_t>(col), r = static_cast<std::ptrdiff_t>(row);
        for (std::size_t k = 1; k < steps; ++k) {
            c += kStepColumn[d];
            r += kStepRow[d];
            if (c < 0 || r < 0 || c >= static_cast<std::ptrdiff_t>(cols_) || r >= static_cast<std::ptrdiff_t>(rows_))
                break;
            if (cell_place(static_cast<std::size_t>(c), static_cast<std::size_t>(r)) != kOnOutline) {
                dir = d;
                steps = k;
                break;
            }
        }
    }
    return dir >= 0;
}

double PolygonIndex::expected_edges_read() const {
    // A point uniform in the box: a cut cell's short ray reads the lists of
    // the cells it passes (repeats included), the row's ray about half the row.
    double total = 0.0;
    for (std::size_t r = 0; r < rows_; ++r)
        for (std::size_t c = 0; c < cols_; ++c) {
            if (cell_place(c, r) != kOnOutline) continue;
            int dir = -1;
            std::size_t steps = 0;
            if (!nearest_clean(r, c, dir, steps)) {
                total += 0.5 * static_cast<double>(row_begin_[r + 1] - row_begin_[r]);
                continue;
            }
            std::size_t cc = c, rr = r;
            for (std::size_t k = 0; k < steps; ++k, step(cc, rr, dir)) {
                const std::size_t cell = rr * cols_ + cc;
                total += static_cast<double>(cell_begin_[cell + 1] - cell_begin_[cell]);
            }
        }
    return total / static_cast<double>(rows_ * cols_);
}

double PolygonIndex::finer_cells_for_location() const {
    if (!(expected_edges_read() > kCostlyEdgesRead)) return 0.0;
    const double cells = static_cast<double>(rows_ * cols_);
    const double finer = std::min(kMaxCells, kFinerForLocation * cells);
    return finer >= 4.0 * cells ? finer : 0.0;
}

PolygonIndex::Place PolygonIndex::cast_short_ray(const Point& p, std::size_t row, std::size_t col) const {
    // Along the row or column, toward the nearest clean cell (right, left,
    // up, down; at most kReach cells): its place, flipped by each crossing
    // of the segment from p to a point q inside it. The edges that can
    // cross are those of the marked cells in between, each counted once.
    // The crossing test is the ray cast's, on the points turned so the ray
    // runs along +x.
    int dir = -1;
    std::size_t steps = 0;
    if (!nearest_clean(row, col, dir, steps)) return cast_ray(p, row);  // no clean cell near: the whole row
    return cast_toward(p, row, col, dir, steps);
}

PolygonIndex::Place PolygonIndex::cast_toward(const Point& p, std::size_t row, std::size_t col, int dir,
                                              std::size_t steps) const {
    constexpr std::size_t kMaxEdges = 128;
    std::uint32_t edges[kMaxEdges];
    std::size_t n = 0;
    std::size_t c = col, r = row;
    for (std::size_t k = 0; k < steps; ++k, step(c, r, dir)) {
        const std::size_t cell = r * cols_ + c;
        for (std::uint32_t at = cell_begin_[cell]; at < cell_begin_[cell + 1]; ++at) {
            if (n == kMaxEdges) return cast_ray(p, row);  // a crowded neighbourhood: the whole row
            edges[n++] = cell_edges_[at];
        }
    }
    std::sort(edges, edges + n);
    n = static_cast<std::size_t>(std::unique(edges, edges + n) - edges);
    // q: p moved along the ray to the clean cell's middle line.
    Point q = p;
    if (dir == kRight || dir == kLeft)
        q.x = box_.x0 + (static_cast<double>(c) + 0.5) / col_scale_;
    else
        q.y = box_.y0 + (static_cast<double>(r) + 0.5) / row_scale_;
    if (column_of(q.x) != c || row_of(q.y) != r) return cast_ray(p, row);
    const Point tp = turned(p, dir), tq = turned(q, dir);
    bool odd = cell_place(c, r) == kInside;
    for (std::size_t i = 0; i < n; ++i) {
        const Point a = turned(rings_.edge_start(edges[i]), dir), b = turned(rings_.edge_end(edges[i]), dir);
        if ((a.y > tp.y) == (b.y > tp.y)) {
            if (on_segment(tp, a, b) && !cancelled(edges[i])) return kOnOutline;
            continue;
        }
        const Point& lo = a.y > tp.y ? b : a;
        const Point& hi = a.y > tp.y ? a : b;
        const int side = orient2d(lo, hi, tp);
        if (side == 0) {
            if (!cancelled(edges[i])) return kOnOutline;
            continue;  // its copy is skipped alike: the parity stands
        }
        // The edge crosses the ray beyond p; before q unless q lies left of it.
        if (side == 1 && orient2d(lo, hi, tq) == -1) odd = !odd;
    }
    return odd ? kInside : kOutside;
}

PolygonIndex::Place PolygonIndex::cast_ray(const Point& p, std::size_t row) const {
    const std::uint32_t* right = by_right_.data() + row_begin_[row];
    const std::uint32_t* left = by_left_.data() + row_begin_[row];
    const std::size_t n = row_begin_[row + 1] - row_begin_[row];
    // Edges that reach p's x or beyond, on each side (the lists are sorted).
    const std::size_t n_right = static_cast<std::size_t>(
        std::partition_point(right, right + n,
                             [&](std::uint32_t e) { return max_x(rings_.edge_start(e), rings_.edge_end(e)) >= p.x; }) -
        right);
    const std::size_t n_left = static_cast<std::size_t>(
        std::partition_point(left, left + n,
                             [&](std::uint32_t e) { return min_x(rings_.edge_start(e), rings_.edge_end(e)) <= p.x; }) -
        left);
    // Either ray gives the parity; an edge through p is among both lists.
    const bool to_right = n_right <= n_left;
    const std::uint32_t* edges = to_right ? right : left;
    const std::size_t count = to_right ? n_right : n_left;
    const int crossing_side = to_right ? 1 : -1;
    bool odd = false;
    for (std::size_t k = 0; k < count; ++k) {
        const Point a = rings_.edge_start(edges[k]), b = rings_.edge_end(edges[k]);
        if ((a.y > p.y) == (b.y > p.y)) {
            if (on_segment(p, a, b) && !cancelled(edges[k])) return kOnOutline;  // horizontal, or touching at an end
            continue;
        }
        const Point& lo = a.y > p.y ? b : a;
        const Point& hi = a.y > p.y ? a : b;
        const int side = orient2d(lo, hi, p);
        if (side == 0) {  // straddles p's height and passes through p
            if (!cancelled(edges[k])) return kOnOutline;
            continue;
        }
        if (side == crossing_side) odd = !odd;
    }
    return odd ? kInside : kOutside;
}

}  // namespace pds
