// dart_grid.cpp - dart throwing on a background grid (see dart_grid.hpp).
#include "dart_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include "predicates.hpp"

namespace pds {

namespace {

std::uint64_t bits_of(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

double from_bits(std::uint64_t b) {
    double v;
    std::memcpy(&v, &b, sizeof v);
    return v;
}

std::size_t cells_along(double length, double side) {
    const double n = std::ceil(length / side);
    return n < 1.0 ? 1 : static_cast<std::size_t>(n);
}

}  // namespace

DartGrid::DartGrid(const Box& domain, double radius)
    : box_(domain),
      r_(radius),
      r2_low_(radius * radius * (1.0 - 0x1.0p-40)),
      r2_high_(radius * radius * (1.0 + 0x1.0p-40)),
      side_(0.99 * radius / std::sqrt(2.0)),
      inv_side_(1.0 / side_) {
    cols_ = cells_along(domain.width(), side_);
    rows_ = cells_along(domain.height(), side_);
    stride_ = cols_ + 2 * kPad;
    const std::size_t total = stride_ * (rows_ + 2 * kPad);
    if (total > static_cast<std::size_t>(-1) / sizeof(Cell)) throw std::bad_alloc();
    cells_.reset(static_cast<Cell*>(std::calloc(total, sizeof(Cell))));
    if (!cells_) throw std::bad_alloc();
    // A window long enough that its acceptance rate is a fair estimate, short
    // enough that the stage ends soon after the rate falls.
    window_ = std::max<std::size_t>(256, cols_ * rows_ / 16);
    hilbert_side_ = 1;
    while (hilbert_side_ < cols_ || hilbert_side_ < rows_) hilbert_side_ *= 2;
}

void DartGrid::reserve(std::size_t points) { points_.reserve(points); }

DartGrid::CellXY DartGrid::column_row(const Point& p) const {
    // Clamped: rounding may put a point on the far edge of the last cell.
    const double fx = (p.x - box_.x0) * inv_side_, fy = (p.y - box_.y0) * inv_side_;
    const std::size_t cx = fx > 0.0 ? static_cast<std::size_t>(fx) : 0;
    const std::size_t cy = fy > 0.0 ? static_cast<std::size_t>(fy) : 0;
    return CellXY{std::min(cx, cols_ - 1), std::min(cy, rows_ - 1)};
}

std::size_t DartGrid::cell_of(const Point& p) const {
    const CellXY c = column_row(p);
    return (c.y + kPad) * stride_ + c.x + kPad;
}

Point DartGrid::read(const Cell& cell) const {
    // Empty cells read as NaN: every comparison with such a point is false.
    return Point{from_bits(~cell.x_bits), from_bits(~cell.y_bits)};
}

void DartGrid::write(std::size_t cell, const Point& p) {
    cells_[cell].x_bits = ~bits_of(p.x);
    cells_[cell].y_bits = ~bits_of(p.y);
}

void DartGrid::draw_batch(Rng& rng) {
    const double w = static_cast<double>(cols_) * side_, h = static_cast<double>(rows_) * side_;
    for (std::size_t k = 0; k < kBatch; ++k) {
        Dart& d = batch_[k];
        d.p.x = box_.x0 + rng.next_double() * w;
        d.p.y = box_.y0 + rng.next_double() * h;
        d.cell = cell_of(d.p);
        // The 5 x 5 block: five rows of 80 bytes, two cache lines each at most.
        const Cell* row = cells_.get() + d.cell - kPad * stride_ - kPad;
        for (int i = 0; i < 2 * kPad + 1; ++i, row += stride_) {
            __builtin_prefetch(row);
            __builtin_prefetch(row + 2 * kPad);
        }
    }
    batch_head_ = 0;
    batch_size_ = kBatch;
}

bool DartGrid::is_free(const Point& p, std::size_t cell) const {
    // An occupied cell is covered whole (its diagonal is under R).
    if (cells_[cell].x_bits != 0) return false;
    const Cell* row = cells_.get() + cell - kPad * stride_ - kPad;
    for (int i = 0; i < 2 * kPad + 1; ++i, row += stride_) {
        for (int j = 0; j < 2 * kPad + 1; ++j) {
            const Point q = read(row[j]);
            const double dx = q.x - p.x, dy = q.y - p.y;
            const double d2 = dx * dx + dy * dy;
            if (d2 < r2_low_) return false;
            if (d2 < r2_high_ && compare_distance(p, q, r_) < 0) return false;
        }
    }
    return true;
}

void DartGrid::end_of_window() {
    if (static_cast<double>(window_hits_) < kMinAcceptance * static_cast<double>(window_darts_))
        over_ = true;
    window_darts_ = window_hits_ = 0;
}

bool DartGrid::add_one(Rng& rng) {
    while (!over_) {
        if (batch_head_ == batch_size_) draw_batch(rng);
        const Dart d = batch_[batch_head_++];
        ++window_darts_;
        const bool hit = box_.contains(d.p) && is_free(d.p, d.cell);
        if (hit) {
            write(d.cell, d.p);
            points_.push_back(d.p);
            ++window_hits_;
        }
        if (window_darts_ == window_) end_of_window();
        if (hit) return true;
    }
    return false;
}

std::uint32_t DartGrid::hilbert_key(const Point& p) const {
    // Position along a Hilbert curve over the cells (rotating each quadrant
    // so the curve stays continuous); nearby keys are nearby cells.
    const CellXY c = column_row(p);
    std::uint32_t x = static_cast<std::uint32_t>(c.x);
    std::uint32_t y = static_cast<std::uint32_t>(c.y);
    std::uint32_t key = 0;
    for (std::uint32_t s = hilbert_side_ / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) != 0, ry = (y & s) != 0;
        key += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - (x & (s - 1));
                y = s - 1 - (y & (s - 1));
            }
            std::swap(x, y);
        }
    }
    return key;
}

std::vector<std::uint32_t> DartGrid::insertion_order() const {
    // Biased randomized insertion order (Amenta, Choi and Rote 2003): the
    // points come in rounds, each about three times the points before it,
    // and each round is sorted along the Hilbert curve. A round's points then
    // fall inside the triangulation of the earlier ones, near where the last
    // one went, so walks are short and flips stay local. The points are in
    // random order already (the order they were added in), so the rounds are
    // prefixes.
    const std::size_t n = points_.size();
    std::vector<std::uint32_t> order(n), key(n), tmp_key(n), tmp_order(n);
    std::vector<std::size_t> ends;
    for (std::size_t end = n; end > 0; end = end > 256 ? end / 4 : 0) ends.push_back(end);
    std::size_t begin = 0;
    for (auto it = ends.rbegin(); it != ends.rend(); ++it) {
        const std::size_t end = *it;
        for (std::size_t i = begin; i < end; ++i) {
            key[i] = hilbert_key(points_[i]);
            order[i] = static_cast<std::uint32_t>(i);
        }
        // Three 10-bit radix passes: keys stay below 2^30 (the grid is
        // bounded by the point count, see Sampler::max_points).
        constexpr int kDigit = 10;
        constexpr std::uint32_t kMask = (1u << kDigit) - 1;
        for (int shift = 0; shift < 3 * kDigit; shift += kDigit) {
            std::size_t count[kMask + 2] = {};
            for (std::size_t i = begin; i < end; ++i) ++count[((key[i] >> shift) & kMask) + 1];
            for (std::size_t d = 0; d <= kMask; ++d) count[d + 1] += count[d];
            for (std::size_t i = begin; i < end; ++i) {
                const std::size_t at = begin + count[(key[i] >> shift) & kMask]++;
                tmp_key[at] = key[i];
                tmp_order[at] = order[i];
            }
            std::copy(tmp_key.begin() + begin, tmp_key.begin() + end, key.begin() + begin);
            std::copy(tmp_order.begin() + begin, tmp_order.begin() + end, order.begin() + begin);
        }
        begin = end;
    }
    return order;
}

bool DartGrid::finds_free_spot() const {
    // Candidates: each empty cell's centre and corners, moved into the domain.
    for (std::size_t cy = 0; cy < rows_; ++cy) {
        for (std::size_t cx = 0; cx < cols_; ++cx) {
            const std::size_t cell = (cy + kPad) * stride_ + cx + kPad;
            if (cells_[cell].x_bits != 0) continue;
            for (int k = 0; k < 5; ++k) {
                const double fx = k == 4 ? 0.5 : (k & 1), fy = k == 4 ? 0.5 : (k >> 1);
                Point p{box_.x0 + (static_cast<double>(cx) + fx) * side_,
                        box_.y0 + (static_cast<double>(cy) + fy) * side_};
                p.x = std::min(std::max(p.x, box_.x0), box_.x1);
                p.y = std::min(std::max(p.y, box_.y0), box_.y1);
                if (is_free(p, cell_of(p))) return true;
            }
        }
    }
    return false;
}

}  // namespace pds
