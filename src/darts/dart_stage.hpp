// dart_stage.hpp - the opening of a run: dart throwing on a background grid,
// the sequencing apart from the grid (dart_grid.hpp for one radius,
// layered_grid.hpp for a field).
//
// Early in a run most of the domain is free, and the cheapest exact way to
// draw the next point uniformly from the free region is to throw darts
// uniformly over the whole domain and keep the first one that is free.
// Rejected darts carry no bias: conditioned on being free, a uniform dart is
// uniform over the free region, which is the law of the Jones loop (and of
// random sequential adsorption). So this stage adds points with exactly the
// same law as the Jones stage, at a fraction of the cost per dart, until the
// free fraction of the domain (the acceptance rate) falls so low that the
// Jones stage, which never misses, becomes cheaper. The switch is decided
// from the darts' own history (dart_queue.hpp), so it is a stopping time and
// the law is unchanged.
//
// The stage keeps no triangulation. Queries (free area, verify) build one on
// the fly (jones_of_points.hpp); the hand-over inserts the points into the
// Jones stage's mesh in an order that keeps walks short (curve_order.hpp),
// using scratch memory reserved with the points, so the hand-over itself
// never allocates.
//
// Fixed points (hold_fixed; a dense grid, or a field's layers) are the
// stage's first points: their clearance disks are laid over the grid's
// (finest) cells (fixed_disks.hpp), a dart inside one is a miss like any
// covered dart, and the new points are decided against one another by the
// grid, as without them. At the hand-over with one radius the mesh of the
// new points is built whole, then the fixed ones inserted (as the
// space-time process does); a field's points go in one by one after them.
//
// A Grid gives: Dart, kVarying (points keep field values), throw_darts,
// is_free, record (with the value when kVarying, asked first of value_at),
// reserve / has_room_for, release, past_memory_budget (the stage ends once
// its pages outgrow the points), cell_count (the window's scale), curve,
// radius, torus, radii. The calls per dart are the grid's inline ones: no
// virtual call.
#ifndef PDS_DART_STAGE_HPP
#define PDS_DART_STAGE_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include "core/point.hpp"
#include "core/rng.hpp"
#include "darts/curve_order.hpp"
#include "darts/dart_constants.hpp"
#include "darts/dart_grid.hpp"
#include "darts/dart_queue.hpp"
#include "darts/fixed_disks.hpp"
#include "domain/rectangle.hpp"
#include "darts/jones_of_points.hpp"
#include "darts/layered_grid.hpp"
#include "darts/opening_stage.hpp"
#include "jones/jones_stage.hpp"
#include "radius/point_radii.hpp"

namespace pds {

template <class Grid>
class DartStageOf final : public OpeningStage {
public:
    using Dart = typename Grid::Dart;

    // The domain (internal frame), then the grid's other arguments; the grid
    // covers the domain's bounds. Allocates the grid (zeroed: address space
    // until points land), throws std::bad_alloc and changes nothing else.
    // polygon: a polygonal domain inside the rectangle, or nullptr; darts
    // are then drawn only in grid cells that meet it (Grid::keep_to) and
    // kept only inside it.
    template <class... Args>
    explicit DartStageOf(const Rectangle& domain, std::shared_ptr<const Polygon> polygon, Args&&... args)
        : domain_(domain),
          polygon_(std::move(polygon)),
          grid_(domain.bounds(), std::forward<Args>(args)...),
          curve_(grid_.curve(domain.bounds())) {
        if (polygon_) grid_.keep_to(*polygon_);  // before the rule: it scales with the cells kept
        // A window long enough that its acceptance rate is a fair estimate,
        // short enough that the stage ends soon after the rate falls.
        // (A window past SIZE_MAX darts, on a 32-bit target, is never reached.)
        const auto window = std::min<GridCell>(grid_.cell_count() / 16, static_cast<std::size_t>(-1));
        queue_.set_rule(std::max<std::size_t>(darts::kMinWindow, static_cast<std::size_t>(window)),
                        darts::kMinAcceptance);
    }

    // Room for `points` points in all, and the hand-over's scratch; strong
    // guarantee (std::bad_alloc): each reserve succeeds or changes nothing.
    void reserve(std::size_t points) override {
        points_.reserve(points);
        if (has_values()) values_.reserve(points);
        curve_.reserve(points);
        grid_.reserve(points);
    }
    // Every vector reserve() grows: a reserve that failed half-way must not
    // pass for room, or the hand-over would allocate.
    bool has_room_for(std::size_t points) const override {
        return points_.capacity() >= points && (!has_values() || values_.capacity() >= points) &&
               curve_.has_room_for(points) && grid_.has_room_for(points);
    }
    void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) override {
        const std::uint32_t* order = handover_order();
        poll();
        if (!fixed_) {
            jones.adopt(points_, order, Grid::kVarying ? &values_ : nullptr, poll);
            return;
        }
        jones.set_fixed(fixed_->count);
        // With one radius the new points' regular mesh is their Delaunay
        // mesh, built whole; the fixed ones go in after.
        jones.adopt(points_, order, &values_, poll, Grid::kVarying ? MeshBuild::insert : MeshBuild::whole);
    }
    // Fixed points (internal frame) with their values, before the first
    // point: they become the stage's first points, a dart inside a
    // clearance disk (radii.radius_of(value)) is covered, and the new
    // points get new_value (a field's: their own). False, and the stage
    // must not be used, for a grid that keeps only its taken cells, for
    // disks whose bounding boxes span more than 4 grids plus 2^20 cells in
    // all (the Jones loop alone is cheaper there, as in the space-time
    // process). Throws std::bad_alloc.
    bool hold_fixed(const std::vector<Point>& points, const std::vector<double>& values, const PointRadii& radii,
                    double new_value) override {
        if constexpr (std::is_same_v<Grid, DartGrid<SparseCells>>) {
            return false;
        } else {
            if (!points_.empty()) throw std::logic_error("hold_fixed after the first point");
            std::vector<double> clearances(points.size());
            for (std::size_t k = 0; k < points.size(); ++k) clearances[k] = radii.radius_of(values[k]);
            const DiskGrid cells = grid_.disk_grid();
            FixedDisks disks;
            if (!disks.build(cells, points, clearances, 4 * cells.cols * cells.rows + (std::size_t{1} << 20)))
                return false;
            // Copied first, swapped in after: a failure changes nothing.
            auto held = std::make_unique<Held>(Held{points.size(), new_value, radii, std::move(disks), cells});
            std::vector<Point> first = points;
            std::vector<double> their_values = values;
            points_.swap(first);
            values_.swap(their_values);
            fixed_ = std::move(held);
            return true;
        }
    }

    void set_memory_budget(double bytes_per_point, std::size_t floor_bytes) override {
        if constexpr (Grid::kVarying) grid_.set_memory_budget(bytes_per_point, floor_bytes);
    }

    std::size_t count() const override { return points_.size(); }
    const Point& point(PointIndex k) const override { return points_[k]; }
    double value(PointIndex k) const override { return has_values() ? values_[k] : 0.0; }
    // Throws darts until one is free and returns it. Returns nullptr once
    // the stage is over (the acceptance rate over a window of darts fell
    // below kMinAcceptance, or the grid passed its memory budget), and from
    // then on.
    const Point* next(Rng& rng) override {
        const Dart* d = queue_.next(
            [&](const Dart& x) {
                return domain_.contains(x.p) && (!polygon_ || Grid::surely_inside(x) || polygon_->contains(x.p)) &&
                       (!fixed_ || !in_clearance(x));
            },
                                    [&](Dart* batch, std::size_t n) { grid_.throw_darts(batch, n, rng); },
                                    [&](const Dart& x) { return grid_.is_free(x, points_, values_); });
        return d ? &d->p : nullptr;
    }
    // A field asks the point's value first (FieldError: nothing changed).
    void add_next() override {
        const Dart& d = queue_.pending();
        const auto index = static_cast<std::uint32_t>(points_.size());
        if constexpr (Grid::kVarying) {
            const double value = grid_.value_at(d.p);
            grid_.record(d, index, value);
            values_.push_back(value);
        } else {
            grid_.record(d, index);
            if (fixed_) values_.push_back(fixed_->new_value);
        }
        points_.push_back(d.p);
        queue_.take();
        // A stopping time like the acceptance rule: decided by the points so far.
        if (grid_.past_memory_budget()) queue_.end();
    }
    double free_area() const override { return jones_of_points()->free_area(); }
    // Failures name points in the order added.
    VerifyReport verify() const override { return jones_of_points()->verify(); }

    const std::vector<Point>& points() const { return points_; }
    const Grid& grid() const { return grid_; }
    std::size_t exact_checks() const { return grid_.exact_checks(); }
    // Darts thrown so far, landed or not (bench/phases.cpp).
    std::size_t darts_thrown() const { return queue_.thrown(); }
    // The points' indices in the order the hand-over inserts them, written
    // into the reserved scratch: never allocates. Ends the stage and
    // releases its grid before the Jones stage's mesh is filled, so the two
    // never peak together.
    const std::uint32_t* handover_order() {
        grid_.release();
        queue_.end();
        if (fixed_) fixed_->disks = FixedDisks{};
        return curve_.order(points_, 1, fixed_count());  // the fixed points first
    }

private:
    std::size_t fixed_count() const { return fixed_ ? fixed_->count : 0; }
    bool has_values() const { return Grid::kVarying || fixed_; }
    // Whether a dart lies strictly inside a fixed point's clearance.
    bool in_clearance(const Dart& d) const { return fixed_->disks.covered(d.p, grid_.disk_cell(d, fixed_->grid)); }
    std::unique_ptr<JonesStage> jones_of_points() const {
        std::unique_ptr<JonesStage> jones =
            pds::jones_of_points(domain_, polygon_, grid_.radius(), grid_.torus(), fixed_ ? &fixed_->radii : grid_.radii(),
                                 points_, has_values() ? &values_ : nullptr, curve_);
        jones->set_fixed(fixed_count());
        return jones;
    }

    Rectangle domain_;
    std::shared_ptr<const Polygon> polygon_;
    Grid grid_;
    std::vector<Point> points_;
    std::vector<double> values_;  // a field, or with fixed points: point k's value
    // What hold_fixed keeps: the fixed points are the first `count` of
    // points_; the new ones' value (one radius); the disks over the grid's cells.
    struct Held {
        std::size_t count;
        double new_value;
        PointRadii radii;
        FixedDisks disks;
        DiskGrid grid;
    };
    std::unique_ptr<Held> fixed_;  // none without fixed points
    CurveOrder curve_;  // the hand-over's order over the grid's cells, its scratch reserved with the points
    DartQueue<Dart> queue_;
};

// One radius on the plane or the torus, on a dense grid.
using DartStage = DartStageOf<DartGrid<DenseCells>>;
// One radius where the whole grid would not fit the address space: the
// same decisions, on a grid that keeps only its taken cells.
using SparseDartStage = DartStageOf<DartGrid<SparseCells>>;
// A varying radius, on the plane or the torus.
using FieldDartStage = DartStageOf<LayeredGrid>;

extern template class DartStageOf<DartGrid<DenseCells>>;
extern template class DartStageOf<DartGrid<SparseCells>>;
extern template class DartStageOf<LayeredGrid>;

}  // namespace pds

#endif
