// radius_layers.cpp - see radius_layers.hpp.
#include "verify/radius_layers.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace pds {

namespace {

// Cells a little larger than the class's largest radius, so a pair closer
// than it never lands two cells apart after the cell coordinates are
// rounded (as spatial_hash.cpp).
constexpr double kCellSlack = 1.0 + 0x1.0p-20;
// key() packs a cell's column and row into 32 bits each; capping the cells
// per axis also keeps the rounding of a coordinate over a cell's width
// within the slack.
constexpr double kMaxCellsPerAxis = 1e9;
static_assert(kMaxCellsPerAxis < 4294967296.0, "cell coordinates must fit 32 bits");
// The dense layouts together have at most this many cells per point, plus
// a few (the budget of spatial_hash.cpp's one grid).
constexpr double kDenseCellsPerPoint = 4.0;
constexpr double kDenseSpareCells = 1024.0;

// Cells to a period: whole, each at least the slackened radius wide.
std::int64_t cells_per_period(double period, double radius) {
    const double n = std::floor(period / (radius * kCellSlack));
    return n < 1.0 ? 1 : static_cast<std::int64_t>(n < kMaxCellsPerAxis ? n : kMaxCellsPerAxis);
}

constexpr std::uint32_t kNoLayer = std::numeric_limits<std::uint32_t>::max();

}  // namespace

RadiusLayers::RadiusLayers(const std::vector<Point>& points, std::size_t first, const RadiusOf& radius_of) {
    find_layers(points, first, radius_of);
    for (Layer& L : layers_) {
        const double width = L.x1 - L.x0, height = L.y1 - L.y0;
        const double span = width > height ? width : height;
        L.cell_x = L.largest * kCellSlack;
        if (span / L.cell_x > kMaxCellsPerAxis) L.cell_x = span / kMaxCellsPerAxis;
        L.cell_y = L.cell_x;
        // Every point's floor((v - origin) / cell) is at most the box's far
        // side's (rounding is monotonic), so it lies in [0, cols).
        L.cols = static_cast<std::int64_t>(std::floor(width / L.cell_x)) + 1;
        L.rows = static_cast<std::int64_t>(std::floor(height / L.cell_y)) + 1;
    }
    choose_layouts(points.size() - first);
    index(points, first, radius_of);
}

RadiusLayers::RadiusLayers(const std::vector<Point>& points, std::size_t first, const Torus& t,
                           const RadiusOf& radius_of) {
    find_layers(points, first, radius_of);
    for (Layer& L : layers_) {
        L.x0 = t.x0;
        L.y0 = t.y0;
        L.cols = L.cols_torus = cells_per_period(t.px, L.largest);
        L.rows = L.rows_torus = cells_per_period(t.py, L.largest);
        L.cell_x = t.px / static_cast<double>(L.cols);
        L.cell_y = t.py / static_cast<double>(L.rows);
    }
    choose_layouts(points.size() - first);
    index(points, first, radius_of);
}

void RadiusLayers::choose_layouts(std::size_t points) {
    // The classes whose grids have the fewest cells first: those are the
    // wide radii, whose grids every point below them reads, where a lookup
    // in a hash map would cost the most.
    std::vector<std::size_t> by_cells(layers_.size());
    for (std::size_t k = 0; k < by_cells.size(); ++k) by_cells[k] = k;
    const auto cells = [&](std::size_t k) {
        return static_cast<double>(layers_[k].cols) * static_cast<double>(layers_[k].rows);
    };
    std::stable_sort(by_cells.begin(), by_cells.end(), [&](std::size_t a, std::size_t b) { return cells(a) < cells(b); });
    double budget = kDenseCellsPerPoint * static_cast<double>(points) + kDenseSpareCells;
    for (std::size_t k : by_cells) {
        if (!(cells(k) <= budget)) break;
        budget -= cells(k);
        layers_[k].dense = true;
    }
}

std::size_t RadiusLayers::dense_count() const {
    return static_cast<std::size_t>(std::count_if(layers_.begin(), layers_.end(), [](const Layer& L) { return L.dense; }));
}

std::size_t RadiusLayers::bytes() const {
    std::size_t n = order_.capacity() * sizeof(std::uint32_t) + layer_at_.capacity() * sizeof(std::uint32_t);
    for (const Layer& L : layers_) n += sizeof(Layer) + L.runs.capacity() * sizeof(std::uint32_t) +
             L.cells.slot_count() * 2 * sizeof(std::uint64_t);  // a slot: a 64-bit key, a 32-bit value, padding
    return n;
}

void RadiusLayers::find_layers(const std::vector<Point>& points, std::size_t first, const RadiusOf& radius_of) {
    if (first >= points.size()) return;
    int lo = std::numeric_limits<int>::max(), hi = std::numeric_limits<int>::min();
    for (std::size_t i = first; i < points.size(); ++i) {
        const int e = std::ilogb(radius_of(i));
        lo = std::min(lo, e);
        hi = std::max(hi, e);
    }
    // Exponents of positive finite doubles span about 2100 values: one
    // slot each, then only the classes that hold points are kept.
    lowest_exponent_ = lo;
    std::vector<Layer> by_exponent(static_cast<std::size_t>(hi - lo) + 1);
    for (std::size_t i = first; i < points.size(); ++i) {
        const double r = radius_of(i);
        Layer& L = by_exponent[static_cast<std::size_t>(std::ilogb(r) - lo)];
        const Point& p = points[i];
        if (L.size++ == 0) {
            L.x0 = L.x1 = p.x;
            L.y0 = L.y1 = p.y;
        }
        L.largest = std::max(L.largest, r);
        L.x0 = std::min(L.x0, p.x), L.x1 = std::max(L.x1, p.x);
        L.y0 = std::min(L.y0, p.y), L.y1 = std::max(L.y1, p.y);
    }
    layer_at_.assign(by_exponent.size(), kNoLayer);
    for (std::size_t k = 0; k < by_exponent.size(); ++k) {
        if (by_exponent[k].size == 0) continue;
        by_exponent[k].exponent = lo + static_cast<int>(k);
        layer_at_[k] = static_cast<std::uint32_t>(layers_.size());
        layers_.push_back(std::move(by_exponent[k]));
    }
}

std::size_t RadiusLayers::layer_of(double r) const {
    return layer_at_[static_cast<std::size_t>(std::ilogb(r) - lowest_exponent_)];
}

void RadiusLayers::cell_of(const Layer& L, const Point& p, std::int64_t* x, std::int64_t* y) {
    *x = clamp_cell(std::floor((p.x - L.x0) / L.cell_x), L.cols);
    *y = clamp_cell(std::floor((p.y - L.y0) / L.cell_y), L.rows);
}

void RadiusLayers::index(const std::vector<Point>& points, std::size_t first, const RadiusOf& radius_of) {
    // A counting sort, as spatial_hash.cpp's: each run's size, then its end
    // (runs laid out class after class), then the points from the last back
    // into their slots, which leaves each run's start behind. A hashed class
    // numbers its runs as their cells first appear.
    for (Layer& L : layers_) {
        if (L.dense) {
            L.runs.assign(static_cast<std::size_t>(L.cols * L.rows) + 1, 0);
        } else {
            L.runs.assign(1, 0);
            L.cells.reserve(L.size);
        }
    }
    const auto run_of = [&](std::size_t i, bool add) -> std::pair<Layer*, std::uint32_t> {
        Layer& L = layers_[layer_of(radius_of(i))];
        std::int64_t x, y;
        cell_of(L, points[i], &x, &y);
        if (L.dense) return {&L, static_cast<std::uint32_t>(y * L.cols + x)};
        const std::uint64_t k = key(x, y);
        const std::uint32_t* found = L.cells.find(k);
        if (found) return {&L, *found};
        // Only the first pass meets new cells.
        const std::uint32_t fresh = static_cast<std::uint32_t>(L.runs.size() - 1);
        if (add) {
            L.cells.insert_or_assign(k, fresh);
            L.runs.push_back(0);
        }
        return {&L, fresh};
    };
    for (std::size_t i = first; i < points.size(); ++i) {
        const auto run = run_of(i, true);
        ++run.first->runs[run.second];
    }
    std::uint32_t end = 0;
    for (Layer& L : layers_) {
        for (std::uint32_t& r : L.runs) r = end += r;
    }
    order_.resize(points.size() - first);
    for (std::size_t i = points.size(); i-- > first;) {
        const auto run = run_of(i, false);
        order_[--run.first->runs[run.second]] = static_cast<std::uint32_t>(i);
    }
}

}  // namespace pds
