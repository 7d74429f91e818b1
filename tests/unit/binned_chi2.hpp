// binned_chi2.hpp - the two-sample chi-square of equal-size samples binned
// alike (test_free_area.cpp, test_power_cells.cpp): the sum over bins of
// (a - b)^2 / (a + b), with its degrees of freedom (bins used - 1); bins
// holding fewer than 10 of both together are too noisy to weigh and skipped.
#ifndef PDS_TEST_BINNED_CHI2_HPP
#define PDS_TEST_BINNED_CHI2_HPP

#include <cstddef>
#include <vector>

struct BinnedChi2 {
    double chi2 = 0.0;
    int dof = 0;
};

inline BinnedChi2 binned_chi2(const std::vector<double>& a, const std::vector<double>& b) {
    BinnedChi2 r;
    r.dof = -1;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (a[k] + b[k] < 10) continue;
        r.chi2 += (a[k] - b[k]) * (a[k] - b[k]) / (a[k] + b[k]);
        ++r.dof;
    }
    return r;
}

#endif
