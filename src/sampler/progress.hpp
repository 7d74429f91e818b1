// progress.hpp - progress reports and cancellation for a run (pds_set_progress).
//
// The meter is consulted after every point a run adds. It calls the user's
// function when the estimated fraction done has grown by a percent, or when
// a second has passed since the last call, so a run makes about a hundred
// calls plus one per second of work. The clock is read only every few dozen
// points: cheap against the microseconds a point costs. The meter never
// touches the generator or the pattern: reports cannot change the points.
#ifndef PDS_PROGRESS_HPP
#define PDS_PROGRESS_HPP

#include <chrono>
#include <cstddef>

namespace pds {

// The user's function: nonzero asks the run to stop.
using ProgressFn = int (*)(void* user, std::size_t count, double done);

struct ProgressHook {
    ProgressFn fn = nullptr;
    void* user = nullptr;
};

class ProgressMeter {
public:
    // expected: the number of points when the pattern is complete; exact
    // (count mode) or an estimate, then reports stay below 1 until the end.
    ProgressMeter(const ProgressHook& hook, double expected, bool exact)
        : hook_(hook), expected_(expected > 1.0 ? expected : 1.0), exact_(exact), last_call_(Clock::now()) {}

    bool active() const { return hook_.fn != nullptr; }
    // After a point was added; true when the user asked to stop.
    bool tick(std::size_t count) {
        if (hook_.fn == nullptr) return false;
        const double done = fraction(count);
        if (done >= last_done_ + kStep) return call(count, done);
        if (++since_clock_ < kPointsPerClockRead) return false;
        since_clock_ = 0;
        if (Clock::now() - last_call_ < std::chrono::seconds(1)) return false;
        return call(count, done);
    }
    // The pattern is complete: the final report, done = 1.
    bool finish(std::size_t count) { return hook_.fn != nullptr && call(count, 1.0); }

private:
    using Clock = std::chrono::steady_clock;
    static constexpr double kStep = 0.01;
    static constexpr int kPointsPerClockRead = 32;
    // Below 1 until the run ends, never decreasing.
    double fraction(std::size_t count) {
        double f = static_cast<double>(count) / expected_;
        if (!exact_ && f > kBelowOne) f = kBelowOne;
        if (f < last_done_) f = last_done_;
        return f;
    }
    bool call(std::size_t count, double done) {
        last_done_ = done;
        last_call_ = Clock::now();
        since_clock_ = 0;
        return hook_.fn(hook_.user, count, done) != 0;
    }
    static constexpr double kBelowOne = 0.999;

    ProgressHook hook_;
    double expected_;
    bool exact_;
    double last_done_ = 0.0;
    int since_clock_ = 0;
    Clock::time_point last_call_;
};

}  // namespace pds

#endif
