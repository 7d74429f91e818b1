// point_radii.hpp - the radius field as the stages see it: in the internal
// frame (frame.hpp), scaled to the radius in force (radius_field.hpp).
//
// A stage asks value_at(p) for a new point before it changes anything (a
// user function may refuse, FieldError), keeps the value, and places the
// point with radius_of(value). A refine changes the radius in force, so every
// radius changes with it and the stages recompute theirs from the values.
#ifndef PDS_POINT_RADII_HPP
#define PDS_POINT_RADII_HPP

#include <stdexcept>

#include "domain/frame.hpp"
#include "core/point.hpp"
#include "radius/radius_field.hpp"

namespace pds {

class PointRadii {
public:
    // field outlives this; frame: the sampler's, its user radius the one in force.
    PointRadii(const RadiusField& field, const Frame& frame) : field_(&field), frame_(frame) {}

    // The field's value (user units) at internal point p. Throws FieldError.
    // Every value a stage keeps passes here: one that is not a number in
    // [rmin, rmax] (a NaN above all, which fails every comparison a stage
    // makes and so would leave its disk empty) is a bug, never a radius.
    double value_at(const Point& p) const {
        const Point u = frame_.to_user(p);
        const double v = field_->value(frame_.user_domain(), u.x, u.y);
        if (!(v >= field_->rmin() && v <= field_->rmax())) throw std::logic_error("radius field value out of its bounds");
        return v;
    }
    // The internal radius of a point whose field value is `value`.
    double radius_of(double value) const {
        return frame_.internal_radius(scaled_radius(value, field_->rmax(), frame_.user_radius()));
    }
    // The user radius of such a point (pds_radii).
    double user_radius_of(double value) const {
        return scaled_radius(value, field_->rmax(), frame_.user_radius());
    }
    // The largest and smallest internal radii a new point may get.
    double rmax() const { return frame_.r(); }
    double rmin() const { return radius_of(field_->rmin()); }
    const Frame& frame() const { return frame_; }
    const RadiusField& field() const { return *field_; }
    // Every new point gets the same radius (a constant field: fixed points
    // in a run of one radius).
    bool constant() const { return field_->rmin() == field_->rmax(); }

private:
    const RadiusField* field_;
    Frame frame_;
};

}  // namespace pds

#endif
