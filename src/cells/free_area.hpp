// free_area.hpp - the free region of one Voronoi cell: its area, and uniform
// points in it (Jones 2006, section 3.1 and figures 3-5).
//
// The free region of site c is its Voronoi cell, clipped to the domain, minus
// the disk of radius R around c. Inside the cell c is the nearest site, so a
// point there is free exactly when it is at least R from c, and the free
// regions of all cells tile the free area of the whole domain.
//
// A variable radius: power cells (weights R_i^2) instead of Voronoi cells.
// Inside c's power cell, a point covered by any disk is covered by c's
// (power_c <= power_i <= 0), so the same holds with c's own radius. A site
// may then lie outside its cell: the fan's pieces cover the cell and a
// shadow beside it (CellSink::shadow); `area` counts both, and is what the
// sampler selects by, and a point drawn in the shadow is rejected by the
// exact cell test. So the law stays exact.
//
// How: the cell is streamed as a fan of triangles around c (cell_stream.hpp),
// each cut into the paper's pieces (cell_pieces.hpp). Measuring and selecting
// (the chunk of pieces holding a target, then a piece in it) share one pass,
// so their sums agree to the last bit.
//
// Rounding: every streamed vertex carries a forward error bound. A cell is
// certified "covered" (area exactly 0) only when every clipping decision was
// certain and every clipped vertex is certainly within R of c; certified free
// when some vertex is certainly beyond R; otherwise it is "doubtful" and the
// exact classifier (cell_coverage.hpp) decides before the cell is sampled.
#ifndef PDS_FREE_AREA_HPP
#define PDS_FREE_AREA_HPP

#include <type_traits>

#include "cells/cell_pieces.hpp"
#include "cells/cell_stream.hpp"
#include "core/point.hpp"
#include "core/rng.hpp"

namespace pds {

struct CellMeasure {
    double area = 0.0;      // free area (with the shadow); exactly 0 when certified covered
    double shadow = 0.0;    // a site outside its power cell: area - shadow is the cell's
    double free() const { return area > shadow ? area - shadow : 0.0; }
    bool doubtful = false;  // rounding left the classification open
    double reach = 0.0;     // bound on the distance from the site to the cell's vertices
    double floor = 0.0;     // the least weight a possibly-free cell gets (area_floor)
};

// The smallest weight a possibly-free cell gets, so it stays selectable:
// 2^-100 of R^2 or of the cell's own area if smaller, far below any area
// rounding can resolve. The cell's area matters where the domain is far
// thinner than R: its cells, R long and a sliver wide, would otherwise all
// weigh R^2 2^-100, far above their free areas, and be chosen alike whatever
// their areas (and pds_free_area would sum the floors). Kept above the
// smallest normal double so a real cell whose area underflows stays
// selectable.
inline double area_floor(double r, double cell_area) {
    const double least = (cell_area < r * r ? cell_area : r * r) * 0x1.0p-100;
    return least > 0x1.0p-1022 ? least : 0x1.0p-1022;
}

// The sink's verdict on the cell as a whole.
inline CellMeasure verdict(const cell_stream::CellSink& sink, bool clip_doubtful, double r) {
    CellMeasure m;
    m.reach = sink.reach();
    m.floor = area_floor(r, sink.fan_area());
    if (!clip_doubtful && sink.certainly_out() == 0 && sink.undecided() == 0) return m;  // covered
    m.doubtful = clip_doubtful || sink.certainly_out() == 0;
    m.area = sink.sum() > m.floor ? sink.sum() : m.floor;
    m.shadow = sink.shadow();
    return m;
}

// Free area of the cell of q.site. `ring(visit)` must call visit(point) for
// every Delaunay neighbour of the site, counterclockwise.
template <class Ring>
CellMeasure measure_cell(const CellQuery& q, const Ring& ring) {
    cell_stream::CellSink sink(q.radius, -1.0);
    const bool clip_doubtful = cell_stream::stream_cell(q, ring, sink);
    return verdict(sink, clip_doubtful, q.radius);
}

// One pass over a cell that measures it and, for a target in [0, area), picks
// the chunk whose share of the area holds the target. When the target is
// reached the pass stops: `measure` then covers only the part walked, and is
// meaningful only when nothing was found.
struct CellSelection {
    explicit CellSelection(double r, double target) : sink(r, target) {}
    cell_stream::CellSink sink;
    CellMeasure measure;
    bool found() const { return sink.found(); }            // the running sum passed the target
    bool fallback() const { return sink.has_fallback(); }  // it did not, but a chunk has area
    const Chunk& chunk() const { return sink.chunk(); }
};

template <class Ring>
CellSelection select_in_cell(const CellQuery& q, const Ring& ring, double target) {
    CellSelection s(q.radius, target);
    s.sink.stop_at_target();
    const bool clip_doubtful = cell_stream::stream_cell(q, ring, s.sink);
    s.measure = verdict(s.sink, clip_doubtful, q.radius);
    return s;
}

// placed: *out holds the point; gave_up: no draw was accepted; rejected:
// (no retry asked) the one draw was refused by `accept`.
enum class SampleOutcome { placed, gave_up, rejected };

// Draws a point uniformly from one chunk of a cell's free region: a piece is
// chosen with probability proportional to its area (u in [0, 1)), then points
// are drawn in that piece until one lies in the free region and
// `accept(absolute point)` (the exact checks) agrees; an accept that also
// takes the piece hears which one the point came from (outline_clip.hpp). Retrying within the
// chosen piece keeps the law exact.
//
// retry false: a draw that `accept` refuses ends the sampling (rejected),
// for cells whose pieces reach outside them (a site outside its power cell).
template <class Accept>
SampleOutcome sample_chunk(const CellQuery& q, const Chunk& chunk, double u, Rng& rng,
                           const Accept& accept, int max_draws, Point* out, bool retry = true) {
    const double r2 = q.radius * q.radius;
    const int k = select_piece(chunk, r2, u);
    if (k < 0) return SampleOutcome::gave_up;
    const Piece& piece = chunk.pieces[k];
    for (int i = 0; i < max_draws; ++i) {
        Point rel;
        if (!draw_in_piece(piece, q.radius, r2, rng, &rel)) continue;
        const Point p{q.site.x + rel.x, q.site.y + rel.y};
        bool accepted;
        if constexpr (std::is_invocable_v<const Accept&, const Point&, const Piece&>) accepted = accept(p, piece);
        else accepted = accept(p);
        if (accepted) {
            *out = p;
            return SampleOutcome::placed;
        }
        if (!retry) return SampleOutcome::rejected;
    }
    return SampleOutcome::gave_up;
}

}  // namespace pds

#endif
