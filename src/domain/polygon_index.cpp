// polygon_index.cpp - see polygon_index.hpp.
#include "domain/polygon_index.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>

#include "core/predicates.hpp"

namespace pds {

namespace {

double min_x(const Point& a, const Point& b) { return std::min(a.x, b.x); }
double max_x(const Point& a, const Point& b) { return std::max(a.x, b.x); }

// About sixteen cells per edge, at least 1024 and at most 2^22.
constexpr double kCellsPerEdge = 16.0;
constexpr double kMinCells = 1024.0;
// A cell stays wider than this share of the largest coordinate, so that the
// marking's slack dwarfs the rounding of an interpolation.
constexpr double kMinCellShare = 0x1p-40;
// An edge marks the cells within this share of a cell of it, or within
// 2^-44 of the largest coordinate if that is more (256 units in the last
// place; a cell is at least 2^-40 of it).
constexpr double kSlackShare = 0x1p-20;
constexpr double kSlackFloor = 0x1p-44;

}  // namespace

bool on_segment(const Point& p, const Point& a, const Point& b) {
    return p.x >= min_x(a, b) && p.x <= max_x(a, b) && p.y >= std::min(a.y, b.y) && p.y <= std::max(a.y, b.y) &&
           orient2d(a, b, p) == 0;
}

double PolygonIndex::cells_for_edges(const PolygonRings& rings) {
    return std::min(kMaxCells, std::max(kMinCells, kCellsPerEdge * static_cast<double>(rings.vertices())));
}

PolygonIndex::PolygonIndex(const PolygonRings& rings, double cells) : rings_(rings), box_(rings.bounds()) {
    const double w = box_.width(), h = box_.height();
    const double smallest = kMinCellShare * box_.largest_magnitude();
    // Square cells where the box allows; a box far taller than wide (or
    // wider than tall) gets one column (row) and at most `cells` rows (columns).
    double rows = std::min(cells, std::max(1.0, std::round(std::sqrt(cells * (h / w)))));
    double cols = std::min(cells, std::max(1.0, std::round(cells / rows)));
    rows = std::max(1.0, std::min(rows, std::floor(h / smallest)));
    cols = std::max(1.0, std::min(cols, std::floor(w / smallest)));
    rows_ = static_cast<std::size_t>(rows);
    cols_ = static_cast<std::size_t>(cols);
    col_scale_ = static_cast<double>(cols_) / w;
    row_scale_ = static_cast<double>(rows_) / h;
    cell_.assign(rows_ * cols_, static_cast<std::int8_t>(kInside));  // settled below
    cancelled_.assign(rings.vertices(), 0);

    // The rows' edge lists: count, then fill.
    const std::size_t edges = rings.vertices();
    row_begin_.assign(rows_ + 1, 0);
    for (std::size_t e = 0; e < edges; ++e) {
        const Point a = rings.edge_start(e), b = rings.edge_end(e);
        for (std::size_t r = row_of(std::min(a.y, b.y)); r <= row_of(std::max(a.y, b.y)); ++r) ++row_begin_[r + 1];
    }
    for (std::size_t r = 0; r < rows_; ++r) row_begin_[r + 1] += row_begin_[r];
    by_right_.resize(row_begin_[rows_]);
    std::vector<std::size_t> fill(row_begin_.begin(), row_begin_.end() - 1);
    for (std::size_t e = 0; e < edges; ++e) {
        const Point a = rings.edge_start(e), b = rings.edge_end(e);
        for (std::size_t r = row_of(std::min(a.y, b.y)); r <= row_of(std::max(a.y, b.y)); ++r)
            by_right_[fill[r]++] = static_cast<std::uint32_t>(e);
        mark_edge_cells(e);
    }
    // The cells' edge lists: the marking again, counted, then filled.
    cell_begin_.assign(rows_ * cols_ + 1, 0);
    for (std::size_t e = 0; e < edges; ++e)
        for_each_edge_cell(e, [&](std::size_t cell) { ++cell_begin_[cell + 1]; });
    for (std::size_t k = 0; k < rows_ * cols_; ++k) {
        if (cell_begin_[k + 1] > UINT32_MAX - cell_begin_[k]) throw std::bad_alloc();  // beyond 32-bit offsets
        cell_begin_[k + 1] += cell_begin_[k];
    }
    cell_edges_.resize(cell_begin_[rows_ * cols_]);
    std::vector<std::uint32_t> at(cell_begin_.begin(), cell_begin_.end() - 1);
    for (std::size_t e = 0; e < edges; ++e)
        for_each_edge_cell(e, [&](std::size_t cell) { cell_edges_[at[cell]++] = static_cast<std::uint32_t>(e); });
    by_left_ = by_right_;
    for (std::size_t r = 0; r < rows_; ++r) {
        const auto begin = static_cast<std::ptrdiff_t>(row_begin_[r]), end = static_cast<std::ptrdiff_t>(row_begin_[r + 1]);
        std::sort(by_right_.begin() + begin, by_right_.begin() + end, [&](std::uint32_t i, std::uint32_t j) {
            return max_x(rings_.edge_start(i), rings_.edge_end(i)) > max_x(rings_.edge_start(j), rings_.edge_end(j));
        });
        std::sort(by_left_.begin() + begin, by_left_.begin() + end, [&](std::uint32_t i, std::uint32_t j) {
            return min_x(rings_.edge_start(i), rings_.edge_end(i)) < min_x(rings_.edge_start(j), rings_.edge_end(j));
        });
    }
    settle_clean_cells();
}

void PolygonIndex::mark_edge_cells(std::size_t edge) {
    for_each_edge_cell(edge, [&](std::size_t cell) { cell_[cell] = static_cast<std::int8_t>(kOnOutline); });
}

template <class Visit>
void PolygonIndex::for_each_edge_cell(std::size_t edge, const Visit& visit) const {
    const Point a = rings_.edge_start(edge), b = rings_.edge_end(edge);
    const double y_lo = std::min(a.y, b.y), y_hi = std::max(a.y, b.y);
    const double x_lo = min_x(a, b), x_hi = max_x(a, b);
    const double row_height = 1.0 / row_scale_;
    // The slack: far above the rounding of the band's ends and of the
    // interpolation (a few units in the last place of the coordinates),
    // far below a cell.
    const double floor = kSlackFloor * box_.largest_magnitude();
    const double dy = std::max(kSlackShare * row_height, floor), dx = std::max(kSlackShare / col_scale_, floor);
    for (std::size_t r = row_of(y_lo); r <= row_of(y_hi); ++r) {
        // The edge's x range over this row's band, both widened by the slack.
        double from = x_lo, to = x_hi;
        if (y_hi > y_lo) {
            const double band_lo = std::max(y_lo, box_.y0 + static_cast<double>(r) * row_height - dy);
            const double band_hi = std::min(y_hi, box_.y0 + static_cast<double>(r + 1) * row_height + dy);
            const double slope = (b.x - a.x) / (b.y - a.y);
            const double u = a.x + (band_lo - a.y) * slope, v = a.x + (band_hi - a.y) * slope;
            from = std::max(x_lo, std::min(u, v) - dx);
            to = std::min(x_hi, std::max(u, v) + dx);
            if (!(from <= to)) from = x_lo, to = x_hi;  // a band the rounding emptied: the whole range
        }
        for (std::size_t c = column_of(from), last = column_of(to); c <= last; ++c) visit(r * cols_ + c);
    }
}

namespace {

// Index rows (or columns) lo..hi met by `count` consecutive cells of another grid.
struct Run {
    std::size_t lo, hi, count;
};

// The runs of cells 0..n-1 of another grid that meet the same index rows:
// span(i) gives cell i's first and last. Both never decrease along the grid
// (rounding is monotone), so each run's end is found by bisection: a few
// runs per index row, whatever n.
template <class Span>
std::vector<Run> runs_of(std::size_t n, const Span& span) {
    std::vector<Run> runs;
    for (std::size_t i = 0; i < n;) {
        const Run first = span(static_cast<double>(i));
        std::size_t last = i, beyond = n;  // span(last) is first's, span(beyond) is not (or beyond == n)
        while (beyond - last > 1) {
            const std::size_t mid = last + (beyond - last) / 2;
            const Run r = span(static_cast<double>(mid));
            if (r.lo <= first.lo && r.hi <= first.hi) last = mid;
            else beyond = mid;
        }
        runs.push_back(Run{first.lo, first.hi, last - i + 1});
        i = last + 1;
    }
    return runs;
}

}  // namespace

bool PolygonIndex::all_cells(const Box& b, Place place) const {
    return all_cells(column_of(b.x0), column_of(b.x1), row_of(b.y0), row_of(b.y1), place);
}

bool PolygonIndex::all_cells(std::size_t c0, std::size_t c1, std::size_t r0, std::size_t r1, Place place) const {
    for (std::size_t r = r0; r <= r1; ++r)
        for (std::size_t c = c0; c <= c1; ++c)
            if (cell_place(c, r) != place) return false;
    return true;
}

std::size_t PolygonIndex::grid_cells_not_outside(double x0, double sx, std::size_t cols, double y0, double sy,
                                                 std::size_t rows) const {
    // Which index rows a cell meets depends on its row alone, and runs of
    // rows meet the same ones (columns alike): a run of rows and a run of
    // columns are kept or not together.
    const std::vector<Run> row_runs =
        runs_of(rows, [&](double j) { return Run{row_of(y0 + j * sy), row_of(y0 + (j + 1.0) * sy), 1}; });
    const std::vector<Run> col_runs =
        runs_of(cols, [&](double i) { return Run{column_of(x0 + i * sx), column_of(x0 + (i + 1.0) * sx), 1}; });
    std::size_t kept = 0;
    for (const Run& r : row_runs)
        for (const Run& c : col_runs)
            if (!all_cells(c.lo, c.hi, r.lo, r.hi, kOutside)) kept += r.count * c.count;
    return kept;
}

void PolygonIndex::edges_near(const Box& b, std::vector<std::uint32_t>& out) const {
    const std::size_t from = out.size();
    const std::size_t c0 = column_of(b.x0), c1 = column_of(b.x1), r0 = row_of(b.y0), r1 = row_of(b.y1);
    for (std::size_t r = r0; r <= r1; ++r)
        for (std::size_t c = c0; c <= c1; ++c) {
            const std::size_t k = r * cols_ + c;
            out.insert(out.end(), cell_edges_.begin() + cell_begin_[k], cell_edges_.begin() + cell_begin_[k + 1]);
        }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
    out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(from), out.end()), out.end());
}

void PolygonIndex::edges_in_rows(double y_lo, double y_hi, std::vector<std::uint32_t>& out) const {
    const std::size_t from = out.size();
    const std::size_t r0 = row_of(y_lo), r1 = row_of(y_hi);
    for (std::size_t r = r0 == 0 ? 0 : r0 - 1; r <= std::min(rows_ - 1, r1 + 1); ++r)
        out.insert(out.end(), by_right_.begin() + static_cast<std::ptrdiff_t>(row_begin_[r]),
                   by_right_.begin() + static_cast<std::ptrdiff_t>(row_begin_[r + 1]));
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(from), out.end());
    out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(from), out.end()), out.end());
}

void PolygonIndex::settle_clean_cells() {
    for (std::size_t r = 0; r < rows_; ++r) {
        Place run = kOnOutline;  // the place of the clean run the last cell belonged to
        std::size_t settled_left = cols_;  // the last settled cell of the row, cols_ for none
        for (std::size_t c = 0; c < cols_; ++c) {
            std::int8_t& cell = cell_[r * cols_ + c];
            if (cell == kOnOutline) {
                run = kOnOutline;
                continue;
            }
            if (run == kOnOutline) {
                // Adjacent clean cells share their place: no edge separates them.
                // A new run is found from the last settled cell to its left,
                // through the cut cells between, or by the row's ray.
                const Point centre{box_.x0 + (static_cast<double>(c) + 0.5) / col_scale_,
                                   box_.y0 + (static_cast<double>(r) + 0.5) / row_scale_};
                if (column_of(centre.x) == c && row_of(centre.y) == r)
                    run = settled_left < c ? cast_toward(centre, r, c, kLeft, c - settled_left) : cast_ray(centre, r);
            }
            cell = static_cast<std::int8_t>(run);  // kOnOutline when no point of it was found
            if (run != kOnOutline) settled_left = c;
        }
    }
}

}  // namespace pds
