// delaunay_build.cpp - a Delaunay mesh built whole, by divide and conquer.
//
// Guibas & Stolfi (1985, section 10): split the vertices in two halves by a
// line, triangulate each half, then zip the halves together from their lower
// common tangent upwards, deleting the edges of either half that a new cross
// edge shows not to be Delaunay. The cuts alternate between x and y (Dwyer
// 1987): each level splits at the median along its axis (ties by the other
// coordinate), so the parts stay about square. The ghost corners are
// vertices like any other, so the outer face is the ghost square, as
// insertion leaves it. With the exact predicates the result is the Delaunay
// triangulation (ties on a circle decided by the merge's fixed rule).
//
// Side by side: the recursion's top k levels (k from n alone) cut the
// vertices into 2^k leaves. Each leaf is built by one worker from its own
// arena of records (3 per vertex and 8 more: a planar graph on m vertices
// has at most 3m - 6 edges, at every moment of the build as at its end), then
// the leaves are merged level by level, the merges of a level side by side,
// each from its two parts' arenas joined. A median split gives the same two
// sets whatever order its range was in, so which worker runs a part changes
// none of its records: the mesh is the same on any number of threads.
#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "core/predicates.hpp"
#include "core/prefetch.hpp"
#include "core/worker_pool.hpp"
#include "mesh/delaunay.hpp"

namespace pds {
namespace {

constexpr std::size_t kMaxLeaves = 64;
constexpr std::uint32_t kArenaSlack = 8;
static_assert(kArenaSlack * kMaxLeaves <= Delaunay::kBuildWholeSlack, "reserve() leaves the arenas their slack");

// A triangulated part: its counterclockwise hull edge out of its leftmost
// vertex, and its clockwise hull edge out of its rightmost (Guibas-Stolfi's
// ldo and rdo). Leftmost in the frame of the cut that made the part: the
// plane's (axis 0, x then y) or the plane turned a quarter (axis 1, y then
// -x). The predicates do not change under the turn, so one merge serves both.
struct Part {
    EdgeRef left_out = kNoEdge, right_out = kNoEdge;
};

bool less_on_axis(const Point& a, const Point& b, unsigned axis) {
    if (axis == 0) return a.x < b.x || (a.x == b.x && a.y < b.y);
    return a.y < b.y || (a.y == b.y && a.x > b.x);
}

// The same order with no branch on the outcome, for the partitions (on
// points in no order the outcome is a coin flip, which a branch would
// mispredict half the time).
template <unsigned kAxis>
bool less_on_axis_flat(const Point& a, const Point& b) {
    if (kAxis == 0) return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
    return (a.y < b.y) | ((a.y == b.y) & (a.x > b.x));
}

class DivideAndConquer {
public:
    DivideAndConquer(QuadEdgeMesh& mesh, const std::vector<Point>& points, VertexIndex* vertices)
        : m_(mesh), p_(points), s_(vertices) {}

    // Splits s_[lo, hi) at its middle along the axis of that depth: the
    // lower half first (in no particular order within each half).
    void split(std::size_t lo, std::size_t hi, unsigned depth) {
        if (depth & 1u)
            select<1>(lo, hi, lo + (hi - lo) / 2);
        else
            select<0>(lo, hi, lo + (hi - lo) / 2);
    }

    // Puts in s_[k] the vertex that sorted order would, the smaller ones
    // before it: quickselect with flat partitions (pivot: the median of
    // three), points fetched ahead; std::nth_element finishes small ranges,
    // and long ones if the pivots keep failing.
    template <unsigned kAxis>
    void select(std::size_t lo, std::size_t hi, std::size_t k) {
        constexpr std::size_t kSmall = 8, kAhead = 16;
        const auto less = [&](VertexIndex a, VertexIndex b) { return less_on_axis_flat<kAxis>(p_[a], p_[b]); };
        for (int rounds = 0; hi - lo > kSmall && rounds < 64; ++rounds) {
            const std::size_t last = hi - 1, mid = lo + (hi - lo) / 2;
            if (less(s_[mid], s_[lo])) std::swap(s_[mid], s_[lo]);
            if (less(s_[last], s_[mid])) std::swap(s_[last], s_[mid]);
            if (less(s_[mid], s_[lo])) std::swap(s_[mid], s_[lo]);
            std::swap(s_[mid], s_[last]);  // the pivot waits at the end
            const Point pivot = p_[s_[last]];
            std::size_t below = lo;
            for (std::size_t i = lo; i < last; ++i) {
                if (i + kAhead < last) pds::prefetch(&p_[s_[i + kAhead]]);
                const VertexIndex v = s_[i];
                const bool smaller = less_on_axis_flat<kAxis>(p_[v], pivot);
                s_[i] = s_[below];
                s_[below] = v;
                below += smaller;
            }
            std::swap(s_[below], s_[last]);  // the pivot in its place
            if (k == below) return;
            if (k < below)
                hi = below;
            else
                lo = below + 1;
        }
        std::nth_element(s_ + lo, s_ + k, s_ + hi, less);
    }

    // Cuts alternately along x and y (Dwyer's alternating cuts): parts cut
    // along one axis only are slivers whose edges the next merge mostly
    // deletes, and square parts keep their vertices, numbered along the
    // hand-over's curve, on few pages.
    Part build(QuadEdgeMesh::Arena& arena, std::size_t lo, std::size_t hi, unsigned depth) {
        const unsigned axis = depth & 1u;
        if (hi - lo <= 3) {
            std::sort(s_ + lo, s_ + hi,
                      [&](VertexIndex a, VertexIndex b) { return less_on_axis(p_[a], p_[b], axis); });
            return build_small(arena, lo, hi);
        }
        split(lo, hi, depth);
        const std::size_t mid = lo + (hi - lo) / 2;
        const Part left = build(arena, lo, mid, depth + 1);
        const Part right = build(arena, mid, hi, depth + 1);
        return merge(arena, in_frame(left, axis), in_frame(right, axis));
    }

    // The part's hull edges for the frame of `axis`: the hull walked once
    // (clockwise, the outside on the left), keeping its extreme vertices.
    Part in_frame(const Part& part, unsigned axis) const {
        const EdgeRef first = part.right_out;
        EdgeRef before = first, e = first;
        EdgeRef lowest = first, before_lowest = kNoEdge, highest = first;
        do {
            const EdgeRef next = m_.lnext(e);
            if (e != first) {
                if (less_on_axis(point_of_org(e), point_of_org(lowest), axis)) {
                    lowest = e;
                    before_lowest = before;
                }
                if (less_on_axis(point_of_org(highest), point_of_org(e), axis)) highest = e;
            }
            before = e;
            e = next;
        } while (e != first);
        if (before_lowest == kNoEdge) before_lowest = before;  // the first edge's predecessor: the last
        return {QuadEdgeMesh::sym(before_lowest), highest};
    }

    // Two or three vertices, s_[lo, hi) sorted in the part's frame.
    Part build_small(QuadEdgeMesh::Arena& arena, std::size_t lo, std::size_t hi) {
        const std::size_t n = hi - lo;
        if (n == 2) {
            const EdgeRef a = m_.make_edge(arena, s_[lo], s_[lo + 1]);
            return {a, QuadEdgeMesh::sym(a)};
        }
        const EdgeRef a = m_.make_edge(arena, s_[lo], s_[lo + 1]);
        const EdgeRef b = m_.make_edge(arena, s_[lo + 1], s_[lo + 2]);
        m_.splice(QuadEdgeMesh::sym(a), b);
        const int turn = orient2d(p_[s_[lo]], p_[s_[lo + 1]], p_[s_[lo + 2]]);
        if (turn > 0) {
            m_.connect(arena, b, a);
            return {a, QuadEdgeMesh::sym(b)};
        }
        if (turn < 0) {
            const EdgeRef c = m_.connect(arena, b, a);
            return {QuadEdgeMesh::sym(c), c};
        }
        return {a, QuadEdgeMesh::sym(b)};  // collinear: a path
    }

    Part merge(QuadEdgeMesh::Arena& arena, Part left, const Part& right) {
        EdgeRef ldo = left.left_out, ldi = left.right_out;
        EdgeRef rdi = right.left_out, rdo = right.right_out;
        // The lower common tangent of the two hulls.
        for (;;) {
            if (left_of(m_.org(rdi), ldi)) {
                ldi = m_.lnext(ldi);
            } else if (right_of(m_.org(ldi), rdi)) {
                rdi = m_.rprev(rdi);
            } else {
                break;
            }
        }
        EdgeRef base = m_.connect(arena, QuadEdgeMesh::sym(rdi), ldi);
        if (m_.org(ldi) == m_.org(ldo)) ldo = QuadEdgeMesh::sym(base);
        if (m_.org(rdi) == m_.org(rdo)) rdo = base;
        // Up the seam: each step adds the cross edge whose circle through the
        // base is empty, after deleting the edges that circle shows wrong.
        for (;;) {
            EdgeRef lcand = m_.onext(QuadEdgeMesh::sym(base));
            if (above(lcand, base)) {
                while (incircle(point_of_dest(base), point_of_org(base), point_of_dest(lcand),
                                point_of_dest(m_.onext(lcand))) > 0) {
                    const EdgeRef t = m_.onext(lcand);
                    m_.delete_edge(arena, lcand);
                    lcand = t;
                }
            }
            EdgeRef rcand = m_.oprev(base);
            if (above(rcand, base)) {
                while (incircle(point_of_dest(base), point_of_org(base), point_of_dest(rcand),
                                point_of_dest(m_.oprev(rcand))) > 0) {
                    const EdgeRef t = m_.oprev(rcand);
                    m_.delete_edge(arena, rcand);
                    rcand = t;
                }
            }
            const bool l_ok = above(lcand, base), r_ok = above(rcand, base);
            if (!l_ok && !r_ok) break;  // the upper common tangent
            if (!l_ok || (r_ok && incircle(point_of_dest(lcand), point_of_org(lcand), point_of_org(rcand),
                                           point_of_dest(rcand)) > 0)) {
                base = m_.connect(arena, rcand, QuadEdgeMesh::sym(base));
            } else {
                base = m_.connect(arena, QuadEdgeMesh::sym(base), QuadEdgeMesh::sym(lcand));
            }
        }
        return {ldo, rdo};
    }

private:
    const Point& point_of_org(EdgeRef e) const { return p_[m_.org(e)]; }
    const Point& point_of_dest(EdgeRef e) const { return p_[m_.dest(e)]; }
    bool left_of(VertexIndex v, EdgeRef e) const {
        return orient2d(p_[v], point_of_org(e), point_of_dest(e)) > 0;
    }
    bool right_of(VertexIndex v, EdgeRef e) const {
        return orient2d(p_[v], point_of_dest(e), point_of_org(e)) > 0;
    }
    // A candidate cross edge: its far end strictly above the base.
    bool above(EdgeRef candidate, EdgeRef base) const { return right_of(m_.dest(candidate), base); }

    QuadEdgeMesh& m_;
    const std::vector<Point>& p_;
    VertexIndex* s_;
};

}  // namespace

bool Delaunay::build_whole(const std::vector<Point>& points, const std::uint32_t* order, std::size_t n,
                           unsigned threads) {
    const std::size_t vertices = kGhosts + n;
    if (n < kBuildWholeFrom || points_.size() != kGhosts || !has_room_for(vertices)) return false;
    std::size_t leaves = 1;
    while (leaves < kMaxLeaves && (vertices / (2 * leaves)) >= kBuildWholeFrom) leaves *= 2;
    const std::size_t records = 3 * vertices + kArenaSlack * leaves;
    if (records > kMaxEdgeRecords || !mesh_.lay_out_for_arenas(records)) return false;

    WorkerPool pool(threads);
    const unsigned workers = pool.size();
    points_.resize(vertices);  // within the room: does not allocate
    vertex_edge_.resize(vertices);
    if (weighted_) {
        // Every point has the ghosts' radius: each power test is the
        // in-circle test, so the regular mesh is this Delaunay mesh.
        radii_.resize(vertices, radii_[0]);
        hidden_by_.resize(vertices, kNoVertex);
    }
    pool.run([&](unsigned w) {
        const std::size_t lo = n * w / workers, hi = n * (w + 1) / workers;
        constexpr std::size_t kAhead = 16;
        for (std::size_t i = lo; i < hi; ++i) {
            if (i + kAhead < hi) pds::prefetch(&points[order[i + kAhead]]);
            points_[kGhosts + i] = points[order[i]];
        }
    });

    // The order of the cuts, in vertex_edge_ until the entry edges are
    // known: the top levels' splits first (a level's side by side), then
    // each leaf cuts its own.
    VertexIndex* order_of_cuts = vertex_edge_.data();
    for (std::size_t v = 0; v < vertices; ++v) order_of_cuts[v] = static_cast<VertexIndex>(v);

    // The leaves: the recursion's cuts (lo + size / 2) down to their level.
    std::size_t cut[kMaxLeaves + 1];
    cut[0] = 0;
    cut[leaves] = vertices;
    for (std::size_t step = leaves; step > 1; step /= 2)
        for (std::size_t i = 0; i < leaves; i += step)
            cut[i + step / 2] = cut[i] + (cut[i + step] - cut[i]) / 2;
    QuadEdgeMesh::Arena arena[kMaxLeaves];
    Part part[kMaxLeaves];
    for (std::size_t i = 0; i < leaves; ++i)
        arena[i] = QuadEdgeMesh::arena(static_cast<std::uint32_t>(3 * cut[i] + kArenaSlack * i),
                                       static_cast<std::uint32_t>(3 * cut[i + 1] + kArenaSlack * (i + 1)));
    DivideAndConquer dc(mesh_, points_, order_of_cuts);
    unsigned leaf_depth = 0;
    for (std::size_t step = leaves; step > 1; step /= 2, ++leaf_depth) {
        const std::size_t ranges = leaves / step;
        pool.run([&](unsigned w) {
            for (std::size_t j = w; j < ranges; j += workers)
                dc.split(cut[j * step], cut[(j + 1) * step], leaf_depth);
        });
    }
    pool.run([&](unsigned w) {
        for (std::size_t i = w; i < leaves; i += workers) part[i] = dc.build(arena[i], cut[i], cut[i + 1], leaf_depth);
    });
    unsigned depth = leaf_depth;
    for (std::size_t step = 1; step < leaves; step *= 2) {
        const std::size_t pairs = leaves / (2 * step);
        const unsigned axis = --depth & 1u;
        pool.run([&](unsigned w) {
            for (std::size_t j = w; j < pairs; j += workers) {
                const std::size_t a = 2 * j * step, b = a + step;
                arena[a] = mesh_.join(arena[a], arena[b]);
                part[a] = dc.merge(arena[a], dc.in_frame(part[a], axis), dc.in_frame(part[b], axis));
            }
        });
    }
    mesh_.close_arenas(arena[0]);

    // Entry edges: each vertex gets the edge out of it in its last record.
    for (std::size_t r = 0; r < records; ++r) {
        if (!mesh_.is_live(r)) continue;
        const EdgeRef e = static_cast<EdgeRef>(4 * r);
        vertex_edge_[mesh_.org(e)] = e;
        vertex_edge_[mesh_.dest(e)] = QuadEdgeMesh::sym(e);
    }
    return true;
}

}  // namespace pds
