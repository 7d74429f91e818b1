// space_time_band.hpp - what one band of rows of the space-time dart
// process holds during an epoch (space_time_stage.cpp), and the order of
// its darts' times; for the stage's own files only.
#ifndef PDS_SPACE_TIME_BAND_HPP
#define PDS_SPACE_TIME_BAND_HPP

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/space_time_stream.hpp"
#include "darts/space_time_stage.hpp"

namespace pds {

// Time order, ties (of probability about 2^-53 a pair) broken by cell and
// place in the cell, so the order is total and fixed by the seed.
inline bool earlier(const SpaceTimeDartStage::Candidate& a, const SpaceTimeDartStage::Candidate& b) {
    if (a.t != b.t) return a.t < b.t;
    if (a.cell != b.cell) return a.cell < b.cell;
    return a.k < b.k;
}

// Each on its own cache lines: one worker writes a band's cursors while another
// reads the next band's bounds.
struct alignas(64) SpaceTimeDartStage::Band {
    std::int64_t r0 = 0, r1 = 0;  // its rows
    std::size_t a0 = 0, a1 = 0;   // its active cells, active_[a0..a1)
    std::size_t kept = 0;         // active cells still active after the epoch
    std::size_t thrown = 0;
    std::vector<Candidate> cands;                        // in the order of their cells
    std::unique_ptr<std::atomic<std::uint8_t>[]> state;  // outcomes, read by every band
    std::size_t state_room = 0;
    std::vector<std::uint64_t> stack;  // decide()'s
    struct Accepted {
        double t;
        std::uint32_t k;       // the candidate
        std::uint32_t number;  // its point's index (merge())
    };
    std::vector<Accepted> accepted;  // by time once sorted
    std::vector<Accepted> sorted;    // sort_by_time()'s scratch
    std::vector<std::uint32_t> starts;
    std::size_t head = 0;            // merge()'s cursor
    struct Darting {
        SpaceTimeStream stream;  // past the count
        std::uint32_t cell;
        unsigned darts;
    };
    std::vector<Darting> darting;  // draw()'s cells with darts this epoch
};

}  // namespace pds

#endif
