// field_dart_stage.hpp - the opening of a run with a varying radius: dart
// throwing on a grid per layer of radii.
//
// The rule of a field (point_radii.hpp): a later point keeps out of every
// earlier point's disk, by that disk's own radius. A uniform dart kept when it
// is outside every disk is uniform over the free region, as with one radius
// (dart_stage.hpp), so this stage has the Jones loop's law too; it runs while
// darts still land free often enough, then hands its points over.
//
// One grid sized by the smallest radius would have to be searched as far as
// the largest: a 1:4 field reads 12 x 12 cells a dart. Instead the points are
// split into layers by radius, each a factor kLayerRatio (under sqrt 2) wider
// than the last: layer k holds the radii in [low_k, kLayerRatio low_k).
// Two points of a layer are at least low_k apart (the earlier one's radius),
// so a grid of cells of side 0.99 low_k / sqrt 2 holds at most one of them a
// cell, and its disk, at most kLayerRatio low_k wide, reaches under 2 cells:
// a dart reads at most 5 x 5 cells of each layer (4 x 4 with one radius). A
// coarse grid of tiles as wide as the largest radius records which layers
// have points in each tile, so a dart reads only the layers near it: where
// the field is smooth, one or two. A bitmap of the finest cells that lie
// inside one disk (covered_cells.hpp) rejects most darts in the regions of
// large disks before any block is read.
//
// A cell is 8 bytes: the point's offset in the cell, rounded as in the
// one-radius grid, and its radius as a float; distances the rounding leaves
// in doubt read the point's index from a parallel array and go to the exact
// predicate with the exact point and radius.
//
// The plane only: on the torus a varying field runs the Jones loop alone
// (sampler.cpp).
#ifndef PDS_FIELD_DART_STAGE_HPP
#define PDS_FIELD_DART_STAGE_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "core/batch.hpp"
#include "darts/covered_cells.hpp"
#include "darts/curve_order.hpp"
#include "darts/dart_queue.hpp"
#include "darts/opening_stage.hpp"
#include "core/point.hpp"
#include "radius/point_radii.hpp"
#include "core/rng.hpp"

namespace pds {

class FieldDartStage final : public OpeningStage {
public:
    // Fields whose largest radius is at most this many times the smallest
    // get the stage: the layers' address space grows as the square of the
    // ratio (their pages are touched only where points land).
    static constexpr double kMaxRatio = 8.0;

    // domain and radii in the internal frame. Allocates the grids (zeroed:
    // address space until points land); throws std::bad_alloc.
    FieldDartStage(const Box& domain, const PointRadii& radii);

    void reserve(std::size_t points) override;
    bool has_room_for(std::size_t points) const override {
        return points_.capacity() >= points && values_.capacity() >= points && curve_.has_room_for(points);
    }
    void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) override;

    std::size_t count() const override { return points_.size(); }
    const Point& point(PointIndex k) const override { return points_[k]; }
    double value(PointIndex k) const override { return values_[k]; }
    // Throws darts until one is outside every disk and returns it; nullptr
    // once the acceptance rate over a window fell below kMinAcceptance.
    const Point* next(Rng& rng) override;
    // Asks the field for the point's value first (FieldError: nothing changed).
    void add_next() override;
    double free_area() const override;
    VerifyReport verify() const override;

    // Internals, for tests.
    std::size_t layer_count() const { return layers_.size(); }
    const CoveredCells& covered_cells() const { return covered_; }
    // Distances the rounded offsets left undecided (for tests).
    std::size_t exact_checks() const { return exact_checks_; }

private:
    static constexpr double kMinAcceptance = 0.04;  // as the one-radius stage: measured alike
    static constexpr std::size_t kMinWindow = 256;
    static constexpr double kLayerRatio = 1.39;  // reach: 1.39 sqrt 2 / 0.99 = 1.986 cells
    static constexpr double kCellShrink = 0.99;
    static constexpr double kFilterSlack = 0x1.0p-12;  // as the one-radius stage's
    static constexpr double kOffsetSteps = 65536.0;
    static constexpr int kPad = 2;
    static constexpr std::size_t kMaxLayers = 32;  // a tile's mask has a bit per layer

    // The hot part of a cell, 8 bytes: bits 0-15 and 16-31 the point's
    // offset in the cell along x and y, 32-63 its radius as a float (0: an
    // empty cell). The point's index, needed only when the rounding leaves a
    // distance in doubt, is kept apart.
    using Cell = std::uint64_t;
    struct Free {
        template <class T>
        void operator()(T* p) const { std::free(p); }
    };
    // A layer's grid is stored in bricks of 32 x 32 cells (8 KiB; flatter
    // for a thin grid), so the 5 x 5 cells a dart reads lie in one or a few
    // pages, and pages are touched only where points are.
    struct Layer {
        double low, high;  // its radii: [low, high]
        double side, inv_side, step, reach;  // reach: high in cells, with slack
        double x0, y0;  // the corner of padded cell (0, 0)
        std::size_t cols, rows;  // real cells; kPad more around them
        int shift_x, shift_y;    // a brick is 2^shift_x x 2^shift_y cells
        std::size_t bricks_x;
        std::unique_ptr<Cell[], Free> cells;
        std::unique_ptr<std::uint32_t[], Free> index;  // a taken cell's point
        // The lower left corner of padded column x, row y: one formula, for
        // writing and reading offsets alike.
        double corner_x(std::size_t x) const { return x0 + static_cast<double>(x) * side; }
        double corner_y(std::size_t y) const { return y0 + static_cast<double>(y) * side; }
        // The cell in padded column x, row y (the real cells from kPad on).
        std::size_t at(std::size_t x, std::size_t y) const {
            const std::size_t mx = (std::size_t{1} << shift_x) - 1, my = (std::size_t{1} << shift_y) - 1;
            const std::size_t brick = (y >> shift_y) * bricks_x + (x >> shift_x);
            return (((brick << shift_y) | (y & my)) << shift_x) | (x & mx);
        }
    };
    // The cells of a layer a disk centred at a point may reach.
    struct Block {
        std::size_t x, y;            // the point's own cell, padded column and row
        int x_lo, x_hi, y_lo, y_hi;  // the block, relative to the own cell
    };
    struct Dart {
        Point p;
        std::size_t tile;
        std::size_t cover_cell;  // its cell in covered_
        // Its block in the first layer near it when drawn (kMaxLayers: none),
        // kept for the test (computing it again cost 4% at 10^7 points).
        std::size_t block_layer;
        Block block;
    };

    static void allocate_cells(Layer& L);
    std::size_t layer_of(double r) const;
    Block block_of(const Layer& L, const Point& p) const;
    std::size_t tile_of(const Point& p) const;
    // Records that layer `layer` has a point at p, in the tiles its disk may reach.
    void mark_layer_near(const Point& p, std::size_t layer);
    // Whether p (whose block in L is b) is outside the disks of layer L's
    // points; false at once when p's own cell is taken.
    bool free_in(const Layer& L, const Block& b, const Point& p) const;
    bool is_free(const Dart& d) const;
    void draw_batch(Dart* batch, std::size_t n, Rng& rng);
    // The Jones stage of the points (queries).
    std::unique_ptr<JonesStage> jones_of_points() const;

    Box box_;
    PointRadii radii_;
    std::vector<Layer> layers_;
    double tile_side_;
    std::size_t tile_cols_, tile_rows_;
    // Per tile: the layers with a point in it or in a tile next to it.
    std::vector<std::uint32_t> tiles_;
    CoveredCells covered_;  // the finest layer's cells inside one disk
    std::vector<Point> points_;
    std::vector<double> values_;  // point k's field value
    CurveOrder curve_;            // the hand-over's order, over the finest layer's cells

    DartQueue<Dart> queue_;
    mutable std::size_t exact_checks_ = 0;
};

}  // namespace pds

#endif
