// dart_stage.cpp - dart throwing on a background grid (see dart_stage.hpp).
#include "dart_stage.hpp"

#include <algorithm>
#include <cmath>
#include <new>

#include "huge_pages.hpp"
#include "jones_stage.hpp"
#include "mesh_cells.hpp"
#include "predicates.hpp"

namespace pds {

namespace {

// An offset in [0, side) as a step count in [0, kOffsetSteps); rounding may
// put a point a hair outside its cell, hence the clamp.
std::uint64_t offset_steps(double offset, double step) {
    const double s = std::floor(offset / step);
    if (!(s > 0.0)) return 0;
    return s < 65535.0 ? static_cast<std::uint64_t>(s) : 65535;
}

// Cell f (a coordinate in cells) clamped into 0..n-1: rounding may put a
// point on the far edge of the last cell.
std::size_t clamped_cell(double f, std::size_t n) {
    const std::size_t c = f > 0.0 ? static_cast<std::size_t>(f) : 0;
    return std::min(c, n - 1);
}

std::size_t cells_along(double length, double side) {
    const double n = std::ceil(length / side);
    return n < 1.0 ? 1 : static_cast<std::size_t>(n);
}

}  // namespace

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
    window_ = std::max<std::size_t>(kMinWindow, cols_ * rows_ / 16);
    hilbert_side_ = 1;
    while (hilbert_side_ < cols_ || hilbert_side_ < rows_) hilbert_side_ *= 2;
}

void DartStage::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its vector as it was.
    points_.reserve(points);
    order_.reserve(points);
    tmp_order_.reserve(points);
    key_.reserve(points);
    tmp_key_.reserve(points);
}

DartStage::CellXY DartStage::column_row(const Point& p) const {
    return CellXY{clamped_cell((p.x - box_.x0) * inv_side_x_, cols_),
                  clamped_cell((p.y - box_.y0) * inv_side_y_, rows_)};
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

void DartStage::draw_batch(Rng& rng) {
    const double w = static_cast<double>(cols_) * side_x_, h = static_cast<double>(rows_) * side_y_;
    for (std::size_t k = 0; k < kMaxBatch; ++k) {
        Dart& d = batch_[k];
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
    batch_head_ = 0;
    batch_size_ = kMaxBatch;
}

void DartStage::aim(Dart& d) const {
    // Its cell as column_row() finds it, and the columns and rows within R.
    const double fx = (d.p.x - box_.x0) * inv_side_x_, fy = (d.p.y - box_.y0) * inv_side_y_;
    const std::size_t cx = clamped_cell(fx, cols_), cy = clamped_cell(fy, rows_);
    d.col = static_cast<std::int64_t>(cx);
    d.row = static_cast<std::int64_t>(cy);
    d.cell = (cy + kPad) * stride_ + cx + kPad;
    const auto offset = [](double f, std::int64_t own) {
        const double k = std::floor(f) - static_cast<double>(own);
        return k < -kPad ? -kPad : k > kPad ? kPad : static_cast<int>(k);
    };
    d.x_lo = offset(fx - reach_x_, d.col);
    d.x_hi = offset(fx + reach_x_, d.col);
    d.y_lo = offset(fy - reach_y_, d.row);
    d.y_hi = offset(fy + reach_y_, d.row);
}

bool DartStage::is_free(const Dart& d) const {
    // An occupied cell is covered whole (its diagonal is under R).
    if (cells_[d.cell] != 0) return false;
    const Point& p = d.p;
    for (int i = d.y_lo; i <= d.y_hi; ++i) {
        const std::size_t row = d.cell + static_cast<std::size_t>(i * static_cast<std::ptrdiff_t>(stride_));
        const double y0 = cell_y0(d.row + i);
        for (int j = d.x_lo; j <= d.x_hi; ++j) {
            const Cell word = cells_[row + j];
            if (word == 0) continue;
            const double qx = cell_x0(d.col + j) + (static_cast<double>((word >> 32) & 0xFFFF) + 0.5) * step_x_;
            const double qy = y0 + (static_cast<double>(word >> 48) + 0.5) * step_y_;
            const double dx = qx - p.x, dy = qy - p.y;
            const double d2 = dx * dx + dy * dy;
            if (d2 < r2_low_) return false;
            if (d2 < r2_high_) {
                ++exact_checks_;
                if (compare_distance(p, exact(row + j, word), r_) < 0) return false;
            }
        }
    }
    return true;
}

void DartStage::end_of_window() {
    if (static_cast<double>(window_hits_) < kMinAcceptance * static_cast<double>(window_darts_))
        over_ = true;
    window_darts_ = window_hits_ = 0;
}

const Point* DartStage::next(Rng& rng) {
    if (has_pending_) return &batch_[batch_head_ - 1].p;
    while (!over_) {
        if (batch_head_ == batch_size_) draw_batch(rng);
        const Dart& d = batch_[batch_head_++];
        ++window_darts_;
        const bool hit = box_.contains(d.p) && is_free(d);
        if (hit) ++window_hits_;
        if (window_darts_ == window_) end_of_window();
        if (hit) {
            has_pending_ = true;
            return &d.p;
        }
    }
    return nullptr;
}

void DartStage::add_next() {
    const Dart& d = batch_[batch_head_ - 1];
    const auto index = static_cast<std::uint32_t>(points_.size());
    write(d.col, d.row, d.p, index);
    if (torus_.on()) write_copies(d.col, d.row, d.p, index);
    points_.push_back(d.p);
    has_pending_ = false;
}

std::uint64_t DartStage::hilbert_key(const Point& p) const {
    // Position along a Hilbert curve over the cells (rotating each quadrant
    // so the curve stays continuous); nearby keys are nearby cells. 64 bits:
    // a side of up to 2^32 cells.
    const CellXY c = column_row(p);
    std::uint64_t x = c.x, y = c.y;
    std::uint64_t key = 0;
    // Without branches (they were most of the hand-over's sorting time, the
    // quadrants being random): the rotation is a flip by masks (s - 1 - v is
    // v ^ (s - 1) below s) and a masked swap. Only bits below s matter later.
    for (std::uint64_t s = hilbert_side_ / 2; s > 0; s /= 2) {
        const std::uint64_t rx = (x & s) != 0, ry = (y & s) != 0;
        key += s * s * ((3 * rx) ^ ry);
        const std::uint64_t low = s - 1;
        const std::uint64_t flip = (0 - (rx & (ry ^ 1))) & low;
        x = (x & low) ^ flip;
        y = (y & low) ^ flip;
        const std::uint64_t swap = (x ^ y) & (0 - (ry ^ 1));
        x ^= swap;
        y ^= swap;
    }
    return key;
}

void DartStage::insertion_order(std::uint32_t* order, std::uint64_t* key, std::uint32_t* tmp_order,
                                std::uint64_t* tmp_key) const {
    // Biased randomized insertion order (Amenta, Choi and Rote 2003): the
    // points come in rounds, each about three times the points before it,
    // and each round is sorted along the Hilbert curve. A round's points then
    // fall inside the triangulation of the earlier ones, near where the last
    // one went, so walks are short and flips stay local. The points are in
    // random order already (the order they were added in), so the rounds are
    // prefixes: ends n, n/4, n/16, ... down to 256 or fewer points.
    const std::size_t n = points_.size();
    std::size_t ends[64];
    std::size_t rounds = 0;
    for (std::size_t end = n; end > 0; end = end > 256 ? end / 4 : 0) ends[rounds++] = end;
    // Keys have 2 log2(side) bits: enough 11-bit radix passes to cover them.
    // The side stays below 2^30 cells: the stage runs only when Oler's bound
    // fits the index type (sampler.cpp), and a grid k cells long has a bound
    // of at least k/1.43 points; so keys fit 64 bits.
    int side_bits = 0;
    while ((std::uint64_t{1} << side_bits) < hilbert_side_) ++side_bits;
    const int key_bits = 2 * side_bits;
    constexpr int kDigit = 11;
    constexpr std::uint64_t kMask = (std::uint64_t{1} << kDigit) - 1;
    std::size_t begin = 0;
    for (std::size_t r = rounds; r-- > 0;) {
        const std::size_t end = ends[r];
        for (std::size_t i = begin; i < end; ++i) {
            key[i] = hilbert_key(points_[i]);
            order[i] = static_cast<std::uint32_t>(i);
        }
        // Stable LSD radix sort of [begin, end) by key.
        for (int shift = 0; shift < key_bits; shift += kDigit) {
            std::size_t count[kMask + 2] = {};
            for (std::size_t i = begin; i < end; ++i) ++count[((key[i] >> shift) & kMask) + 1];
            for (std::size_t d = 0; d <= kMask; ++d) count[d + 1] += count[d];
            for (std::size_t i = begin; i < end; ++i) {
                const std::size_t at = begin + count[(key[i] >> shift) & kMask]++;
                tmp_key[at] = key[i];
                tmp_order[at] = order[i];
            }
            std::copy(tmp_key + begin, tmp_key + end, key + begin);
            std::copy(tmp_order + begin, tmp_order + end, order + begin);
        }
        begin = end;
    }
}

const std::uint32_t* DartStage::handover_order() {
    // The stage ends here: its grid is released before the Jones stage's
    // mesh is filled, so the two never peak together.
    cells_.reset();
    over_ = true;
    has_pending_ = false;
    // Sizes within the reserved capacity: no allocation.
    const std::size_t n = points_.size();
    order_.resize(n);
    tmp_order_.resize(n);
    key_.resize(n);
    tmp_key_.resize(n);
    insertion_order(order_.data(), key_.data(), tmp_order_.data(), tmp_key_.data());
    return order_.data();
}

Delaunay DartStage::triangulate(std::vector<std::uint32_t>& order) const {
    const std::size_t n = points_.size();
    order.resize(n);
    std::vector<std::uint32_t> tmp_order(n);
    std::vector<std::uint64_t> key(n), tmp_key(n);
    insertion_order(order.data(), key.data(), tmp_order.data(), tmp_key.data());
    Delaunay mesh(box_);
    mesh.reserve(n + Delaunay::kGhosts);
    mesh.insert_in_order(points_, order.data(), n, [](std::uint32_t, VertexIndex) {});
    return mesh;
}

JonesStage DartStage::torus_stage(std::vector<std::uint32_t>& order) const {
    // On the torus the queries need the copies: a Jones stage of the points.
    const std::size_t n = points_.size();
    order.resize(n);
    std::vector<std::uint32_t> tmp_order(n);
    std::vector<std::uint64_t> key(n), tmp_key(n);
    insertion_order(order.data(), key.data(), tmp_order.data(), tmp_key.data());
    JonesStage stage(box_, r_, torus_);
    stage.reserve(n);
    stage.adopt(points_, order.data());
    stage.settle();
    return stage;
}

double DartStage::free_area() const {
    if (torus_.on()) {
        std::vector<std::uint32_t> order;
        return torus_stage(order).free_area();
    }
    std::vector<std::uint32_t> order;
    const Delaunay mesh = triangulate(order);
    return MeshCells(mesh, box_, r_).total_free_area();
}

VerifyReport DartStage::verify() const {
    if (torus_.on()) {
        std::vector<std::uint32_t> order;
        return torus_stage(order).verify();  // names points in the order added
    }
    std::vector<std::uint32_t> order;
    const Delaunay mesh = triangulate(order);
    VerifyReport rep = verify_pattern(mesh, box_, r_);
    if (rep.vertex != kNoVertex) name_point(rep, order[site_of(rep.vertex)]);
    return rep;
}

}  // namespace pds
