// alloc_hook.cpp - the replaced global operator new (see alloc_hook.hpp).
// Replacing operator new and delete is allowed to any program ([new.delete]).
// The nothrow forms are replaced too, as libstdc++ defines them (the
// throwing form, nullptr for std::bad_alloc): AddressSanitizer brings its
// own nothrow new, whose blocks this file's delete would free as malloc's
// (std::stable_sort's temporary buffer: an alloc-dealloc mismatch).
#include "alloc_hook.hpp"

#include <cstdlib>
#include <new>

namespace {

bool armed = false;
long counted = 0;
long fail_at = 0;

void* allocate(std::size_t size) {
    if (armed && ++counted == fail_at) throw std::bad_alloc();
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

}  // namespace

namespace alloc_hook {

void arm(long k) {
    armed = true;
    counted = 0;
    fail_at = k;
}

long disarm() {
    armed = false;
    return counted;
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
