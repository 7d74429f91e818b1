// outline_clip.hpp - a cell inside a polygonal domain: the region (cell ∩ P)
// as the fan of its boundary around the site, for free_area.hpp's pieces.
//
// The cell, clipped to the box, arrives from the pipeline (cell_stream.hpp)
// as a convex polygon around the site. When the domain's grid (polygon_index
// .hpp) says the cell's box is inside, it goes on as it is: most cells cost
// one lookup more than in a rectangle. Otherwise the cell is cut: its edges
// split where the outline crosses them, the parts inside the domain kept,
// and the outline's edges clipped to the cell, turned so the domain lies on
// their left. Every boundary segment of (cell ∩ P), region on its left, then
// feeds the fan; their order does not matter.
//
// Why the fan still measures the region: the triangles (site, a, b) over
// the boundary, signed by their turn, cover each point the number of times
// the boundary winds around it: once inside, zero outside. Counterclockwise
// triangles are the exits of a ray from the site, clockwise ones its
// entries (CellSink::shadow). So the sum of the counterclockwise pieces'
// free areas minus the clockwise ones' is the free area of the region; a
// point drawn from the counterclockwise pieces is counted once for each exit
// beyond it. It is kept only from the first exit beyond it (counts()): then
// every free point is drawn with the same density, and the law is exact. A
// draw refused there ends the selection (no retry in the piece), as for a
// site outside its power cell.
//
// Rounding: the cut is computed in floating point; every vertex it makes
// carries an error bound widened by a margin far above rounding, and a cut
// made at a grazing angle marks the cell doubtful. A cell is only ever
// declared covered by its vertices or by the exact test
// (polygon_coverage.hpp), and every kept point is checked exactly.
#ifndef PDS_OUTLINE_CLIP_HPP
#define PDS_OUTLINE_CLIP_HPP

#include <cstdint>
#include <vector>

#include "cells/cell_pieces.hpp"
#include "cells/cell_stream.hpp"
#include "cells/region_trapezoids.hpp"
#include "core/point.hpp"
#include "domain/polygon.hpp"

namespace pds {

class OutlineClip {
public:
    using Vtx = cell_stream::Vtx;

    // Reserves its scratch: the loop measures a new cell between changes
    // to the mesh, where nothing may allocate, so the vectors only grow for
    // a cell beyond these sizes (a site of degree 256, or 4096 outline
    // edges near one cell).
    explicit OutlineClip(const Polygon& polygon) : polygon_(polygon) {
        cell_.reserve(256);
        segments_.reserve(4096);
        edges_.reserve(4096);
        cuts_.reserve(4096);
    }

    // The last cell streamed through sink(): whether the outline cut it (its
    // pieces may then reach outside the region), and the outline edges near it.
    bool cut() const { return cut_; }
    bool doubtful() const { return doubtful_; }
    const std::vector<std::uint32_t>& edges() const { return edges_; }
    // The last cut cell's region (cell and domain) outside the disk of
    // radius r about its site, relative to the site, as trapezoids
    // (region_trapezoids.hpp). Allocates its scratch once.
    const std::vector<Trapezoid>& region_trapezoids(double r) {
        cut_into_trapezoids(segments_, trapezoid_xs_, trapezoid_crossings_, trapezoid_stack_);
        drop_inside_disk(trapezoid_stack_, r, trapezoid_split_, trapezoids_);
        return trapezoids_;
    }
    std::vector<double>& trapezoid_sums() { return trapezoid_sums_; }  // scratch for a draw among them
    const Polygon& polygon() const { return polygon_; }

    // Whether a draw p (absolute) from `piece` (relative to site) of the last
    // cell is counted: no outline edge separates it from the piece's edge
    // along the ray from the site (the first exit beyond p).
    bool counts(const Point& site, const Point& p, const Piece& piece, double r) const;

    // The stage between the cell pipeline's fan and a sink: collects the
    // clipped cell, then feeds the sink the region's boundary.
    template <class Sink>
    class Stage {
    public:
        Stage(OutlineClip& clip, Sink& sink, const Point& site, const Box& box, double r)
            : clip_(clip), sink_(sink), site_(site), box_(box), r_(r) {
            clip_.cell_.clear();
        }
        void vertex(const Vtx& v) { clip_.cell_.push_back(v); }
        void edge(const Vtx&, const Vtx&) {}
        bool done() const { return false; }
        void finish() {
            if (!clip_.cut_cell(site_, box_, r_)) {
                // Uncut: the cell as it came, as the pipeline's own fan feeds it.
                const std::vector<Vtx>& cell = clip_.cell_;
                for (std::size_t i = 0; i < cell.size(); ++i) {
                    sink_.vertex(cell[i]);
                    if (i > 0) sink_.edge(cell[i - 1], cell[i]);
                }
                if (!cell.empty()) sink_.edge(cell.back(), cell.front());
                sink_.finish();
                return;
            }
            for (const Segment& s : clip_.segments_) {
                sink_.vertex(s.a);
                sink_.vertex(s.b);
                sink_.edge(s.a, s.b);
            }
            sink_.finish();
        }

    private:
        OutlineClip& clip_;
        Sink& sink_;
        Point site_;
        Box box_;
        double r_;
    };

private:
    struct Segment {
        Vtx a, b;
    };
    // cell_ -> segments_ (and cut_, doubtful_, edges_); returns cut_. An
    // uncut cell leaves segments_ alone: cell_ is its boundary.
    bool cut_cell(const Point& site, const Box& box, double r);
    void keep_cell_edges(const Point& site, const Box& box, double margin);
    void keep_whole_cell(const Point& site, double margin);  // a cell no edge meets
    void keep_outline_edges(const Point& site, const Box& box, double margin);

    const Polygon& polygon_;
    std::vector<Vtx> cell_;             // the cell clipped to the box, relative to the site
    std::vector<Segment> segments_;     // the region's boundary, region on the left
    std::vector<std::uint32_t> edges_;  // outline edges near the cell
    std::vector<double> cuts_;          // scratch: where one cell edge is crossed
    std::vector<Trapezoid> trapezoids_;  // region_trapezoids() and its scratch
    std::vector<Trapezoid> trapezoid_stack_, trapezoid_split_;
    std::vector<double> trapezoid_sums_;
    std::vector<double> trapezoid_xs_;
    std::vector<trapezoid_detail::Crossing> trapezoid_crossings_;
    bool cut_ = false;
    bool doubtful_ = false;
};

}  // namespace pds

#endif
