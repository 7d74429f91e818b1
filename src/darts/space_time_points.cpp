// space_time_points.cpp - the end of an epoch of the space-time dart
// process (space_time_stage.hpp): each band's accepted darts in order of
// time, numbered across the bands, written into the grid as points; then the
// cells left active.
#include <algorithm>
#include <vector>

#include "core/time_order.hpp"
#include "darts/space_time_band.hpp"
#include "darts/space_time_stage.hpp"

namespace pds {

void SpaceTimeDartStage::sort_by_time(Band& band) {
    // Into the band's scratch, kept from epoch to epoch (fresh pages each
    // epoch would cost a fault apiece), then swapped in.
    band.sorted.resize(band.accepted.size());
    order_by_time(
        band.accepted.size(),
        [&](const auto& put) {
            for (const Band::Accepted& x : band.accepted) put(x);
        },
        [](const Band::Accepted& x) { return x.t; },
        [&](const Band::Accepted& x, const Band::Accepted& y) {
            return x.t != y.t ? x.t < y.t : earlier(band.cands[x.k], band.cands[y.k]);
        },
        band.sorted.data(), band.starts);
    band.accepted.swap(band.sorted);
}

void SpaceTimeDartStage::merge() {
    // The bands' accepted candidates numbered by time: a merge of a few
    // lists sorted by resolve(), which reads the lists alone (the
    // candidates only for ties of time); write_points() puts the points in
    // place, band by band.
    std::size_t total = 0;
    for (Band& band : bands_) {
        band.head = 0;
        total += band.accepted.size();
    }
    pending_base_ = points_.size();
    next_pending_ = 0;
    pending_.resize(total);  // within the room run_epoch() reserved
    for (std::size_t next = 0; next < total; ++next) {
        Band* best = nullptr;
        for (Band& band : bands_) {
            if (band.head == band.accepted.size()) continue;
            if (best) {
                const Band::Accepted &x = band.accepted[band.head], &y = best->accepted[best->head];
                if (x.t > y.t || (x.t == y.t && !earlier(band.cands[x.k], best->cands[y.k]))) continue;
            }
            best = &band;
        }
        best->accepted[best->head++].number = static_cast<std::uint32_t>(pending_base_ + next);
    }
}

void SpaceTimeDartStage::write_points(Band& band) {
    // Each cell that listed candidates gets its point (at most one: a cell's
    // diagonal is under R), or is empty again.
    const auto cols = static_cast<std::uint32_t>(grid_.cols());
    for (const Candidate& c : band.cands) grid_.store_with_copies(c.cell % cols, c.cell / cols, 0);
    for (const Band::Accepted& x : band.accepted) {
        const Candidate& c = band.cands[x.k];
        pending_[x.number - pending_base_] = c.p;
        grid_.write(c.cell % cols, c.cell / cols, c.p, x.number);
        masks_[c.cell] = SpaceTimeGrid::kAllCovered;  // its point's disk holds it whole
    }
}

void SpaceTimeDartStage::drop_covered(Band& band) {
    // Cells whose sub-squares each lie in one disk leave: those with a
    // point (write_points()) and those whose masks grew whole in draw().
    std::size_t kept = band.a0;
    for (std::size_t i = band.a0; i < band.a1; ++i) {
        const std::uint32_t cell = active_[i];
        if (masks_[cell] != SpaceTimeGrid::kAllCovered) active_[kept++] = cell;
    }
    band.kept = kept - band.a0;
}

}  // namespace pds
