// poll.hpp - a hook that a long step of a run calls every kPollEvery items,
// so the sampler can keep its promise of a progress report every second
// (sampler/progress.hpp) through steps that add no point: the hand-over
// from the dart stage to the Jones loop. Calling it changes nothing the step
// computes; an empty hook does nothing.
#ifndef PDS_POLL_HPP
#define PDS_POLL_HPP

#include <cstddef>

namespace pds {

struct Poll {
    void (*fn)(void* context) = nullptr;
    void* context = nullptr;
    void operator()() const {
        if (fn != nullptr) fn(context);
    }
    // Every this many items: a clock read each time costs nothing beside them.
    static constexpr std::size_t kEvery = 4096;
};

}  // namespace pds

#endif
