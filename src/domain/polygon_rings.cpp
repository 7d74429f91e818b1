// polygon_rings.cpp - see polygon_rings.hpp.
#include "domain/polygon_rings.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"

namespace pds {

namespace {

std::string where(std::size_t ring, std::size_t vertex) {
    return "ring " + std::to_string(ring) + " vertex " + std::to_string(vertex);
}

bool same(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }

// Whether the ring's vertices [begin, end) enclose something: three of them
// are not on one line (exact).
bool encloses(const std::vector<Point>& p, std::size_t begin, std::size_t end) {
    const Point a = p[begin];
    const Point b = p[begin + 1];  // differs from a: duplicates are gone
    for (std::size_t i = begin + 2; i < end; ++i)
        if (orient2d(a, b, p[i]) != 0) return true;
    return false;
}

}  // namespace

namespace {

// Whether the ring turns straight back at b: a, b, c on one line and c
// behind b. Such a vertex is the tip of a spike of zero width, which holds
// no area and no point a sampler could draw.
bool turns_back(const Point& a, const Point& b, const Point& c) {
    return orient2d(a, b, c) == 0 && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0.0;
}

// Drops the tips of zero-width spikes from the ring pts[first..] (and the
// repeated vertex a spike that comes straight back leaves), until none is
// left, around the ring's closing vertex too.
void drop_spikes(std::vector<Point>& pts, std::size_t first) {
    std::vector<Point> kept;
    kept.reserve(pts.size() - first);
    for (std::size_t i = first; i < pts.size(); ++i) {
        kept.push_back(pts[i]);
        for (;;) {
            const std::size_t n = kept.size();
            if (n >= 2 && kept[n - 1].x == kept[n - 2].x && kept[n - 1].y == kept[n - 2].y) {
                kept.pop_back();
                continue;
            }
            if (n >= 3 && turns_back(kept[n - 3], kept[n - 2], kept[n - 1])) {
                kept.erase(kept.end() - 2);
                continue;
            }
            break;
        }
    }
    // Around the closing vertex: the last and the first.
    for (bool changed = true; changed && kept.size() >= 3;) {
        changed = false;
        const std::size_t n = kept.size();
        if (kept[n - 1].x == kept[0].x && kept[n - 1].y == kept[0].y) {
            kept.pop_back();
            changed = true;
        } else if (turns_back(kept[n - 2], kept[n - 1], kept[0])) {
            kept.pop_back();
            changed = true;
        } else if (turns_back(kept[n - 1], kept[0], kept[1])) {
            kept.erase(kept.begin());
            changed = true;
        }
    }
    pts.resize(first);
    pts.insert(pts.end(), kept.begin(), kept.end());
}

}  // namespace

PolygonRings::PolygonRings(const double* xy, const std::size_t* ring_ends, std::size_t rings) {
    if (rings == 0) throw DomainError("the outline has no rings");
    if (!xy || !ring_ends) throw DomainError("the outline's coordinates or ring ends are NULL");
    for (std::size_t k = 0, start = 0; k < rings; start = ring_ends[k++])
        if (ring_ends[k] < start)
            throw DomainError("ring " + std::to_string(k) + ": its end " + std::to_string(ring_ends[k]) +
                              " is before its start " + std::to_string(start) + " (ring ends never decrease)");
    const std::size_t given = ring_ends[rings - 1];
    if (given > kMaxVertices) throw DomainError("the outline has more than 2^28 vertices");
    points_.reserve(given);
    next_.reserve(given);
    ring_begin_.reserve(rings + 1);
    std::size_t start = 0;
    for (std::size_t k = 0; k < rings; ++k) {
        const std::size_t end = ring_ends[k];
        const std::size_t first = points_.size();
        ring_begin_.push_back(first);
        for (std::size_t v = start; v < end; ++v) {
            const Point q{xy[2 * v], xy[2 * v + 1]};
            if (!std::isfinite(q.x) || !std::isfinite(q.y))
                throw DomainError(where(k, v - start) + ": a coordinate is not finite");
            if (points_.size() > first && same(points_.back(), q)) continue;
            points_.push_back(q);
        }
        while (points_.size() > first + 1 && same(points_.back(), points_[first])) points_.pop_back();
        const std::size_t distinct = points_.size() - first;
        if (distinct < 3)
            throw DomainError("ring " + std::to_string(k) + ": " + std::to_string(distinct) +
                              " distinct vertices (" + std::to_string(end - start) + " given); a ring needs 3");
        if (!encloses(points_, first, points_.size()))
            throw DomainError("ring " + std::to_string(k) + ": its vertices lie on one line, it encloses nothing");
        drop_spikes(points_, first);
        if (points_.size() - first < 3 || !encloses(points_, first, points_.size()))
            throw DomainError("ring " + std::to_string(k) + ": it folds back onto itself and encloses nothing");
        for (std::size_t i = first; i + 1 < points_.size(); ++i) next_.push_back(static_cast<std::uint32_t>(i + 1));
        next_.push_back(static_cast<std::uint32_t>(first));
        start = end;
    }
    ring_begin_.push_back(points_.size());
    bounds_ = Box{points_[0].x, points_[0].y, points_[0].x, points_[0].y};
    for (const Point& q : points_) {
        bounds_.x0 = std::min(bounds_.x0, q.x);
        bounds_.y0 = std::min(bounds_.y0, q.y);
        bounds_.x1 = std::max(bounds_.x1, q.x);
        bounds_.y1 = std::max(bounds_.y1, q.y);
    }
}

double PolygonRings::perimeter() const {
    double sum = 0.0;
    for (std::size_t i = 0; i < points_.size(); ++i) {
        const Point a = edge_start(i), b = edge_end(i);
        sum += std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    }
    return sum;
}

}  // namespace pds
