// make_jones_stage.cpp - the factory that picks the Jones loop for a mesh
// (plane, torus, polygon) and a radius rule (one radius, power cells).
#include <memory>
#include <stdexcept>

#include "jones/jones_loop.hpp"
#include "jones/plane_space.hpp"
#include "jones/polygon_space.hpp"
#include "jones/radius_rule.hpp"
#include "jones/torus_space.hpp"

namespace pds {

std::unique_ptr<JonesStage> make_jones_stage(const Rectangle& domain, double r, const Torus& torus,
                                             const PointRadii* radii, std::shared_ptr<const Polygon> polygon) {
    if (torus.on()) {
        if (polygon) throw std::logic_error("a polygon on the torus");
        if (radii) return std::make_unique<JonesLoop<TorusSpace, PowerRule>>(domain, r, torus, radii, nullptr);
        return std::make_unique<JonesLoop<TorusSpace, OneRadius>>(domain, r, torus, radii, nullptr);
    }
    if (polygon) {
        if (radii) return std::make_unique<JonesLoop<PolygonSpace, PowerRule>>(domain, r, torus, radii, polygon);
        return std::make_unique<JonesLoop<PolygonSpace, OneRadius>>(domain, r, torus, radii, polygon);
    }
    if (radii) return std::make_unique<JonesLoop<PlaneSpace, PowerRule>>(domain, r, torus, radii, nullptr);
    return std::make_unique<JonesLoop<PlaneSpace, OneRadius>>(domain, r, torus, radii, nullptr);
}

}  // namespace pds
