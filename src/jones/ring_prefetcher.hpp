// ring_prefetcher.hpp - a helper thread that walks the mesh rings the next
// insertions of the free regions' points will read, a few batches ahead of
// the caller's thread, so that their cache misses are paid beside it.
//
// Why. With threads, the free regions' points are inserted on the caller's
// thread alone while the other cores wait (region_darts.hpp): a sixth of
// the run at 10^6 points on two cores. Each insertion reads the ring of the
// cell its dart was drawn in and the triangles just beyond it, far apart in
// memory. The caller prefetches a batch ahead, but a ring is walked link by
// link, each step a miss; a core that walks them ahead of it takes those
// misses off its path (docs/performance.md, 1.15.2).
//
// It changes nothing the run computes: it reads links and prefetches. It
// reads while the caller writes, so it sees each word old or new (relaxed
// loads and stores, core/relaxed.hpp), which at worst makes a prefetch
// useless; its walks are bounded. It owns the mesh's shared switch
// (Delaunay::set_shared): on from before its thread starts until after it
// is joined, so the caller's insertions are shared exactly while it runs.
// It reads the darts, which do not change during an epoch's insertions,
// and no container that could move: the run stops it (joins the thread)
// before the darts are drawn again and before anything may reallocate the
// mesh (JonesLoop::quiet_helper), and it never outlives the pds_run call
// that started it (Sampler::run). When the caller stops advancing it gives
// up rather than spin; when its thread cannot be started the insertions
// simply go without it.
//
// Between its walks, while it waits for the caller, it may do a side job
// in steps (the next epoch's scan of the active list, active_scan.hpp):
// work whose result does not depend on how far it got, since the caller
// finishes whatever it leaves once it is joined.
#ifndef PDS_RING_PREFETCHER_HPP
#define PDS_RING_PREFETCHER_HPP

#include <cstddef>
#if !defined(__wasi__)  // wasm32-wasi has no threads: no helper
#include <atomic>
#include <thread>
#endif

#include "jones/region_darts.hpp"
#include "mesh/delaunay.hpp"

namespace pds {

class RingPrefetcher {
public:
    // Work done a step at a time; step() returns false once it is done.
    class SideJob {
    public:
        virtual bool step() = 0;

    protected:
        ~SideJob() = default;
    };

    RingPrefetcher() = default;
    RingPrefetcher(const RingPrefetcher&) = delete;
    RingPrefetcher& operator=(const RingPrefetcher&) = delete;
#if defined(__wasi__)
    bool start(Delaunay&, const RegionDarts::Dart*, std::size_t, SideJob* = nullptr) { return false; }
    void reached(std::size_t) {}
    void stop() {}
    bool running() const { return false; }
#else
    ~RingPrefetcher() { stop(); }
    // Walks, ahead of the caller, the rings of darts[kMaxBatch .. n)'s
    // cells (the caller fetches its first batch itself), and steps `job`
    // (if any) while it waits; the mesh is shared until stop(). Never
    // throws; false, and the mesh not shared, when it did not start (too
    // few darts, or no thread).
    bool start(Delaunay& mesh, const RegionDarts::Dart* darts, std::size_t n, SideJob* job = nullptr) noexcept;
    // The caller is about to insert dart `next`.
    void reached(std::size_t next) { reached_.store(next, std::memory_order_relaxed); }
    // Ends the walk, joins the thread and unshares the mesh; nothing if
    // none runs.
    void stop() noexcept;
    bool running() const { return thread_.joinable(); }

private:
    void walk(const Delaunay& mesh, const RegionDarts::Dart* darts, std::size_t n, SideJob* job);

    std::thread thread_;
    Delaunay* mesh_ = nullptr;  // shared while the thread runs
    std::atomic<std::size_t> reached_{0};
    std::atomic<bool> stop_{false};
#endif
};

}  // namespace pds

#endif
