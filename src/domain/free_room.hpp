// free_room.hpp - how much of a domain a set of disks leaves free, and how
// long their outline is inside it: an estimate on a lattice of sample points,
// for count mode's first radius around fixed points (sampler.cpp).
//
// The area: the share of the lattice's points inside the domain that lie in
// no disk (closed), times the domain's exact area; unbiased whatever the
// disks' sizes, with a sampling error of a few tenths of a percent.
// The outline: by Cauchy-Crofton, a curve of length L crosses the lattice's
// rows (spacing hy) and columns (spacing hx) N_rows and N_cols times with
// hy N_rows + hx N_cols about 4 L / pi on average over its directions. That
// counts the union of the disks at least two spacings wide; a narrower one,
// which the lattice may miss, adds its whole circumference (so on the high
// side: a count estimate from a longer outline asks for a larger radius,
// which count mode then lowers).
#ifndef PDS_FREE_ROOM_HPP
#define PDS_FREE_ROOM_HPP

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/point.hpp"
#include "domain/frame.hpp"

namespace pds {

struct FreeRoom {
    double area;     // the domain's area the disks leave free (internal frame)
    double outline;  // the disks' outline inside the domain
};

class FreeRoomLattice {
public:
    // The lattice over the frame's box, and which of its points lie in the
    // domain (its rectangle or polygon). Throws std::bad_alloc.
    explicit FreeRoomLattice(const Frame& frame);

    // For disks of radius radii[k] around centres[k] (internal frame).
    // Nothing (no estimate) when the lattice has no point in the domain, or
    // when the disks overlap so much that marking them would take over
    // kMaxMarksPerSample marks a lattice point.
    std::optional<FreeRoom> estimate(const std::vector<Point>& centres, const std::vector<double>& radii);

private:
    template <class Keep>
    void mark(const std::vector<Point>& centres, const std::vector<double>& radii, const Keep& keep);
    Point sample(std::int64_t i, std::int64_t j) const;
    // The lattice points in the box of the disk of radius r around c.
    struct Span {
        std::int64_t i0, i1, j0, j1;
    };
    Span span_of(const Point& c, double r) const;

    Box box_;
    double area_, hx_, hy_;
    std::vector<std::uint8_t> state_;  // a lattice point: outside, free or covered
    std::size_t inside_ = 0;
};

}  // namespace pds

#endif
