// rectangle_boundary.cpp - the certificate that a rectangle's boundary is
// covered (rectangle.hpp): each side, a segment, lies in the union of the
// disks that reach it. Exact: along a side the power of a point to a disk
// is a parabola, their lower envelope is built from the lines left after
// subtracting x^2, and on each envelope piece the power is convex, so its
// ends decide it (expansions and rationals, core/expansion.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/expansion.hpp"
#include "domain/rectangle.hpp"
#include "mesh/delaunay.hpp"

namespace pds {

namespace {

using E = Expansion;

// A site seen from a side of the domain: position along the side, exact
// squared distance to the side's line.
struct SideSite {
    double along;
    E h2;
    E c;   // along^2 + h2 - r^2: the constant of the line g(x) = -2 along x + c
    E r2;  // the disk's squared radius
};

// x where the lines of sites i < j (by `along`) meet: (cj - ci) / (2 (aj - ai)).
Rational meeting_point(const SideSite& i, const SideSite& j) {
    return make_rational(j.c - i.c, E::diff(j.along, i.along).scaled(2.0));
}

// (x - along)^2 + h2 <= r^2 at x = num/den (den > 0).
bool covers_at(const SideSite& s, const Rational& x) {
    const E diff = x.num - x.den.scaled(s.along);
    const E den2 = x.den * x.den;
    return (s.r2 * den2 - diff * diff - s.h2 * den2).sign() >= 0;
}

// Is the segment [lo, hi] of a side covered by the disks of `sites`?
bool side_covered(std::vector<SideSite>& sites, double lo, double hi) {
    if (sites.empty()) return false;
    std::sort(sites.begin(), sites.end(), [](const SideSite& a, const SideSite& b) {
        if (a.along != b.along) return a.along < b.along;
        return (a.c - b.c).sign() < 0;
    });
    // Lower envelope of the lines g_i (the least power along the side: x^2
    // plus the line), by increasing position; a line is dropped when its
    // neighbours meet before it would appear.
    std::vector<const SideSite*> env;
    for (const SideSite& s : sites) {
        if (!env.empty() && env.back()->along == s.along) continue;  // same position, farther
        while (env.size() >= 2 &&
               compare(meeting_point(*env[env.size() - 2], *env.back()),
                       meeting_point(*env.back(), s)) >= 0)
            env.pop_back();
        env.push_back(&s);
    }
    // On each envelope piece the power is convex, so checking the
    // piece's ends (clipped to [lo, hi]) decides it.
    const Rational lo_r = make_rational(E(lo), E(1.0)), hi_r = make_rational(E(hi), E(1.0));
    for (std::size_t k = 0; k < env.size(); ++k) {
        Rational a = lo_r, b = hi_r;
        if (k > 0) {
            const Rational m = meeting_point(*env[k - 1], *env[k]);
            if (compare(m, a) > 0) a = m;
        }
        if (k + 1 < env.size()) {
            const Rational m = meeting_point(*env[k], *env[k + 1]);
            if (compare(m, b) < 0) b = m;
        }
        if (compare(a, b) > 0) continue;  // this piece lies outside [lo, hi]
        if (!covers_at(*env[k], a) || !covers_at(*env[k], b)) return false;
    }
    return true;
}

}  // namespace

const char* Rectangle::uncovered_side(const Delaunay& dt, double r) const {
    const Box& box = box_;
    const std::vector<Point>& pts = dt.points();
    // For each side: the coordinate along it, and the line's fixed coordinate.
    struct Side {
        bool horizontal;
        double line, lo, hi;
        const char* name;
    };
    const Side sides[4] = {{true, box.y0, box.x0, box.x1, "bottom"},
                           {true, box.y1, box.x0, box.x1, "top"},
                           {false, box.x0, box.y0, box.y1, "left"},
                           {false, box.x1, box.y0, box.y1, "right"}};
    for (const Side& side : sides) {
        std::vector<SideSite> near;
        for (std::size_t i = Delaunay::kGhosts; i < pts.size(); ++i) {
            const double across = side.horizontal ? pts[i].y : pts[i].x;
            const double ri = dt.weighted() ? dt.radius(static_cast<VertexIndex>(i)) : r;
            if (std::fabs(across - side.line) > 2.0 * ri) continue;  // cheap prefilter
            const E h = E::diff(across, side.line);
            E h2 = h * h;
            E r2 = E::product(ri, ri);
            if ((h2 - r2).sign() > 0) continue;  // cannot reach the side
            const double along = side.horizontal ? pts[i].x : pts[i].y;
            E c = E::product(along, along) + h2 - r2;
            near.push_back(SideSite{along, std::move(h2), std::move(c), std::move(r2)});
        }
        if (!side_covered(near, side.lo, side.hi)) return side.name;
    }
    return nullptr;
}


}  // namespace pds
