// jones_of_points.cpp - see jones_of_points.hpp.
#include "darts/jones_of_points.hpp"

#include <cstdint>

namespace pds {

std::unique_ptr<JonesStage> jones_of_points(const Rectangle& domain, const std::shared_ptr<const Polygon>& polygon,
                                            double r, const Torus& torus, const PointRadii* radii,
                                            const std::vector<Point>& points, const std::vector<double>* values,
                                            const CurveOrder& curve) {
    std::unique_ptr<JonesStage> stage = make_jones_stage(domain, r, torus, radii, polygon);
    stage->reserve(points.size());
    const std::vector<std::uint32_t> order = curve.fresh_order(points);
    stage->adopt(points, order.data(), values);
    stage->settle();  // the torus: the margin the hand-over left to widen
    return stage;
}

}  // namespace pds
