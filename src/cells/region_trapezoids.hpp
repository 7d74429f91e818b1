// region_trapezoids.hpp - a region given by its boundary segments (region
// on their left, in any order, as OutlineClip gives a cut cell) cut into
// trapezoids between vertical lines through every segment end, the ones
// inside a disk dropped, and a uniform point in one of them.
//
// Unlike the fan from the site (outline_clip.hpp), these pieces never
// overlap and never reach outside the region, so drawing from them wastes
// nothing however the region bends: the sampler uses them for regions the
// fan reaches too rarely (a strip far thinner than R that turns inside a
// cell). Floating point: the pieces follow the segments as rounded; a draw
// is only ever kept after the exact checks.
#ifndef PDS_REGION_TRAPEZOIDS_HPP
#define PDS_REGION_TRAPEZOIDS_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/point.hpp"
#include "core/trapezoid.hpp"

namespace pds {

namespace trapezoid_detail {

struct Crossing {
    double mid, at0, at1;
    int up;  // +1: the region lies above the segment (it runs toward +x)
};

template <class Segment>
bool spans(const Segment& s, double x0, double x1) {
    return std::min(s.a.x, s.b.x) <= x0 && std::max(s.a.x, s.b.x) >= x1;
}

template <class Segment>
double y_at(const Segment& s, double x) {
    const double t = (x - s.a.x) / (s.b.x - s.a.x);
    return s.a.y + t * (s.b.y - s.a.y);
}

}  // namespace trapezoid_detail

// Segment: .a and .b with .x and .y. xs and crossings are scratch.
template <class Segment>
void cut_into_trapezoids(const std::vector<Segment>& segments, std::vector<double>& xs,
                         std::vector<trapezoid_detail::Crossing>& crossings, std::vector<Trapezoid>& out) {
    using trapezoid_detail::Crossing;
    out.clear();
    xs.clear();
    for (const Segment& s : segments) xs.push_back(s.a.x), xs.push_back(s.b.x);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
        const double x0 = xs[i], x1 = xs[i + 1], xm = 0.5 * (x0 + x1);
        crossings.clear();
        for (const Segment& s : segments)
            if (s.a.x != s.b.x && trapezoid_detail::spans(s, x0, x1))
                crossings.push_back(Crossing{trapezoid_detail::y_at(s, xm), trapezoid_detail::y_at(s, x0),
                                             trapezoid_detail::y_at(s, x1), s.b.x > s.a.x ? 1 : -1});
        std::sort(crossings.begin(), crossings.end(),
                  [](const Crossing& p, const Crossing& q) { return p.mid < q.mid; });
        // Upward through the slab, the winding count: the region runs from
        // where it leaves 0 to where it comes back (rounding that breaks the
        // count only loses a sliver).
        int winding = 0;
        const Crossing* low = nullptr;
        for (const Crossing& c : crossings) {
            const int before = winding;
            winding = std::max(0, winding + c.up);
            if (before == 0 && winding > 0) low = &c;
            if (before > 0 && winding == 0 && low) {
                const double h0 = c.at0 - low->at0, h1 = c.at1 - low->at1;
                const double area = 0.5 * (x1 - x0) * (std::max(0.0, h0) + std::max(0.0, h1));
                if (area > 0.0) out.push_back(Trapezoid{x0, x1, low->at0, low->at1, c.at0, c.at1, area});
            }
        }
    }
}

// The parts of `in` that may lie outside the disk of radius r about the
// origin, into out: a piece whose corners all lie inside is dropped (the
// disk is convex); those that straddle the circle are halved across their
// longer side, level by level, while the pieces number fewer than
// kMaxTrapezoids. So the pieces hug the free part, however small.
constexpr std::size_t kMaxTrapezoids = 512;

inline void drop_inside_disk(const std::vector<Trapezoid>& in, double r, std::vector<Trapezoid>& next,
                             std::vector<Trapezoid>& out) {
    const double inside = r * r * (1.0 - 0x1p-40);
    const auto in_disk = [&](double x, double y) { return x * x + y * y < inside; };
    // 0: inside (drop), 1: outside or too thin to halve (keep), 2: straddles.
    const auto place = [&](const Trapezoid& t) {
        if (in_disk(t.x0, t.lo0) && in_disk(t.x0, t.hi0) && in_disk(t.x1, t.lo1) && in_disk(t.x1, t.hi1)) return 0;
        const double nx = std::clamp(0.0, t.x0, t.x1);
        const double ny = std::clamp(0.0, std::min(t.lo0, t.lo1), std::max(t.hi0, t.hi1));
        const bool thin = !(t.x1 - t.x0 > 0.0 && std::max(t.hi0 - t.lo0, t.hi1 - t.lo1) > 0.0);
        return nx * nx + ny * ny >= r * r || thin ? 1 : 2;
    };
    out.clear();
    for (const Trapezoid& t : in)
        if (place(t) != 0) out.push_back(t);
    for (int level = 0; level < 64; ++level) {
        std::size_t straddling = 0;
        for (const Trapezoid& t : out) straddling += place(t) == 2;
        if (straddling == 0 || out.size() + straddling > kMaxTrapezoids) return;
        next.clear();
        for (const Trapezoid& t : out) {
            if (place(t) != 2) {
                next.push_back(t);
                continue;
            }
            const double h0 = t.hi0 - t.lo0, h1 = t.hi1 - t.lo1, w = t.x1 - t.x0;
            Trapezoid a = t, b = t;
            if (w >= std::max(h0, h1)) {
                const double xm = 0.5 * (t.x0 + t.x1), lom = 0.5 * (t.lo0 + t.lo1), him = 0.5 * (t.hi0 + t.hi1);
                a.x1 = xm, a.lo1 = lom, a.hi1 = him, b.x0 = xm, b.lo0 = lom, b.hi0 = him;
            } else {
                a.hi0 = b.lo0 = 0.5 * (t.lo0 + t.hi0), a.hi1 = b.lo1 = 0.5 * (t.lo1 + t.hi1);
            }
            for (Trapezoid* half : {&a, &b}) {
                half->area = 0.5 * (half->x1 - half->x0) * ((half->hi0 - half->lo0) + (half->hi1 - half->lo1));
                if (half->area > 0.0 && place(*half) != 0) next.push_back(*half);
            }
        }
        out.swap(next);
    }
}

}  // namespace pds

#endif
