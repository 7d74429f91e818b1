// region_darts.cpp - the bookkeeping and the greedy decision of the free
// regions' dart process (region_darts.hpp).
#include "jones/region_darts.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"
#include "core/prefetch.hpp"
#include "core/time_order.hpp"

namespace pds {

void RegionDarts::start(std::uint64_t salted_seed, std::size_t epoch, const Box& domain, double r) {
    stop();
    on_ = true;
    salted_ = salted_seed;
    epoch_ = epoch;
    // The grid is allocated at the first decision (the hand-over allocates
    // nothing); here only its shape.
    grid_x0_ = domain.x0 - r;
    grid_y0_ = domain.y0 - r;
    grid_columns_ = static_cast<std::size_t>(std::ceil((domain.width() + 2.0 * r) / (2.0 * r))) + 1;
    grid_rows_ = static_cast<std::size_t>(std::ceil((domain.height() + 2.0 * r) / (2.0 * r))) + 1;
}

void RegionDarts::stop() {
    on_ = false;
    ending_ = false;
    listed_ = 0;
    next_ = 0;
    pending_.clear();
    std::vector<SiteIndex>().swap(active_);
    std::vector<Block>().swap(blocks_);
    std::vector<Dart>().swap(darts_);
    std::vector<std::uint32_t>().swap(chain_);
    std::vector<std::uint32_t>().swap(bucket_);
    std::vector<std::uint32_t>().swap(grid_);
}

std::vector<RegionDarts::Block>& RegionDarts::blocks(std::size_t n) {
    if (blocks_.size() < n) blocks_.resize(n);
    for (std::size_t b = 0; b < n; ++b) {
        blocks_[b].darts.clear();
        blocks_[b].bounds.clear();
    }
    return blocks_;
}

void RegionDarts::decide(std::size_t nblocks, double r) {
    // The grid of accepted darts: cells of side 2r over the domain and a
    // margin of r, so the disk of radius r around a dart meets at most 2 x 2
    // of them (two words in each of two rows). Its cells are emptied of the
    // last epoch's darts first.
    const double side = 2.0 * r;
    const auto index = [side](double v, double v0, std::size_t count) {
        return std::min(count - 1, static_cast<std::size_t>(std::max(0.0, std::floor((v - v0) / side))));
    };
    const auto column = [&](double x) { return index(x, grid_x0_, grid_columns_); };
    const auto row = [&](double y) { return index(y, grid_y0_, grid_rows_); };
    constexpr std::uint32_t kNone = ~std::uint32_t{0};
    for (const Dart& d : pending_) grid_[row(d.p.y) * grid_columns_ + column(d.p.x)] = kNone;
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
    next_ = 0;
    // The grid's rows for the darts a few ahead, asked for early.
    constexpr std::size_t kAhead = 8;
    const auto prefetch_rows = [&](std::size_t i) {
        const Point& q = darts_[i].p;
        const std::size_t x0 = column(q.x - r), y0 = row(q.y - r), y1 = row(q.y + r);
        pds::prefetch(&grid_[y0 * grid_columns_ + x0]);
        pds::prefetch(&grid_[y1 * grid_columns_ + x0]);
    };
    for (std::size_t i = 0; i < std::min(n, kAhead); ++i) prefetch_rows(i);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (i + kAhead < n) prefetch_rows(i + kAhead);
        const Point& p = darts_[i].p;
        const std::size_t x0 = column(p.x - r), x1 = column(p.x + r);
        const std::size_t y0 = row(p.y - r), y1 = row(p.y + r);
        bool free = true;
        for (std::size_t y = y0; y <= y1 && free; ++y)
            for (std::size_t x = x0; x <= x1 && free; ++x)
                for (std::uint32_t j = grid_[y * grid_columns_ + x]; j != kNone && free; j = chain_[j])
                    if (compare_distance(p, darts_[j].p, r) < 0) free = false;
        if (!free) continue;
        std::uint32_t& head = grid_[row(p.y) * grid_columns_ + column(p.x)];
        chain_[i] = head;
        head = i;
        pending_.push_back(darts_[i]);
    }
    ++stats_.epochs;
    stats_.darts += n;
    stats_.points += pending_.size();
}

}  // namespace pds
