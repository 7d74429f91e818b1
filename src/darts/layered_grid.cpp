// layered_grid.cpp - a grid per layer of radii (see layered_grid.hpp): the
// layers' layout and the recording of a point.
#include "darts/layered_grid.hpp"

#include <algorithm>
#include <cmath>
#include <new>

namespace pds {

namespace {

// The memory budget's unit: a page, as most systems' ordinary pages.
constexpr std::size_t kPageBytes = 4096;
constexpr std::size_t kCellsPerPage = kPageBytes / sizeof(std::uint64_t);
constexpr std::size_t kIndicesPerPage = kPageBytes / sizeof(std::uint32_t);

// A cell's word: the offsets in steps (bits 0-15, 16-31), the radius as a
// float (32-63).
std::uint64_t cell_word(std::uint64_t sx, std::uint64_t sy, double r) {
    const auto r_float = static_cast<float>(r);
    std::uint32_t bits;
    std::memcpy(&bits, &r_float, sizeof bits);
    return (std::uint64_t{bits} << 32) | (sy << 16) | sx;
}

}  // namespace

LayeredGrid::LayeredGrid(const Box& domain, const PointRadii& radii, const Torus& torus)
    : box_(domain), radii_(radii), torus_(torus) {
    using namespace darts;
    const double rmin = radii.rmin(), rmax = radii.rmax();
    for (double low = rmin;; low *= kLayerRatio) {
        if (layers_.size() == kMaxLayers) throw std::bad_alloc();  // the factory keeps the ratio far below
        Layer L;
        L.low = low;
        L.high = std::min(low * kLayerRatio, rmax);
        L.side = cell_side(low);
        L.inv_side = 1.0 / L.side;
        L.x0 = domain.x0 - kPad * L.side;
        L.y0 = domain.y0 - kPad * L.side;
        L.step = L.side / kOffsetSteps;
        L.reach = L.high * L.inv_side + kReachSlack;
        L.cols = cells_along(domain.width(), L.side);
        L.rows = cells_along(domain.height(), L.side);
        allocate_cells(L);
        layers_.push_back(std::move(L));
        if (low * kLayerRatio >= rmax) break;
    }
    tile_side_ = rmax;
    tile_cols_ = cells_along(domain.width(), tile_side_);
    tile_rows_ = cells_along(domain.height(), tile_side_);
    tiles_.assign(tile_cols_ * tile_rows_, 0);
    const Layer& finest = layers_.front();
    covered_ = CoveredBitmap(box_.x0, box_.y0, finest.side, finest.cols, finest.rows);
    const RadiusField& field = radii.field();
    if (!field.calls_user()) {
        RadiusField::MeanInverseSquare mean;
        while (!mean.done()) mean.step(field, radii.frame().user_domain());
        map_expected_count_ = radii.frame().expected_count(radii.user_radius_of(1.0 / std::sqrt(mean.mean())));
    }
}

double LayeredGrid::expected_count() const {
    if (map_expected_count_ > 0.0) return map_expected_count_;
    const double rms_value = std::sqrt(value_squares_ / static_cast<double>(recorded_));
    return radii_.frame().expected_count(radii_.user_radius_of(rms_value));
}

void LayeredGrid::keep_to(const Polygon& polygon) {
    if (!raster_suits(polygon, box_)) return;
    // Past its budget, no raster: darts over the box.
    const Layer& finest = layers_.front();
    const double side = finest.side;
    if (!raster_.build(polygon, box_.x0, side, finest.cols, box_.y0, side, finest.rows,
                       raster_band_budget(polygon, side * side)))
        raster_ = PolygonRaster();
}

std::size_t LayeredGrid::cell_count() const {
    const Layer& coarsest = layers_.back();
    const std::size_t all = coarsest.cols * coarsest.rows;
    if (raster_.cells() == 0) return all;
    const Layer& finest = layers_.front();
    const double share =
        static_cast<double>(raster_.cells()) / (static_cast<double>(finest.cols) * static_cast<double>(finest.rows));
    return std::max<std::size_t>(1, static_cast<std::size_t>(share * static_cast<double>(all)));
}

void LayeredGrid::allocate_cells(Layer& L) {
    // Bricks of 2^10 cells (8 KiB, two pages): 32 x 32, or flatter for a
    // grid under 32 rows or columns (the shorter side first). Ordinary pages:
    // a layer whose points are scattered over the domain (a fine-grained
    // field) then touches a page or two per point; on 2 MiB pages it would
    // touch whole bricks of 2 MiB, several times the memory, for little
    // speed (docs/performance.md).
    using darts::kPad;
    constexpr int kSquareShift = 5, kBrickShift = 10;
    const std::size_t padded_cols = L.cols + 2 * kPad, padded_rows = L.rows + 2 * kPad;
    const auto shift_for = [](std::size_t cells, int at_most) {
        int s = 0;
        while (s < at_most && (std::size_t{1} << s) < cells) ++s;
        return s;
    };
    if (padded_rows <= padded_cols) {
        L.shift_y = shift_for(padded_rows, kSquareShift);
        L.shift_x = shift_for(padded_cols, kBrickShift - L.shift_y);
    } else {
        L.shift_x = shift_for(padded_cols, kSquareShift);
        L.shift_y = shift_for(padded_rows, kBrickShift - L.shift_x);
    }
    const std::size_t brick_x = std::size_t{1} << L.shift_x, brick_y = std::size_t{1} << L.shift_y;
    L.bricks_x = (padded_cols + brick_x - 1) / brick_x;
    const std::size_t bricks_y = (padded_rows + brick_y - 1) / brick_y;
    if (L.bricks_x > static_cast<std::size_t>(-1) / (brick_x * brick_y * sizeof(Cell)) / bricks_y)
        throw std::bad_alloc();
    const std::size_t total = L.bricks_x * bricks_y * brick_x * brick_y;
    // Zeroed: address space until points land.
    L.cells.reset(static_cast<Cell*>(std::calloc(total, sizeof(Cell))));
    L.index.reset(static_cast<std::uint32_t*>(std::calloc(total, sizeof(std::uint32_t))));
    if (!L.cells || !L.index) throw std::bad_alloc();
    L.cell_pages.assign(total / kCellsPerPage + 1, false);
    L.index_pages.assign(total / kIndicesPerPage + 1, false);
}

std::size_t LayeredGrid::layer_of(double r) const {
    std::size_t k = 0;
    while (k + 1 < layers_.size() && r >= layers_[k + 1].low) ++k;
    return k;
}

void LayeredGrid::touch(Layer& L, std::size_t cell) {
    const auto first_touch = [&](std::vector<bool>& pages, std::size_t page) {
        if (pages[page]) return;
        pages[page] = true;
        touched_bytes_ += kPageBytes;
    };
    first_touch(L.cell_pages, cell / kCellsPerPage);
    first_touch(L.index_pages, cell / kIndicesPerPage);
}

void LayeredGrid::mark_layer_near(const Point& p, std::size_t layer) {
    // A disk reaches at most the largest radius from its centre: into the
    // tiles next to its own, never further.
    const std::size_t t = tile_of(p), x = t % tile_cols_, y = t / tile_cols_;
    for (std::size_t j = y > 0 ? y - 1 : 0; j <= y + 1 && j < tile_rows_; ++j)
        for (std::size_t i = x > 0 ? x - 1 : 0; i <= x + 1 && i < tile_cols_; ++i)
            tiles_[j * tile_cols_ + i] |= std::uint32_t{1} << layer;
}

void LayeredGrid::record(const Dart& d, std::uint32_t index, double value) {
    const Point p = d.p;
    const double r = radii_.radius_of(value);
    const std::size_t k = layer_of(r);
    const Layer& L = layers_[k];
    const Block b = block_of(L, p);
    // The offsets from the corner free_in reads them from.
    const std::uint64_t sx = offset_steps(p.x - L.corner_x(b.x), L.step);
    const std::uint64_t sy = offset_steps(p.y - L.corner_y(b.y), L.step);
    const std::size_t cell = L.at(b.x, b.y);
    L.cells[cell] = cell_word(sx, sy, r);
    L.index[cell] = index;
    touch(layers_[k], cell);
    ++recorded_;
    value_squares_ += value * value;
    mark_layer_near(p, k);
    covered_.cover_disk(p, r);
}

bool LayeredGrid::copies_free(const Point& p, const std::vector<Point>& points,
                              const std::vector<double>& values) const {
    // A point's disk reaches at most the largest radius: a copy farther from
    // the domain meets none (the slack far above the rounding of the bounds).
    const double reach = layers_.back().high * (1.0 + 0x1.0p-20);
    for (int sy = -1; sy <= 1; ++sy)
        for (int sx = -1; sx <= 1; ++sx) {
            if (sx == 0 && sy == 0) continue;
            const Point q = torus_.shifted(p, sx, sy);
            if (q.x < box_.x0 - reach || q.x > box_.x1 + reach || q.y < box_.y0 - reach || q.y > box_.y1 + reach)
                continue;
            // q's own cell is clamped to the grid's edge (its block then
            // reaches into the padding, which is empty): judged by distance.
            for (std::uint32_t m = tiles_[tile_of(q)]; m != 0; m &= m - 1) {
                const Layer& L = layers_[static_cast<std::size_t>(__builtin_ctz(m))];
                if (!free_in<false>(L, block_of(L, q), q, points, values)) return false;
            }
        }
    return true;
}

void LayeredGrid::release() {
    layers_.clear();
    tiles_ = std::vector<std::uint32_t>();
    covered_ = CoveredBitmap();
}

CurveOrder LayeredGrid::curve(const Box& domain) const {
    const Layer& finest = layers_.front();
    return CurveOrder(domain, finest.side, finest.side, finest.cols, finest.rows);
}

}  // namespace pds
