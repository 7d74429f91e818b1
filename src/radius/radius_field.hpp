// radius_field.hpp - a radius that varies with position (variable density).
//
// The law (poissondisk.h, pds_set_radius_map): point i carries r_i = r(p_i),
// evaluated once when it is placed; a later point keeps out of every earlier
// point's closed disk, |p_j - p_i| >= r_i for i < j; each new point is
// uniform over what is left, and the pattern is maximal when nothing is.
//
// A field is a radius map (w x h values over the domain, row 0 at y0,
// bilinear between pixel centres, clamped at the edges) or a user function
// with declared bounds [rmin, rmax]. Values are in user units.
//
// Scaling (pds_refine): the radius in force is scale * value, with
// scale = R / rmax for the largest radius R in force (pds_radius). Until the
// first refine R = rmax and a point's radius is its value exactly; a field
// whose values all equal rmax gives every point R exactly, as the plain
// sampler does.
#ifndef PDS_RADIUS_FIELD_HPP
#define PDS_RADIUS_FIELD_HPP

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/point.hpp"

namespace pds {

// A user function returned a value outside its declared bounds, or not finite.
class FieldError : public std::runtime_error {
public:
    FieldError(double value, double x, double y)
        : std::runtime_error("radius field"), value_(value), x_(x), y_(y) {}
    double value() const { return value_; }
    double x() const { return x_; }
    double y() const { return y_; }

private:
    double value_, x_, y_;
};

class RadiusField {
public:
    using Function = double (*)(void* user, double x, double y);

    // Requires w, h >= 1 and every value finite and > 0 (checked by the C shim).
    static RadiusField map(std::size_t w, std::size_t h, const double* values);
    // Requires 0 < rmin <= rmax, both finite.
    static RadiusField function(Function fn, void* user, double rmin, double rmax);

    double rmin() const { return rmin_; }
    double rmax() const { return rmax_; }
    // All values equal (a map of one value, or rmin == rmax).
    bool constant() const { return rmin_ == rmax_; }
    // The value at user point (x, y) of `domain`. Throws FieldError.
    double value(const Box& domain, double x, double y) const;
    // A map field: an upper bound on the number of points of any pattern
    // over `box` (the domain, in any frame), where a point of value v has
    // the radius radius_of(v) in that frame. Infinite for a function, whose
    // values are known only where it is asked. See radius_field.cpp.
    double map_count_bound(const Box& box, const std::function<double(double)>& radius_of) const;

    // A user function's field calls user code for every value.
    bool calls_user() const { return fn_ != nullptr && !constant(); }

    // The mean of 1 / r^2 over the domain, estimated from its values at a
    // grid of kMeanGrid^2 points (the expected count, for progress reports).
    // A function's may take long, so the estimate goes a value at a time:
    // step() adds the next grid point's, done() says all are in.
    static constexpr int kMeanGrid = 64;
    class MeanInverseSquare {
    public:
        bool done() const { return next_ == kMeanGrid * kMeanGrid; }
        void step(const RadiusField& field, const Box& domain);
        double mean() const { return sum_ / (kMeanGrid * kMeanGrid); }

    private:
        int next_ = 0;
        double sum_ = 0.0;
    };

private:
    std::vector<double> map_;
    std::size_t w_ = 0, h_ = 0;
    Function fn_ = nullptr;
    void* user_ = nullptr;
    double rmin_ = 0.0, rmax_ = 0.0;
};

// A point's radius in force from its field value: `value` until the first
// refine (scale 1), then value / rmax * R (R, the largest radius in force).
inline double scaled_radius(double value, double rmax, double r_in_force) {
    return r_in_force == rmax ? value : value / rmax * r_in_force;
}

// The value that scaled_radius turns into `radius`: exactly `radius` while
// the radius in force is rmax (a clearance is then kept to the bit).
inline double unscaled_radius(double radius, double rmax, double r_in_force) {
    return r_in_force == rmax ? radius : radius / r_in_force * rmax;
}

}  // namespace pds

#endif
