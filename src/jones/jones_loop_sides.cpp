// jones_loop_sides.cpp - a free regions' epoch inserted on two sides of the
// domain's middle at once (Delaunay::insert_on_side), in the plane with
// one radius.
//
// The epoch's accepted darts all go into the mesh right after they are
// decided; the points are then handed out one by one in order of time
// (add_region_point), the point table giving each its vertex. A dart goes
// into the slot its side and its rank on the side give: the left side's
// darts first, then the right side's, each side in order of time. A side
// inserts its darts in order of time, each one whose insertion stays on the
// side, and measures its new cell; the others wait, and are inserted after
// both sides, in order of time, on the caller's thread. One thread does the
// same in the same order, so the mesh's records, and so the points drawn
// later, do not depend on the threads.
//
// A cell measured before an earlier waiting dart went in is larger than the
// cell now: its weight is still an upper bound on its free area, which is
// all the lazy weights need (jones_loop.hpp).
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/room_growth.hpp"
#include "core/worker_pool.hpp"
#include "jones/jones_loop.hpp"
#include "jones/plane_space.hpp"
#include "jones/polygon_space.hpp"
#include "jones/radius_rule.hpp"
#include "jones/torus_space.hpp"

namespace pds {

template <class Space, class Rule>
void JonesLoop<Space, Rule>::set_side_insertions(bool on) {
    side_insertions_ = on && std::is_same_v<Space, PlaneSpace> && std::is_same_v<Rule, OneRadius>;
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::make_room_for_epoch(std::size_t darts) {
    // The decided darts are at most those drawn, and their records are
    // appended after the free ones. Grown by the sampler's policy, up to the
    // pattern's bound that the sampler gave (in the plane, where epochs go
    // by sides, a point is a vertex).
    const std::size_t need = count() + darts;
    if (!has_room_for(need) || !dt_.can_append_edges(darts))
        reserve(grown_room(std::max(need, dt_.vertices_to_append_edges(darts) - Delaunay::kGhosts), count(),
                           room_cap_));
    // And the epoch's own lists: once it is decided nothing may fail.
    side_dart_of_.reserve(darts);
    side_area_.reserve(darts);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::insert_epoch_by_sides(WorkerPool& pool) {
    const std::size_t m = regions_.pending_count();
    if (m == 0) return;
    const RegionDarts::Dart* darts = regions_.pending_darts();
    const Box box = space_.clip_box();
    const double mid = 0.5 * (box.x0 + box.x1);
    // The slots' darts: the left side's, then the right's, each in order of
    // time.
    std::vector<std::uint32_t>& by_rank = side_dart_of_;
    std::vector<double>& area = side_area_;
    by_rank.resize(m);
    area.assign(m, -1.0);  // -1: waiting
    std::size_t left = 0;
    for (std::size_t i = 0; i < m; ++i) left += darts[i].p.x < mid ? 1 : 0;
    std::size_t next[2] = {0, left};
    for (std::size_t i = 0; i < m; ++i) by_rank[next[darts[i].p.x < mid ? 0 : 1]++] = static_cast<std::uint32_t>(i);
    const std::size_t before = count();
    const VertexIndex base = dt_.open_slots(m);
    QuadEdgeMesh::Arena arenas[2] = {dt_.edge_arena(left), dt_.edge_arena(m - left)};
    const bool alone = pool.size() < 2;
    const auto insert_side = [&](unsigned s) {
        const Delaunay::Side side{mid, s == 0};
        const MeshCells cells = cells_of(s);
        const std::size_t first = s == 0 ? 0 : left, last = s == 0 ? left : m;
        for (std::size_t r = first; r < last; ++r) {
            // The darts come in order of time, so far apart: their sources'
            // rings, fetched together ahead, are what the searches wait on.
            // Those of the side only, and nothing beyond them unless this
            // thread is alone: the other side's records may be changing.
            if ((r - first) % kMaxBatch == 0) {
                VertexIndex ahead[kMaxBatch];
                std::size_t n = 0;
                for (std::size_t q = r; q < last && q < r + kMaxBatch; ++q)
                    if (dt_.on_side(darts[by_rank[q]].source, side)) ahead[n++] = darts[by_rank[q]].source;
                dt_.prefetch_rings(ahead, n);
                if (alone) dt_.prefetch_beyond_rings(ahead, n);
            }
            const RegionDarts::Dart& d = darts[by_rank[r]];
            const VertexIndex v = base + static_cast<VertexIndex>(r);
            if (!dt_.insert_on_side(d.p, d.source, side, v, arenas[s])) continue;
            area[r] = cells.measure(v).area;
        }
    };
    if (!alone) {
        pool.run([&](unsigned w) {
            if (w < 2) insert_side(w);
        });
    } else {
        insert_side(0);
        insert_side(1);
    }
    dt_.close_edge_arena(arenas[0]);
    dt_.close_edge_arena(arenas[1]);
    // The waiting darts, in order of time: the two sides' slots merged.
    std::size_t waiting = 0;
    for (std::size_t r = 0; r < m; ++r) waiting += area[r] < 0.0 ? 1 : 0;
    QuadEdgeMesh::Arena rest = dt_.edge_arena(waiting);
    const MeshCells cells = cells_of(0);
    for (std::size_t a = 0, b = left; waiting > 0 && (a < left || b < m);) {
        const std::size_t r = b == m || (a < left && by_rank[a] < by_rank[b]) ? a++ : b++;
        if (!(area[r] < 0.0)) continue;
        const RegionDarts::Dart& d = darts[by_rank[r]];
        const VertexIndex v = base + static_cast<VertexIndex>(r);
        dt_.insert_in_slot(d.p, d.source, v, rest);
        area[r] = cells.measure(v).area;
        --waiting;
    }
    dt_.close_edge_arena(rest);
    // The tree's leaves in vertex order; the points' vertices in order of
    // time, after those of the points inserted one by one before.
    order_.extend_to(before);
    order_.resize(before + m);
    for (std::size_t r = 0; r < m; ++r) {
        tree_.push_back(area[r]);
        order_.set(before + by_rank[r], base + static_cast<VertexIndex>(r));
    }
    inserted_ahead_ = m;
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::hand_out_inserted(double value) {
    if (inserted_ahead_ == 0) throw std::logic_error("add_next: the epoch's points were all handed out");
    --inserted_ahead_;
    record_new_point(order_.vertex(count() - 1), value);
}

template <class Space, class Rule>
void JonesLoop<Space, Rule>::require_epoch_handed_out(const char* what) const {
    if (inserted_ahead_ != 0)
        throw std::logic_error(std::string(what) + " while an epoch inserted by sides is being handed out");
}

#define PDS_SIDES_MEMBERS(Space, Rule)                                                  \
    template void JonesLoop<Space, Rule>::set_side_insertions(bool);                     \
    template void JonesLoop<Space, Rule>::make_room_for_epoch(std::size_t);              \
    template void JonesLoop<Space, Rule>::insert_epoch_by_sides(WorkerPool&);            \
    template void JonesLoop<Space, Rule>::hand_out_inserted(double);                     \
    template void JonesLoop<Space, Rule>::require_epoch_handed_out(const char*) const;
PDS_SIDES_MEMBERS(PlaneSpace, OneRadius)
PDS_SIDES_MEMBERS(PlaneSpace, PowerRule)
PDS_SIDES_MEMBERS(TorusSpace, OneRadius)
PDS_SIDES_MEMBERS(TorusSpace, PowerRule)
PDS_SIDES_MEMBERS(PolygonSpace, OneRadius)
PDS_SIDES_MEMBERS(PolygonSpace, PowerRule)

}  // namespace pds
