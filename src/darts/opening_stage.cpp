// opening_stage.cpp - which opening stage a run gets (see opening_stage.hpp).
#include "darts/opening_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "darts/dart_constants.hpp"
#include "darts/dart_stage.hpp"
#include "darts/polygon_raster.hpp"
#include "darts/space_time_stage.hpp"
#include "domain/frame.hpp"
#include "radius/point_radii.hpp"
#include "radius/radius_field.hpp"

namespace pds {

namespace {

enum class Opening { none, space_time, dense, sparse, field };

constexpr double kSparseFrom = 128.0;

// The cells of a dart grid of radius r over the box (dart_grid.hpp's side
// and count along each axis).
double grid_cells(const Box& box, double r) {
    const double side = darts::cell_side(r);
    return std::max(std::ceil(box.width() / side), 1.0) * std::max(std::ceil(box.height() / side), 1.0);
}

// A polygon that fills little of its box, whose grid of radius r over the
// box would have over kSparseFrom cells for each point it can hold.
bool spread_thin(const Frame& frame, double r, double count_bound) {
    return frame.polygon() && raster_suits(*frame.polygon(), frame.domain().bounds()) &&
           grid_cells(frame.domain().bounds(), r) > kSparseFrom * count_bound;
}

Opening opening_for(const Frame& frame, double count_bound, const RadiusField* field, bool space_time) {
    const bool fits = count_bound <= static_cast<double>(Frame::max_points());
    if (field) {
        // A grid per layer of radii (layered_grid.hpp), in the plane or on
        // the torus, while the layers stay few and a maximal pattern fits the
        // index. The loop runs alone in a polygon whose layers' grids,
        // spanning its box, would have over kSparseFrom cells for each point
        // it can hold (islands far apart): the loop's memory follows the points.
        const bool few_layers = field->rmax() <= LayeredGrid::kMaxRatio * field->rmin();
        const double rmin = frame.r() * (field->rmin() / field->rmax());
        return fits && few_layers && !spread_thin(frame, rmin, count_bound) ? Opening::field : Opening::none;
    }
    // One radius: a dense grid while a maximal pattern fits the index (its
    // address space then stays within a few words a point). Beyond, only
    // bounded runs are possible (the sampler refuses the others), and their
    // darts go to a sparse grid whose memory follows the points: the Jones
    // loop alone would start from a sparse mesh whose cells span the domain
    // (on a torus, with copies across whole periods).
    // Asked for: the space-time process (its darts tied to space, so
    // threads share its work), in a rectangle, a polygon or on the torus.
    // A polygon that fills little of its box draws its darts among the grid
    // cells it meets (polygon_raster.hpp); its grid keeps only its taken
    // cells once the whole grid would have over kSparseFrom cells for each
    // point the polygon can hold (islands far apart: more than memory).
    if (!fits || spread_thin(frame, frame.r(), count_bound)) return Opening::sparse;
    return space_time ? Opening::space_time : Opening::dense;
}

}  // namespace

bool opening_stage_suits(const Frame& frame, double count_bound, const RadiusField* field) {
    return opening_for(frame, count_bound, field, false) != Opening::none;
}

std::unique_ptr<OpeningStage> make_opening_stage(const Frame& frame, double count_bound, const RadiusField* field,
                                                std::optional<std::uint64_t> space_time) {
    switch (opening_for(frame, count_bound, field, space_time.has_value())) {
    case Opening::space_time: {
        auto stage = std::make_unique<SpaceTimeDartStage>(frame.domain(), frame.shared_polygon(), frame.r(), *space_time,
                                                          frame.torus());
        if (stage->outline_rastered()) return stage;
        // An outline too costly to raster over the sub-squares: the dart
        // grid that tests each dart against it.
        stage.reset();
        [[fallthrough]];
    }
    case Opening::dense:
        return std::make_unique<DartStage>(frame.domain(), frame.shared_polygon(), frame.r(), frame.torus());
    case Opening::sparse:
        return std::make_unique<SparseDartStage>(frame.domain(), frame.shared_polygon(), frame.r(), frame.torus());
    case Opening::field:
        return std::make_unique<FieldDartStage>(frame.domain(), frame.shared_polygon(), PointRadii(*field, frame),
                                                frame.torus());
    case Opening::none:
        break;
    }
    return nullptr;
}

}  // namespace pds
