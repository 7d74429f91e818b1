// cell_coverage.cpp - exact coverage test of one clipped Voronoi cell (see
// cell_coverage.hpp for the method).
#include "cells/cell_coverage.hpp"

#include <cstddef>

#include "core/circumcentre.hpp"
#include "core/expansion.hpp"

namespace pds {

namespace {

using E = Expansion;

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

// |P(t) - c|^2 <= R^2 on the power bisector of c and c + b, for t = a/q:
// P(t) - c = s b + t perp(b) with s = bw / (2 |b|^2), so the condition is
// |b|^2 (s^2 + t^2) <= R^2  <=>  bw^2 q^2 + 4 |b|^4 a^2 <= 4 |b|^2 R^2 q^2.
bool within_radius(const Rational& t, const E& bb, const E& bw, const E& r2) {
    const E q2 = t.den * t.den;
    const E lhs = bw * bw * q2 + (bb * bb * t.num * t.num).scaled(4.0);
    const E rhs = (bb * r2 * q2).scaled(4.0);
    return (rhs - lhs).sign() >= 0;
}

E squared_distance(const Point& p, const Point& q) {
    const E dx = E::diff(p.x, q.x), dy = E::diff(p.y, q.y);
    return dx * dx + dy * dy;
}

}  // namespace

bool cell_is_covered_exact(const Point& c, const std::vector<Point>& ring, const Box& box,
                           double radius) {
    return power_cell_is_covered_exact(c, radius, ring, std::vector<double>(ring.size(), radius), box);
}

bool power_cell_is_covered_exact(const Point& c, double radius, const std::vector<Point>& ring,
                                 const std::vector<double>& ring_radii, const Box& box, const Polygon* outline) {
    const E r2 = E::product(radius, radius);
    const std::size_t k = ring.size();
    for (std::size_t j = 0; j < k; ++j) {
        const Point& n = ring[j];
        const std::size_t jl = (j + 1) % k, jr = (j + k - 1) % k;
        const double rn = ring_radii[j];
        Interval t;  // triangle (c, n, left) and (c, right, n) are CCW
        t.raise_lo(power_bisector_parameter(c, radius, n, rn, ring[jr], ring_radii[jr]));
        t.lower_hi(power_bisector_parameter(c, radius, n, rn, ring[jl], ring_radii[jl]));
        // 2|b|^2 P(t) = 2|b|^2 c + bw b + 2|b|^2 t (-by, bx) must stay inside the box.
        const E bx = E::diff(n.x, c.x), by = E::diff(n.y, c.y);
        const E bb = bx * bx + by * by;
        const E bw = bb + r2 - E::product(rn, rn);
        const E bb2 = bb.scaled(2.0);
        const E mx = bb2 * E(c.x) + bw * bx, my = bb2 * E(c.y) + bw * by;
        t.at_least(-(bb2 * by), bb2 * E(box.x0) - mx);  // x >= x0
        t.at_least(bb2 * by, mx - bb2 * E(box.x1));     // x <= x1
        t.at_least(bb2 * bx, bb2 * E(box.y0) - my);     // y >= y0
        t.at_least(-(bb2 * bx), my - bb2 * E(box.y1));  // y <= y1
        if (t.empty || compare(t.lo, t.hi) > 0) continue;  // edge outside the box
        // An end beyond R uncovers the cell, if the domain holds it: the
        // point 2|b|^2 P(t) / (2|b|^2), t = num / den, in homogeneous form.
        const auto uncovers = [&](const Rational& at) {
            if (within_radius(at, bb, bw, r2)) return false;
            return outline == nullptr ||
                   outline->contains_exact(mx * at.den - bb2 * by * at.num, my * at.den + bb2 * bx * at.num, bb2 * at.den);
        };
        if (uncovers(t.lo) || uncovers(t.hi)) return false;
    }
    const Point corners[4] = {{box.x0, box.y0}, {box.x1, box.y0}, {box.x1, box.y1}, {box.x0, box.y1}};
    for (const Point& corner : corners) {
        const E dc = squared_distance(corner, c);
        if ((dc - r2).sign() <= 0) continue;  // within R: fine wherever it belongs
        if (outline != nullptr && !outline->contains(corner)) continue;
        bool in_cell = true;
        for (std::size_t j = 0; j < k; ++j) {
            // A neighbour with a smaller power at the corner owns it.
            if ((squared_distance(corner, ring[j]) - E::product(ring_radii[j], ring_radii[j]) - dc + r2).sign() < 0) {
                in_cell = false;
                break;
            }
        }
        if (in_cell) return false;
    }
    return true;
}

}  // namespace pds
