// frame.cpp - internal coordinates and limits (see frame.hpp).
#include "domain/frame.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/delaunay.hpp"
#include "mesh/quadedge.hpp"

namespace pds {

namespace {

// Coordinates are scaled so the largest magnitude is in [1, 2); the radius
// must keep this many bits of resolution below it.
constexpr double kMinInternalRadius = 0x1.0p-26;
constexpr double kMinMagnitude = 0x1.0p-900;
// Upper bound on memory per point, for the address-space check on 32-bit.
constexpr std::size_t kBytesPerPointBudget = 256;

double max_magnitude(const Box& b) { return Rectangle(b).largest_magnitude(); }

// Whether coordinates whose largest magnitude is `largest` and smallest
// nonzero one `smallest` scale into the internal frame exactly.
bool scales_exactly(double largest, double smallest) {
    return largest >= kMinMagnitude && smallest >= largest * kMinMagnitude;
}

// Any radius at least the diagonal gives the same one-point pattern; capping
// keeps R^2 finite.
double effective_radius(const Rectangle& domain, double r) {
    const double cap = 2.0 * domain.diameter();
    return r < cap ? r : cap;
}

// The largest period on the torus grid with lo + period <= hi exactly.
double grid_period(double lo, double hi) {
    // hi - lo = s + e exactly (two-sum); rounding s may have gone up.
    const double s = hi - lo;
    const double bv = s - hi;
    const double e = (hi - (s - bv)) + (-lo - bv);
    double p = Torus::snap_down(s);
    if (p > s || (p == s && e < 0.0)) p -= Torus::kQuantum;
    return p;
}

}  // namespace

Frame::Frame(const Box& user_domain, double user_radius)
    : user_domain_(user_domain), user_radius_(user_radius) {
    set_domain(user_domain);
}

void Frame::set_domain(const Box& user_domain) {
    user_domain_ = user_domain;
    // Coordinates too small to scale keep k = 0; precision_limit() refuses them.
    scale_exp_ = max_magnitude(user_domain) < kMinMagnitude ? 0 : -std::ilogb(max_magnitude(user_domain));
    to_user_factor_ = scale_exp_ >= -1023 && scale_exp_ <= 1022 ? std::ldexp(1.0, -scale_exp_) : 0.0;
    Box box = Rectangle(user_domain).scaled(scale_exp_).bounds();
    if (torus_) {
        // Periods on the torus grid, rounded down so every point stays inside
        // the user's rectangle (torus.hpp).
        Torus t;
        t.px = grid_period(box.x0, box.x1);
        t.py = grid_period(box.y0, box.y1);
        t.x0 = box.x0;
        t.y0 = box.y0;
        if (t.px > 0.0 && t.py > 0.0) {
            box.x1 = box.x0 + t.px;
            box.y1 = box.y0 + t.py;
        } else {
            t = Torus{};  // degenerate: precision_limit() refuses it
        }
        torus_ = t;
    }
    domain_ = Rectangle(box);
    polygon_.reset();
    // A polygon's vertices: scaled exactly unless one would underflow, or
    // too small to scale (precision_limit() refuses both).
    const double m = max_magnitude(user_domain);
    // At scale 2^0 the user's polygon is the scaled one: shared, not built again.
    if (user_polygon_ && scales_exactly(m, smallest_vertex_))
        polygon_ = scale_exp_ + user_exp_ == 0 ? user_polygon_
                                                : std::make_shared<const Polygon>(user_polygon_->scaled(scale_exp_ + user_exp_));
    set_radius(user_radius_);
}

void Frame::set_polygon(std::shared_ptr<const Polygon> user_polygon, int user_exp) {
    user_polygon_ = std::move(user_polygon);
    user_exp_ = user_polygon_ ? user_exp : 0;
    smallest_vertex_ = HUGE_VAL;
    if (!user_polygon_) return;
    for (const Point& p : user_polygon_->rings().points())
        for (double c : {std::fabs(p.x), std::fabs(p.y)})
            if (c != 0.0 && c < smallest_vertex_) smallest_vertex_ = c;
    smallest_vertex_ = std::ldexp(smallest_vertex_, user_exp_);
    const Box& b = user_polygon_->bounds();
    set_domain(Box{std::ldexp(b.x0, user_exp_), std::ldexp(b.y0, user_exp_), std::ldexp(b.x1, user_exp_),
                   std::ldexp(b.y1, user_exp_)});
}

int Frame::polygon_reading_exponent(const double* c, std::size_t n) {
    const auto [hi, lo] = magnitudes(c, n);
    // set_domain's scale, when it builds the internal polygon.
    if (scales_exactly(hi, lo)) return std::ilogb(hi);
    return reading_exponent(c, n);
}

void Frame::set_periodic(bool periodic) {
    if (periodic) torus_.emplace();
    else torus_.reset();
    set_domain(user_domain_);
}

void Frame::set_radius(double user_radius) {
    user_radius_ = user_radius;
    r_ = internal_radius(user_radius);
}

bool Frame::periods_beyond(double ratio) const {
    // In the scaled frame: the user's sides may overflow (-1.7e308 to
    // 1.7e308), their scaled copies cannot, and scaling by 2^k keeps the ratio.
    const Box user = Rectangle(user_domain_).scaled(scale_exp_).bounds();
    const double w = user.x1 - user.x0, h = user.y1 - user.y0;
    return periodic() && std::max(w, h) > ratio * std::min(w, h);
}

double Frame::internal_radius(double user_radius) const {
    return effective_radius(domain_, std::ldexp(user_radius, scale_exp_));
}

Limit Frame::precision_limit() const {
    const double m = max_magnitude(user_domain_);
    if (m < kMinMagnitude) return Limit::coordinates_too_small;
    // Scaling is exact only while no coordinate underflows: a nonzero one far
    // below the largest would lose its bits (and exact products need room
    // below every value).
    const double coords[4] = {user_domain_.x0, user_domain_.y0, user_domain_.x1, user_domain_.y1};
    for (double c : coords)
        if (c != 0.0 && std::fabs(c) < m * kMinMagnitude) return Limit::coordinates_too_small;
    if (user_polygon_ && smallest_vertex_ < m * kMinMagnitude) return Limit::coordinates_too_small;
    if (!(std::ldexp(user_radius_, scale_exp_) >= kMinInternalRadius)) return Limit::radius_below_precision;
    if (periodic()) {
        if (!torus().on()) return Limit::radius_below_precision;
        // Against the user's periods: their rounding onto the grid (below
        // 2^-50) must not refuse R = period / 2.
        const Box user = Rectangle(user_domain_).scaled(scale_exp_).bounds();
        const double shorter = std::min(user.x1 - user.x0, user.y1 - user.y0);
        const double longer = std::max(user.x1 - user.x0, user.y1 - user.y0);
        if (longer > kMaxPeriodRatio * shorter) return Limit::periods_too_unequal;
        if (2.0 * r_ > shorter) return Limit::radius_exceeds_period;
    }
    return Limit::ok;
}

double Frame::count_bound() const { return polygon_ ? polygon_->count_bound(r_) : domain_.count_bound(r_); }

namespace {
constexpr double kSaturationCoverage = 0.547;  // pi R^2 N / (4 A) of a maximal RSA pattern
constexpr double kEdgeExcess = 0.23;           // extra points per R of a rectangle's perimeter
}  // namespace

double Frame::expected_count(double user_radius) const {
    const double r = std::ldexp(user_radius, scale_exp_);
    const double a = area(), perimeter = this->perimeter();
    const double bulk = kSaturationCoverage * 4.0 * a / (M_PI * r * r);
    return periodic() ? bulk : bulk + kEdgeExcess * perimeter / r;
}

double Frame::max_radius() const {
    if (!periodic()) return HUGE_VAL;
    // Scaled and back, exactly: a user side may overflow (periods_beyond).
    const Box user = Rectangle(user_domain_).scaled(scale_exp_).bounds();
    const double w = user.x1 - user.x0, h = user.y1 - user.y0;
    return std::ldexp(0.5 * std::min(w, h), -scale_exp_);
}

double Frame::radius_for_count(double n, double area, double perimeter) const {
    // n = a / r^2 + b / r, solved for r > 0.
    const double a = kSaturationCoverage * 4.0 * area / M_PI;
    const double b = periodic() ? 0.0 : kEdgeExcess * perimeter;
    const double r = (b + std::sqrt(b * b + 4.0 * a * n)) / (2.0 * n);
    return std::ldexp(r, -scale_exp_);
}

double Frame::lowest_count_radius(double n) const {
    constexpr double kBelowEveryStep = 0.98;
    const double area = this->area();
    return std::ldexp(kBelowEveryStep * std::sqrt(area / (M_PI * n)), -scale_exp_);
}

std::size_t Frame::count_bound_points() const {
    const double bound = count_bound();
    const double cap = static_cast<double>(max_points()) + 1.0;
    return static_cast<std::size_t>(bound < cap ? bound : cap);
}

std::size_t Frame::max_points() {
    const std::size_t by_edges = kMaxEdgeRecords / 3 - Delaunay::kGhosts;
    const std::size_t by_memory = static_cast<std::size_t>(-1) / 2 / kBytesPerPointBudget;
    return std::min(by_edges, by_memory);
}

Point Frame::to_internal(const Point& user) const {
    return Point{std::ldexp(user.x, scale_exp_), std::ldexp(user.y, scale_exp_)};
}

double Frame::area_to_user(double a) const { return std::ldexp(a, -2 * scale_exp_); }

}  // namespace pds
