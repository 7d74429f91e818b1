// fixed_disks.cpp - see fixed_disks.hpp.
#include "darts/fixed_disks.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"
#include "darts/dart_constants.hpp"

namespace pds {

template <class Inside>
bool FixedDisks::lay(const DiskGrid& grid, std::size_t budget, const Inside& inside) {
    const Box& box = grid.box;
    const auto cols = static_cast<std::int64_t>(grid.cols), rows = static_cast<std::int64_t>(grid.rows);
    // The cells a disk's bounding box meets, a cell wider each way for the
    // rounding of the cell coordinates.
    const auto span = [&](double lo, double hi, double x0, double side, std::int64_t n, std::int64_t* a,
                          std::int64_t* b) {
        const double fa = std::floor((lo - x0) / side) - 1.0, fb = std::floor((hi - x0) / side) + 1.0;
        *a = fa < 0.0 ? 0 : fa > static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(fa);
        *b = fb < 0.0 ? 0 : fb > static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(fb);
    };
    std::size_t cells = 0;
    for (std::size_t k = 0; k < centres_.size(); ++k) {
        if (!(radii_[k] > 0.0)) continue;
        const Point& c = centres_[k];
        const double r = radii_[k];
        std::int64_t c0, c1, r0, r1;
        span(c.x - r, c.x + r, box.x0, grid.side_x, cols, &c0, &c1);
        span(c.y - r, c.y + r, box.y0, grid.side_y, rows, &r0, &r1);
        cells += static_cast<std::size_t>((c1 - c0 + 1) * (r1 - r0 + 1));
        if (cells > budget) return false;
        for (std::int64_t row = r0; row <= r1; ++row)
            for (std::int64_t col = c0; col <= c1; ++col) {
                const auto cell = static_cast<std::uint32_t>(row * cols + col);
                if (inside(col, row, k)) continue;
                // Listed when the cell comes within the radius of the
                // centre (with slack: listing a disk too many is only
                // slower).
                const double hx = 0.5 * grid.side_x, hy = 0.5 * grid.side_y;
                const double ex = std::max(std::fabs(c.x - (grid.cell_x0(col) + hx)) - hx, 0.0);
                const double ey = std::max(std::fabs(c.y - (grid.cell_y0(row) + hy)) - hy, 0.0);
                const double reach = r * (1.0 + 0x1.0p-20) + 0x1.0p-20 * (hx + hy);
                if (ex * ex + ey * ey <= reach * reach) pairs_.push_back(std::uint64_t{cell} << 32 | k);
            }
    }
    std::sort(pairs_.begin(), pairs_.end());
    bits_.assign((grid.cols * grid.rows + 63) / 64, 0);
    for (const std::uint64_t x : pairs_) {
        const auto cell = static_cast<std::uint32_t>(x >> 32);
        bits_[cell >> 6] |= std::uint64_t{1} << (cell & 63);
    }
    return true;
}

bool FixedDisks::build(const SpaceTimeGrid& grid, const std::vector<Point>& centres, const std::vector<double>& radii,
                       std::vector<std::uint16_t>& masks, std::size_t budget) {
    centres_ = centres;
    radii_ = radii;
    const Box& box = grid.box();
    return lay(DiskGrid{box, grid.cols(), grid.rows(), grid.side_x(), grid.side_y()}, budget,
               [&](std::int64_t col, std::int64_t row, std::size_t k) {
                   const std::uint16_t in = grid.covered_by_disk(col, row, centres[k], radii[k], box);
                   std::uint16_t& mask = masks[static_cast<std::size_t>(row) * grid.cols() + static_cast<std::size_t>(col)];
                   mask = static_cast<std::uint16_t>(mask | in);
                   return in == SpaceTimeGrid::kAllCovered;
               });
}

bool FixedDisks::build(const DiskGrid& grid, const std::vector<Point>& centres, const std::vector<double>& radii,
                       std::size_t budget) {
    if (grid.rows != 0 && grid.cols > (std::size_t{1} << 32) / grid.rows) return false;
    centres_ = centres;
    radii_ = radii;
    whole_.assign((grid.cols * grid.rows + 63) / 64, 0);
    // A dart lands in its closed cell up to the rounding of its coordinates,
    // far under the margin of 4 offset steps.
    const double margin = 4.0 * std::max(grid.side_x, grid.side_y) / darts::kOffsetSteps;
    return lay(grid, budget, [&](std::int64_t col, std::int64_t row, std::size_t k) {
        const double cover = radii[k] - margin;
        if (!(cover > 0.0)) return false;
        const double x0 = grid.cell_x0(col), y0 = grid.cell_y0(row);
        // The farthest corner.
        const double ax = std::max(std::fabs(x0 - centres[k].x), std::fabs(x0 + grid.side_x - centres[k].x));
        const double ay = std::max(std::fabs(y0 - centres[k].y), std::fabs(y0 + grid.side_y - centres[k].y));
        if (!(ax * ax + ay * ay < cover * cover)) return false;
        const auto cell = static_cast<std::size_t>(row) * grid.cols + static_cast<std::size_t>(col);
        whole_[cell >> 6] |= std::uint64_t{1} << (cell & 63);
        return true;
    });
}

bool FixedDisks::covers(const Point& p, std::uint32_t cell) const {
    auto it = std::lower_bound(pairs_.begin(), pairs_.end(), std::uint64_t{cell} << 32);
    for (; it != pairs_.end() && (*it >> 32) == cell; ++it) {
        const auto k = static_cast<std::uint32_t>(*it);
        if (compare_distance(p, centres_[k], radii_[k]) < 0) return true;
    }
    return false;
}

}  // namespace pds
