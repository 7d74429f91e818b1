// polygon_slabs.cpp - uniform points of a polygon by its vertical slabs (see
// polygon_slabs.hpp).
#include "domain/polygon_slabs.hpp"

#include <algorithm>
#include <cmath>

namespace pds {

namespace {

double y_at(const Point& a, const Point& b, double x) { return a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y); }

double low_x(const PolygonRings& rings, std::uint32_t e) {
    return std::min(rings.edge_start(e).x, rings.edge_end(e).x);
}

double high_x(const PolygonRings& rings, std::uint32_t e) {
    return std::max(rings.edge_start(e).x, rings.edge_end(e).x);
}

}  // namespace

void PolygonSlabs::parts_of(const std::vector<std::uint32_t>& edges, double x0, double x1,
                            std::vector<Trapezoid>& out) const {
    struct Crossing {
        double mid, at0, at1;
    };
    std::vector<Crossing> crossings;
    crossings.reserve(edges.size());
    const double xm = 0.5 * (x0 + x1);
    for (const std::uint32_t e : edges) {
        const Point a = rings_.edge_start(e), b = rings_.edge_end(e);
        crossings.push_back(Crossing{y_at(a, b, xm), y_at(a, b, x0), y_at(a, b, x1)});
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& p, const Crossing& q) { return p.mid < q.mid; });
    out.clear();
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        const Crossing &lo = crossings[k], &hi = crossings[k + 1];
        const double area = 0.5 * (x1 - x0) * (std::max(0.0, hi.at0 - lo.at0) + std::max(0.0, hi.at1 - lo.at1));
        out.push_back(Trapezoid{x0, x1, lo.at0, lo.at1, hi.at0, hi.at1, area});
    }
}

PolygonSlabs::PolygonSlabs(const PolygonRings& rings) : rings_(rings) {
    const std::size_t n = rings.vertices();
    xs_.reserve(n);
    for (const Point& p : rings.points()) xs_.push_back(p.x);
    std::sort(xs_.begin(), xs_.end());
    xs_.erase(std::unique(xs_.begin(), xs_.end()), xs_.end());
    // Edges that span some slab (vertical ones span none), by their left end.
    std::vector<std::uint32_t> order;
    for (std::uint32_t e = 0; e < n; ++e)
        if (rings.edge_start(e).x != rings.edge_end(e).x) order.push_back(e);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t p, std::uint32_t q) { return low_x(rings, p) < low_x(rings, q); });
    // The sweep: an edge spans slab [x0, x1] exactly when its ends lie at or
    // beyond both (the slabs' ends are the vertices' abscissae).
    std::vector<std::uint32_t> active;
    std::vector<Trapezoid> parts;
    std::size_t next = 0;
    double total = 0.0;
    cumulative_.reserve(xs_.size());
    for (std::size_t i = 0; i + 1 < xs_.size(); ++i) {
        const double x0 = xs_[i], x1 = xs_[i + 1];
        active.erase(
            std::remove_if(active.begin(), active.end(), [&](std::uint32_t e) { return high_x(rings, e) <= x0; }),
            active.end());
        while (next < order.size() && low_x(rings, order[next]) <= x0) active.push_back(order[next++]);
        parts_of(active, x0, x1, parts);
        for (const Trapezoid& t : parts) total += t.area;
        cumulative_.push_back(total);
    }
}

bool PolygonSlabs::draw(Rng& rng, Point* out) const {
    if (!(area() > 0.0)) return false;
    const double target = rng.next_double() * area();
    const std::size_t slab = std::min<std::size_t>(
        cumulative_.size() - 1,
        static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) -
                                 cumulative_.begin()));
    const double x0 = xs_[slab], x1 = xs_[slab + 1];
    std::vector<std::uint32_t> edges;
    for (std::uint32_t e = 0; e < rings_.vertices(); ++e)
        if (rings_.edge_start(e).x != rings_.edge_end(e).x && low_x(rings_, e) <= x0 && high_x(rings_, e) >= x1)
            edges.push_back(e);
    std::vector<Trapezoid> parts;
    parts_of(edges, x0, x1, parts);
    double sum = 0.0;
    for (const Trapezoid& t : parts) sum += t.area;
    if (!(sum > 0.0)) return false;
    // A part by its area, then a point in it.
    const double pick = rng.next_double() * sum;
    const Trapezoid* chosen = &parts.back();
    double running = 0.0;
    for (const Trapezoid& t : parts) {
        running += t.area;
        if (running > pick && t.area > 0.0) {
            chosen = &t;
            break;
        }
    }
    const double u = rng.next_double(), v = rng.next_double();
    *out = point_in_trapezoid(*chosen, u, v);
    return true;
}

}  // namespace pds
