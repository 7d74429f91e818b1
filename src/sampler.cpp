// sampler.cpp - the Jones loop (see sampler.hpp).
#include "sampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cell_coverage.hpp"
#include "predicates.hpp"

namespace pds {

namespace {

constexpr Box kUnitSquare{0.0, 0.0, 1.0, 1.0};
// Coordinates are scaled so the largest magnitude is in [1, 2); the radius
// must keep this many bits of resolution below it.
constexpr double kMinInternalRadius = 0x1.0p-26;
constexpr double kMinMagnitude = 0x1.0p-900;
// Upper bound on memory per point, for the address-space check on 32-bit.
constexpr std::size_t kBytesPerPointBudget = 256;

double max_magnitude(const Box& b) {
    return std::max(std::max(std::fabs(b.x0), std::fabs(b.x1)),
                    std::max(std::fabs(b.y0), std::fabs(b.y1)));
}

int scale_exponent(const Box& b) { return -std::ilogb(max_magnitude(b)); }

Box scaled(const Box& b, int k) {
    return Box{std::ldexp(b.x0, k), std::ldexp(b.y0, k), std::ldexp(b.x1, k), std::ldexp(b.y1, k)};
}

// Any radius at least the diagonal gives the same one-point pattern; capping
// keeps R^2 finite.
double effective_radius(const Box& b, double r) {
    const double w = b.width(), h = b.height();
    const double cap = 2.0 * std::sqrt(w * w + h * h);  // not hypot: see delaunay.cpp
    return r < cap ? r : cap;
}

}  // namespace

Sampler::Sampler(double radius, std::uint64_t seed)
    : rng_(seed), user_domain_(kUnitSquare), user_radius_(radius), dt_(kUnitSquare) {
    set_frame(kUnitSquare, radius);
    tree_.reserve(1);
    queue_.reserve(kMaxBatch);
    since_batch_.reserve(kMaxBatch + 1);
}

double Sampler::count_bound(const Box& d, double radius) {
    // Oler (1961): points at mutual distance >= R in a convex region of area A
    // and perimeter P number at most 2A/(sqrt(3) R^2) + P/(2R) + 1.
    const double w = d.width() / radius, h = d.height() / radius;
    return 2.0 / std::sqrt(3.0) * w * h + (w + h) + 1.0;
}

std::size_t Sampler::max_points() {
    const std::size_t by_edges = kMaxEdgeRecords / 3 - Delaunay::kGhosts;
    const std::size_t by_memory = static_cast<std::size_t>(-1) / 2 / kBytesPerPointBudget;
    return std::min(by_edges, by_memory);
}

Limit Sampler::check_limits(const Box& domain, double radius) {
    if (max_magnitude(domain) < kMinMagnitude) return Limit::coordinates_too_small;
    const int k = scale_exponent(domain);
    const Box b = scaled(domain, k);
    const double r = std::ldexp(radius, k);
    if (!(r >= kMinInternalRadius)) return Limit::radius_below_precision;
    const double bound = count_bound(b, effective_radius(b, r));
    if (!(bound <= static_cast<double>(max_points()))) return Limit::too_many_points;
    return Limit::ok;
}

void Sampler::set_frame(const Box& domain, double radius) {
    scale_exp_ = scale_exponent(domain);
    box_ = scaled(domain, scale_exp_);
    r_ = effective_radius(box_, std::ldexp(radius, scale_exp_));
}

void Sampler::set_domain(const Box& domain) {
    if (count() != 0) throw std::logic_error("set_domain after the first point");
    const int k = scale_exponent(domain);
    Delaunay fresh(scaled(domain, k));  // may throw: nothing changed yet
    fresh.reserve(dt_.points().capacity());
    dt_ = std::move(fresh);
    darts_.reset();  // its grid was laid over the old domain
    user_domain_ = domain;
    set_frame(domain, user_radius_);
}

void Sampler::skip_dart_stage() {
    if (count() != 0) throw std::logic_error("skip_dart_stage after the first point");
    dart_stage_ = false;
    darts_.reset();
}

void Sampler::ensure_room(std::size_t points) {
    // Each reserve either succeeds or leaves its container as it was. The
    // triangulation and the tree are reserved for the whole run even in the
    // dart stage: address space, touched only when the Jones loop takes over.
    dt_.reserve(points + Delaunay::kGhosts);
    tree_.reserve(points);
    if (dart_stage_) {
        if (!darts_) darts_ = std::make_unique<DartGrid>(box_, r_);
        darts_->reserve(points);
        emitted_.reserve(points);
    }
}

bool Sampler::has_room_for_one() const {
    const std::size_t n = count();
    // In the dart stage the triangulation holds only the ghosts; the hand-over
    // may come with the next point, so it needs room for one more as well.
    const bool mesh_room = dart_stage_ ? dt_.has_room_for(n + 1 + Delaunay::kGhosts) : dt_.has_room_for_one();
    const bool stage_room = !dart_stage_ || (darts_ && darts_->has_room_for_one() && emitted_.capacity() > n);
    return mesh_room && stage_room && tree_.capacity() > n;
}

bool Sampler::step() {
    const std::size_t n = count();
    if (!has_room_for_one()) {
        // Grow geometrically, but never past what the pattern can hold.
        const double cap = std::min(count_bound(box_, r_), static_cast<double>(max_points())) + 1.0;
        const double want = std::min(2.0 * static_cast<double>(n) + 64.0, cap);
        ensure_room(std::max(static_cast<std::size_t>(want), n + 1));
    }
    return add_one();
}

std::size_t Sampler::run(std::size_t max_new, bool* maximal) {
    const double bound = std::min(count_bound(box_, r_), static_cast<double>(max_points()));
    const std::size_t n = count();
    std::size_t target = static_cast<std::size_t>(bound) + 1;
    if (max_new != 0 && max_new < target - std::min(target, n)) target = n + max_new;
    ensure_room(std::max(target, n + 1));
    std::size_t added = 0;
    bool more = true;
    while ((max_new == 0 || added < max_new) && (more = add_one())) ++added;
    *maximal = !more || !has_room();
    return added;
}

void Sampler::refine(double radius) {
    // The dart stage's grid is laid out for the old radius: hand its points
    // to the Jones loop (or, with none yet, start the grid afresh).
    if (dart_stage_) {
        if (count() > 0)
            finish_dart_stage();
        else
            darts_.reset();
    }
    // Queued candidates were drawn for the old radius: the free region grows
    // now, so they would not be uniform over it.
    drop_queue();
    user_radius_ = radius;
    r_ = effective_radius(box_, std::ldexp(radius, scale_exp_));
    for (std::size_t site = 0; site < count(); ++site) tree_.set_leaf_only(site, cell_measure(site).area);
    tree_.rebuild();
}

CellMeasure Sampler::cell_measure(std::size_t site) const { return measure_in(dt_, vertex_of(site)); }

CellMeasure Sampler::measure_in(const Delaunay& mesh, std::uint32_t v) const {
    return measure_cell(CellQuery{mesh.point(v), box_, r_}, ring_of(mesh, v));
}

CellQuery Sampler::cell_query(std::size_t site) const {
    return CellQuery{dt_.point(vertex_of(site)), box_, r_};
}

std::vector<Point> Sampler::cell_ring(std::size_t site) const { return ring_points(dt_, vertex_of(site)); }

bool Sampler::add_one() {
    if (dart_stage_) {
        if (!darts_) throw std::logic_error("dart stage without its grid");
        if (darts_->add_one(rng_)) return true;
        finish_dart_stage();
    }
    if (count() == 0) {
        // The whole domain is free: the first point is uniform in it.
        Point p{box_.x0 + rng_.next_double() * box_.width(),
                box_.y0 + rng_.next_double() * box_.height()};
        p.x = std::min(p.x, box_.x1);
        p.y = std::min(p.y, box_.y1);
        insert_point(p, 0);
        return true;
    }
    for (;;) {
        while (queue_head_ < queue_.size()) {
            const Candidate cand = queue_[queue_head_++];
            if (still_free(cand.p)) {
                insert_point(cand.p, cand.source);
                return true;
            }
        }
        // Batch size, in selections: double it while every candidate becomes
        // a point; when newer points cover some, shrink it so that about a
        // fifth more candidates are drawn than survive.
        if (!queue_.empty()) {
            const std::size_t drawn = queue_.size(), placed = since_batch_.size();
            const std::size_t next = placed == drawn
                                         ? 2 * batch_size_
                                         : batch_size_ * (placed + placed / 4 + 1) / drawn;
            batch_size_ = std::max<std::size_t>(1, std::min(kMaxBatch, next));
        }
        drop_queue();
        if (tree_.total() == 0.0) return false;
        draw_batch(batch_size_);
    }
}

void Sampler::insert_dart_points(Delaunay& into, std::vector<std::uint32_t>* vertex_of_point) const {
    if (!darts_) return;
    const std::vector<std::uint32_t> order = darts_->insertion_order();
    const std::vector<Point>& pts = darts_->points();
    if (vertex_of_point != nullptr) vertex_of_point->resize(pts.size());
    std::uint32_t previous = 0;  // each walk starts at the last point: a neighbour
    for (std::uint32_t i : order) {
        previous = into.insert(pts[i], previous);
        if (vertex_of_point != nullptr) (*vertex_of_point)[i] = previous;
    }
}

void Sampler::finish_dart_stage() {
    // Room for all of this was reserved with the dart stage's (ensure_room),
    // except the insertion order, allocated first: std::bad_alloc changes nothing.
    const std::size_t n = count();
    insert_dart_points(dt_, &emitted_);
    tree_.resize(n);
    for (std::size_t site = 0; site < n; ++site) tree_.set_leaf_only(site, cell_measure(site).area);
    tree_.rebuild();
    darts_.reset();
    dart_stage_ = false;
}

Delaunay Sampler::mesh_of_dart_points() const {
    Delaunay mesh(box_);
    mesh.reserve(count() + Delaunay::kGhosts);
    insert_dart_points(mesh, nullptr);
    return mesh;
}

void Sampler::drop_queue() {
    queue_.clear();
    queue_head_ = 0;
    since_batch_.clear();
}

bool Sampler::still_free(const Point& p) const {
    // It was free when drawn; only the points added since can cover it. Most
    // of those are far away: a box test skips them before the exact check.
    const double reach = 1.5 * r_;
    for (std::uint32_t v : since_batch_) {
        const Point& q = dt_.point(v);
        if (std::fabs(p.x - q.x) > reach || std::fabs(p.y - q.y) > reach) continue;
        if (compare_distance(p, q, r_) < 0) return false;
    }
    return true;
}

void Sampler::draw_batch(std::size_t n) {
    double target[kMaxBatch] = {};
    std::size_t sites[kMaxBatch];
    std::uint32_t vertices[kMaxBatch];
    double bound[kMaxBatch];
    const double total = tree_.total();
    for (std::size_t k = 0; k < n; ++k) target[k] = rng_.next_double() * total;
    tree_.select_many(target, n, sites);
    for (std::size_t k = 0; k < n; ++k) {
        vertices[k] = vertex_of(sites[k]);
        bound[k] = tree_.weight(sites[k]);
    }
    dt_.prefetch_rings(vertices, n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t site = sites[k];
        const std::uint32_t v = vertices[k];
        const CellQuery q = cell_query(site);
        // One pass: the chunk holding target u * U; if the exact area A falls
        // short of the target, the selection is rejected.
        const CellSelection sel = select_in_cell(q, ring_of(dt_, v), rng_.next_double() * bound[k]);
        const cell_detail::Chunk* chunk = &sel.chunk();
        if (!sel.found()) {
            // The whole cell was measured: settle doubt, tighten the bound
            // (the same cell may come twice in a batch: only downwards).
            if (sel.measure.doubtful && covered_exactly(site)) {
                tree_.set(site, 0.0);
                continue;
            }
            if (sel.measure.area < tree_.weight(site)) tree_.set(site, sel.measure.area);
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
        if (sample_chunk(q, *chunk, rng_.next_double(), rng_, accept, kMaxDraws, &p) ==
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
    std::uint32_t sources[kMaxBatch];
    for (std::size_t k = 0; k < queue_.size(); ++k) sources[k] = queue_[k].source;
    dt_.prefetch_beyond_rings(sources, queue_.size());
}

bool Sampler::acceptable(const Point& p, std::uint32_t v) const {
    // Exact: inside the domain, at least R from the site, and in the site's
    // Voronoi cell (no Delaunay neighbour strictly closer), hence at least R
    // from every point.
    if (!box_.contains(p)) return false;
    const Point& c = dt_.point(v);
    if (compare_distance(p, c, r_) < 0) return false;
    bool ok = true;
    for_each_neighbour(v, [&](std::uint32_t n) {
        if (ok && !Delaunay::is_ghost(n) && compare_closer(p, c, dt_.point(n)) > 0) ok = false;
    });
    return ok;
}

void Sampler::insert_point(const Point& p, std::uint32_t near) {
    const std::uint32_t v = dt_.insert(p, near);
    // The neighbours' cells only shrank: their weights stay valid upper bounds
    // and are tightened when next selected (measured: re-measuring them here,
    // even only the source cell, costs more than the rejections it saves).
    // Only the new cell is measured.
    tree_.push_back(cell_measure(v - Delaunay::kGhosts).area);
    since_batch_.push_back(v);
    draw_failures_ = 0;
}

bool Sampler::covered_exactly_in(const Delaunay& mesh, std::uint32_t v) const {
    return cell_is_covered_exact(mesh.point(v), ring_points(mesh, v), box_, r_);
}

bool Sampler::has_free_region_in(const Delaunay& mesh, std::uint32_t v) const {
    const CellMeasure m = measure_in(mesh, v);
    if (m.area == 0.0) return false;
    if (!m.doubtful) return true;
    try {
        return !covered_exactly_in(mesh, v);
    } catch (const std::bad_alloc&) {
        return true;  // cannot tell without memory: say there may be room
    }
}

void Sampler::give_up(std::size_t site) {
    if (!covered_exactly(site)) ++stats_.gave_up_cells;
    tree_.set(site, 0.0);
}

bool Sampler::dart_pattern_has_room() const {
    if (count() == 0) return true;
    if (darts_->finds_free_spot()) return true;
    // None of the grid's probes is free: decide on the triangulation.
    const Delaunay mesh = mesh_of_dart_points();
    for (std::uint32_t v = Delaunay::kGhosts; v < mesh.vertex_count(); ++v)
        if (has_free_region_in(mesh, v)) return true;
    return false;
}

bool Sampler::has_room() const {
    if (dart_stage_) {
        try {
            return dart_pattern_has_room();
        } catch (const std::bad_alloc&) {
            return true;  // cannot tell without memory: say there may be room
        }
    }
    // Some cell with a positive bound must have positive free area, decided
    // exactly; nothing is changed, so asking never alters later points. The
    // newest cell is the likeliest candidate, then all others.
    for (std::size_t k = queue_head_; k < queue_.size(); ++k)
        if (still_free(queue_[k].p)) return true;
    if (tree_.total() == 0.0) return false;
    const auto free_cell = [&](std::size_t site) {
        return tree_.weight(site) != 0.0 && has_free_region_in(dt_, vertex_of(site));
    };
    if (free_cell(count() - 1)) return true;
    bool found = false;
    tree_.for_each_positive([&](std::size_t site) {
        if (!found && free_cell(site)) found = true;
        return !found;
    });
    return found;
}

const Point& Sampler::point_at(std::size_t k) const {
    // Points in the order they were added: the dart stage's own list; after
    // the hand-over, its points through emitted_, then the Jones loop's
    // vertices, which are numbered in that order.
    if (darts_) return darts_->points()[k];
    if (k < emitted_.size()) return dt_.point(emitted_[k]);
    return dt_.point(vertex_of(k));
}

std::size_t Sampler::copy_points(std::size_t first, std::size_t n, double* xy) const {
    const std::size_t have = count();
    if (first >= have) return 0;
    n = std::min(n, have - first);
    for (std::size_t i = 0; i < n; ++i) {
        const Point& p = point_at(first + i);
        xy[2 * i] = std::ldexp(p.x, -scale_exp_);
        xy[2 * i + 1] = std::ldexp(p.y, -scale_exp_);
    }
    return n;
}

double Sampler::free_area() const {
    if (count() == 0) return user_domain_.width() * user_domain_.height();
    if (dart_stage_) {
        const Delaunay mesh = mesh_of_dart_points();
        double sum = 0.0;
        for (std::uint32_t v = Delaunay::kGhosts; v < mesh.vertex_count(); ++v) sum += measure_in(mesh, v).area;
        return std::ldexp(sum, -2 * scale_exp_);
    }
    // The tree holds upper bounds; the exact area is re-measured, cell by cell,
    // in leaf order (so the sum is the same on every call).
    double sum = 0.0;
    tree_.for_each_positive([&](std::size_t site) {
        sum += cell_measure(site).area;
        return true;
    });
    return std::ldexp(sum, -2 * scale_exp_);
}

VerifyReport Sampler::verify() const {
    if (dart_stage_) return verify_pattern(mesh_of_dart_points(), box_, r_);
    VerifyReport rep = verify_pattern(dt_, box_, r_);
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
