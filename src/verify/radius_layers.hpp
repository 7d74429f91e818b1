// radius_layers.hpp - points with radii, bucketed by class of radius and by
// grid cell: the neighbour search of the spacing check when the radius varies.
//
// One grid with cells as wide as the largest radius puts (rmax/r)^2 points
// in a cell where the radius is r, so checking a 1000:1 field through it
// costs about 10^6 distance tests a point. Here the points are grouped by the
// binary exponent of their radius (a class: radii in [2^e, 2^(e+1))), and
// each class has a grid of its own, with cells a little wider than the
// class's largest radius. Invariants, and what they buy:
//   - a pair closer than the largest radius of a class, one of them in that
//     class, lies in the same or in adjacent cells of the class's grid (the
//     3 x 3 block around the other point), even after rounding;
//   - in a valid pattern two points of one class are more than half a cell
//     apart (the later lies outside the earlier's disk, whose radius is over
//     half the class's largest), so a block holds a bounded number of them.
// A pair breaks the rule only if it is closer than the larger of its two
// radii; for_each_near, called from the point in the lower class, looks in
// the block of every class at or above its own, which finds every such
// pair: the work per point is a constant times the number of classes, not
// (rmax/rmin)^2.
//
// Layout (about 10 bytes a point, as spatial_hash.hpp): one array of point
// indices sorted by class and cell; per class, where each cell's run starts,
// either for every cell of a grid over the class's bounding box (the classes
// with the fewest cells first, within a few cells a point in all) or,
// through HashMap, for the occupied cells only, so memory stays O(points)
// however the classes spread. On a torus the cells divide the periods and
// the neighbours of an edge cell wrap around, each with the shift that
// brings its points next to the query, as in spatial_hash.hpp.
#ifndef PDS_RADIUS_LAYERS_HPP
#define PDS_RADIUS_LAYERS_HPP

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "core/hash_map.hpp"
#include "core/point.hpp"
#include "core/torus.hpp"

namespace pds {

class RadiusLayers {
public:
    // radius_of(i): the radius of points[i], which must be usable.
    using RadiusOf = std::function<double(std::size_t)>;
    // Positive and finite: a radius with a class (and a rule can use).
    static bool usable(double r) { return r > 0.0 && r <= std::numeric_limits<double>::max(); }

    // Indexes points[first..] in the plane.
    RadiusLayers(const std::vector<Point>& points, std::size_t first, const RadiusOf& radius_of);
    // The same on the torus t (t.on(); points in its fundamental domain).
    RadiusLayers(const std::vector<Point>& points, std::size_t first, const Torus& t, const RadiusOf& radius_of);

    // Calls visit(index, sx, sy, same) for every indexed point in a class at
    // or above that of radius r whose copy shifted by (sx, sy) periods may
    // lie within its class's largest radius of p (a superset: the caller
    // decides exactly; p's own index among them); same: the point is in r's
    // class (whose points all look in it: the pair is visited from both
    // sides). Off the torus sx = sy = 0.
    template <class Visit>
    void for_each_near(const Point& p, double r, const Visit& visit) const {
        const int e = std::ilogb(r);
        for (std::size_t k = layers_.size(); k-- > 0 && layers_[k].exponent >= e;) {
            const Layer& L = layers_[k];
            const bool same = L.exponent == e;
            const double fx = std::floor((p.x - L.x0) / L.cell_x), fy = std::floor((p.y - L.y0) / L.cell_y);
            if (L.cols_torus > 0) {
                near_on_torus(L, clamp_cell(fx, L.cols_torus), clamp_cell(fy, L.rows_torus), same, visit);
                continue;
            }
            // The block misses a grid it lies one cell or more beyond.
            if (!(fx >= -1.0 && fx <= static_cast<double>(L.cols) && fy >= -1.0 && fy <= static_cast<double>(L.rows)))
                continue;
            const std::int64_t cx = static_cast<std::int64_t>(fx), cy = static_cast<std::int64_t>(fy);
            const std::int64_t x_lo = cx > 0 ? cx - 1 : 0, x_hi = cx + 1 < L.cols ? cx + 1 : L.cols - 1;
            const std::int64_t y_lo = cy > 0 ? cy - 1 : 0, y_hi = cy + 1 < L.rows ? cy + 1 : L.rows - 1;
            for (std::int64_t y = y_lo; y <= y_hi; ++y) {
                if (L.dense) {
                    // The runs of a row's cells follow each other: one range.
                    const std::size_t row = static_cast<std::size_t>(y * L.cols);
                    const std::size_t first = row + static_cast<std::size_t>(x_lo);
                    const std::size_t last = row + static_cast<std::size_t>(x_hi);
                    for (std::uint32_t j = L.runs[first]; j < L.runs[last + 1]; ++j)
                        visit(order_[j], 0, 0, same);
                    continue;
                }
                for (std::int64_t x = x_lo; x <= x_hi; ++x) {
                    const std::uint32_t* run = L.cells.find(key(x, y));
                    if (run) visit_run(*run, L, 0, 0, same, visit);
                }
            }
        }
    }

    // For tests: the classes, how many of them use the dense layout, and
    // the bytes the index holds.
    std::size_t layer_count() const { return layers_.size(); }
    std::size_t dense_count() const;
    std::size_t bytes() const;

private:
    // One class: radii in [2^exponent, 2^(exponent + 1)).
    struct Layer {
        int exponent = 0;
        double largest = 0.0;   // its largest radius
        std::uint32_t size = 0;  // its points
        double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  // the plane: its points' bounding box
        double cell_x = 0.0, cell_y = 0.0;
        std::int64_t cols = 0, rows = 0;               // the grid's cells per axis
        std::int64_t cols_torus = 0, rows_torus = 0;   // the same on a torus (cells to a period); 0 in the plane
        bool dense = false;
        // Run k: the points order_[runs[k], runs[k + 1]); dense, run k is
        // cell k (row-major), else cells maps a cell's key to its run.
        std::vector<std::uint32_t> runs;
        HashMap cells;
    };

    template <class Visit>
    void visit_run(std::uint32_t run, const Layer& L, int sx, int sy, bool same, const Visit& visit) const {
        for (std::uint32_t j = L.runs[run]; j < L.runs[run + 1]; ++j) visit(order_[j], sx, sy, same);
    }
    // The 3 x 3 block around cell (cx, cy) of L on the torus: the cells
    // beyond an edge wrap around (a grid of one or two cells a period meets
    // the same cell more than once, each time with another shift).
    template <class Visit>
    void near_on_torus(const Layer& L, std::int64_t cx, std::int64_t cy, bool same, const Visit& visit) const {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                std::int64_t x = cx + dx, y = cy + dy;
                int sx = 0, sy = 0;
                wrap(&x, L.cols, &sx);
                wrap(&y, L.rows, &sy);
                if (L.dense) {
                    visit_run(static_cast<std::uint32_t>(y * L.cols + x), L, sx, sy, same, visit);
                } else if (const std::uint32_t* run = L.cells.find(key(x, y))) {
                    visit_run(*run, L, sx, sy, same, visit);
                }
            }
        }
    }

    // Column (or row) f, already floored, clamped into [0, n).
    static std::int64_t clamp_cell(double f, std::int64_t n) {
        if (!(f > 0.0)) return 0;
        return f >= static_cast<double>(n) ? n - 1 : static_cast<std::int64_t>(f);
    }
    // Brings column or row c of a torus grid of n onto it by a whole period
    // (*shift: which way).
    static void wrap(std::int64_t* c, std::int64_t n, int* shift) {
        if (*c < 0) *c += n, *shift = -1;
        else if (*c >= n) *c -= n, *shift = 1;
    }
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) | static_cast<std::uint64_t>(y);
    }

    // The classes of points[first..], their sizes, largest radii and (in
    // the plane) bounding boxes, lowest exponent first.
    void find_layers(const std::vector<Point>& points, std::size_t first, const RadiusOf& radius_of);
    // The class of radius r (one of layers_).
    std::size_t layer_of(double r) const;
    // Which classes get the dense layout, within a budget of cells for all.
    void choose_layouts(std::size_t points);
    // The points into order_, by class and cell.
    void index(const std::vector<Point>& points, std::size_t first, const RadiusOf& radius_of);
    // The cell (column, row) of p in L's grid.
    static void cell_of(const Layer& L, const Point& p, std::int64_t* x, std::int64_t* y);

    std::vector<Layer> layers_;
    int lowest_exponent_ = 0;
    std::vector<std::uint32_t> layer_at_;  // layers_ index of exponent lowest_exponent_ + k
    std::vector<std::uint32_t> order_;
};

}  // namespace pds

#endif
