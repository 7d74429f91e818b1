// dart_constants.hpp - the numbers every dart grid and dart stage shares:
// the rule that ends a stage, and the cells' geometry and rounding.
#ifndef PDS_DART_CONSTANTS_HPP
#define PDS_DART_CONSTANTS_HPP

#include <cmath>
#include <cstddef>

namespace pds {
namespace darts {

// The stage ends once fewer than this share of a window's darts land free:
// below it a dart costs more per point than the Jones loop does (chosen by
// measurement, make bench; one figure serves one radius and fields alike).
constexpr double kMinAcceptance = 0.04;
// Darts per window, at least: enough for a fair estimate of the rate.
constexpr std::size_t kMinWindow = 256;
// Cells of side kCellShrink r / sqrt 2: a diagonal under r even after
// rounding, so a cell never holds two points of radius r or more.
constexpr double kCellShrink = 0.99;
inline double cell_side(double r) { return kCellShrink * r / std::sqrt(2.0); }
// A point's offset in its cell is kept in 16 bits a side.
constexpr double kOffsetSteps = 65536.0;
// The filter decides |p - q|^2 against r^2 (1 -+ kFilterSlack), q read from
// its cell's rounded offsets: 16 times wider than that rounding can move a
// distance (under 2^-17 of a cell a side, a cell under 0.71 r: a distance by
// under 7.6e-6 r, a squared one by under 1.6e-5 r^2), so only distances
// within the slack go to the exact predicate.
constexpr double kFilterSlack = 0x1.0p-12;
// Empty cells around a grid (on the torus: the copies), so a dart's block
// needs no bounds tests.
constexpr int kPad = 2;
// Slack on a disk's reach in cells, far above the rounding of a cell
// coordinate: a block a column too wide costs a little time, one too narrow
// would be wrong.
constexpr double kReachSlack = 1e-6;

}  // namespace darts
}  // namespace pds

#endif
