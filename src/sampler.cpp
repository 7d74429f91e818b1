// sampler.cpp - the Jones loop (see sampler.hpp).
#include "sampler.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
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
    const double cap = 2.0 * std::hypot(b.width(), b.height());
    return r < cap ? r : cap;
}

}  // namespace

Sampler::Sampler(double radius, std::uint64_t seed)
    : rng_(seed), user_domain_(kUnitSquare), user_radius_(radius), dt_(kUnitSquare) {
    set_frame(kUnitSquare, radius);
    ensure_room(1);
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
    user_domain_ = domain;
    set_frame(domain, user_radius_);
}

void Sampler::ensure_room(std::size_t points) {
    const std::size_t vertices = points + Delaunay::kGhosts;
    if (dt_.points().capacity() >= vertices && tree_.capacity() >= points &&
        doubtful_.capacity() >= points && dt_.has_room_for_one())
        return;
    // Each reserve either succeeds or leaves its container as it was.
    dt_.reserve(vertices);
    tree_.reserve(points);
    doubtful_.reserve(points);
    if (ring_scratch_.capacity() < 64) ring_scratch_.reserve(64);
}

bool Sampler::step() {
    const std::size_t n = count();
    const bool room = dt_.has_room_for_one() && tree_.capacity() > n && doubtful_.capacity() > n;
    if (!room) {
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
    *maximal = !more || tree_.total() == 0.0;
    return added;
}

void Sampler::refine(double radius) {
    user_radius_ = radius;
    r_ = effective_radius(box_, std::ldexp(radius, scale_exp_));
    for (std::size_t site = 0; site < count(); ++site) {
        const CellMeasure m = measure_cell(cell_query(site), [&](const auto& visit) {
            for_each_neighbour(vertex_of(site), [&](std::uint32_t n) { visit(dt_.point(n)); });
        });
        tree_.set_leaf_only(site, m.area);
        doubtful_[site] = m.doubtful;
    }
    tree_.rebuild();
}

CellQuery Sampler::cell_query(std::size_t site) const {
    return CellQuery{dt_.point(vertex_of(site)), box_, r_};
}

std::vector<Point> Sampler::cell_ring(std::size_t site) const {
    std::vector<Point> ring;
    for_each_neighbour(vertex_of(site), [&](std::uint32_t n) { ring.push_back(dt_.point(n)); });
    return ring;
}

bool Sampler::add_one() {
    if (count() == 0) {
        // The whole domain is free: the first point is uniform in it.
        Point p{box_.x0 + rng_.next_double() * box_.width(),
                box_.y0 + rng_.next_double() * box_.height()};
        p.x = std::min(p.x, box_.x1);
        p.y = std::min(p.y, box_.y1);
        insert_point(p, 0);
        return true;
    }
    int failures = 0;
    for (;;) {
        const double total = tree_.total();
        if (total == 0.0) return false;
        const std::size_t site = tree_.select(rng_.next_double() * total);
        if (doubtful_[site]) {
            // Decide before sampling; either way the next draw starts afresh,
            // which keeps the law exact (a covered cell only ever rejects).
            resolve_doubtful(site);
            continue;
        }
        const std::uint32_t v = vertex_of(site);
        const auto ring = [&](const auto& visit) {
            for_each_neighbour(v, [&](std::uint32_t n) { visit(dt_.point(n)); });
        };
        const auto accept = [&](const Point& p) { return acceptable(p, v); };
        Point p;
        const SampleOutcome outcome =
            sample_cell(cell_query(site), ring, tree_.weight(site), rng_, accept, kMaxDraws, &p);
        if (outcome == SampleOutcome::placed) {
            insert_point(p, v);
            return true;
        }
        // A healthy cell practically never fails 64 draws; a cell that keeps
        // failing has a free region below double resolution, or none.
        ++stats_.failed_draw_rounds;
        if (++failures % kFailuresPerGiveUp == 0) give_up(site);
    }
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
    tree_.push_back(0.0);
    doubtful_.push_back(0);
    update_cell(v);
    // Only the new point's Delaunay neighbours lost area (paper, step 5);
    // a covered cell stays covered, since cells only shrink.
    for_each_neighbour(v, [&](std::uint32_t n) {
        if (!Delaunay::is_ghost(n) && tree_.weight(n - Delaunay::kGhosts) > 0.0) update_cell(n);
    });
}

void Sampler::update_cell(std::uint32_t v) {
    const std::size_t site = v - Delaunay::kGhosts;
    const CellMeasure m = measure_cell(cell_query(site), [&](const auto& visit) {
        for_each_neighbour(v, [&](std::uint32_t n) { visit(dt_.point(n)); });
    });
    tree_.set(site, m.area);
    doubtful_[site] = m.doubtful;
}

bool Sampler::covered_exactly(std::size_t site) {
    ++stats_.exact_classifications;
    ring_scratch_.clear();
    for_each_neighbour(vertex_of(site), [&](std::uint32_t n) { ring_scratch_.push_back(dt_.point(n)); });
    return cell_is_covered_exact(dt_.point(vertex_of(site)), ring_scratch_, box_, r_);
}

void Sampler::resolve_doubtful(std::size_t site) {
    const bool covered = covered_exactly(site);  // may throw bad_alloc: nothing changed yet
    doubtful_[site] = 0;
    if (covered) tree_.set(site, 0.0);
}

void Sampler::give_up(std::size_t site) {
    if (!covered_exactly(site)) ++stats_.gave_up_cells;
    doubtful_[site] = 0;
    tree_.set(site, 0.0);
}

std::size_t Sampler::copy_points(std::size_t first, std::size_t n, double* xy) const {
    const std::size_t have = count();
    if (first >= have) return 0;
    n = std::min(n, have - first);
    const Point* src = dt_.points().data() + Delaunay::kGhosts + first;
    if (scale_exp_ == 0) {
        std::memcpy(xy, src, n * sizeof(Point));
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            xy[2 * i] = std::ldexp(src[i].x, -scale_exp_);
            xy[2 * i + 1] = std::ldexp(src[i].y, -scale_exp_);
        }
    }
    return n;
}

double Sampler::free_area() const {
    if (count() == 0) return user_domain_.width() * user_domain_.height();
    return std::ldexp(tree_.total(), -2 * scale_exp_);
}

VerifyReport Sampler::verify() const {
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

std::size_t Sampler::memory_bytes() const {
    return dt_.memory_bytes() + tree_.memory_bytes() + doubtful_.capacity() +
           ring_scratch_.capacity() * sizeof(Point);
}

}  // namespace pds
