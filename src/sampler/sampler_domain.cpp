// sampler_domain.cpp - the domain a sampler fills, beyond its rectangle: a
// polygon, a mask's outline, fixed points (see sampler.hpp). The frame keeps
// the polygon in internal units; the Jones stage adopts the fixed points as
// its first vertices before the first sampled point.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "domain/free_room.hpp"
#include "domain/mask_outline.hpp"
#include "sampler/sampler.hpp"

namespace pds {

namespace {

// A mask's outline over box, and the power of two its coordinates are read
// at: the box's reading_exponent, then the internal frame's when the
// outline scales to it exactly (Frame::polygon_reading_exponent). Pixel
// lines scale exactly with the box.
struct MaskPolygon {
    std::shared_ptr<const Polygon> polygon;
    int exponent;
};

MaskPolygon mask_polygon(std::size_t w, std::size_t h, const std::uint8_t* inside, const Box& box) {
    const double corners[4] = {box.x0, box.y0, box.x1, box.y1};
    const int k = reading_exponent(corners, 4);
    const Box read{std::ldexp(box.x0, -k), std::ldexp(box.y0, -k), std::ldexp(box.x1, -k), std::ldexp(box.y1, -k)};
    Outline o = mask_outline(w, h, inside, read);
    const int to_frame = Frame::polygon_reading_exponent(o.xy.data(), o.xy.size());
    if (to_frame != 0)
        for (double& c : o.xy) c = std::ldexp(c, -to_frame);
    try {
        return MaskPolygon{std::make_shared<const Polygon>(o.xy.data(), o.ring_ends.data(), o.ring_ends.size()),
                           k + to_frame};
    } catch (const DomainError& e) {
        // The pixel lines rounded together: the rectangle is too small for
        // the raster at its coordinates.
        throw DomainError(std::string("the mask's pixels do not fit the rectangle at double precision (") +
                          e.what() + ")");
    }
}

// Removes the fixed points marked dropped; the others keep their order.
void erase_dropped(std::vector<Point>& points, std::vector<double>& values, const std::vector<bool>& dropped) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (dropped[k]) continue;
        points[kept] = points[k];
        values[kept++] = values[k];
    }
    points.resize(kept);
    values.resize(kept);
}

// Whether p lies within a few rounding steps of the box [lo, hi] (user units).
bool within_rounding(const Point& p, const Point& lo, const Point& hi) {
    // (The box's sides are at most twice its largest coordinate: no overflow.)
    const double scale = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(hi.x), std::fabs(hi.y)});
    const double slack = 8.0 * std::numeric_limits<double>::epsilon() * scale;
    return p.x >= lo.x - slack && p.x <= hi.x + slack && p.y >= lo.y - slack && p.y <= hi.y + slack;
}

}  // namespace

void Sampler::set_domain(const Box& domain) {
    if (count() != 0) throw std::logic_error("set_domain after the first point");
    if (!mask_.empty()) {
        // The mask spread over the new rectangle, built first: a refusal
        // (pixel lines that round together) changes nothing.
        MaskPolygon outline = mask_polygon(mask_w_, mask_h_, mask_.data(), domain);
        rectangle_ = domain;
        use_shape(std::move(outline.polygon), outline.exponent);
        return;
    }
    rectangle_ = domain;
    if (!shape_) {
        forget_stages();
        frame_.set_domain(domain);
        mean_inverse_square_ = RadiusField::MeanInverseSquare{};
        if (count_target_ != 0) set_count(count_target_);
    }
}

void Sampler::set_polygon(std::shared_ptr<const Polygon> polygon, int exponent) {
    if (count() != 0) throw std::logic_error("set_polygon after the first point");
    mask_.clear();
    mask_w_ = mask_h_ = 0;
    use_shape(std::move(polygon), exponent);
}

void Sampler::set_polygon(const double* xy, const std::size_t* ring_ends, std::size_t rings) {
    // The coordinates' count is known once the ring ends are readable; else
    // the constructor says what is wrong with them.
    bool readable =
        rings > 0 && xy != nullptr && ring_ends != nullptr && ring_ends[rings - 1] <= PolygonRings::kMaxVertices;
    for (std::size_t k = 1; readable && k < rings; ++k) readable = ring_ends[k] >= ring_ends[k - 1];
    const int e = readable ? Frame::polygon_reading_exponent(xy, 2 * ring_ends[rings - 1]) : 0;
    if (e == 0) {
        set_polygon(std::make_shared<const Polygon>(xy, ring_ends, rings));
        return;
    }
    std::vector<double> read(xy, xy + 2 * ring_ends[rings - 1]);
    for (double& c : read) c = std::ldexp(c, -e);
    set_polygon(std::make_shared<const Polygon>(read.data(), ring_ends, rings), e);
}

void Sampler::set_mask(std::size_t w, std::size_t h, const std::uint8_t* inside) {
    if (count() != 0) throw std::logic_error("set_mask after the first point");
    if (w == 0 || h == 0) {
        set_polygon(nullptr);
        return;
    }
    // Built first: a refusal or std::bad_alloc changes nothing.
    MaskPolygon outline = mask_polygon(w, h, inside, rectangle_);
    std::vector<std::uint8_t> copy(inside, inside + w * h);
    use_shape(std::move(outline.polygon), outline.exponent);
    mask_ = std::move(copy);
    mask_w_ = w;
    mask_h_ = h;
}

void Sampler::use_shape(std::shared_ptr<const Polygon> shape, int exponent) {
    forget_stages();
    shape_ = std::move(shape);
    frame_.set_polygon(shape_, exponent);
    if (!shape_) frame_.set_domain(rectangle_);
    mean_inverse_square_ = RadiusField::MeanInverseSquare{};
    if (count_target_ != 0) set_count(count_target_);
}

void Sampler::set_fixed(std::vector<Point> points, std::vector<double> clearances) {
    if (count() != 0) throw std::logic_error("set_fixed after the first point");
    forget_stages();
    fixed_ = std::move(points);
    fixed_clearance_ = std::move(clearances);
}

void Sampler::prepare_fixed(std::vector<Point>& points, std::vector<double>& values) const {
    const PointRadii radii = *point_radii(frame_);
    points.clear();
    values.clear();
    points.reserve(fixed_.size());
    values.reserve(fixed_.size());
    const double rmax = varying_field() ? field_->rmax() : fixed_radius_;
    for (std::size_t k = 0; k < fixed_.size(); ++k) {
        Point p = frame_.to_internal(fixed_[k]);
        const Box& b = frame_.box();
        // The box in the user's units: a mask's is its inside pixels', not its rectangle.
        const Point lo = frame_.to_user(Point{b.x0, b.y0}), hi = frame_.to_user(Point{b.x1, b.y1});
        if (!b.contains(p) && within_rounding(fixed_[k], lo, hi)) {
            // A point the user put on the box (a mask's pixel line computed
            // their way) counts as on it: moved there by the rounding it has.
            p.x = std::min(std::max(p.x, b.x0), b.x1);
            p.y = std::min(std::max(p.y, b.y0), b.y1);
        }
        if (!b.contains(p)) {
            char what[256];
            std::snprintf(what, sizeof what,
                          "fixed point %zu (%g, %g) lies outside the domain's bounding box [%g,%g]x[%g,%g]", k,
                          fixed_[k].x, fixed_[k].y, lo.x, hi.x, lo.y, hi.y);
            throw DomainError(what);
        }
        // A value the field's scaling turns into the clearance, now and after a refine.
        const double c = fixed_clearance_[k];
        values.push_back(c > 0.0 ? unscaled_radius(c, rmax, frame_.user_radius()) : radii.value_at(p));
        points.push_back(p);
    }
    drop_repeated_fixed(points, values);
    merge_nearly_coincident_fixed(points, values, std::ldexp(frame_.r(), -40));
}

void Sampler::start_count_around_fixed() {
    // set_count's start counts the whole domain. The clearances take part
    // of it and add their outline: the first maximal pattern would hold far
    // fewer than n points, and count mode would lower the radius by 1% a
    // step, each a refine of the whole pattern (a clearance of 0.3 in the
    // unit square: at least 15 steps at n = 10^5). The start from the room
    // they leave instead, never above set_count's, from which it is found
    // each time (a first run refused, a fixed point outside the box, leaves
    // nothing to the next).
    frame_.set_radius(count_start_radius());
    const double start = frame_.user_radius();
    std::vector<Point> centres(fixed_.size());
    for (std::size_t k = 0; k < fixed_.size(); ++k) centres[k] = frame_.to_internal(fixed_[k]);
    const bool moves = std::find(fixed_clearance_.begin(), fixed_clearance_.end(), 0.0) != fixed_clearance_.end();
    FreeRoomLattice lattice(frame_);
    std::vector<double> radii(fixed_.size());
    const double n = static_cast<double>(count_target_);
    // The start the room left at radius r asks for (none: no estimate, or
    // nothing left, where count mode lowers the radius until points fit).
    const auto start_at = [&](double r) -> std::optional<double> {
        for (std::size_t k = 0; k < fixed_.size(); ++k)
            radii[k] = frame_.internal_radius(fixed_clearance_[k] > 0.0 ? fixed_clearance_[k] : r);
        const std::optional<FreeRoom> room = lattice.estimate(centres, radii);
        if (!room || !(room->area > 0.0)) return std::nullopt;
        return count_start_factor(n) * frame_.radius_for_count(n, room->area, frame_.perimeter() + room->outline);
    };
    const std::optional<double> first = start_at(start);
    if (first && !(*first < start)) return;
    if (!moves) {
        // The disks do not move: the room they leave gives the start.
        if (first) frame_.set_radius(*first);
        return;
    }
    // A clearance of 0 is the radius, so the room grows as the radius falls:
    // the start is the radius r that start_at(r) gives, between lo, where
    // start_at(lo) >= lo, and hi, where it is below (or nothing is left). The
    // upper end is kept: there the first maximal pattern holds fewer than n.
    double lo = first ? *first : 0.0, hi = start;  // start_at(lo) >= start_at(start) = lo
    for (int halving = 0; lo == 0.0 && halving < 64; ++halving) {
        // Nothing left at the start (the clearances cover the domain):
        // down by halves until room is left for the radius it gives.
        const double r = 0.5 * hi;
        const std::optional<double> at = start_at(r);
        (at && *at >= r ? lo : hi) = r;
    }
    if (lo == 0.0) return;  // the given clearances cover it all
    for (int step = 0; step < 40 && hi > lo * (1.0 + 1e-4); ++step) {
        const double mid = std::sqrt(lo * hi);
        const std::optional<double> at = start_at(mid);
        (at && *at >= mid ? lo : hi) = mid;
    }
    frame_.set_radius(hi);
}

std::vector<std::uint32_t> Sampler::identity_order(std::size_t n) {
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(k);
    return order;
}

void Sampler::merge_nearly_coincident_fixed(std::vector<Point>& points, std::vector<double>& values, double tol) {
    // Two fixed points within tol (2^-40 R) of each other are one: the
    // larger disk (the first of equal ones) stands for both, the other's
    // edge moving by tol at most. Closer, the mesh's triangles around them
    // could be too thin for the floating-point centres of their cells.
    std::vector<std::uint32_t> by_x(points.size());
    for (std::size_t k = 0; k < by_x.size(); ++k) by_x[k] = static_cast<std::uint32_t>(k);
    std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) {
        return points[a].x != points[b].x ? points[a].x < points[b].x : a < b;
    });
    std::vector<bool> dropped(points.size(), false);
    bool any = false;
    for (std::size_t i = 0; i < by_x.size(); ++i) {
        const std::uint32_t a = by_x[i];
        for (std::size_t j = i + 1; j < by_x.size() && !dropped[a] && points[by_x[j]].x - points[a].x <= tol; ++j) {
            const std::uint32_t b = by_x[j];
            if (dropped[b] || std::fabs(points[b].y - points[a].y) > tol) continue;
            const bool keep_a = values[a] > values[b] || (values[a] == values[b] && a < b);
            dropped[keep_a ? b : a] = any = true;
        }
    }
    if (any) erase_dropped(points, values, dropped);
}

void Sampler::drop_repeated_fixed(std::vector<Point>& points, std::vector<double>& values) {
    // A point given twice is one disk, the larger (it holds the other): the
    // mesh takes one vertex a position. The others keep their order.
    std::vector<std::uint32_t> by_place(points.size());
    for (std::size_t k = 0; k < by_place.size(); ++k) by_place[k] = static_cast<std::uint32_t>(k);
    std::sort(by_place.begin(), by_place.end(), [&](std::uint32_t a, std::uint32_t b) {
        return points[a].x != points[b].x   ? points[a].x < points[b].x
               : points[a].y != points[b].y ? points[a].y < points[b].y
                                            : a < b;
    });
    std::vector<bool> dropped(points.size(), false);
    bool any = false;
    for (std::size_t i = 0; i < by_place.size();) {
        std::size_t j = i + 1, keep = i;
        const Point& p = points[by_place[i]];
        for (; j < by_place.size() && points[by_place[j]].x == p.x && points[by_place[j]].y == p.y; ++j) {
            if (values[by_place[j]] > values[by_place[keep]]) keep = j;
        }
        for (std::size_t k = i; k < j; ++k)
            if (k != keep) dropped[by_place[k]] = any = true;
        i = j;
    }
    if (any) erase_dropped(points, values, dropped);
}

}  // namespace pds
