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
// A Grid gives: Dart, kVarying (points keep field values), throw_darts,
// is_free, record (with the value when kVarying, asked first of value_at),
// reserve / has_room_for, release, cell_count (the window's scale), curve,
// radius, torus, radii. The calls per dart are the grid's inline ones: no
// virtual call.
#ifndef PDS_DART_STAGE_HPP
#define PDS_DART_STAGE_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/point.hpp"
#include "core/rng.hpp"
#include "darts/curve_order.hpp"
#include "darts/dart_constants.hpp"
#include "darts/dart_grid.hpp"
#include "darts/dart_queue.hpp"
#include "domain/rectangle.hpp"
#include "darts/jones_of_points.hpp"
#include "darts/layered_grid.hpp"
#include "darts/opening_stage.hpp"
#include "jones/jones_stage.hpp"

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
        if (Grid::kVarying) values_.reserve(points);
        curve_.reserve(points);
        grid_.reserve(points);
    }
    // Every vector reserve() grows: a reserve that failed half-way must not
    // pass for room, or the hand-over would allocate.
    bool has_room_for(std::size_t points) const override {
        return points_.capacity() >= points && (!Grid::kVarying || values_.capacity() >= points) &&
               curve_.has_room_for(points) && grid_.has_room_for(points);
    }
    void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) override {
        const std::uint32_t* order = handover_order();
        poll();
        jones.adopt(points_, order, Grid::kVarying ? &values_ : nullptr, poll);
    }

    std::size_t count() const override { return points_.size(); }
    const Point& point(PointIndex k) const override { return points_[k]; }
    double value(PointIndex k) const override { return Grid::kVarying ? values_[k] : 0.0; }
    // Throws darts until one is free and returns it. Returns nullptr once
    // the stage is over (the acceptance rate over a window of darts fell
    // below kMinAcceptance), and from then on.
    const Point* next(Rng& rng) override {
        const Dart* d = queue_.next(
            [&](const Dart& x) {
                return domain_.contains(x.p) && (!polygon_ || Grid::surely_inside(x) || polygon_->contains(x.p));
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
        }
        points_.push_back(d.p);
        queue_.take();
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
        return curve_.order(points_);
    }

private:
    std::unique_ptr<JonesStage> jones_of_points() const {
        return pds::jones_of_points(domain_, polygon_, grid_.radius(), grid_.torus(), grid_.radii(), points_,
                                    Grid::kVarying ? &values_ : nullptr, curve_);
    }

    Rectangle domain_;
    std::shared_ptr<const Polygon> polygon_;
    Grid grid_;
    std::vector<Point> points_;
    std::vector<double> values_;  // a field: point k's value
    CurveOrder curve_;  // the hand-over's order over the grid's cells, its scratch reserved with the points
    DartQueue<Dart> queue_;
};

// One radius on the plane or the torus, on a dense grid.
using DartStage = DartStageOf<DartGrid<DenseCells>>;
// One radius where the whole grid would not fit the address space: the
// same decisions, on a grid that keeps only its taken cells.
using SparseDartStage = DartStageOf<DartGrid<SparseCells>>;
// A varying radius, on the plane.
using FieldDartStage = DartStageOf<LayeredGrid>;

extern template class DartStageOf<DartGrid<DenseCells>>;
extern template class DartStageOf<DartGrid<SparseCells>>;
extern template class DartStageOf<LayeredGrid>;

}  // namespace pds

#endif
