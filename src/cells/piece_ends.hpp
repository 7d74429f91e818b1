// piece_ends.hpp - where to look for a point in a free region too thin for
// the draws: the clipped cell's vertices and the ends of its pieces
// (cell_pieces.hpp), relative to the site. Such a region lies along the
// cell's boundary between them (a clearance that falls short of a corner,
// two disks that leave an ulp of a side open), so its representable points
// lie within a few rounding steps of one, where the exact test can find one.
// A sink of the cell pipeline (cell_stream.hpp, outline_clip.hpp's Stage).
#ifndef PDS_PIECE_ENDS_HPP
#define PDS_PIECE_ENDS_HPP

#include "cells/cell_pieces.hpp"
#include "core/circumcentre.hpp"
#include "core/point.hpp"
#include "core/vec.hpp"

namespace pds {

class PieceEnds {
public:
    static constexpr int kMax = 64;  // a cell has a few dozen at most; the rest are dropped

    explicit PieceEnds(double r) : r2_(r * r) {}
    void vertex(const RelativeCentre& v) { add(Point{v.x, v.y}, v.err); }
    void edge(const RelativeCentre& a, const RelativeCentre& b) {
        // Counterclockwise, as the fan's pieces are cut (a clockwise fan
        // triangle is a power cell's shadow: its ends count all the same).
        const Point pa{a.x, a.y}, pb{b.x, b.y};
        const double err = a.err > b.err ? a.err : b.err;
        Piece pieces[2];
        const int n = cross(pa, pb) >= 0.0 ? split_fan_triangle(pa, pb, r2_, pieces)
                                           : split_fan_triangle(pb, pa, r2_, pieces);
        for (int i = 0; i < n; ++i) {
            add(pieces[i].p, err);
            add(pieces[i].q, err);
        }
    }
    void finish() {}
    bool done() const { return count_ == kMax; }

    int count() const { return count_; }
    const Point& operator[](int i) const { return points_[i]; }
    // A bound on the error of end i's cell vertices (their centres').
    double error(int i) const { return errors_[i]; }

private:
    void add(const Point& p, double err) {
        if (count_ == kMax) return;
        errors_[count_] = err;
        points_[count_++] = p;
    }

    double r2_;
    Point points_[kMax];
    double errors_[kMax];
    int count_ = 0;
};

}  // namespace pds

#endif
