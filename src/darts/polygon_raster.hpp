// polygon_raster.hpp - the cells of a dart grid that a polygon may meet, as
// runs along the grid's rows, and the k-th of them: darts for a polygon that
// fills little of its bounding box (islands far apart, a thin ring) are drawn
// among these cells instead of over the whole box, where nearly every dart
// would be drawn again.
//
// Why the runs hold the polygon. A point q of the polygon in the band of row
// j either reaches the band's middle line straight up or down without
// meeting an edge, and then lies in a span that the middle line has inside
// by the even-odd rule; or it meets an edge in the band at its own x, and
// then lies in that edge's x-extent within the band. The runs are the
// cells of both, one cell wider on each side for the rounding of the
// crossings. A cell in a run may still hold no point of the polygon: its
// darts are refused by the exact test, as before.
#ifndef PDS_POLYGON_RASTER_HPP
#define PDS_POLYGON_RASTER_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "domain/polygon.hpp"

namespace pds {

// Whether darts in `polygon` should be drawn among its raster's cells: it
// fills under 1/32 of the box (over the box, over 32 darts are drawn for
// one kept). Such a polygon's grid also keeps only its taken cells
// (grid_storage.hpp): the whole grid over the box may not fit in memory.
bool raster_suits(const Polygon &polygon, const Box &box);

class PolygonRaster {
public:
  // The grid: corner (x0, y0), cells sx by sy, cols by rows. False, and
  // nothing held, when the edges cross more than max_bands row bands in
  // all (a raster would cost more than the points it serves).
  bool build(const Polygon &polygon, double x0, double sx, std::size_t cols,
             double y0, double sy, std::size_t rows, std::size_t max_bands);
  // Cells in all the runs.
  std::size_t cells() const { return before_.empty() ? 0 : before_.back(); }
  // The column and row of cell k of the runs (k < cells()), in row order.
  void cell(std::size_t k, std::size_t *col, std::size_t *row) const;
  std::size_t runs() const { return runs_.size(); }

private:
  struct Run {
    std::size_t row, lo, hi; // columns lo..hi of the row
  };
  std::vector<Run> runs_;           // by row, then column; disjoint
  std::vector<std::size_t> before_; // before_[i + 1]: cells in runs 0..i
};

} // namespace pds

#endif
