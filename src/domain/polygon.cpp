// polygon.cpp - see polygon.hpp.
#include "domain/polygon.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/predicates.hpp"
#include "domain/polygon_slabs.hpp"
#include "domain/polygon_splits.hpp"

namespace pds {

namespace {

// The side of edge i the inside lies on: +1 left, -1 right, 0 when the
// probes do not tell (both alike: the edge is cancelled by another, or
// edges crowd it closer than every offset tried).
//
// The probes sit on the normal through the edge's midpoint, at offsets from
// about 2^-48 of the coordinates (some 16-32 ulps: clear of rounding, and
// below any feature a radius above the precision limit can resolve) up by
// factors of 16 to 2^-20 of the edge's length. The first offset at which the
// two probes differ decides. Starting small matters where edges crowd one
// another closer than 2^-20 of their length (a mask of pixels far taller
// than wide): a probe that jumps over a neighbouring edge reads the wrong
// place, and an offset below rounding reads the edge itself. Each probe is
// checked exactly to lie strictly on its side of the edge.
int edge_side(const PolygonRings& rings, const PolygonIndex& index, std::size_t i) {
    const Point a = rings.edge_start(i), b = rings.edge_end(i);
    const Point m{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
    if (!(length > 0.0)) return 0;
    const double scale =
        std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y), length});
    const double largest = std::max(0x1p-20 * length, 0x1p-48 * scale);
    // From the least positive double at least: 2^-48 of a subnormal scale
    // rounds to 0, which growing by 16 would never leave.
    for (double offset = std::max(0x1p-48 * scale, std::numeric_limits<double>::denorm_min());; offset *= 16.0) {
        const bool last = offset >= largest;
        if (last) offset = largest;
        const double f = offset / length;
        const Point left{m.x - dy * f, m.y + dx * f}, right{m.x + dy * f, m.y - dx * f};
        if (orient2d(a, b, left) > 0 && orient2d(a, b, right) < 0) {
            const PolygonIndex::Place l = index.locate(left), r = index.locate(right);
            if (l == PolygonIndex::kInside && r == PolygonIndex::kOutside) return 1;
            if (l == PolygonIndex::kOutside && r == PolygonIndex::kInside) return -1;
        }
        if (last) return 0;
    }
}

// Edge i's term of the shoelace area, about the centre of the bounding box
// (one origin for every edge: with sides that vary along a ring, only the
// whole boundary is a closed curve), positive for a counterclockwise turn.
double edge_area(const PolygonRings& rings, std::size_t i) {
    const Box& box = rings.bounds();
    const Point o{0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
    const Point a = rings.edge_start(i), b = rings.edge_end(i);
    return 0.5 * ((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x));
}

// Which edges are copies of one segment (the same two ends, either way)
// that cancel in pairs by the even-odd rule: of k copies, all when k is even,
// all but the first when k is odd (a ring traced twice, or traced again
// along another ring's edge).
std::vector<std::uint8_t> paired_copies(const PolygonRings& rings) {
    const auto key = [&](std::size_t i) {
        Point a = rings.edge_start(i), b = rings.edge_end(i);
        if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
        return std::array<double, 4>{a.x, a.y, b.x, b.y};
    };
    std::vector<std::uint32_t> order(rings.vertices());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return key(i) < key(j); });
    std::vector<std::uint8_t> paired(rings.vertices(), 0);
    for (std::size_t from = 0; from < order.size();) {
        std::size_t to = from + 1;
        while (to < order.size() && key(order[to]) == key(order[from])) ++to;
        for (std::size_t c = (to - from) % 2; c < to - from; ++c) paired[order[from + c]] = 1;
        from = to;
    }
    return paired;
}

}  // namespace

Polygon::Polygon(const double* xy, const std::size_t* ring_ends, std::size_t rings)
    : rings_(std::make_unique<PolygonRings>(xy, ring_ends, rings)), index_(std::make_unique<PolygonIndex>(*rings_)) {
    // Edges that cross are split where they cross, edges that overlap in
    // part where they meet, and vertices of different rings within rounding
    // of each other merged (polygon_splits.hpp). Where three edges or more
    // cross within rounding of one point, a rounded crossing can make
    // another crossing, or land on a third edge: so again, until nothing is
    // split (of 20,000 random clusters of 3 to 6 edges through one point
    // within 1e-15, a third still crossed after one round, and none needed
    // more than 15; crossings still left after kSplitRounds stay as they are).
    constexpr int kSplitRounds = 16;
    std::vector<double> split_xy;
    std::vector<std::size_t> split_ends;
    for (int round = 0; round < kSplitRounds; ++round) {
        bool split = false;
        for (const auto how : {split_at_crossings, merge_or_split_at_vertices}) {
            if (!how(*rings_, *index_, split_xy, split_ends)) continue;
            rings_ = std::make_unique<PolygonRings>(split_xy.data(), split_ends.data(), split_ends.size());
            index_ = std::make_unique<PolygonIndex>(*rings_);
            split = true;
        }
        if (!split) break;
    }
    perimeter_ = rings_->perimeter();
    // Each edge's side, probed: the region's boundary, oriented with the
    // inside on its left, is then known edge by edge, even where rings
    // cross (a bow tie's two lobes run opposite ways), and the even-odd area
    // is its boundary integral. An edge the probes cannot tell takes its
    // ring's side (the majority of its told edges).
    // Copies of one segment cancel in pairs first: they take no side.
    inside_left_.resize(rings_->vertices());
    const std::vector<std::uint8_t> paired = paired_copies(*rings_);
    std::vector<int> side(rings_->vertices());
    bool any_side = false;
    for (std::size_t k = 0; k < rings_->rings(); ++k) {
        int votes = 0;
        for (std::size_t i = rings_->ring_begin(k); i < rings_->ring_begin(k + 1); ++i) {
            side[i] = paired[i] ? 0 : edge_side(*rings_, *index_, i);
            votes += side[i];
        }
        for (std::size_t i = rings_->ring_begin(k); i < rings_->ring_begin(k + 1); ++i) {
            if (side[i] == 0 && !paired[i]) side[i] = votes > 0 ? 1 : (votes < 0 ? -1 : 0);
            any_side = any_side || side[i] != 0;
            inside_left_[i] = side[i] >= 0;
            if (side[i] == 0) index_->mark_cancelled(i);
            area_ += side[i] * edge_area(*rings_, i);
        }
    }
    if (!any_side || !(area_ > 0.0)) throw DomainError("the outline encloses nothing by the even-odd rule");
    if (const double finer = index_->finer_cells_for_location(); finer > 0.0) {
        locator_ = std::make_unique<PolygonIndex>(*rings_, finer);
        for (std::size_t i = 0; i < rings_->vertices(); ++i)
            if (index_->cancelled(i)) locator_->mark_cancelled(i);
    }
    for (std::size_t r = 0; r < index_->rows(); ++r)
        for (std::size_t c = 0; c < index_->columns(); ++c)
            if (index_->cell_place(c, r) != PolygonIndex::kOutside) candidate_cells_.push_back(r * index_->columns() + c);
}

void Polygon::outline_edges_near(const Box& b, std::vector<std::uint32_t>& out) const {
    index_->edges_near(b, out);
    out.erase(std::remove_if(out.begin(), out.end(), [&](std::uint32_t e) { return index_->cancelled(e); }), out.end());
}

double Polygon::count_bound(double r) const {
    const double rho = 0.5 * r;
    const double disk = M_PI * rho * rho;
    const double reach = area_ + 2.0 * rho * perimeter_ + static_cast<double>(rings_->vertices()) * disk;
    return reach / disk * (1.0 + 1e-9) + 1.0;  // the margin covers the rounding of the sums
}

double Polygon::candidate_area() const {
    const Box& b = bounds();
    return static_cast<double>(candidate_cells_.size()) * (b.width() / static_cast<double>(index_->columns())) *
           (b.height() / static_cast<double>(index_->rows()));
}

Point Polygon::uniform_point(Rng& rng) const {
    const Box& b = bounds();
    const double cell_w = b.width() / static_cast<double>(index_->columns());
    const double cell_h = b.height() / static_cast<double>(index_->rows());
    const double n = static_cast<double>(candidate_cells_.size());
    const auto candidate = [&] {
        const auto pick = std::min(candidate_cells_.size() - 1, static_cast<std::size_t>(rng.next_double() * n));
        const std::size_t cell = candidate_cells_[pick];
        const double col = static_cast<double>(cell % index_->columns());
        const double row = static_cast<double>(cell / index_->columns());
        return Point{b.x0 + (col + rng.next_double()) * cell_w, b.y0 + (row + rng.next_double()) * cell_h};
    };
    // 64 times the expected tries (a failure once in e^64), from 256 up to
    // 2^16; past them the polygon is far thinner than the cells, and its
    // slabs give the point (a mixture of uniform draws is uniform). Slabs
    // without area (none seen) leave it to the cells.
    const double expected = candidate_area() / area_;
    const double budget = std::min(65536.0, std::max(256.0, 64.0 * expected));
    for (double tries = 0.0; tries < budget; tries += 1.0) {
        const Point p = candidate();
        if (contains(p)) return p;
    }
    const PolygonSlabs slabs(*rings_);
    const bool by_slabs = slabs.area() > 0.0;
    for (Point p;;)
        if (by_slabs ? slabs.draw(rng, &p) && contains(p) : contains(p = candidate())) return p;
}

Magnitudes magnitudes(const double* c, std::size_t n) {
    Magnitudes m{0.0, HUGE_VAL};
    for (std::size_t i = 0; i < n; ++i) {
        const double a = std::fabs(c[i]);
        if (!std::isfinite(a) || a == 0.0) continue;
        m.largest = std::max(m.largest, a);
        m.smallest = std::min(m.smallest, a);
    }
    return m;
}

int reading_exponent(const double* c, std::size_t n) {
    const auto [hi, lo] = magnitudes(c, n);
    if (hi == 0.0 || (hi <= 0x1p500 && hi >= 0x1p-500)) return 0;
    // The exponent of the largest brings it near 1; a smaller one is enough
    // (the largest at most 2^500) and keeps the smallest a normal number,
    // so that each scales exactly (-2^1023 beside 0.25: 2^1020).
    const int e = std::ilogb(hi);
    const int k = std::min(e, std::ilogb(lo) + 1022);
    if (k < e - 500) {
        char what[160];
        std::snprintf(what, sizeof what,
                      "its coordinates' magnitudes run from %.3g to %.3g, a span no one scale reads exactly", lo, hi);
        throw DomainError(what);
    }
    return k;
}

Polygon Polygon::scaled(int k) const {
    std::vector<double> xy;
    xy.reserve(2 * rings_->vertices());
    for (const Point& p : rings_->points()) {
        xy.push_back(std::ldexp(p.x, k));
        xy.push_back(std::ldexp(p.y, k));
    }
    std::vector<std::size_t> ends;
    for (std::size_t r = 0; r < rings_->rings(); ++r) ends.push_back(rings_->ring_begin(r + 1));
    return Polygon(xy.data(), ends.data(), ends.size());
}

}  // namespace pds
