// fixed_disks.hpp - the fixed points' clearance disks laid over a dart grid's
// cells, so a dart inside one (strictly, as the Jones loop's power rule
// decides) is known covered before any point is placed.
//
// Built once, before the first dart. Each cell a disk's edge crosses lists
// that disk, and a dart in it is tested exactly against the disks listed; a
// bit per cell says whether it lists any, so most darts never look. A cell
// wholly inside a disk (with a margin of 4 rounding steps of the grid's
// offsets) is not listed:
//   - over the space-time grid (space_time_stage.hpp) its sub-squares
//     inside a disk are OR-ed into the cells' masks instead, like
//     sub-squares an earlier point covers, so such a cell never becomes
//     active;
//   - over a plain grid (dart_stage.hpp) a second bit per cell says so, and
//     every dart there is covered.
// Memory: two bits per cell and a word per (cell, disk) pair, about the
// disks' perimeters in cells.
#ifndef PDS_FIXED_DISKS_HPP
#define PDS_FIXED_DISKS_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "darts/space_time_grid.hpp"

namespace pds {

// A grid of cols x rows cells of side_x by side_y from box's lower left
// corner; cell (col, row) is number col + row * cols.
struct DiskGrid {
    Box box;
    std::size_t cols, rows;
    double side_x, side_y;
    // The lower left corner of cell (col, row).
    double cell_x0(std::int64_t col) const { return box.x0 + static_cast<double>(col) * side_x; }
    double cell_y0(std::int64_t row) const { return box.y0 + static_cast<double>(row) * side_y; }
};

class FixedDisks {
public:
    // The disks (centres, radii in the internal frame) over the space-time
    // grid's cells, their sub-squares inside a disk OR-ed into masks. False,
    // and masks partly marked, when the disks' bounding boxes span more than
    // `budget` cells in all (the caller then does without the process).
    // Throws std::bad_alloc.
    bool build(const SpaceTimeGrid& grid, const std::vector<Point>& centres, const std::vector<double>& radii,
               std::vector<std::uint16_t>& masks, std::size_t budget);
    // The same over a plain grid, the cells wholly inside a disk kept as
    // bits (covered()); also false when the grid has 2^32 cells or more.
    bool build(const DiskGrid& grid, const std::vector<Point>& centres, const std::vector<double>& radii,
               std::size_t budget);

    // Whether the cell lists a disk (a dart there must ask covers()).
    bool listed(std::uint32_t cell) const {
        return !bits_.empty() && (bits_[cell >> 6] >> (cell & 63) & 1u) != 0;
    }
    // Whether p, a dart in the cell, lies strictly inside a disk it lists.
    bool covers(const Point& p, std::uint32_t cell) const;
    // Whether p, a dart in the cell, lies strictly inside a disk: the cell
    // is wholly inside one, or it lists one that holds p (the plain grid's
    // build).
    bool covered(const Point& p, std::uint32_t cell) const {
        return (whole_[cell >> 6] >> (cell & 63) & 1u) != 0 || (listed(cell) && covers(p, cell));
    }

private:
    // Lays the disks over cols x rows cells: inside(col, row, k) says
    // whether the cell lies wholly inside disk k (and marks what the caller
    // keeps); cell_x0, cell_y0 place the cells.
    template <class Inside>
    bool lay(const DiskGrid& grid, std::size_t budget, const Inside& inside);

    std::vector<Point> centres_;
    std::vector<double> radii_;
    std::vector<std::uint64_t> bits_;   // a bit per cell: it lists a disk
    std::vector<std::uint64_t> whole_;  // a bit per cell: wholly inside a disk (plain grid)
    std::vector<std::uint64_t> pairs_;  // (cell << 32 | disk), sorted
};

}  // namespace pds

#endif
