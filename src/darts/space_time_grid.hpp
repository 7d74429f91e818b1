// space_time_grid.hpp - the background grid of the space-time dart process
// (space_time_stage.hpp): one radius R on the plane or the torus, cells of
// side 0.99 R / sqrt 2 (no two points share one), a word per cell as in
// dart_grid.hpp (the point's index plus one, its offset in 16 bits a side).
// On the torus, as in dart_grid.hpp, the cells divide the periods (so they
// are rectangles, a little narrower) and the padding holds copies: of the
// points, and during an epoch of the candidate lists; a word read in the
// padding stands for its source shifted by the periods (copy_shift()).
//
// Differences from DartGrid, for bands of rows resolved by several threads:
// - words are read and written with relaxed atomics (a thread reads the rows
//   next to its band while the neighbour band writes them);
// - during an epoch, an empty cell that received darts holds the list of
//   them instead (kEpochFlag set: the band, the first and the count);
// - covered_by(): which of a cell's 4 x 4 sub-squares one disk covers, so
//   cells covered by several disks can leave the active set.
#ifndef PDS_SPACE_TIME_GRID_HPP
#define PDS_SPACE_TIME_GRID_HPP

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/point.hpp"
#include "core/torus.hpp"
#include "darts/dart_constants.hpp"
#include "darts/grid_arithmetic.hpp"
#include "darts/grid_storage.hpp"

namespace pds {

class SpaceTimeGrid {
public:
    using Word = std::uint64_t;
    static constexpr std::uint32_t kEpochFlag = std::uint32_t{1} << 31;
    static constexpr std::uint16_t kAllCovered = 0xFFFF;

    // A point's place: its cell (padded index), column and row, and the
    // cells its disk reaches relative to its own (as DartGrid::Dart).
    struct Aim {
        std::size_t cell;
        std::int64_t col, row;
        int x_lo, x_hi, y_lo, y_hi;
    };

    SpaceTimeGrid() = default;
    // box: the domain's bounds (internal frame), or on the torus its
    // fundamental domain; throws std::bad_alloc.
    SpaceTimeGrid(const Box& box, double radius, const Torus& torus = Torus{});

    std::size_t cols() const { return cols_; }
    std::size_t rows() const { return rows_; }
    std::size_t cell_count() const { return cols_ * rows_; }
    double side_x() const { return x_.side; }
    double side_y() const { return y_.side; }
    const Torus& torus() const { return torus_; }
    const Box& box() const { return box_; }  // the cells' span (on the torus, the fundamental domain)
    double cell_x0(std::int64_t col) const { return box_.x0 + static_cast<double>(col) * x_.side; }
    double cell_y0(std::int64_t row) const { return box_.y0 + static_cast<double>(row) * y_.side; }
    std::size_t padded(std::int64_t col, std::int64_t row) const {
        return static_cast<std::size_t>(row + darts::kPad) * stride_ + static_cast<std::size_t>(col + darts::kPad);
    }
    std::size_t stride() const { return stride_; }

    // The place of a point of the closed cell in column col, row row (a
    // dart drawn in it may round onto its far side: it stays the cell's).
    Aim aim_in(const Point& p, std::int64_t col, std::int64_t row) const;
    Word load(std::size_t cell) const { return cells_.load(cell); }
    // Asks for the rows of the 5 x 5 block around a cell ahead of its reads.
    void prefetch_block(std::int64_t col, std::int64_t row) const {
        std::size_t first = padded(col - darts::kPad, row - darts::kPad);
        for (int i = -darts::kPad; i <= darts::kPad; ++i, first += stride_) {
            cells_.prefetch(first);
            cells_.prefetch(first + 2 * darts::kPad);
        }
    }
    void store(std::size_t cell, Word w) { cells_.store(cell, w); }
    // Stores w in the cell in column col, row row and, on the torus, in its
    // copies in the padding.
    void store_with_copies(std::int64_t col, std::int64_t row, Word w) {
        cells_.store(padded(col, row), w);
        if (torus_.on()) store_copies(col, row, w);
    }
    // The periods (i, j) by which the source of a word read in the cell
    // col + dj, row + di (relative to the cell in column col, row row) is
    // shifted: 0 but in the torus's padding.
    void copy_shift(std::int64_t col, std::int64_t row, int dj, int di, int* i, int* j) const {
        const auto shift = [](std::int64_t k, std::size_t n) { return k < 0 ? -1 : k >= static_cast<std::int64_t>(n) ? 1 : 0; };
        *i = shift(col + dj, cols_);
        *j = shift(row + di, rows_);
    }
    // An epoch's list of candidates in a cell: `count` of them from `first`
    // in band `band`'s array.
    static Word list_word(std::uint32_t band, std::uint32_t first, std::uint32_t count) {
        return (Word{band} << 40) | (Word{count} << 32) | kEpochFlag | first;
    }
    static bool is_list(Word w) { return (static_cast<std::uint32_t>(w) & kEpochFlag) != 0; }
    static std::uint32_t list_band(Word w) { return static_cast<std::uint32_t>(w >> 40) & 0xFF; }
    static std::uint32_t list_first(Word w) { return static_cast<std::uint32_t>(w) & ~kEpochFlag; }
    static std::uint32_t list_count(Word w) { return static_cast<std::uint32_t>(w >> 32) & 0xFF; }
    // Point `index` at p, in column col, row row (and its copies).
    void write(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index) {
        const std::uint64_t sx = offset_steps(p.x - cell_x0(col), x_.step);
        const std::uint64_t sy = offset_steps(p.y - cell_y0(row), y_.step);
        store_with_copies(col, row, (sy << 48) | (sx << 32) | (std::uint64_t{index} + 1));
    }
    static std::uint32_t index_of(Word w) { return static_cast<std::uint32_t>(w) - 1; }
    // The point a word holds, from its rounded offsets (within 2^-17 of a
    // cell of the exact point, or of its copy in the padding, a side).
    Point rounded(Word w, std::int64_t col, std::int64_t row) const {
        return Point{cell_x0(col) + (static_cast<double>((w >> 32) & 0xFFFF) + 0.5) * x_.step,
                     cell_y0(row) + (static_cast<double>(w >> 48) + 0.5) * y_.step};
    }
    // Whether q, read rounded from a word, lies within R of p: -1 surely
    // not, 1 surely, 0 too close to R to say from the rounding.
    int rounded_within(const Point& p, const Point& q) const {
        const double dx = q.x - p.x, dy = q.y - p.y, d2 = dx * dx + dy * dy;
        return d2 < r2_low_ ? 1 : d2 < r2_high_ ? 0 : -1;
    }

    // The bit of the sub-square that holds a dart at (u, v) of its cell,
    // u and v in [0, 1).
    static unsigned sub_square(double u, double v) {
        return 4u * static_cast<unsigned>(v * 4.0) + static_cast<unsigned>(u * 4.0);
    }
    // The sub-squares of the cell in column col, row row (bit 4 b + a for
    // column a, row b) that lie in the disk of radius R around q: with a
    // margin far above every rounding, so a bit set is a sub-square covered.
    // The sub-squares are clipped to `domain` (darts never land outside it).
    std::uint16_t covered_by(std::int64_t col, std::int64_t row, const Point& q, const Box& domain) const;
    // The same for the disk of `radius` around q (a fixed point's clearance).
    std::uint16_t covered_by_disk(std::int64_t col, std::int64_t row, const Point& q, double radius,
                                  const Box& domain) const;
    // The sub-squares of p's cell (aimed at by a) that lie in one of the
    // disks around p, from the grid's points not surely beyond R of p.
    std::uint16_t covered_by_disks_at(const Point& p, const Aim& a, const Box& domain) const;
    // The sub-squares of that cell that lie outside `domain` (edge cells).
    std::uint16_t outside(std::int64_t col, std::int64_t row, const Box& domain) const;

    // Huge pages once the points reserved are worth them (grid_storage.hpp).
    void reserve(std::size_t points) { cells_.reserve(points, points); }
    void release() { cells_.release(); }

private:
    // The sub-squares whose farthest corner lies within sqrt(cover2) of q
    // (none when every centre lies beyond radius).
    std::uint16_t covered_within(std::int64_t col, std::int64_t row, const Point& q, double radius, double cover2,
                                 const Box& domain) const;
    void store_copies(std::int64_t col, std::int64_t row, Word w);

    Box box_{0, 0, 1, 1};
    Torus torus_;
    double r_ = 1.0;
    GridAxis x_{1, 1.0, 1.0, 1.0, 1.0}, y_{1, 1.0, 1.0, 1.0, 1.0};  // grid_axis()
    double r2_low_ = 1.0, r2_high_ = 1.0, r2_cover_ = 1.0;
    std::size_t cols_ = 0, rows_ = 0, stride_ = 0;
    DenseCells cells_;
};

}  // namespace pds

#endif
