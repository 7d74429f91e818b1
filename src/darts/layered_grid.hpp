// layered_grid.hpp - the background grids of dart throwing with a varying
// radius, a grid per layer of radii: is this dart outside every disk?
// record a point with its radius.
//
// The rule of a field (point_radii.hpp): a later point keeps out of every
// earlier point's disk, by that disk's own radius. One grid sized by the
// smallest radius would have to be searched as far as the largest: a 1:4
// field reads 12 x 12 cells a dart. Instead the points are split into layers
// by radius, each a factor kLayerRatio (under sqrt 2) wider than the last:
// layer k holds the radii in [low_k, kLayerRatio low_k). Two points of a
// layer are at least low_k apart (the earlier one's radius), so a grid of
// cells of side 0.99 low_k / sqrt 2 holds at most one of them a cell, and its
// disk, at most kLayerRatio low_k wide, reaches under 2 cells: a dart reads
// at most 5 x 5 cells of each layer. A coarse grid of tiles as wide as the
// largest radius records which layers have points in each tile, so a dart
// reads only the layers near it: where the field is smooth, one or two. A
// bitmap of the finest cells that lie inside one disk (covered_bitmap.hpp)
// rejects most darts in the regions of large disks before any block is read.
//
// A cell is 8 bytes: the point's offset in the cell, rounded as in the
// one-radius grid (dart_grid.hpp), and its radius as a float; distances the
// rounding leaves in doubt read the point's index from a parallel array and
// go to the exact predicate with the exact point and radius.
//
// On the torus a point also stands for its copies a period away. It is
// recorded once, in the fundamental domain; a dart within the largest
// radius of the domain's edge is tested again at its own copies there (the
// darts are snapped, so a copy is exact: torus.hpp), which is the same as
// testing the dart against the points' copies. The copies' tests go through
// the same blocks, clamped to the grid's edge, with no shortcut by the own
// cell: every point they meet is judged by its distance.
#ifndef PDS_LAYERED_GRID_HPP
#define PDS_LAYERED_GRID_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "core/point.hpp"
#include "core/predicates.hpp"
#include "core/prefetch.hpp"
#include "core/rng.hpp"
#include "core/torus.hpp"
#include "domain/polygon.hpp"
#include "darts/covered_bitmap.hpp"
#include "darts/curve_order.hpp"
#include "darts/dart_constants.hpp"
#include "darts/fixed_disks.hpp"
#include "darts/grid_arithmetic.hpp"
#include "darts/polygon_raster.hpp"
#include "radius/point_radii.hpp"

namespace pds {

class LayeredGrid {
public:
    static constexpr bool kVarying = true;  // each point keeps its field value
    // Fields whose largest radius is at most this many times the smallest
    // get the grids. Their address space follows the smallest radius (a few
    // words a point of a pattern of it); the budget below bounds what is touched.
    static constexpr double kMaxRatio = 16.0;
    // The memory budget: the stage ends once the pages its grids touched
    // pass this many bytes for each point the maximal pattern is expected
    // to hold, above a floor. A smooth field fills the pages it touches
    // (about 50 bytes for each point of the pattern, measured at 1:2 to
    // 1:16); a fine-grained one scatters its small radii, and each lone
    // point in a fine layer touches a page of cells and one of indices
    // (470-560 bytes a point of the pattern, measured with noise maps).
    // The budget is a little over what the Jones loop's mesh takes for a
    // field's pattern (170-210 bytes a point measured): a fine-grained
    // field's peak at 10^6 points stays within about 1.6 times the loop's
    // alone (3 times without the budget), and a map grained coarser than
    // its largest radius keeps its darts' speed.
    static constexpr double kBudgetBytesPerPoint = 256.0;
    static constexpr std::size_t kBudgetFloorBytes = std::size_t{16} << 20;
    // The expected count is the frame's (a maximal pattern's, with its edge
    // excess), at the radius R whose 1 / R^2 is the field's mean 1 / r^2. A
    // map's mean is taken over the domain at the start; a function is asked
    // only where points land, so its mean is judged from the points so far
    // (their count over the sum of their r^2: low early, when they are
    // spread evenly and the small radii's crowds have yet to come, so the
    // budget then errs on the side of memory). Measured on a 1:4 ramp: a
    // map's within 1%, a function's 0.84-0.87 of the pattern's count at the
    // stage's end. A field grained within a few radii holds fewer points
    // than its mean says (large disks cover the small grains: 1.5 times too
    // many for a map of 1:8 noise whose pixels are 0.25 to 2 radii wide),
    // so there the budget is more lenient.

private:
    static constexpr double kLayerRatio = 1.39;  // reach: 1.39 sqrt 2 / 0.99 = 1.986 cells
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
        // The pages of cells and of indices a point has been written to.
        std::vector<bool> cell_pages, index_pages;
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

public:
    struct Dart {
        Point p;
        std::size_t tile;
        std::size_t cover_cell;  // its cell in the covered bitmap
        // Its block in the first layer near it when drawn (kMaxLayers: none),
        // kept for the test rather than computed again.
        std::size_t block_layer;
        Block block;
        bool inside;  // drawn in a raster cell wholly inside keep_to's polygon
    };

    // domain and radii in the internal frame; on the torus (torus.on()) the
    // domain is its fundamental one. Allocates the grids (zeroed: address
    // space until points land); throws std::bad_alloc.
    LayeredGrid(const Box& domain, const PointRadii& radii, const Torus& torus = Torus{});

    void reserve(std::size_t) {}
    bool has_room_for(std::size_t) const { return true; }

    // n darts uniform over the finest layer's cells (with keep_to's raster,
    // over its cells), their tiles, bitmap words and blocks prefetched.
    void throw_darts(Dart* batch, std::size_t n, Rng& rng) const;
    // A polygonal domain: darts uniform over the whole box, the stage keeping
    // those inside it (exact); or, for a polygon that fills little of the box
    // (raster_suits), uniform over the finest layer's cells it may meet
    // (polygon_raster.hpp), where over the box most darts would be drawn in
    // vain.
    void keep_to(const Polygon& polygon);
    static bool surely_inside(const Dart& d) { return d.inside; }
    // The finest layer's real cells, for laying fixed disks over them, and
    // a dart's cell there (found as the covered bitmap finds it).
    DiskGrid disk_grid() const {
        const Layer& f = layers_.front();
        return DiskGrid{box_, f.cols, f.rows, f.side, f.side};
    }
    std::uint32_t disk_cell(const Dart& d, const DiskGrid& g) const {
        const double inv = layers_.front().inv_side;
        return static_cast<std::uint32_t>(clamped_cell((d.p.y - box_.y0) * inv, g.rows) * g.cols +
                                          clamped_cell((d.p.x - box_.x0) * inv, g.cols));
    }
    // Whether keep_to's darts are drawn among its polygon's raster (tests).
    bool draws_in_raster() const { return raster_.cells() > 0; }
    // Whether d is outside every disk; points[k] and values[k] are point
    // k's position and field value.
    bool is_free(const Dart& d, const std::vector<Point>& points, const std::vector<double>& values) const;
    // The field's value at the point about to be recorded (may throw
    // FieldError, before anything changes).
    double value_at(const Point& p) const { return radii_.value_at(p); }
    // Records point `index`, whose field value is `value`, at d.
    void record(const Dart& d, std::uint32_t index, double value);
    // Frees the grids: the stage is over.
    void release();
    // Whether the pages the grids touched are past the memory budget (the
    // stage then ends).
    bool past_memory_budget() const {
        if (touched_bytes_ <= budget_floor_) return false;
        return static_cast<double>(touched_bytes_ - budget_floor_) > budget_per_point_ * expected_count();
    }
    // The count the maximal pattern is expected to reach; for a function,
    // requires a point recorded.
    double expected_count() const;
    // The bytes of the pages points were written to (4 KiB pages; the
    // budget is an estimate where pages are larger).
    std::size_t touched_bytes() const { return touched_bytes_; }
    // Another budget (tests: the hand-over it causes, in small runs).
    void set_memory_budget(double per_point, std::size_t floor) {
        budget_per_point_ = per_point;
        budget_floor_ = floor;
    }

    // The sampling rule's scale: the coarsest layer's cells (with a raster,
    // the share of them its cells cover).
    std::size_t cell_count() const;
    // The hand-over's curve over the finest layer's cells.
    CurveOrder curve(const Box& domain) const;
    double radius() const { return radii_.rmax(); }
    const Torus& torus() const { return torus_; }
    const PointRadii* radii() const { return &radii_; }

    // Internals, for tests.
    std::size_t layer_count() const { return layers_.size(); }
    const CoveredBitmap& covered() const { return covered_; }
    // Distances the rounded offsets left undecided (for tests).
    std::size_t exact_checks() const { return exact_checks_; }

private:
    static void allocate_cells(Layer& L);
    std::size_t layer_of(double r) const;
    Block block_of(const Layer& L, const Point& p) const;
    std::size_t tile_of(const Point& p) const;
    // Records that layer `layer` has a point at p, in the tiles its disk may reach.
    void mark_layer_near(const Point& p, std::size_t layer);
    // Counts the pages of L's cell and index that a point written there
    // touches for the first time.
    void touch(Layer& L, std::size_t cell);
    // Whether p (whose block in L is b) is outside the disks of layer L's
    // points; with kOwnCell (b's own cell is p's), false at once when that
    // cell is taken.
    template <bool kOwnCell = true>
    bool free_in(const Layer& L, const Block& b, const Point& p, const std::vector<Point>& points,
                 const std::vector<double>& values) const;
    // On the torus: whether p's copies a period away (those within the
    // largest radius of the domain) are outside every disk.
    bool copies_free(const Point& p, const std::vector<Point>& points, const std::vector<double>& values) const;

    Box box_;
    PointRadii radii_;
    Torus torus_;  // off in the plane
    std::vector<Layer> layers_;
    double tile_side_;
    std::size_t tile_cols_, tile_rows_;
    // Per tile: the layers with a point in it or in a tile next to it.
    std::vector<std::uint32_t> tiles_;
    CoveredBitmap covered_;  // the finest layer's cells inside one disk
    PolygonRaster raster_;   // keep_to's, on the finest layer's cells; or none
    mutable std::size_t exact_checks_ = 0;
    // The memory budget's state: a map's expected count, taken at the start
    // (0 for a function); the points recorded and the sum of their values^2.
    double map_expected_count_ = 0.0;
    std::size_t recorded_ = 0;
    double value_squares_ = 0.0;
    std::size_t touched_bytes_ = 0;
    double budget_per_point_ = kBudgetBytesPerPoint;
    std::size_t budget_floor_ = kBudgetFloorBytes;
};

// The per-dart calls, inline: the stage's loop (dart_stage.hpp) runs them
// for every dart.

namespace layered_grid {

// A cell's radius, stored as a float in bits 32-63.
inline double radius_in(std::uint64_t word) {
    const auto bits = static_cast<std::uint32_t>(word >> 32);
    float r;
    std::memcpy(&r, &bits, sizeof r);
    return static_cast<double>(r);
}

}  // namespace layered_grid

inline std::size_t LayeredGrid::tile_of(const Point& p) const {
    const std::size_t x = clamped_cell((p.x - box_.x0) / tile_side_, tile_cols_);
    const std::size_t y = clamped_cell((p.y - box_.y0) / tile_side_, tile_rows_);
    return y * tile_cols_ + x;
}

inline LayeredGrid::Block LayeredGrid::block_of(const Layer& L, const Point& p) const {
    using darts::kPad;
    const double fx = (p.x - box_.x0) * L.inv_side, fy = (p.y - box_.y0) * L.inv_side;
    const auto col = static_cast<std::int64_t>(clamped_cell(fx, L.cols));
    const auto row = static_cast<std::int64_t>(clamped_cell(fy, L.rows));
    Block b;
    b.x = static_cast<std::size_t>(col + kPad);
    b.y = static_cast<std::size_t>(row + kPad);
    b.x_lo = block_offset(fx - L.reach, col, kPad);
    b.x_hi = block_offset(fx + L.reach, col, kPad);
    b.y_lo = block_offset(fy - L.reach, row, kPad);
    b.y_hi = block_offset(fy + L.reach, row, kPad);
    return b;
}

template <bool kOwnCell>
inline bool LayeredGrid::free_in(const Layer& L, const Block& b, const Point& p, const std::vector<Point>& points,
                                 const std::vector<double>& values) const {
    // A taken cell is covered whole: its point's radius is over its diagonal.
    if (kOwnCell && L.cells[L.at(b.x, b.y)] != 0) return false;
    // Whether the point in the cell i rows and j columns from the dart's (if
    // there is one) lies within its radius.
    const auto covers = [&](int i, int j) {
        const std::size_t x = b.x + static_cast<std::size_t>(j), y = b.y + static_cast<std::size_t>(i);
        const std::size_t cell = L.at(x, y);
        const Cell word = L.cells[cell];
        if (word == 0) return false;
        const double qx = L.corner_x(x) + (static_cast<double>(word & 0xFFFF) + 0.5) * L.step;
        const double qy = L.corner_y(y) + (static_cast<double>((word >> 16) & 0xFFFF) + 0.5) * L.step;
        const double dx = qx - p.x, dy = qy - p.y, r = layered_grid::radius_in(word);
        const double d2 = dx * dx + dy * dy, r2 = r * r;
        if (d2 < r2 * (1.0 - darts::kFilterSlack)) return true;
        if (!(d2 < r2 * (1.0 + darts::kFilterSlack))) return false;
        // The float radius is within 2^-24 of the point's: far inside the slack.
        ++exact_checks_;
        const std::uint32_t k = L.index[cell];
        return compare_distance(p, points[k], radii_.radius_of(values[k])) < 0;
    };
    // A layer's radii span over one cell, so the block holds the eight
    // around the dart's own cell (grid_arithmetic.hpp reads those first).
    if (!kOwnCell && covers(0, 0)) return false;
    return !block_covers(b.x_lo, b.x_hi, b.y_lo, b.y_hi, covers);
}

inline bool LayeredGrid::is_free(const Dart& d, const std::vector<Point>& points,
                                 const std::vector<double>& values) const {
    if (covered_.covered(d.cover_cell)) return false;
    // The layers near as they are now: points added since the dart was
    // drawn may have brought new ones.
    for (std::uint32_t m = tiles_[d.tile]; m != 0; m &= m - 1) {
        const auto k = static_cast<std::size_t>(__builtin_ctz(m));
        const Layer& L = layers_[k];
        if (!free_in(L, k == d.block_layer ? d.block : block_of(L, d.p), d.p, points, values)) return false;
    }
    return !torus_.on() || copies_free(d.p, points, values);
}

inline void LayeredGrid::throw_darts(Dart* batch, std::size_t n, Rng& rng) const {
    const Layer& finest = layers_.front();
    const double w = static_cast<double>(finest.cols) * finest.side, h = static_cast<double>(finest.rows) * finest.side;
    // First the darts, their tiles and bitmap words (megabytes in a large
    // run: misses too); then the blocks of those still in doubt.
    for (std::size_t at = 0; at < n; ++at) {
        Dart& d = batch[at];
        d.inside = false;
        if (raster_.cells() > 0) {
            const PolygonRaster::Dart r = raster_.draw(rng);
            d.p = r.p;
            d.inside = r.inside;
        } else if (torus_.on()) {
            // On the torus grid, inside the fundamental domain (torus.hpp).
            const double u = rng.next_double(), v = rng.next_double();
            d.p = torus_.wrap(Point{Torus::snap(torus_.x0 + u * torus_.px), Torus::snap(torus_.y0 + v * torus_.py)});
        } else {
            d.p.x = box_.x0 + rng.next_double() * w;
            d.p.y = box_.y0 + rng.next_double() * h;
        }
        d.tile = tile_of(d.p);
        d.cover_cell = covered_.cell_of(d.p);
        pds::prefetch(&tiles_[d.tile]);
        covered_.prefetch(d.cover_cell);
    }
    for (std::size_t at = 0; at < n; ++at) {
        Dart& d = batch[at];
        d.block_layer = kMaxLayers;
        if (covered_.covered(d.cover_cell)) continue;  // no block to read
        // Each near layer's block: 4 or 5 rows of at most 40 bytes. The first
        // layer's is kept (most darts have one).
        for (std::uint32_t m = tiles_[d.tile]; m != 0; m &= m - 1) {
            const auto k = static_cast<std::size_t>(__builtin_ctz(m));
            const Layer& L = layers_[k];
            const Block b = block_of(L, d.p);
            if (d.block_layer == kMaxLayers) {
                d.block = b;
                d.block_layer = k;
            }
            for (int i = b.y_lo; i <= b.y_hi; ++i) {
                const std::size_t y = b.y + static_cast<std::size_t>(i);
                pds::prefetch(L.cells.get() + L.at(b.x + static_cast<std::size_t>(b.x_lo), y));
                pds::prefetch(L.cells.get() + L.at(b.x + static_cast<std::size_t>(b.x_hi), y));
            }
        }
    }
}

}  // namespace pds

#endif
