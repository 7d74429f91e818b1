// outline_clip.cpp - cutting one cell by a polygonal domain's outline (see
// outline_clip.hpp).
#include "cells/outline_clip.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"
#include "core/roundoff.hpp"
#include "core/vec.hpp"

namespace pds {

namespace {

// Vertices the cut makes are trusted to this share of R beyond their
// rounding bound: far above rounding, far below what a pattern resolves.
constexpr double kMarginShare = 0x1p-30;
// A cut at a sharper angle than this (its sine) is too close to call.
constexpr double kGrazingSine = 1e-6;

cell_stream::Vtx vertex_at(double x, double y, double err) { return cell_stream::Vtx{x, y, err, x * x + y * y}; }

double magnitude(const cell_stream::Vtx& v) { return std::fabs(v.x) + std::fabs(v.y); }

}  // namespace

bool OutlineClip::cut_cell(const Point& site, const Box& box, double r) {
    edges_.clear();
    cut_ = false;
    doubtful_ = false;
    if (cell_.empty()) return false;
    // The cell's box, widened by its vertices' errors and the margin.
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL, err = 0.0, scale = 0.0;
    for (const Vtx& v : cell_) {
        x0 = std::min(x0, v.x), x1 = std::max(x1, v.x);
        y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
        err = std::max(err, v.err);
        scale = std::max(scale, magnitude(v));
    }
    const double margin = kMarginShare * r;
    const double widen = err + margin + 4.0 * kUnitRoundoff * (std::fabs(site.x) + std::fabs(site.y) + scale);
    const Box near{site.x + x0 - widen, site.y + y0 - widen, site.x + x1 + widen, site.y + y1 + widen};
    const PolygonIndex& index = polygon_.index();
    if (index.all_cells(near, PolygonIndex::kInside)) return false;
    cut_ = true;
    segments_.clear();
    polygon_.outline_edges_near(near, edges_);
    // Only the edges whose box meets the cell's: the grid's lists are wider.
    const PolygonRings& rings = polygon_.rings();
    edges_.erase(std::remove_if(edges_.begin(), edges_.end(),
                                [&](std::uint32_t e) {
                                    const Point a = rings.edge_start(e), b = rings.edge_end(e);
                                    return std::max(a.x, b.x) < near.x0 || std::min(a.x, b.x) > near.x1 ||
                                           std::max(a.y, b.y) < near.y0 || std::min(a.y, b.y) > near.y1;
                                }),
                 edges_.end());
    if (edges_.empty()) {
        keep_whole_cell(site, margin);
        return true;
    }
    keep_cell_edges(site, box, margin);
    keep_outline_edges(site, box, margin);
    return true;
}

void OutlineClip::keep_whole_cell(const Point& site, double margin) {
    // No outline edge meets the widened box, which is convex and holds the
    // cell: the box lies on one side of the outline, and one point of it
    // settles every side. (Not the site: a power cell need not hold it.)
    // The sides as keep_cell_edges would keep them, uncut.
    const std::size_t n = cell_.size();
    const Vtx& u0 = cell_[0];
    const Vtx& v0 = cell_[1 % n];
    if (polygon_.locate(Point{site.x + 0.5 * (u0.x + v0.x), site.y + 0.5 * (u0.y + v0.y)}) == PolygonIndex::kOutside)
        return;
    for (std::size_t i = 0; i < n; ++i) {
        const Vtx& u = cell_[i];
        const Vtx& v = cell_[(i + 1) % n];
        if (v.x - u.x == 0.0 && v.y - u.y == 0.0) continue;
        segments_.push_back(Segment{Vtx{u.x, u.y, u.err + margin, u.d2}, Vtx{v.x, v.y, v.err + margin, v.d2}});
    }
}

void OutlineClip::keep_cell_edges(const Point& site, const Box& box, double margin) {
    const PolygonRings& rings = polygon_.rings();
    const double lx = box.x0 - site.x, hx = box.x1 - site.x, ly = box.y0 - site.y, hy = box.y1 - site.y;
    const std::size_t n = cell_.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vtx& u = cell_[i];
        const Vtx& v = cell_[(i + 1) % n];
        const Point d{v.x - u.x, v.y - u.y};
        if (d.x == 0.0 && d.y == 0.0) continue;
        const double dlen = std::sqrt(d.x * d.x + d.y * d.y);
        // Where the outline crosses this edge, and the sharpest crossing.
        cuts_.clear();
        double sine = 1.0, scale = magnitude(u) + magnitude(v);
        for (std::uint32_t e : edges_) {
            const Point a0 = rings.edge_start(e), b0 = rings.edge_end(e);
            const Point a{a0.x - site.x, a0.y - site.y}, b{b0.x - site.x, b0.y - site.y};
            const Point ev{b.x - a.x, b.y - a.y};
            const double den = cross(d, ev);
            if (den == 0.0) continue;
            const Point w{a.x - u.x, a.y - u.y};
            const double s = cross(w, ev) / den, t = cross(w, d) / den;
            if (!(s > 0.0 && s < 1.0 && t >= 0.0 && t <= 1.0)) continue;
            cuts_.push_back(s);
            sine = std::min(sine, std::fabs(den) / (dlen * std::sqrt(ev.x * ev.x + ev.y * ev.y)));
            scale = std::max(scale, std::fabs(a.x) + std::fabs(a.y) + std::fabs(b.x) + std::fabs(b.y));
        }
        if (sine < kGrazingSine) doubtful_ = true;
        std::sort(cuts_.begin(), cuts_.end());
        cuts_.push_back(1.0);
        const double cut_err = (std::max(u.err, v.err) + 16.0 * kUnitRoundoff * scale) * (1.0 + 1.0 / sine) + margin;
        // A side of the box: its points snap onto it exactly before they are located.
        const bool left = u.x == lx && v.x == lx, right = u.x == hx && v.x == hx;
        const bool bottom = u.y == ly && v.y == ly, top = u.y == hy && v.y == hy;
        double prev = 0.0;
        Vtx from{u.x, u.y, u.err + margin, u.d2};
        for (double s : cuts_) {
            if (!(s > prev)) continue;
            const Vtx to = s == 1.0 ? Vtx{v.x, v.y, v.err + margin, v.d2}
                                    : vertex_at(u.x + s * d.x, u.y + s * d.y, cut_err);
            const double m = 0.5 * (prev + s);
            Point mid{site.x + (u.x + m * d.x), site.y + (u.y + m * d.y)};
            if (left) mid.x = box.x0;
            if (right) mid.x = box.x1;
            if (bottom) mid.y = box.y0;
            if (top) mid.y = box.y1;
            // Inside or on the outline: a side of the box the outline runs
            // along bounds the region there (the outline's own edge is skipped).
            if (polygon_.locate(mid) != PolygonIndex::kOutside) segments_.push_back(Segment{from, to});
            prev = s;
            from = to;
        }
    }
}

void OutlineClip::keep_outline_edges(const Point& site, const Box& box, double margin) {
    const PolygonRings& rings = polygon_.rings();
    const std::size_t n = cell_.size();
    double cell_err = 0.0, cell_scale = 0.0;
    for (const Vtx& v : cell_) cell_err = std::max(cell_err, v.err), cell_scale = std::max(cell_scale, magnitude(v));
    for (std::uint32_t e : edges_) {
        const Point a0 = rings.edge_start(e), b0 = rings.edge_end(e);
        // An edge along a side of the box: the cell's own side stands for it.
        if ((a0.x == b0.x && (a0.x == box.x0 || a0.x == box.x1)) || (a0.y == b0.y && (a0.y == box.y0 || a0.y == box.y1)))
            continue;
        const Point a{a0.x - site.x, a0.y - site.y}, b{b0.x - site.x, b0.y - site.y};
        const Point ev{b.x - a.x, b.y - a.y};
        const double elen = std::sqrt(ev.x * ev.x + ev.y * ev.y);
        double t0 = 0.0, t1 = 1.0, sine0 = 1.0, sine1 = 1.0;
        for (std::size_t i = 0; i < n && t0 < t1; ++i) {
            const Vtx& u = cell_[i];
            const Vtx& v = cell_[(i + 1) % n];
            const Point d{v.x - u.x, v.y - u.y};
            // cross(d, a + t ev - u) >= 0: on the cell's side of this edge.
            const double g0 = cross(d, Point{a.x - u.x, a.y - u.y}), g1 = cross(d, ev);
            if (g1 == 0.0) {
                if (g0 < 0.0) t1 = -1.0;
                continue;
            }
            const double t = -g0 / g1;
            const auto sine = [&] { return std::fabs(g1) / (std::sqrt(d.x * d.x + d.y * d.y) * elen); };
            if (g1 > 0.0 && t > t0) t0 = t, sine0 = sine();
            if (g1 < 0.0 && t < t1) t1 = t, sine1 = sine();
        }
        if (!(t0 < t1)) continue;
        if (std::min(sine0, sine1) < kGrazingSine) doubtful_ = true;
        const double scale = cell_scale + std::fabs(a.x) + std::fabs(a.y) + std::fabs(b.x) + std::fabs(b.y);
        const double base = cell_err + 16.0 * kUnitRoundoff * scale;
        const Vtx p = t0 == 0.0 ? vertex_at(a.x, a.y, kUnitRoundoff * (std::fabs(a.x) + std::fabs(a.y)) + margin)
                                : vertex_at(a.x + t0 * ev.x, a.y + t0 * ev.y, base * (1.0 + 1.0 / sine0) + margin);
        const Vtx q = t1 == 1.0 ? vertex_at(b.x, b.y, kUnitRoundoff * (std::fabs(b.x) + std::fabs(b.y)) + margin)
                                : vertex_at(a.x + t1 * ev.x, a.y + t1 * ev.y, base * (1.0 + 1.0 / sine1) + margin);
        if (polygon_.inside_left(e)) segments_.push_back(Segment{p, q});
        else segments_.push_back(Segment{q, p});
    }
}

bool OutlineClip::counts(const Point& site, const Point& p, const Piece& piece, double r) const {
    if (!cut_) return true;
    const Point x{p.x - site.x, p.y - site.y};
    const Point e{piece.q.x - piece.p.x, piece.q.y - piece.p.y};
    const double den = cross(x, e);
    if (den == 0.0) return false;
    const double t = cross(piece.p, e) / den;  // the ray meets the piece's edge at t x
    const Point y{site.x + t * x.x, site.y + t * x.y};
    const Point pa{site.x + piece.p.x, site.y + piece.p.y}, qa{site.x + piece.q.x, site.y + piece.q.y};
    const double tol = kMarginShare * r;
    const PolygonRings& rings = polygon_.rings();
    for (std::uint32_t id : edges_) {
        const Point a = rings.edge_start(id), b = rings.edge_end(id);
        const Point ab{b.x - a.x, b.y - a.y};
        const double len = std::sqrt(ab.x * ab.x + ab.y * ab.y);
        // The edge the piece lies along ends the ray there: it does not separate.
        if (std::fabs(cross(ab, Point{pa.x - a.x, pa.y - a.y})) <= tol * len &&
            std::fabs(cross(ab, Point{qa.x - a.x, qa.y - a.y})) <= tol * len)
            continue;
        const int o1 = orient2d(p, y, a), o2 = orient2d(p, y, b);
        if (o1 * o2 > 0 || (o1 == 0 && o2 == 0)) continue;
        if (orient2d(a, b, p) * orient2d(a, b, y) > 0) continue;
        return false;
    }
    return true;
}

}  // namespace pds
