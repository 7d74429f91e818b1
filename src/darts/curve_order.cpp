// curve_order.cpp - BRIO rounds along a Hilbert curve (see curve_order.hpp).
#include "darts/curve_order.hpp"

#include <algorithm>

#include "darts/grid_arithmetic.hpp"

namespace pds {

CurveOrder::CurveOrder(const Box& box, double side_x, double side_y, std::size_t cols, std::size_t rows)
    : box_(box), inv_side_x_(1.0 / side_x), inv_side_y_(1.0 / side_y), cols_(cols), rows_(rows) {
    while (side_ < cols_ || side_ < rows_) side_ *= 2;
}

void CurveOrder::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its vector as it was.
    order_.reserve(points);
    tmp_order_.reserve(points);
    key_.reserve(points);
    tmp_key_.reserve(points);
}

std::uint64_t CurveOrder::key(const Point& p) const {
    // Position along a Hilbert curve over the cells (rotating each quadrant
    // so the curve stays continuous); nearby keys are nearby cells. 64 bits:
    // a side of up to 2^32 cells.
    std::uint64_t x = clamped_cell((p.x - box_.x0) * inv_side_x_, cols_);
    std::uint64_t y = clamped_cell((p.y - box_.y0) * inv_side_y_, rows_);
    std::uint64_t key = 0;
    // Without branches (they were most of the hand-over's sorting time, the
    // quadrants being random): the rotation is a flip by masks (s - 1 - v is
    // v ^ (s - 1) below s) and a masked swap. Only bits below s matter later.
    for (std::uint64_t s = side_ / 2; s > 0; s /= 2) {
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

const std::uint32_t* CurveOrder::order(const std::vector<Point>& points) {
    // Sizes within the reserved capacity: no allocation.
    const std::size_t n = points.size();
    order_.resize(n);
    tmp_order_.resize(n);
    key_.resize(n);
    tmp_key_.resize(n);
    sort(points, order_.data(), key_.data(), tmp_order_.data(), tmp_key_.data());
    return order_.data();
}

std::vector<std::uint32_t> CurveOrder::fresh_order(const std::vector<Point>& points) const {
    const std::size_t n = points.size();
    std::vector<std::uint32_t> order(n), tmp_order(n);
    std::vector<std::uint64_t> key(n), tmp_key(n);
    sort(points, order.data(), key.data(), tmp_order.data(), tmp_key.data());
    return order;
}

void CurveOrder::sort(const std::vector<Point>& points, std::uint32_t* order, std::uint64_t* key,
                      std::uint32_t* tmp_order, std::uint64_t* tmp_key) const {
    const std::size_t n = points.size();
    std::size_t ends[64];
    std::size_t rounds = 0;
    for (std::size_t end = n; end > 0; end = end > 256 ? end / 4 : 0) ends[rounds++] = end;
    // Keys have 2 log2(side) bits: enough 11-bit radix passes to cover them.
    // The side stays below 2^30 cells: a dart stage runs only when Oler's
    // bound fits the index type (sampler.cpp), and a grid k cells long has
    // a bound of at least k/1.43 points; so keys fit 64 bits.
    int side_bits = 0;
    while ((std::uint64_t{1} << side_bits) < side_) ++side_bits;
    const int key_bits = 2 * side_bits;
    constexpr int kDigit = 11;
    constexpr std::uint64_t kMask = (std::uint64_t{1} << kDigit) - 1;
    std::size_t begin = 0;
    for (std::size_t r = rounds; r-- > 0;) {
        const std::size_t end = ends[r];
        for (std::size_t i = begin; i < end; ++i) {
            key[i] = this->key(points[i]);
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

}  // namespace pds
