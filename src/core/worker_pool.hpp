// worker_pool.hpp - a few threads that run one task each, side by side, and
// wait for the next: the parallel stages' workers.
//
// The pool starts its threads once and keeps them (an epoch of darts is a
// few milliseconds; starting threads for each would cost as much). A thread
// that cannot be started is not an error: the pool runs with the workers it
// has, and size() says how many. The callers split their work by size(), and
// their results never depend on it (the darts are tied to space, not to
// threads), so fewer threads only means less speed.
//
// Between runs a helper waits a few tens of microseconds awake before it
// sleeps, and so does the caller for the helpers' end: an epoch's steps
// follow one another closely, and waking a sleeping thread costs more (an
// interrupt to another core, tens of microseconds in a virtual machine).
//
// run(task) calls task(i) for i = 0 .. size()-1 at the same time, task(0) on
// the calling thread, and returns when all have returned. The tasks may wait
// for one another (the dart stage's bands do): every task runs on its own
// thread, so a wait always ends. An exception thrown by a task is rethrown by
// run() once all tasks are done (the first one, by worker index).
#ifndef PDS_WORKER_POOL_HPP
#define PDS_WORKER_POOL_HPP

#include <cstddef>
#include <exception>
#include <vector>
#if !defined(__wasi__)  // wasm32-wasi has no threads: the pool is its caller alone
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#endif

namespace pds {

class WorkerPool {
public:
    // Up to `wanted` workers (the caller's thread is one of them); never
    // throws: threads that cannot be started are done without.
#if defined(__wasi__)
    explicit WorkerPool(unsigned) {}
#else
    explicit WorkerPool(unsigned wanted);
    ~WorkerPool();
#endif
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // Never allocates: the task is called through a plain pointer (a
    // std::function could allocate, and an epoch must not fail half-way).
    template <class Task>
    void run(const Task& task) {
        run_erased([](const void* t, unsigned i) { (*static_cast<const Task*>(t))(i); }, &task);
    }

#if defined(__wasi__)
    unsigned size() const { return 1; }

private:
    void run_erased(void (*call)(const void*, unsigned), const void* task) { call(task, 0); }
};
#else
    unsigned size() const { return static_cast<unsigned>(threads_.size()) + 1; }

private:
    void run_erased(void (*call)(const void*, unsigned), const void* task);
    void serve(unsigned index);

    std::mutex mutex_;
    std::condition_variable start_, done_;
    void (*call_)(const void*, unsigned) = nullptr;
    const void* task_ = nullptr;
    // Written under mutex_, read awake without it as well.
    std::atomic<std::size_t> generation_{0};  // one per run()
    std::atomic<unsigned> running_{0};        // helpers still in the current run
    std::atomic<bool> closing_{false};
    std::vector<std::exception_ptr> helper_errors_;  // worker i's at i - 1
    std::vector<std::thread> threads_;
};
#endif

}  // namespace pds

#endif
