// poisson_gaps.hpp - which cells of a list draw darts in an epoch, without a
// draw for every cell.
//
// Each cell's count of darts in an epoch is Poisson of a small mean m, most
// of them zero. Whether a cell draws any is a coin of probability 1 - e^-m,
// the same for every cell and independent, so the number of cells without a
// dart before the next one with some is geometric: P(gap >= k) = e^-mk. One
// draw for each cell that has darts gives the gap to it; its count, given
// that it is at least one, comes from its own stream. Together the counts
// are independent Poisson of mean m, as if every cell had drawn its own, at
// about one draw in 1 / (1 - e^-m) of the cost (8.5 cells for m = 1/8).
//
// The gaps are found in a table of e^-mk built by repeated multiplication,
// not by a logarithm, so they are the same bits wherever the arithmetic is
// IEEE (the library and its WebAssembly build alike).
#ifndef PDS_POISSON_GAPS_HPP
#define PDS_POISSON_GAPS_HPP

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/space_time_stream.hpp"

namespace pds {

class PoissonGaps {
public:
    explicit PoissonGaps(double mean) : mean_(mean), exp_minus_mean_(std::exp(-mean)) {
        // Down to below 2^-53, the smallest v gap() is given.
        double p = 1.0;
        do {
            tail_.push_back(p);
            p *= exp_minus_mean_;
        } while (p >= 0x1.0p-54);
        tail_.push_back(p);
    }

    double mean() const { return mean_; }
    double exp_minus_mean() const { return exp_minus_mean_; }

    // The cells without darts before the next one with some.
    std::size_t gap(SpaceTimeStream& stream) const { return gap_at(1.0 - stream.next_double()); }
    // A cell's count given that it is at least one.
    unsigned count_of_darting(SpaceTimeStream& stream) const { return count_of_darting_at(stream.next_double()); }

    // The gap for v in (0, 1]: the largest k with e^-mk >= v (for v at
    // or below the table's end, its last entry's k).
    std::size_t gap_at(double v) const {
        std::size_t k = 0;
        while (k + 1 < tail_.size() && tail_[k + 1] >= v) ++k;
        return k;
    }
    // The count for u in [0, 1): the Poisson inversion of e^-m + u (1 -
    // e^-m), uniform past the count zero's share.
    unsigned count_of_darting_at(double u) const {
        return SpaceTimeStream::poisson_at(exp_minus_mean_ + u * (1.0 - exp_minus_mean_), mean_, exp_minus_mean_);
    }

private:
    double mean_, exp_minus_mean_;
    std::vector<double> tail_;  // tail_[k] = e^-mk; the last one below 2^-54
};

}  // namespace pds

#endif
