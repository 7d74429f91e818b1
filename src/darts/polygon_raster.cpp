// polygon_raster.cpp - a polygon's cells on a dart grid, row by row (see
// polygon_raster.hpp).
#include "darts/polygon_raster.hpp"

#include <algorithm>
#include <cmath>

namespace pds {

bool raster_suits(const Polygon& polygon, const Box& box) {
    // An infinite box area (a box wider than DBL_MAX squared) also suits.
    return 32.0 * polygon.area() < box.width() * box.height();
}

std::size_t raster_band_budget(const Polygon& polygon, double cell_area) {
    return static_cast<std::size_t>(std::min(4194304.0, 1048576.0 + 4.0 * polygon.area() / cell_area));
}

namespace {

// Where x or y falls on the grid, clamped to it (rounding and the box's
// edges may put a coordinate a hair outside).
std::size_t clamped_index(double offset, double side, std::size_t count) {
    const double f = std::floor(offset / side);
    if (!(f > 0.0)) return 0;
    if (f >= static_cast<double>(count - 1)) return count - 1;
    return static_cast<std::size_t>(f);
}

// x on the segment from a to b (a.y < b.y) at height y, inside the
// segment's x-range whatever the rounding.
double x_at(const Point& a, const Point& b, double y) {
    if (y <= a.y) return a.x;
    if (y >= b.y) return b.x;
    const double x = a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
    return std::min(std::max(x, std::min(a.x, b.x)), std::max(a.x, b.x));
}

struct Crossing {
    std::size_t row;
    double x;
    bool operator<(const Crossing& o) const { return row != o.row ? row < o.row : x < o.x; }
};

}  // namespace

// Sorts runs by row and column and joins those that overlap or touch.
std::vector<PolygonRaster::Run> PolygonRaster::joined(std::vector<Run> runs) {
    std::sort(runs.begin(), runs.end(),
              [](const Run& p, const Run& q) { return p.row != q.row ? p.row < q.row : p.lo < q.lo; });
    std::vector<Run> out;
    for (const Run& r : runs) {
        if (!out.empty() && out.back().row == r.row && r.lo <= out.back().hi + 1) {
            out.back().hi = std::max(out.back().hi, r.hi);
        } else {
            out.push_back(r);
        }
    }
    return out;
}

// The cells of the spans that no near-edge run holds (both joined).
std::vector<PolygonRaster::Run> PolygonRaster::inside_of(const std::vector<Run>& spans,
                                                         const std::vector<Run>& near_edges) {
    std::vector<Run> out;
    std::size_t p = 0;
    for (const Run& span : spans) {
        while (p < near_edges.size() &&
               (near_edges[p].row < span.row || (near_edges[p].row == span.row && near_edges[p].hi < span.lo)))
            ++p;
        std::size_t from = span.lo;
        for (std::size_t q = p; q < near_edges.size() && near_edges[q].row == span.row && near_edges[q].lo <= span.hi;
             ++q) {
            if (near_edges[q].lo > from) out.push_back(Run{span.row, from, near_edges[q].lo - 1, true});
            from = std::max(from, near_edges[q].hi + 1);
        }
        if (from <= span.hi) out.push_back(Run{span.row, from, span.hi, true});
    }
    return out;
}

bool PolygonRaster::index_runs() {
    before_.reserve(runs_.size() + 1);
    before_.push_back(0);
    for (const Run& r : runs_) before_.push_back(before_.back() + (r.hi - r.lo + 1));
    // About one run a bucket: a cell's run is found in a step or two.
    const std::size_t total = cells();
    if (total == 0) return false;
    step_ = (total + runs_.size() - 1) / runs_.size();
    bucket_.resize((total + step_ - 1) / step_);
    std::size_t i = 0;
    for (std::size_t j = 0; j < bucket_.size(); ++j) {
        while (before_[i + 1] <= j * step_) ++i;
        bucket_[j] = i;
    }
    return true;
}

bool PolygonRaster::build(const Polygon& polygon, double x0, double sx, std::size_t cols, double y0, double sy,
                          std::size_t rows, std::size_t max_bands) {
    runs_.clear();
    before_.clear();
    bucket_.clear();
    step_ = 1;
    x0_ = x0, sx_ = sx, y0_ = y0, sy_ = sy;
    if (cols == 0 || rows == 0) return false;
    const PolygonRings& rings = polygon.rings();
    const std::size_t n = rings.vertices();
    const auto row_of = [&](double y) { return clamped_index(y - y0, sy, rows); };
    const auto col_of = [&](double x) { return clamped_index(x - x0, sx, cols); };
    // Each edge is taken in the bands it meets and one more on either side
    // (a coordinate rounded across a band's edge): count them first.
    std::size_t bands = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Point a = rings.edge_start(i), b = rings.edge_end(i);
        const std::size_t r0 = row_of(std::min(a.y, b.y)), r1 = row_of(std::max(a.y, b.y));
        bands += r1 - r0 + 3;
        if (bands > max_bands) return false;
    }
    std::vector<Run> near_edges, spans;
    std::vector<Crossing> crossings;
    near_edges.reserve(bands);
    crossings.reserve(bands);
    for (std::size_t i = 0; i < n; ++i) {
        Point a = rings.edge_start(i), b = rings.edge_end(i);
        if (b.y < a.y) std::swap(a, b);
        const std::size_t r0 = row_of(a.y), r1 = row_of(b.y);
        const std::size_t first = r0 > 0 ? r0 - 1 : 0, last = std::min(r1 + 1, rows - 1);
        for (std::size_t r = first; r <= last; ++r) {
            // The edge's x-extent within the band (an end's x outside it),
            // one cell wider on each side.
            const double band_lo = y0 + static_cast<double>(r) * sy;
            const double band_hi = y0 + static_cast<double>(r + 1) * sy;
            const double xa = a.y == b.y ? a.x : x_at(a, b, band_lo), xb = a.y == b.y ? b.x : x_at(a, b, band_hi);
            const std::size_t lo = col_of(std::min(xa, xb)), hi = col_of(std::max(xa, xb));
            near_edges.push_back(Run{r, lo > 0 ? lo - 1 : 0, std::min(hi + 1, cols - 1), false});
            // Its crossing of the band's middle line, by the half-open rule
            // of ray casting (a horizontal edge never crosses).
            const double mid = y0 + (static_cast<double>(r) + 0.5) * sy;
            if (a.y <= mid && mid < b.y) crossings.push_back(Crossing{r, x_at(a, b, mid)});
        }
    }
    // Between the 2i-th and (2i+1)-th crossings of a middle line: inside.
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t i = 0; i < crossings.size();) {
        std::size_t j = i;
        while (j < crossings.size() && crossings[j].row == crossings[i].row) ++j;
        if ((j - i) % 2 != 0) return false;  // closed rings cross evenly; never seen
        for (std::size_t k = i; k < j; k += 2)
            spans.push_back(Run{crossings[i].row, col_of(crossings[k].x), col_of(crossings[k + 1].x), true});
        i = j;
    }
    near_edges = joined(std::move(near_edges));
    spans = joined(std::move(spans));
    // The runs: the cells near edges, and the spans' other cells (inside).
    const std::vector<Run> inside = inside_of(spans, near_edges);
    runs_ = std::move(near_edges);
    runs_.insert(runs_.end(), inside.begin(), inside.end());
    std::sort(runs_.begin(), runs_.end(),
              [](const Run& u, const Run& v) { return u.row != v.row ? u.row < v.row : u.lo < v.lo; });
    return index_runs();
}

}  // namespace pds
