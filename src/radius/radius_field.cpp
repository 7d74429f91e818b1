// radius_field.cpp - radius maps and functions (see radius_field.hpp).
#include "radius/radius_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pds {

RadiusField RadiusField::map(std::size_t w, std::size_t h, const double* values) {
    RadiusField f;
    f.map_.assign(values, values + w * h);
    f.w_ = w;
    f.h_ = h;
    const auto mm = std::minmax_element(f.map_.begin(), f.map_.end());
    f.rmin_ = *mm.first;
    f.rmax_ = *mm.second;
    return f;
}

RadiusField RadiusField::function(Function fn, void* user, double rmin, double rmax) {
    RadiusField f;
    f.fn_ = fn;
    f.user_ = user;
    f.rmin_ = rmin;
    f.rmax_ = rmax;
    return f;
}

namespace {

// Where v lies between lo and hi, as a fraction of hi - lo. A domain may
// span more than the largest double (-1.7e308 to 1.7e308): its width and
// v - lo would overflow to inf/inf; halving every term is exact (bar
// subnormals) and cannot overflow, and where the width is finite the
// direct form is used, giving the same bits as always.
double fraction(double v, double lo, double hi) {
    const double width = hi - lo;
    if (std::isfinite(width)) return (v - lo) / width;
    return (0.5 * v - 0.5 * lo) / (0.5 * hi - 0.5 * lo);
}

// The point a fraction t in [0, 1] of the way from lo to hi, without
// overflow (see fraction()).
double between(double lo, double hi, double t) {
    const double width = hi - lo;
    if (std::isfinite(width)) return lo + t * width;
    return (1.0 - t) * lo + t * hi;
}

// Pixel-centre coordinate of t in [0, 1] over n pixels, clamped to
// [0, n - 1]; its cell i and the weight of i + 1.
void locate(double t, std::size_t n, std::size_t* i, double* frac) {
    const double u = std::min(std::max(t * static_cast<double>(n) - 0.5, 0.0), static_cast<double>(n - 1));
    std::size_t k = static_cast<std::size_t>(u);
    if (k + 1 >= n) k = n >= 2 ? n - 2 : 0;
    *i = k;
    *frac = n >= 2 ? u - static_cast<double>(k) : 0.0;
}

}  // namespace

double RadiusField::value(const Box& d, double x, double y) const {
    if (fn_) {
        const double v = fn_(user_, x, y);
        if (!(v >= rmin_ && v <= rmax_)) throw FieldError(v, x, y);  // NaN fails too
        return v;
    }
    // A point outside the plane (NaN, inf) has no place in the map: its
    // index would be undefined. The stages never ask for one.
    if (!std::isfinite(x) || !std::isfinite(y)) throw std::logic_error("radius map asked at a non-finite point");
    std::size_t i, j;
    double fx, fy;
    locate(fraction(x, d.x0, d.x1), w_, &i, &fx);
    locate(fraction(y, d.y0, d.y1), h_, &j, &fy);
    const std::size_t i1 = w_ >= 2 ? i + 1 : i, j1 = h_ >= 2 ? j + 1 : j;
    const double a = map_[j * w_ + i], b = map_[j * w_ + i1];
    const double c = map_[j1 * w_ + i], e = map_[j1 * w_ + i1];
    const double v = (1 - fy) * ((1 - fx) * a + fx * b) + fy * ((1 - fx) * c + fx * e);
    // Rounding may leave the convex combination an ulp outside its corners.
    // A NaN cannot come from finite weights in [0, 1] and finite corners; if
    // it ever did, clamping would pass it on (NaN fails every comparison).
    if (std::isnan(v)) throw std::logic_error("radius map interpolated to NaN");
    return std::min(std::max(v, rmin_), rmax_);
}

double RadiusField::map_count_bound(const Box& box, const std::function<double(double)>& radius_of) const {
    // The lines through the pixel centres cut the domain into (w + 1) x
    // (h + 1) rectangles (the outer ones are the clamped margins). In each,
    // the field lies between the values at its corners (bilinear between
    // centres, constant across a margin), so it is at least their least, m.
    // Point i keeps every later point r_i >= m away: the points in one
    // rectangle are pairwise at least radius_of(m) apart, and Oler's bound
    // (frame.hpp) holds for each; the rectangles cover the domain, so the
    // sum bounds the pattern. Neighbours share their computed edges, so
    // rounding leaves no gap; the margin covers rounding in the radii.
    if (fn_ != nullptr) return HUGE_VAL;
    const auto edge = [](double lo, double hi, std::size_t k, std::size_t n) {
        return k == 0 ? lo : k == n + 1 ? hi : between(lo, hi, (static_cast<double>(k) - 0.5) / static_cast<double>(n));
    };
    const auto at = [this](std::size_t i, std::size_t j) { return map_[j * w_ + i]; };
    double sum = 0.0;
    for (std::size_t j = 0; j <= h_; ++j) {
        const double ylo = edge(box.y0, box.y1, j, h_), yhi = edge(box.y0, box.y1, j + 1, h_);
        const std::size_t j0 = j == 0 ? 0 : j - 1, j1 = j == h_ ? h_ - 1 : j;
        for (std::size_t i = 0; i <= w_; ++i) {
            const double xlo = edge(box.x0, box.x1, i, w_), xhi = edge(box.x0, box.x1, i + 1, w_);
            const std::size_t i0 = i == 0 ? 0 : i - 1, i1 = i == w_ ? w_ - 1 : i;
            const double m = std::min(std::min(at(i0, j0), at(i1, j0)), std::min(at(i0, j1), at(i1, j1)));
            const double d = radius_of(m);
            const double cw = (xhi - xlo) / d, ch = (yhi - ylo) / d;
            sum += 2.0 / std::sqrt(3.0) * cw * ch + (cw + ch) + 1.0;
        }
    }
    constexpr double kRoundingMargin = 1.0 + 1e-9;
    return sum * kRoundingMargin;
}

void RadiusField::MeanInverseSquare::step(const RadiusField& field, const Box& d) {
    // Pixel centres of a kMeanGrid x kMeanGrid grid, row by row: enough for
    // a progress estimate. A value out of bounds counts as rmax (no error).
    const int i = next_ % kMeanGrid, j = next_ / kMeanGrid;
    const double x = between(d.x0, d.x1, (i + 0.5) / kMeanGrid);
    const double y = between(d.y0, d.y1, (j + 0.5) / kMeanGrid);
    double v;
    try {
        v = field.value(d, x, y);
    } catch (const FieldError&) {
        v = field.rmax();
    }
    sum_ += 1.0 / (v * v);
    ++next_;
}

}  // namespace pds
