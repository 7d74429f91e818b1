// Cases for cxx_eh.cpp, the exception runtime of the WebAssembly build, run by
// test/eh.test.js: which clause catches what, rethrow, nested handlers,
// destructors during unwinding, and operator new throwing std::bad_alloc.
#include <cstdint>
#include <new>
#include <stdexcept>
#include <vector>

namespace {
struct Derived : std::runtime_error {
    using std::runtime_error::runtime_error;
};
int destroyed = 0;
struct Guard {
    ~Guard() { ++destroyed; }
};
}  // namespace

// k selects what is thrown; the result names the clause that caught it.
extern "C" __attribute__((export_name("catch_kind"))) int catch_kind(int k) {
    try {
        Guard g;
        if (k == 1) throw std::bad_alloc();
        if (k == 2) throw Derived("derived");
        if (k == 3) throw std::logic_error("logic");  // caught as its base std::exception
        if (k == 4) throw 42;
        return 0;
    } catch (const std::bad_alloc&) {
        return 1;
    } catch (const Derived& e) {
        return e.what()[0] == 'd' ? 2 : -2;
    } catch (const std::exception& e) {
        return e.what()[0] == 'l' ? 3 : -3;
    } catch (int v) {
        return v == 42 ? 4 : -4;
    } catch (...) {
        return 5;
    }
}

// A handler that rethrows, caught one level up; the Guard ran once.
extern "C" __attribute__((export_name("rethrow_outer"))) int rethrow_outer() {
    destroyed = 0;
    try {
        try {
            Guard g;
            throw Derived("again");
        } catch (...) {
            throw;
        }
    } catch (const std::runtime_error& e) {
        return destroyed == 1 && e.what()[0] == 'a' ? 1 : -1;
    }
}

// An exception thrown and caught inside a handler of another one.
extern "C" __attribute__((export_name("nested"))) int nested() {
    try {
        throw std::logic_error("outer");
    } catch (const std::logic_error& outer) {
        try {
            throw std::bad_alloc();
        } catch (const std::bad_alloc&) {
        }
        return outer.what()[0] == 'o' ? 1 : -1;
    }
}

// operator new of more than the 4 GiB address space can hold: std::bad_alloc.
extern "C" __attribute__((export_name("alloc_fails"))) int alloc_fails(uint32_t mib) {
    std::vector<char*> blocks;
    int result = 0;
    try {
        for (uint32_t i = 0; i < mib / 256 + 1; ++i) blocks.push_back(new char[256u << 20]);
    } catch (const std::bad_alloc&) {
        result = 1;
    }
    for (char* b : blocks) delete[] b;
    return result;
}

extern "C" __attribute__((export_name("destroyed_count"))) int destroyed_count() { return destroyed; }
