// test_progress.cpp - the progress meter (progress.hpp) through the sampler:
// a report at least every second of the run whatever a point costs, during
// the estimate of a field's count and during the hand-over too, and a stop
// asked for in either honoured without changing any point.
//
// Time is a fake clock the tests advance (ProgressHook::now): a slow radius
// function advances it by its cost, so the tests count reports against
// simulated seconds and never measure real time.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

#include "radius/radius_field.hpp"
#include "sampler/progress.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

using Clock = pds::ProgressClock;

// The fake clock: now() returns `fake_time`, plus `per_read` after each read.
Clock::time_point fake_time{};
Clock::duration per_read{};
Clock::time_point fake_now() {
    fake_time += per_read;
    return fake_time;
}
void reset_clock(Clock::duration advance_per_read) {
    fake_time = Clock::time_point{};
    per_read = advance_per_read;
}

constexpr Clock::duration kSecond = std::chrono::seconds(1);
constexpr Clock::duration kSlowPoint = std::chrono::milliseconds(100);

// What the progress function saw: the fake time and count of each call.
struct Reports {
    const pds::Sampler* sampler = nullptr;
    std::vector<Clock::time_point> at;
    std::vector<std::size_t> count;
    std::size_t stop_at = 0;      // the call (1-based) that asks to stop; 0: none
    bool stop_on_repeat = false;  // ask to stop at a call with the previous call's count, not 0
    bool read_wrong = false;      // a call's count was not the sampler's
};

int record(void* user, std::size_t count, double) {
    Reports* r = static_cast<Reports*>(user);
    if (r->sampler != nullptr && r->sampler->count() != count) r->read_wrong = true;
    // Repeated counts past 0 come from the hand-over (0: the estimate).
    const bool repeat = count > 0 && !r->count.empty() && r->count.back() == count;
    r->at.push_back(fake_time);
    r->count.push_back(count);
    return (r->stop_at != 0 && r->at.size() == r->stop_at) || (r->stop_on_repeat && repeat);
}

pds::ProgressHook hook_of(Reports& r) {
    pds::ProgressHook h;
    h.fn = record;
    h.user = &r;
    h.now = fake_now;
    return h;
}

// The longest stretch of fake time without a report, from `start` to `end`.
Clock::duration longest_silence(const Reports& r, Clock::time_point start, Clock::time_point end) {
    Clock::duration longest = Clock::duration::zero();
    Clock::time_point last = start;
    for (const Clock::time_point t : r.at) {
        longest = std::max(longest, t - last);
        last = t;
    }
    return std::max(longest, end - last);
}

// A radius function costing 100 ms a call, counting its calls.
std::size_t slow_calls = 0;
double slow_field(void*, double x, double) {
    fake_time += kSlowPoint;
    ++slow_calls;
    return 0.02 * (1.0 + x);
}

std::vector<double> points_of(const pds::Sampler& s) {
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    return xy;
}

}  // namespace

// Points costing 100 ms each: the clock is read often enough that no
// second passes without a report, with the stride adapting (no radius
// function) or at every point (one).
START_TEST(meter_keeps_the_second_at_any_cost) {
    for (const bool every_point : {false, true}) {
        reset_clock(Clock::duration::zero());
        Reports r;
        pds::ProgressMeter meter(hook_of(r), every_point);
        meter.expect(1e9, false);  // the 1% rule never fires
        const Clock::time_point start = fake_time;
        for (std::size_t k = 1; k <= 200; ++k) {
            fake_time += kSlowPoint;
            meter.tick(k);
        }
        ck_assert_msg(r.at.size() >= 18, "%zu reports in 20 s of 100 ms points", r.at.size());
        ck_assert_msg(longest_silence(r, start, fake_time) <= kSecond + kSlowPoint,
                      "%.2f s without a report", std::chrono::duration<double>(longest_silence(r, start, fake_time)).count());
    }
    // Cheap points let the stride grow; a radius function keeps it at 1.
    reset_clock(std::chrono::microseconds(1));
    Reports r;
    pds::ProgressMeter cheap(hook_of(r), false), user(hook_of(r), true);
    cheap.expect(1e9, false);
    user.expect(1e9, false);
    for (std::size_t k = 1; k <= 4096; ++k) {
        cheap.tick(k);
        user.tick(k);
    }
    ck_assert_int_eq(cheap.stride(), pds::ProgressMeter::kMaxStride);
    ck_assert_int_eq(user.stride(), 1);
}
END_TEST

// A radius function costing 100 ms a call: the 4096 calls of the count's
// estimate and every point after them are covered by reports a second apart.
START_TEST(slow_radius_function_reports_every_second) {
    reset_clock(Clock::duration::zero());
    pds::Sampler s(0.04, 3);
    s.set_field(pds::RadiusField::function(slow_field, nullptr, 0.02, 0.04));
    Reports r;
    r.sampler = &s;
    s.set_progress(hook_of(r));
    const Clock::time_point start = fake_time;
    std::size_t added = 0;
    ck_assert(s.run(300, &added) == pds::Sampler::RunEnd::limit);
    ck_assert_uint_eq(added, 300);
    const double silence = std::chrono::duration<double>(longest_silence(r, start, fake_time)).count();
    ck_assert_msg(silence <= 1.5, "%.1f s without a report (100 ms a point)", silence);
    ck_assert_msg(r.at.size() >= 400, "%zu reports in %.0f s", r.at.size(),
                  std::chrono::duration<double>(fake_time - start).count());
    ck_assert(!r.read_wrong);
}
END_TEST

// A stop asked for during the estimate ends the run before its first point,
// keeps what was estimated, and the points are those of a run never stopped.
START_TEST(estimate_can_be_stopped) {
    reset_clock(Clock::duration::zero());
    slow_calls = 0;
    pds::Sampler plain(0.04, 3);
    plain.set_field(pds::RadiusField::function(slow_field, nullptr, 0.02, 0.04));
    std::size_t added = 0;
    plain.run(200, &added);
    const std::size_t calls_without_estimate = slow_calls;

    slow_calls = 0;
    pds::Sampler s(0.04, 3);
    s.set_field(pds::RadiusField::function(slow_field, nullptr, 0.02, 0.04));
    Reports r;
    r.stop_at = 1;
    s.set_progress(hook_of(r));
    ck_assert(s.run(200, &added) == pds::Sampler::RunEnd::canceled);
    ck_assert_uint_eq(s.count(), 0);
    ck_assert_msg(slow_calls < 100, "the estimate went on for %zu calls after a stop", slow_calls);
    r.stop_at = 0;
    ck_assert(s.run(200, &added) == pds::Sampler::RunEnd::limit);
    // The estimate resumed where it stopped: its 4096 values, once.
    ck_assert_uint_eq(slow_calls, calls_without_estimate + 4096);
    ck_assert(points_of(s) == points_of(plain));
}
END_TEST

// The hand-over adds no point but takes time: with a clock that advances a
// second at every read, reports come during it (the same count, repeated),
// and a stop asked for there takes effect when it ends, points unchanged.
START_TEST(hand_over_reports_and_stops) {
    for (const bool field : {false, true}) {
        pds::Sampler plain(0.004, 9);
        if (field) plain.set_field(pds::RadiusField::map(2, 1, std::vector<double>{0.003, 0.004}.data()));
        std::size_t added = 0;
        plain.run(0, &added);

        reset_clock(kSecond);
        pds::Sampler s(0.004, 9);
        if (field) s.set_field(pds::RadiusField::map(2, 1, std::vector<double>{0.003, 0.004}.data()));
        Reports r;
        r.sampler = &s;
        s.set_progress(hook_of(r));
        ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
        std::size_t longest_repeat = 0, repeat = 0;
        for (std::size_t i = 1; i < r.count.size(); ++i) {
            repeat = r.count[i] > 0 && r.count[i] == r.count[i - 1] ? repeat + 1 : 0;
            longest_repeat = std::max(longest_repeat, repeat);
        }
        // Tens of thousands of points handed over: a report every 4096.
        ck_assert_msg(longest_repeat >= 5, "%zu reports in a row at one count (field %d)", longest_repeat, field);
        ck_assert(!r.read_wrong);
        ck_assert(points_of(s) == points_of(plain));

        reset_clock(kSecond);
        pds::Sampler t(0.004, 9);
        if (field) t.set_field(pds::RadiusField::map(2, 1, std::vector<double>{0.003, 0.004}.data()));
        Reports stop;
        stop.stop_on_repeat = true;
        t.set_progress(hook_of(stop));
        ck_assert(t.run(0, &added) == pds::Sampler::RunEnd::canceled);
        ck_assert_msg(!t.in_dart_stage(), "field %d: stopped at %zu of %zu, %zu reports", field, t.count(), plain.count(), stop.count.size());
        pds::ProgressHook none;
        t.set_progress(none);
        ck_assert(t.run(0, &added) == pds::Sampler::RunEnd::complete);
        ck_assert(points_of(t) == points_of(plain));
    }
}
END_TEST

Suite* progress_suite() {
    Suite* s = suite_create("progress");
    TCase* tc = tcase_create("meter_keeps_the_second_at_any_cost");
    tcase_add_test(tc, meter_keeps_the_second_at_any_cost);
    suite_add_tcase(s, tc);
    tc = tcase_create("slow_radius_function_reports_every_second");
    tcase_add_test(tc, slow_radius_function_reports_every_second);
    suite_add_tcase(s, tc);
    tc = tcase_create("estimate_can_be_stopped");
    tcase_add_test(tc, estimate_can_be_stopped);
    suite_add_tcase(s, tc);
    tc = tcase_create("hand_over_reports_and_stops");
    tcase_add_test(tc, hand_over_reports_and_stops);
    suite_add_tcase(s, tc);
    return s;
}
