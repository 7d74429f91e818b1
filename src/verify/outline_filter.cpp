// outline_filter.cpp - see outline_filter.hpp.
#include "verify/outline_filter.hpp"

#include <algorithm>
#include <cmath>

#include "core/roundoff.hpp"

namespace pds {

namespace {
constexpr double kEps = kUnitRoundoff;
// A bisector's bound on the edge, widened: it is computed to a few units of
// roundoff of [0, 1], far below this.
constexpr double kParameterSlack = 1e-9;

// Whether segment ab certainly misses the square of half-side w around q:
// their boxes apart, or the square's corners all on one side of the line
// (each side decided with a bound on its rounding).
bool misses_square(const Point& a, const Point& b, const Point& q, double w) {
    if (std::max(a.x, b.x) < q.x - w || std::min(a.x, b.x) > q.x + w || std::max(a.y, b.y) < q.y - w ||
        std::min(a.y, b.y) > q.y + w)
        return true;
    const double dx = b.x - a.x, dy = b.y - a.y;
    int sides = 0;
    for (const double sx : {-w, w})
        for (const double sy : {-w, w}) {
            const double px = q.x + sx - a.x, py = q.y + sy - a.y;
            const double det = dx * py - dy * px;
            const double bound = 16.0 * kEps * (std::fabs(dx * py) + std::fabs(dy * px)) +
                                 4.0 * kEps * (std::fabs(dx) + std::fabs(dy)) * (std::fabs(q.x) + std::fabs(q.y) + w);
            if (det > bound)
                sides |= 1;
            else if (det < -bound)
                sides |= 2;
            else
                return false;
        }
    return sides != 3;
}

}  // namespace

bool OutlineFilter::certainly_within(double px, double py, double e) const {
    // |P| <= |p| + e, |p| <= sqrt(px^2 + py^2) to a few roundoffs; the disk is closed.
    const double reach = std::sqrt(px * px + py * py) * (1.0 + 8.0 * kEps) + e;
    return reach < rc_ * (1.0 - 8.0 * kEps);
}

bool PolygonClearance::certainly_outside(const Point& q, double e) {
    // Wide enough that q.x + w, rounded, still bounds q.x + e (and so on).
    const double w = (e + 8.0 * kEps * (std::fabs(q.x) + std::fabs(q.y))) * (1.0 + 16.0 * kEps);
    const Box& b = polygon_.bounds();
    if (q.x + w < b.x0 || q.x - w > b.x1 || q.y + w < b.y0 || q.y - w > b.y1) return true;
    // The grid cells the error box meets, and one more each way (a point
    // within rounding of a grid line may be placed on either side).
    const PolygonIndex& index = polygon_.index();
    std::size_t c0 = index.column_of(q.x - w), c1 = index.column_of(q.x + w);
    std::size_t r0 = index.row_of(q.y - w), r1 = index.row_of(q.y + w);
    c0 = c0 > 0 ? c0 - 1 : 0;
    r0 = r0 > 0 ? r0 - 1 : 0;
    c1 = std::min(c1 + 1, index.columns() - 1);
    r1 = std::min(r1 + 1, index.rows() - 1);
    if (index.all_cells(c0, c1, r0, r1, PolygonIndex::kOutside)) return true;
    // No edge meets a square around the error disk: the polygon holds all of
    // it or none, as it holds q or not (exactly, q being a double point).
    const double side = 2.0 * w;
    near_.clear();
    index.edges_near(Box{q.x - side, q.y - side, q.x + side, q.y + side}, near_);
    const PolygonRings& rings = polygon_.rings();
    for (const std::uint32_t id : near_)
        if (!misses_square(rings.edge_start(id), rings.edge_end(id), q, side)) return false;
    return !polygon_.contains(q);
}

void OutlineFilter::vertex(const cell_stream::Vtx& v) {
    if (!vertices_certain_ || certainly_within(v.x, v.y, v.err)) return;
    // Beyond the radius, or too close to call: harmless only where the polygon is not.
    const Point q{c_.x + v.x, c_.y + v.y};
    const double e = v.err + 4.0 * kEps * (std::fabs(c_.x) + std::fabs(c_.y) + std::fabs(v.x) + std::fabs(v.y));
    if (!clearance_.certainly_outside(q, e)) vertices_certain_ = false;
}

bool OutlineFilter::edges_certain(const std::vector<Point>& ring, const std::vector<double>& ring_radii,
                                  const std::vector<std::uint32_t>& edges) const {
    const PolygonRings& rings = polygon_.rings();
    for (const std::uint32_t id : edges) {
        const Point a = rings.edge_start(id), b = rings.edge_end(id);
        // The ends relative to the site, each coordinate to one roundoff.
        const double ax = a.x - c_.x, ay = a.y - c_.y, bx = b.x - c_.x, by = b.y - c_.y;
        const double ea = 2.0 * kEps * (std::fabs(ax) + std::fabs(ay));
        const double eb = 2.0 * kEps * (std::fabs(bx) + std::fabs(by));
        if (certainly_within(ax, ay, ea) && certainly_within(bx, by, eb)) continue;
        // The edge a + t (b - a), t in [lo, hi], holds every point of it in
        // the cell: there each power difference f_k <= 0, and f_k is linear
        // in t, computed at the ends to within bound_k.
        double lo = 0.0, hi = 1.0;
        for (std::size_t k = 0; k < ring.size() && lo <= hi; ++k) {
            const double nx = ring[k].x - c_.x, ny = ring[k].y - c_.y;
            const double nn = nx * nx + ny * ny, w = (rc_ - ring_radii[k]) * (rc_ + ring_radii[k]);
            const double fa = 2.0 * (ax * nx + ay * ny) - nn - w;
            const double fb = 2.0 * (bx * nx + by * ny) - nn - w;
            const double size =
                2.0 * (std::fabs(ax * nx) + std::fabs(ay * ny) + std::fabs(bx * nx) + std::fabs(by * ny)) + nn +
                std::fabs(w);
            const double bound = 32.0 * kEps * size + 0x1p-1000;
            const bool a_in = fa <= bound, b_in = fb <= bound;
            if (a_in && b_in) continue;
            if (!a_in && !b_in) {
                lo = 2.0;  // the whole edge is beyond this bisector
                break;
            }
            const double t = (bound - fa) / (fb - fa);  // in [0, 1] up to rounding
            if (a_in)
                hi = std::min(hi, t + kParameterSlack);
            else
                lo = std::max(lo, t - kParameterSlack);
        }
        if (lo > hi) continue;  // the edge misses the cell
        lo = std::max(lo, 0.0);
        hi = std::min(hi, 1.0);
        const double e = ea + eb + 4.0 * kEps * (std::fabs(ax) + std::fabs(ay) + std::fabs(bx) + std::fabs(by));
        for (const double t : {lo, hi})
            if (!certainly_within(ax + t * (bx - ax), ay + t * (by - ay), e)) return false;
    }
    return true;
}

}  // namespace pds
