// dart_queue.hpp - the sequencing every dart stage (dart_stage.hpp) shares,
// whatever its grid: darts drawn a batch at a time, the dart next() returned
// kept until added, and the rule that ends the stage.
//
// The rule: the stage ends once fewer than a given share of the darts of a
// window landed free. It is decided from the darts' own history, so it is a
// stopping time and the law is unchanged. The batch persists across calls,
// so splitting a run does not change its darts.
#ifndef PDS_DART_QUEUE_HPP
#define PDS_DART_QUEUE_HPP

#include <cstddef>

#include "core/batch.hpp"

namespace pds {

template <class Dart>
class DartQueue {
public:
    // window: darts per window; min_acceptance: the share that must land free.
    void set_rule(std::size_t window, double min_acceptance) {
        window_ = window;
        min_acceptance_ = min_acceptance;
    }

    // The next dart with is_free(dart) (and inside, it is checked first), drawing a
    // new batch with draw(batch, kMaxBatch) when one is used up; the same dart
    // until take(); nullptr once the stage is over.
    template <class Inside, class Draw, class IsFree>
    const Dart* next(const Inside& inside, const Draw& draw, const IsFree& is_free) {
        if (has_pending_) return &batch_[head_ - 1];
        while (!over_) {
            if (head_ == kMaxBatch) {
                draw(batch_, kMaxBatch);
                head_ = 0;
            }
            const Dart& d = batch_[head_++];
            ++window_darts_;
            ++thrown_;
            const bool hit = inside(d) && is_free(d);
            if (hit) ++window_hits_;
            if (window_darts_ == window_) end_of_window();
            if (hit) {
                has_pending_ = true;
                return &d;
            }
        }
        return nullptr;
    }
    // The dart next() returned; requires one.
    const Dart& pending() const { return batch_[head_ - 1]; }
    void take() { has_pending_ = false; }
    // Darts tested so far (bench/phases.cpp).
    std::size_t thrown() const { return thrown_; }
    // Ends the stage (the hand-over).
    void end() {
        over_ = true;
        has_pending_ = false;
    }

private:
    void end_of_window() {
        if (static_cast<double>(window_hits_) < min_acceptance_ * static_cast<double>(window_darts_)) over_ = true;
        window_darts_ = window_hits_ = 0;
    }

    Dart batch_[kMaxBatch];
    std::size_t head_ = kMaxBatch;  // used up: the first next() draws
    std::size_t window_ = 0, window_darts_ = 0, window_hits_ = 0;
    std::size_t thrown_ = 0;
    double min_acceptance_ = 0.0;
    bool over_ = false;
    bool has_pending_ = false;
};

}  // namespace pds

#endif
