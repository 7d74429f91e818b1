// field_dart_throwing.hpp - the reference for the variable-radius law tests:
// saturated dart throwing (as dart_throwing.hpp) under the variable-radius
// rule: a dart is kept when it lies outside every earlier disk,
// |p - p_i| >= r_i, and then carries r(p). Darts are uniform over equal
// squares that may still hold free area (level 0: side rmin / sqrt 2), so
// every kept dart is uniform over the free region; a square is dropped when
// one disk covers it, and the survivors are split in four, until none is
// left (true saturation). Independent of the library: plain floating point
// and a bucket grid of side rmax. Periodic: the box is a torus, distances
// wrap (the nearest copy), buckets divide the periods, and darts in squares
// overhanging the far sides are refused (not wrapped), so no area counts
// twice.
#ifndef PDS_TEST_FIELD_DART_THROWING_HPP
#define PDS_TEST_FIELD_DART_THROWING_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/point.hpp"

class FieldDartThrowing {
public:
    using Field = double (*)(void*, double, double);

    FieldDartThrowing(const pds::Box& box, Field field, double rmin, double rmax, bool periodic = false)
        : box_(box), field_(field), rmin_(rmin), grid_(rmax), periodic_(periodic) {
        if (periodic) {
            // Cells at least rmax wide that divide the periods.
            gx_ = std::max(1, static_cast<int>(box.width() / rmax));
            gy_ = std::max(1, static_cast<int>(box.height() / rmax));
            cell_x_ = box.width() / gx_;
            cell_y_ = box.height() / gy_;
        } else {
            gx_ = static_cast<int>(std::ceil(box.width() / grid_)) + 1;
            gy_ = static_cast<int>(std::ceil(box.height() / grid_)) + 1;
            cell_x_ = cell_y_ = grid_;
        }
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
                const bool inside = periodic_ ? p.x < box_.x1 && p.y < box_.y1 : box_.contains(p);
                if (inside && !covered(p)) add(p);
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

    int bucket_x(double x) const { return std::min(gx_ - 1, std::max(0, static_cast<int>((x - box_.x0) / cell_x_))); }
    int bucket_y(double y) const { return std::min(gy_ - 1, std::max(0, static_cast<int>((y - box_.y0) / cell_y_))); }

    // Every point in the buckets within `reach` of (x, y)'s (wrapping on a
    // torus, each bucket once).
    template <class F>
    bool any_near(double x, double y, int reach, const F& f) const {
        const int cx = bucket_x(x), cy = bucket_y(y);
        std::vector<std::size_t> seen;
        for (int i = cx - reach; i <= cx + reach; ++i)
            for (int j = cy - reach; j <= cy + reach; ++j) {
                int a = i, b = j;
                if (periodic_) {
                    a = ((a % gx_) + gx_) % gx_;
                    b = ((b % gy_) + gy_) % gy_;
                } else if (a < 0 || b < 0 || a >= gx_ || b >= gy_) {
                    continue;
                }
                const std::size_t cell = static_cast<std::size_t>(b) * gx_ + a;
                if (std::find(seen.begin(), seen.end(), cell) != seen.end()) continue;
                seen.push_back(cell);
                for (std::size_t k : buckets_[cell])
                    if (f(k)) return true;
            }
        return false;
    }

    // The displacement to the nearest copy (a torus) or plain.
    double delta(double d, double period) const {
        if (!periodic_) return d;
        d = std::fabs(d);
        return d > 0.5 * period ? period - d : d;
    }
    double d2(double x, double y, const pds::Point& q) const {
        const double dx = delta(x - q.x, box_.width()), dy = delta(y - q.y, box_.height());
        return dx * dx + dy * dy;
    }

    bool covered(const pds::Point& p) const {
        return any_near(p.x, p.y, 1, [&](std::size_t k) { return d2(p.x, p.y, points_[k]) < radii_[k] * radii_[k]; });
    }

    // Inside one disk: all four corners within one copy of it. On the torus
    // the corners' copies must be the same: the square's centre's nearest
    // copy (a square is far smaller than half a period).
    bool covered_square(const Square& sq, double side) const {
        return any_near(sq.x + side / 2, sq.y + side / 2, 2, [&](std::size_t k) {
            double qx = points_[k].x, qy = points_[k].y;
            if (periodic_) {
                const double cx = sq.x + side / 2, cy = sq.y + side / 2;
                qx += box_.width() * std::round((cx - qx) / box_.width());
                qy += box_.height() * std::round((cy - qy) / box_.height());
            }
            for (int c = 0; c < 4; ++c) {
                const double dx = sq.x + (c & 1) * side - qx, dy = sq.y + (c >> 1) * side - qy;
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
    bool periodic_;
    double cell_x_ = 0, cell_y_ = 0;
    int gx_, gy_;
    std::vector<pds::Point> points_;
    std::vector<double> radii_;
    std::vector<std::vector<std::size_t>> buckets_;
};

#endif
