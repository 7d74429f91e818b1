// cell_stream.hpp - the pipeline that streams one Voronoi cell, clipped to
// the domain, as the fan of triangles around its site (Jones 2006, figure 3).
// Private to free_area.hpp, its only user.
//
// Power cells (a variable radius) stream the same way, with power centres in
// place of circumcentres; the site may then lie outside its cell (see
// CellSink::shadow).
//
// The cell is streamed, never stored: the Delaunay neighbours of the site
// arrive counterclockwise, consecutive pairs give the Voronoi vertices
// (circumcentre.hpp), and the clipped polygon's edges form the fan. Most
// cells lie well inside the domain: their vertices are buffered and, when all
// are certainly inside, go straight to the fan; otherwise four
// Sutherland-Hodgman stages clip them. No allocation happens, whatever the
// vertex degree, so the sampler can measure a cell right after an insertion.
//
// The sink cuts the fan into the paper's pieces (cell_pieces.hpp), groups
// consecutive pieces into chunks (one arctangent per chunk), sums their free
// areas, and for a selection keeps the chunk where the running sum passes a
// target. It also classifies every clipped vertex against R with its error
// bound, for the cell's verdict (free_area.hpp).
#ifndef PDS_CELL_STREAM_HPP
#define PDS_CELL_STREAM_HPP

#include <cmath>

#include "cells/cell_pieces.hpp"
#include "core/circumcentre.hpp"
#include "core/point.hpp"
#include "core/roundoff.hpp"

namespace pds {

// What the sampler needs to know about one cell.
struct CellQuery {
    Point site;      // c
    Box domain;      // absolute coordinates
    double radius;   // R, the site's radius
};

namespace cell_stream {

// A polygon vertex relative to the site, with a bound on its absolute error
// and its squared distance (the classification and the fan both need it).
using Vtx = RelativeCentre;

// The domain relative to the site, and a test for "certainly inside it".
struct RelativeBox {
    RelativeBox(double lx_, double hx_, double ly_, double hy_)
        : lx(lx_), hx(hx_), ly(ly_), hy(hy_),
          rounding(4.0 * kUnitRoundoff *
                   (std::fabs(lx_) + std::fabs(hx_) + std::fabs(ly_) + std::fabs(hy_))) {}
    bool certainly_contains(const Vtx& v) const {
        const double slack = v.err + rounding + 4.0 * kUnitRoundoff * (std::fabs(v.x) + std::fabs(v.y));
        return v.x - lx > slack && hx - v.x > slack && v.y - ly > slack && hy - v.y > slack;
    }
    double lx, hx, ly, hy;
    double rounding;  // bound on the rounding of the four sides
};

// Stage 1: consecutive neighbours -> Voronoi vertices. Most cells lie well
// inside the domain, so the vertices are buffered: if every one is certainly
// inside, they go straight to the fan and clipping is skipped; otherwise, or
// when the buffer fills (a vertex of very high degree), they go through the
// clipping stages, streamed from then on.
template <class Fan, class Clip>
class VoronoiStage {
public:
    VoronoiStage(const Point& site, const RelativeBox& box, Fan& fan, Clip& clip)
        : site_(site), box_(box), fan_(fan), clip_(clip) {}
    // w: the site's squared radius minus the neighbour's (0 for equal radii).
    void push(const Point& neighbour, double w) {
        const Point rel{neighbour.x - site_.x, neighbour.y - site_.y};
        if (count_++ == 0) {
            first_ = rel;
            first_w_ = w;
        } else {
            emit(relative_power_centre(prev_, rel, prev_w_, w));
        }
        prev_ = rel;
        prev_w_ = w;
    }
    void close() {
        if (count_ >= 2) emit(relative_power_centre(prev_, first_, prev_w_, first_w_));
        if (streaming_) {
            clip_.close();
            return;
        }
        bool inside = true;
        for (int i = 0; i < buffered_ && inside; ++i) inside = box_.certainly_contains(buffer_[i]);
        if (inside) {
            for (int i = 0; i < buffered_; ++i) fan_.push(buffer_[i]);
            fan_.close();
        } else {
            for (int i = 0; i < buffered_; ++i) clip_.push(buffer_[i]);
            clip_.close();
        }
    }

private:
    static constexpr int kBuffer = 24;
    void emit(const Vtx& v) {
        if (streaming_) {
            clip_.push(v);
        } else if (buffered_ < kBuffer) {
            buffer_[buffered_++] = v;
        } else {
            streaming_ = true;
            for (int i = 0; i < buffered_; ++i) clip_.push(buffer_[i]);
            clip_.push(v);
        }
    }

    Point site_;
    const RelativeBox& box_;
    Fan& fan_;
    Clip& clip_;
    Point first_{0, 0}, prev_{0, 0};
    double first_w_ = 0.0, prev_w_ = 0.0;
    int count_ = 0;
    int buffered_ = 0;
    bool streaming_ = false;
    Vtx buffer_[kBuffer];
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
        return axis_ == 0 ? Vtx{bound_, other, err, bound_ * bound_ + other * other}
                          : Vtx{other, bound_, err, other * other + bound_ * bound_};
    }

    int axis_;
    double bound_;
    double sign_;
    bool& doubtful_;
    Next& next_;
    Vtx first_, prev_;  // set by the first push
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
        sink_.finish();
    }

private:
    Sink& sink_;
    Vtx first_{}, prev_{};
    bool has_first_ = false;
};

// Runs the whole pipeline for one cell into `sink`; returns whether any
// clipping decision was too close to call.
template <class Ring, class Sink>
bool stream_cell(const CellQuery& q, const Ring& ring, Sink& sink) {
    bool doubtful = false;
    const Box& d = q.domain;
    const Point& c = q.site;
    const RelativeBox rel(d.x0 - c.x, d.x1 - c.x, d.y0 - c.y, d.y1 - c.y);
    // Voronoi vertices -> left -> right -> bottom -> top -> fan -> sink.
    using Fan = FanStage<Sink>;
    using Top = ClipStage<Fan>;
    using Bottom = ClipStage<Top>;
    using Right = ClipStage<Bottom>;
    using Left = ClipStage<Right>;
    Fan fan(sink);
    Top top(1, rel.hy, -1.0, doubtful, fan);
    Bottom bottom(1, rel.ly, 1.0, doubtful, top);
    Right right(0, rel.hx, -1.0, doubtful, bottom);
    Left left(0, rel.lx, 1.0, doubtful, right);
    VoronoiStage<Fan, Left> voronoi(c, rel, fan, left);
    // A sink that has what it needs (a selection found its chunk) stops the
    // geometry; the rest of the ring is still walked, but not computed.
    ring([&](const Point& n, double w) {
        if (!sink.done()) voronoi.push(n, w);
    });
    if (!sink.done()) voronoi.close();
    return doubtful;
}

// Sums chunk areas, classifies the clipped vertices, and (given a target) keeps
// the chunk where the running sum passes the target. Measuring and selecting
// share this one code path, so the sums agree to the last bit.
class CellSink {
public:
    CellSink(double r, double target)
        : r_(r), r2_(r * r), target_(target), rounding_(8.0 * kUnitRoundoff * r * r) {}
    void vertex(const Vtx& v) {
        if (v.d2 > max_d2_) max_d2_ = v.d2;
        if (v.err > max_err_) max_err_ = v.err;
        const double margin = v.err * (2.0 * r_ + v.err) + rounding_;
        if (v.d2 > r2_ + margin) ++certainly_out_;
        else if (v.d2 >= r2_ - margin) ++undecided_;
    }
    void edge(const Vtx& a, const Vtx& b);
    void finish() { flush(); }
    // A selection stops at its chunk: the cell is re-measured after the
    // insertion anyway, and its draws are checked exactly.
    bool done() const { return found_ && stop_at_target_; }
    void stop_at_target() { stop_at_target_ = true; }

    double sum() const { return sum_; }
    // The free area of the fan triangles that turn clockwise: a site outside
    // its power cell sees the cell's near side that way, and those triangles
    // cover the part of the fan outside the cell (the shadow). The cell's
    // free area is sum() - shadow(); chunks hold only the counterclockwise
    // pieces, which cover the cell once, and the shadow too.
    double shadow() const { return shadow_; }
    // The area of the fan, free or not: the cell's area, with the shadow.
    double fan_area() const { return 0.5 * fan_; }
    // A bound on the distance from the site to every polygon vertex.
    double reach() const { return std::sqrt(max_d2_) * (1.0 + 4.0 * kUnitRoundoff) + max_err_; }
    int certainly_out() const { return certainly_out_; }
    int undecided() const { return undecided_; }
    // The chunk where the running sum passed the target, if it did.
    bool found() const { return found_; }
    // Otherwise the last chunk with positive area, if any.
    bool has_fallback() const { return fallback_; }
    const Chunk& chunk() const { return chunks_[1 - building_]; }

private:
    // Measuring only (negative target), or still looking for the target chunk.
    bool selecting() const { return target_ >= 0.0 && !found_; }
    void flush();
    Chunk& chunk_() { return chunks_[building_]; }
    double r_, r2_;
    double target_;
    double rounding_;  // bound on the rounding of |v|^2 and R^2
    double sum_ = 0.0;
    double shadow_ = 0.0;
    double fan_ = 0.0;  // twice the fan's area
    double max_d2_ = 0.0, max_err_ = 0.0;
    int certainly_out_ = 0, undecided_ = 0;
    bool found_ = false, fallback_ = false, stop_at_target_ = false;
    // The chunk being built and the one last chosen; choosing swaps them, so
    // no chunk is ever copied.
    Chunk chunks_[2];
    int building_ = 0;
};

}  // namespace cell_stream
}  // namespace pds

#endif
