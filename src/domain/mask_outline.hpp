// mask_outline.hpp - the outline of a raster mask: the union of its inside
// pixels' squares as rings (polygon_rings.hpp), so a mask is a polygonal
// domain taken exactly.
//
// Every side between an inside and an outside pixel (or the raster's edge)
// is traced once, with the inside on its left; runs of sides along one line
// become one edge. Where two inside pixels touch only at a corner, the ring
// turns left there, so such pixels' rings touch at that vertex instead of
// crossing. Vertices lie on the pixel grid x0 + i (x1 - x0) / w, computed
// the same way wherever a grid line is used, so rings meet exactly.
#ifndef PDS_MASK_OUTLINE_HPP
#define PDS_MASK_OUTLINE_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"

namespace pds {

struct Outline {
    std::vector<double> xy;             // x y interleaved
    std::vector<std::size_t> ring_ends;  // as PolygonRings takes them
};

// inside: w * h bytes, row-major, row 0 along y0; nonzero is inside. Throws
// DomainError when no pixel is inside.
Outline mask_outline(std::size_t w, std::size_t h, const std::uint8_t* inside, const Box& box);

}  // namespace pds

#endif
