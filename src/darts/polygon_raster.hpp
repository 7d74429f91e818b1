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
// cells of both; an edge's extent is one cell wider on each side, and taken
// in the bands beside its ends too, for the rounding of its x.
//
// Inside runs. A cell of a span that no edge's extent reaches holds no point
// of the outline, and a point of it on the middle line is inside: the whole
// cell is inside, and its darts need no test. The other cells may hold
// nothing of the polygon: their darts are tested exactly, as before.
#ifndef PDS_POLYGON_RASTER_HPP
#define PDS_POLYGON_RASTER_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "core/rng.hpp"
#include "domain/polygon.hpp"

namespace pds {

// Whether darts in `polygon` should be drawn among its raster's cells: it
// fills under 1/32 of the box (over the box, over 32 darts are drawn for
// one kept).
bool raster_suits(const Polygon& polygon, const Box& box);
// The most row bands a raster of cells of `cell_area` over `polygon` may
// take (build's max_bands): a few words per cell of the polygon's area, and
// 2^22 at most (about 200 MB while it is built). A bounded run in a polygon
// far larger than its points draws its darts otherwise.
std::size_t raster_band_budget(const Polygon& polygon, double cell_area);

class PolygonRaster {
public:
    // The grid: corner (x0, y0), cells sx by sy, cols by rows. False, and
    // nothing held, when the edges cross more than max_bands row bands in
    // all (a raster would cost more than the points it serves).
    bool build(const Polygon& polygon, double x0, double sx, std::size_t cols, double y0, double sy, std::size_t rows,
               std::size_t max_bands);
    // Cells in all the runs.
    std::size_t cells() const { return before_.empty() ? 0 : before_.back(); }
    // Cell k of the runs (k < cells(), in row order): its column and row,
    // and whether it lies wholly inside the polygon.
    struct Cell {
        std::size_t col, row;
        bool inside;
    };
    Cell cell(std::size_t k) const {
        std::size_t i = bucket_[k / step_];
        while (before_[i + 1] <= k) ++i;
        return Cell{runs_[i].lo + (k - before_[i]), runs_[i].row, runs_[i].inside};
    }
    std::size_t runs() const { return runs_.size(); }
    // Calls fn(row, first column, last column, inside) on each run, by row.
    template <class Fn>
    void for_each_run(Fn&& fn) const {
        for (const Run& run : runs_) fn(run.row, run.lo, run.hi, run.inside);
    }

    // A dart uniform over the runs' cells (requires cells() > 0): a cell,
    // then a point in it; inside when its cell lies wholly inside.
    struct Dart {
        Point p;
        bool inside;
    };
    Dart draw(Rng& rng) const {
        const double n = static_cast<double>(cells());
        const Cell c = cell(std::min(cells() - 1, static_cast<std::size_t>(rng.next_double() * n)));
        Dart d;
        d.p.x = x0_ + (static_cast<double>(c.col) + rng.next_double()) * sx_;
        d.p.y = y0_ + (static_cast<double>(c.row) + rng.next_double()) * sy_;
        d.inside = c.inside;
        return d;
    }

private:
    struct Run {
        std::size_t row, lo, hi;  // columns lo..hi of the row
        bool inside;
    };
    static std::vector<Run> joined(std::vector<Run> runs);
    static std::vector<Run> inside_of(const std::vector<Run>& spans, const std::vector<Run>& near_edges);
    bool index_runs();  // before_ and the buckets from runs_; false when empty

    std::vector<Run> runs_;            // by row, then column; disjoint
    std::vector<std::size_t> before_;  // before_[i]: cells in runs 0..i-1
    std::vector<std::size_t> bucket_;  // bucket_[j]: the run holding cell j step_
    std::size_t step_ = 1;
    double x0_ = 0.0, sx_ = 1.0, y0_ = 0.0, sy_ = 1.0;  // the grid build() was given
};

}  // namespace pds

#endif
