// fixed_disks.cpp - see fixed_disks.hpp.
#include "darts/fixed_disks.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"

namespace pds {

bool FixedDisks::build(const SpaceTimeGrid& grid, const std::vector<Point>& centres, const std::vector<double>& radii,
                       std::vector<std::uint16_t>& masks, std::size_t budget) {
    centres_ = centres;
    radii_ = radii;
    const Box& box = grid.box();
    const auto cols = static_cast<std::int64_t>(grid.cols()), rows = static_cast<std::int64_t>(grid.rows());
    // The cells a disk's bounding box meets, a cell wider each way for the
    // rounding of the cell coordinates.
    const auto span = [&](double lo, double hi, double x0, double side, std::int64_t n, std::int64_t* a,
                          std::int64_t* b) {
        const double fa = std::floor((lo - x0) / side) - 1.0, fb = std::floor((hi - x0) / side) + 1.0;
        *a = fa < 0.0 ? 0 : fa > static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(fa);
        *b = fb < 0.0 ? 0 : fb > static_cast<double>(n - 1) ? n - 1 : static_cast<std::int64_t>(fb);
    };
    std::size_t cells = 0;
    for (std::size_t k = 0; k < centres.size(); ++k) {
        if (!(radii[k] > 0.0)) continue;
        std::int64_t c0, c1, r0, r1;
        span(centres[k].x - radii[k], centres[k].x + radii[k], box.x0, grid.side_x(), cols, &c0, &c1);
        span(centres[k].y - radii[k], centres[k].y + radii[k], box.y0, grid.side_y(), rows, &r0, &r1);
        cells += static_cast<std::size_t>((c1 - c0 + 1) * (r1 - r0 + 1));
        if (cells > budget) return false;
        for (std::int64_t row = r0; row <= r1; ++row)
            for (std::int64_t col = c0; col <= c1; ++col) {
                const auto cell = static_cast<std::uint32_t>(row * cols + col);
                const std::uint16_t inside = grid.covered_by_disk(col, row, centres[k], radii[k], box);
                masks[cell] = static_cast<std::uint16_t>(masks[cell] | inside);
                if (inside == SpaceTimeGrid::kAllCovered) continue;
                // Listed when the cell comes within the radius of the
                // centre (with slack: listing a disk too many is only
                // slower).
                const double hx = 0.5 * grid.side_x(), hy = 0.5 * grid.side_y();
                const double ex = std::max(std::fabs(centres[k].x - (grid.cell_x0(col) + hx)) - hx, 0.0);
                const double ey = std::max(std::fabs(centres[k].y - (grid.cell_y0(row) + hy)) - hy, 0.0);
                const double reach = radii[k] * (1.0 + 0x1.0p-20) + 0x1.0p-20 * (hx + hy);
                if (ex * ex + ey * ey <= reach * reach) pairs_.push_back(std::uint64_t{cell} << 32 | k);
            }
    }
    std::sort(pairs_.begin(), pairs_.end());
    bits_.assign((grid.cell_count() + 63) / 64, 0);
    for (const std::uint64_t x : pairs_) {
        const auto cell = static_cast<std::uint32_t>(x >> 32);
        bits_[cell >> 6] |= std::uint64_t{1} << (cell & 63);
    }
    return true;
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
