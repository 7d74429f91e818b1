// space_time_stage.hpp - the opening of a one-radius run in a rectangle, a
// polygon or on the torus: dart throwing as a space-time process, resolved
// by several threads with the same points on any number of them.
//
// The darts. Every cell of the grid (space_time_grid.hpp) receives darts as
// a Poisson process in time, uniform over the cell, all cells at the same
// rate: together, a Poisson process on domain x time, so the darts taken in
// order of time are independent and uniform over the domain. Which active
// cells draw darts in epoch e (times in [e, e+1)) comes from their row's
// stream keyed by (seed, row, e), by the gaps between them
// (core/poisson_gaps.hpp); such a cell's count and darts come from its own
// stream (space_time_stream.hpp) keyed by (seed, cell, e). The active cells
// follow from the earlier epochs, so the set of darts is fixed by the seed
// alone.
//
// The points. A dart becomes a point iff it lies in the domain (a rectangle,
// or a polygon: sub_square_raster.hpp says which sub-squares need no test;
// on the torus, snapped to its grid) and no earlier point lies within R (on
// the torus, no copy: the grid's padding holds them, space_time_grid.hpp):
// greedy independent set in order of time. Conditioned
// on the points before it, the next point is uniform over the free region:
// random sequential adsorption, the Jones loop's law. A cell certified
// covered (it holds a point, or each of its 4 x 4 sub-squares lies in one
// disk) leaves the active set; its darts could never land free, so skipping
// them changes no point.
//
// An epoch, for the active cells, in bands of rows (one per worker): (1) draw
// the darts and drop those an earlier epoch's point covers; the survivors
// ("candidates") are listed in their cells' words; (2) decide each one: it
// is rejected iff an earlier candidate within R was accepted, which asks
// those first (memoized, so each is decided once; two workers that decide
// the same one near a band's edge find the same outcome), in the order of
// the cells, so the reads stay near one another; (3) number the accepted
// ones by time and write them into the grid; (4) drop the cells now
// certified covered. The outcome is the greedy set itself, whatever the
// bands or the scheduling. The stage ends after an epoch whose darts landed
// free less often than kStopAcceptance: a stopping time, so the Jones loop
// goes on with the same law.
//
// Points are handed out one at a time in order of time (next / add_next), so
// a run split into calls gives the same points. An epoch is all or nothing:
// std::bad_alloc during one leaves the stage as it was before it.
#ifndef PDS_SPACE_TIME_STAGE_HPP
#define PDS_SPACE_TIME_STAGE_HPP

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/point.hpp"
#include "core/poisson_gaps.hpp"
#include "core/torus.hpp"
#include "core/worker_pool.hpp"
#include "darts/curve_order.hpp"
#include "darts/fixed_disks.hpp"
#include "darts/opening_stage.hpp"
#include "darts/space_time_grid.hpp"
#include "core/space_time_stream.hpp"
#include "domain/polygon.hpp"
#include "domain/rectangle.hpp"
#include "radius/point_radii.hpp"

namespace pds {

class SpaceTimeDartStage final : public OpeningStage {
public:
    // The domain and R in the internal frame; polygon: a polygonal domain
    // inside the rectangle, or nullptr; torus: the periods, or off (no
    // polygon on the torus). Throws std::bad_alloc.
    SpaceTimeDartStage(const Rectangle& domain, std::shared_ptr<const Polygon> polygon, double radius,
                       std::uint64_t seed, const Torus& torus = Torus{});
    ~SpaceTimeDartStage() override;

    // Fixed points, before the first epoch: they become the stage's first
    // points (as they are the Jones stage's after the hand-over), with
    // their values (radii.radius_of(value): the clearance), and the new
    // points get new_value. A dart inside a clearance disk is covered
    // (fixed_disks.hpp). False, and the stage must not be used, when the
    // disks would take too long to lay over the grid. Throws std::bad_alloc.
    bool hold_fixed(const std::vector<Point>& points, const std::vector<double>& values, const PointRadii& radii,
                    double new_value) override;

    void set_threads(unsigned n) override { threads_ = n == 0 ? 1 : n; }
    void reserve(std::size_t points) override;
    bool has_room_for(std::size_t points) const override;
    void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) override;

    std::size_t count() const override { return points_.size(); }
    const Point& point(PointIndex k) const override { return points_[k]; }
    double value(PointIndex k) const override { return fixed_ != 0 ? values_[k] : 0.0; }
    const Point* next(Rng& rng) override;
    void add_next() override {
        points_.push_back(pending_[next_pending_++]);
        if (fixed_ != 0) values_.push_back(new_value_);
    }
    double free_area() const override;
    VerifyReport verify() const override;

    // False when the polygon's outline was too costly to raster over the
    // sub-squares (sub_square_raster.hpp): the stage must not be used.
    bool outline_rastered() const { return rastered_; }

    // For tests and bench/phases.cpp.
    std::size_t epochs() const { return epoch_; }
    const std::vector<Point>& points() const { return points_; }

    // A candidate: a dart that no earlier epoch's point covers.
    struct Candidate {
        double t;            // time within the epoch
        Point p;
        std::uint32_t cell;  // col + row * cols
        std::uint32_t k;     // the dart's place in its cell's epoch
    };
    struct Band;

private:
    // Runs an epoch; true if it gave points. Sets over_ once the stage ends.
    bool run_epoch();
    void draw(Band& band);
    void list_candidates(Band& band, std::uint32_t band_index, bool write);
    void resolve(Band& band);
    void sort_by_time(Band& band);
    bool decide(std::size_t band, std::size_t k, std::vector<std::uint64_t>& stack);
    void merge();
    void write_points(Band& band);
    void drop_covered(Band& band);
    void list_active_cells();
    std::unique_ptr<JonesStage> jones_of_points() const;
    const Point& numbered_point(std::uint32_t index) const {
        // Point k of the last epoch is points_[k] once handed out.
        return index < points_.size() ? points_[index] : pending_[index - pending_base_];
    }

    Rectangle domain_;
    std::shared_ptr<const Polygon> polygon_;
    double r_;
    std::uint64_t seed_;
    Torus torus_;
    SpaceTimeGrid grid_;
    PoissonGaps gaps_;  // which active cells draw darts in an epoch
    CurveOrder curve_;
    unsigned threads_ = 1;
    std::vector<Band> bands_;
    std::vector<std::uint32_t> active_;  // active cells, in increasing order
    std::vector<std::uint16_t> masks_;   // each cell's sub-squares known covered (one disk each) or outside
    std::vector<std::uint16_t> inside_;  // each cell's sub-squares wholly inside the polygon (none without)
    std::vector<Point> points_;          // the fixed ones, then those handed out
    std::size_t fixed_ = 0;              // fixed points (hold_fixed)
    std::vector<double> values_;         // with fixed points: each point's value
    double new_value_ = 0.0;
    std::optional<PointRadii> radii_;    // with fixed points
    FixedDisks fixed_disks_;
    std::vector<Point> pending_;         // the last epoch's points, by time
    std::size_t pending_base_ = 0, next_pending_ = 0;
    std::size_t epoch_ = 0;
    bool over_ = false;
    bool rastered_ = true;
};

}  // namespace pds

#endif
