// field_dart_throwing.hpp - the reference for the variable-radius law tests:
// saturated dart throwing (as dart_throwing.hpp) under the variable-radius
// rule: a dart is kept when it lies outside every earlier disk,
// |p - p_i| >= r_i, and then carries r(p). Darts are uniform over equal
// squares that may still hold free area (level 0: side rmin / sqrt 2), so
// every kept dart is uniform over the free region; a square is dropped when
// one disk covers it, and the survivors are split in four, until none is
// left (true saturation). Independent of the library: plain floating point
// and a bucket grid of side rmax.
#ifndef PDS_TEST_FIELD_DART_THROWING_HPP
#define PDS_TEST_FIELD_DART_THROWING_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "point.hpp"

class FieldDartThrowing {
public:
    using Field = double (*)(void*, double, double);

    FieldDartThrowing(const pds::Box& box, Field field, double rmin, double rmax)
        : box_(box), field_(field), rmin_(rmin), grid_(rmax) {
        gx_ = static_cast<int>(std::ceil(box.width() / grid_)) + 1;
        gy_ = static_cast<int>(std::ceil(box.height() / grid_)) + 1;
    }

    // A maximal pattern for this seed; radii[i] is point i's radius.
    std::vector<pds::Point> run(std::uint64_t seed, std::vector<double>* radii) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        points_.clear();
        radii_.clear();
        buckets_.assign(static_cast<std::size_t>(gx_) * gy_, {});
        double side = rmin_ / std::sqrt(2.0);
        std::vector<Square> active;
        const int nx = static_cast<int>(std::ceil(box_.width() / side));
        const int ny = static_cast<int>(std::ceil(box_.height() / side));
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < ny; ++j) active.push_back({box_.x0 + i * side, box_.y0 + j * side});
        for (int level = 0; !active.empty() && level < 60; ++level) {
            const std::size_t darts = active.size();
            for (std::size_t k = 0; k < darts && !active.empty(); ++k) {
                std::size_t pick = static_cast<std::size_t>(u01(rng) * static_cast<double>(active.size()));
                if (pick >= active.size()) pick = active.size() - 1;
                const Square sq = active[pick];
                const pds::Point p{sq.x + u01(rng) * side, sq.y + u01(rng) * side};
                if (box_.contains(p) && !covered(p)) add(p);
                if (covered_square(sq, side)) {
                    active[pick] = active.back();
                    active.pop_back();
                }
            }
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
        *radii = radii_;
        return points_;
    }

private:
    struct Square {
        double x, y;
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
                    if (f(k)) return true;
            }
        return false;
    }

    bool covered(const pds::Point& p) const {
        return any_near(p.x, p.y, 1, [&](std::size_t k) {
            const double dx = p.x - points_[k].x, dy = p.y - points_[k].y;
            return dx * dx + dy * dy < radii_[k] * radii_[k];
        });
    }

    bool covered_square(const Square& sq, double side) const {
        return any_near(sq.x + side / 2, sq.y + side / 2, 2, [&](std::size_t k) {
            for (int c = 0; c < 4; ++c) {
                const double dx = sq.x + (c & 1) * side - points_[k].x, dy = sq.y + (c >> 1) * side - points_[k].y;
                if (dx * dx + dy * dy > radii_[k] * radii_[k]) return false;
            }
            return true;
        });
    }

    void add(const pds::Point& p) {
        buckets_[static_cast<std::size_t>(bucket_y(p.y)) * gx_ + bucket_x(p.x)].push_back(points_.size());
        points_.push_back(p);
        radii_.push_back(field_(nullptr, p.x, p.y));
    }

    pds::Box box_;
    Field field_;
    double rmin_, grid_;
    int gx_, gy_;
    std::vector<pds::Point> points_;
    std::vector<double> radii_;
    std::vector<std::vector<std::size_t>> buckets_;
};

#endif
