// jones_stage.cpp - the Jones loop (see jones_stage.hpp).
#include "jones_stage.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>

#include "predicates.hpp"

namespace pds {

JonesStage::JonesStage(const Box& box, double r) : box_(box), r_(r), dt_(box) {
    tree_.reserve(1);
    queue_.reserve(kMaxBatch);
    since_batch_.reserve(kMaxBatch + 1);
}

void JonesStage::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its container as it was.
    dt_.reserve(points + Delaunay::kGhosts);
    tree_.reserve(points);
    order_.reserve(points);
}

bool JonesStage::has_room_for(std::size_t points) const {
    return dt_.has_room_for(points + Delaunay::kGhosts) && tree_.capacity() >= points &&
           order_.capacity() >= points;
}

void JonesStage::adopt(const std::vector<Point>& points, const std::uint32_t* order) {
    if (count() != 0 || !has_room_for(points.size())) throw std::logic_error("hand-over without room");
    const std::size_t n = points.size();
    order_.resize(n);
    dt_.insert_in_order(points, order, n, [&](std::uint32_t k, VertexIndex v) { order_.set(k, v); });
    tree_.resize(n);
    measure_all_cells();
}

void JonesStage::set_radius(double r) {
    drop_queue();
    has_first_ = false;
    r_ = r;
    measure_all_cells();
}

void JonesStage::measure_all_cells() {
    const MeshCells cells = this->cells();
    for (SiteIndex site = 0; site < count(); ++site)
        tree_.set_leaf_only(site, cells.measure(vertex_of(site)).area);
    tree_.rebuild();
}

const Point* JonesStage::next(Rng& rng) {
    if (count() == 0) {
        // The whole domain is free: the first point is uniform in it.
        if (!has_first_) {
            Point p{box_.x0 + rng.next_double() * box_.width(), box_.y0 + rng.next_double() * box_.height()};
            p.x = std::min(p.x, box_.x1);
            p.y = std::min(p.y, box_.y1);
            first_ = Candidate{p, 0};
            has_first_ = true;
        }
        return &first_.p;
    }
    for (;;) {
        while (queue_head_ < queue_.size()) {
            const Candidate& cand = queue_[queue_head_];
            if (still_free(cand.p)) return &cand.p;
            ++queue_head_;
        }
        adapt_batch_size();
        drop_queue();
        if (tree_.total() == 0.0) return nullptr;
        draw_batch(batch_size_, rng);
    }
}

void JonesStage::add_next() {
    if (count() == 0) {
        if (!has_first_) throw std::logic_error("add_next without next");
        has_first_ = false;
        insert_point(first_.p, 0);
        return;
    }
    if (queue_head_ >= queue_.size()) throw std::logic_error("add_next without next");
    const Candidate cand = queue_[queue_head_++];
    insert_point(cand.p, cand.source);
}

void JonesStage::adapt_batch_size() {
    // In selections: double it while every candidate becomes a point; when
    // newer points cover some, shrink it so that about a fifth more
    // candidates are drawn than survive.
    if (queue_.empty()) return;
    const std::size_t drawn = queue_.size(), placed = since_batch_.size();
    const std::size_t next =
        placed == drawn ? 2 * batch_size_ : batch_size_ * (placed + placed / 4 + 1) / drawn;
    batch_size_ = std::max<std::size_t>(1, std::min(kMaxBatch, next));
}

void JonesStage::drop_queue() {
    queue_.clear();
    queue_head_ = 0;
    since_batch_.clear();
}

bool JonesStage::still_free(const Point& p) const {
    // It was free when drawn; only the points added since can cover it. Most
    // of those are far away: a box test skips them before the exact check.
    constexpr double kBoxReach = 1.5;  // any half-side >= R holds the disk; some margin
    const double reach = kBoxReach * r_;
    for (VertexIndex v : since_batch_) {
        const Point& q = dt_.point(v);
        if (std::fabs(p.x - q.x) > reach || std::fabs(p.y - q.y) > reach) continue;
        if (compare_distance(p, q, r_) < 0) return false;
    }
    return true;
}

void JonesStage::set_weight(SiteIndex site, double weight) {
    if (undo_count_ == sizeof undo_ / sizeof undo_[0]) throw std::logic_error("batch undo log full");
    undo_[undo_count_++] = WeightUndo{site, tree_.weight(site)};
    tree_.set(site, weight);
}

void JonesStage::draw_batch(std::size_t n, Rng& rng) {
    // Only the exact coverage test allocates here. If it fails, undo the
    // batch: the queue was empty, so afterwards the stage is as it was.
    const Rng rng_before = rng;
    const int failures_before = draw_failures_;
    const JonesStats stats_before = stats_;
    undo_count_ = 0;
    try {
        draw_batch_unguarded(n, rng);
    } catch (const std::bad_alloc&) {
        while (undo_count_ > 0) {
            --undo_count_;
            tree_.set(undo_[undo_count_].site, undo_[undo_count_].weight);
        }
        rng = rng_before;
        draw_failures_ = failures_before;
        stats_ = stats_before;
        queue_.clear();
        throw;
    }
}

void JonesStage::draw_batch_unguarded(std::size_t n, Rng& rng) {
    double target[kMaxBatch] = {};
    std::size_t sites[kMaxBatch];
    VertexIndex vertices[kMaxBatch];
    double bound[kMaxBatch];
    const double total = tree_.total();
    for (std::size_t k = 0; k < n; ++k) target[k] = rng.next_double() * total;
    tree_.select_many(target, n, sites);
    for (std::size_t k = 0; k < n; ++k) {
        vertices[k] = vertex_of(sites[k]);
        bound[k] = tree_.weight(sites[k]);
    }
    dt_.prefetch_rings(vertices, n);
    const MeshCells cells = this->cells();
    for (std::size_t k = 0; k < n; ++k) {
        const SiteIndex site = sites[k];
        const VertexIndex v = vertices[k];
        const CellQuery q = cells.query(v);
        // One pass: the chunk holding target u * U; if the exact area A falls
        // short of the target, the selection is rejected.
        const CellSelection sel = select_in_cell(q, cells.ring(v), rng.next_double() * bound[k]);
        if (!sel.found()) {
            // The whole cell was measured: settle doubt, tighten the bound
            // (the same cell may come twice in a batch: only downwards).
            if (sel.measure.doubtful && cells.covered_exactly(v)) {
                set_weight(site, 0.0);
                continue;
            }
            if (sel.measure.area < tree_.weight(site)) set_weight(site, sel.measure.area);
            if (sel.measure.area < bound[k]) {
                // The target fell in the part of the bound the cell has lost
                // since it was measured.
                continue;
            }
            if (!sel.fallback()) {
                give_up(site);  // free by its vertices, yet no chunk with area
                continue;
            }
            // else rounding left the target just out of reach: the last chunk
        }
        // A found chunk in a cell floating point could not certify needs no
        // special care: every draw is checked exactly before it is kept.
        const auto accept = [&](const Point& p) { return acceptable(p, v); };
        Point p;
        if (sample_chunk(q, sel.chunk(), rng.next_double(), rng, accept, kMaxDraws, &p) ==
            SampleOutcome::placed) {
            queue_.push_back(Candidate{p, v});
            continue;
        }
        // A healthy piece practically never fails 64 draws; a cell that keeps
        // failing has a free region below double resolution, or none.
        if (++draw_failures_ % kFailuresPerGiveUp == 0) give_up(site);
    }
    // Inserting a candidate flips edges one triangle beyond its source's
    // ring: fetch those too, for all candidates at once.
    VertexIndex sources[kMaxBatch];
    for (std::size_t k = 0; k < queue_.size(); ++k) sources[k] = queue_[k].source;
    dt_.prefetch_beyond_rings(sources, queue_.size());
}

bool JonesStage::acceptable(const Point& p, VertexIndex v) const {
    // Exact: inside the domain, at least R from the site, and in the site's
    // Voronoi cell (no Delaunay neighbour strictly closer), hence at least R
    // from every point.
    if (!box_.contains(p)) return false;
    const Point& c = dt_.point(v);
    if (compare_distance(p, c, r_) < 0) return false;
    bool ok = true;
    dt_.for_each_neighbour(v, [&](VertexIndex n) {
        if (ok && !Delaunay::is_ghost(n) && compare_closer(p, c, dt_.point(n)) > 0) ok = false;
    });
    return ok;
}

void JonesStage::insert_point(const Point& p, VertexIndex near) {
    const VertexIndex v = dt_.insert(p, near);
    // The neighbours' cells only shrank: their weights stay valid upper bounds
    // and are tightened when next selected (measured: re-measuring them here,
    // even only the source cell, costs more than the rejections it saves).
    // Only the new cell is measured.
    tree_.push_back(cells().measure(v).area);
    since_batch_.push_back(v);
    draw_failures_ = 0;
}

void JonesStage::give_up(SiteIndex site) {
    if (!cells().covered_exactly(vertex_of(site))) ++stats_.gave_up_cells;
    set_weight(site, 0.0);
}

double JonesStage::free_area() const {
    // The tree holds upper bounds; the exact area is re-measured, cell by cell,
    // in leaf order (so the sum is the same on every call).
    const MeshCells cells = this->cells();
    double sum = 0.0;
    tree_.for_each_positive([&](SiteIndex site) {
        sum += cells.measure(vertex_of(site)).area;
        return true;
    });
    return sum;
}

VerifyReport JonesStage::verify() const {
    VerifyReport rep = verify_pattern(dt_, box_, r_);
    if (rep.vertex != kNoVertex) name_point(rep, order_.point(rep.vertex));
    if (rep.valid && !rep.maximal && count() > 0 && tree_.total() == 0.0) {
        rep.valid = false;
        rep.failure = "the sampler reported a maximal pattern, but " + rep.failure;
        if (stats_.gave_up_cells > 0)
            rep.failure += " (" + std::to_string(stats_.gave_up_cells) +
                           " free regions were below double-precision resolution)";
    }
    return rep;
}

}  // namespace pds
