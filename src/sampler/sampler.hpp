// sampler.hpp - one pattern: the frame, the generator, the two stages of a
// run and the hand-over between them. Knows nothing of C types; the C shim
// (capi.cpp) validates arguments and maps exceptions to error codes.
//
// Stages (stage.hpp): a run opens with dart throwing (dart_stage.hpp), which
// adds points with the Jones loop's law while most of the domain is free,
// and hands its points to the Jones stage (jones_stage.hpp) once darts
// mostly miss. The hand-over happens once, here (hand_over). Which opening
// stage a run gets, if any, is decided from its settings alone
// (make_opening_stage, opening_stage.hpp).
//
// Determinism: the generator's state depends only on the operations done,
// never on how a caller split them into calls. A stage draws its next point
// once and keeps it until it is added (Stage::next), so a bounded run that
// asks "is there room left?" does the work the next call starts with. A
// refine first draws the next point at the old radius (or finds the pattern
// maximal), then drops it: whether or not the caller had already asked, the
// generator is in the same state when the radius changes.
//
// Limits (frame.hpp) are judged when the radius and domain are first used
// together: at the first point, and at a refine once points exist. Memory
// for the points a call may add is reserved before its first point, growing
// geometrically, so calls of any size cost O(1) amortized per point.
//
// Errors: LimitError (before any change); std::bad_alloc before the first
// point of a call, or, from the exact coverage test, with the pattern
// exactly as an undisturbed run would have it after the points already
// added (jones_loop.hpp); std::logic_error for a broken invariant (a bug).
#ifndef PDS_SAMPLER_HPP
#define PDS_SAMPLER_HPP

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "darts/opening_stage.hpp"
#include "domain/frame.hpp"
#include "domain/polygon.hpp"
#include "jones/jones_stage.hpp"
#include "core/point.hpp"
#include "radius/point_radii.hpp"
#include "sampler/progress.hpp"
#include "radius/radius_field.hpp"
#include "core/rng.hpp"
#include "verify/verify.hpp"

namespace pds {

class Sampler {
public:
    // The unit square; requires a finite radius > 0.
    Sampler(double radius, std::uint64_t seed);

    // Each requires count() == 0.
    // The rectangle: the domain, or a mask's frame (without a polygon).
    void set_domain(const Box& domain);
    // A polygonal domain: polygon times 2^exponent in user units (nullptr:
    // back to the rectangle).
    void set_polygon(std::shared_ptr<const Polygon> polygon, int exponent = 0);
    // The same from the user's rings (Polygon's constructor), read at the
    // internal frame's scale when they scale to it exactly, so the frame
    // keeps the one polygon built (Frame::polygon_reading_exponent).
    // Throws DomainError as the constructor does.
    void set_polygon(const double* xy, const std::size_t* ring_ends, std::size_t rings);
    // A w x h mask spread over the rectangle, row 0 along y0 (mask_outline.hpp);
    // w or h 0: back to the rectangle. Throws DomainError when no pixel is inside.
    void set_mask(std::size_t w, std::size_t h, const std::uint8_t* inside);
    // A polygon or a mask is set.
    bool has_shape() const { return shape_ != nullptr; }
    // Fixed points (user units) that sampled points keep clearances[k] from
    // (0: the radius in force at the point, R or the field's value); not
    // checked against each other, never returned. Empty: none.
    void set_fixed(std::vector<Point> points, std::vector<double> clearances);
    bool has_fixed() const { return !fixed_.empty(); }
    void set_periodic(bool periodic);
    // Count mode: the radius is chosen, and lowered by 1% whenever the
    // pattern is maximal with fewer than n points (0 turns it off).
    void set_count(std::size_t n);
    std::size_t count_target() const { return count_target_; }
    void set_progress(const ProgressHook& hook) { progress_ = hook; }
    // Threads a run may use (at least 1). The first call, before the first
    // point, selects the parallel opening (the space-time dart process,
    // space_time_stage.hpp), whose points depend on the seed and settings,
    // never on n; afterwards n may change at any time (from the next call
    // that adds points). Requires count() == 0 or parallel().
    void set_threads(unsigned n);
    unsigned threads() const { return threads_; }
    bool parallel() const { return parallel_; }
    // A variable radius (radius_field.hpp): the radius in force becomes the
    // field's largest; requires count() == 0 and no count.
    void set_field(const RadiusField& field);
    bool has_field() const { return field_.has_value(); }
    const RadiusField* field() const { return field_ ? &*field_ : nullptr; }

    // Adds one point (true), or finds the pattern complete (false): maximal,
    // or holding the count asked for.
    bool step();
    enum class RunEnd { complete, limit, canceled };
    // Adds up to max_new points (0: no limit); *added counts them. Ends
    // complete (maximal, or the count reached; decided exactly), at the limit
    // with room left, or canceled by the progress function.
    RunEnd run(std::size_t max_new, std::size_t* added);
    // run() for callers that need only the count: returns how many points
    // were added; *maximal: the run ended complete.
    std::size_t add_points(std::size_t max_new, bool* maximal) {
        std::size_t added = 0;
        *maximal = run(max_new, &added) == RunEnd::complete;
        return added;
    }
    // Continues with a smaller radius; requires 0 < radius <= radius().
    void refine(double radius);

    std::size_t count() const { return started() ? stage().count() - adopted_fixed_ : 0; }
    std::size_t copy_points(std::size_t first, std::size_t n, double* xy) const;
    // Each point's radius in force (user units): R for all without a field.
    std::size_t copy_radii(std::size_t first, std::size_t n, double* r) const;
    double radius() const { return frame_.user_radius(); }
    const Box& domain() const { return frame_.user_domain(); }
    // Exact free area: O(cells not yet known covered), 0 at once when maximal.
    double free_area() const;
    VerifyReport verify() const;

    // Internals, for the unit tests.
    // Runs the Jones loop from the first point; requires count() == 0.
    void skip_dart_stage();
    // Cut cells drawn from by their regions from the first point
    // (JonesStage::draw_cut_cells_by_region); requires count() == 0.
    void draw_cut_cells_by_region();
    // Epochs of the free regions' darts of another mean length
    // (JonesStage::set_region_darts_per_cell); requires count() == 0.
    void set_region_darts_per_cell(double mean) { region_darts_per_cell_ = mean; }
    // The free regions' epochs inserted on two sides at once
    // (JonesStage::set_side_insertions); requires count() == 0.
    void set_side_insertions(bool on) { side_insertions_ = on; }
    // Another memory budget for the opening stage's grids
    // (OpeningStage::set_memory_budget); requires count() == 0.
    void set_dart_memory_budget(double bytes_per_point, std::size_t floor_bytes) {
        dart_budget_ = {bytes_per_point, floor_bytes};
    }
    // No opening: the free regions' dart process from the second point on,
    // as after the parallel opening's hand-over (JonesStage::carry_darts);
    // requires count() == 0.
    void carry_region_darts_from_start();
    bool in_dart_stage() const { return darts_ != nullptr || (!started() && use_darts()); }
    const Frame& frame() const { return frame_; }
    // The Jones stage; requires a point to have been added.
    const JonesStage& jones() const { return *jones_; }

private:
    bool started() const { return jones_ != nullptr; }
    // Points the stage answers for: sampled ones, or fixed points adopted
    // (their clearances count before the first point; they may leave no room).
    bool stage_holds_points() const { return count() != 0 || (started() && adopted_fixed_ > 0); }
    // The expected size of a maximal pattern (for progress reports); for a
    // field, nothing when the meter was asked to stop while the field's
    // mean was being estimated (the estimate so far is kept).
    std::optional<double> expected_count(ProgressMeter& meter);
    // The frame at the smallest radius in force: what the limits and the
    // bounds on the count are judged with.
    Frame smallest_frame() const;
    // A field whose values differ; a constant one runs the plain stages at
    // its radius (the same points, at the same speed).
    bool varying_field() const { return field_ && !field_->constant(); }
    // What the stages see of a varying field.
    // Fixed points need them too (each disk its own radius), from a
    // constant field at the radius of the first point when there is no
    // varying field.
    std::optional<PointRadii> point_radii(const Frame& frame) const {
        if (varying_field()) return PointRadii(*field_, frame);
        if (has_fixed() && fixed_field_) return PointRadii(*fixed_field_, frame);
        return std::nullopt;
    }
    // The fixed points in the internal frame, with their values (the
    // clearance, or the radius at the point): a position given twice is one
    // point, with its larger clearance, and near ones are merged. They
    // become the first points of the opening stage that holds them, or of
    // the Jones stage. Throws DomainError (a point outside the box).
    void prepare_fixed(std::vector<Point>& points, std::vector<double>& values) const;
    static std::vector<std::uint32_t> identity_order(std::size_t n);
    static void drop_repeated_fixed(std::vector<Point>& points, std::vector<double>& values);
    static void merge_nearly_coincident_fixed(std::vector<Point>& points, std::vector<double>& values, double tol);
    bool use_darts() const;
    // A varying field's bound on the size of any pattern (the smaller of
    // Oler's at rmin and the map's own), saturated as count_bound_points().
    std::size_t field_count_bound() const;
    Stage& stage() { return darts_ ? static_cast<Stage&>(*darts_) : *jones_; }
    const Stage& stage() const { return darts_ ? static_cast<const Stage&>(*darts_) : *jones_; }
    // Judges the limits for a call that may bring the total to `points`,
    // makes the stages at the first point, and reserves room.
    void prepare(std::size_t points);
    // The most points worth reserving room for: the pattern's bound.
    std::size_t room_cap() const { return std::min(smallest_frame().count_bound_points(), Frame::max_points()); }
    void forget_stages();
    const Point* next_point();
    bool add_one();
    bool complete() const { return count_target_ != 0 && count() >= count_target_; }
    void hand_over();
    void lower_radius_for_count();
    // Count mode's first radius (set_count), and with fixed points the one
    // from the room their clearances leave (sampler_domain.cpp).
    double count_start_radius() const;
    static double count_start_factor(double n) { return 1.015 + 10.0 / n; }
    void start_count_around_fixed();
    // refine() once the stages exist: they go on at the smaller radius.
    void refine_stages(double radius);

    void use_shape(std::shared_ptr<const Polygon> shape, int exponent = 0);

    Frame frame_;
    Box rectangle_{0.0, 0.0, 1.0, 1.0};        // the user's rectangle (set_domain)
    std::shared_ptr<const Polygon> shape_;       // the polygon or the mask's outline, user units
    std::size_t mask_w_ = 0, mask_h_ = 0;        // a mask, kept to follow the rectangle
    std::vector<std::uint8_t> mask_;
    std::vector<Point> fixed_;                   // user units
    std::vector<double> fixed_clearance_;        // user units, 0: the radius at the point
    double fixed_radius_ = 0.0;                  // fixed_field_'s value
    std::optional<RadiusField> fixed_field_;     // constant, for fixed points without a field
    std::size_t adopted_fixed_ = 0;              // fixed points in the stage (its first vertices)
    std::uint64_t seed_;
    Rng rng_;  // at seed_'s state while count() == 0
    bool skip_darts_ = false;
    bool region_draws_ = false;  // draw_cut_cells_by_region()
    double region_darts_per_cell_ = 0.0;  // set_region_darts_per_cell(); 0: the default
    bool side_insertions_ = false;        // set_side_insertions()
    bool region_darts_from_start_ = false;  // carry_region_darts_from_start()
    std::optional<std::pair<double, std::size_t>> dart_budget_;  // set_dart_memory_budget()
    unsigned threads_ = 1;
    bool parallel_ = false;  // set_threads was called: the space-time opening
    std::size_t count_target_ = 0;
    ProgressHook progress_;
    std::optional<RadiusField> field_;
    RadiusField::MeanInverseSquare mean_inverse_square_;  // of the field over the domain, once asked
    ProgressMeter* meter_ = nullptr;  // the running pds_run's, polled by the hand-over
    std::unique_ptr<OpeningStage> darts_;  // while a dart stage runs
    std::unique_ptr<JonesStage> jones_;  // from the first point on
};

}  // namespace pds

#endif
