// torus_space.hpp - the Jones loop's mesh on the torus (jones_loop.hpp,
// torus_copies.hpp): the mesh also holds copies of the points near the
// fundamental domain. Copies are vertices with weight 0 in the tree (never
// selected), points are drawn in their real cell (unclipped), snapped to the
// torus grid and moved into the fundamental domain when inserted, and a
// candidate is checked against every copy of the points added since.
//
// The margin of copies widens until every real cell is a true torus cell
// (and narrows again as a pattern with a variable radius fills, which runs
// the loop from its first point on a sparse torus). The space's functions
// take the loop (a friend) when they change the mesh, as plane_space.hpp's.
#ifndef PDS_TORUS_SPACE_HPP
#define PDS_TORUS_SPACE_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/indices.hpp"
#include "core/point.hpp"
#include "core/poll.hpp"
#include "core/predicates.hpp"
#include "core/rng.hpp"
#include "core/torus.hpp"
#include "domain/rectangle.hpp"
#include "jones/mesh_build.hpp"
#include "jones/mesh_cells.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/torus_copies.hpp"
#include "verify/verify_torus.hpp"

namespace pds {

class TorusSpace {
public:
    static constexpr bool kPeriodic = true;
    static constexpr bool kMeasuresSideBySide = true;
    // A margin widened during an insertion measures every cell again.
    static constexpr bool kBoundsStayWhileInserting = false;

    TorusSpace(const Rectangle& domain, double r, const Torus& torus, bool weighted,
               const std::shared_ptr<const Polygon>& polygon);

    Box mesh_region() const { return copies_.largest_region(); }
    Box clip_box() const { return copies_.clip_box(); }
    OutlineClip* outline_clip(unsigned /*w*/ = 0) const { return nullptr; }
    void set_workers(unsigned) {}
    const TorusCopies& copies() const { return copies_; }
    bool is_copy(VertexIndex v) const { return is_copy_[v] != 0; }
    // The real vertex v copies (itself if real).
    VertexIndex original(VertexIndex v) const { return original_[v]; }
    std::size_t vertices_for(std::size_t points) const;
    void reserve(std::size_t vertices) {
        is_copy_.reserve(vertices);
        original_.reserve(vertices);
    }
    bool has_room_for(std::size_t vertices) const {
        return is_copy_.capacity() >= vertices && original_.capacity() >= vertices;
    }
    template <class Loop>
    std::size_t count(const Loop& loop) const {
        return loop.order_.handed_over();
    }

    // On the torus grid, inside the fundamental domain.
    Point first_point(Rng& rng) const;
    // The torus has no corners (JonesLoop::give_up).
    template <class Fn>
    bool any_corner_in(const Box&, Fn&&) const {
        return false;
    }
    Point snap(const Point& p) const { return Point{Torus::snap(p.x), Torus::snap(p.y)}; }
    bool inside(const Point&) const { return true; }  // cells are unclipped; wrapped when inserted
    Point wrap(const Point& p) const { return copies_.torus().wrap(p); }
    template <class Radius>
    bool covers(const Point& q, const Point& p, double reach, const Radius& radius) const;

    template <class Loop>
    void adopt(Loop& loop, const std::vector<Point>& points, const std::uint32_t* order,
               const std::vector<double>* values, const Poll& poll, MeshBuild build);
    template <class Loop>
    void insert_point(Loop& loop, const Point& p, VertexIndex near, double value);
    // Whether the triangles around real vertex v, measured as m, keep the
    // torus invariant.
    template <class Loop>
    bool cell_valid(const Loop& loop, VertexIndex v, const CellMeasure& m) const;
    // Finishes a widening that memory interrupted, or that the hand-over
    // left to do (may throw std::bad_alloc).
    template <class Loop>
    void settle(Loop& loop) {
        if (widen_pending_) widen_margin(loop);
    }
    // Widens the margin until every real ring is valid, inserting the copies
    // it brings, and measures every cell again. Interrupted by
    // std::bad_alloc, it leaves the copies as they were (room is made before
    // each round) and the widening pending.
    template <class Loop>
    void widen_margin(Loop& loop);
    bool pending() const { return widen_pending_; }

    VerifyReport verify(const Delaunay& dt, double r, const std::vector<std::size_t>* rank,
                        std::size_t /*fixed: none on the torus*/) const {
        return verify_torus(dt, copies_, is_copy_, r, rank);
    }

private:
    bool is_real(VertexIndex v) const { return !Delaunay::is_ghost(v) && original_[v] == v; }
    // Room for one more point and all its copies (may allocate).
    template <class Loop>
    void make_room_for_copies(Loop& loop, std::size_t copies);
    // Inserts p with its bookkeeping: a copy of real vertex *copy_of (with
    // its radius), or a real point of radius `radius` when there is none. Its
    // tree leaf is 0 until measured.
    template <class Loop>
    VertexIndex insert_vertex(Loop& loop, const Point& p, VertexIndex near,
                              std::optional<VertexIndex> copy_of = std::nullopt, double radius = 0.0);
    // The bookkeeping of vertex v just made: a copy of real vertex *copy_of,
    // or real; its tree leaf 0 until measured.
    template <class Loop>
    void record_vertex(Loop& loop, VertexIndex v, std::optional<VertexIndex> copy_of = std::nullopt);
    // Inserts p (real, wrapped; radius: its radius with a variable one) and
    // its copies; returns p's vertex.
    template <class Loop>
    VertexIndex insert_with_copies(Loop& loop, const Point& p, VertexIndex near, double radius);
    // Calls f(o) for each neighbour of v that is a copy of real vertex o
    // shifted by exactly (sx, sy) (exact on the grid).
    template <class F>
    void for_each_neighbour_copy(const Delaunay& dt, VertexIndex v, double sx, double sy, const F& f) const;
    // Where to start the walk that inserts w, p moved into the domain.
    VertexIndex walk_start(const Delaunay& dt, const Point& p, const Point& w, VertexIndex near) const;
    // Where to start the walk that inserts c, the copy of real vertex v
    // shifted by (i, j) periods; hint: the last copy with that offset.
    VertexIndex copy_walk_start(const Delaunay& dt, VertexIndex v, const Point& c, int i, int j,
                                VertexIndex hint) const;
    // Whether the triangles around the new vertices [from, vertex_count)
    // keep the torus invariant.
    bool new_rings_valid(const Delaunay& dt, VertexIndex from) const;
    // A variable radius: each time the count doubles, if the cells now need
    // under half the margin, the mesh is rebuilt with the copies of a
    // narrower one (drawn candidates are dropped, as at a refine: a decision
    // that depends on the count only, so the law and the splits' bytes are
    // kept); held back while the free regions' darts run.
    template <class Loop>
    void maybe_narrow_margin(Loop& loop);
    template <class Loop>
    void rebuild_with_margin(Loop& loop, double margin);

    TorusCopies copies_;
    std::vector<std::uint8_t> is_copy_;   // per vertex
    std::vector<VertexIndex> original_;   // per vertex: the real one it copies (itself if real)
    std::vector<VertexIndex> copy_hint_;  // per offset: the last copy inserted
    bool widen_pending_ = false;          // copies may be missing: widen_margin() first
    std::size_t next_narrowing_ = 64;     // the count at which to look at the margin again
};

}  // namespace pds

#include "jones/torus_space_loop.hpp"

#endif
