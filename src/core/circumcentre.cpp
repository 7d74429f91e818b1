// circumcentre.cpp - exact forms of the circumcentre (see circumcentre.hpp).
#include "core/circumcentre.hpp"

#include <stdexcept>

namespace pds {

void degenerate_triangle() { throw std::logic_error("degenerate Delaunay triangle around a site"); }

ExactCentre exact_circumcentre(const Point& a, const Point& b, const Point& c) {
    using E = Expansion;
    const E bx = E::diff(b.x, a.x), by = E::diff(b.y, a.y);
    const E dx = E::diff(c.x, a.x), dy = E::diff(c.y, a.y);
    const E bb = bx * bx + by * by, dd = dx * dx + dy * dy;
    return ExactCentre{dy * bb - by * dd, bx * dd - dx * bb, (bx * dy - by * dx).scaled(2.0)};
}

ExactCentre exact_power_centre(const Point& a, double ra, const Point& b, double rb, const Point& c, double rc) {
    using E = Expansion;
    const E bx = E::diff(b.x, a.x), by = E::diff(b.y, a.y);
    const E dx = E::diff(c.x, a.x), dy = E::diff(c.y, a.y);
    const E wa = E::product(ra, ra);
    const E bb = bx * bx + by * by + wa - E::product(rb, rb);
    const E dd = dx * dx + dy * dy + wa - E::product(rc, rc);
    return ExactCentre{dy * bb - by * dd, bx * dd - dx * bb, (bx * dy - by * dx).scaled(2.0)};
}

Rational bisector_parameter(const Point& a, const Point& b, const Point& c) {
    using E = Expansion;
    const E bx = E::diff(b.x, a.x), by = E::diff(b.y, a.y);
    const E dx = E::diff(c.x, a.x), dy = E::diff(c.y, a.y);
    const E num = dx * E::diff(c.x, b.x) + dy * E::diff(c.y, b.y);
    const E den = (bx * dy - by * dx).scaled(2.0);
    return make_rational(num, den);
}

Rational power_bisector_parameter(const Point& a, double ra, const Point& b, double rb, const Point& c,
                                  double rc) {
    using E = Expansion;
    const E bx = E::diff(b.x, a.x), by = E::diff(b.y, a.y);
    const E dx = E::diff(c.x, a.x), dy = E::diff(c.y, a.y);
    const E bb = bx * bx + by * by, dd = dx * dx + dy * dy;
    const E wa = E::product(ra, ra);
    const E bw = bb + wa - E::product(rb, rb), dw = dd + wa - E::product(rc, rc);
    // t = perp(e) . centre / |e|^2 = (|e|^2 dw - bw (e . d)) / (|e|^2 2 (e x d)).
    const E num = bb * dw - bw * (bx * dx + by * dy);
    const E den = bb * (bx * dy - by * dx).scaled(2.0);
    return make_rational(num, den);
}

}  // namespace pds
