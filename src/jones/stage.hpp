// stage.hpp - what the sampler asks of a stage of a run.
//
// A run has two stages with the same law (each new point uniform over the
// free area), told apart by how they find the next point: the dart stage
// (dart_stage.hpp) throws darts while most of the domain is free, the Jones
// stage (jones_stage.hpp) draws from the Voronoi cells' free regions until
// none is left. The sampler (sampler.hpp) holds the frame and the generator
// and hands the points over from the first stage to the second, once.
//
// next() draws the next point without adding it, and draws it once: until
// add_next(), calling it again returns the same point. So "is there room?"
// (a bounded run's last question) is answered by the same draws the next
// call would make first, and the generator's state never depends on where a
// caller split the work. Coordinates are in the internal frame (frame.hpp).
#ifndef PDS_STAGE_HPP
#define PDS_STAGE_HPP

#include <cstddef>

#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/rng.hpp"
#include "verify/verify.hpp"

namespace pds {

class Stage {
public:
    virtual ~Stage() = default;

    virtual std::size_t count() const = 0;
    // Point k in the order added.
    virtual const Point& point(PointIndex k) const = 0;
    // Points first .. first + n - 1 into out: one call for many points.
    virtual void copy_points(PointIndex first, std::size_t n, Point* out) const {
        for (std::size_t i = 0; i < n; ++i) out[i] = point(first + static_cast<PointIndex>(i));
    }
    // Point k's field value (user units; a varying radius only, else 0).
    virtual double value(PointIndex k) const = 0;
    // The next point, or nullptr when this stage has none: the dart stage
    // then hands over, the Jones stage has found the pattern maximal.
    virtual const Point* next(Rng& rng) = 0;
    // Adds the point next() returned; requires room (reserved beforehand).
    virtual void add_next() = 0;
    // Exact free area of the domain (internal units).
    virtual double free_area() const = 0;
    // The independent certificate; failures name the user's point.
    virtual VerifyReport verify() const = 0;
};

}  // namespace pds

#endif
