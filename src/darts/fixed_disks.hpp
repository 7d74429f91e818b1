// fixed_disks.hpp - the fixed points' clearance disks for the space-time
// dart process (space_time_stage.hpp): a dart inside one (strictly, as the
// Jones loop's power rule decides) is covered before any dart is thrown.
//
// Built once, before the first epoch, over the process's grid: every
// sub-square wholly inside a disk (with the grid's margin, covered_by_disk)
// is marked in the cells' masks like a sub-square an earlier point covers,
// so a cell inside a disk never becomes active; each cell a disk's edge
// crosses lists that disk, and a dart in it is tested exactly against the
// disks listed. A bit per cell says whether it lists any, so most darts
// never look. Memory: a bit per cell and a word per (cell, disk) pair,
// about the disks' perimeters in cells.
#ifndef PDS_FIXED_DISKS_HPP
#define PDS_FIXED_DISKS_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "darts/space_time_grid.hpp"

namespace pds {

class FixedDisks {
public:
    // The disks (centres, radii in the internal frame) over the grid's
    // cells (ids col + row * cols), their sub-squares inside a disk OR-ed
    // into masks. False, and masks partly marked, when the disks' bounding
    // boxes span more than `budget` cells in all (the caller then does
    // without the process). Throws std::bad_alloc.
    bool build(const SpaceTimeGrid& grid, const std::vector<Point>& centres, const std::vector<double>& radii,
               std::vector<std::uint16_t>& masks, std::size_t budget);

    // Whether the cell lists a disk (a dart there must ask covers()).
    bool listed(std::uint32_t cell) const {
        return !bits_.empty() && (bits_[cell >> 6] >> (cell & 63) & 1u) != 0;
    }
    // Whether p, a dart in the cell, lies strictly inside a disk it lists.
    bool covers(const Point& p, std::uint32_t cell) const;

private:
    std::vector<Point> centres_;
    std::vector<double> radii_;
    std::vector<std::uint64_t> bits_;   // a bit per cell: it lists a disk
    std::vector<std::uint64_t> pairs_;  // (cell << 32 | disk), sorted
};

}  // namespace pds

#endif
