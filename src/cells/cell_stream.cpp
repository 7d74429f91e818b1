// cell_stream.cpp - the chunk sums of the cell pipeline (see cell_stream.hpp).
#include "cells/cell_stream.hpp"

#include <cmath>

namespace pds {
namespace cell_stream {

namespace {

// The fan triangle's pieces, skipping triangles inside the disk: when both ends
// of the far side are within R, so is the whole triangle (it is convex).
int fan_pieces(const Vtx& va, const Vtx& vb, double r2, Piece out[2]) {
    if (va.d2 <= r2 && vb.d2 <= r2) return 0;
    return split_fan_triangle(Point{va.x, va.y}, Point{vb.x, vb.y}, r2, out);
}

}  // namespace

void CellSink::edge(const Vtx& a, const Vtx& b) {
    if (done()) return;
    Piece pieces[2];
    const double turn = cross(Point{a.x, a.y}, Point{b.x, b.y});
    fan_ += std::fabs(turn);
    if (turn < 0.0) {
        // A clockwise fan triangle: the site is outside its power cell. Its
        // free area, measured turned counterclockwise, is the shadow's.
        flush();
        const int n = fan_pieces(b, a, r2_, pieces);
        for (int i = 0; i < n; ++i) shadow_ += piece_area(pieces[i], r2_);
        return;
    }
    const int n = fan_pieces(a, b, r2_, pieces);
    if (n == 0) flush();  // the boundary runs inside the disk here
    for (int i = 0; i < n; ++i) {
        if (chunk_().extends_with(pieces[i])) {
            chunk_().extend(pieces[i], selecting());
        } else {
            flush();
            chunk_().begin(pieces[i], selecting());
        }
    }
}

void CellSink::flush() {
    Chunk& c = chunk_();
    if (c.count == 0) return;
    const double a = c.area(r2_);
    sum_ += a;
    // Keep the chunk where the sum first passes the target, or else the last
    // one with positive area; once found, later chunks only add to the sum.
    if (selecting() && a > 0.0) {
        building_ = 1 - building_;  // the chunk just built becomes the chosen one
        if (sum_ > target_) found_ = true;
        else fallback_ = true;
    }
    chunk_().count = 0;
}

}  // namespace cell_stream
}  // namespace pds
