// sampler_queries.cpp - what a sampler tells without adding points (see
// sampler.hpp): its points and radii in the caller's units, the free area
// left, and the independent verification.
#include <algorithm>
#include <optional>

#include "radius/point_radii.hpp"
#include "sampler/sampler.hpp"

namespace pds {

std::size_t Sampler::copy_points(std::size_t first, std::size_t n, double* xy) const {
    const std::size_t have = count();
    if (first >= have) return 0;
    n = std::min(n, have - first);
    const Stage& s = stage();
    constexpr std::size_t kChunk = 512;
    Point chunk[kChunk];
    for (std::size_t done = 0; done < n; done += kChunk) {
        const std::size_t m = std::min(kChunk, n - done);
        s.copy_points(static_cast<PointIndex>(adopted_fixed_ + first + done), m, chunk);
        for (std::size_t i = 0; i < m; ++i) {
            const Point p = frame_.to_user(chunk[i]);
            xy[2 * (done + i)] = p.x;
            xy[2 * (done + i) + 1] = p.y;
        }
    }
    return n;
}

std::size_t Sampler::copy_radii(std::size_t first, std::size_t n, double* r) const {
    const std::size_t have = count();
    if (first >= have) return 0;
    n = std::min(n, have - first);
    const std::optional<PointRadii> radii = point_radii(frame_);
    for (std::size_t i = 0; i < n; ++i)
        r[i] = radii ? radii->user_radius_of(stage().value(adopted_fixed_ + first + i)) : frame_.user_radius();
    return n;
}

double Sampler::free_area() const {
    // Adopted fixed points are the stage's own: their clearances count even
    // before the first point (they may leave no room for one).
    const double whole = frame_.area_to_user(frame_.area());
    if (!stage_holds_points()) return whole;
    // Summed cell by cell, a few points' huge cells (a bounded run in a
    // domain 10^7 R wide) may pass the domain's area by rounding; the free
    // area cannot.
    return std::min(whole, frame_.area_to_user(stage().free_area()));
}

VerifyReport Sampler::verify() const {
    if (!stage_holds_points()) {
        VerifyReport rep;
        rep.failure = "no points yet";
        return rep;
    }
    return stage().verify();
}

}  // namespace pds
