// spatial_hash.hpp - points bucketed by square grid cells, for neighbour
// queries independent of the triangulation.
//
// Cells are slightly larger than the query radius, so every pair of points
// closer than the radius lies in the same or in adjacent cells even after the
// cell coordinates are rounded. Each occupied cell maps (through HashMap) to
// the first point in it; the others follow through a `next` chain. Memory is
// O(points) whatever the domain's size.
#ifndef PDS_SPATIAL_HASH_HPP
#define PDS_SPATIAL_HASH_HPP

#include <cstdint>
#include <vector>

#include "hash_map.hpp"
#include "point.hpp"

namespace pds {

class SpatialHash {
public:
    // Indexes points (all inside `domain`) for queries of radius `radius`.
    SpatialHash(const std::vector<Point>& points, std::size_t first, const Box& domain,
                double radius);

    // Calls visit(index) for every indexed point that may lie within the
    // radius of p (a superset: the caller decides exactly).
    template <class Visit>
    void for_each_near(const Point& p, const Visit& visit) const {
        const std::int64_t cx = cell_x(p), cy = cell_y(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                if (cx + dx < 0 || cy + dy < 0) continue;
                const std::uint32_t* head = cells_.find(key(cx + dx, cy + dy));
                for (std::uint32_t i = head ? *head : kEnd; i != kEnd; i = next_[i]) visit(i);
            }
        }
    }

private:
    static constexpr std::uint32_t kEnd = 0xFFFFFFFFu;
    std::int64_t cell_x(const Point& p) const;
    std::int64_t cell_y(const Point& p) const;
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) | static_cast<std::uint64_t>(y);
    }

    Box domain_;
    double cell_;
    HashMap cells_;
    std::vector<std::uint32_t> next_;
};

}  // namespace pds

#endif
