// polygon_slabs.hpp - uniform points of a polygon by its vertical slabs, for
// a polygon far thinner than its outline grid's cells (a strip 1e-12 wide
// along a diagonal), where rejection over those cells would need about
// 10^11 tries a point.
//
// Between consecutive vertex abscissae, the edges that span a slab, in order
// of their height at its middle, bound its parts pairwise by the even-odd
// rule: trapezoids. Edges never cross inside a slab (polygon_splits.hpp
// splits them where they cross, and the split points are vertices), so the
// pairs hold across the slab. A slab is chosen by its area, a trapezoid in
// it by area, a point in that uniformly. Floating point: the pieces follow
// the edges as rounded, so a draw is only kept after the exact test
// (Polygon::uniform_point).
//
// Cost: building sorts the vertices' abscissae and sweeps the edges once,
// O(V log V + sum over slabs of A log A) with A the edges spanning a slab,
// and keeps one double a slab; a draw scans the edges once, O(V).
#ifndef PDS_POLYGON_SLABS_HPP
#define PDS_POLYGON_SLABS_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "core/rng.hpp"
#include "core/trapezoid.hpp"
#include "domain/polygon_rings.hpp"

namespace pds {

class PolygonSlabs {
public:
    // Refers to rings, which must outlive it.
    explicit PolygonSlabs(const PolygonRings& rings);

    // The trapezoids' total area (the polygon's, up to rounding).
    double area() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
    // A point uniform in the trapezoids; false when they have no area.
    bool draw(Rng& rng, Point* out) const;

private:
    // The parts of the slab between x0 and x1 from the edges spanning it.
    void parts_of(const std::vector<std::uint32_t>& edges, double x0, double x1, std::vector<Trapezoid>& out) const;

    const PolygonRings& rings_;
    std::vector<double> xs_;          // the vertices' distinct abscissae, ascending
    std::vector<double> cumulative_;  // area of slabs 0..i
};

}  // namespace pds

#endif
