// free_area.hpp - the free region of one Voronoi cell: its area, and uniform
// points in it (Jones 2006, section 3.1 and figures 3-5).
//
// The free region of site c is its Voronoi cell, clipped to the domain, minus
// the disk of radius R around c. Inside the cell c is the nearest site, so a
// point there is free exactly when it is at least R from c, and the free
// regions of all cells tile the free area of the whole domain.
//
// The cell is streamed, never stored: the Delaunay neighbours of c arrive
// counterclockwise, consecutive pairs give the Voronoi vertices, and the
// clipped polygon's edges form the triangle fan around c. Most cells lie well
// inside the domain: their vertices are buffered and, when all are certainly
// inside, go straight to the fan; otherwise four Sutherland-Hodgman stages
// clip them. No allocation happens, whatever the vertex degree, so the sampler
// can measure a cell right after an insertion.
//
// The fan is cut into the paper's pieces (cases 1-4); a piece's free area is
// its triangle minus a circular sector. Consecutive pieces form chunks whose
// sector angles add up, so one arctangent serves a chunk. Measuring and
// selecting (the chunk holding a target, then a piece in it) share one pass.
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
    double d2;  // x^2 + y^2, computed once: the classification and the fan both need it
};

// One piece of a fan triangle (paper's case 4): segment p-q seen from the site,
// with the distance to the site monotone along it and at least R (up to
// rounding) everywhere on it.
struct Piece {
    Point p;
    Point q;
};

// Consecutive pieces that share endpoints span one contiguous angle, and the
// sector angles of a piece's free area add up over them: such a chunk's free
// area is (sum of cross products - R^2 * its angle) / 2, one arctangent for the
// whole chunk. A chunk ends where the boundary dips inside the disk, before it
// would reach a half turn, or at kMaxChunkPieces pieces (which the sampler
// stores).
constexpr int kMaxChunkPieces = 16;

struct Chunk {
    Point start{0, 0};
    Point end{0, 0};
    double cross_sum = 0.0;
    int count = 0;
    Piece pieces[kMaxChunkPieces];

    // Extends while the chunk stays below a half turn: its angle is then the
    // argument of (start . end, start x end), unambiguous.
    bool extends_with(const Piece& pc) const {
        return count > 0 && count < kMaxChunkPieces && pc.p.x == end.x && pc.p.y == end.y &&
               start.x * pc.q.y - start.y * pc.q.x > 0.0;
    }
    void begin(const Piece& pc, bool keep_pieces);
    void extend(const Piece& pc, bool keep_pieces);
    double area(double r2) const;
};

constexpr double kUnitRoundoff = 0x1.0p-53;

// Throws std::logic_error: a broken mesh invariant.
[[noreturn]] void degenerate_triangle();

// Voronoi vertex of the counterclockwise triangle (site, site+b, site+d).
// Inline: it runs for every neighbour of every cell the sampler looks at.
inline Vtx voronoi_vertex(const Point& b, const Point& d) {
    const double bb = b.x * b.x + b.y * b.y, dd = d.x * d.x + d.y * d.y;
    const double cr = b.x * d.y - b.y * d.x;
    // Delaunay triangles around a site are counterclockwise, and with points
    // at least R apart inside the ghost square their angles stay far from 0.
    if (!(cr > 0.0) || !(cr < 1e300)) degenerate_triangle();
    const double inv = 0.5 / cr;
    const double vx = (d.y * bb - b.y * dd) * inv;
    const double vy = (b.x * dd - d.x * bb) * inv;
    // Forward error: the circumcentre's sensitivity to rounding of b and d and
    // of the arithmetic is below ~(|b|+|d|)^2 / |b x d| ulps of its distance;
    // 256 is a generous constant.
    const double err = 256.0 * kUnitRoundoff * (bb + dd) * inv * (std::fabs(vx) + std::fabs(vy));
    return Vtx{vx, vy, err, vx * vx + vy * vy};
}
// Splits the fan triangle (site, a, b) into at most two pieces; returns how many.
int split_fan_triangle(const Point& a, const Point& b, double r2, Piece out[2]);
// Free area of a piece: its triangle minus the circular sector it spans.
double piece_area(const Piece& piece, double r2);
// Index of the piece of `chunk` where the running sum of piece areas passes
// u times their total (u in [0, 1)); -1 when every piece has zero area.
int select_piece(const Chunk& chunk, double r2, double u);
// One rejection-sampling draw in the piece's quadrilateral (figure 5). Returns
// true and the point (relative to the site) when the draw is at least R out.
bool draw_in_piece(const Piece& piece, double r, double r2, Rng& rng, Point* out);

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
    void push(const Point& neighbour) {
        const Point rel{neighbour.x - site_.x, neighbour.y - site_.y};
        if (count_++ == 0) first_ = rel;
        else emit(voronoi_vertex(prev_, rel));
        prev_ = rel;
    }
    void close() {
        if (count_ >= 2) emit(voronoi_vertex(prev_, first_));
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
    FanStage<Sink> fan(sink);
    ClipStage<FanStage<Sink>> top(1, rel.hy, -1.0, doubtful, fan);
    ClipStage<ClipStage<FanStage<Sink>>> bottom(1, rel.ly, 1.0, doubtful, top);
    ClipStage<ClipStage<ClipStage<FanStage<Sink>>>> right(0, rel.hx, -1.0, doubtful, bottom);
    ClipStage<ClipStage<ClipStage<ClipStage<FanStage<Sink>>>>> left(0, rel.lx, 1.0, doubtful, right);
    VoronoiStage<FanStage<Sink>, decltype(left)> voronoi(c, rel, fan, left);
    // A sink that has what it needs (a selection found its chunk) stops the
    // geometry; the rest of the ring is still walked, but not computed.
    ring([&](const Point& n) {
        if (!sink.done()) voronoi.push(n);
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
    int certainly_out_ = 0, undecided_ = 0;
    bool found_ = false, fallback_ = false, stop_at_target_ = false;
    // The chunk being built and the one last chosen; choosing swaps them, so
    // no chunk is ever copied.
    Chunk chunks_[2];
    int building_ = 0;
};

// The smallest weight a possibly-free cell gets, so it stays selectable.
inline double area_floor(double r) { return r * r * 0x1.0p-100; }

// The sink's verdict on the cell as a whole.
inline CellMeasure verdict(const CellSink& sink, bool clip_doubtful, double r) {
    CellMeasure m;
    if (!clip_doubtful && sink.certainly_out() == 0 && sink.undecided() == 0) return m;  // covered
    m.doubtful = clip_doubtful || sink.certainly_out() == 0;
    const double floor = area_floor(r);
    m.area = sink.sum() > floor ? sink.sum() : floor;
    return m;
}

}  // namespace cell_detail

// Free area of the cell of q.site. `ring(visit)` must call visit(point) for
// every Delaunay neighbour of the site, counterclockwise.
template <class Ring>
CellMeasure measure_cell(const CellQuery& q, const Ring& ring) {
    cell_detail::CellSink sink(q.radius, -1.0);
    const bool clip_doubtful = cell_detail::stream_cell(q, ring, sink);
    return cell_detail::verdict(sink, clip_doubtful, q.radius);
}

// One pass over a cell that measures it and, for a target in [0, area), picks
// the chunk whose share of the area holds the target. When the target is
// reached the pass stops: `measure` then covers only the part walked, and is
// meaningful only when nothing was found.
struct CellSelection {
    explicit CellSelection(double r, double target) : sink(r, target) {}
    cell_detail::CellSink sink;
    CellMeasure measure;
    bool found() const { return sink.found(); }            // the running sum passed the target
    bool fallback() const { return sink.has_fallback(); }  // it did not, but a chunk has area
    const cell_detail::Chunk& chunk() const { return sink.chunk(); }
};

template <class Ring>
CellSelection select_in_cell(const CellQuery& q, const Ring& ring, double target) {
    CellSelection s(q.radius, target);
    s.sink.stop_at_target();
    const bool clip_doubtful = cell_detail::stream_cell(q, ring, s.sink);
    s.measure = cell_detail::verdict(s.sink, clip_doubtful, q.radius);
    return s;
}

enum class SampleOutcome { placed, gave_up };

// Draws a point uniformly from one chunk of a cell's free region: a piece is
// chosen with probability proportional to its area (u in [0, 1)), then points
// are drawn in that piece until one lies in the free region and
// `accept(absolute point)` (the exact checks) agrees. Retrying within the
// chosen piece keeps the law exact.
template <class Accept>
SampleOutcome sample_chunk(const CellQuery& q, const cell_detail::Chunk& chunk, double u, Rng& rng,
                           const Accept& accept, int max_draws, Point* out) {
    const double r2 = q.radius * q.radius;
    const int k = cell_detail::select_piece(chunk, r2, u);
    if (k < 0) return SampleOutcome::gave_up;
    const cell_detail::Piece& piece = chunk.pieces[k];
    for (int i = 0; i < max_draws; ++i) {
        Point rel;
        if (!cell_detail::draw_in_piece(piece, q.radius, r2, rng, &rel)) continue;
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
