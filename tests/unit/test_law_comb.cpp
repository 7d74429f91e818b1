// test_law_comb.cpp - the law through whole runs where nearly every cell is
// cut and folded: a comb of ten teeth 0.01 wide, 0.1 apart, at R 0.3, so a
// cell reaches across several teeth and a ray from its site leaves the comb
// and enters it again many times. The fan's draws there count only from the
// first exit beyond them, with no retry in the piece (outline_clip.hpp);
// these tests check that every point of a run, not only the first two,
// follows random sequential adsorption in the polygon.
//
// Against saturated dart throwing in the same polygon (dart_throwing.hpp's
// InPolygon, its own even-odd test), over many seeds: the count N (z test
// and Kolmogorov-Smirnov), the near-contact pairs (distance < 1.1 R), and
// the mean distance from each point to the nearest point placed before it,
// over R. Both samplers place points in their random-sequential order, so
// that last statistic sees where each new point fell relative to its cell's
// site. For the Jones loop alone, the free regions' darts from the first
// point (the parallel process), and cut cells drawn by trapezoids.
//
// Measured (2000 seeds each side): every z within 2. Mutants, each run
// through this test: a draw counted at every exit beyond it
// (OutlineClip::counts always true) gives z -10.2 (the Jones loop) and
// -12.6 (the free regions' darts) on the sequential distance; a retry in
// a cut cell's piece gives 15.3 in the Jones loop and 6.6 in the darts,
// each mutated alone; a trapezoid chosen by its index, not its area, gives
// 16.6 on N. Not seen here: x drawn uniformly across a trapezoid instead
// of by its area's distribution (z 1.9 at most; the slabs' draws in
// test_polygon_slabs.cpp catch it, chi-square 11688).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "dart_throwing.hpp"
#include "domain/polygon.hpp"
#include "law_compare.hpp"
#include "polygon_rings.hpp"
#include "sampler/sampler.hpp"
#include "suites.hpp"

namespace {

constexpr double kRadius = 0.3;

// A base [0,1]x[0,0.2] and ten teeth 0.01 wide up to y = 1, one at the
// right of each tenth of the width; counter-clockwise.
std::vector<double> thin_comb() {
    const double width = 0.01;
    std::vector<double> xy{0, 0, 1, 0};
    for (int k = 10; k >= 1; --k) {
        const double right = 0.1 * k;
        xy.insert(xy.end(), {right, 1.0, right - width, 1.0, right - width, 0.2});
        if (k > 1) xy.insert(xy.end(), {right - 0.1, 0.2});
    }
    xy.insert(xy.end(), {0.0, 0.2});
    return xy;
}

struct Statistics {
    std::vector<double> count, close_pairs, to_earlier;

    void add(const std::vector<pds::Point>& p) {
        double close = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            for (std::size_t j = i + 1; j < p.size(); ++j)
                if (std::hypot(p[i].x - p[j].x, p[i].y - p[j].y) < 1.1 * kRadius) ++close;
        count.push_back(static_cast<double>(p.size()));
        close_pairs.push_back(close);
        to_earlier.push_back(law::mean_distance_to_earlier(p, oracle::Plane{pds::Box{0, 0, 1, 1}}) / kRadius);
    }
};

enum class Draws { jones_loop, region_darts, trapezoids };

const char* name_of(Draws d) {
    return d == Draws::jones_loop ? "the Jones loop" : d == Draws::region_darts ? "the free regions' darts" : "trapezoids";
}

// The library's pattern for a seed, drawn as `draws` says, checked inside
// and maximal; adds the points the free regions' darts placed.
std::vector<pds::Point> library_pattern(const std::vector<double>& ring, Draws draws, std::uint64_t seed,
                                        std::size_t* from_regions) {
    pds::Sampler s(kRadius, seed);
    s.set_polygon(std::make_shared<const pds::Polygon>(rings_of({ring})));
    if (draws == Draws::region_darts) {
        s.carry_region_darts_from_start();
        s.set_region_darts_per_cell(16.0);  // an epoch seldom ends with no point
    } else {
        s.skip_dart_stage();
        if (draws == Draws::trapezoids) s.draw_cut_cells_by_region();
    }
    std::size_t added = 0;
    ck_assert(s.run(0, &added) == pds::Sampler::RunEnd::complete);
    if (!s.verify().maximal) ck_abort_msg("%s, seed %llu: not maximal", name_of(draws), static_cast<unsigned long long>(seed));
    *from_regions += s.jones().region_stats().points;
    std::vector<double> xy(2 * s.count());
    s.copy_points(0, s.count(), xy.data());
    std::vector<pds::Point> p;
    for (std::size_t k = 0; k < s.count(); ++k) p.push_back({xy[2 * k], xy[2 * k + 1]});
    return p;
}

}  // namespace

START_TEST(reference_in_the_comb_is_maximal) {
    // The reference's patterns lie in the comb, R apart, and leave no room:
    // no point of a fine lattice over the box is in the comb and outside
    // every disk. A reference that stopped early would fail it.
    const oracle::InPolygon comb({thin_comb()});
    auto reference = oracle::dart_throwing(comb, oracle::ConstantRadius{kRadius});
    const std::uint64_t seeds = test_light() ? 4 : 20;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        const oracle::Pattern t = reference.run(seed);
        for (std::size_t i = 0; i < t.p.size(); ++i) {
            ck_assert(comb.inside(t.p[i]));
            for (std::size_t j = i + 1; j < t.p.size(); ++j) ck_assert(comb.d2(t.p[i], t.p[j]) >= kRadius * kRadius);
        }
        for (int a = 0; a <= 1000; ++a)  // ten columns across each tooth
            for (int b = 0; b <= 200; ++b) {
                const pds::Point q{a / 1000.0, b / 200.0};
                if (!comb.inside(q)) continue;
                bool covered = false;
                for (const pds::Point& p : t.p) covered = covered || comb.d2(p, q) < kRadius * kRadius;
                if (!covered) ck_abort_msg("seed %llu: (%g, %g) is free", static_cast<unsigned long long>(seed), q.x, q.y);
            }
    }
}
END_TEST

START_TEST(whole_runs_in_folded_cells_keep_the_law) {
    const Draws draws = static_cast<Draws>(_i);
    const std::vector<double> ring = thin_comb();
    const int runs = test_light() ? 300 : 2000;
    auto reference = oracle::dart_throwing(oracle::InPolygon({ring}), oracle::ConstantRadius{kRadius});
    Statistics lib, ref;
    std::size_t from_regions = 0;
    for (int k = 1; k <= runs; ++k) {
        lib.add(library_pattern(ring, draws, static_cast<std::uint64_t>(k), &from_regions));
        ref.add(reference.run(1000000 + static_cast<std::uint64_t>(k)).p);
    }
    if (draws == Draws::region_darts)
        ck_assert_msg(from_regions > static_cast<std::size_t>(runs) * 3, "%zu points by the free regions' darts",
                      from_regions);
    else
        ck_assert_uint_eq(from_regions, 0);
    const double zn = law::z_score(lib.count, ref.count), zc = law::z_score(lib.close_pairs, ref.close_pairs);
    const double ze = law::z_score(lib.to_earlier, ref.to_earlier), ks = law::ks_scaled(lib.count, ref.count);
    const char* what = name_of(draws);
    if (std::getenv("PDS_LAW_PRINT"))
        std::printf("%s: N %.4f / %.4f (z %.2f, KS %.2f), close pairs %.4f / %.4f (z %.2f), to earlier %.5f / %.5f (z %.2f); %zu points by region darts\n",
                    what, law::mean(lib.count), law::mean(ref.count), zn, ks, law::mean(lib.close_pairs),
                    law::mean(ref.close_pairs), zc, law::mean(lib.to_earlier), law::mean(ref.to_earlier), ze, from_regions);
    ck_assert_msg(std::fabs(zn) < 4.5, "%s: N %.4f, reference %.4f (z %.2f)", what, law::mean(lib.count),
                  law::mean(ref.count), zn);
    ck_assert_msg(std::fabs(zc) < 4.5, "%s: close pairs %.4f, reference %.4f (z %.2f)", what,
                  law::mean(lib.close_pairs), law::mean(ref.close_pairs), zc);
    ck_assert_msg(std::fabs(ze) < 4.5, "%s: distance to the nearest earlier point %.5f R, reference %.5f R (z %.2f)",
                  what, law::mean(lib.to_earlier), law::mean(ref.to_earlier), ze);
    ck_assert_msg(ks < 1.95, "%s: the distribution of N differs (KS %.3f)", what, ks);
}
END_TEST

Suite* law_comb_suite() {
    Suite* s = suite_create("law_comb");
    TCase* t = tcase_create("whole runs in folded cells");
    tcase_set_timeout(t, 600);
    tcase_add_test(t, reference_in_the_comb_is_maximal);
    tcase_add_loop_test(t, whole_runs_in_folded_cells_keep_the_law, 0, 3);
    suite_add_tcase(s, t);
    return s;
}
