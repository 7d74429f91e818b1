// sampler.cpp - frame, stages and hand-over (see sampler.hpp).
#include "sampler/sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/room_growth.hpp"
#include "core/space_time_stream.hpp"

namespace pds {

Sampler::Sampler(double radius, std::uint64_t seed)
    : frame_(Box{0.0, 0.0, 1.0, 1.0}, radius), seed_(seed), rng_(seed) {}

bool Sampler::use_darts() const {
    // Fixed points: the dart stages keep their darts out of the clearances
    // (a stage may still decline: hold_fixed).
    return !skip_darts_ &&
           opening_stage_suits(frame_, smallest_frame().count_bound(), varying_field() ? &*field_ : nullptr);
}

std::optional<double> Sampler::expected_count(ProgressMeter& meter) {
    // A field's: as for the radius whose 1/R^2 is the mean of 1/r^2 over the domain.
    if (!varying_field()) return frame_.expected_count(frame_.user_radius());
    // The field's mean of 1/r^2 is measured once per field and domain. A
    // user function may be slow: the meter is polled after each value, and a
    // stop keeps what was measured for the next run.
    while (!mean_inverse_square_.done()) {
        mean_inverse_square_.step(*field_, frame_.user_domain());
        if (meter.poll(count())) return std::nullopt;
    }
    return frame_.expected_count(frame_.user_radius() / field_->rmax() / std::sqrt(mean_inverse_square_.mean()));
}

Frame Sampler::smallest_frame() const {
    if (!field_) return frame_;
    Frame f = frame_;
    f.set_radius(scaled_radius(field_->rmin(), field_->rmax(), frame_.user_radius()));
    return f;
}

void Sampler::set_field(const RadiusField& field) {
    if (count() != 0) throw std::logic_error("set_field after the first point");
    if (count_target_ != 0) throw std::logic_error("set_field in count mode");
    forget_stages();
    field_ = field;
    mean_inverse_square_ = RadiusField::MeanInverseSquare{};
    frame_.set_radius(field.rmax());
}

std::size_t Sampler::field_count_bound() const {
    // Oler's bound at rmin holds for any field. A map's own bound (cells
    // between its pixel centres, each at its least value) is far smaller
    // when few values are small, and is worked out only when Oler's at rmin
    // would refuse the run (it costs O(w h)).
    const std::size_t oler = smallest_frame().count_bound_points();
    if (oler <= Frame::max_points()) return oler;
    const PointRadii radii(*field_, frame_);
    const double map = field_->map_count_bound(frame_.box(), [&](double v) { return radii.radius_of(v); });
    const double cap = static_cast<double>(Frame::max_points()) + 1.0;
    return map < cap ? std::min(oler, static_cast<std::size_t>(map)) : oler;
}

void Sampler::forget_stages() {
    // Without points the stages hold nothing but the old frame, and a first
    // point drawn but refused by a radius field: the generator goes back to
    // the seed, so the points are a fresh sampler's with these settings.
    darts_.reset();
    jones_.reset();
    adopted_fixed_ = 0;
    rng_ = Rng(seed_);
}


void Sampler::set_periodic(bool periodic) {
    if (count() != 0) throw std::logic_error("set_periodic after the first point");
    forget_stages();
    frame_.set_periodic(periodic);
    if (count_target_ != 0) set_count(count_target_);
}

void Sampler::set_count(std::size_t n) {
    if (count() != 0) throw std::logic_error("set_count after the first point");
    forget_stages();
    count_target_ = n;
    if (n == 0) return;
    frame_.set_radius(count_start_radius());
}

double Sampler::count_start_radius() const {
    // Above the expected radius, so the first maximal pattern holds fewer
    // than n points and the steps approach n from below (sampler.hpp): a
    // for large n (1.5%), more for small n, whose counts vary more (10/n: dozens of
    // cheap steps for a few points). Not more: each step leaves a pattern a
    // little less dense than one made at the final radius, so many steps
    // would end at a smaller radius. On the torus, at most half the shorter
    // period; anywhere, at most the largest double: in a domain whose sides
    // come near it, the start overflows, and an infinite radius lowered by 1%
    // stays infinite, so the steps would never end.
    const double n = static_cast<double>(count_target_);
    const double start = count_start_factor(n) * frame_.radius_for_count(n);
    return std::min({start, frame_.max_radius(), std::numeric_limits<double>::max()});
}

void Sampler::set_threads(unsigned n) {
    if (!parallel_) {
        if (count() != 0) throw std::logic_error("set_threads selects the opening before the first point");
        forget_stages();
        parallel_ = true;
    }
    threads_ = n == 0 ? 1 : n;  // the stages learn it in prepare(), before each call adds points
}

void Sampler::skip_dart_stage() {
    if (count() != 0) throw std::logic_error("skip_dart_stage after the first point");
    forget_stages();
    skip_darts_ = true;
}

void Sampler::carry_region_darts_from_start() {
    skip_dart_stage();
    region_darts_from_start_ = true;
}

void Sampler::draw_cut_cells_by_region() {
    if (count() != 0) throw std::logic_error("draw_cut_cells_by_region after the first point");
    forget_stages();
    region_draws_ = true;
}

void Sampler::prepare(std::size_t points) {
    const JudgedRadius smallest = field_ ? JudgedRadius::field_smallest : JudgedRadius::radius;
    const JudgedRadius largest = field_ ? JudgedRadius::field_largest : JudgedRadius::radius;
    // Coordinates too close to zero are the reason before any count: the
    // count a run asks for comes from the area over R^2, which underflows.
    if (!started() && frame_.precision_limit() == Limit::coordinates_too_small)
        throw LimitError(Limit::coordinates_too_small, smallest_frame().user_radius(), smallest);
    if (points > Frame::max_points()) throw LimitError(Limit::too_many_points, frame_.user_radius());
    if (!started() && count_target_ != 0 && has_fixed()) start_count_around_fixed();
    if (!started()) {
        // A field: precision at the smallest radius, the torus's period at
        // the largest (each error names the one judged). A too large radius
        // is judged first: it is the cause when both fail (a period under
        // 2 rmax makes the smallest radius's pattern no denser).
        const Frame low = smallest_frame();
        const Limit high = frame_.precision_limit();
        if (high == Limit::radius_exceeds_period) throw LimitError(high, frame_.user_radius(), largest);
        const Limit limit = low.precision_limit();
        if (limit != Limit::ok) throw LimitError(limit, low.user_radius(), smallest);
        if (high != Limit::ok) throw LimitError(high, frame_.user_radius(), largest);
        if (varying_field() && frame_.periods_beyond(Frame::kMaxFieldPeriodRatio))
            throw LimitError(Limit::field_periods_too_unequal, frame_.user_radius(), largest);
        // Count mode lowers the radius as it goes: the lowest it can reach is
        // judged now, so a run never meets the limit half way.
        if (count_target_ != 0) {
            Frame lowest = frame_;
            lowest.set_radius(std::min(frame_.user_radius(),
                                       frame_.lowest_count_radius(static_cast<double>(count_target_))));
            const Limit at_lowest = lowest.precision_limit();
            if (at_lowest != Limit::ok) throw LimitError(at_lowest, lowest.user_radius(), JudgedRadius::count_lowest);
        }
        // Built aside, kept only when both exist: std::bad_alloc changes nothing.
        // A constant field runs as its radius does: the plain sampler's points.
        if (has_fixed() && !varying_field()) {
            fixed_radius_ = frame_.user_radius();
            fixed_field_ = RadiusField::function(
                [](void* r, double, double) { return *static_cast<const double*>(r); }, &fixed_radius_,
                fixed_radius_, fixed_radius_);
        }
        const std::optional<PointRadii> radii = point_radii(frame_);
        auto jones = make_jones_stage(frame_.domain(), frame_.r(), frame_.torus(), radii ? &*radii : nullptr,
                                      frame_.shared_polygon());
        std::unique_ptr<OpeningStage> darts;
        if (use_darts())
            darts = make_opening_stage(frame_, smallest_frame().count_bound(), varying_field() ? &*field_ : nullptr,
                                       parallel_ ? std::optional<std::uint64_t>(seed_) : std::nullopt);
        if (darts && dart_budget_) darts->set_memory_budget(dart_budget_->first, dart_budget_->second);
        std::size_t fixed = 0;
        if (has_fixed()) {
            std::vector<Point> at;
            std::vector<double> values;
            prepare_fixed(at, values);
            // One radius: any point's value is the new points' (a field's
            // new points take their own, and its function is not asked here).
            const Point corner{frame_.box().x0, frame_.box().y0};
            const double new_value = varying_field() ? 0.0 : radii->value_at(corner);
            if (darts && !darts->hold_fixed(at, values, *radii, new_value)) darts.reset();
            if (!darts) {
                jones->reserve(points + at.size());
                jones->adopt(at, identity_order(at.size()).data(), &values, Poll{});
                jones->set_fixed(at.size());
            }
            fixed = at.size();
        }
        if (region_draws_) jones->draw_cut_cells_by_region();
        if (region_darts_per_cell_ > 0.0) jones->set_region_darts_per_cell(region_darts_per_cell_);
        if (side_insertions_) jones->set_side_insertions(true);
        if (region_darts_from_start_) jones->carry_darts(SpaceTimeStream::salted(seed_), 0);
        jones_ = std::move(jones);
        darts_ = std::move(darts);
        adopted_fixed_ = fixed;
    }
    // One growth policy for every call (core/room_growth.hpp): at least
    // double what is there, up to what the pattern can hold, so small calls
    // cost O(1) amortized. The Jones stage gets room for the dart stage's
    // points too (the hand-over may come with any point), and each reserve
    // is all or nothing.
    if (parallel_) {
        jones_->set_threads(threads_);
        if (darts_) darts_->set_threads(threads_);
    }
    // The epochs by sides grow the Jones stage's room themselves, within the
    // same bound (the radius, and with it the bound, may have changed).
    if (side_insertions_) jones_->set_room_cap(room_cap() + adopted_fixed_);
    const bool room = jones_->has_room_for(points + adopted_fixed_) &&
                      (!darts_ || darts_->has_room_for(points + adopted_fixed_));
    if (room) return;
    const std::size_t want = grown_room(points, count(), room_cap());
    jones_->reserve(want + adopted_fixed_);
    if (darts_) darts_->reserve(want + adopted_fixed_);
}

const Point* Sampler::next_point() {
    if (darts_) {
        if (const Point* p = darts_->next(rng_)) return p;
        hand_over();
    }
    return jones_->next(rng_);
}

bool Sampler::add_one() {
    for (;;) {
        if (complete()) return false;
        if (next_point() != nullptr) break;
        if (count_target_ == 0) return false;
        lower_radius_for_count();
    }
    stage().add_next();
    return true;
}

void Sampler::lower_radius_for_count() {
    // Maximal with m < n points: the count goes as 1/R^2, so R sqrt(m/n)
    // would hold about n; steps are kept between 0.1% and 1%, so the last
    // radius ends close below the one that reaches n, and the pattern stays
    // maximal at pds_radius()/0.99 (pds_set_count).
    constexpr double kLargestStep = 0.99, kSmallestStep = 0.999;
    const double guess = std::sqrt(static_cast<double>(count()) / static_cast<double>(count_target_));
    const double step = std::min(kSmallestStep, std::max(kLargestStep, guess));
    // With no point yet (fixed points' clearances cover the domain) the
    // stages are kept all the same: the clearances shrink with the radius,
    // as they do once points exist, until points fit, or until the radius
    // meets the precision limit (clearances a hundred million times the
    // domain): the message then says why it went so low.
    try {
        refine_stages(step * frame_.user_radius());
    } catch (const LimitError& e) {
        if (count() != 0 || e.judged() != JudgedRadius::radius) throw;
        throw LimitError(e.limit(), e.radius(), JudgedRadius::count_covered);
    }
}

void Sampler::hand_over() {
    // Room for the points and the order was reserved with the dart stage's:
    // nothing here allocates. Inside pds_run the meter is polled as it goes,
    // so the reports keep coming; a stop asked for then takes effect after
    // the hand-over (the run checks the meter after its next point).
    Poll poll;
    if (meter_ != nullptr && meter_->active()) {
        poll.fn = [](void* context) {
            Sampler* s = static_cast<Sampler*>(context);
            s->meter_->poll(s->count());
        };
        poll.context = this;
    }
    darts_->hand_over_to(*jones_, poll);  // sets the fixed points it held (set_fixed)
    darts_.reset();
    // A field's opening is the one-thread dart stage; with threads its
    // darts are carried on in the free regions, whose draws they share.
    if (parallel_ && varying_field()) jones_->carry_darts(SpaceTimeStream::salted(seed_), 0);
}

bool Sampler::step() {
    if (complete()) return false;
    prepare(count() + 1);
    return add_one();
}

Sampler::RunEnd Sampler::run(std::size_t max_new, std::size_t* added) {
    *added = 0;
    const std::size_t n = count();
    // Room to end maximal (Oler's bound; never below n, whatever its
    // rounding), or the count asked for, or for max_new more if fewer.
    // prepare() refuses a total past the index space, so an unbounded run
    // whose maximal pattern might not fit fails before any point.
    // A varying field: Oler's bound at the smallest radius may exceed the
    // pattern by any factor (one small pixel in a map); a map's own bound
    // (field_count_bound) is used when it is smaller. It is judged at the
    // first point, as a constant radius is; afterwards the pattern itself
    // says whether it is complete. Memory is not reserved for that bound but
    // grows with the run (geometrically, O(1) amortized), and a pattern that
    // truly outgrows the index space stops there (PDS_ERANGE, points kept).
    const bool grows = varying_field();
    const std::size_t bound = grows ? field_count_bound() : smallest_frame().count_bound_points();
    // A pattern already maximal has nothing to reserve: fixed points'
    // clearances may leave no room at a radius whose bound is past the
    // index space (asked only then: it draws the next point).
    const auto maximal = [&] { return started() && count_target_ == 0 && next_point() == nullptr; };
    if (grows) {
        // After the first point a bounded run is not judged either: a bound
        // that refused count + max_new would refuse a maximal pattern.
        const std::size_t asked = n != 0 ? 0 : max_new == 0 ? bound : std::min(max_new, bound);
        if (asked > Frame::max_points() && !maximal())
            throw LimitError(Limit::too_many_points, smallest_frame().user_radius(), JudgedRadius::field_smallest);
        prepare(n + 1);
    } else {
        const std::size_t whole = count_target_ != 0 ? std::max(count_target_, n) : std::max(bound, n) + 1;
        const std::size_t total = max_new != 0 && max_new < whole - n ? n + max_new : whole;
        if (!(total > Frame::max_points() && maximal())) prepare(total);
    }
    // The meter reads the clock after every point when each point calls the
    // user's radius function, whose cost the library cannot know.
    ProgressMeter meter(progress_, field_ && field_->calls_user());
    // The estimate is needed only for reports (a field's asks the field).
    if (meter.active()) {
        const std::optional<double> expected =
            count_target_ != 0 ? std::optional<double>(static_cast<double>(count_target_)) : expected_count(meter);
        if (!expected) return RunEnd::canceled;
        meter.expect(*expected, count_target_ != 0);
    }
    // The hand-over, which may come with any point, polls the meter.
    struct Watch {
        ProgressMeter*& slot;
        ~Watch() { slot = nullptr; }
    } watch{meter_};
    meter_ = &meter;
    // A helper may walk ahead of the insertions while this call runs, and
    // stops before it returns (jones/ring_prefetcher.hpp).
    struct Helper {
        JonesStage* stage;
        ~Helper() {
            if (stage) stage->allow_helper(false);
        }
    } helper{jones_.get()};
    if (helper.stage) helper.stage->allow_helper(parallel_);
    while (max_new == 0 || *added < max_new) {
        if (grows) prepare(count() + 1);  // nothing to do while there is room
        if (!add_one()) {
            // The final report. The pattern is complete: a stop asked for
            // here (or in a hand-over just before) has nothing left to stop,
            // and the run says what it is (poissondisk.h, pds_progress_fn).
            meter.finish(count());
            return RunEnd::complete;
        }
        ++*added;
        if (meter.tick(count())) return RunEnd::canceled;
    }
    // The limit was reached: there is room if a next point exists. Drawing
    // it now is the work the next call would start with (stage.hpp).
    if (complete() || (count_target_ == 0 && next_point() == nullptr)) {
        meter.finish(count());
        return RunEnd::complete;
    }
    return RunEnd::limit;
}

void Sampler::refine(double radius) {
    if (count() == 0) {
        forget_stages();
        frame_.set_radius(radius);
        return;
    }
    refine_stages(radius);
}

void Sampler::refine_stages(double radius) {
    Frame next = frame_;
    next.set_radius(radius);
    Frame next_smallest = next;
    if (field_) next_smallest.set_radius(scaled_radius(field_->rmin(), field_->rmax(), radius));
    const Limit limit = next_smallest.precision_limit();
    if (limit != Limit::ok)
        throw LimitError(limit, next_smallest.user_radius(), field_ ? JudgedRadius::field_smallest : JudgedRadius::radius);
    const Limit high = next.precision_limit();
    if (high != Limit::ok) throw LimitError(high, radius, field_ ? JudgedRadius::field_largest : JudgedRadius::radius);
    // The generator's state at a refine must not depend on whether the caller
    // already asked for room (sampler.hpp): draw the next point, then drop it.
    next_point();
    // The dart stage's grid is laid out for the old radius.
    if (darts_) hand_over();
    const std::optional<PointRadii> radii = point_radii(next);
    jones_->set_radius(next.r(), radii ? &*radii : nullptr);
    frame_ = next;
}

}  // namespace pds
