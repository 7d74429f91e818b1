// law_compare.hpp - the comparison behind the law tests (test_law.cpp on the
// rectangle, test_law_torus.cpp on the torus): over many seeds, the final
// count N and the number of near-contact pairs (distance < 1.2 R, measured
// by the caller's metric) of the sampler against an independent saturated
// dart thrower. A two-sample z test on the means and a two-sample
// Kolmogorov-Smirnov test on N, with fixed seeds, so the outcome is
// deterministic: |z| > 4.5 has probability ~7e-6 under the same law, KS
// scaled > 1.95 ~1e-3.
#ifndef PDS_TEST_LAW_COMPARE_HPP
#define PDS_TEST_LAW_COMPARE_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace law {

enum class Stages { darts_then_jones, jones_only };

struct Sample {
    std::vector<double> count, close_pairs;
};

// Adds one pattern; d2(a, b) is the squared distance the domain uses.
template <class Distance2>
void add(Sample& s, const std::vector<pds::Point>& p, double r, const Distance2& d2) {
    double n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j)
            if (d2(p[i], p[j]) < 1.44 * r * r) ++n;
    s.count.push_back(static_cast<double>(p.size()));
    s.close_pairs.push_back(n);
}

inline double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

inline double variance(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return s / static_cast<double>(v.size() - 1);
}

inline double z_score(const std::vector<double>& a, const std::vector<double>& b) {
    const double se = std::sqrt(variance(a) / static_cast<double>(a.size()) + variance(b) / static_cast<double>(b.size()));
    return (mean(a) - mean(b)) / se;
}

// Two-sample Kolmogorov-Smirnov statistic scaled by sqrt(n m / (n + m)).
inline double ks_scaled(std::vector<double> a, std::vector<double> b) {
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

// Runs s to the end so that both stages take part (one point at a time until
// the hand-over); adds the points the dart stage placed to *from_darts.
inline std::vector<pds::Point> run_both_stages(pds::Sampler& s, std::size_t* from_darts) {
    bool maximal = false;
    while (s.in_dart_stage() && s.add_points(1, &maximal) == 1) {
    }
    *from_darts += s.in_dart_stage() ? s.count() : s.count() - (s.count() > 0 ? 1 : 0);
    s.add_points(0, &maximal);
    ck_assert(maximal);
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    std::vector<pds::Point> p(s.count());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = {xy[2 * i], xy[2 * i + 1]};
    return p;
}

// The dart stage must place a real share of the points, and leave the Jones
// loop a real share too, or the test would not test both.
inline void assert_both_stages(std::size_t from_darts, std::size_t total) {
    const double share = static_cast<double>(from_darts) / static_cast<double>(total);
    ck_assert_msg(share > 0.3 && share < 0.95, "dart stage placed %.3f of the points", share);
}

inline void assert_same_law(const Sample& sampler, const Sample& darts) {
    const double z_count = z_score(sampler.count, darts.count);
    const double z_pairs = z_score(sampler.close_pairs, darts.close_pairs);
    const double ks = ks_scaled(sampler.count, darts.count);
    ck_assert_msg(std::fabs(z_count) < 4.5, "mean N: sampler %.3f, dart throwing %.3f (z = %.2f)",
                  mean(sampler.count), mean(darts.count), z_count);
    ck_assert_msg(std::fabs(z_pairs) < 4.5, "close pairs: sampler %.3f, dart throwing %.3f (z = %.2f)",
                  mean(sampler.close_pairs), mean(darts.close_pairs), z_pairs);
    ck_assert_msg(ks < 1.95, "distribution of N differs (KS %.3f)", ks);
}

}  // namespace law

#endif
