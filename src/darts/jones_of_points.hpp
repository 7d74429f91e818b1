// jones_of_points.hpp - the mesh of a dart stage's points, for the queries
// asked while the stage runs (free area, verify): a Jones stage holding the
// points, built as the hand-over builds it, with the torus's copies settled.
// Each query builds it anew; the run goes on without it.
#ifndef PDS_JONES_OF_POINTS_HPP
#define PDS_JONES_OF_POINTS_HPP

#include <memory>
#include <vector>

#include "core/point.hpp"
#include "core/torus.hpp"
#include "domain/rectangle.hpp"
#include "darts/curve_order.hpp"
#include "jones/jones_stage.hpp"
#include "radius/point_radii.hpp"

namespace pds {

// The domain and r in the internal frame (r: the largest radius with a field);
// radii and values for a varying radius (values[k]: point k's), else null;
// curve: the stage's hand-over order. Allocates; may throw std::bad_alloc.
std::unique_ptr<JonesStage> jones_of_points(const Rectangle& domain, const std::shared_ptr<const Polygon>& polygon,
                                            double r, const Torus& torus, const PointRadii* radii,
                                            const std::vector<Point>& points, const std::vector<double>* values,
                                            const CurveOrder& curve);

}  // namespace pds

#endif
