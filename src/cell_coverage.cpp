// cell_coverage.cpp - exact coverage test of one clipped Voronoi cell (see
// cell_coverage.hpp for the method).
#include "cell_coverage.hpp"

#include <cstddef>

#include "circumcentre.hpp"
#include "expansion.hpp"

namespace pds {

namespace {

using E = Expansion;

// x/2 exactly (a power-of-two scaling; our frame keeps values far from underflow).
E half(double x) { return E(x * 0.5); }

struct Interval {
    Rational lo, hi;
    bool has_lo = false, has_hi = false;
    bool empty = false;

    void raise_lo(const Rational& r) {
        if (!has_lo || compare(r, lo) > 0) lo = r;
        has_lo = true;
    }
    void lower_hi(const Rational& r) {
        if (!has_hi || compare(r, hi) < 0) hi = r;
        has_hi = true;
    }
    // Constraint coef * t >= rhs.
    void at_least(const E& coef, const E& rhs) {
        const int s = coef.sign();
        if (s == 0) {
            if (rhs.sign() > 0) empty = true;
        } else if (s > 0) {
            raise_lo(make_rational(rhs, coef));
        } else {
            lower_hi(make_rational(rhs, coef));
        }
    }
};

// |P(t) - c|^2 <= R^2 for t = a/q on the bisector of c and c + b:
// |b|^2 / 4 + t^2 |b|^2 <= R^2  <=>  |b|^2 (q^2 + 4 a^2) <= 4 R^2 q^2.
bool within_radius(const Rational& t, const E& bb, const E& r2) {
    const E q2 = t.den * t.den;
    const E lhs = bb * (q2 + (t.num * t.num).scaled(4.0));
    const E rhs = (r2 * q2).scaled(4.0);
    return (rhs - lhs).sign() >= 0;
}

E squared_distance(const Point& p, const Point& q) {
    const E dx = E::diff(p.x, q.x), dy = E::diff(p.y, q.y);
    return dx * dx + dy * dy;
}

}  // namespace

bool cell_is_covered_exact(const Point& c, const std::vector<Point>& ring, const Box& box,
                           double radius) {
    const E r2 = E::product(radius, radius);
    const std::size_t k = ring.size();
    for (std::size_t j = 0; j < k; ++j) {
        const Point& n = ring[j];
        const Point& left = ring[(j + 1) % k];       // triangle (c, n, left) is CCW
        const Point& right = ring[(j + k - 1) % k];  // triangle (c, right, n) is CCW
        Interval t;
        t.raise_lo(bisector_parameter(c, n, right));
        t.lower_hi(bisector_parameter(c, n, left));
        // P(t) = (c + n)/2 + t * (-by, bx) must stay inside the box.
        const E bx = E::diff(n.x, c.x), by = E::diff(n.y, c.y);
        const E mx = half(c.x) + half(n.x), my = half(c.y) + half(n.y);
        t.at_least(-by, E(box.x0) - mx);  // x >= x0
        t.at_least(by, mx - E(box.x1));   // x <= x1
        t.at_least(bx, E(box.y0) - my);   // y >= y0
        t.at_least(-bx, my - E(box.y1));  // y <= y1
        if (t.empty || compare(t.lo, t.hi) > 0) continue;  // edge outside the box
        const E bb = bx * bx + by * by;
        if (!within_radius(t.lo, bb, r2) || !within_radius(t.hi, bb, r2)) return false;
    }
    const Point corners[4] = {{box.x0, box.y0}, {box.x1, box.y0}, {box.x1, box.y1}, {box.x0, box.y1}};
    for (const Point& corner : corners) {
        const E dc = squared_distance(corner, c);
        if ((dc - r2).sign() <= 0) continue;  // within R: fine wherever it belongs
        bool in_cell = true;
        for (const Point& n : ring) {
            if ((squared_distance(corner, n) - dc).sign() < 0) {
                in_cell = false;
                break;
            }
        }
        if (in_cell) return false;
    }
    return true;
}

}  // namespace pds
