// test_law.cpp - the sampler follows the random-sequential-adsorption law:
// over many seeds, the distribution of the final count N and of the number of
// near-contact pairs (distance < 1.2 R) matches saturated dart throwing
// (dart_throwing.hpp), an independent exact implementation of the same law.
//
// The comparison is a two-sample z test on the means plus a two-sample
// Kolmogorov-Smirnov test on N; both use fixed seeds, so the outcome is
// deterministic. A biased sampler fails it: picking cells uniformly instead of
// by area, or skipping the rejection step, shifts the mean N by many standard
// errors (see the closing note of the issue that introduced this test).
#include <algorithm>
#include <cmath>
#include <vector>

#include "dart_throwing.hpp"
#include "sampler.hpp"
#include "suites.hpp"

namespace {

struct Stats {
    std::vector<double> count, close_pairs;
};

double close_pairs(const std::vector<pds::Point>& p, double r) {
    double n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            const double dx = p[i].x - p[j].x, dy = p[i].y - p[j].y;
            if (dx * dx + dy * dy < 1.44 * r * r) ++n;
        }
    return n;
}

void add(Stats& s, const std::vector<pds::Point>& p, double r) {
    s.count.push_back(static_cast<double>(p.size()));
    s.close_pairs.push_back(close_pairs(p, r));
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

double variance(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return s / static_cast<double>(v.size() - 1);
}

double z_score(const std::vector<double>& a, const std::vector<double>& b) {
    const double se = std::sqrt(variance(a) / static_cast<double>(a.size()) + variance(b) / static_cast<double>(b.size()));
    return (mean(a) - mean(b)) / se;
}

// Two-sample Kolmogorov-Smirnov statistic scaled by sqrt(n m / (n + m)).
double ks_scaled(std::vector<double> a, std::vector<double> b) {
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    std::size_t i = 0, j = 0;
    double d = 0;
    while (i < a.size() && j < b.size()) {
        const double x = std::min(a[i], b[j]);
        while (i < a.size() && a[i] == x) ++i;
        while (j < b.size() && b[j] == x) ++j;
        d = std::max(d, std::fabs(double(i) / static_cast<double>(a.size()) - double(j) / static_cast<double>(b.size())));
    }
    const double n = static_cast<double>(a.size()), m = static_cast<double>(b.size());
    return d * std::sqrt(n * m / (n + m));
}

enum class Stages { darts_then_jones, jones_only };

void compare_laws(const pds::Box& box, double r, int runs, Stages stages) {
    Stats jones, darts;
    SaturatedDartThrowing reference(box, r);
    std::size_t from_darts = 0, total = 0;
    for (int seed = 1; seed <= runs; ++seed) {
        pds::Sampler s(r, static_cast<std::uint64_t>(seed));
        s.set_domain(box);
        if (stages == Stages::jones_only) s.skip_dart_stage();
        bool maximal = false;
        // Both stages must take part: run until the hand-over, count.
        while (s.in_dart_stage() && s.run(1, &maximal) == 1) {
        }
        from_darts += s.in_dart_stage() ? s.count() : s.count() - (s.count() > 0 ? 1 : 0);
        s.run(0, &maximal);
        total += s.count();
        ck_assert(maximal);
        std::vector<double> xy(2 * s.count());
        s.copy_points(0, s.count(), xy.data());
        std::vector<pds::Point> p(s.count());
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = {xy[2 * i], xy[2 * i + 1]};
        add(jones, p, r);
        add(darts, reference.run(static_cast<std::uint64_t>(1000000 + seed)), r);
    }
    if (stages == Stages::darts_then_jones) {
        // The dart stage must place a real share of the points, and leave
        // the Jones loop a real share too, or this test would not test both.
        const double share = static_cast<double>(from_darts) / static_cast<double>(total);
        ck_assert_msg(share > 0.3 && share < 0.95, "dart stage placed %.3f of the points", share);
    }
    const double z_count = z_score(jones.count, darts.count);
    const double z_pairs = z_score(jones.close_pairs, darts.close_pairs);
    const double ks = ks_scaled(jones.count, darts.count);
    // |z| > 4.5 has probability ~7e-6 under the same law; KS scaled > 1.95
    // has probability ~1e-3.
    ck_assert_msg(std::fabs(z_count) < 4.5, "mean N: sampler %.3f, dart throwing %.3f (z = %.2f)",
                  mean(jones.count), mean(darts.count), z_count);
    ck_assert_msg(std::fabs(z_pairs) < 4.5, "close pairs: sampler %.3f, dart throwing %.3f (z = %.2f)",
                  mean(jones.close_pairs), mean(darts.close_pairs), z_pairs);
    ck_assert_msg(ks < 1.95, "distribution of N differs (KS %.3f)", ks);
}

}  // namespace

START_TEST(reference_is_maximal) {
    // The reference itself must saturate: probe it densely.
    const pds::Box box{0, 0, 1, 1};
    const double r = 0.1;
    SaturatedDartThrowing reference(box, r);
    for (int seed = 1; seed <= 5; ++seed) {
        const std::vector<pds::Point> p = reference.run(static_cast<std::uint64_t>(seed));
        for (int i = 0; i <= 200; ++i)
            for (int j = 0; j <= 200; ++j) {
                const double x = i / 200.0, y = j / 200.0;
                bool near = false;
                for (const pds::Point& q : p)
                    if ((q.x - x) * (q.x - x) + (q.y - y) * (q.y - y) <= r * r) near = true;
                ck_assert(near);
            }
    }
}
END_TEST

START_TEST(law_in_the_unit_square) {
    compare_laws(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 400 : 3000, Stages::darts_then_jones);
}
END_TEST

START_TEST(law_in_a_rectangle) {
    compare_laws(pds::Box{0, 0, 2, 0.5}, 0.12, test_light() ? 300 : 2000, Stages::darts_then_jones);
}
END_TEST

START_TEST(law_of_the_jones_loop_alone) {
    // The Jones loop from the first point (it alone serves refine()).
    compare_laws(pds::Box{0, 0, 1, 1}, 0.1, test_light() ? 300 : 2000, Stages::jones_only);
}
END_TEST

Suite* law_suite() {
    Suite* s = suite_create("law");
    TCase* t = tcase_create("random sequential adsorption");
    tcase_set_timeout(t, 900);
    tcase_add_test(t, reference_is_maximal);
    tcase_add_test(t, law_in_the_unit_square);
    tcase_add_test(t, law_in_a_rectangle);
    tcase_add_test(t, law_of_the_jones_loop_alone);
    suite_add_tcase(s, t);
    return s;
}
