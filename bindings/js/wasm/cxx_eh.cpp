// cxx_eh.cpp - the C++ exception runtime for the WebAssembly build.
//
// Debian's wasm32 libc++abi is built without exceptions: it has no
// __cxa_throw, no personality routine and no libunwind. The library throws
// and catches internally (std::bad_alloc, LimitError, FieldError, all caught
// in capi.cpp), so this file supplies the small part of the Itanium C++ ABI
// that clang's -fwasm-exceptions code calls. The engine does the unwinding
// (the Wasm exception-handling proposal: Node >= 18, Chromium >= 95, Firefox
// >= 100, Safari >= 15.2); what is left is allocating the exception, telling
// a catch clause whether it matches (the personality, reading the LSDA that
// clang emits) and the catch bookkeeping. Type matching is libc++abi's own
// (__shim_type_info::can_catch), so derived-to-base catches work as natively.
// One thread: the module is never shared between threads.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <typeinfo>

namespace __cxxabiv1 {
// libc++abi's private base of every type_info it defines (private_typeinfo.h);
// declared here with the same virtual functions in the same order, so the
// call below goes through the vtable slot of libc++abi's can_catch.
class __shim_type_info : public std::type_info {
public:
    ~__shim_type_info() override;
    virtual void noop1() const;
    virtual void noop2() const;
    virtual bool can_catch(const __shim_type_info* thrown_type, void*& adjusted) const = 0;
};
}  // namespace __cxxabiv1

using Shim = __cxxabiv1::__shim_type_info;

extern "C" {

struct _Unwind_Exception {
    uint64_t exception_class;
    void (*cleanup)(int, _Unwind_Exception*);
    uintptr_t private_1, private_2;
};

// Shared with the code clang generates (WasmEHPrepare): before a typed catch
// clause it stores the landing pad's index and its function's LSDA here and
// calls _Unwind_CallPersonality, then compares `selector` with the clauses'
// type indices.
struct LandingPadContext {
    uintptr_t lpad_index;
    uintptr_t lsda;
    uintptr_t selector;
};
LandingPadContext __wasm_lpad_context;

}  // extern "C"

namespace {

struct Header {
    Header* next_caught;
    int handlers;  // catch clauses running on it; negative once rethrown
    const std::type_info* type;
    // Destructors return `this` on WebAssembly (clang's ABI there).
    void* (*destroy)(void*);
    void* adjusted;  // the object as the matching catch clause sees it
    _Unwind_Exception unwind;
};

// malloc's alignment is 16 on wasm32; the object follows the header, padded
// to that alignment so any thrown type fits.
constexpr std::size_t kAlign = 16;
constexpr std::size_t kHeaderSize = (sizeof(Header) + kAlign - 1) / kAlign * kAlign;

Header* caught = nullptr;  // the innermost exception being handled first
unsigned uncaught = 0;

void* object_of(Header* h) { return reinterpret_cast<char*>(h) + kHeaderSize; }
Header* header_of_object(void* obj) {
    return reinterpret_cast<Header*>(static_cast<char*>(obj) - kHeaderSize);
}
Header* header_of_unwind(void* u) {
    return reinterpret_cast<Header*>(static_cast<char*>(u) - offsetof(Header, unwind));
}

// A LEB128 number's 7-bit groups, low first; *last is its final byte and
// *bits the bits read (the signed form extends the sign from there).
uintptr_t read_leb_groups(const uint8_t*& p, uint8_t* last, unsigned* bits) {
    uintptr_t v = 0;
    unsigned shift = 0;
    uint8_t b;
    do {
        b = *p++;
        v |= uintptr_t(b & 0x7f) << shift;
        shift += 7;
    } while (b & 0x80);
    *last = b;
    *bits = shift;
    return v;
}

uintptr_t read_uleb(const uint8_t*& p) {
    uint8_t last;
    unsigned bits;
    return read_leb_groups(p, &last, &bits);
}

intptr_t read_sleb(const uint8_t*& p) {
    uint8_t last;
    unsigned bits;
    uintptr_t v = read_leb_groups(p, &last, &bits);
    if ((last & 0x40) && bits < 8 * sizeof(v)) v |= ~uintptr_t(0) << bits;
    return static_cast<intptr_t>(v);
}

// The type table holds 4-byte absolute addresses on wasm32 (DW_EH_PE_absptr,
// udata4 or sdata4, possibly indirect); nothing else is emitted for it.
const Shim* type_at(const uint8_t* class_info, uint8_t encoding, intptr_t index) {
    uint32_t addr;
    std::memcpy(&addr, class_info - index * 4, 4);
    if (addr != 0 && (encoding & 0x80)) std::memcpy(&addr, reinterpret_cast<void*>(addr), 4);
    return reinterpret_cast<const Shim*>(addr);
}

// Which clause of the landing pad catches h: its type index (> 0), or 0.
uintptr_t select_clause(Header* h) {
    const uint8_t* p = reinterpret_cast<const uint8_t*>(__wasm_lpad_context.lsda);
    if (p == nullptr) return 0;
    if (*p++ != 0xff) read_uleb(p);  // @LPStart: unused on wasm
    const uint8_t ttype_encoding = *p++;
    const uint8_t* class_info = nullptr;
    if (ttype_encoding != 0xff) {
        const uintptr_t offset = read_uleb(p);
        class_info = p + offset;
    }
    ++p;  // call-site encoding: uleb128
    const uintptr_t table_length = read_uleb(p);
    const uint8_t* action_table = p + table_length;
    // Call sites are indexed by landing pad: (pad index, action + 1) each.
    uintptr_t action = 0;
    for (uintptr_t i = 0; i <= __wasm_lpad_context.lpad_index; ++i) {
        if (p >= action_table) return 0;
        read_uleb(p);
        action = read_uleb(p);
    }
    if (action == 0) return 0;  // a cleanup only
    const uint8_t* a = action_table + (action - 1);
    for (;;) {
        const intptr_t index = read_sleb(a);
        const uint8_t* next_at = a;
        const intptr_t next = read_sleb(a);
        if (index > 0 && class_info != nullptr) {
            const Shim* catch_type = type_at(class_info, ttype_encoding, index);
            void* adjusted = object_of(h);
            if (catch_type == nullptr ||
                catch_type->can_catch(static_cast<const Shim*>(h->type), adjusted)) {
                h->adjusted = adjusted;
                return static_cast<uintptr_t>(index);
            }
        }
        // index == 0: a cleanup; index < 0: a dynamic exception specification
        // (not in C++17 code): neither selects a clause.
        if (next == 0) return 0;
        a = next_at + next;
    }
}

[[noreturn]] void raise(Header* h) { __builtin_wasm_throw(0, &h->unwind); }

}  // namespace

extern "C" {

int _Unwind_CallPersonality(void* unwind) {
    __wasm_lpad_context.selector = select_clause(header_of_unwind(unwind));
    return __wasm_lpad_context.selector != 0 ? 6 /* _URC_HANDLER_FOUND */
                                              : 8 /* _URC_CONTINUE_UNWIND */;
}

void* __cxa_allocate_exception(std::size_t size) noexcept {
    void* raw = std::malloc(kHeaderSize + size);
    if (raw == nullptr) std::terminate();
    std::memset(raw, 0, kHeaderSize);
    return object_of(static_cast<Header*>(raw));
}

void __cxa_free_exception(void* obj) noexcept { std::free(header_of_object(obj)); }

[[noreturn]] void __cxa_throw(void* obj, std::type_info* type, void* (*destroy)(void*)) {
    Header* h = header_of_object(obj);
    h->type = type;
    h->destroy = destroy;
    h->adjusted = obj;
    h->unwind.exception_class = 0x434C4E47432B2B00ULL;  // "CLNGC++\0"
    ++uncaught;
    raise(h);
}

void* __cxa_get_exception_ptr(void* unwind) noexcept { return header_of_unwind(unwind)->adjusted; }

void* __cxa_begin_catch(void* unwind) noexcept {
    Header* h = header_of_unwind(unwind);
    h->handlers = (h->handlers < 0 ? -h->handlers : h->handlers) + 1;
    if (h != caught) {
        h->next_caught = caught;
        caught = h;
    }
    if (uncaught > 0) --uncaught;
    return h->adjusted;
}

void __cxa_end_catch() {
    Header* h = caught;
    if (h == nullptr) return;
    if (h->handlers < 0) {  // rethrown: it lives on, outside this handler
        if (++h->handlers == 0) caught = h->next_caught;
        return;
    }
    if (--h->handlers == 0) {
        caught = h->next_caught;
        if (h->destroy != nullptr) h->destroy(object_of(h));
        std::free(h);
    }
}

[[noreturn]] void __cxa_rethrow() {
    Header* h = caught;
    if (h == nullptr) std::terminate();
    h->handlers = -h->handlers;
    ++uncaught;
    raise(h);
}

}  // extern "C"

namespace std {
int uncaught_exceptions() noexcept { return static_cast<int>(uncaught); }
bool uncaught_exception() noexcept { return uncaught > 0; }
}  // namespace std

// libc++'s operator new, built without exceptions, returns null when memory
// runs out; the library's promise (PDS_ENOMEM, nothing changed) needs the
// std::bad_alloc the standard requires, so the throwing forms are replaced.
void* operator new(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (p == nullptr) throw std::bad_alloc();
    return p;
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, std::align_val_t align) {
    const std::size_t a = static_cast<std::size_t>(align);
    void* p = std::aligned_alloc(a, (size + a - 1) / a * a);
    if (p == nullptr) throw std::bad_alloc();
    return p;
}
void* operator new[](std::size_t size, std::align_val_t align) { return operator new(size, align); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
