// grid_arithmetic.hpp - arithmetic shared by the dart grids (dart_grid.hpp,
// layered_grid.hpp) and the covered bitmap (covered_bitmap.hpp).
#ifndef PDS_GRID_ARITHMETIC_HPP
#define PDS_GRID_ARITHMETIC_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "darts/dart_constants.hpp"

namespace pds {

// Cells of `side` needed to cover `length`, at least one.
inline std::size_t cells_along(double length, double side) {
    const double n = std::ceil(length / side);
    return n < 1.0 ? 1 : static_cast<std::size_t>(n);
}

// One axis of a one-radius dart grid (dart_grid.hpp, space_time_grid.hpp):
// ceil(span / side) cells of side `side`; along a torus's period divided
// evenly instead (span / count wide), so a copy one period away sits exactly
// `count` cells away (with R at most half a period the cells stay wider
// than R / 2, at least 0.518 R: the 5 x 5 block still holds every point
// within R). With the side's inverse, an offset step (side / kOffsetSteps)
// and R in cells, with a little slack.
struct GridAxis {
    std::size_t count;
    double side, inv, step, reach;
};
inline GridAxis grid_axis(double span, double side, double radius, bool period) {
    GridAxis a;
    a.count = cells_along(span, side);
    a.side = period ? span / static_cast<double>(a.count) : side;
    a.inv = 1.0 / a.side;
    a.step = a.side / darts::kOffsetSteps;
    a.reach = radius * a.inv + darts::kReachSlack;
    return a;
}

// Cell f (a coordinate in cells) clamped into 0..n-1: rounding may put a
// point on the far edge of the last cell.
inline std::size_t clamped_cell(double f, std::size_t n) {
    const std::size_t c = f > 0.0 ? static_cast<std::size_t>(f) : 0;
    return std::min(c, n - 1);
}

// An offset in [0, side) as a step count in [0, 65536); rounding may put a
// point a hair outside its cell, hence the clamp.
inline std::uint64_t offset_steps(double offset, double step) {
    const double s = std::floor(offset / step);
    if (!(s > 0.0)) return 0;
    return s < 65535.0 ? static_cast<std::uint64_t>(s) : 65535;
}

// The offset (in cells, from the cell of f's own column `own`) of the cell
// holding coordinate f, clamped into -pad..pad.
inline int block_offset(double f, std::int64_t own, int pad) {
    const double k = std::floor(f) - static_cast<double>(own);
    return k < -pad ? -pad : k > pad ? pad : static_cast<int>(k);
}

// Whether covers(i, j) holds for a cell of the block i = y_lo..y_hi,
// j = x_lo..x_hi (offsets from the dart's own cell), asking the eight cells
// around the dart's own first: a point there is the likeliest to cover it,
// so most rejected darts stop early, having read a line or two. The block must
// hold those eight: a disk reaching over one cell puts x_lo, y_lo <= -1 and
// x_hi, y_hi >= 1. Always inlined into the dart's test: it runs for every
// dart, and a call would keep its lambda out of line too.
template <class Covers>
__attribute__((always_inline)) inline bool block_covers(int x_lo, int x_hi, int y_lo, int y_hi, const Covers& covers) {
    if (covers(0, -1) || covers(0, 1) || covers(-1, 0) || covers(1, 0)) return true;
    if (covers(-1, -1) || covers(-1, 1) || covers(1, -1) || covers(1, 1)) return true;
    for (int i = y_lo; i <= y_hi; ++i) {
        for (int j = x_lo; j <= x_hi; ++j) {
            const bool inner = i >= -1 && i <= 1 && j >= -1 && j <= 1;
            if (!inner && covers(i, j)) return true;
        }
    }
    return false;
}

}  // namespace pds

#endif
