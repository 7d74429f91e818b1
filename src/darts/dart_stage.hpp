// dart_stage.hpp - the opening of a run: dart throwing on a background grid.
//
// Early in a run most of the domain is free, and the cheapest exact way to
// draw the next point uniformly from the free region is to throw darts
// uniformly over the whole domain and keep the first one that is at least R
// from every point. Rejected darts carry no bias: conditioned on being free, a
// uniform dart is uniform over the free region, which is the law of the Jones
// loop (and of random sequential adsorption). So this stage adds points with
// exactly the same law as the Delaunay stage, at a fraction of the cost per
// dart, until the free fraction of the domain (the acceptance rate) falls so
// low that the Delaunay stage, which never misses, becomes cheaper. The switch
// is decided from the darts' own history, so it is a stopping time and the law
// is unchanged.
//
// The grid: cells of side s = 0.99 R / sqrt 2, so a cell's diagonal is under
// R and no two points can share one; a point closer than R to a dart lies at
// most two cells away, and only in the 3 or 4 columns and rows that the
// dart's own disk reaches, so one dart reads at most a 4 x 4 block.
// A cell is 8 bytes: its point's index (plus one: zeroed memory is an empty
// grid, its pages touched only where points land) and the point's offset in
// the cell rounded to 16 bits a side. Distances from the rounded offsets
// decide all but the pairs within 2^-12 of R (rounding moves a point by under
// 2^-17 of a cell, under 10^-5 R); those read the exact point and go to the
// exact predicate. Half the bytes of whole coordinates: half the lines a
// dart misses, half the pages the kernel zeroes.
//
// Memory-level parallelism: darts are drawn in batches and their blocks are
// prefetched before any is tested, so the cache misses of a batch overlap.
// The batch persists across calls, so splitting a run does not change it.
//
// The stage keeps no triangulation. Queries (free area, verify) build one on
// the fly; the hand-over inserts the points into the Jones stage's mesh in
// an order that keeps walks short (handover_order), using scratch memory
// reserved with the points, so the hand-over itself never allocates.
#ifndef PDS_DART_STAGE_HPP
#define PDS_DART_STAGE_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "core/batch.hpp"
#include "darts/curve_order.hpp"
#include "darts/dart_queue.hpp"
#include "mesh/delaunay.hpp"
#include "jones/jones_stage.hpp"
#include "darts/opening_stage.hpp"
#include "core/point.hpp"
#include "core/rng.hpp"
#include "core/torus.hpp"

namespace pds {

class DartStage final : public OpeningStage {
public:
    // Allocates the grid (zeroed: address space until points land); throws
    // std::bad_alloc and changes nothing else.
    // On the torus (torus.on()) the grid wraps: its cells divide the periods
    // exactly and the padding holds the copies of the points along the
    // opposite edges, so a dart's 5 x 5 block sees every copy near it.
    DartStage(const Box& domain, double radius, const Torus& torus = Torus{});

    // Room for `points` points in all, and the hand-over's scratch; strong
    // guarantee (std::bad_alloc).
    void reserve(std::size_t points) override;
    // Every vector reserve() grows: a reserve that failed half-way must not
    // pass for room, or the hand-over would allocate.
    bool has_room_for(std::size_t points) const override {
        return points_.capacity() >= points && curve_.has_room_for(points);
    }
    void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) override {
        const std::uint32_t* order = handover_order();
        poll();
        jones.adopt(points_, order, nullptr, poll);
    }

    std::size_t count() const override { return points_.size(); }
    const Point& point(PointIndex k) const override { return points_[k]; }
    double value(PointIndex) const override { return 0.0; }
    // Throws darts until one is at least R from every point and returns it.
    // Returns nullptr once the stage is over (the acceptance rate over a
    // window of darts fell below kMinAcceptance), and from then on.
    const Point* next(Rng& rng) override;
    void add_next() override;
    double free_area() const override;
    VerifyReport verify() const override;

    const std::vector<Point>& points() const { return points_; }
    // Distances the rounded offsets left undecided, sent to the exact
    // predicate (for tests: the path must be taken).
    std::size_t exact_checks() const { return exact_checks_; }
    // Darts thrown so far, landed or not (bench/phases.cpp).
    std::size_t darts_thrown() const { return queue_.thrown(); }
    // The points' indices in the order the hand-over inserts them (see the
    // .cpp); written into the reserved scratch: never allocates. Ends the
    // stage and releases its grid.
    const std::uint32_t* handover_order();

private:
    // Fraction of darts that must still land free, over a window, to go on.
    // Chosen by measurement (make bench): below about 4% a dart costs more per
    // point than the Delaunay stage does.
    static constexpr double kMinAcceptance = 0.04;
    static constexpr std::size_t kMinWindow = 256;  // darts per window, at least
    // Cells of side kCellShrink * R / sqrt 2: a diagonal under R even after
    // rounding, so a cell never holds two points.
    static constexpr double kCellShrink = 0.99;
    // The filter decides |p - q|^2 against R^2 (1 -+ kFilterSlack), q read
    // from its cell's rounded offsets: 16 times wider than that rounding can
    // move a distance (under 2^-17 of a cell a side, a cell under 0.71 R: a
    // distance by under 7.6e-6 R, a squared one by under 1.6e-5 R^2), so only
    // distances within the slack go to the exact predicate.
    static constexpr double kFilterSlack = 0x1.0p-12;
    static constexpr double kOffsetSteps = 65536.0;  // 16 bits a side
    static constexpr int kPad = 2;  // empty cells around the grid: no bounds tests

    struct Dart {
        Point p;
        std::size_t cell;
        std::int64_t col, row;  // its cell's column and row, without the padding
        // The cells the dart's disk reaches, relative to its own: columns
        // x_lo..x_hi and rows y_lo..y_hi, each within -kPad..kPad.
        int x_lo, x_hi, y_lo, y_hi;
    };
    // Bits 0-31: point index + 1 (0: empty); 32-47 and 48-63: the offset in
    // the cell along x and y, in steps of side / kOffsetSteps.
    using Cell = std::uint64_t;
    struct Free {
        void operator()(Cell* p) const { std::free(p); }
    };

    // A triangulation of the points, for queries; vertex v holds point
    // order[v - kGhosts].
    Delaunay triangulate(std::vector<std::uint32_t>& order) const;
    // The torus: the points with their copies, as the Jones stage keeps them.
    std::unique_ptr<JonesStage> torus_stage(std::vector<std::uint32_t>& order) const;
    // The lower left corner of the cell in column col, row row (the padding's
    // columns and rows are negative or past the last): one formula, for
    // writing and reading offsets alike.
    double cell_x0(std::int64_t col) const { return box_.x0 + static_cast<double>(col) * side_x_; }
    double cell_y0(std::int64_t row) const { return box_.y0 + static_cast<double>(row) * side_y_; }
    // Point `index` (or its copy) p into the cell in column col, row row.
    void write(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index);
    // The exact point of a nonempty cell (its copy, in the padding of a torus).
    Point exact(std::size_t cell, Cell word) const;
    // The torus: the copies of p (in cell column col, row row) into the padding.
    void write_copies(std::int64_t col, std::int64_t row, const Point& p, std::uint32_t index);
    void aim(Dart& d) const;  // fills d's cell, column, row and block from d.p
    void draw_batch(Dart* batch, std::size_t n, Rng& rng);
    bool is_free(const Dart& d) const;

    Box box_;
    double r_;
    double r2_low_, r2_high_;  // R^2 bracketing the rounding of a squared distance
    double side_x_, side_y_;   // s, or on the torus the periods divided evenly
    double inv_side_x_, inv_side_y_;
    double step_x_, step_y_;    // an offset step: side / kOffsetSteps
    double reach_x_, reach_y_;  // R in cells, with a little slack
    Torus torus_;
    std::size_t cols_ = 0, rows_ = 0;  // real cells; the padded row has cols_ + 2 kPad
    std::size_t stride_ = 0;
    std::unique_ptr<Cell[], Free> cells_;
    std::vector<Point> points_;
    CurveOrder curve_;  // the hand-over's order over the grid's cells, its scratch reserved with the points

    DartQueue<Dart> queue_;
    mutable std::size_t exact_checks_ = 0;
};

}  // namespace pds

#endif
