// cell_pieces.hpp - the paper's pieces of a cell's free region (Jones 2006,
// section 3.1, cases 1-4 and figure 5), relative to the cell's site.
//
// The clipped Voronoi cell is a fan of triangles around the site. Each fan
// triangle (site, a, b) is split where its far side a-b enters or leaves the
// disk of radius R, or at its point of closest approach (cases 1-3), into at
// most two pieces of case 4: a segment p-q along which the distance to the
// site is monotone and at least R. A piece's free area is its triangle minus
// the circular sector it spans; a point is drawn in it by rejection inside
// the quadrilateral of figure 5, which is more than half free.
#ifndef PDS_CELL_PIECES_HPP
#define PDS_CELL_PIECES_HPP

#include "core/point.hpp"
#include "core/rng.hpp"
#include "core/vec.hpp"

namespace pds {

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
               cross(start, pc.q) > 0.0;
    }
    void begin(const Piece& pc, bool keep_pieces);
    void extend(const Piece& pc, bool keep_pieces);
    double area(double r2) const;
};

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

}  // namespace pds

#endif
