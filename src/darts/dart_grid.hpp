// dart_grid.hpp - the background grid of dart throwing with one radius R, on
// the plane or the torus: is this dart at least R from every point? record a
// point.
//
// Cells of side s = 0.99 R / sqrt 2, so a cell's diagonal is under R and no
// two points can share one; a point closer than R to a dart lies at most two
// cells away, and only in the 3 or 4 columns and rows that the dart's own
// disk reaches, so one dart reads at most a 4 x 4 block.
// A cell is 8 bytes: its point's index (plus one: 0 is an empty cell) and the
// point's offset in the cell rounded to 16 bits a side. Distances from the
// rounded offsets decide all but the pairs within 2^-12 of R (rounding moves
// a point by under 2^-17 of a cell, under 10^-5 R); those read the exact
// point and go to the exact predicate. So every decision is exact, whatever
// store holds the words (grid_storage.hpp): a dense and a sparse grid decide
// every dart alike. Half the bytes of whole coordinates: half the lines a
// dart misses, half the pages the kernel zeroes.
//
// On the torus the grid wraps: its cells divide the periods exactly and the
// padding holds the copies of the points along the opposite edges, so a
// dart's block sees every copy near it.
//
// Darts are drawn a batch at a time and their blocks prefetched before any
// is tested (throw_darts), so the cache misses of a batch overlap.
#ifndef PDS_DART_GRID_HPP
#define PDS_DART_GRID_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include "core/point.hpp"
#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "core/torus.hpp"
#include "domain/polygon.hpp"
#include "darts/curve_order.hpp"
#include "darts/dart_constants.hpp"
#include "darts/fixed_disks.hpp"
#include "darts/grid_arithmetic.hpp"
#include "darts/grid_storage.hpp"
#include "darts/polygon_raster.hpp"

namespace pds {

class PointRadii;

template <class Cells>
class DartGrid {
public:
    static constexpr bool kVarying = false;  // one radius: no per-point values

    struct Dart {
        Point p;
        GridCell cell;          // its cell's number in the padded grid
        std::int64_t col, row;  // its cell's column and row, without the padding
        // The cells the dart's disk reaches, relative to its own: columns
        // x_lo..x_hi and rows y_lo..y_hi, each within -kPad..kPad.
        int x_lo, x_hi, y_lo, y_hi;
        bool inside;  // drawn in a cell wholly inside keep_to's polygon
    };

    // domain and radius in the internal frame; throws std::bad_alloc.
    DartGrid(const Box& domain, double radius, const Torus& torus = Torus{});

    // Room for `points` points and their copies; strong guarantee.
    void reserve(std::size_t points) { cells_.reserve(points, points * writes_per_point()); }
    bool has_room_for(std::size_t points) const { return cells_.has_room_for(points, points * writes_per_point()); }

    // n darts uniform over the grid's cells (on the torus, on its grid inside
    // the fundamental domain; with keep_to, over the cells kept), aimed,
    // their blocks prefetched.
    void throw_darts(Dart* batch, std::size_t n, Rng& rng) const;
    // Darts from now on only where the polygon's grid does not say outside:
    // uniform over that union of its cells, which holds the polygon (a dart
    // drawn in an outside cell is drawn again, at the cost of one lookup in
    // a small array). A polygon that fills little of the box (raster_suits)
    // has its darts drawn among the grid cells it may meet instead
    // (polygon_raster.hpp), each cell alike. The polygon must outlive the grid.
    void keep_to(const Polygon& polygon);
    // Whether d lies in keep_to's polygon without testing it.
    static bool surely_inside(const Dart& d) { return d.inside; }
    // Whether d is at least R from every point; points[k] is point k.
    bool is_free(const Dart& d, const std::vector<Point>& points, const std::vector<double>&) const;
    // Records point `index` at d (and its copies on the torus).
    void record(const Dart& d, std::uint32_t index);
    // Frees the cells: the stage is over.
    void release() { cells_.release(); }
    // One radius needs no memory budget: its points fill the cells they touch.
    static bool past_memory_budget() { return false; }

    // The sampling rule's scale: the grid's cells (those kept, with keep_to).
    GridCell cell_count() const { return keep_ ? GridCell{kept_cells_} : GridCell{cols_} * rows_; }
    // The hand-over's curve over the grid's cells.
    CurveOrder curve(const Box& domain) const { return CurveOrder(domain, side_x_, side_y_, cols_, rows_); }
    // The real cells (no padding), for laying fixed disks over them, and a
    // dart's cell there.
    DiskGrid disk_grid() const { return DiskGrid{box_, cols_, rows_, side_x_, side_y_}; }
    static std::uint32_t disk_cell(const Dart& d, const DiskGrid& g) {
        return static_cast<std::uint32_t>(static_cast<std::size_t>(d.row) * g.cols + static_cast<std::size_t>(d.col));
    }
    double radius() const { return r_; }
    const Torus& torus() const { return torus_; }
    const PointRadii* radii() const { return nullptr; }
    const Cells& cells() const { return cells_; }
    // Whether keep_to's darts are drawn among its polygon's raster (tests).
    bool draws_in_raster() const { return raster_.cells() > 0; }
    // Distances the rounded offsets left undecided, sent to the exact
    // predicate (for tests: the path must be taken).
    std::size_t exact_checks() const { return exact_checks_; }

private:
    using Word = std::uint64_t;  // bits 0-31: index + 1; 32-47, 48-63: the offset along x, y

    // Cells a point and its copies may take: on the torus a copy one period
    // away along x when the point lies within kPad columns of a side (both
    // ways only on a grid under 2 kPad columns), the same along y, and the
    // diagonal ones.
    std::size_t writes_per_point() const {
        if (!torus_.on()) return 1;
        const std::size_t x = cols_ < 2 * darts::kPad ? 3 : 2, y = rows_ < 2 * darts::kPad ? 3 : 2;
        return x * y;
    }
    // The lower left corner of the cell in column col, row row (the padding's
    // are negative or past the last): one formula, for writing and reading.
    double cell_x0(std::int64_t col) const { return box_.x0 + static_cast<double>(col) * side_x_; }
    double cell_y0(std::int64_t row) const { return box_.y0 + static_cast<double>(row) * side_y_; }
    // Point `index` (or its copy) p into the cell in column col, row row.
    void write(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index);
    // The exact point of a nonempty cell (its copy, in the padding of a torus).
    Point exact(GridCell cell, Word word, const std::vector<Point>& points) const;
    void aim(Dart& d) const;  // fills d's cell, column, row and block from d.p

    Box box_;
    double r_;
    double r2_low_, r2_high_;  // R^2 bracketing the rounding of a squared distance
    double side_x_, side_y_;   // s, or on the torus the periods divided evenly
    double inv_side_x_, inv_side_y_;
    double step_x_, step_y_;    // an offset step: side / kOffsetSteps
    double reach_x_, reach_y_;  // R in cells, with a little slack
    Torus torus_;
    std::size_t cols_ = 0, rows_ = 0;  // real cells; the padded row has cols_ + 2 kPad
    GridCell stride_ = 0;
    const PolygonIndex* keep_ = nullptr;  // keep_to's polygon grid, or none
    PolygonRaster raster_;                // or, for a polygon filling little of the box, its cells
    std::size_t kept_cells_ = 0;          // grid cells darts are drawn in
    Cells cells_;
    mutable std::size_t exact_checks_ = 0;
};

template <class Cells>
DartGrid<Cells>::DartGrid(const Box& domain, double radius, const Torus& torus)
    : box_(domain),
      r_(radius),
      r2_low_(radius * radius * (1.0 - darts::kFilterSlack)),
      r2_high_(radius * radius * (1.0 + darts::kFilterSlack)),
      torus_(torus) {
    using namespace darts;
    // On the torus the cells divide the periods (grid_axis).
    const bool on = torus_.on();
    const GridAxis x = grid_axis(on ? torus_.px : domain.width(), cell_side(radius), radius, on);
    const GridAxis y = grid_axis(on ? torus_.py : domain.height(), cell_side(radius), radius, on);
    cols_ = x.count;
    rows_ = y.count;
    side_x_ = x.side;
    side_y_ = y.side;
    inv_side_x_ = x.inv;
    inv_side_y_ = y.inv;
    step_x_ = x.step;
    step_y_ = y.step;
    reach_x_ = x.reach;
    reach_y_ = y.reach;
    stride_ = GridCell{cols_} + 2 * kPad;
    const GridCell padded_rows = GridCell{rows_} + 2 * kPad;
    if (padded_rows > static_cast<GridCell>(-1) / stride_) throw std::bad_alloc();
    cells_ = Cells(stride_ * padded_rows);
}

template <class Cells>
void DartGrid<Cells>::write(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index) {
    using darts::kPad;
    const GridCell cell = static_cast<GridCell>(row + kPad) * stride_ + static_cast<GridCell>(col + kPad);
    const std::uint64_t sx = offset_steps(p.x - cell_x0(col), step_x_);
    const std::uint64_t sy = offset_steps(p.y - cell_y0(row), step_y_);
    cells_.set(cell, (sy << 48) | (sx << 32) | (std::uint64_t{index} + 1));
}

template <class Cells>
Point DartGrid<Cells>::exact(GridCell cell, Word word, const std::vector<Point>& points) const {
    using darts::kPad;
    const Point& p = points[static_cast<std::uint32_t>(word) - 1];
    if (!torus_.on()) return p;
    // A copy sits in the padding, shifted toward the side it pads.
    const GridCell col = cell % stride_, row = cell / stride_;
    const int i = col < kPad ? -1 : col >= cols_ + kPad ? 1 : 0;
    const int j = row < kPad ? -1 : row >= rows_ + kPad ? 1 : 0;
    return torus_.shifted(p, i, j);
}

template <class Cells>
void DartGrid<Cells>::record(const Dart& d, std::uint32_t index) {
    using darts::kPad;
    write(d.col, d.row, d.p, index);
    if (!torus_.on()) return;
    // The copies into the padding.
    const auto cols = static_cast<std::int64_t>(cols_), rows = static_cast<std::int64_t>(rows_);
    for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
            if (i == 0 && j == 0) continue;
            const std::int64_t x = d.col + i * cols, y = d.row + j * rows;
            if (x < -kPad || x >= cols + kPad || y < -kPad || y >= rows + kPad) continue;
            write(x, y, torus_.shifted(d.p, i, j), index);
        }
    }
}

template <class Cells>
void DartGrid<Cells>::throw_darts(Dart* batch, std::size_t n, Rng& rng) const {
    const double w = static_cast<double>(cols_) * side_x_, h = static_cast<double>(rows_) * side_y_;
    for (std::size_t k = 0; k < n; ++k) {
        Dart& d = batch[k];
        d.inside = false;
        if (raster_.cells() > 0) {
            const PolygonRaster::Dart r = raster_.draw(rng);
            d.p = r.p;
            d.inside = r.inside;
        } else if (keep_) {
            do {
                d.p.x = box_.x0 + rng.next_double() * w;
                d.p.y = box_.y0 + rng.next_double() * h;
            } while (keep_->cell_place(keep_->column_of(d.p.x), keep_->row_of(d.p.y)) == PolygonIndex::kOutside);
        } else if (torus_.on()) {
            // On the torus grid, inside the fundamental domain (torus.hpp).
            const double u = rng.next_double(), v = rng.next_double();
            d.p = torus_.wrap(Point{Torus::snap(torus_.x0 + u * torus_.px), Torus::snap(torus_.y0 + v * torus_.py)});
        } else {
            d.p.x = box_.x0 + rng.next_double() * w;
            d.p.y = box_.y0 + rng.next_double() * h;
        }
        aim(d);
        // The block: 3 or 4 rows of at most 32 bytes, a line or two each.
        GridCell row = d.cell + static_cast<GridCell>(d.y_lo * static_cast<std::int64_t>(stride_));
        for (int i = d.y_lo; i <= d.y_hi; ++i, row += stride_) {
            cells_.prefetch(row + static_cast<GridCell>(d.x_lo));
            cells_.prefetch(row + static_cast<GridCell>(d.x_hi));
        }
    }
}

template <class Cells>
void DartGrid<Cells>::keep_to(const Polygon& polygon) {
    if (torus_.on()) return;  // no polygon on the torus
    keep_ = &polygon.index();
    if (raster_suits(polygon, box_)) {
        // Past its budget (raster_band_budget) a bounded run in a polygon far
        // larger than its points draws over the outline grid's cells instead;
        // so it does where the raster holds more than the outline grid's
        // cells (cells far wider than the polygon's parts: large R).
        if (raster_.build(polygon, box_.x0, side_x_, cols_, box_.y0, side_y_, rows_,
                          raster_band_budget(polygon, side_x_ * side_y_)) &&
            !(static_cast<double>(raster_.cells()) * side_x_ * side_y_ < polygon.candidate_area()))
            raster_ = PolygonRaster();
    }
    kept_cells_ = raster_.cells() > 0
                      ? raster_.cells()
                      : keep_->grid_cells_not_outside(box_.x0, side_x_, cols_, box_.y0, side_y_, rows_);
    cells_.writes_only_in(kept_cells_);
}

template <class Cells>
void DartGrid<Cells>::aim(Dart& d) const {
    using darts::kPad;
    // Its cell (clamped: rounding may put a point on the far edge of the
    // last cell), and the columns and rows within R.
    const double fx = (d.p.x - box_.x0) * inv_side_x_, fy = (d.p.y - box_.y0) * inv_side_y_;
    const std::size_t cx = clamped_cell(fx, cols_), cy = clamped_cell(fy, rows_);
    d.col = static_cast<std::int64_t>(cx);
    d.row = static_cast<std::int64_t>(cy);
    d.cell = (GridCell{cy} + kPad) * stride_ + cx + kPad;
    d.x_lo = block_offset(fx - reach_x_, d.col, kPad);
    d.x_hi = block_offset(fx + reach_x_, d.col, kPad);
    d.y_lo = block_offset(fy - reach_y_, d.row, kPad);
    d.y_hi = block_offset(fy + reach_y_, d.row, kPad);
}

template <class Cells>
bool DartGrid<Cells>::is_free(const Dart& d, const std::vector<Point>& points, const std::vector<double>&) const {
    // An occupied cell is covered whole (its diagonal is under R).
    if (cells_.get(d.cell) != 0) return false;
    const Point& p = d.p;
    const auto stride = static_cast<std::int64_t>(stride_);
    // Whether the point in the cell i rows and j columns from the dart's
    // (if there is one) lies within R.
    const auto covers = [&](int i, int j) {
        const GridCell cell = d.cell + static_cast<GridCell>(i * stride + j);
        const Word word = cells_.get(cell);
        if (word == 0) return false;
        const double qx = cell_x0(d.col + j) + (static_cast<double>((word >> 32) & 0xFFFF) + 0.5) * step_x_;
        const double qy = cell_y0(d.row + i) + (static_cast<double>(word >> 48) + 0.5) * step_y_;
        const double dx = qx - p.x, dy = qy - p.y;
        const double d2 = dx * dx + dy * dy;
        if (d2 < r2_low_) return true;
        if (!(d2 < r2_high_)) return false;
        ++exact_checks_;
        return compare_distance(p, exact(cell, word, points), r_) < 0;
    };
    // R spans more than one cell, so the block holds the eight around the
    // dart's own cell (grid_arithmetic.hpp reads those first).
    return !block_covers(d.x_lo, d.x_hi, d.y_lo, d.y_hi, covers);
}

}  // namespace pds

#endif
