// polygon_index.hpp - where a point lies against a polygonal outline
// (polygon_rings.hpp): inside, on it, or outside, by the even-odd rule, exactly.
//
// A point is inside when a ray from it crosses the outline an odd number of
// times. The crossing test is exact: an edge counts when one end lies above
// the point's height and the other at or below it (a vertex at the height
// counts as below, so a ray through a vertex counts the two edges there
// consistently), and the point lies on the ray's side of it by orient2d.
// A point on an edge is on the outline; the closed domain contains it.
//
// A grid over the bounding box makes this about constant time:
//   - each row lists the edges whose height range meets it, once sorted by
//     their right end and once by their left end, so a ray cast to either
//     side reads only the edges it can cross, and takes the shorter side;
//   - each cell that no edge meets ("clean") holds the answer for all its
//     points, found once: from the settled clean cell to its left in the
//     row, through the edges of the cut cells between, or by the row's ray
//     when there is none.
// An outline whose edges are long against their spacing (a comb's teeth)
// cuts nearly every cell of a grid sized by its edge count; a second, finer
// index then locates points (Polygon::locator), while this one keeps every
// other answer the sampler reads, so the points do not depend on it.
// The cells an edge meets are marked from its height band and its x range
// there, each widened by a slack of 2^-20 of a cell, far more than rounding
// can move them: a cell marked without need only costs a ray cast, one
// missed would be wrong. The cells keep their edges' lists too, for the
// short ray casts and the cells of the mesh that the outline cuts.
#ifndef PDS_POLYGON_INDEX_HPP
#define PDS_POLYGON_INDEX_HPP

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/point.hpp"
#include "domain/polygon_rings.hpp"

namespace pds {

// Whether p lies on the closed segment from a to b (exact).
bool on_segment(const Point& p, const Point& a, const Point& b);

class PolygonIndex {
public:
    // Where a point lies.
    enum Place : int { kOutside = -1, kOnOutline = 0, kInside = 1 };

    // Keeps a reference to rings: they must outlive the index. About
    // `cells` cells (cells_for_edges by default).
    explicit PolygonIndex(const PolygonRings& rings) : PolygonIndex(rings, cells_for_edges(rings)) {}
    PolygonIndex(const PolygonRings& rings, double cells);
    // About sixteen cells per edge, at least 1024 and at most kMaxCells.
    static double cells_for_edges(const PolygonRings& rings);
    static constexpr double kMaxCells = 4194304.0;  // 2^22
    // How many edges locate() reads on average for a point uniform in the
    // box: the lists of the cut cells its short ray passes, or half its
    // row's when no clean cell is near (polygon_locate.cpp).
    double expected_edges_read() const;
    // The cells of an index that only locates points, when this one makes
    // that costly: an outline whose edges are long against their spacing
    // (a comb's teeth, a ring of spikes) cuts nearly every cell near them,
    // and a short ray crosses many. 16 times the cells (at most kMaxCells)
    // when more than 2 edges are read on average; 0 when this index serves.
    double finer_cells_for_location() const;

    Place locate(const Point& p) const;
    // The closed domain: inside or on the outline.
    bool contains(const Point& p) const { return locate(p) != kOutside; }

    // The grid (tests, and the dart grids that skip clean outside cells).
    std::size_t columns() const { return cols_; }
    std::size_t rows() const { return rows_; }
    std::size_t column_of(double x) const {
        const double c = std::floor((x - box_.x0) * col_scale_);
        if (!(c > 0.0)) return 0;
        return c >= static_cast<double>(cols_) ? cols_ - 1 : static_cast<std::size_t>(c);
    }
    std::size_t row_of(double y) const {
        const double r = std::floor((y - box_.y0) * row_scale_);
        if (!(r > 0.0)) return 0;
        return r >= static_cast<double>(rows_) ? rows_ - 1 : static_cast<std::size_t>(r);
    }
    // Whether every grid cell box b overlaps is clean with place `place`.
    bool all_cells(const Box& b, Place place) const;
    // The same for the cells in columns c0..c1 and rows r0..r1 (inclusive).
    bool all_cells(std::size_t c0, std::size_t c1, std::size_t r0, std::size_t r1, Place place) const;
    // How many cells of another grid, whose cell (i, j) is [x0 + i sx,
    // x0 + (i + 1) sx] x [y0 + j sy, y0 + (j + 1) sy], i < cols, j < rows,
    // meet a cell of this one that is not outside (all_cells(box, kOutside)
    // is false). In time about this grid's cells plus cols plus rows, not
    // cols times rows (a sparse dart grid has up to ~10^10 cells).
    std::size_t grid_cells_not_outside(double x0, double sx, std::size_t cols, double y0, double sy,
                                       std::size_t rows) const;
    // kInside or kOutside for a clean cell, kOnOutline for one an edge may meet.
    Place cell_place(std::size_t col, std::size_t row) const {
        return static_cast<Place>(cell_[row * cols_ + col]);
    }

    // Grid cell k's edges (k = row * columns() + column): every edge that
    // meets the cell is among them.
    struct EdgeList {
        const std::uint32_t* first;
        const std::uint32_t* last;
        const std::uint32_t* begin() const { return first; }
        const std::uint32_t* end() const { return last; }
    };
    EdgeList cell_edges(std::size_t k) const {
        return EdgeList{cell_edges_.data() + cell_begin_[k], cell_edges_.data() + cell_begin_[k + 1]};
    }
    // The edges that may meet box b (those of every grid cell it overlaps),
    // appended to out sorted and without repeats. Every edge that meets b
    // is among them.
    void edges_near(const Box& b, std::vector<std::uint32_t>& out) const;
    // The edges that may cross the horizontal line at any height in
    // [y_lo, y_hi] widened by a row each way, appended sorted and without
    // repeats: for a ray cast from a point known only to lie in that band.
    void edges_in_rows(double y_lo, double y_hi, std::vector<std::uint32_t>& out) const;

    // An edge with the region on both of its sides or on neither (a ring
    // traced twice): it still counts in the parity of a ray that crosses
    // it, but a point on it is not on the outline for that; its copy or
    // the edges around decide (polygon.cpp finds these edges).
    void mark_cancelled(std::size_t edge) { cancelled_.at(edge) = 1; }
    bool cancelled(std::size_t edge) const { return cancelled_[edge] != 0; }

private:
    // The exact ray cast from p through the edges of its row.
    Place cast_ray(const Point& p, std::size_t row) const;
    // The same, only as far as the nearest clean cell along p's row or
    // column (p in column col): usually a few cells' edges, not the row's.
    Place cast_short_ray(const Point& p, std::size_t row, std::size_t col) const;
    // The nearest clean cell along the row or the column of (col, row),
    // within a short ray's reach: its direction and distance in cells.
    bool nearest_clean(std::size_t row, std::size_t col, int& dir, std::size_t& steps) const;
    // The same toward the settled clean cell `steps` cells away in direction
    // dir (kRight, kLeft, kUp, kDown), or by cast_ray when the cells between
    // hold too many edges.
    Place cast_toward(const Point& p, std::size_t row, std::size_t col, int dir, std::size_t steps) const;
    enum Direction : int { kRight = 0, kLeft = 1, kUp = 2, kDown = 3 };
    void mark_edge_cells(std::size_t edge);
    // Calls visit(k) for each grid cell k the edge marks.
    template <class Visit>
    void for_each_edge_cell(std::size_t edge, const Visit& visit) const;
    void settle_clean_cells();

    const PolygonRings& rings_;
    Box box_;
    std::size_t cols_ = 1, rows_ = 1;
    double col_scale_ = 0.0, row_scale_ = 0.0;  // cells per unit length
    std::vector<std::int8_t> cell_;             // a Place per cell
    // Row r's edges are by_right_[row_begin_[r] .. row_begin_[r + 1]), by
    // decreasing right end, and by_left_ over the same range, by increasing
    // left end.
    std::vector<std::size_t> row_begin_;
    std::vector<std::uint32_t> by_right_, by_left_;
    // Grid cell k's edges are cell_edges_[cell_begin_[k] .. cell_begin_[k + 1]),
    // from the same marking as cell_ (so a cell's list holds every edge
    // meeting it).
    std::vector<std::uint32_t> cell_begin_, cell_edges_;
    std::vector<std::uint8_t> cancelled_;  // per edge
};

}  // namespace pds

#endif
