// alloc_hook.cpp - the replaced global operator new (see alloc_hook.hpp).
// Replacing operator new and delete is allowed to any program ([new.delete]).
// The nothrow forms are replaced too, as libstdc++ defines them (the
// throwing form, nullptr for std::bad_alloc): AddressSanitizer brings its
// own nothrow new, whose blocks this file's delete would free as malloc's
// (std::stable_sort's temporary buffer: an alloc-dealloc mismatch).
#include "alloc_hook.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

// Atomic: a threaded run's workers allocate too (their epochs' lists).
std::atomic<bool> armed{false};
std::atomic<long> counted{0};
std::atomic<long> fail_at{0};

void* allocate(std::size_t size) {
    if (armed.load(std::memory_order_relaxed) &&
        counted.fetch_add(1, std::memory_order_relaxed) + 1 == fail_at.load(std::memory_order_relaxed))
        throw std::bad_alloc();
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

}  // namespace

namespace alloc_hook {

void arm(long k) {
    counted.store(0);
    fail_at.store(k);
    armed.store(true);
}

long disarm() {
    armed.store(false);
    return counted.load();
}


}  // namespace alloc_hook

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
