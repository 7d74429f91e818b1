// worker_pool.cpp - see worker_pool.hpp.
#include "core/worker_pool.hpp"

#if !defined(__wasi__)

namespace pds {

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
        closing_ = true;
    }
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void WorkerPool::serve(unsigned index) {
    std::size_t seen = 0;
    for (;;) {
        void (*call)(const void*, unsigned);
        const void* task;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, [&] { return closing_ || generation_ != seen; });
            if (closing_) return;
            seen = generation_;
            call = call_;
            task = task_;
        }
        try {
            call(task, index);
        } catch (...) {
            helper_errors_[index - 1] = std::current_exception();
        }
        std::lock_guard<std::mutex> lock(mutex_);
        if (--running_ == 0) done_.notify_one();
    }
}

void WorkerPool::run_erased(void (*call)(const void*, unsigned), const void* task) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        call_ = call;
        task_ = task;
        running_ = static_cast<unsigned>(threads_.size());
        ++generation_;
        for (std::exception_ptr& e : helper_errors_) e = nullptr;
    }
    start_.notify_all();
    std::exception_ptr own;
    try {
        call(task, 0);
    } catch (...) {
        own = std::current_exception();
    }
    {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [&] { return running_ == 0; });
        call_ = nullptr;
        task_ = nullptr;
    }
    if (own) std::rethrow_exception(own);
    for (const std::exception_ptr& e : helper_errors_)
        if (e) std::rethrow_exception(e);
}

}  // namespace pds

#endif
