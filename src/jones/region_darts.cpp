// region_darts.cpp - the bookkeeping and the greedy decision of the free
// regions' dart process (region_darts.hpp).
#include "jones/region_darts.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/predicates.hpp"
#include "core/prefetch.hpp"
#include "core/time_order.hpp"

namespace pds {

void RegionDarts::start(std::uint64_t salted_seed, std::size_t epoch, const Box& domain, double r,
                        const Torus& torus, bool varying) {
    stop();
    on_ = true;
    salted_ = salted_seed;
    epoch_ = epoch;
    r_ = r;
    torus_ = torus;
    varying_ = varying;
    // The grid is allocated at the first decision (the hand-over allocates
    // nothing); here only its shape. In the plane, cells of side 2r over
    // the domain and a margin of r; on the torus, as many cells as fit the
    // periods at side 2r at least (at least one: r is at most half of each).
    if (torus_.on()) {
        grid_x0_ = torus_.x0;
        grid_y0_ = torus_.y0;
        grid_columns_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(torus_.px / (2.0 * r))));
        grid_rows_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(torus_.py / (2.0 * r))));
        side_x_ = torus_.px / static_cast<double>(grid_columns_);
        side_y_ = torus_.py / static_cast<double>(grid_rows_);
        return;
    }
    grid_x0_ = domain.x0 - r;
    grid_y0_ = domain.y0 - r;
    side_x_ = side_y_ = 2.0 * r;
    grid_columns_ = static_cast<std::size_t>(std::ceil((domain.width() + 2.0 * r) / (2.0 * r))) + 1;
    grid_rows_ = static_cast<std::size_t>(std::ceil((domain.height() + 2.0 * r) / (2.0 * r))) + 1;
}

std::size_t RegionDarts::column_of(double x) const {
    return std::min(grid_columns_ - 1, static_cast<std::size_t>(std::max(0.0, std::floor((x - grid_x0_) / side_x_))));
}

std::size_t RegionDarts::row_of(double y) const {
    return std::min(grid_rows_ - 1, static_cast<std::size_t>(std::max(0.0, std::floor((y - grid_y0_) / side_y_))));
}

template <bool kVarying>
bool RegionDarts::free_in_plane(std::uint32_t i) const {
    // With a field, r is the largest radius, and each accepted dart holds
    // others out of its own disk.
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    const double r = r_;
    const Point& p = darts_[i].p;
    const std::size_t x0 = column_of(p.x - r), x1 = column_of(p.x + r);
    const std::size_t y0 = row_of(p.y - r), y1 = row_of(p.y + r);
    for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x)
            for (std::uint32_t j = grid_[y * grid_columns_ + x]; j != kNone; j = chain_[j])
                if (compare_distance(p, darts_[j].p, kVarying ? reach_[j] : r) < 0) return false;
    return true;
}

template <bool kVarying>
bool RegionDarts::free_on_torus(std::uint32_t i) const {
    // The cells (wrapped) that the disk around p meets, widened by far more
    // than the rounding of a cell index, so the cell of every copy within r
    // is among them; at most three along an axis, as a cell is 2r wide.
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    const double r = r_;
    const Point p = torus_.wrap(darts_[i].p);
    const auto cells = [](double v, double v0, double side, std::size_t n, double reach, std::size_t* out) {
        const double slack = side * 0x1.0p-30;
        const auto n64 = static_cast<std::int64_t>(n);
        const auto lo = static_cast<std::int64_t>(std::floor((v - reach - slack - v0) / side));
        const auto hi = static_cast<std::int64_t>(std::floor((v + reach + slack - v0) / side));
        std::size_t m = 0;
        for (std::int64_t k = lo; k <= hi && m < n; ++k) {
            const auto c = static_cast<std::size_t>(((k % n64) + n64) % n64);
            if (std::find(out, out + m, c) == out + m) out[m++] = c;
        }
        return m;
    };
    std::size_t xs[4], ys[4];
    const std::size_t nx = cells(p.x, grid_x0_, side_x_, grid_columns_, r, xs);
    const std::size_t ny = cells(p.y, grid_y0_, side_y_, grid_rows_, r, ys);
    // A dart within r of some copy of q (the copies shifted by whole
    // periods are exact on the torus grid); with a field, within q's own
    // radius (at most r).
    const double reach = r * (1.0 + 0x1.0p-20);
    for (std::size_t a = 0; a < ny; ++a)
        for (std::size_t b = 0; b < nx; ++b)
            for (std::uint32_t j = grid_[ys[a] * grid_columns_ + xs[b]]; j != kNone; j = chain_[j]) {
                const Point q = torus_.wrap(darts_[j].p);
                for (int sy = -1; sy <= 1; ++sy)
                    for (int sx = -1; sx <= 1; ++sx) {
                        const Point c = torus_.shifted(q, sx, sy);
                        if (std::fabs(c.x - p.x) > reach || std::fabs(c.y - p.y) > reach) continue;
                        if (compare_distance(p, c, kVarying ? reach_[j] : r) < 0) return false;
                    }
            }
    return true;
}

void RegionDarts::stop() {
    on_ = false;
    ending_ = false;
    varying_ = false;
    listed_ = 0;
    next_ = 0;
    pending_.clear();
    std::vector<SiteIndex>().swap(active_);
    std::vector<Block>().swap(blocks_);
    std::vector<Dart>().swap(darts_);
    std::vector<std::uint32_t>().swap(chain_);
    std::vector<std::uint32_t>().swap(bucket_);
    std::vector<std::uint32_t>().swap(grid_);
    std::vector<double>().swap(reach_);
    std::vector<double>().swap(values_);
}

std::size_t RegionDarts::cell_of(const Point& q) const {
    const Point w = torus_.on() ? torus_.wrap(q) : q;
    return row_of(w.y) * grid_columns_ + column_of(w.x);
}

void RegionDarts::undo_decision() {
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    for (const Dart& d : pending_) grid_[cell_of(d.p)] = kNone;
    pending_.clear();
    values_.clear();
    next_ = 0;
}

std::vector<RegionDarts::Block>& RegionDarts::blocks(std::size_t n) {
    if (blocks_.size() < n) blocks_.resize(n);
    for (std::size_t b = 0; b < n; ++b) {
        blocks_[b].darts.clear();
        blocks_[b].bounds.clear();
    }
    return blocks_;
}

void RegionDarts::decide(std::size_t nblocks, const DartField* field) {
    if (varying_ != (field != nullptr)) throw std::logic_error("region darts decided without their field");
    // The grid of accepted darts: cells of side 2r (at least), so the disk
    // of radius r around a dart meets at most 2 x 2 of them in the plane
    // (two words in each of two rows). Its cells are emptied of the last
    // epoch's darts first.
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    const double r = r_;
    for (const Dart& d : pending_) grid_[cell_of(d.p)] = kNone;
    // Everything is allocated before pending_ changes: std::bad_alloc here
    // leaves the points that were pending (none: an epoch starts when they
    // are all handed out) and the bounds as they were.
    if (grid_.empty()) grid_.assign(grid_columns_ * grid_rows_, kNone);
    std::size_t n = 0;
    for (std::size_t b = 0; b < nblocks; ++b) n += blocks_[b].darts.size();
    darts_.resize(n);
    chain_.resize(n);
    bucket_.reserve(n + 1);
    pending_.reserve(n);
    if (varying_) {
        reach_.resize(n);
        values_.reserve(n);
    }
    // The blocks' darts copied straight into order of time, stably: ties
    // (1 in 2^53 per pair) go to the earlier in block order. The decision
    // then reads the darts in sequence.
    order_by_time(
        n,
        [&](const auto& put) {
            for (std::size_t b = 0; b < nblocks; ++b)
                for (const Dart& d : blocks_[b].darts) put(d);
        },
        [](const Dart& d) { return d.t; }, [](const Dart& x, const Dart& y) { return x.t < y.t; }, darts_.data(),
        bucket_);
    pending_.clear();
    values_.clear();
    next_ = 0;
    // The grid's rows for the darts a few ahead, asked for early.
    constexpr std::size_t kAhead = 8;
    const auto prefetch_rows = [&](std::size_t i) {
        const Point& q = darts_[i].p;
        const std::size_t x0 = column_of(q.x - r), y0 = row_of(q.y - r), y1 = row_of(q.y + r);
        pds::prefetch(&grid_[y0 * grid_columns_ + x0]);
        pds::prefetch(&grid_[y1 * grid_columns_ + x0]);
    };
    for (std::size_t i = 0; i < std::min(n, kAhead); ++i) prefetch_rows(i);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (i + kAhead < n) prefetch_rows(i + kAhead);
        if (varying_) {
            if (!free<true>(i)) continue;
            // The field at the dart that becomes the next point (it may
            // refuse: the epoch is then left undecided).
            double value = 0.0;
            try {
                value = field->value_at(darts_[i].p);
            } catch (...) {
                undo_decision();
                throw;
            }
            reach_[i] = field->radius_of(value);
            values_.push_back(value);
        } else if (!free<false>(i)) {
            continue;
        }
        std::uint32_t& head = grid_[cell_of(darts_[i].p)];
        chain_[i] = head;
        head = i;
        pending_.push_back(darts_[i]);
    }
    ++stats_.epochs;
    stats_.darts += n;
    stats_.points += pending_.size();
}

}  // namespace pds
