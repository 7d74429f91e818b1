// covered_bitmap.hpp - a bitmap of grid cells each known to lie inside one
// disk: a dart landing in one is covered, decided with one bit.
//
// The layered grid of a field (layered_grid.hpp) reads its layers' blocks
// for every dart, eight lines or so; late in the stage most darts land in the
// regions of large disks, which are covered already. Each added disk marks
// the cells of the finest grid that lie wholly inside it (a disk of radius
// 5.7 cells marks about 60), and a dart in a marked cell is rejected without
// reading the blocks. Only cells certainly inside are marked (a margin of
// 2^-20 cell against rounding), so the decisions, and the points, are those
// of the full test.
#ifndef PDS_COVERED_BITMAP_HPP
#define PDS_COVERED_BITMAP_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "core/prefetch.hpp"

namespace pds {

class CoveredBitmap {
public:
    CoveredBitmap() = default;
    // cols x rows cells of side `side` from (x0, y0). May throw std::bad_alloc.
    CoveredBitmap(double x0, double y0, double side, std::size_t cols, std::size_t rows);

    // Marks the cells lying wholly inside the closed disk (c, r).
    void cover_disk(const Point& c, double r);
    // The cell of p, as the layered grid finds it (clamped to the grid).
    std::size_t cell_of(const Point& p) const;
    bool covered(std::size_t cell) const { return (bits_[cell / 64] >> (cell % 64)) & 1; }
    void prefetch(std::size_t cell) const { pds::prefetch(&bits_[cell / 64]); }
    // Whether cell (col, row) is marked (tests).
    bool covered(std::size_t col, std::size_t row) const { return covered(row * words_ * 64 + col); }
    // Unmarks every cell (tests).
    void clear() { std::fill(bits_.begin(), bits_.end(), 0); }
    bool operator==(const CoveredBitmap& o) const { return bits_ == o.bits_; }

private:
    double x0_ = 0, y0_ = 0, inv_side_ = 1;
    std::size_t cols_ = 0, rows_ = 0, words_ = 0;  // words_: 64-bit words a row
    std::vector<std::uint64_t> bits_;
};

}  // namespace pds

#endif
