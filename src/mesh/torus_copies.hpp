// torus_copies.hpp - the torus as a plane triangulation with copies.
//
// On the torus a site's Voronoi cell is its cell among all the copies of
// the pattern shifted by whole periods (torus.hpp). The sampler keeps the
// real points and those copies that lie within a margin M of the
// fundamental domain (the region E) in one plane Delaunay triangulation.
// A real site's cell there is its true torus cell as soon as every triangle
// around it has its circumdisk inside E: a copy missing from the mesh lies
// outside E, hence outside every such disk, so the triangle is Delaunay
// among all copies too. That invariant is checked (in floating point with
// error bounds, conservatively) for every triangle an insertion creates
// around a real vertex; when it fails, M doubles and the missing copies are
// inserted. M never needs to exceed the domain's diagonal D: a Voronoi
// vertex of a real site lies within D/2 of it (its cell lies in the
// rectangle of half-periods around it), so its disk stays within D of the
// fundamental domain. Early, sparse patterns get a wide margin; a dense one
// (after the dart stage) keeps M near a few R, so copies cost a few percent.
// Real cells are never clipped: on the torus the cells tile it exactly.
//
// A variable radius (a weighted mesh): the cells are power cells and a
// triangle's disk is its conflict disk: centred at its power centre w, of
// radius sqrt(pi + rmax^2) with pi the power of w (the same to its three
// disks). A missing disk (q, r_q) with q outside that disk has power at w
// above pi + rmax^2 - r_q^2 >= pi: it does not conflict. A real site's power
// cell also lies in the rectangle of half-periods around it (its own copies
// bound it, at equal weight), so pi <= D^2/4 and, with rmax <= D/2, the
// disk stays within 1.21 D of the fundamental domain: the largest margin
// is 1.25 D.
#ifndef PDS_TORUS_COPIES_HPP
#define PDS_TORUS_COPIES_HPP

#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/delaunay.hpp"
#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/torus.hpp"

namespace pds {

class TorusCopies {
public:
    TorusCopies() = default;
    // t must be on; r is the radius (the first margin is a few R); weighted:
    // a variable radius, r the largest.
    TorusCopies(const Torus& t, double r, bool weighted = false);

    bool on() const { return torus_.on(); }
    const Torus& torus() const { return torus_; }
    double margin() const { return margin_; }
    bool weighted() const { return weighted_; }
    double rmax() const { return rmax_; }
    // E: the fundamental domain widened by the margin m.
    Box region(double m) const {
        return Box{torus_.x0 - m, torus_.y0 - m, torus_.x0 + torus_.px + m, torus_.y0 + torus_.py + m};
    }
    Box region() const { return region(margin_); }
    // E at the largest margin: the triangulation's ghosts go around it.
    Box largest_region() const { return region(max_margin_); }
    // A box every valid cell lies well inside: cells are never clipped.
    Box clip_box() const { return region(2.0 * max_margin_); }
    // The margin after the current one (the current one when it is the largest).
    double next_margin() const;
    // The first margin (a few R): no margin is ever set below it.
    double first_margin() const { return first_margin_; }
    // How far beyond the fundamental domain the (conflict) disks of v's
    // triangles reach, at most, rounding included; infinite with a ghost
    // corner. A margin above it keeps v's cell a torus cell.
    double ring_overshoot(const Delaunay& dt, VertexIndex v) const;
    void set_margin(double m) { margin_ = m; }

    // Calls f(copy) for every copy of the real point p inside region(m) but
    // not inside region(old) (old < 0: none excluded). Copies are exact.
    template <class F>
    void for_each_copy(const Point& p, double m, double old, const F& f) const {
        // Farther than m from every side: every copy is beyond E (most points).
        const double right = torus_.x0 + torus_.px, top = torus_.y0 + torus_.py;
        if (p.x - torus_.x0 > m && right - p.x > m && p.y - torus_.y0 > m && top - p.y > m) return;
        const Box e = region(m);
        const Box before = region(old);
        // Copies shifted by more than ceil(m / period) periods are beyond E.
        constexpr double kUp = 1.0 + 0x1.0p-40;  // absorbs the rounding of the quotient
        const int ni = static_cast<int>(std::ceil(m / torus_.px * kUp));
        const int nj = static_cast<int>(std::ceil(m / torus_.py * kUp));
        for (int i = -ni; i <= ni; ++i) {
            for (int j = -nj; j <= nj; ++j) {
                if (i == 0 && j == 0) continue;
                const Point c = torus_.shifted(p, i, j);
                if (!inside(c, e)) continue;
                if (old >= 0.0 && inside(c, before)) continue;
                f(c, i, j);
            }
        }
    }
    // Offsets (i, j) of copies at any margin map to slots [0, max_offsets()).
    std::size_t max_offsets() const { return (2 * max_i_ + 1) * (2 * max_j_ + 1); }
    std::size_t offset_slot(int i, int j) const {
        return static_cast<std::size_t>(i + max_i_) * (2 * max_j_ + 1) + static_cast<std::size_t>(j + max_j_);
    }
    // The most copies one point can have at the current margin.
    std::size_t max_copies() const;
    // Copies per real point to expect at the current margin, on average.
    double copies_per_point() const;

    // The invariant around vertex v: every triangle (v, a, b) of its ring
    // with a real corner (is_real(vertex)) has its circumdisk inside E.
    // (A hidden disk has no triangles: nothing to check.)
    template <class IsReal>
    bool ring_valid(const Delaunay& dt, VertexIndex v, const IsReal& is_real) const {
        if (dt.weighted() && dt.is_hidden(v)) return true;
        const Box e = region();
        const bool v_real = is_real(v);
        const Point& c = dt.point(v);
        VertexIndex first = 0, prev = 0;
        int n = 0;
        bool ok = true;
        const auto triangle = [&](VertexIndex a, VertexIndex b) {
            if (!ok || (!v_real && !is_real(a) && !is_real(b))) return;
            ok = dt.weighted() ? conflict_disk_inside(c, dt.radius(v), dt.point(a), dt.radius(a), dt.point(b),
                                                      dt.radius(b), e)
                               : disk_inside(c, dt.point(a), dt.point(b), e);
        };
        dt.for_each_neighbour(v, [&](VertexIndex nb) {
            if (n++ == 0) first = nb;
            else triangle(prev, nb);
            prev = nb;
        });
        if (n >= 2) triangle(prev, first);
        return ok;
    }

private:
    // Half-open in nothing: a copy on E's border counts as inside.
    static bool inside(const Point& p, const Box& b) {
        return p.x >= b.x0 && p.x <= b.x1 && p.y >= b.y0 && p.y <= b.y1;
    }
    // The circumdisk of the counterclockwise triangle (c, a, b) lies inside
    // e, certainly (false when unsure or when a corner is a ghost).
    static bool disk_inside(const Point& c, const Point& a, const Point& b, const Box& e);
    // The same for the conflict disk of the disks (c, a, b) (weighted).
    bool conflict_disk_inside(const Point& c, double rc, const Point& a, double ra, const Point& b, double rb,
                              const Box& e) const;

    Torus torus_;
    bool weighted_ = false;
    double margin_ = 0.0;
    double first_margin_ = 0.0;
    double max_margin_ = 0.0;
    double rmax_ = 0.0;          // weighted: the largest radius
    int max_i_ = 0, max_j_ = 0;  // the largest offsets for_each_copy can give
};

}  // namespace pds

#endif
