// spatial_hash.cpp - see spatial_hash.hpp.
#include "spatial_hash.hpp"

#include <cmath>

namespace pds {

namespace {

// Cells a little larger than the radius, so a pair closer than R never lands
// two cells apart after the cell coordinates are rounded.
constexpr double kCellSlack = 1.0 + 0x1.0p-20;
// key() packs a cell's column and row into 32 bits each.
constexpr double kMaxCellsPerAxis = 1e9;
static_assert(kMaxCellsPerAxis < 4294967296.0, "cell coordinates must fit 32 bits");

}  // namespace

SpatialHash::SpatialHash(const std::vector<Point>& points, std::size_t first, const Box& domain,
                         double radius)
    : domain_(domain), cell_(radius * kCellSlack) {
    // Cells per axis must fit in 32 bits; a cell that large holds more points,
    // which costs time, not correctness.
    const double span = domain.width() > domain.height() ? domain.width() : domain.height();
    if (span / cell_ > kMaxCellsPerAxis) cell_ = span / kMaxCellsPerAxis;
    next_.assign(points.size(), kEnd);
    cells_.reserve(points.size() - first);
    for (std::size_t i = first; i < points.size(); ++i) {
        const std::uint64_t k = key(cell_x(points[i]), cell_y(points[i]));
        const std::uint32_t* head = cells_.find(k);
        next_[i] = head ? *head : kEnd;
        cells_.insert_or_assign(k, static_cast<std::uint32_t>(i));
    }
}

std::int64_t SpatialHash::cell_x(const Point& p) const {
    const double c = std::floor((p.x - domain_.x0) / cell_);
    return c < 0.0 ? 0 : static_cast<std::int64_t>(c);
}

std::int64_t SpatialHash::cell_y(const Point& p) const {
    const double c = std::floor((p.y - domain_.y0) / cell_);
    return c < 0.0 ? 0 : static_cast<std::int64_t>(c);
}

}  // namespace pds
