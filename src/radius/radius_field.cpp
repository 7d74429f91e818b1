// radius_field.cpp - radius maps and functions (see radius_field.hpp).
#include "radius/radius_field.hpp"

#include <algorithm>
#include <cmath>

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
    std::size_t i, j;
    double fx, fy;
    locate((x - d.x0) / (d.x1 - d.x0), w_, &i, &fx);
    locate((y - d.y0) / (d.y1 - d.y0), h_, &j, &fy);
    const std::size_t i1 = w_ >= 2 ? i + 1 : i, j1 = h_ >= 2 ? j + 1 : j;
    const double a = map_[j * w_ + i], b = map_[j * w_ + i1];
    const double c = map_[j1 * w_ + i], e = map_[j1 * w_ + i1];
    const double v = (1 - fy) * ((1 - fx) * a + fx * b) + fy * ((1 - fx) * c + fx * e);
    // Rounding may leave the convex combination an ulp outside its corners.
    return std::min(std::max(v, rmin_), rmax_);
}

double RadiusField::mean_inverse_square(const Box& d) const {
    // A 64 x 64 grid of pixel centres: enough for a progress estimate.
    constexpr int kGrid = 64;
    double sum = 0.0;
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            const double x = d.x0 + (i + 0.5) / kGrid * (d.x1 - d.x0);
            const double y = d.y0 + (j + 0.5) / kGrid * (d.y1 - d.y0);
            double v;
            try {
                v = value(d, x, y);
            } catch (const FieldError&) {
                v = rmax_;
            }
            sum += 1.0 / (v * v);
        }
    }
    return sum / (kGrid * kGrid);
}

}  // namespace pds
