// free_area.hpp - the free region of one Voronoi cell: its area, and uniform
// points in it (Jones 2006, section 3.1 and figures 3-5).
//
// The free region of site c is its Voronoi cell, clipped to the domain, minus
// the disk of radius R around c. Inside the cell c is the nearest site, so a
// point there is free exactly when it is at least R from c, and the free
// regions of all cells tile the free area of the whole domain.
//
// The cell is streamed, never stored: the Delaunay neighbours of c arrive
// counterclockwise, consecutive pairs give the Voronoi vertices, four
// Sutherland-Hodgman stages clip them to the domain, and the clipped polygon's
// edges form the triangle fan around c. No allocation happens, whatever the
// vertex degree, so the sampler can update cells right after an insertion.
//
// Rounding: every streamed vertex carries a forward error bound. A cell is
// certified "covered" (area exactly 0) only when every clipping decision was
// certain and every clipped vertex is certainly within R of c; certified free
// when some vertex is certainly beyond R; otherwise it is "doubtful" and the
// exact classifier (cell_coverage.hpp) decides before the cell is sampled.
#ifndef PDS_FREE_AREA_HPP
#define PDS_FREE_AREA_HPP

#include <cmath>
#include <cstdint>

#include "point.hpp"
#include "rng.hpp"

namespace pds {

// What the sampler needs to know about one cell.
struct CellQuery {
    Point site;      // c
    Box domain;      // absolute coordinates
    double radius;   // R
};

struct CellMeasure {
    double area = 0.0;      // free area; exactly 0 when certified covered
    bool doubtful = false;  // rounding left the classification open
};

namespace cell_detail {

// A polygon vertex relative to the site, with a bound on its absolute error.
struct Vtx {
    double x;
    double y;
    double err;
};

// One piece of a fan triangle (paper's case 4): segment p-q seen from the site,
// with the distance to the site monotone along it and at least R (up to
// rounding) everywhere on it.
struct Piece {
    Point p;
    Point q;
};

constexpr double kUnitRoundoff = 0x1.0p-53;

// Voronoi vertex of the counterclockwise triangle (site, site+b, site+d).
Vtx voronoi_vertex(const Point& b, const Point& d);
// Splits the fan triangle (site, a, b) into at most two pieces; returns how many.
int split_fan_triangle(const Point& a, const Point& b, double r2, Piece out[2]);
// Free area of a piece: its triangle minus the circular sector it spans.
double piece_area(const Piece& piece, double r2);
// One rejection-sampling draw in the piece's quadrilateral (figure 5). Returns
// true and the point (relative to the site) when the draw is at least R out.
bool draw_in_piece(const Piece& piece, double r, double r2, Rng& rng, Point* out);

// Stage 1: consecutive neighbours -> Voronoi vertices.
template <class Next>
class VoronoiStage {
public:
    VoronoiStage(const Point& site, Next& next) : site_(site), next_(next) {}
    void push(const Point& neighbour) {
        const Point rel{neighbour.x - site_.x, neighbour.y - site_.y};
        if (count_++ == 0) first_ = rel;
        else next_.push(voronoi_vertex(prev_, rel));
        prev_ = rel;
    }
    void close() {
        if (count_ >= 2) next_.push(voronoi_vertex(prev_, first_));
        next_.close();
    }

private:
    Point site_;
    Next& next_;
    Point first_{0, 0}, prev_{0, 0};
    int count_ = 0;
};

// Stages 2-5: keep the side of an axis-parallel line where sign * (coord -
// bound) >= 0. Decisions closer to the line than the vertex error are flagged.
template <class Next>
class ClipStage {
public:
    ClipStage(int axis, double bound, double sign, bool& doubtful, Next& next)
        : axis_(axis), bound_(bound), sign_(sign), doubtful_(doubtful), next_(next) {}
    void push(const Vtx& v) {
        const bool in = inside(v);
        if (!has_first_) {
            first_ = v;
            first_in_ = in;
            has_first_ = true;
        } else {
            edge(prev_, prev_in_, v, in);
        }
        prev_ = v;
        prev_in_ = in;
    }
    void close() {
        if (has_first_) edge(prev_, prev_in_, first_, first_in_);
        next_.close();
    }

private:
    double coord(const Vtx& v) const { return axis_ == 0 ? v.x : v.y; }
    bool inside(const Vtx& v) {
        const double d = sign_ * (coord(v) - bound_);
        if (std::fabs(d) <= v.err + 4.0 * kUnitRoundoff * (std::fabs(bound_) + std::fabs(coord(v))))
            doubtful_ = true;
        return d >= 0.0;
    }
    void edge(const Vtx& a, bool a_in, const Vtx& b, bool b_in) {
        if (a_in && b_in) {
            next_.push(b);
        } else if (a_in) {
            next_.push(crossing(a, b));
        } else if (b_in) {
            next_.push(crossing(a, b));
            next_.push(b);
        }
    }
    // Where a-b crosses the line. The error grows with the slope along the
    // line: a crossing at a grazing angle is poorly determined.
    Vtx crossing(const Vtx& a, const Vtx& b) const {
        const double ac = coord(a), bc = coord(b);
        const double ao = axis_ == 0 ? a.y : a.x, bo = axis_ == 0 ? b.y : b.x;
        const double t = (bound_ - ac) / (bc - ac);
        const double other = ao + t * (bo - ao);
        const double slope = std::fabs(bo - ao) / std::fabs(bc - ac);
        const double tc = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        const double err = ((1.0 - tc) * a.err + tc * b.err + kUnitRoundoff * std::fabs(bound_)) *
                               (1.0 + slope) +
                           8.0 * kUnitRoundoff * (std::fabs(ao) + std::fabs(bo));
        return axis_ == 0 ? Vtx{bound_, other, err} : Vtx{other, bound_, err};
    }

    int axis_;
    double bound_;
    double sign_;
    bool& doubtful_;
    Next& next_;
    Vtx first_{0, 0, 0}, prev_{0, 0, 0};
    bool first_in_ = false, prev_in_ = false, has_first_ = false;
};

// Last stage: the clipped polygon's edges, as fan triangles around the site.
template <class Sink>
class FanStage {
public:
    explicit FanStage(Sink& sink) : sink_(sink) {}
    void push(const Vtx& v) {
        sink_.vertex(v);
        if (!has_first_) {
            first_ = v;
            has_first_ = true;
        } else {
            sink_.edge(prev_, v);
        }
        prev_ = v;
    }
    void close() {
        if (has_first_) sink_.edge(prev_, first_);
    }

private:
    Sink& sink_;
    Vtx first_{0, 0, 0}, prev_{0, 0, 0};
    bool has_first_ = false;
};

// Runs the whole pipeline for one cell into `sink`; returns whether any
// clipping decision was too close to call.
template <class Ring, class Sink>
bool stream_cell(const CellQuery& q, const Ring& ring, Sink& sink) {
    bool doubtful = false;
    const Box& d = q.domain;
    const Point& c = q.site;
    FanStage<Sink> fan(sink);
    ClipStage<FanStage<Sink>> top(1, d.y1 - c.y, -1.0, doubtful, fan);
    ClipStage<ClipStage<FanStage<Sink>>> bottom(1, d.y0 - c.y, 1.0, doubtful, top);
    ClipStage<ClipStage<ClipStage<FanStage<Sink>>>> right(0, d.x1 - c.x, -1.0, doubtful, bottom);
    ClipStage<ClipStage<ClipStage<ClipStage<FanStage<Sink>>>>> left(0, d.x0 - c.x, 1.0, doubtful,
                                                                     right);
    VoronoiStage<decltype(left)> voronoi(c, left);
    ring([&](const Point& n) { voronoi.push(n); });
    voronoi.close();
    return doubtful;
}

// Sums piece areas and classifies the clipped vertices.
class MeasureSink {
public:
    explicit MeasureSink(double r) : r_(r), r2_(r * r) {}
    void vertex(const Vtx& v) {
        const double d2 = v.x * v.x + v.y * v.y;
        const double margin = 2.0 * r_ * v.err + v.err * v.err + 8.0 * kUnitRoundoff * r2_;
        if (d2 > r2_ + margin) ++certainly_out_;
        else if (d2 >= r2_ - margin) ++undecided_;
    }
    void edge(const Vtx& a, const Vtx& b);
    double sum() const { return sum_; }
    int certainly_out() const { return certainly_out_; }
    int undecided() const { return undecided_; }

private:
    double r_, r2_;
    double sum_ = 0.0;
    int certainly_out_ = 0, undecided_ = 0;
};

// Walks the pieces in the same order as MeasureSink and keeps the one where
// the running sum passes `target`.
class SelectSink {
public:
    SelectSink(double r, double target) : r2_(r * r), target_(target) {}
    void vertex(const Vtx&) {}
    void edge(const Vtx& a, const Vtx& b);
    bool found() const { return found_; }
    const Piece& piece() const { return piece_; }

private:
    double r2_;
    double target_;
    double sum_ = 0.0;
    bool found_ = false;
    Piece piece_{{0, 0}, {0, 0}};
};

// The smallest weight a possibly-free cell gets, so it stays selectable.
inline double area_floor(double r) { return r * r * 0x1.0p-100; }

}  // namespace cell_detail

// Free area of the cell of q.site. `ring(visit)` must call visit(point) for
// every Delaunay neighbour of the site, counterclockwise.
template <class Ring>
CellMeasure measure_cell(const CellQuery& q, const Ring& ring) {
    cell_detail::MeasureSink sink(q.radius);
    const bool clip_doubtful = cell_detail::stream_cell(q, ring, sink);
    CellMeasure m;
    if (!clip_doubtful && sink.certainly_out() == 0 && sink.undecided() == 0) return m;  // covered
    m.doubtful = clip_doubtful || sink.certainly_out() == 0;
    const double floor = cell_detail::area_floor(q.radius);
    m.area = sink.sum() > floor ? sink.sum() : floor;
    return m;
}

enum class SampleOutcome { placed, no_piece, gave_up };

// Draws a point uniformly from the cell's free region: a piece is chosen with
// probability proportional to its area, then points are drawn in that piece
// until one lies in the free region and `accept(absolute point)` (the exact
// checks) agrees. Retrying within the chosen piece keeps the law exact.
// `total` must be the area measure_cell computed for this cell.
template <class Ring, class Accept>
SampleOutcome sample_cell(const CellQuery& q, const Ring& ring, double total, Rng& rng,
                          const Accept& accept, int max_draws, Point* out) {
    cell_detail::SelectSink sink(q.radius, rng.next_double() * total);
    cell_detail::stream_cell(q, ring, sink);
    if (!sink.found()) return SampleOutcome::no_piece;
    const double r2 = q.radius * q.radius;
    for (int i = 0; i < max_draws; ++i) {
        Point rel;
        if (!cell_detail::draw_in_piece(sink.piece(), q.radius, r2, rng, &rel)) continue;
        const Point p{q.site.x + rel.x, q.site.y + rel.y};
        if (accept(p)) {
            *out = p;
            return SampleOutcome::placed;
        }
    }
    return SampleOutcome::gave_up;
}

}  // namespace pds

#endif
