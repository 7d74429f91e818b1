// dart_throwing.hpp - the reference sampler for the law test: plain dart
// throwing run to true saturation, after Ebeida et al., "Efficient maximal
// Poisson-disk sampling" (SIGGRAPH 2011).
//
// Darts are uniform over the union of equal-size "active" squares that may
// still contain free area; a dart is kept when it is in the domain and at
// least R from every point. Since the active squares always contain the whole
// free area, every kept dart is uniform over the free area: the exact
// random-sequential-adsorption law. A square is dropped only when one disk
// covers it entirely; after a batch of darts the survivors are split in four.
// It stops when no square is left, i.e. at true saturation (a fixed budget of
// misses would stop early and bias the count low).
#ifndef PDS_TEST_DART_THROWING_HPP
#define PDS_TEST_DART_THROWING_HPP

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/point.hpp"

class SaturatedDartThrowing {
public:
    SaturatedDartThrowing(const pds::Box& box, double r) : box_(box), r_(r), r2_(r * r) {
        grid_ = r;  // neighbour grid: points closer than R are in adjacent cells
        gx_ = static_cast<int>(std::ceil(box.width() / grid_)) + 1;
        gy_ = static_cast<int>(std::ceil(box.height() / grid_)) + 1;
    }

    // A maximal pattern for this seed; `levels` receives the refinement depth.
    std::vector<pds::Point> run(std::uint64_t seed, int* levels = nullptr) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        points_.clear();
        buckets_.assign(static_cast<std::size_t>(gx_) * gy_, {});
        // Level-0 squares of side R/sqrt(2): one point covers its square.
        double side = r_ / std::sqrt(2.0);
        std::vector<Square> active;
        const int nx = static_cast<int>(std::ceil(box_.width() / side));
        const int ny = static_cast<int>(std::ceil(box_.height() / side));
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < ny; ++j) active.push_back({box_.x0 + i * side, box_.y0 + j * side});
        int level = 0;
        while (!active.empty()) {
            if (++level > 60) break;  // squares below double resolution: not expected
            const std::size_t darts = active.size();
            for (std::size_t k = 0; k < darts && !active.empty(); ++k) {
                const std::size_t pick = static_cast<std::size_t>(u01(rng) * static_cast<double>(active.size()));
                const Square sq = active[pick < active.size() ? pick : active.size() - 1];
                const pds::Point p{sq.x + u01(rng) * side, sq.y + u01(rng) * side};
                if (box_.contains(p) && !covered(p)) add(p);
                if (covered_square(sq, side)) {
                    active[pick < active.size() ? pick : active.size() - 1] = active.back();
                    active.pop_back();
                }
            }
            // Split the survivors; keep children that meet the domain and are
            // not inside a single disk.
            side *= 0.5;
            std::vector<Square> next;
            for (const Square& sq : active) {
                for (int c = 0; c < 4; ++c) {
                    const Square child{sq.x + (c & 1) * side, sq.y + (c >> 1) * side};
                    if (child.x > box_.x1 || child.y > box_.y1) continue;
                    if (!covered_square(child, side)) next.push_back(child);
                }
            }
            active.swap(next);
        }
        if (levels) *levels = level;
        return points_;
    }

private:
    struct Square {
        double x, y;  // lower-left corner
    };

    int bucket_x(double x) const { return std::min(gx_ - 1, std::max(0, static_cast<int>((x - box_.x0) / grid_))); }
    int bucket_y(double y) const { return std::min(gy_ - 1, std::max(0, static_cast<int>((y - box_.y0) / grid_))); }

    template <class F>
    bool any_near(double x, double y, int reach, const F& f) const {
        const int cx = bucket_x(x), cy = bucket_y(y);
        for (int i = cx - reach; i <= cx + reach; ++i)
            for (int j = cy - reach; j <= cy + reach; ++j) {
                if (i < 0 || j < 0 || i >= gx_ || j >= gy_) continue;
                for (std::size_t k : buckets_[static_cast<std::size_t>(j) * gx_ + i])
                    if (f(points_[k])) return true;
            }
        return false;
    }

    bool covered(const pds::Point& p) const {
        return any_near(p.x, p.y, 1, [&](const pds::Point& q) {
            const double dx = p.x - q.x, dy = p.y - q.y;
            return dx * dx + dy * dy < r2_;
        });
    }

    // Inside one disk: all four corners within R of the same point.
    bool covered_square(const Square& sq, double side) const {
        const double cx = sq.x + side / 2, cy = sq.y + side / 2;
        return any_near(cx, cy, 2, [&](const pds::Point& q) {
            for (int c = 0; c < 4; ++c) {
                const double dx = sq.x + (c & 1) * side - q.x, dy = sq.y + (c >> 1) * side - q.y;
                if (dx * dx + dy * dy > r2_) return false;
            }
            return true;
        });
    }

    void add(const pds::Point& p) {
        buckets_[static_cast<std::size_t>(bucket_y(p.y)) * gx_ + bucket_x(p.x)].push_back(points_.size());
        points_.push_back(p);
    }

    pds::Box box_;
    double r_, r2_, grid_;
    int gx_, gy_;
    std::vector<pds::Point> points_;
    std::vector<std::vector<std::size_t>> buckets_;
};

#endif
