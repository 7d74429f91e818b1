// curve_order.hpp - the order in which a dart stage's points are inserted
// into the Jones stage's mesh at the hand-over.
//
// Biased randomized insertion order (Amenta, Choi and Rote 2003): the points
// come in rounds, each about three times the points before it, and each round
// is sorted along a Hilbert curve over a grid of cells. A round's points then
// fall inside the triangulation of the earlier ones, near where the last one
// went, so walks are short and flips stay local. The points are in random
// order already (the order they were added in), so the rounds are prefixes:
// ends n, n/4, n/16, ... down to 256 or fewer points. Fixed points, in the
// user's order, come first in rounds of their own.
//
// The scratch is reserved with the points, so the hand-over never allocates.
#ifndef PDS_CURVE_ORDER_HPP
#define PDS_CURVE_ORDER_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"

namespace pds {

class CurveOrder {
public:
    CurveOrder() = default;  // over one cell, until assigned
    // The curve runs over cols x rows cells of side_x by side_y from the
    // box's lower left corner (points outside count as in the nearest cell).
    CurveOrder(const Box& box, double side_x, double side_y, std::size_t cols, std::size_t rows);

    // Room for `points` points; strong guarantee (std::bad_alloc).
    void reserve(std::size_t points);
    bool has_room_for(std::size_t points) const {
        return order_.capacity() >= points && tmp_order_.capacity() >= points && key_.capacity() >= points &&
               tmp_key_.capacity() >= points && counts_.capacity() >= kCounts;
    }
    // The indices of points in insertion order, in the reserved scratch
    // (valid until the next call); requires room for points.size(). Large
    // sets are keyed and sorted on up to `threads` threads (the same order).
    // The first `first` points (fixed points) come first, in rounds and
    // along the curve among themselves: inserted after the others' mesh is
    // built, or into the ghosts alone, each walk is then short too.
    const std::uint32_t* order(const std::vector<Point>& points, unsigned threads = 1, std::size_t first = 0);
    // The same order in fresh scratch (for queries; allocates).
    std::vector<std::uint32_t> fresh_order(const std::vector<Point>& points) const;

    // Position along the curve of p's cell.
    std::uint64_t key(const Point& p) const;

private:
    static constexpr std::size_t kSideBySideFrom = std::size_t{1} << 16;  // points
    static constexpr unsigned kMaxWorkers = 8;
    static constexpr int kDigit = 11;  // bits per radix pass
    static constexpr std::size_t kCounts = kMaxWorkers << kDigit;
    // Sorts points[first, last) into order[0, last - first) (their indices
    // in points); the other three arrays are scratch of as many entries
    // each, counts of kCounts.
    void sort(const std::vector<Point>& points, std::size_t first, std::size_t last, std::uint32_t* order,
              std::uint64_t* key, std::uint32_t* tmp_order, std::uint64_t* tmp_key, std::uint32_t* counts,
              unsigned threads) const;

    Box box_{0.0, 0.0, 1.0, 1.0};
    double inv_side_x_ = 1.0, inv_side_y_ = 1.0;
    std::size_t cols_ = 1, rows_ = 1;
    int side_bits_ = 0;  // the curve's side is 2^side_bits_ cells, at least cols_ and rows_
    std::vector<std::uint32_t> order_, tmp_order_;
    std::vector<std::uint64_t> key_, tmp_key_;
    std::vector<std::uint32_t> counts_;  // the radix sort's, kCounts
};

}  // namespace pds

#endif
