// test_sampler.cpp - whole patterns from the core sampler, over seeds, radii
// and domains: points inside, pairs at least R apart (exact), the mesh
// Delaunay, maximal by the certificate and by random probes, free area exactly
// zero at the end, refine, and determinism.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "core/predicates.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

struct Case {
    pds::Box box;
    double r;
};

std::vector<double> user_points(const pds::Sampler& s) {
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    return xy;
}

// Pairs at least R apart, exactly, by brute force over a sorted sweep.
void check_min_distance(const std::vector<double>& xy, double r) {
    std::vector<pds::Point> p(xy.size() / 2);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = {xy[2 * i], xy[2 * i + 1]};
    std::sort(p.begin(), p.end(), [](const pds::Point& a, const pds::Point& b) { return a.x < b.x; });
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size() && p[j].x - p[i].x < r; ++j)
            ck_assert_int_ge(pds::compare_distance(p[i], p[j], r), 0);
}

// Whether a point has a sample within R: brute force over a coarse grid of
// buckets, independent of the sampler's mesh.
class CoverageOracle {
public:
    CoverageOracle(const std::vector<double>& xy, const pds::Box& box, double r)
        : xy_(xy), box_(box), r_(r) {
        const int g = std::max(1, static_cast<int>(std::min(box.width(), box.height()) / r));
        cw_ = box.width() / g;
        ch_ = box.height() / g;
        gx_ = static_cast<int>(box.width() / cw_);
        gy_ = static_cast<int>(box.height() / ch_);
        cells_.resize(static_cast<std::size_t>(gx_ + 1) * (gy_ + 1));
        for (std::size_t i = 0; i < xy.size() / 2; ++i) {
            const auto c = cell_of(xy[2 * i], xy[2 * i + 1]);
            cells_[c.second * (gx_ + 1) + c.first].push_back(i);
        }
        reach_ = static_cast<int>(std::ceil(r / std::min(cw_, ch_))) + 1;
    }

    bool covered(double x, double y) const {
        const auto c = cell_of(x, y);
        for (int dx = -reach_; dx <= reach_; ++dx)
            for (int dy = -reach_; dy <= reach_; ++dy) {
                const int cx = c.first + dx, cy = c.second + dy;
                if (cx < 0 || cy < 0 || cx > gx_ || cy > gy_) continue;
                for (std::size_t i : cells_[cy * (gx_ + 1) + cx]) {
                    const double ddx = xy_[2 * i] - x, ddy = xy_[2 * i + 1] - y;
                    if (ddx * ddx + ddy * ddy <= r_ * r_) return true;
                }
            }
        return false;
    }

private:
    std::pair<int, int> cell_of(double x, double y) const {
        const int cx = std::min(gx_, std::max(0, static_cast<int>((x - box_.x0) / cw_)));
        const int cy = std::min(gy_, std::max(0, static_cast<int>((y - box_.y0) / ch_)));
        return {cx, cy};
    }

    const std::vector<double>& xy_;
    pds::Box box_;
    double r_, cw_, ch_;
    int gx_, gy_, reach_;
    std::vector<std::vector<std::size_t>> cells_;
};

// Random probes: every probe point has a sample within R. A probabilistic,
// mesh-free maximality check.
void check_probes(const std::vector<double>& xy, const pds::Box& box, double r, int probes) {
    const CoverageOracle oracle(xy, box, r);
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> ux(box.x0, box.x1), uy(box.y0, box.y1);
    for (int k = 0; k < probes; ++k) {
        const double x = ux(rng), y = uy(rng);
        ck_assert_msg(oracle.covered(x, y), "probe (%.17g, %.17g) is farther than R from every point", x, y);
    }
}

void check_pattern(const pds::Sampler& s, bool expect_maximal) {
    const std::vector<double> xy = user_points(s);
    const pds::Box& d = s.domain();
    for (std::size_t i = 0; i < xy.size() / 2; ++i)
        ck_assert(d.contains(pds::Point{xy[2 * i], xy[2 * i + 1]}));
    check_min_distance(xy, s.radius());
    check_delaunay_mesh(s.jones().mesh());
    const pds::VerifyReport rep = s.verify();
    ck_assert_msg(rep.valid, "verify: %s", rep.failure.c_str());
    ck_assert_int_eq(rep.maximal, expect_maximal);
    ck_assert_uint_eq(s.jones().stats().gave_up_cells, 0);
    if (expect_maximal) {
        ck_assert(s.free_area() == 0.0);
        check_probes(xy, d, s.radius(), test_light() ? 2000 : 20000);
    }
}

}  // namespace

START_TEST(maximal_patterns_over_seeds_and_domains) {
    const Case cases[] = {{{0, 0, 1, 1}, 0.05},           {{0, 0, 1, 1}, 0.013},
                          {{0, 0, 4, 0.5}, 0.03},         {{1000, -3, 1001, -2}, 0.02},
                          {{-1e-6, -1e-6, 1e-6, 1e-6}, 1e-7}, {{0, 0, 100, 100}, 2.0},
                          {{0, 0, 1, 0.05}, 0.2},          {{-7.5, 3.25, -2.0, 9.0}, 0.11}};
    const int seeds = test_light() ? 1 : 6;
    for (const Case& cs : cases) {
        for (int seed = 1; seed <= seeds; ++seed) {
            pds::Sampler s(cs.r, static_cast<std::uint64_t>(seed * 7919));
            s.set_domain(cs.box);
            bool maximal = false;
            s.add_points(0, &maximal);
            ck_assert(maximal);
            ck_assert(!s.step());
            check_pattern(s, true);
        }
    }
}
END_TEST

START_TEST(partial_patterns_are_valid) {
    pds::Sampler s(0.02, 5);
    bool maximal = true;
    s.add_points(700, &maximal);
    ck_assert(!maximal);
    ck_assert_uint_eq(s.count(), 700);
    ck_assert_double_gt(s.free_area(), 0.0);
    check_pattern(s, false);
    // Free area never grows while points are added.
    double last = s.free_area();
    for (int i = 0; i < 200; ++i) {
        ck_assert(s.step());
        ck_assert_double_le(s.free_area(), last);
        last = s.free_area();
    }
}
END_TEST

START_TEST(dart_stage_and_hand_over) {
    // Queries in the dart stage (no triangulation kept) against independent
    // answers, then the hand-over: points keep their order and values.
    pds::Sampler s(0.02, 11);
    s.set_domain(pds::Box{0, 0, 1.5, 0.8});
    bool maximal = true;
    s.add_points(800, &maximal);
    ck_assert(s.in_dart_stage());
    ck_assert(!maximal);
    // Free area against the fraction of a fine probe grid farther than R.
    const std::vector<double> xy = user_points(s);
    const CoverageOracle oracle(xy, s.domain(), s.radius());
    const int g = test_light() ? 300 : 900;
    long uncovered = 0;
    for (int i = 0; i < g; ++i)
        for (int j = 0; j < g; ++j) uncovered += !oracle.covered(1.5 * (i + 0.5) / g, 0.8 * (j + 0.5) / g);
    const double probed = 1.5 * 0.8 * static_cast<double>(uncovered) / (static_cast<double>(g) * g);
    ck_assert_double_gt(probed, 0.01);
    ck_assert_double_lt(std::fabs(s.free_area() - probed), 0.03 * probed);
    check_pattern(s, false);
    ck_assert(s.in_dart_stage());  // the queries changed nothing
    // Hand over (somewhere in the next points) and run to the end: the
    // first 800 points are the same, in the same order.
    s.add_points(0, &maximal);
    ck_assert(maximal);
    ck_assert(!s.in_dart_stage());
    const std::vector<double> all = user_points(s);
    ck_assert(std::equal(xy.begin(), xy.end(), all.begin()));
    check_pattern(s, true);
}
END_TEST

START_TEST(refine_continues_at_the_smaller_radius) {
    pds::Sampler s(0.06, 17);
    s.set_domain(pds::Box{0, 0, 2, 1});
    bool maximal = false;
    s.add_points(0, &maximal);
    const std::vector<double> before = user_points(s);
    s.refine(0.03);
    ck_assert_double_gt(s.free_area(), 0.0);
    s.add_points(0, &maximal);
    ck_assert(maximal);
    const std::vector<double> after = user_points(s);
    ck_assert_uint_gt(after.size(), before.size());
    ck_assert_int_eq(std::memcmp(before.data(), after.data(), before.size() * sizeof(double)), 0);
    check_pattern(s, true);
    // Refine in the middle of a run, then again.
    pds::Sampler t(0.05, 18);
    t.add_points(30, &maximal);
    t.refine(0.04);
    t.add_points(100, &maximal);
    t.refine(0.021);
    t.add_points(0, &maximal);
    ck_assert(maximal);
    check_pattern(t, true);
}
END_TEST

START_TEST(same_seed_same_bytes) {
    const auto run = [](std::uint64_t seed, std::size_t chunk) {
        pds::Sampler s(0.015, seed);
        s.set_domain(pds::Box{-1, 0, 1, 1});
        bool maximal = false;
        do s.add_points(chunk, &maximal);
        while (!maximal);
        return user_points(s);
    };
    const std::vector<double> a = run(42, 0), b = run(42, 0), c = run(42, 13), d = run(43, 0);
    ck_assert_uint_eq(a.size(), b.size());
    ck_assert_int_eq(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
    ck_assert_uint_eq(a.size(), c.size());
    ck_assert_int_eq(std::memcmp(a.data(), c.data(), a.size() * sizeof(double)), 0);
    ck_assert(a.size() != d.size() || std::memcmp(a.data(), d.data(), a.size() * sizeof(double)) != 0);
}
END_TEST

START_TEST(limits) {
    using pds::Frame;
    using pds::Limit;
    ck_assert(Frame({0, 0, 1, 1}, 0.01).precision_limit() == Limit::ok);
    ck_assert(Frame({0, 0, 1, 1}, 1e-5).precision_limit() == Limit::ok);
    ck_assert_double_gt(Frame({0, 0, 1, 1}, 1e-5).count_bound(), static_cast<double>(Frame::max_points()));
    ck_assert(Frame({1e15, 0, 1e15 + 1, 1}, 0.05).precision_limit() == Limit::radius_below_precision);
    ck_assert(Frame({0, 0, 1e-300, 1e-300}, 1e-302).precision_limit() == Limit::coordinates_too_small);
    ck_assert(Frame({-1e308, -1e308, 1e308, 1e308}, 1e306).precision_limit() == Limit::ok);
    // Found by the fuzzer: x0 and x1 underflowed to 0 when scaled.
    ck_assert(Frame({1e-300, 0, 2e-300, 1e300}, 1e299).precision_limit() == Limit::coordinates_too_small);
    ck_assert(Frame({0, 0, 1e-300, 1}, 0.1).precision_limit() == Limit::coordinates_too_small);
    ck_assert(Frame({0, 0, 1e-200, 1e-200}, 1e-202).precision_limit() == Limit::ok);
    // Oler's bound really bounds: a hexagonal packing at spacing R fits under it.
    const double r = 0.01;
    const double rows = std::floor(1.0 / (r * std::sqrt(3.0) / 2)) + 1, cols = std::floor(1.0 / r) + 1;
    ck_assert_double_ge(Frame({0, 0, 1, 1}, r).count_bound(), rows * cols - rows / 2);
}
END_TEST

START_TEST(limits_judged_at_first_use) {
    bool maximal = true;
    // A maximal pattern would not fit 32-bit indices: only bounded runs, and
    // their darts on a grid that keeps only its taken cells (the whole grid
    // would be huge).
    pds::Sampler huge(1e-5, 1);
    try {
        huge.add_points(0, &maximal);
        ck_abort_msg("an unbounded run at R = 1e-5 must throw LimitError");
    } catch (const pds::LimitError& e) {
        ck_assert(e.limit() == pds::Limit::too_many_points);
    }
    ck_assert_uint_eq(huge.count(), 0);
    ck_assert_uint_eq(huge.add_points(100, &maximal), 100);
    ck_assert(!maximal);
    ck_assert(huge.in_dart_stage());
    ck_assert(huge.verify().valid);
    // The same radius for a domain it suits, given in either order.
    pds::Sampler tiny(1e-5, 2);
    tiny.set_domain(pds::Box{0, 0, 4e-4, 4e-4});
    tiny.add_points(0, &maximal);
    ck_assert(maximal);
    ck_assert_uint_gt(tiny.count(), 500);
    // Precision: refused at the first point, with nothing changed.
    pds::Sampler far(0.05, 3);
    far.set_domain(pds::Box{1e15, 0, 1e15 + 1, 1});
    try {
        far.step();
        ck_abort_msg("a radius below precision must throw LimitError");
    } catch (const pds::LimitError& e) {
        ck_assert(e.limit() == pds::Limit::radius_below_precision);
    }
    ck_assert_uint_eq(far.count(), 0);
}
END_TEST

// A polygon, or a mask's outline, is read at the internal frame's scale when
// its coordinates scale there exactly: the frame keeps it as built instead
// of a second, scaled copy, and the points are those of the copy.
START_TEST(polygons_are_read_at_the_internal_scale) {
    using pds::Frame;
    const double pixels[] = {0, 0, 640, 0, 640, 480, 100, 300};
    ck_assert_int_eq(Frame::polygon_reading_exponent(pixels, 8), 9);
    const double unit[] = {1.5, -1.25, 1, 0.5};
    ck_assert_int_eq(Frame::polygon_reading_exponent(unit, 4), 0);
    const double huge[] = {1e300, -3e299, 2e299, 1e299};
    ck_assert_int_eq(Frame::polygon_reading_exponent(huge, 4), std::ilogb(1e300));
    // A coordinate below 2^-900 of the largest does not scale there.
    const double spread[] = {1e300, 1e-10, 2e299, 1e299};
    ck_assert_int_eq(Frame::polygon_reading_exponent(spread, 4), pds::reading_exponent(spread, 4));
    ck_assert_int_ne(Frame::polygon_reading_exponent(spread, 4), std::ilogb(1e300));

    const std::size_t ends[] = {4};
    pds::Sampler read(20.0, 5);
    read.set_polygon(pixels, ends, 1);
    ck_assert(read.frame().shares_polygon());
    ck_assert_double_eq(read.frame().user_domain().x1, 640.0);
    pds::Sampler copied(20.0, 5);
    copied.set_polygon(std::make_shared<const pds::Polygon>(pixels, ends, 1));
    ck_assert(!copied.frame().shares_polygon());
    bool maximal = false;
    read.add_points(0, &maximal);
    ck_assert(maximal);
    copied.add_points(0, &maximal);
    ck_assert_uint_gt(read.count(), 100);
    const std::vector<double> a = user_points(read), b = user_points(copied);
    ck_assert_uint_eq(a.size(), b.size());
    ck_assert_int_eq(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);

    // A mask's outline over pixel coordinates, then spread over another rectangle.
    const std::uint8_t inside[] = {1, 1, 0, 0, 1, 1, 0, 1, 1, 1, 1, 1};  // 4 x 3
    pds::Sampler mask(20.0, 6);
    mask.set_domain(pds::Box{0, 0, 640, 480});
    mask.set_mask(4, 3, inside);
    ck_assert(mask.frame().shares_polygon());
    mask.set_domain(pds::Box{-3, -1, 3, 2});
    ck_assert(mask.frame().shares_polygon());
    ck_assert_double_eq(mask.frame().user_domain().x0, -3.0);
}
END_TEST

Suite* sampler_suite() {
    Suite* s = suite_create("sampler");
    TCase* t = tcase_create("patterns");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, maximal_patterns_over_seeds_and_domains);
    tcase_add_test(t, partial_patterns_are_valid);
    tcase_add_test(t, dart_stage_and_hand_over);
    tcase_add_test(t, refine_continues_at_the_smaller_radius);
    suite_add_tcase(s, t);
    t = tcase_create("determinism");
    tcase_set_timeout(t, 300);
    tcase_add_test(t, same_seed_same_bytes);
    suite_add_tcase(s, t);
    t = tcase_create("limits");
    tcase_add_test(t, limits);
    tcase_add_test(t, limits_judged_at_first_use);
    suite_add_tcase(s, t);
    t = tcase_create("polygon scale");
    tcase_add_test(t, polygons_are_read_at_the_internal_scale);
    suite_add_tcase(s, t);
    return s;
}
