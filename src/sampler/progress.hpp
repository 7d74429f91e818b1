// progress.hpp - progress reports and cancellation for a run (pds_set_progress).
//
// The meter is consulted after every point a run adds (tick), and polled
// during the long steps between points: the estimate of the final count
// (which may call the user's radius function 4096 times) and the hand-over
// from the dart stage to the Jones loop (poll). It calls the user's
// function when the estimated fraction done has grown by a percent, or when
// a second has passed since the last call, so a run makes about a hundred
// calls plus one per second of work.
//
// The second is kept whatever a point costs: the clock is read every
// `stride` points, and the stride follows the measured cost, cut in
// proportion (down to 1) when reads come more than kReadGap apart, doubled (up to
// kMaxStride) while they come much closer; with a user radius function,
// whose cost the library cannot know, every point reads it. A clock read
// (tens of nanoseconds) is then cheap beside the points between reads.
//
// The meter never touches the generator or the pattern: reports cannot
// change the points. A stop asked for during a poll is kept (stop_asked)
// until the run can act on it.
#ifndef PDS_PROGRESS_HPP
#define PDS_PROGRESS_HPP

#include <algorithm>
#include <chrono>
#include <cstddef>

namespace pds {

// The user's function: nonzero asks the run to stop.
using ProgressFn = int (*)(void* user, std::size_t count, double done);

using ProgressClock = std::chrono::steady_clock;

struct ProgressHook {
    ProgressFn fn = nullptr;
    void* user = nullptr;
    // The clock the meter reads; the unit tests give a fake one.
    ProgressClock::time_point (*now)() = &ProgressClock::now;
};

class ProgressMeter {
public:
    // every_point: read the clock after every point (a user radius function
    // is called for each). The expected count comes later (expect): it may
    // take a long estimate, during which the meter is polled.
    ProgressMeter(const ProgressHook& hook, bool every_point)
        : hook_(hook), every_point_(every_point) {
        if (hook_.fn != nullptr) last_call_ = last_read_ = hook_.now();
    }

    bool active() const { return hook_.fn != nullptr; }
    // expected: the number of points when the pattern is complete; exact
    // (count mode) or an estimate, then reports stay below 1 until the end.
    void expect(double expected, bool exact) {
        expected_ = expected > 1.0 ? expected : 1.0;
        exact_ = exact;
    }
    // After a point was added; true when the user asked to stop (now or at
    // a poll since the last tick).
    bool tick(std::size_t count) {
        if (hook_.fn == nullptr) return false;
        if (stop_asked_) return true;
        const double done = fraction(count);
        if (done >= last_done_ + kStep) return call(count, done);
        if (++since_read_ < stride_) return false;
        const ProgressClock::time_point now = read_clock();
        if (now - last_call_ < std::chrono::seconds(1)) return false;
        return call(count, done);
    }
    // Inside a long step, with `count` points: a report if a second has
    // passed, `done` as last reported. Reads the clock at every call, so the
    // step calls it every few thousand items. True when a stop was asked.
    bool poll(std::size_t count) {
        if (hook_.fn == nullptr) return false;
        if (!stop_asked_ && hook_.now() - last_call_ >= std::chrono::seconds(1)) call(count, last_done_);
        return stop_asked_;
    }
    bool stop_asked() const { return stop_asked_; }
    // The pattern is complete: the final report, done = 1.
    bool finish(std::size_t count) { return hook_.fn != nullptr && call(count, 1.0); }
    // The clock's stride now (for the unit tests).
    int stride() const { return stride_; }

    // Reads spaced more than this apart halve the stride.
    static constexpr std::chrono::milliseconds kReadGap{50};
    static constexpr int kMaxStride = 32;

private:
    static constexpr double kStep = 0.01;
    static constexpr double kBelowOne = 0.999;
    // Below 1 until the run ends, never decreasing.
    double fraction(std::size_t count) {
        double f = static_cast<double>(count) / expected_;
        if (!exact_ && f > kBelowOne) f = kBelowOne;
        if (f < last_done_) f = last_done_;
        return f;
    }
    ProgressClock::time_point read_clock() {
        const ProgressClock::time_point now = hook_.now();
        const ProgressClock::duration gap = now - last_read_;
        last_read_ = now;
        since_read_ = 0;
        if (every_point_) stride_ = 1;
        else if (gap > kReadGap) stride_ = static_cast<int>(std::max<ProgressClock::rep>(1, stride_ * kReadGap / gap));
        else if (gap < kReadGap / 4 && stride_ < kMaxStride) stride_ *= 2;
        return now;
    }
    bool call(std::size_t count, double done) {
        last_done_ = done;
        since_read_ = 0;
        const bool stop = hook_.fn(hook_.user, count, done) != 0;
        // From the call's end: the user's own time is not the run's.
        last_call_ = last_read_ = hook_.now();
        stop_asked_ = stop_asked_ || stop;
        return stop_asked_;
    }

    ProgressHook hook_;
    bool every_point_;
    double expected_ = 1.0;
    bool exact_ = false;
    double last_done_ = 0.0;
    bool stop_asked_ = false;
    int stride_ = 1;
    int since_read_ = 0;
    ProgressClock::time_point last_call_{}, last_read_{};
};

}  // namespace pds

#endif
