// jones_stage.cpp - the Jones loop (see jones_stage.hpp).
#include "jones/jones_stage.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>

#include "core/predicates.hpp"
#include "verify/verify_torus.hpp"

namespace pds {

JonesStage::JonesStage(const Box& box, double r, const Torus& torus, const PointRadii* radii)
    : box_(box),
      r_(r),
      dt_(torus.on() ? TorusCopies(torus, r, radii != nullptr).largest_region() : box, radii != nullptr,
          radii ? radii->rmax() : 0.0) {
    if (radii) radii_ = *radii;
    if (torus.on()) {
        copies_ = TorusCopies(torus, r, radii != nullptr);
        is_copy_.assign(Delaunay::kGhosts, 0);
        original_.assign(Delaunay::kGhosts, 0);
        copy_hint_.assign(copies_.max_offsets(), 0);
    }
    tree_.reserve(1);
    queue_.reserve(kMaxBatch);
    since_batch_.reserve(kMaxBatch + 1);
}

std::size_t JonesStage::vertices_for(std::size_t points) const {
    if (!copies_.on()) return points;
    // The copies expected at the current margin, and one point's worth more.
    const double copies = static_cast<double>(points) * copies_.copies_per_point() * 1.25;
    return points + static_cast<std::size_t>(copies) + copies_.max_copies() + 1;
}

void JonesStage::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its container as it was.
    const std::size_t vertices = vertices_for(points);
    dt_.reserve(vertices + Delaunay::kGhosts);
    tree_.reserve(vertices);
    order_.reserve(points);
    if (radii_) values_.reserve(points);
    if (copies_.on()) {
        is_copy_.reserve(vertices + Delaunay::kGhosts);
        original_.reserve(vertices + Delaunay::kGhosts);
    }
}

bool JonesStage::has_room_for(std::size_t points) const {
    const std::size_t vertices = vertices_for(points);
    return dt_.has_room_for(vertices + Delaunay::kGhosts) && tree_.capacity() >= vertices &&
           order_.capacity() >= points && (!radii_ || values_.capacity() >= points) &&
           (!copies_.on() || (is_copy_.capacity() >= vertices + Delaunay::kGhosts &&
                              original_.capacity() >= vertices + Delaunay::kGhosts));
}

void JonesStage::adopt(const std::vector<Point>& points, const std::uint32_t* order,
                       const std::vector<double>* values, const Poll& poll) {
    if (radii_.has_value() != (values != nullptr) || (values && copies_.on()))
        throw std::logic_error("hand-over without the field's values");
    if (count() != 0 || (!copies_.on() && !has_room_for(points.size()))) throw std::logic_error("hand-over without room");
    const std::size_t n = points.size();
    order_.resize(n);
    if (copies_.on()) {
        adopt_on_torus(points, order, poll);
        return;
    }
    if (values) values_.assign(values->begin(), values->end());  // within the reserved room
    std::size_t inserted = 0;
    dt_.insert_in_order(
        points, order, n, [&](std::uint32_t k) { return radii_->radius_of(values_[k]); },
        [&](std::uint32_t k, VertexIndex v) {
            order_.set(k, v);
            if (++inserted % Poll::kEvery == 0) poll();
        });
    tree_.resize(n);
    measure_all_cells(poll);
}

void JonesStage::set_radius(double r, const PointRadii* radii) {
    settle();
    if (radii_) {
        const PointRadii old = *radii_;
        radii_ = *radii;
        try {
            rebuild_mesh();
        } catch (...) {
            radii_ = old;
            throw;
        }
    }
    drop_queue();
    has_first_ = false;
    r_ = r;
    // On the torus the new radii may need a wider margin (their conflict disks
    // are not the old ones).
    if (!measure_all_cells() && radii_) widen_margin();
}

bool JonesStage::measure_all_cells(const Poll& poll) {
    const MeshCells cells = this->cells();
    const SiteIndex sites = dt_.vertex_count() - Delaunay::kGhosts;
    bool valid = true;
    // The rings are walked in step a batch ahead, so their misses overlap
    // (at 10^7 points the ring reads were most of this loop's time).
    constexpr SiteIndex kAhead = 16;
    VertexIndex ahead[kAhead];
    for (SiteIndex site = 0; site < sites; ++site) {
        const VertexIndex v = vertex_of(site);
        if (site % kAhead == 0) {
            if (site % Poll::kEvery == 0) poll();
            SiteIndex m = 0;
            for (SiteIndex s = site + kAhead; s < sites && m < kAhead; ++s) ahead[m++] = vertex_of(s);
            dt_.prefetch_rings(ahead, m);
        }
        if (is_copy(v) || (radii_ && dt_.is_hidden(v))) {
            tree_.set_leaf_only(site, 0.0);
            continue;
        }
        const CellMeasure m = cells.measure(v);
        if (copies_.on() && valid && !cell_valid(v, m)) valid = false;
        tree_.set_leaf_only(site, m.area);
    }
    tree_.rebuild();
    return valid;
}

Point JonesStage::first_point(Rng& rng) const {
    if (copies_.on()) {
        // On the torus grid, inside the fundamental domain.
        const Torus& t = copies_.torus();
        const double u = rng.next_double(), w = rng.next_double();
        return t.wrap(Point{Torus::snap(t.x0 + u * t.px), Torus::snap(t.y0 + w * t.py)});
    }
    Point p{box_.x0 + rng.next_double() * box_.width(), box_.y0 + rng.next_double() * box_.height()};
    p.x = std::min(p.x, box_.x1);
    p.y = std::min(p.y, box_.y1);
    return p;
}

const Point* JonesStage::next(Rng& rng) {
    settle();
    if (count() == 0) {
        // The whole domain is free: the first point is uniform in it.
        if (!has_first_) {
            first_ = Candidate{first_point(rng), 0};
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
    // The field is asked first: if it refuses, nothing has changed.
    if (count() == 0) {
        if (!has_first_) throw std::logic_error("add_next without next");
        const double value = value_at(first_.p);
        has_first_ = false;
        insert_point(first_.p, 0, value);
        return;
    }
    if (queue_head_ >= queue_.size()) throw std::logic_error("add_next without next");
    const double value = value_at(queue_[queue_head_].p);
    const Candidate cand = queue_[queue_head_++];
    insert_point(cand.p, cand.source, value);
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
    if (copies_.on()) return still_free_on_torus(p);
    const double reach = kBoxReach * r_;
    for (VertexIndex v : since_batch_) {
        const Point& q = dt_.point(v);
        if (std::fabs(p.x - q.x) > reach || std::fabs(p.y - q.y) > reach) continue;
        // Each newer disk by its own radius (r_ is the largest).
        if (compare_distance(p, q, radii_ ? dt_.radius(v) : r_) < 0) return false;
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
    stats_.selections += n;
    VertexIndex rings[kMaxBatch];
    for (std::size_t k = 0; k < n; ++k) {
        vertices[k] = vertex_of(sites[k]);
        bound[k] = tree_.weight(sites[k]);
        // A hidden disk has no ring: a ghost's stands in for the prefetch.
        rings[k] = radii_ && dt_.is_hidden(vertices[k]) ? 0 : vertices[k];
    }
    dt_.prefetch_rings(rings, n);
    const MeshCells cells = this->cells();
    for (std::size_t k = 0; k < n; ++k) {
        const SiteIndex site = sites[k];
        const VertexIndex v = vertices[k];
        if (rings[k] != v) {
            set_weight(site, 0.0);  // hidden since it was measured: no cell left
            continue;
        }
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
                ++stats_.stale_selections;
                if (sel.measure.area == 0.0) ++stats_.stale_at_zero;
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
        // On the torus the point is snapped to the grid first (torus.hpp)
        // and the exact checks judge the snapped point.
        Point chosen{0.0, 0.0};
        const auto accept = [&](const Point& p) {
            chosen = copies_.on() ? Point{Torus::snap(p.x), Torus::snap(p.y)} : p;
            return acceptable(chosen, v);
        };
        Point p;
        // A site outside its power cell: its pieces reach outside the cell,
        // so a draw there rejects the whole selection (a retry inside the
        // piece would favour the piece's part in the cell).
        const bool retry = !radii_ || site_in_own_cell(v);
        const SampleOutcome drawn = sample_chunk(q, sel.chunk(), rng.next_double(), rng, accept, kMaxDraws, &p, retry);
        if (drawn == SampleOutcome::placed) {
            queue_.push_back(Candidate{chosen, v});
            continue;
        }
        if (drawn == SampleOutcome::rejected) continue;
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
    // from every point. On the torus the cell is unclipped and p is moved
    // into the fundamental domain when inserted.
    if (!copies_.on() && !box_.contains(p)) return false;
    const Point& c = dt_.point(v);
    if (radii_) return in_free_power_cell(p, v);
    if (compare_distance(p, c, r_) < 0) return false;
    bool ok = true;
    dt_.for_each_neighbour(v, [&](VertexIndex n) {
        if (ok && !Delaunay::is_ghost(n) && compare_closer(p, c, dt_.point(n)) > 0) ok = false;
    });
    return ok;
}

void JonesStage::insert_point(const Point& p, VertexIndex near, double value) {
    if (radii_ && !copies_.on()) {
        // Room was reserved (values_ too): nothing here allocates.
        const VertexIndex v = dt_.insert(p, radii_->radius_of(value), near);
        values_.push_back(value);
        tree_.push_back(dt_.is_hidden(v) ? 0.0 : cells().measure(v).area);
        since_batch_.push_back(v);
        draw_failures_ = 0;
        return;
    }
    if (copies_.on()) {
        insert_point_on_torus(p, near, value);
        return;
    }
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
    // Cells are the torus's only once the margin is settled.
    if (widen_pending_) throw std::bad_alloc();
    // The tree holds upper bounds; the exact area is re-measured, cell by cell,
    // in leaf order (so the sum is the same on every call).
    const MeshCells cells = this->cells();
    double sum = 0.0;
    tree_.for_each_positive([&](SiteIndex site) {
        const VertexIndex v = vertex_of(site);
        if (!radii_ || !dt_.is_hidden(v)) sum += cells.measure(v).free();
        return true;
    });
    return sum;
}

VerifyReport JonesStage::verify() const {
    if (widen_pending_) throw std::bad_alloc();
    VerifyReport rep;
    if (radii_) {
        std::vector<std::size_t> rank(dt_.vertex_count(), 0);
        for (std::size_t k = 0; k < count(); ++k) rank[order_.vertex(k)] = k;
        rep = copies_.on() ? verify_torus(dt_, copies_, is_copy_, r_, &rank) : verify_pattern(dt_, box_, r_, &rank);
    } else {
        rep = copies_.on() ? verify_torus(dt_, copies_, is_copy_, r_) : verify_pattern(dt_, box_, r_);
    }
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
