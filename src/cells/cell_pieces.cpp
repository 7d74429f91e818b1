// cell_pieces.cpp - fan-triangle geometry of a cell's free region (Jones 2006,
// section 3.1, cases 1-4; see cell_pieces.hpp).
#include "cells/cell_pieces.hpp"

#include <cmath>

#include "core/angle.hpp"
#include "core/vec.hpp"

namespace pds {

namespace {

// The split of the far side a-b, given as a + t (ex, ey) for t in [0, end],
// with ee = ex^2 + ey^2 and cr = cross(a, (ex, ey)) (cross(a, b) when end is
// 1); t is measured in lengths of (ex, ey) throughout.
__attribute__((always_inline)) inline int split_side(const Point& a, const Point& b, double ex, double ey,
                                                     double ee, double end, double cr, double r2, Piece out[2]) {
    const auto at = [&](double t) { return Point{a.x + t * ex, a.y + t * ey}; };
    const double inv_ee = 1.0 / ee;
    const double closest = -(a.x * ex + a.y * ey) * inv_ee;  // parameter of closest approach
    const double h2 = cr * cr * inv_ee;                        // squared distance of the line
    if (h2 >= r2) {
        // The far side misses the circle (case 3 if the closest approach is
        // inside the side: split there so distance is monotone on each piece).
        if (closest > 0.0 && closest < end) {
            const Point m = at(closest);
            out[0] = Piece{a, m};
            out[1] = Piece{m, b};
            return 2;
        }
        out[0] = Piece{a, b};
        return 1;
    }
    // The line cuts the circle at t1 < t2; only the parts outside count
    // (cases 1 and 2).
    const double s = std::sqrt((r2 - h2) * inv_ee);
    const double t1 = closest - s, t2 = closest + s;
    int n = 0;
    if (t1 > 0.0) out[n++] = Piece{a, t1 < end ? at(t1) : b};
    if (t2 < end) out[n++] = Piece{t2 > 0.0 ? at(t2) : a, b};
    return n;
}

// A side so short that its squared length loses precision or underflows (a
// domain far thinner than R has them, and they hold most of its cells'
// area): the same split with the side scaled by a power of two, exactly.
int split_short_side(const Point& a, const Point& b, double r2, Piece out[2]) {
    const double longest = std::fmax(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
    if (!(longest >= 0x1.0p-1000)) return 0;  // no area a double could hold
    int shift = 0;
    std::frexp(longest, &shift);
    // (ex, ey) = (b - a) 2^-shift, so the side ends at t = 2^shift.
    const double ex = std::ldexp(b.x - a.x, -shift), ey = std::ldexp(b.y - a.y, -shift);
    return split_side(a, b, ex, ey, ex * ex + ey * ey, std::ldexp(1.0, shift), cross(a, Point{ex, ey}), r2, out);
}

}  // namespace

int split_fan_triangle(const Point& a, const Point& b, double r2, Piece out[2]) {
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double ee = ex * ex + ey * ey;
    if (ee < 0x1.0p-800) return split_short_side(a, b, r2, out);
    return split_side(a, b, ex, ey, ee, 1.0, cross(a, b), r2, out);
}

void Chunk::begin(const Piece& pc, bool keep_pieces) {
    start = pc.p;
    end = pc.q;
    cross_sum = cross(pc.p, pc.q);
    count = 1;
    if (keep_pieces) pieces[0] = pc;
}

void Chunk::extend(const Piece& pc, bool keep_pieces) {
    end = pc.q;
    cross_sum += cross(pc.p, pc.q);
    if (keep_pieces) pieces[count] = pc;
    ++count;
}

double Chunk::area(double r2) const {
    const double theta = angle_of(cross(start, end), dot(start, end));
    const double a = 0.5 * (cross_sum - r2 * theta);
    return a > 0.0 ? a : 0.0;
}

int select_piece(const Chunk& chunk, double r2, double u) {
    double areas[kMaxChunkPieces];
    double total = 0.0;
    for (int i = 0; i < chunk.count; ++i) total += (areas[i] = piece_area(chunk.pieces[i], r2));
    const double target = u * total;
    double sum = 0.0;
    int last = -1;
    for (int i = 0; i < chunk.count; ++i) {
        if (areas[i] <= 0.0) continue;
        sum += areas[i];
        last = i;
        if (sum > target) return i;
    }
    return last;
}

double piece_area(const Piece& piece, double r2) {
    const double cr = cross(piece.p, piece.q);
    const double theta = angle_of(cr, dot(piece.p, piece.q));
    const double area = 0.5 * (cr - r2 * theta);
    return area > 0.0 ? area : 0.0;
}

bool draw_in_piece(const Piece& piece, double r, double r2, Rng& rng, Point* out) {
    // Quadrilateral p_i, p, q, q_j where p_i, q_j are the circle's crossings of
    // the rays to p and q (figure 5); it contains the piece's free region and
    // at least half of it is free, so few draws are rejected.
    const Point& p = piece.p;
    const Point& q = piece.q;
    const double sp = r / std::sqrt(dot(p, p)), sq = r / std::sqrt(dot(q, q));
    const Point pi{p.x * sp, p.y * sp}, qj{q.x * sq, q.y * sq};
    const Point e1{p.x - pi.x, p.y - pi.y}, e2{q.x - pi.x, q.y - pi.y}, e3{qj.x - pi.x, qj.y - pi.y};
    const double a1 = std::fabs(cross(e1, e2)), a2 = std::fabs(cross(e2, e3));
    if (!(a1 + a2 > 0.0)) return false;
    const bool first = rng.next_double() * (a1 + a2) < a1;
    const Point& u = first ? e1 : e2;
    const Point& v = first ? e2 : e3;
    double s = rng.next_double(), t = rng.next_double();
    if (s + t > 1.0) {
        s = 1.0 - s;
        t = 1.0 - t;
    }
    const Point x{pi.x + s * u.x + t * v.x, pi.y + s * u.y + t * v.y};
    if (dot(x, x) < r2) return false;
    *out = x;
    return true;
}

}  // namespace pds
