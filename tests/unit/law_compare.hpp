// law_compare.hpp - the comparison behind every law test: a sampler
// configuration (domain, plane or torus, one radius or a radius field, which
// stages run) against the independent saturated dart thrower
// (dart_throwing.hpp) under the same distance and radius rules. Over many
// seeds it compares the final count N, the number of near-contact pairs
// (a later point within 1.2 times an earlier one's radius, by the domain's
// distance) and the mean distance from each point to the nearest point
// placed before it (both samplers place points in random-sequential order,
// so this sees where each new point fell): a two-sample z test on the means and a two-sample
// Kolmogorov-Smirnov test on N, with fixed seeds, so the outcome is
// deterministic: |z| > 4.5 has probability ~7e-6 under the same law, KS
// scaled > 1.95 ~1e-3.
#ifndef PDS_TEST_LAW_COMPARE_HPP
#define PDS_TEST_LAW_COMPARE_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "dart_throwing.hpp"
#include "polygon_rings.hpp"
#include "radius/radius_field.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace law {

enum class Stages {
    darts_then_jones,  // as configured; both stages must place a real share
    jones_only,        // skip_dart_stage(): the Jones loop from the first point
    no_dart_stage,     // as configured, which has no dart stage (checked)
};

// What the sampler is given, and the dart thrower follows.
struct Config {
    pds::Box box{0, 0, 1, 1};
    bool periodic = false;
    double r = 0;                    // one radius, when there is no field
    oracle::Field field = nullptr;   // or a radius field within [rmin, rmax]
    double rmin = 0, rmax = 0;
    Stages stages = Stages::darts_then_jones;
    unsigned threads = 0;            // > 0: the parallel opening (set_threads) on that many
    double region_darts_per_cell = 0;  // > 0: the free regions' epochs of that mean length
    bool side_insertions = false;    // their epochs inserted on two sides at once
    double dart_budget_per_point = 0;  // > 0: the dart stage's memory budget, bytes a point (no floor)
    int runs = 0;                    // seeds 1..runs (the dart thrower: 10^6 + seed)
    std::vector<std::vector<double>> rings;  // in the plane: a polygon (x, y lists) within box
};

struct Sample {
    std::vector<double> count, close_pairs, to_earlier;
};

// The mean, over the points after the first, of the distance to the nearest
// point placed before it (by `distance`; 0 for fewer than two points).
template <class Distance>
double mean_distance_to_earlier(const std::vector<pds::Point>& p, const Distance& distance) {
    double earlier = 0;
    for (std::size_t i = 1; i < p.size(); ++i) {
        double nearest2 = INFINITY;
        for (std::size_t j = 0; j < i; ++j) nearest2 = std::min(nearest2, distance.d2(p[i], p[j]));
        earlier += std::sqrt(nearest2);
    }
    return p.size() > 1 ? earlier / static_cast<double>(p.size() - 1) : 0.0;
}

// Adds one pattern, its pairs measured by `distance` (Plane or Torus).
template <class Distance>
void add(Sample& s, const oracle::Pattern& t, const Distance& distance) {
    double n = 0;
    for (std::size_t i = 0; i < t.p.size(); ++i)
        for (std::size_t j = i + 1; j < t.p.size(); ++j)
            if (distance.d2(t.p[i], t.p[j]) < 1.44 * t.r[i] * t.r[i]) ++n;
    s.count.push_back(static_cast<double>(t.p.size()));
    s.close_pairs.push_back(n);
    s.to_earlier.push_back(mean_distance_to_earlier(t.p, distance));
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

// s (made with radius c.r, or 1 with a field) set up as c says.
inline void configure(pds::Sampler& s, const Config& c) {
    s.set_domain(c.box);
    if (!c.rings.empty()) s.set_polygon(std::make_shared<const pds::Polygon>(rings_of(c.rings)));
    s.set_periodic(c.periodic);
    if (c.field) s.set_field(pds::RadiusField::function(c.field, nullptr, c.rmin, c.rmax));
    if (c.stages == Stages::jones_only) s.skip_dart_stage();
    if (c.threads != 0) s.set_threads(c.threads);
    if (c.region_darts_per_cell > 0) s.set_region_darts_per_cell(c.region_darts_per_cell);
    s.set_side_insertions(c.side_insertions);
    if (c.dart_budget_per_point > 0) s.set_dart_memory_budget(c.dart_budget_per_point, 0);
}

// Runs s to the end, checks it ends maximal and returns its points and radii.
// With from_darts, one point at a time until the hand-over, adding the
// points the dart stage placed to *from_darts.
inline oracle::Pattern run_to_the_end(pds::Sampler& s, std::size_t* from_darts = nullptr) {
    bool maximal = false;
    if (from_darts) {
        while (s.in_dart_stage() && s.add_points(1, &maximal) == 1) {
        }
        *from_darts += s.in_dart_stage() ? s.count() : s.count() - (s.count() > 0 ? 1 : 0);
    }
    s.add_points(0, &maximal);
    ck_assert(maximal);
    oracle::Pattern out;
    std::vector<double> xy(2 * s.count());
    out.r.resize(s.count());
    s.copy_points(0, s.count(), xy.data());
    s.copy_radii(0, s.count(), out.r.data());
    for (std::size_t i = 0; i < s.count(); ++i) out.p.push_back({xy[2 * i], xy[2 * i + 1]});
    return out;
}

// The stages took the part c.stages says: with both, the dart stage must
// place a real share of the points and leave the Jones loop a real share
// too, or the test would not test both.
inline void assert_stages(const Config& c, std::size_t from_darts, std::size_t total) {
    if (c.stages != Stages::darts_then_jones) {
        ck_assert_msg(from_darts == 0, "the dart stage placed %zu points", from_darts);
        return;
    }
    const double share = static_cast<double>(from_darts) / static_cast<double>(total);
    ck_assert_msg(share > 0.3 && share < 0.95, "dart stage placed %.3f of the points", share);
}

inline void assert_same_law(const Sample& sampler, const Sample& darts) {
    const double z_count = z_score(sampler.count, darts.count);
    const double z_pairs = z_score(sampler.close_pairs, darts.close_pairs);
    const double z_earlier = z_score(sampler.to_earlier, darts.to_earlier);
    const double ks = ks_scaled(sampler.count, darts.count);
    if (std::getenv("PDS_LAW_PRINT"))
        std::printf("law: mean N %.3f / %.3f (z %.2f), close pairs z %.2f, nearest earlier z %.2f, KS %.3f\n",
                    mean(sampler.count), mean(darts.count), z_count, z_pairs, z_earlier, ks);
    ck_assert_msg(std::fabs(z_count) < 4.5, "mean N: sampler %.3f, dart throwing %.3f (z = %.2f)",
                  mean(sampler.count), mean(darts.count), z_count);
    ck_assert_msg(std::fabs(z_pairs) < 4.5, "close pairs: sampler %.3f, dart throwing %.3f (z = %.2f)",
                  mean(sampler.close_pairs), mean(darts.close_pairs), z_pairs);
    ck_assert_msg(std::fabs(z_earlier) < 4.5, "distance to the nearest earlier point: sampler %.5f, dart throwing %.5f (z = %.2f)",
                  mean(sampler.to_earlier), mean(darts.to_earlier), z_earlier);
    ck_assert_msg(ks < 1.95, "distribution of N differs (KS %.3f)", ks);
}

// The reference itself keeps the rule and saturates: every later point
// outside every earlier disk, and probes on a (probes + 1)^2 grid over the
// box each in some closed disk (by the domain's distance, so across the seam
// on the torus). Brute force.
template <class Distance>
void assert_saturated(const oracle::Pattern& t, const Distance& distance, int probes) {
    for (std::size_t i = 0; i < t.p.size(); ++i)
        for (std::size_t j = i + 1; j < t.p.size(); ++j)
            ck_assert_msg(distance.d2(t.p[i], t.p[j]) >= t.r[i] * t.r[i], "point %zu inside point %zu's disk", j, i);
    const pds::Box& b = distance.box;
    for (int a = 0; a <= probes; ++a)
        for (int c = 0; c <= probes; ++c) {
            const pds::Point x{b.x0 + b.width() * a / probes, b.y0 + b.height() * c / probes};
            bool in = false;
            for (std::size_t i = 0; i < t.p.size() && !in; ++i) in = distance.d2(x, t.p[i]) <= t.r[i] * t.r[i];
            ck_assert_msg(in, "the probe (%g, %g) is in no disk", x.x, x.y);
        }
}

// Returns the share of the points the dart stage placed.
template <class Distance, class Radius>
double compare_with(const Config& c, oracle::DartThrowing<Distance, Radius> reference) {
    Sample sampler, darts;
    std::size_t from_darts = 0, from_regions = 0, total = 0;
    for (int seed = 1; seed <= c.runs; ++seed) {
        pds::Sampler s(c.field ? 1.0 : c.r, static_cast<std::uint64_t>(seed));
        configure(s, c);
        const oracle::Pattern a = run_to_the_end(s, &from_darts);
        total += a.p.size();
        from_regions += s.jones().region_stats().points;
        add(sampler, a, reference.distance());
        add(darts, reference.run(static_cast<std::uint64_t>(1000000 + seed)), reference.distance());
    }
    assert_stages(c, from_darts, total);
    // The parallel process carries its darts on into the free regions: they
    // must place a real share of the points, or the test would not test them.
    const double regions = static_cast<double>(from_regions) / static_cast<double>(total);
    if (c.threads != 0) ck_assert_msg(regions > 0.1, "the free regions' darts placed %.3f of the points", regions);
    else ck_assert_msg(from_regions == 0, "the free regions' darts ran without threads");
    assert_same_law(sampler, darts);
    return static_cast<double>(from_darts) / static_cast<double>(total);
}

// The sampler configured as c against dart throwing under c's rules;
// returns the share of the points the dart stage placed.
inline double compare(const Config& c) {
    using oracle::dart_throwing;
    const oracle::ConstantRadius one{c.r};
    const oracle::FieldRadius field{c.field, c.rmin, c.rmax};
    if (c.periodic && c.field)
        return compare_with(c, dart_throwing(oracle::Torus{c.box}, field));
    else if (c.periodic)
        return compare_with(c, dart_throwing(oracle::Torus{c.box}, one));
    else if (!c.rings.empty() && c.field)
        return compare_with(c, dart_throwing(oracle::InPolygon{c.rings}, field));
    else if (!c.rings.empty())
        return compare_with(c, dart_throwing(oracle::InPolygon{c.rings}, one));
    else if (c.field)
        return compare_with(c, dart_throwing(oracle::Plane{c.box}, field));
    else
        return compare_with(c, dart_throwing(oracle::Plane{c.box}, one));
}

}  // namespace law

#endif
