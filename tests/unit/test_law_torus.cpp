// test_law_torus.cpp - on the torus (Sampler::set_periodic) the sampler
// follows the random-sequential-adsorption law too: over many seeds, the
// distribution of the final count N and of the number of near-contact pairs
// (wrapped distance < 1.2 R) matches saturated dart throwing on the torus,
// written here with wrapped distances and independent of the library.
//
// The statistics and thresholds are those of test_law.cpp (law_compare.hpp). A sampler that treats the
// seam as a wall packs extra points along it (about 0.23 per R of
// perimeter): N moves by many standard errors.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/point.hpp"
#include "law_compare.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

// Wrapped displacement along one period.
double wrap_delta(double d, double period) {
    d = std::fabs(d);
    return d > 0.5 * period ? period - d : d;
}

// Plain dart throwing on the torus [x0,x1) x [y0,y1), run to true
// saturation as in dart_throwing.hpp (Ebeida et al. 2011): darts are uniform
// over active squares that hold all the free area; a dart is kept when it is
// in the fundamental domain and at least R from every point (wrapped); a
// square is dropped once a single disk (one copy of a point) covers it;
// survivors split in four until none is left. Squares may overhang the far
// sides: darts there are refused, not wrapped, so no part counts twice.
class TorusDartThrowing {
public:
    TorusDartThrowing(const pds::Box& box, double r) : box_(box), r_(r), r2_(r * r) {
        // Bucket cells at least R wide divide the periods evenly.
        gx_ = std::max(1, static_cast<int>(box.width() / r));
        gy_ = std::max(1, static_cast<int>(box.height() / r));
    }

    std::vector<pds::Point> run(std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        points_.clear();
        buckets_.assign(static_cast<std::size_t>(gx_) * gy_, {});
        double side = r_ / std::sqrt(2.0);  // one point covers a level-0 square
        std::vector<pds::Point> active;     // lower-left corners
        const int nx = static_cast<int>(std::ceil(box_.width() / side));
        const int ny = static_cast<int>(std::ceil(box_.height() / side));
        for (int i = 0; i < nx; ++i)
            for (int j = 0; j < ny; ++j) active.push_back({box_.x0 + i * side, box_.y0 + j * side});
        for (int level = 0; !active.empty() && level < 60; ++level) {
            const std::size_t darts = active.size();
            for (std::size_t k = 0; k < darts && !active.empty(); ++k) {
                std::size_t pick = static_cast<std::size_t>(u01(rng) * static_cast<double>(active.size()));
                pick = std::min(pick, active.size() - 1);
                const pds::Point sq = active[pick];
                const pds::Point p{sq.x + u01(rng) * side, sq.y + u01(rng) * side};
                if (inside(p) && !covered(p)) add(p);
                if (covered_square(sq, side)) {
                    active[pick] = active.back();
                    active.pop_back();
                }
            }
            side *= 0.5;
            std::vector<pds::Point> next;
            for (const pds::Point& sq : active)
                for (int c = 0; c < 4; ++c) {
                    const pds::Point child{sq.x + (c & 1) * side, sq.y + (c >> 1) * side};
                    if (child.x >= box_.x1 || child.y >= box_.y1) continue;
                    if (!covered_square(child, side)) next.push_back(child);
                }
            active.swap(next);
        }
        return points_;
    }

    double d2(const pds::Point& a, const pds::Point& b) const {
        const double dx = wrap_delta(a.x - b.x, box_.width()), dy = wrap_delta(a.y - b.y, box_.height());
        return dx * dx + dy * dy;
    }

private:
    bool inside(const pds::Point& p) const { return p.x >= box_.x0 && p.x < box_.x1 && p.y >= box_.y0 && p.y < box_.y1; }

    int cell(double v, double lo, double len, int n) const {
        const int c = static_cast<int>((v - lo) / len * n);
        return ((c % n) + n) % n;  // overhanging corners wrap to the near side
    }

    // f(q) for every point q in the (2 reach + 1)^2 wrapped cells around (x, y).
    template <class F>
    bool any_near(double x, double y, int reach, const F& f) const {
        const int cx = cell(x, box_.x0, box_.width(), gx_), cy = cell(y, box_.y0, box_.height(), gy_);
        for (int i = cx - reach; i <= cx + reach; ++i)
            for (int j = cy - reach; j <= cy + reach; ++j) {
                const int wi = ((i % gx_) + gx_) % gx_, wj = ((j % gy_) + gy_) % gy_;
                for (std::size_t k : buckets_[static_cast<std::size_t>(wj) * gx_ + wi])
                    if (f(points_[k])) return true;
            }
        return false;
    }

    bool covered(const pds::Point& p) const {
        return any_near(p.x, p.y, 1, [&](const pds::Point& q) { return d2(p, q) < r2_; });
    }

    // All four corners within R of the same copy of one point: the copy of q
    // nearest the square's centre.
    bool covered_square(const pds::Point& sq, double side) const {
        const double cx = sq.x + side / 2, cy = sq.y + side / 2;
        return any_near(cx, cy, 2, [&](const pds::Point& q) {
            const double w = box_.width(), h = box_.height();
            const double qx = q.x - w * std::nearbyint((q.x - cx) / w);
            const double qy = q.y - h * std::nearbyint((q.y - cy) / h);
            for (int c = 0; c < 4; ++c) {
                const double dx = sq.x + (c & 1) * side - qx, dy = sq.y + (c >> 1) * side - qy;
                if (dx * dx + dy * dy > r2_) return false;
            }
            return true;
        });
    }

    void add(const pds::Point& p) {
        const int cx = cell(p.x, box_.x0, box_.width(), gx_), cy = cell(p.y, box_.y0, box_.height(), gy_);
        buckets_[static_cast<std::size_t>(cy) * gx_ + cx].push_back(points_.size());
        points_.push_back(p);
    }

    pds::Box box_;
    double r_, r2_;
    int gx_, gy_;
    std::vector<pds::Point> points_;
    std::vector<std::vector<std::size_t>> buckets_;
};

using law::Stages;

void compare_laws(const pds::Box& box, double r, int runs, Stages stages) {
    law::Sample sampler, darts;
    TorusDartThrowing reference(box, r);
    const auto d2 = [&reference](const pds::Point& a, const pds::Point& b) { return reference.d2(a, b); };
    std::size_t from_darts = 0, total = 0;
    for (int seed = 1; seed <= runs; ++seed) {
        pds::Sampler s(r, static_cast<std::uint64_t>(seed));
        s.set_domain(box);
        s.set_periodic(true);
        if (stages == Stages::jones_only) s.skip_dart_stage();
        const std::vector<pds::Point> p = law::run_both_stages(s, &from_darts);
        total += p.size();
        law::add(sampler, p, r, d2);
        law::add(darts, reference.run(static_cast<std::uint64_t>(1000000 + seed)), r, d2);
    }
    if (stages == Stages::darts_then_jones) law::assert_both_stages(from_darts, total);
    law::assert_same_law(sampler, darts);
}

}  // namespace

START_TEST(torus_reference_is_maximal_and_spaced) {
    // The reference must saturate across the seam and keep wrapped spacing.
    const pds::Box box{0, 0, 1, 1};
    const double r = 0.1;
    TorusDartThrowing reference(box, r);
    for (int seed = 1; seed <= (test_light() ? 1 : 5); ++seed) {
        const std::vector<pds::Point> p = reference.run(static_cast<std::uint64_t>(seed));
        for (std::size_t i = 0; i < p.size(); ++i)
            for (std::size_t j = i + 1; j < p.size(); ++j) ck_assert(reference.d2(p[i], p[j]) >= r * r);
        for (int i = 0; i < 200; ++i)
            for (int j = 0; j < 200; ++j) {
                const pds::Point x{i / 200.0, j / 200.0};
                bool near = false;
                for (const pds::Point& q : p)
                    if (reference.d2(x, q) <= r * r) near = true;
                ck_assert(near);
            }
    }
}
END_TEST

// Under Valgrind (PDS_TEST_LIGHT) a few dozen seeds: the thresholds stay
// valid, only the power drops, and the run stays short.
START_TEST(law_on_the_unit_torus) {
    compare_laws(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 60 : 3000, Stages::darts_then_jones);
}
END_TEST

START_TEST(law_on_a_rectangular_torus) {
    compare_laws(pds::Box{0, 0, 2, 0.5}, 0.12, test_light() ? 50 : 2000, Stages::darts_then_jones);
}
END_TEST

START_TEST(law_of_the_jones_loop_alone_on_the_torus) {
    compare_laws(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 50 : 2000, Stages::jones_only);
}
END_TEST

Suite* law_torus_suite() {
    Suite* s = suite_create("law_torus");
    TCase* t = tcase_create("random sequential adsorption on the torus");
    tcase_set_timeout(t, 900);
    tcase_add_test(t, torus_reference_is_maximal_and_spaced);
    tcase_add_test(t, law_on_the_unit_torus);
    tcase_add_test(t, law_on_a_rectangular_torus);
    tcase_add_test(t, law_of_the_jones_loop_alone_on_the_torus);
    suite_add_tcase(s, t);
    return s;
}
