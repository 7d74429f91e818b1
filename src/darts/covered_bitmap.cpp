// covered_bitmap.cpp - see covered_bitmap.hpp.
#include "darts/covered_bitmap.hpp"

#include <algorithm>
#include <cmath>

#include "darts/grid_arithmetic.hpp"

namespace pds {

CoveredBitmap::CoveredBitmap(double x0, double y0, double side, std::size_t cols, std::size_t rows)
    : x0_(x0), y0_(y0), inv_side_(1.0 / side), cols_(cols), rows_(rows), words_((cols + 63) / 64) {
    bits_.assign(words_ * rows_, 0);
}

std::size_t CoveredBitmap::cell_of(const Point& p) const {
    const std::size_t col = clamped_cell((p.x - x0_) * inv_side_, cols_);
    const std::size_t row = clamped_cell((p.y - y0_) * inv_side_, rows_);
    return row * words_ * 64 + col;
}

void CoveredBitmap::cover_disk(const Point& c, double r) {
    // In cell units, where cell (i, j) is [i, i + 1] x [j, j + 1]: the same
    // arithmetic that places a dart in its cell (cell_of), so a margin far
    // above its rounding keeps every mark certain.
    constexpr double kMargin = 0x1.0p-20;
    const double fx = (c.x - x0_) * inv_side_, fy = (c.y - y0_) * inv_side_;
    const double rr = r * inv_side_ - kMargin;
    if (!(rr > 0.7)) return;  // no whole cell fits (the diagonal is 1.414)
    const double row_lo = std::max(std::ceil(fy - rr), 0.0);
    const double row_hi = std::min(std::floor(fy + rr) - 1.0, static_cast<double>(rows_) - 1.0);
    for (double j = row_lo; j <= row_hi; j += 1.0) {
        // The row's edge farther from the centre decides its width.
        const double dy = std::max(std::fabs(j - fy), std::fabs(j + 1.0 - fy));
        const double w2 = rr * rr - dy * dy;
        if (w2 <= 0.0) continue;
        const double w = std::sqrt(w2);
        const double col_lo = std::max(std::ceil(fx - w), 0.0);
        const double col_hi = std::min(std::floor(fx + w) - 1.0, static_cast<double>(cols_) - 1.0);
        if (col_lo > col_hi) continue;
        auto* row = &bits_[static_cast<std::size_t>(j) * words_];
        for (auto i = static_cast<std::size_t>(col_lo); i <= static_cast<std::size_t>(col_hi); ++i)
            row[i / 64] |= std::uint64_t{1} << (i % 64);
    }
}

}  // namespace pds
