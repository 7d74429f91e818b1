// sub_square_raster.hpp - which of a dart grid's 4 x 4 sub-squares lie
// wholly outside a polygon, and which wholly inside: the space-time dart
// process (space_time_stage.hpp) skips the first like covered ones (a cell
// all outside is never active) and keeps darts in the second untested.
//
// From a PolygonRaster (polygon_raster.hpp) over the sub-squares: a
// sub-square in none of its runs holds no point of the closed polygon, one
// in an inside run lies wholly inside it. The runs are widened for the
// rounding of the outline's coordinates, and a dart rounded an ulp past its
// sub-square lands in a neighbour that the same widening covers.
#ifndef PDS_SUB_SQUARE_RASTER_HPP
#define PDS_SUB_SQUARE_RASTER_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "domain/polygon.hpp"

namespace pds {

// The grid: corner (x0, y0), square cells of side `side`, cols by rows;
// bit 4 b + a of a cell's mask is its sub-square in column a, row b. Cell
// col + row * cols gets outside[...] |= the sub-squares wholly outside and
// inside[...] = those wholly inside (both sized cols * rows by the caller,
// inside all zeros).
// False, and nothing written, when the raster would cost more than its
// budget (raster_band_budget): then the caller tests every dart instead.
// May throw std::bad_alloc.
bool classify_sub_squares(const Polygon& polygon, double x0, double y0, double side, std::size_t cols,
                          std::size_t rows, std::vector<std::uint16_t>& outside, std::vector<std::uint16_t>& inside);

}  // namespace pds

#endif
