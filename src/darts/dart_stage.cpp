// dart_stage.cpp - dart throwing on a background grid (see dart_stage.hpp).
#include "darts/dart_stage.hpp"

#include <algorithm>
#include <cmath>
#include <new>

#include "darts/grid_cells.hpp"
#include "core/huge_pages.hpp"
#include "jones/jones_stage.hpp"
#include "jones/mesh_cells.hpp"
#include "core/predicates.hpp"

namespace pds {

DartStage::DartStage(const Box& domain, double radius, const Torus& torus)
    : box_(domain),
      r_(radius),
      r2_low_(radius * radius * (1.0 - kFilterSlack)),
      r2_high_(radius * radius * (1.0 + kFilterSlack)),
      torus_(torus) {
    const double side = kCellShrink * radius / std::sqrt(2.0);
    cols_ = cells_along(domain.width(), side);
    rows_ = cells_along(domain.height(), side);
    side_x_ = side_y_ = side;
    if (torus_.on()) {
        // Cells divide the periods: then a copy one period away sits exactly
        // cols_ (rows_) cells away. With R at most half a period the cells
        // stay wider than R/2 (at least 0.518 R), so the 5 x 5 block still
        // holds every point within R.
        cols_ = cells_along(torus_.px, side);
        rows_ = cells_along(torus_.py, side);
        side_x_ = torus_.px / static_cast<double>(cols_);
        side_y_ = torus_.py / static_cast<double>(rows_);
    }
    inv_side_x_ = 1.0 / side_x_;
    inv_side_y_ = 1.0 / side_y_;
    step_x_ = side_x_ / kOffsetSteps;
    step_y_ = side_y_ / kOffsetSteps;
    // Slack far above the rounding of a cell coordinate: a block a column
    // too wide costs a little time, one too narrow would be wrong.
    constexpr double kReachSlack = 1e-6;
    reach_x_ = radius * inv_side_x_ + kReachSlack;
    reach_y_ = radius * inv_side_y_ + kReachSlack;
    stride_ = cols_ + 2 * kPad;
    const std::size_t total = stride_ * (rows_ + 2 * kPad);
    if (total > static_cast<std::size_t>(-1) / sizeof(Cell)) throw std::bad_alloc();
    cells_.reset(static_cast<Cell*>(std::calloc(total, sizeof(Cell))));
    if (!cells_) throw std::bad_alloc();
    advise_huge_pages(cells_.get(), total * sizeof(Cell));
    // A window long enough that its acceptance rate is a fair estimate, short
    // enough that the stage ends soon after the rate falls.
    queue_.set_rule(std::max<std::size_t>(kMinWindow, cols_ * rows_ / 16), kMinAcceptance);
    curve_ = CurveOrder(box_, side_x_, side_y_, cols_, rows_);
}

void DartStage::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its vector as it was.
    points_.reserve(points);
    curve_.reserve(points);
}

void DartStage::write(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index) {
    const std::size_t cell = static_cast<std::size_t>(row + kPad) * stride_ + static_cast<std::size_t>(col + kPad);
    const std::uint64_t sx = offset_steps(p.x - cell_x0(col), step_x_);
    const std::uint64_t sy = offset_steps(p.y - cell_y0(row), step_y_);
    cells_[cell] = (sy << 48) | (sx << 32) | (std::uint64_t{index} + 1);
}

Point DartStage::exact(std::size_t cell, Cell word) const {
    const Point& p = points_[static_cast<std::uint32_t>(word) - 1];
    if (!torus_.on()) return p;
    // A copy sits in the padding, shifted toward the side it pads.
    const std::size_t col = cell % stride_, row = cell / stride_;
    const int i = col < kPad ? -1 : col >= cols_ + kPad ? 1 : 0;
    const int j = row < kPad ? -1 : row >= rows_ + kPad ? 1 : 0;
    return torus_.shifted(p, i, j);
}

void DartStage::write_copies(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index) {
    const auto cols = static_cast<std::int64_t>(cols_), rows = static_cast<std::int64_t>(rows_);
    for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
            if (i == 0 && j == 0) continue;
            const std::int64_t x = col + i * cols, y = row + j * rows;
            if (x < -kPad || x >= cols + kPad || y < -kPad || y >= rows + kPad) continue;
            write(x, y, torus_.shifted(p, i, j), index);
        }
    }
}

void DartStage::draw_batch(Dart* batch, std::size_t n, Rng& rng) {
    const double w = static_cast<double>(cols_) * side_x_, h = static_cast<double>(rows_) * side_y_;
    for (std::size_t k = 0; k < n; ++k) {
        Dart& d = batch[k];
        if (torus_.on()) {
            // On the torus grid, inside the fundamental domain (torus.hpp).
            const double u = rng.next_double(), v = rng.next_double();
            d.p = torus_.wrap(Point{Torus::snap(torus_.x0 + u * torus_.px), Torus::snap(torus_.y0 + v * torus_.py)});
        } else {
            d.p.x = box_.x0 + rng.next_double() * w;
            d.p.y = box_.y0 + rng.next_double() * h;
        }
        aim(d);
        // The block: 3 or 4 rows of at most 32 bytes, a line or two each.
        const Cell* row = cells_.get() + d.cell + d.y_lo * static_cast<std::ptrdiff_t>(stride_);
        for (int i = d.y_lo; i <= d.y_hi; ++i, row += stride_) {
            __builtin_prefetch(row + d.x_lo);
            __builtin_prefetch(row + d.x_hi);
        }
    }
}

void DartStage::aim(Dart& d) const {
    // Its cell (clamped: rounding may put a point on the far edge of the
    // last cell), and the columns and rows within R.
    const double fx = (d.p.x - box_.x0) * inv_side_x_, fy = (d.p.y - box_.y0) * inv_side_y_;
    const std::size_t cx = clamped_cell(fx, cols_), cy = clamped_cell(fy, rows_);
    d.col = static_cast<std::int64_t>(cx);
    d.row = static_cast<std::int64_t>(cy);
    d.cell = (cy + kPad) * stride_ + cx + kPad;
    d.x_lo = block_offset(fx - reach_x_, d.col, kPad);
    d.x_hi = block_offset(fx + reach_x_, d.col, kPad);
    d.y_lo = block_offset(fy - reach_y_, d.row, kPad);
    d.y_hi = block_offset(fy + reach_y_, d.row, kPad);
}

bool DartStage::is_free(const Dart& d) const {
    // An occupied cell is covered whole (its diagonal is under R).
    if (cells_[d.cell] != 0) return false;
    const Point& p = d.p;
    const auto stride = static_cast<std::ptrdiff_t>(stride_);
    // Whether the point in the cell i rows and j columns from the dart's
    // (if there is one) lies within R.
    const auto covers = [&](int i, int j) {
        const std::size_t cell = d.cell + static_cast<std::size_t>(i * stride + j);
        const Cell word = cells_[cell];
        if (word == 0) return false;
        const double qx = cell_x0(d.col + j) + (static_cast<double>((word >> 32) & 0xFFFF) + 0.5) * step_x_;
        const double qy = cell_y0(d.row + i) + (static_cast<double>(word >> 48) + 0.5) * step_y_;
        const double dx = qx - p.x, dy = qy - p.y;
        const double d2 = dx * dx + dy * dy;
        if (d2 < r2_low_) return true;
        if (!(d2 < r2_high_)) return false;
        ++exact_checks_;
        return compare_distance(p, exact(cell, word), r_) < 0;
    };
    // R spans more than one cell, so the block holds the eight around the
    // dart's own cell (grid_cells.hpp reads those first).
    return !block_covers(d.x_lo, d.x_hi, d.y_lo, d.y_hi, covers);
}

const Point* DartStage::next(Rng& rng) {
    const Dart* d = queue_.next([&](const Dart& x) { return box_.contains(x.p); },
                                [&](Dart* batch, std::size_t n) { draw_batch(batch, n, rng); },
                                [&](const Dart& x) { return is_free(x); });
    return d ? &d->p : nullptr;
}

void DartStage::add_next() {
    const Dart& d = queue_.pending();
    const auto index = static_cast<std::uint32_t>(points_.size());
    write(d.col, d.row, d.p, index);
    if (torus_.on()) write_copies(d.col, d.row, d.p, index);
    points_.push_back(d.p);
    queue_.take();
}

const std::uint32_t* DartStage::handover_order() {
    // The stage ends here: its grid is released before the Jones stage's
    // mesh is filled, so the two never peak together.
    cells_.reset();
    queue_.end();
    return curve_.order(points_);
}

Delaunay DartStage::triangulate(std::vector<std::uint32_t>& order) const {
    const std::size_t n = points_.size();
    order = curve_.fresh_order(points_);
    Delaunay mesh(box_);
    mesh.reserve(n + Delaunay::kGhosts);
    mesh.insert_in_order(points_, order.data(), n, [](std::uint32_t, VertexIndex) {});
    return mesh;
}

std::unique_ptr<JonesStage> DartStage::torus_stage(std::vector<std::uint32_t>& order) const {
    // On the torus the queries need the copies: a Jones stage of the points.
    order = curve_.fresh_order(points_);
    std::unique_ptr<JonesStage> stage = make_jones_stage(box_, r_, torus_);
    stage->reserve(points_.size());
    stage->adopt(points_, order.data());
    stage->settle();
    return stage;
}

double DartStage::free_area() const {
    if (torus_.on()) {
        std::vector<std::uint32_t> order;
        return torus_stage(order)->free_area();
    }
    std::vector<std::uint32_t> order;
    const Delaunay mesh = triangulate(order);
    return MeshCells(mesh, box_, r_).total_free_area();
}

VerifyReport DartStage::verify() const {
    if (torus_.on()) {
        std::vector<std::uint32_t> order;
        return torus_stage(order)->verify();  // names points in the order added
    }
    std::vector<std::uint32_t> order;
    const Delaunay mesh = triangulate(order);
    VerifyReport rep = verify_pattern(mesh, box_, r_);
    if (rep.vertex != kNoVertex) name_point(rep, order[site_of(rep.vertex)]);
    return rep;
}

}  // namespace pds
