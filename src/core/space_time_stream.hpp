// space_time_stream.hpp - the random numbers of one cell in one epoch of a
// space-time dart process: the parallel opening's grid cells
// (darts/space_time_stage.hpp) and, after it, the Voronoi cells' free
// regions (jones/region_darts.hpp), each with its own salt.
//
// A counter-based stream: its state is a hash of (seed, cell, epoch), so a
// cell's darts are the same whichever thread draws them, in whatever order,
// and a cell that is never asked costs nothing. splitmix64 steps the state
// and mixes it (mix64, rng.hpp); the seed is salted so that these
// streams share nothing with the handle's generator (rng.hpp), which the
// Jones loop keeps using after the hand-over.
#ifndef PDS_SPACE_TIME_STREAM_HPP
#define PDS_SPACE_TIME_STREAM_HPP

#include <cmath>
#include <cstdint>

#include "core/rng.hpp"

namespace pds {

class SpaceTimeStream {
public:
    // The seed's part of every state: worked out once per epoch.
    static std::uint64_t salted(std::uint64_t seed) { return mix64(seed ^ 0x5DA47D5C0FFEE123ull); }
    SpaceTimeStream(std::uint64_t salted_seed, std::uint64_t cell, std::uint64_t epoch) {
        const std::uint64_t s = mix64(salted_seed + (cell + 1) * 0x9E3779B97F4A7C15ull);
        state_ = mix64(s ^ ((epoch + 1) * 0xD1B54A32D192ED03ull));
    }

    std::uint64_t next_u64() {
        state_ += 0x9E3779B97F4A7C15ull;
        return mix64(state_);
    }
    // Uniform on [0, 1), multiples of 2^-53.
    double next_double() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
    // A Poisson count of the given mean, by inversion; exp_minus_mean is
    // e^-mean (worked out once per epoch). Capped at 63, whose probability
    // is below 1e-19 for means up to kInvertUpTo.
    unsigned poisson(double mean, double exp_minus_mean) { return poisson_at(next_double(), mean, exp_minus_mean); }
    // A count of a larger mean: the sum of counts of equal means of at most
    // kInvertUpTo, each from the next draw (one inversion would pass the
    // cap, and beyond about 745 lose e^-mean to underflow).
    static constexpr double kInvertUpTo = 16.0;
    unsigned poisson_large(double mean) {
        const double parts = std::ceil(mean / kInvertUpTo);
        const double part = mean / parts, exp_minus_part = std::exp(-part);
        unsigned k = 0;
        for (double i = 0; i < parts; i += 1.0) k += poisson(part, exp_minus_part);
        return k;
    }
    // The count whose cumulative probability first passes u in [0, 1).
    static unsigned poisson_at(double u, double mean, double exp_minus_mean) {
        double p = exp_minus_mean, sum = p;
        unsigned k = 0;
        while (u >= sum && k < 63) {
            ++k;
            p *= mean / k;
            sum += p;
        }
        return k;
    }

private:
    std::uint64_t state_;
};

}  // namespace pds

#endif
