// delaunay_build.cpp - a Delaunay mesh built whole, by divide and conquer.
//
// Guibas & Stolfi (1985, section 10): sort the vertices lexicographically,
// triangulate each half, then zip the halves together from their lower
// common tangent upwards, deleting the edges of either half that a new cross
// edge shows not to be Delaunay. The ghost corners are vertices like any
// other: the left two sort first and the right two last, so the outer face
// is the ghost square, as insertion leaves it. With the exact predicates the
// result is the Delaunay triangulation (ties on a circle decided by the
// merge's fixed rule).
//
// Side by side: the recursion's top k levels (k from n alone) cut the sorted
// vertices into 2^k leaves. Each leaf is built by one worker from its own
// arena of records (3 per vertex and 8 more: a planar graph on m vertices
// has at most 3m - 6 edges, at every moment of the build as at its end), then
// the leaves are merged level by level, the merges of a level side by side,
// each from its two parts' arenas joined. Which worker runs a part changes
// none of its records, so the mesh is the same on any number of threads.
#include <algorithm>
#include <cmath>
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
// ldo and rdo). Leftmost in the frame the part was cut in: the plane's, or
// the plane turned a quarter (x' = y, y' = -x) for the strips' parts.
struct Part {
    EdgeRef left_out = kNoEdge, right_out = kNoEdge;
};

bool lexicographic_less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
bool turned_less(const Point& a, const Point& b) { return a.y < b.y || (a.y == b.y && a.x > b.x); }

class DivideAndConquer {
public:
    // `sorted`: the vertices in lexicographic order; strips of up to
    // `strip` of them are cut across (below).
    DivideAndConquer(QuadEdgeMesh& mesh, const std::vector<Point>& points, VertexIndex* sorted, std::size_t strip)
        : m_(mesh), p_(points), s_(sorted), strip_(strip) {}

    // Cuts along x alone, down to strips: a part cut only along x is a tall
    // sliver whose edges the next merge mostly deletes. So a strip is sorted
    // by y and cut across (Dwyer 1987: O(n log log n) expected for uniform
    // points), then its part is turned back to the plane's frame.
    Part build(QuadEdgeMesh::Arena& arena, std::size_t lo, std::size_t hi) {
        if (hi - lo > strip_) {
            const std::size_t mid = lo + (hi - lo) / 2;
            const Part left = build(arena, lo, mid);
            const Part right = build(arena, mid, hi);
            return merge(arena, left, right);
        }
        std::sort(s_ + lo, s_ + hi, [&](VertexIndex a, VertexIndex b) { return turned_less(p_[a], p_[b]); });
        return in_plane_frame(build_in_order(arena, lo, hi));
    }

    // Guibas and Stolfi's recursion on s_[lo, hi), sorted in the part's frame.
    Part build_in_order(QuadEdgeMesh::Arena& arena, std::size_t lo, std::size_t hi) {
        const std::size_t n = hi - lo;
        if (n == 2) {
            const EdgeRef a = m_.make_edge(arena, s_[lo], s_[lo + 1]);
            return {a, QuadEdgeMesh::sym(a)};
        }
        if (n == 3) {
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
        const std::size_t mid = lo + n / 2;
        const Part left = build_in_order(arena, lo, mid);
        const Part right = build_in_order(arena, mid, hi);
        return merge(arena, left, right);
    }

    // The part's hull edges for the plane's frame: the hull walked once
    // (clockwise, the outside on the left), keeping its extreme vertices.
    Part in_plane_frame(const Part& turned) const {
        const EdgeRef first = turned.right_out;
        EdgeRef before = first, e = first;
        EdgeRef lowest = first, before_lowest = kNoEdge, highest = first;
        do {
            const EdgeRef next = m_.lnext(e);
            if (e != first) {
                if (lexicographic_less(point_of_org(e), point_of_org(lowest))) {
                    lowest = e;
                    before_lowest = before;
                }
                if (lexicographic_less(point_of_org(highest), point_of_org(e))) highest = e;
            }
            before = e;
            e = next;
        } while (e != first);
        if (before_lowest == kNoEdge) before_lowest = before;  // the first edge's predecessor: the last
        return {QuadEdgeMesh::sym(before_lowest), highest};
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
    std::size_t strip_;
};

}  // namespace

bool Delaunay::build_whole(const std::vector<Point>& points, const std::uint32_t* order, std::size_t n,
                           unsigned threads) {
    const std::size_t vertices = kGhosts + n;
    if (weighted_ || n < kBuildWholeFrom || points_.size() != kGhosts || !has_room_for(vertices)) return false;
    std::size_t leaves = 1;
    while (leaves < kMaxLeaves && (vertices / (2 * leaves)) >= kBuildWholeFrom) leaves *= 2;
    const std::size_t records = 3 * vertices + kArenaSlack * leaves;
    if (records > kMaxEdgeRecords || !mesh_.lay_out_for_arenas(records)) return false;

    WorkerPool pool(threads);
    const unsigned workers = pool.size();
    points_.resize(vertices);  // within the room: does not allocate
    vertex_edge_.resize(vertices);
    pool.run([&](unsigned w) {
        const std::size_t lo = n * w / workers, hi = n * (w + 1) / workers;
        constexpr std::size_t kAhead = 16;
        for (std::size_t i = lo; i < hi; ++i) {
            if (i + kAhead < hi) pds::prefetch(&points[order[i + kAhead]]);
            points_[kGhosts + i] = points[order[i]];
        }
    });

    // The lexicographic order, in vertex_edge_ until the entry edges are
    // known: a counting sort by x into about n/4 buckets (their counts in the
    // records' room, before any edge is made), then each bucket sorted.
    VertexIndex* sorted = vertex_edge_.data();
    double x0 = points_[kGhosts].x, x1 = x0;
    for (std::size_t v = kGhosts; v < vertices; ++v) {
        x0 = std::min(x0, points_[v].x);
        x1 = std::max(x1, points_[v].x);
    }
    const std::size_t buckets = n / 4 + 1;
    const double scale = x1 > x0 ? static_cast<double>(buckets) / (x1 - x0) : 0.0;
    auto bucket_of = [&](VertexIndex v) {
        const double b = (points_[v].x - x0) * scale;
        return b < static_cast<double>(buckets - 1) ? static_cast<std::size_t>(b) : buckets - 1;
    };
    for (std::size_t b = 0; b <= buckets; ++b) mesh_.scratch_word(b) = 0;
    for (std::size_t v = kGhosts; v < vertices; ++v) ++mesh_.scratch_word(bucket_of(static_cast<VertexIndex>(v)) + 1);
    mesh_.scratch_word(0) = 2;  // the left ghosts come first
    for (std::size_t b = 1; b <= buckets; ++b) mesh_.scratch_word(b) += mesh_.scratch_word(b - 1);
    // Ghosts 0 and 3 are the left corners (bottom first), 1 and 2 the right.
    sorted[0] = 0;
    sorted[1] = 3;
    sorted[vertices - 2] = 1;
    sorted[vertices - 1] = 2;
    for (std::size_t v = kGhosts; v < vertices; ++v)
        sorted[mesh_.scratch_word(bucket_of(static_cast<VertexIndex>(v)))++] = static_cast<VertexIndex>(v);
    // Now word b is where bucket b ends (and b + 1 begins).
    pool.run([&](unsigned w) {
        const std::size_t b0 = buckets * w / workers, b1 = buckets * (w + 1) / workers;
        for (std::size_t b = b0; b < b1; ++b) {
            const std::size_t begin = b == 0 ? 2 : mesh_.scratch_word(b - 1), end = mesh_.scratch_word(b);
            std::sort(sorted + begin, sorted + end,
                      [&](VertexIndex a, VertexIndex c) { return lexicographic_less(points_[a], points_[c]); });
        }
    });

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
    // Strips of about sqrt(n log n) vertices (Dwyer's choice).
    const std::size_t strip = std::max<std::size_t>(
        1024, static_cast<std::size_t>(std::sqrt(static_cast<double>(vertices) * std::log2(static_cast<double>(vertices)))));
    DivideAndConquer dc(mesh_, points_, sorted, strip);
    pool.run([&](unsigned w) {
        for (std::size_t i = w; i < leaves; i += workers) part[i] = dc.build(arena[i], cut[i], cut[i + 1]);
    });
    for (std::size_t step = 1; step < leaves; step *= 2) {
        const std::size_t pairs = leaves / (2 * step);
        pool.run([&](unsigned w) {
            for (std::size_t j = w; j < pairs; j += workers) {
                const std::size_t a = 2 * j * step, b = a + step;
                arena[a] = mesh_.join(arena[a], arena[b]);
                part[a] = dc.merge(arena[a], part[a], part[b]);
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
