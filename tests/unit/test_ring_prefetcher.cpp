// test_ring_prefetcher.cpp - the helper that walks the rings ahead of the
// insertions: a mesh it walks beside ends exactly as the same mesh built
// without it, record for record, plain and weighted (disks hidden on the
// way); it does not start for a batch of darts or fewer; it stops (joins)
// when asked, whether it is walking or waiting for the caller; it does its
// side job while it waits, and leaves what it did not do; the mesh is
// shared exactly while it runs, and its arrays refuse to move meanwhile.
// `make check-tsan` runs this suite built with -fsanitize=thread too: there,
// a write the helper may meet that is not a relaxed atomic store (an
// insertion on a mesh not shared) is reported as a data race.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/batch.hpp"
#include "core/rng.hpp"
#include "jones/region_darts.hpp"
#include "jones/ring_prefetcher.hpp"
#include "mesh/delaunay.hpp"
#include "mesh_checks.hpp"
#include "suites.hpp"

namespace {

struct Disk {
    pds::Point p;
    double r;
};

std::vector<Disk> random_disks(std::size_t n, std::uint64_t seed) {
    pds::Rng rng(seed);
    std::vector<Disk> disks(n);
    for (Disk& d : disks) {
        d.p = {rng.next_double(), rng.next_double()};
        d.r = 0.002 + 0.006 * rng.next_double();
    }
    return disks;
}

// A mesh of the first `before` disks, then the rest inserted by the caller;
// with the helper, it walks ahead of those insertions the rings of old
// vertices (each dart's source: any vertex that exists before they start).
pds::Delaunay build(const std::vector<Disk>& disks, std::size_t before, bool weighted, bool helper) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1}, weighted, 0.008);
    dt.reserve(disks.size() + pds::Delaunay::kGhosts);
    const auto insert = [&](const Disk& d, std::uint32_t near) {
        return weighted ? dt.insert(d.p, d.r, near) : dt.insert(d.p, near);
    };
    std::uint32_t last = 0;
    for (std::size_t i = 0; i < before; ++i) last = insert(disks[i], last);
    const std::size_t n = disks.size() - before;
    std::vector<pds::RegionDarts::Dart> darts(n);
    for (std::size_t k = 0; k < n; ++k) {
        const auto source = static_cast<pds::VertexIndex>(pds::Delaunay::kGhosts + (k * 7919) % before);
        darts[k] = pds::RegionDarts::Dart{disks[before + k].p, 0.0, source};
    }
    pds::RingPrefetcher walker;
    if (helper) ck_assert(walker.start(dt, darts.data(), n));
    for (std::size_t k = 0; k < n; ++k) {
        if (k % pds::kMaxBatch == 0) walker.reached(k);
        last = insert(disks[before + k], last);
    }
    walker.stop();
    ck_assert(!walker.running());
    ck_assert(!dt.shared());
    return dt;
}

// A plain mesh of n random points.
pds::Delaunay plain_mesh(std::size_t n, std::uint64_t seed) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1});
    dt.reserve(n + pds::Delaunay::kGhosts);
    for (const Disk& d : random_disks(n, seed)) dt.insert(d.p, 0);
    return dt;
}

// The same vertices, entry edges and links, record for record.
void check_same_mesh(const pds::Delaunay& a, const pds::Delaunay& b) {
    ck_assert_uint_eq(a.vertex_count(), b.vertex_count());
    ck_assert_uint_eq(a.mesh().record_count(), b.mesh().record_count());
    for (std::uint32_t v = 0; v < a.vertex_count(); ++v) ck_assert_uint_eq(a.edge_of(v), b.edge_of(v));
    for (std::size_t rec = 0; rec < a.mesh().record_count(); ++rec) {
        ck_assert(a.mesh().is_live(rec) == b.mesh().is_live(rec));
        if (!a.mesh().is_live(rec)) continue;
        const auto e = static_cast<pds::EdgeRef>(4 * rec);
        for (pds::EdgeRef q = e; q < e + 4; ++q) ck_assert_uint_eq(a.mesh().onext(q), b.mesh().onext(q));
        ck_assert_uint_eq(a.mesh().org(e), b.mesh().org(e));
        ck_assert_uint_eq(a.mesh().dest(e), b.mesh().dest(e));
    }
}

}  // namespace

START_TEST(the_mesh_it_walks_beside_ends_as_without_it) {
    const std::size_t n = test_light() ? 3000 : 20000;
    for (const bool weighted : {false, true}) {
        const std::vector<Disk> disks = random_disks(n, weighted ? 7 : 3);
        const pds::Delaunay alone = build(disks, n / 4, weighted, false);
        const pds::Delaunay beside = build(disks, n / 4, weighted, true);
        check_delaunay_mesh(beside);
        check_same_mesh(alone, beside);
        // The weighted case hid some disks on the way (hide_vertex's writes).
        if (weighted) ck_assert_uint_gt(beside.hidden_count(), 0);
    }
}
END_TEST

START_TEST(not_for_a_batch_or_fewer) {
    pds::Delaunay dt = plain_mesh(200, 5);
    std::vector<pds::RegionDarts::Dart> darts(pds::kMaxBatch + 1, pds::RegionDarts::Dart{{0.5, 0.5}, 0.0, 4});
    pds::RingPrefetcher walker;
    ck_assert(!walker.start(dt, darts.data(), pds::kMaxBatch));
    ck_assert(!walker.running());
    ck_assert(!dt.shared());
    ck_assert(walker.start(dt, darts.data(), pds::kMaxBatch + 1));
    ck_assert(dt.shared());
    walker.stop();
    ck_assert(!walker.running());
    ck_assert(!dt.shared());
    walker.stop();  // again: nothing to do
}
END_TEST

START_TEST(stops_when_asked_walking_or_waiting) {
    pds::Delaunay dt = plain_mesh(2000, 9);
    // Many darts and a caller that never advances: the helper walks a few
    // batches ahead, then waits; stop() ends it either way.
    std::vector<pds::RegionDarts::Dart> darts(100000);
    for (std::size_t k = 0; k < darts.size(); ++k)
        darts[k] = pds::RegionDarts::Dart{{0.5, 0.5}, 0.0, static_cast<pds::VertexIndex>(4 + k % 2000)};
    pds::RingPrefetcher walker;
    for (int round = 0; round < 20; ++round) {
        ck_assert(walker.start(dt, darts.data(), darts.size()));
        ck_assert(walker.running());
        if (round % 2 == 1) walker.reached(darts.size() / 2);  // far ahead: it walks
        walker.stop();
        ck_assert(!walker.running());
        ck_assert(!dt.shared());
    }
}
END_TEST

// A side job of `steps` steps, counted (read by the test while it runs).
struct CountedJob final : pds::RingPrefetcher::SideJob {
    explicit CountedJob(int n) : steps(n) {}
    bool step() override { return done.fetch_add(1, std::memory_order_relaxed) + 1 < steps; }
    int steps;
    std::atomic<int> done{0};
};

START_TEST(steps_its_side_job_while_it_waits) {
    pds::Delaunay dt = plain_mesh(2000, 10);
    std::vector<pds::RegionDarts::Dart> darts(100000);
    for (std::size_t k = 0; k < darts.size(); ++k)
        darts[k] = pds::RegionDarts::Dart{{0.5, 0.5}, 0.0, static_cast<pds::VertexIndex>(4 + k % 2000)};
    // The caller never advances: the helper walks a few batches ahead, then
    // does the whole job instead of napping (up to 20 s here: no timing).
    CountedJob job(500);
    pds::RingPrefetcher walker;
    ck_assert(walker.start(dt, darts.data(), darts.size(), &job));
    for (int i = 0; i < 2000 && job.done < job.steps; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    walker.stop();
    ck_assert_int_eq(job.done.load(), job.steps);  // all of it, and not a step more
    // Stopped at once, it leaves the rest of a long job to the caller.
    CountedJob endless(1 << 30);
    ck_assert(walker.start(dt, darts.data(), darts.size(), &endless));
    walker.stop();
    ck_assert_int_lt(endless.done.load(), endless.steps);
    ck_assert(!dt.shared());
}
END_TEST

START_TEST(the_arrays_do_not_move_while_shared) {
    pds::Delaunay dt(pds::Box{0, 0, 1, 1});
    dt.reserve(100);
    dt.set_shared(true);
    bool refused = false;
    try {
        dt.reserve(1000);
    } catch (const std::logic_error&) {
        refused = true;
    }
    ck_assert(refused);
    ck_assert(!dt.has_room_for(1000));  // nothing moved
    dt.set_shared(false);
    dt.reserve(1000);
    ck_assert(dt.has_room_for(1000));
}
END_TEST

Suite* ring_prefetcher_suite() {
    Suite* s = suite_create("ring_prefetcher");
    TCase* t = tcase_create("walks");
    tcase_set_timeout(t, 120);
    tcase_add_test(t, the_mesh_it_walks_beside_ends_as_without_it);
    tcase_add_test(t, not_for_a_batch_or_fewer);
    tcase_add_test(t, stops_when_asked_walking_or_waiting);
    tcase_add_test(t, steps_its_side_job_while_it_waits);
    tcase_add_test(t, the_arrays_do_not_move_while_shared);
    suite_add_tcase(s, t);
    return s;
}
