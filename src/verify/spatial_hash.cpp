// spatial_hash.cpp - see spatial_hash.hpp.
#include "verify/spatial_hash.hpp"

#include <algorithm>
#include <cmath>

namespace pds {

namespace {

// Cells a little larger than the radius, so a pair closer than R never lands
// two cells apart after the cell coordinates are rounded.
constexpr double kCellSlack = 1.0 + 0x1.0p-20;
// key() packs a cell's column and row into 32 bits each.
constexpr double kMaxCellsPerAxis = 1e9;
static_assert(kMaxCellsPerAxis < 4294967296.0, "cell coordinates must fit 32 bits");

// Cells to a period: whole, each at least the slackened radius wide, and
// within the key's range (a coarser cell holds more points: time, not
// correctness).
std::int64_t cells_per_period(double period, double radius) {
    const double n = std::floor(period / (radius * kCellSlack));
    return n < 1.0 ? 1 : static_cast<std::int64_t>(n < kMaxCellsPerAxis ? n : kMaxCellsPerAxis);
}

}  // namespace

SpatialHash::SpatialHash(const std::vector<Point>& points, std::size_t first, const Box& domain,
                         double radius)
    : x0_(domain.x0), y0_(domain.y0), cell_x_(radius * kCellSlack), cell_y_(cell_x_) {
    // Cells per axis must fit in 32 bits; a cell that large holds more points,
    // which costs time, not correctness.
    const double span = domain.width() > domain.height() ? domain.width() : domain.height();
    if (span / cell_x_ > kMaxCellsPerAxis) cell_x_ = cell_y_ = span / kMaxCellsPerAxis;
    if (!index_dense(points, first, domain.width(), domain.height())) index(points, first);
}

SpatialHash::SpatialHash(const std::vector<Point>& points, std::size_t first, const Torus& t,
                         double radius)
    : x0_(t.x0), y0_(t.y0), cols_(cells_per_period(t.px, radius)), rows_(cells_per_period(t.py, radius)) {
    cell_x_ = t.px / static_cast<double>(cols_);
    cell_y_ = t.py / static_cast<double>(rows_);
    if (!index_dense(points, first, t.px, t.py)) index(points, first);
}

bool SpatialHash::index_dense(const std::vector<Point>& points, std::size_t first, double width, double height) {
    // Two cells more than the extent needs: rounding never reaches past them,
    // and a point's cell is clamped into the grid anyway (queries clamp the
    // same way, so neighbours stay neighbours).
    constexpr double kDenseCellsPerPoint = 4.0;
    const double n = static_cast<double>(points.size() - first);
    const double cols = cols_ > 0 ? static_cast<double>(cols_) : std::floor(width / cell_x_) + 2.0;
    const double rows = rows_ > 0 ? static_cast<double>(rows_) : std::floor(height / cell_y_) + 2.0;
    if (!(cols * rows <= kDenseCellsPerPoint * n + 1024.0)) return false;
    dense_cols_ = static_cast<std::int64_t>(cols);
    dense_rows_ = static_cast<std::int64_t>(rows);
    const std::size_t cells = static_cast<std::size_t>(dense_cols_ * dense_rows_);
    const auto cell_of = [&](const Point& p) {
        const std::int64_t x = std::min(cell(p.x, x0_, cell_x_, cols_), dense_cols_ - 1);
        const std::int64_t y = std::min(cell(p.y, y0_, cell_y_, rows_), dense_rows_ - 1);
        return static_cast<std::size_t>(y * dense_cols_ + x);
    };
    // A counting sort: sizes, then each cell's end, then the points from the
    // last back into their slots, which leaves each cell's start behind.
    start_.assign(cells + 1, 0);
    for (std::size_t i = first; i < points.size(); ++i) ++start_[cell_of(points[i])];
    for (std::size_t c = 1; c <= cells; ++c) start_[c] += start_[c - 1];
    sorted_.resize(points.size() - first);
    for (std::size_t i = points.size(); i-- > first;)
        sorted_[--start_[cell_of(points[i])]] = static_cast<std::uint32_t>(i);
    dense_ = true;
    return true;
}

void SpatialHash::index(const std::vector<Point>& points, std::size_t first) {
    next_.assign(points.size(), kEnd);
    cells_.reserve(points.size() - first);
    for (std::size_t i = first; i < points.size(); ++i) {
        const std::uint64_t k =
            key(cell(points[i].x, x0_, cell_x_, cols_), cell(points[i].y, y0_, cell_y_, rows_));
        const std::uint32_t* head = cells_.find(k);
        next_[i] = head ? *head : kEnd;
        cells_.insert_or_assign(k, static_cast<std::uint32_t>(i));
    }
}

std::int64_t SpatialHash::cell(double v, double origin, double width, std::int64_t n) {
    const double c = std::floor((v - origin) / width);
    if (!(c > 0.0)) return 0;
    const std::int64_t k = static_cast<std::int64_t>(c);
    return n > 0 && k >= n ? n - 1 : k;
}

}  // namespace pds
