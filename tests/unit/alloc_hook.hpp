// alloc_hook.hpp - a test-only failing operator new for the unit suites.
//
// The unit binary replaces the global operator new (alloc_hook.cpp): while
// armed it counts C++ allocations and throws std::bad_alloc at the k-th,
// once. Under Valgrind, whose own operator new wins, in_effect() is false.
// The library's malloc-based buffers (the dart grid, the tree) are not
// counted here; the public-API test tests/alloc covers every allocation.
#ifndef PDS_TEST_ALLOC_HOOK_HPP
#define PDS_TEST_ALLOC_HOOK_HPP

#include <vector>

namespace alloc_hook {

// Counts from now on; the k-th allocation (1-based) throws. k = 0: never.
void arm(long fail_at);
// Stops counting; returns how many allocations were counted.
long disarm();
// False when another replacement took over operator new (Valgrind does):
// then nothing can be counted or failed here. Inline, so the probe's
// allocation is made from the caller's code, as the library's are.
inline bool in_effect() {
    arm(0);
    std::vector<int> probe(1);
    probe.clear();
    probe.shrink_to_fit();
    return disarm() == 1;
}

}  // namespace alloc_hook

#endif
