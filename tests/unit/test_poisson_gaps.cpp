// test_poisson_gaps.cpp - the gaps between the cells that draw darts
// (core/poisson_gaps.hpp): walked along rows as the parallel opening walks
// them, every cell's count is Poisson of the mean, independent of its
// neighbour's; the inversions' thresholds fall where e^-mk does; and the
// opening's points stay the same on any number of threads.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/poisson_gaps.hpp"
#include "core/rng.hpp"
#include "core/space_time_stream.hpp"
#include "darts/space_time_stage.hpp"
#include "domain/rectangle.hpp"
#include "suites.hpp"

namespace {

// Counts for rows x cells cells, walked as SpaceTimeDartStage::draw walks
// an epoch's active cells: each row's gaps from its own stream, each
// darting cell's count from its own.
std::vector<unsigned> counts_by_gaps(const pds::PoissonGaps& gaps, std::size_t rows, std::size_t cells) {
    std::vector<unsigned> counts(rows * cells, 0);
    for (std::size_t row = 0; row < rows; ++row) {
        pds::SpaceTimeStream row_stream(11, row, 3);
        for (std::size_t j = gaps.gap(row_stream); j < cells; j += 1 + gaps.gap(row_stream)) {
            pds::SpaceTimeStream cell_stream(12, row * cells + j, 3);
            counts[row * cells + j] = gaps.count_of_darting(cell_stream);
        }
    }
    return counts;
}

double poisson_probability(double mean, unsigned k) {
    return std::exp(-mean + k * std::log(mean) - std::lgamma(k + 1.0));
}

// Pearson's statistic of observed against expected counts, bins with an
// expectation under 10 pooled into the last one kept.
double pearson(const std::vector<double>& observed, const std::vector<double>& expected, int* dof) {
    double chi2 = 0.0, o_rest = 0.0, e_rest = 0.0;
    *dof = -1;
    for (std::size_t k = 0; k < observed.size(); ++k) {
        o_rest += observed[k];
        e_rest += expected[k];
        if (e_rest < 10.0) continue;
        chi2 += (o_rest - e_rest) * (o_rest - e_rest) / e_rest;
        ++*dof;
        o_rest = e_rest = 0.0;
    }
    return chi2;
}

}  // namespace

START_TEST(counts_are_poisson_of_the_mean) {
    // 10^6 cells for each mean: the histogram of counts against Poisson's.
    for (const double mean : {0.125, 0.6, 2.5}) {
        const pds::PoissonGaps gaps(mean);
        const std::size_t rows = 1000, cells = 1000, n = rows * cells;
        const std::vector<unsigned> counts = counts_by_gaps(gaps, rows, cells);
        std::vector<double> observed(24, 0.0), expected(24, 0.0);
        for (unsigned c : counts) observed[c < 23 ? c : 23] += 1.0;
        for (unsigned k = 0; k < 24; ++k) expected[k] = static_cast<double>(n) * poisson_probability(mean, k);
        int dof = 0;
        const double chi2 = pearson(observed, expected, &dof);
        ck_assert_int_ge(dof, 2);
        // About 5 standard deviations of the statistic past its mean.
        ck_assert_msg(chi2 < dof + 5.0 * std::sqrt(2.0 * dof), "mean %g: chi2 %g on %d dof (zeros %g, expected %g)", mean,
                      chi2, dof, observed[0], expected[0]);
    }
}
END_TEST

START_TEST(neighbours_draw_independently) {
    // Whether a cell and the next one in its row draw darts: the four
    // pairs' frequencies against the products of e^-m and 1 - e^-m.
    const double mean = 0.125;
    const pds::PoissonGaps gaps(mean);
    const std::size_t rows = 2000, cells = 500;
    const std::vector<unsigned> counts = counts_by_gaps(gaps, rows, cells);
    std::vector<double> observed(4, 0.0), expected(4, 0.0);
    const double q = 1.0 - std::exp(-mean), pairs = static_cast<double>(rows * (cells - 1));
    for (std::size_t row = 0; row < rows; ++row)
        for (std::size_t j = 0; j + 1 < cells; ++j)
            observed[2 * (counts[row * cells + j] > 0) + (counts[row * cells + j + 1] > 0)] += 1.0;
    expected[0] = pairs * (1 - q) * (1 - q);
    expected[1] = expected[2] = pairs * (1 - q) * q;
    expected[3] = pairs * q * q;
    double chi2 = 0.0;
    for (int k = 0; k < 4; ++k) chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
    // 3 degrees of freedom: 25 is far past its 0.9999 quantile (21.1).
    ck_assert_msg(chi2 < 25.0, "chi2 %g: pairs %g %g %g %g", chi2, observed[0], observed[1], observed[2], observed[3]);
}
END_TEST

START_TEST(thresholds_fall_at_the_powers) {
    const pds::PoissonGaps gaps(0.125);
    const double e = gaps.exp_minus_mean();
    ck_assert_uint_eq(gaps.gap_at(1.0), 0);
    ck_assert_uint_eq(gaps.gap_at(std::nextafter(e, 1.0)), 0);
    ck_assert_uint_eq(gaps.gap_at(e), 1);
    ck_assert_uint_eq(gaps.gap_at(e * e), 2);
    ck_assert_uint_eq(gaps.gap_at(std::nextafter(e * e, 0.0)), 2);
    ck_assert_uint_eq(gaps.gap_at(std::nextafter(e * e * e, 0.0)), 3);
    // The smallest v a stream gives: -ln(2^-53) / m = 293.6.
    ck_assert_uint_eq(gaps.gap_at(0x1.0p-53), 293);
    // No count of a darting cell is zero; its shares follow Poisson's past zero.
    ck_assert_uint_eq(gaps.count_of_darting_at(0.0), 1);
    const double one = 0.125 * e / (1.0 - e);  // P(1 | at least 1)
    ck_assert_uint_eq(gaps.count_of_darting_at(one * 0.999), 1);
    ck_assert_uint_eq(gaps.count_of_darting_at(one * 1.001), 2);
    ck_assert_uint_ge(gaps.count_of_darting_at(1.0 - 0x1.0p-53), 2);
}
END_TEST

START_TEST(opening_points_the_same_on_any_threads) {
    // Rows with few active cells late in the opening, split among bands
    // differently for each thread count: the same darts, the same points.
    const pds::Rectangle square(pds::Box{0, 0, 1, 1});
    std::vector<pds::Point> first;
    for (unsigned threads = 1; threads <= 5; ++threads) {
        pds::SpaceTimeDartStage stage(square, nullptr, 0.01, 77);
        stage.set_threads(threads);
        stage.reserve(20000);
        pds::Rng rng(1);
        while (stage.next(rng)) stage.add_next();
        ck_assert_uint_gt(stage.epochs(), 4);
        if (threads == 1) {
            first = stage.points();
            ck_assert_uint_gt(first.size(), 4000);
            continue;
        }
        ck_assert_uint_eq(stage.points().size(), first.size());
        for (std::size_t k = 0; k < first.size(); ++k)
            ck_assert_msg(stage.points()[k].x == first[k].x && stage.points()[k].y == first[k].y,
                          "threads %u: point %zu differs", threads, k);
    }
}
END_TEST

Suite* poisson_gaps_suite() {
    Suite* s = suite_create("poisson_gaps");
    TCase* t = tcase_create("poisson_gaps");
    tcase_add_test(t, counts_are_poisson_of_the_mean);
    tcase_add_test(t, neighbours_draw_independently);
    tcase_add_test(t, thresholds_fall_at_the_powers);
    tcase_add_test(t, opening_points_the_same_on_any_threads);
    suite_add_tcase(s, t);
    return s;
}
