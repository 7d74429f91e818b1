// ring_prefetcher.cpp - the helper's walk ahead of the insertions
// (ring_prefetcher.hpp).
#include "jones/ring_prefetcher.hpp"

#if !defined(__wasi__)
#include <chrono>

#include "core/batch.hpp"

namespace pds {

bool RingPrefetcher::start(Delaunay& mesh, const RegionDarts::Dart* darts, std::size_t n, SideJob* job) noexcept {
    stop();
    if (n <= kMaxBatch) return false;  // the caller's own batch covers them
    reached_.store(0, std::memory_order_relaxed);
    stop_.store(false, std::memory_order_relaxed);
    mesh.set_shared(true);  // before the thread's first read
    try {
        thread_ = std::thread([this, &mesh, darts, n, job] { walk(mesh, darts, n, job); });
    } catch (...) {
        // No thread (std::system_error), or no memory for its state: the
        // insertions go on without the helper.
        mesh.set_shared(false);
        return false;
    }
    mesh_ = &mesh;
    return true;
}

void RingPrefetcher::stop() noexcept {
    if (!thread_.joinable()) return;
    stop_.store(true, std::memory_order_relaxed);
    thread_.join();
    mesh_->set_shared(false);  // no reader left
    mesh_ = nullptr;
}

void RingPrefetcher::walk(const Delaunay& mesh, const RegionDarts::Dart* darts, std::size_t n, SideJob* job) {
    // Up to kAhead darts ahead of the caller: far enough that the lines
    // arrive before it needs them, near enough that they are still cached
    // (at 10^6 points 256 and 1024 did no better).
    constexpr std::size_t kAhead = 8 * kMaxBatch;
    // Far enough ahead, it sleeps: a batch of insertions takes tens of
    // microseconds, its walk a few. Naps without progress before it gives
    // up: the caller is in a progress callback, or has stopped.
    constexpr auto kNap = std::chrono::microseconds(50);
    constexpr int kPatience = 1000;
    for (std::size_t first = kMaxBatch; first < n; first += kMaxBatch) {
        for (int waited = 0; first > reached_.load(std::memory_order_relaxed) + kAhead;) {
            if (waited == kPatience || stop_.load(std::memory_order_relaxed)) return;
            if (job && job->step()) continue;  // a step of the side job instead of a nap
            job = nullptr;
            std::this_thread::sleep_for(kNap);
            ++waited;
        }
        if (stop_.load(std::memory_order_relaxed)) return;
        VertexIndex sources[kMaxBatch];
        std::size_t m = 0;
        for (std::size_t i = first; i < n && m < kMaxBatch; ++i) sources[m++] = darts[i].source;
        mesh.prefetch_rings<true>(sources, m);
        mesh.prefetch_beyond_rings<true>(sources, m);
    }
    while (job && !stop_.load(std::memory_order_relaxed) && job->step()) {
    }
}

}  // namespace pds
#endif
