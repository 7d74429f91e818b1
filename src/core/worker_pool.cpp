// worker_pool.cpp - see worker_pool.hpp.
#include "core/worker_pool.hpp"

#if !defined(__wasi__)

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace pds {

namespace {

// About 50 microseconds of waiting awake (a pause takes 10 to 150 cycles;
// 23 ns on the machines of docs/performance.md).
constexpr unsigned kSpins = 2048;

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#elif defined(__aarch64__) || defined(__arm__)
    __asm__ __volatile__("yield");
#else
    std::atomic_signal_fence(std::memory_order_seq_cst);  // a pause the compiler keeps
#endif
}

// Waits awake until done() holds, up to kSpins checks; says whether it did.
template <class Done>
bool spin_until(const Done& done) {
    for (unsigned i = 0; i < kSpins; ++i) {
        if (done()) return true;
        relax();
    }
    return done();
}

}  // namespace

WorkerPool::WorkerPool(unsigned wanted) {
    const unsigned helpers = wanted > 1 ? wanted - 1 : 0;
    try {
        // Sized before any thread starts: a helper writes only its own slot.
        helper_errors_.resize(helpers);
        threads_.reserve(helpers);
        for (unsigned i = 1; i <= helpers; ++i) threads_.emplace_back([this, i] { serve(i); });
    } catch (...) {
        // std::system_error (no thread) or std::bad_alloc: run with the
        // threads started so far (none if the vectors could not grow).
    }
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        closing_.store(true, std::memory_order_release);
    }
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::serve(unsigned index) {
    std::size_t seen = 0;
    const auto called = [&] {
        return closing_.load(std::memory_order_acquire) || generation_.load(std::memory_order_acquire) != seen;
    };
    for (;;) {
        void (*call)(const void*, unsigned);
        const void* task;
        spin_until(called);
        {
            // Asleep if the spin ended first; either way call_ and task_
            // are read under the lock they were written under.
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, called);
            if (closing_.load(std::memory_order_relaxed)) return;
            seen = generation_.load(std::memory_order_relaxed);
            call = call_;
            task = task_;
        }
        try {
            call(task, index);
        } catch (...) {
            helper_errors_[index - 1] = std::current_exception();
        }
        // The last helper out wakes the caller if it sleeps: under the lock,
        // so the caller cannot check running_ and then miss the notice.
        if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            std::lock_guard<std::mutex> lock(mutex_);
            done_.notify_one();
        }
    }
}

void WorkerPool::run_erased(void (*call)(const void*, unsigned), const void* task) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        call_ = call;
        task_ = task;
        running_.store(static_cast<unsigned>(threads_.size()), std::memory_order_relaxed);
        for (std::exception_ptr& e : helper_errors_) e = nullptr;
        generation_.fetch_add(1, std::memory_order_release);
    }
    start_.notify_all();
    std::exception_ptr own;
    try {
        call(task, 0);
    } catch (...) {
        own = std::current_exception();
    }
    const auto finished = [&] { return running_.load(std::memory_order_acquire) == 0; };
    if (!spin_until(finished)) {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, finished);
    }
    if (own) std::rethrow_exception(own);
    for (const std::exception_ptr& e : helper_errors_)
        if (e) std::rethrow_exception(e);
}

}  // namespace pds

#endif
