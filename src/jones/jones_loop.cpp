// jones_loop.cpp - the Jones loop (see jones_loop.hpp), compiled once for
// each mesh and radius rule (make_jones_stage.cpp picks one).
#include "jones/jones_loop.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <stdexcept>

#include "core/worker_pool.hpp"
#include "jones/plane_space.hpp"
#include "jones/polygon_space.hpp"
#include "jones/radius_rule.hpp"
#include "jones/torus_space.hpp"

namespace pds {

template <class Space, class Rule>
JonesLoop<Space, Rule>::JonesLoop(const Rectangle& domain, double r, const Torus& torus, const PointRadii* radii,
                                  std::shared_ptr<const Polygon> polygon)
    : rule_(radii),
      space_(domain, r, torus, Rule::kWeighted, std::move(polygon)),
      r_(r),
      dt_(space_.mesh_region(), Rule::kWeighted, rule_.rmax()) {
    tree_.reserve(1);
    queue_.reserve(kMaxBatch);
    since_batch_.reserve(kMaxBatch + 1);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::reserve(std::size_t points) {
    // Each reserve either succeeds or leaves its container as it was. The
    // helper reads the mesh's arrays: it stops before they may move.
    quiet_helper();
    const std::size_t vertices = vertices_for(points);
    dt_.reserve(vertices + Delaunay::kGhosts);
    tree_.reserve(vertices);
    order_.reserve(points);
    rule_.reserve(points);
    space_.reserve(vertices + Delaunay::kGhosts);
}

template <class Space, class Rule>
bool JonesLoop<Space, Rule>::has_room_for(std::size_t points) const {
    const std::size_t vertices = vertices_for(points);
    return dt_.has_room_for(vertices + Delaunay::kGhosts) && tree_.capacity() >= vertices &&
           order_.capacity() >= points && rule_.has_room_for(points) &&
           space_.has_room_for(vertices + Delaunay::kGhosts);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::adopt(const std::vector<Point>& points, const std::uint32_t* order,
                                   const std::vector<double>* values, const Poll& poll, MeshBuild build) {
    if (Rule::kWeighted != (values != nullptr))
        throw std::logic_error("hand-over without the field's values");
    if (count() != 0 || (!Space::kPeriodic && !has_room_for(points.size())))
        throw std::logic_error("hand-over without room");
    quiet_helper();
    order_.resize(points.size());
    space_.adopt(*this, points, order, values, poll, build);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::set_radius(double r, const PointRadii* radii) {
    require_epoch_handed_out("set_radius");
    quiet_helper();  // a field's mesh is rebuilt
    settle();
    rule_.rescale(*this, radii);
    regions_.stop();  // its darts were drawn for the old radius
    drop_queue();
    has_first_ = false;
    r_ = r;
    // On the torus the new radii may need a wider margin (their conflict disks
    // are not the old ones).
    if (!measure_all_cells() && Rule::kWeighted) space_.widen_margin(*this);
}

template <class Space, class Rule>
bool JonesLoop<Space, Rule>::measure_cells(SiteIndex first, SiteIndex last, unsigned w) {
    const MeshCells cells = cells_of(w);
    bool valid = true;
    // The rings are walked in step a batch ahead, so their misses overlap.
    constexpr SiteIndex kAhead = 16;
    VertexIndex ahead[kAhead];
    for (SiteIndex site = first; site < last; ++site) {
        const VertexIndex v = vertex_of(site);
        if ((site - first) % kAhead == 0) {
            SiteIndex m = 0;
            for (SiteIndex s = site + kAhead; s < last && m < kAhead; ++s) ahead[m++] = vertex_of(s);
            dt_.prefetch_rings(ahead, m);
        }
        if (space_.is_copy(v) || rule_.hidden(dt_, v)) {
            tree_.set_leaf_only(site, 0.0);
            continue;
        }
        const CellMeasure m = cells.measure(v);
        if (valid && !space_.cell_valid(*this, v, m)) valid = false;
        tree_.set_leaf_only(site, m.area);
    }
    return valid;
}

template <class Space, class Rule>
bool JonesLoop<Space, Rule>::measure_all_cells(const Poll& poll) {
    const SiteIndex sites = dt_.vertex_count() - Delaunay::kGhosts;
    // A block of Poll::kEvery sites a worker between the polls. Each cell
    // is measured from the mesh alone into its own leaf, so the cells can
    // be measured side by side (in a polygon each worker has its own
    // cutter; on the torus only reading the mesh: a margin too narrow is
    // widened afterwards, on the caller's thread).
    const unsigned threads = Space::kMeasuresSideBySide && sites >= 4 * Poll::kEvery ? threads_ : 1;
    WorkerPool pool(threads);
    std::atomic<bool> valid{true};
    const SiteIndex per = static_cast<SiteIndex>(Poll::kEvery), block = per * pool.size();
    for (SiteIndex start = 0; start < sites; start += block) {
        poll();
        pool.run([&](unsigned w) {
            const SiteIndex lo = std::min(sites, start + w * per), hi = std::min(sites, lo + per);
            if (!measure_cells(lo, hi, w)) valid.store(false, std::memory_order_relaxed);
        });
    }
    tree_.rebuild();
    return valid.load(std::memory_order_relaxed);
}

template <class Space, class Rule>
const Point* JonesLoop<Space, Rule>::next(Rng& rng) {
    settle();
    if (count() == 0) {
        // The whole domain is free: the first point is uniform in it.
        if (!has_first_) {
            first_ = Candidate{space_.first_point(rng), 0};
            has_first_ = true;
        }
        return &first_.p;
    }
    if (const Point* p = regions_.on() ? next_region_point() : nullptr) return p;
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

template <class Space, class Rule>
void JonesLoop<Space, Rule>::add_next() {
    // The field is asked first: if it refuses, nothing has changed.
    if (count() == 0) {
        if (!has_first_) throw std::logic_error("add_next without next");
        const double value = rule_.value_at(space_, first_.p);
        has_first_ = false;
        space_.insert_point(*this, first_.p, 0, value);
        return;
    }
    if (regions_.on()) return add_region_point();
    if (queue_head_ >= queue_.size()) throw std::logic_error("add_next without next");
    const double value = rule_.value_at(space_, queue_[queue_head_].p);
    const Candidate cand = queue_[queue_head_++];
    space_.insert_point(*this, cand.p, cand.source, value);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::adapt_batch_size() {
    // In selections: double it while every candidate becomes a point; when
    // newer points cover some, shrink it so that about a fifth more
    // candidates are drawn than survive.
    if (queue_.empty()) return;
    const std::size_t drawn = queue_.size(), placed = since_batch_.size();
    const std::size_t next =
        placed == drawn ? 2 * batch_size_ : batch_size_ * (placed + placed / 4 + 1) / drawn;
    batch_size_ = std::max<std::size_t>(1, std::min(kMaxBatch, next));
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::drop_queue() {
    queue_.clear();
    queue_head_ = 0;
    since_batch_.clear();
}

template <class Space, class Rule>
bool JonesLoop<Space, Rule>::still_free(const Point& p) const {
    // It was free when drawn; only the points added since can cover it. Most
    // of those are far away: a box test skips them before the exact check,
    // each newer disk by its own radius.
    const double reach = kBoxReach * r_;
    for (VertexIndex v : since_batch_)
        if (space_.covers(dt_.point(v), p, reach, [&] { return rule_.newer_radius(dt_, v, r_); })) return false;
    return true;
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::set_weight(SiteIndex site, double weight) {
    if (undo_count_ == sizeof undo_ / sizeof undo_[0]) throw std::logic_error("batch undo log full");
    undo_[undo_count_++] = WeightUndo{site, tree_.weight(site)};
    tree_.set(site, weight);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::draw_batch(std::size_t n, Rng& rng) {
    // Only the exact coverage test allocates here. If it fails, undo the
    // batch: the queue was empty, so afterwards the stage is as it was.
    const Rng rng_before = rng;
    const int failures_before = draw_failures_;
    const std::size_t rejections_before = rejections_;
    const bool region_draws_before = region_draws_;
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
        rejections_ = rejections_before;
        region_draws_ = region_draws_before;
        stats_ = stats_before;
        queue_.clear();
        throw;
    }
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::draw_batch_unguarded(std::size_t n, Rng& rng) {
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
        rings[k] = rule_.hidden(dt_, vertices[k]) ? 0 : vertices[k];
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
        const double cell_target = rng.next_double() * bound[k];
        const CellSelection sel = cells.select(v, cell_target);
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
        if (region_draws_ && cells.cut()) {
            // Drawn from its trapezoids, the cell is kept with probability (free
            // area) / bound, not area / bound: the fan's shadow is not drawn
            // from, so the bound drops to the free area.
            const CellMeasure m = cells.measure(v);
            const double free = m.free() > 0.0 ? m.free() : (m.area > 0.0 ? m.floor : 0.0);
            Point p;
            if (!(cell_target < free)) {
                if (free < tree_.weight(site)) set_weight(site, free);
                ++stats_.stale_selections;
            } else if (cells.draw_in_cut_cell(v, free, rng, [&](const Point& x) { return acceptable(x, v); }, &p)) {
                queue_.push_back(Candidate{p, v});
                ++stats_.region_draws;
            } else if (++draw_failures_ % kFailuresPerGiveUp == 0) {
                give_up(site);
            }
            continue;
        }
        // A found chunk in a cell floating point could not certify needs no
        // special care: every draw is checked exactly before it is kept, as
        // the space places it (the torus snaps it to its grid first).
        Point chosen{0.0, 0.0};
        const auto accept = [&](const Point& p, const Piece& piece) {
            chosen = space_.snap(p);
            return acceptable(chosen, v) && cells.counts(v, chosen, piece);
        };
        Point p;
        // A site outside its power cell, or a cell the outline cuts: its
        // pieces reach outside the region, so a draw there rejects the whole
        // selection (a retry inside the piece would favour the piece's part
        // in the region).
        const bool retry = rule_.retry_in_piece(dt_, v) && !cells.cut();
        const SampleOutcome drawn = sample_chunk(q, sel.chunk(), rng.next_double(), rng, accept, kMaxDraws, &p, retry);
        if (drawn == SampleOutcome::placed) {
            queue_.push_back(Candidate{chosen, v});
            ++stats_.placed_draws;
            continue;
        }
        if (drawn == SampleOutcome::rejected) {
            if (++stats_.refused_draws >= kRejectionsPerFailure && !region_draws_ && cells.cut() &&
                stats_.refused_draws >= kRefusalsPerPlaced * stats_.placed_draws)
                region_draws_ = true;
            // A refused draw ends a selection without counting against its
            // cell. So many in a row, with no point placed, means a free
            // region rounding cannot reach (a sliver along the outline): a
            // failure, as below; the first such failure turns the cut cells
            // to draws from their regions' trapezoids instead.
            if (++rejections_ % kRejectionsPerFailure == 0 && ++draw_failures_ % kFailuresPerGiveUp == 0) {
                if (region_draws_ || !cells.cut()) give_up(site);
                else region_draws_ = true;
            }
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

template class JonesLoop<PlaneSpace, OneRadius>;
template class JonesLoop<PlaneSpace, PowerRule>;
template class JonesLoop<TorusSpace, OneRadius>;
template class JonesLoop<TorusSpace, PowerRule>;
template class JonesLoop<PolygonSpace, OneRadius>;
template class JonesLoop<PolygonSpace, PowerRule>;

}  // namespace pds
