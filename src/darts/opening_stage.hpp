// opening_stage.hpp - the stage that opens a run (stage.hpp): darts thrown
// over the whole domain while most of it is free (dart_stage.hpp), then its
// points handed over to the Jones stage, once; and the one place that
// chooses which opening stage a run gets (make_opening_stage).
#ifndef PDS_OPENING_STAGE_HPP
#define PDS_OPENING_STAGE_HPP

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/point.hpp"
#include "core/poll.hpp"
#include "jones/stage.hpp"

namespace pds {

class Frame;
class JonesStage;
class PointRadii;
class RadiusField;

class OpeningStage : public Stage {
public:
    // Room for `points` points in all, the hand-over's scratch included;
    // strong guarantee (std::bad_alloc).
    virtual void reserve(std::size_t points) = 0;
    virtual bool has_room_for(std::size_t points) const = 0;
    // Inserts the points into `jones` (no points yet, room reserved for
    // these) in an order that keeps its walks short; never allocates. Ends
    // this stage and releases its grid. Calls poll between its steps and
    // every Poll::kEvery points (progress reports). Fixed points it holds
    // (hold_fixed) go first, and it tells `jones` so (set_fixed).
    virtual void hand_over_to(JonesStage& jones, const Poll& poll = Poll{}) = 0;
    // Threads the stage may use from its next step on (at least 1); a stage
    // that runs on one thread ignores it. Never changes the points.
    virtual void set_threads(unsigned) {}
    // Another memory budget for a stage that has one (a field's layered
    // grids: layered_grid.hpp), bytes a point above a floor (tests: the
    // hand-over it causes, in small runs).
    virtual void set_memory_budget(double /*bytes_per_point*/, std::size_t /*floor_bytes*/) {}
    // Fixed points (internal frame) with their values, before the first
    // point: the stage holds them as its first points, keeps its darts out
    // of their clearance disks (radii.radius_of(value)), gives its own
    // points new_value and hands all over. False when the stage cannot
    // (only the space-time process can), and it must then not be used.
    virtual bool hold_fixed(const std::vector<Point>& /*points*/, const std::vector<double>& /*values*/,
                            const PointRadii& /*radii*/, double /*new_value*/) {
        return false;
    }
};

// Whether a run with these settings opens with darts: frame at the radius in
// force; count_bound: Oler's bound at the smallest radius; field: a varying
// field (null for one radius, or a constant field, which runs as one radius).
// Decided from the settings alone, never from the points asked for, so a
// run split into calls opens as one call does.
bool opening_stage_suits(const Frame& frame, double count_bound, const RadiusField* field);
// The opening stage for those settings, or nullptr when the Jones loop runs
// alone (opening_stage_suits false). Throws std::bad_alloc.
// space_time: the handle's seed when the run asked for the parallel opening
// (one radius in a rectangle then gets the space-time dart process; other
// settings the same stages as without it).
std::unique_ptr<OpeningStage> make_opening_stage(const Frame& frame, double count_bound, const RadiusField* field,
                                                std::optional<std::uint64_t> space_time = std::nullopt);

}  // namespace pds

#endif
