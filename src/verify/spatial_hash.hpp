// spatial_hash.hpp - points bucketed by grid cells, for neighbour queries
// independent of the triangulation.
//
// Cells are slightly larger than the query radius, so every pair of points
// closer than the radius lies in the same or in adjacent cells even after the
// cell coordinates are rounded. When the grid has at most a few cells per
// point (a pattern that fills its domain, as every pattern pds_verify sees at
// scale), the points are sorted by cell into one array with an offset per
// cell: about 10 bytes a point, read in order. A sparser grid maps each
// occupied cell (through HashMap) to the first point in it, the others
// following through a `next` chain, so memory stays O(points) whatever the
// domain's size. On a torus the cells divide the
// periods evenly and the neighbours of an edge cell wrap around, each with
// the shift that brings its points next to the query.
#ifndef PDS_SPATIAL_HASH_HPP
#define PDS_SPATIAL_HASH_HPP

#include <cstdint>
#include <vector>

#include "core/hash_map.hpp"
#include "core/point.hpp"
#include "core/torus.hpp"

namespace pds {

class SpatialHash {
public:
    // Indexes points[first..] (all inside `domain`) for queries of radius `radius`.
    SpatialHash(const std::vector<Point>& points, std::size_t first, const Box& domain,
                double radius);
    // The same on the torus t (t.on(); points in its fundamental domain).
    SpatialHash(const std::vector<Point>& points, std::size_t first, const Torus& t, double radius);

    // Calls visit(index, sx, sy) for every indexed point whose copy shifted by
    // (sx, sy) periods may lie within the radius of p (a superset: the caller
    // decides exactly). Off the torus sx = sy = 0.
    // Which layout was chosen (for tests): sorted by cell, or hashed.
    bool dense() const { return dense_; }

    template <class Visit>
    void for_each_near(const Point& p, const Visit& visit) const {
        const std::int64_t cx = cell(p.x, x0_, cell_x_, cols_), cy = cell(p.y, y0_, cell_y_, rows_);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                std::int64_t x = cx + dx, y = cy + dy;
                int sx = 0, sy = 0;
                if (!onto_grid(&x, cols_, &sx) || !onto_grid(&y, rows_, &sy)) continue;
                if (dense_) {
                    if (x >= dense_cols_ || y >= dense_rows_) continue;
                    const std::size_t c = static_cast<std::size_t>(y * dense_cols_ + x);
                    for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) visit(sorted_[k], sx, sy);
                    continue;
                }
                const std::uint32_t* head = cells_.find(key(x, y));
                for (std::uint32_t i = head ? *head : kEnd; i != kEnd; i = next_[i]) visit(i, sx, sy);
            }
        }
    }

private:
    static constexpr std::uint32_t kEnd = 0xFFFFFFFFu;
    // The cell of coordinate v along one axis: clamped at 0 and, on a torus
    // (n cells to a period, n > 0), at n - 1.
    static std::int64_t cell(double v, double origin, double width, std::int64_t n);
    // Brings column or row c onto the grid: on a torus by a whole period
    // (*shift: which way); in the plane only c >= 0 is on it (n == 0).
    static bool onto_grid(std::int64_t* c, std::int64_t n, int* shift) {
        if (n == 0) return *c >= 0;
        if (*c < 0) *c += n, *shift = -1;
        else if (*c >= n) *c -= n, *shift = 1;
        return true;
    }
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) | static_cast<std::uint64_t>(y);
    }
    void index(const std::vector<Point>& points, std::size_t first);
    // The sorted layout, when the grid over the extent (width, height) has at
    // most kDenseCellsPerPoint cells per point; false otherwise.
    bool index_dense(const std::vector<Point>& points, std::size_t first, double width, double height);

    double x0_, y0_;
    double cell_x_, cell_y_;
    std::int64_t cols_ = 0, rows_ = 0;  // cells to a period on the torus; 0 in the plane
    HashMap cells_;
    std::vector<std::uint32_t> next_;
    bool dense_ = false;
    std::int64_t dense_cols_ = 0, dense_rows_ = 0;
    std::vector<std::uint32_t> start_;  // dense: cell c's points are sorted_[start_[c], start_[c + 1])
    std::vector<std::uint32_t> sorted_;
};

}  // namespace pds

#endif
