// opening_stage.hpp - the stage that opens a run (stage.hpp): darts thrown
// over the whole domain while most of it is free (dart_stage.hpp for one
// radius, field_dart_stage.hpp for a varying one), then its points handed
// over to the Jones stage, once.
#ifndef PDS_OPENING_STAGE_HPP
#define PDS_OPENING_STAGE_HPP

#include <cstddef>

#include "core/poll.hpp"
#include "jones/stage.hpp"

namespace pds {

class JonesStage;

class OpeningStage : public Stage {
public:
    // Room for `points` points in all, the hand-over's scratch included;
    // strong guarantee (std::bad_alloc).
    virtual void reserve(std::size_t points) = 0;
    virtual bool has_room_for(std::size_t points) const = 0;
    // Inserts the points into `jones` (no points yet, room reserved for
    // these) in an order that keeps its walks short; never allocates. Ends
    // this stage and releases its grid. Calls poll between its steps and
    // every Poll::kEvery points (progress reports).
    virtual void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) = 0;
};

}  // namespace pds

#endif
