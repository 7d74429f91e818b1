// field_dart_stage.cpp - darts on a grid per layer of radii (see
// field_dart_stage.hpp).
#include "darts/field_dart_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include "darts/grid_cells.hpp"
#include "jones/jones_stage.hpp"
#include "core/predicates.hpp"

namespace pds {

namespace {

// A cell's word: the offsets in steps (bits 0-15, 16-31), the radius as a
// float (32-63).
std::uint64_t cell_word(std::uint64_t sx, std::uint64_t sy, double r) {
    const auto r_float = static_cast<float>(r);
    std::uint32_t bits;
    std::memcpy(&bits, &r_float, sizeof bits);
    return (std::uint64_t{bits} << 32) | (sy << 16) | sx;
}

double radius_in(std::uint64_t word) {
    const auto bits = static_cast<std::uint32_t>(word >> 32);
    float r;
    std::memcpy(&r, &bits, sizeof r);
    return static_cast<double>(r);
}

}  // namespace

FieldDartStage::FieldDartStage(const Box& domain, const PointRadii& radii)
    : box_(domain), radii_(radii) {
    const double rmin = radii.rmin(), rmax = radii.rmax();
    // Slack far above the rounding of a cell coordinate (as dart_stage.cpp).
    constexpr double kReachSlack = 1e-6;
    for (double low = rmin;; low *= kLayerRatio) {
        if (layers_.size() == kMaxLayers) throw std::bad_alloc();  // the sampler keeps the ratio far below
        Layer L;
        L.low = low;
        L.high = std::min(low * kLayerRatio, rmax);
        L.side = kCellShrink * low / std::sqrt(2.0);
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
    // The window as the one-radius stage's, counted in the coarsest layer's
    // cells: a small fraction of the points.
    const Layer& top = layers_.back();
    queue_.set_rule(std::max<std::size_t>(kMinWindow, top.cols * top.rows / 16), kMinAcceptance);
    const Layer& finest = layers_.front();
    curve_ = CurveOrder(box_, finest.side, finest.side, finest.cols, finest.rows);
    covered_ = CoveredCells(box_.x0, box_.y0, finest.side, finest.cols, finest.rows);
}

void FieldDartStage::allocate_cells(Layer& L) {
    // Bricks of 2^10 cells (8 KiB, two pages): 32 x 32, or flatter for a
    // grid under 32 rows or columns (the shorter side first). Ordinary pages:
    // a layer whose points are scattered over the domain (a fine-grained
    // field) then touches a page or two per point; on 2 MiB pages it would
    // touch whole bricks of 2 MiB (on a 1 x 1000 domain with the field along
    // its width, 745 MB at 200,000 points instead of 231), for a dart stage
    // 2% faster at 10^7 points (none at 10^6).
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
}

void FieldDartStage::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its vector as it was.
    points_.reserve(points);
    values_.reserve(points);
    curve_.reserve(points);
}

std::size_t FieldDartStage::layer_of(double r) const {
    std::size_t k = 0;
    while (k + 1 < layers_.size() && r >= layers_[k + 1].low) ++k;
    return k;
}

std::size_t FieldDartStage::tile_of(const Point& p) const {
    const std::size_t x = clamped_cell((p.x - box_.x0) / tile_side_, tile_cols_);
    const std::size_t y = clamped_cell((p.y - box_.y0) / tile_side_, tile_rows_);
    return y * tile_cols_ + x;
}

void FieldDartStage::mark_layer_near(const Point& p, std::size_t layer) {
    // A disk reaches at most the largest radius from its centre: into the
    // tiles next to its own, never further.
    const std::size_t t = tile_of(p), x = t % tile_cols_, y = t / tile_cols_;
    for (std::size_t j = y > 0 ? y - 1 : 0; j <= y + 1 && j < tile_rows_; ++j)
        for (std::size_t i = x > 0 ? x - 1 : 0; i <= x + 1 && i < tile_cols_; ++i)
            tiles_[j * tile_cols_ + i] |= std::uint32_t{1} << layer;
}

FieldDartStage::Block FieldDartStage::block_of(const Layer& L, const Point& p) const {
    const double fx = (p.x - box_.x0) * L.inv_side, fy = (p.y - box_.y0) * L.inv_side;
    const auto col = static_cast<std::int64_t>(clamped_cell(fx, L.cols));
    const auto row = static_cast<std::int64_t>(clamped_cell(fy, L.rows));
    Block b;
    b.x = static_cast<std::size_t>(col + kPad);
    b.y = static_cast<std::size_t>(row + kPad);
    b.x_lo = block_offset(fx - L.reach, col, kPad);
    b.x_hi = block_offset(fx + L.reach, col, kPad);
    b.y_lo = block_offset(fy - L.reach, row, kPad);
    b.y_hi = block_offset(fy + L.reach, row, kPad);
    return b;
}

bool FieldDartStage::free_in(const Layer& L, const Block& b, const Point& p) const {
    // A taken cell is covered whole: its point's radius is over its diagonal.
    if (L.cells[L.at(b.x, b.y)] != 0) return false;
    // Whether the point in the cell i rows and j columns from the dart's (if
    // there is one) lies within its radius.
    const auto covers = [&](int i, int j) {
        const std::size_t x = b.x + static_cast<std::size_t>(j), y = b.y + static_cast<std::size_t>(i);
        const std::size_t cell = L.at(x, y);
        const Cell word = L.cells[cell];
        if (word == 0) return false;
        const double qx = L.corner_x(x) + (static_cast<double>(word & 0xFFFF) + 0.5) * L.step;
        const double qy = L.corner_y(y) + (static_cast<double>((word >> 16) & 0xFFFF) + 0.5) * L.step;
        const double dx = qx - p.x, dy = qy - p.y, r = radius_in(word);
        const double d2 = dx * dx + dy * dy, r2 = r * r;
        if (d2 < r2 * (1.0 - kFilterSlack)) return true;
        if (!(d2 < r2 * (1.0 + kFilterSlack))) return false;
        // The float radius is within 2^-24 of the point's: far inside the slack.
        ++exact_checks_;
        const std::uint32_t k = L.index[cell];
        return compare_distance(p, points_[k], radii_.radius_of(values_[k])) < 0;
    };
    // A layer's radii span over one cell, so the block holds the eight
    // around the dart's own cell (grid_cells.hpp reads those first).
    return !block_covers(b.x_lo, b.x_hi, b.y_lo, b.y_hi, covers);
}

bool FieldDartStage::is_free(const Dart& d) const {
    if (covered_.covered(d.cover_cell)) return false;
    // The layers near as they are now: points added since the dart was
    // drawn may have brought new ones.
    for (std::uint32_t m = tiles_[d.tile]; m != 0; m &= m - 1) {
        const auto k = static_cast<std::size_t>(__builtin_ctz(m));
        const Layer& L = layers_[k];
        if (!free_in(L, k == d.block_layer ? d.block : block_of(L, d.p), d.p)) return false;
    }
    return true;
}

void FieldDartStage::draw_batch(Dart* batch, std::size_t n, Rng& rng) {
    const Layer& finest = layers_.front();
    const double w = static_cast<double>(finest.cols) * finest.side, h = static_cast<double>(finest.rows) * finest.side;
    // First the darts, their tiles and bitmap words (megabytes at 10^7
    // points: misses too); then the blocks of those still in doubt.
    for (std::size_t at = 0; at < n; ++at) {
        Dart& d = batch[at];
        d.p.x = box_.x0 + rng.next_double() * w;
        d.p.y = box_.y0 + rng.next_double() * h;
        d.tile = tile_of(d.p);
        d.cover_cell = covered_.cell_of(d.p);
        __builtin_prefetch(&tiles_[d.tile]);
        covered_.prefetch(d.cover_cell);
    }
    for (std::size_t at = 0; at < n; ++at) {
        Dart& d = batch[at];
        d.block_layer = kMaxLayers;
        if (covered_.covered(d.cover_cell)) continue;  // no block to read
        // Each near layer's block: 4 or 5 rows of at most 40 bytes. The first
        // layer's is kept (most darts have one).
        for (std::uint32_t m = tiles_[d.tile]; m != 0; m &= m - 1) {
            const auto k = static_cast<std::size_t>(__builtin_ctz(m));
            const Layer& L = layers_[k];
            const Block b = block_of(L, d.p);
            if (d.block_layer == kMaxLayers) {
                d.block = b;
                d.block_layer = k;
            }
            for (int i = b.y_lo; i <= b.y_hi; ++i) {
                const std::size_t y = b.y + static_cast<std::size_t>(i);
                __builtin_prefetch(L.cells.get() + L.at(b.x + static_cast<std::size_t>(b.x_lo), y));
                __builtin_prefetch(L.cells.get() + L.at(b.x + static_cast<std::size_t>(b.x_hi), y));
            }
        }
    }
}

const Point* FieldDartStage::next(Rng& rng) {
    const Dart* d = queue_.next([&](const Dart& x) { return box_.contains(x.p); },
                                [&](Dart* batch, std::size_t n) { draw_batch(batch, n, rng); },
                                [&](const Dart& x) { return is_free(x); });
    return d ? &d->p : nullptr;
}

void FieldDartStage::add_next() {
    const Point p = queue_.pending().p;
    const double value = radii_.value_at(p);  // may throw FieldError: nothing changed yet
    const double r = radii_.radius_of(value);
    const std::size_t k = layer_of(r);
    const Layer& L = layers_[k];
    const Block b = block_of(L, p);
    // The offsets from the corner free_in reads them from.
    const std::uint64_t sx = offset_steps(p.x - L.corner_x(b.x), L.step);
    const std::uint64_t sy = offset_steps(p.y - L.corner_y(b.y), L.step);
    const std::size_t cell = L.at(b.x, b.y);
    L.cells[cell] = cell_word(sx, sy, r);
    L.index[cell] = static_cast<std::uint32_t>(points_.size());
    mark_layer_near(p, k);
    covered_.cover_disk(p, r);
    points_.push_back(p);
    values_.push_back(value);
    queue_.take();
}

void FieldDartStage::hand_over_to(JonesStage& jones, const Poll& poll) {
    // The grids go before the mesh is filled, so the two never peak together.
    layers_.clear();
    queue_.end();
    const std::uint32_t* order = curve_.order(points_);
    poll();
    jones.adopt(points_, order, &values_, poll);
}

std::unique_ptr<JonesStage> FieldDartStage::jones_of_points() const {
    auto stage = make_jones_stage(box_, radii_.rmax(), Torus{}, &radii_);
    stage->reserve(points_.size());
    stage->adopt(points_, curve_.fresh_order(points_).data(), &values_);
    return stage;
}

double FieldDartStage::free_area() const { return jones_of_points()->free_area(); }

VerifyReport FieldDartStage::verify() const { return jones_of_points()->verify(); }

}  // namespace pds
