// capi_handle.hpp - the C handle and the helpers every C entry point shares
// (capi.cpp, capi_domains.cpp): the message buffer, the one exception guard,
// and the rules that refuse changes. Private to those files.
#ifndef PDS_CAPI_HANDLE_HPP
#define PDS_CAPI_HANDLE_HPP

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

#include "poissondisk.h"
#include "domain/polygon_rings.hpp"
#include "sampler/sampler.hpp"

struct pds_sampler {
    explicit pds_sampler(std::unique_ptr<pds::Sampler> c) : core(std::move(c)) {}
    std::unique_ptr<pds::Sampler> core;
    bool broken = false;  // an internal invariant failed: refuse changes
    pds_progress_fn progress = nullptr;
    void* progress_user = nullptr;
    const char* in_callback = nullptr;  // the user callback running, by name: refuse changes
    pds_radius_fn radius_fn = nullptr;
    void* radius_user = nullptr;
    char message[256] = "no error";
};

namespace pds_capi {


__attribute__((format(printf, 3, 4))) inline int fail(pds_sampler* s, int code, const char* fmt, ...) {
    if (s != nullptr) {
        va_list args;
        va_start(args, fmt);
        std::vsnprintf(s->message, sizeof s->message, fmt, args);
        va_end(args);
    }
    return code;
}

// The radius a limit was judged on, as the subject of its message.
inline const char* judged_text(pds::JudgedRadius judged) {
    switch (judged) {
        case pds::JudgedRadius::field_smallest:
            return "the field's smallest radius";
        case pds::JudgedRadius::field_largest:
            return "the field's largest radius";
        case pds::JudgedRadius::count_lowest:
            return "the lowest radius the count may need";
        case pds::JudgedRadius::count_covered:
            return "the radius count mode lowered to while the fixed points' clearances covered the domain";
        case pds::JudgedRadius::radius:
            break;
    }
    return "the radius";
}

// What is wrong; after the subject judged_text() names, where there is one.
inline const char* limit_text(pds::Limit limit) {
    switch (limit) {
        case pds::Limit::too_many_points:
            return "is too small for the domain: the pattern would exceed the "
                   "supported number of points";
        case pds::Limit::radius_below_precision:
            return "is too small relative to the domain's coordinates for double "
                   "precision (it must be at least 2^-26 of their magnitude)";
        case pds::Limit::coordinates_too_small:
            return "the domain's coordinates are too close to zero (all below 2^-900, or a nonzero "
                   "one below 2^-900 times the largest: use 0 there)";
        case pds::Limit::radius_exceeds_period:
            return "is larger than half the shorter period of the periodic domain";
        case pds::Limit::field_periods_too_unequal:
            return "a radius field on a periodic domain needs the longer side at most 16 times the "
                   "shorter";
        case pds::Limit::periods_too_unequal:
            return "the periodic domain's longer side is more than 1024 times its shorter side";
        case pds::Limit::ok:
            break;
    }
    return "no limit";
}

// Runs f() on s's core; maps exceptions to codes. A failure inside a call
// that changes the pattern may have left it half-updated, so the handle turns
// read-only; a read-only call (`changes` false) leaves it usable.
template <class F>
int guarded(pds_sampler* s, const char* what, F&& f, bool changes = true) PDS_NOEXCEPT {
    try {
        return f();
    } catch (const std::bad_alloc&) {
        return fail(s, PDS_ENOMEM, "%s: out of memory", what);
    } catch (const pds::DomainError& e) {
        // A domain refused as it was read: nothing changed.
        return fail(s, PDS_EINVAL, "%s: %s", what, e.what());
    } catch (const pds::FieldError& e) {
        // Thrown before the point was added: the sampler is as it was.
        return fail(s, PDS_EINVAL,
                    "%s: the radius function returned %g at (%g, %g), outside its declared bounds or not "
                    "finite; the points so far are kept",
                    what, e.value(), e.x(), e.y());
    } catch (const pds::LimitError& e) {
        // Thrown before anything changed. A limit on a radius names it.
        const pds::Limit l = e.limit();
        if (l == pds::Limit::too_many_points || l == pds::Limit::radius_below_precision ||
            l == pds::Limit::radius_exceeds_period)
            return fail(s, PDS_ERANGE, "%s: %s %s (%g)", what, judged_text(e.judged()), limit_text(l), e.radius());
        return fail(s, PDS_ERANGE, "%s: %s (radius %g)", what, limit_text(l), e.radius());
    } catch (const std::exception& e) {
        if (changes) s->broken = true;
        return fail(s, PDS_EINTERNAL, "%s: internal error (please report): %s", what, e.what());
    } catch (...) {
        if (changes) s->broken = true;
        return fail(s, PDS_EINTERNAL, "%s: internal error (please report)", what);
    }
}

inline int refuse_broken(pds_sampler* s, const char* what) {
    if (s->in_callback != nullptr)
        return fail(s, PDS_ESTATE, "%s: not allowed from inside %s", what, s->in_callback);
    return fail(s, PDS_ESTATE, "%s: the sampler is read-only after an internal error", what);
}

// Calls that change the sampler are refused after an internal error and
// from inside a user callback (the progress callback, the radius function).
inline bool refuses_changes(const pds_sampler* s) { return s->broken || s->in_callback != nullptr; }

// The sampler calls this; it marks the handle while the user's function runs.
inline int progress_trampoline(void* handle, std::size_t count, double done) {
    pds_sampler* s = static_cast<pds_sampler*>(handle);
    s->in_callback = "the progress callback";
    const int stop = s->progress(s->progress_user, count, done);
    s->in_callback = nullptr;
    return stop;
}

inline double radius_trampoline(void* handle, double x, double y) {
    pds_sampler* s = static_cast<pds_sampler*>(handle);
    // The radius function may run inside the progress callback's run, never
    // inside the callback itself; either way the outer name is restored.
    const char* outer = s->in_callback;
    s->in_callback = "the radius function";
    const double r = s->radius_fn(s->radius_user, x, y);
    s->in_callback = outer;
    return r;
}

// What a field needs of the sampler's state; 0 when it may be set.
inline int refuse_field(pds_sampler* s, const char* what) {
    if (refuses_changes(s)) return refuse_broken(s, what);
    if (s->core->count() != 0)
        return fail(s, PDS_ESTATE, "%s: points exist already (%zu); set the field before the first point",
                    what, s->core->count());
    if (s->core->count_target() != 0)
        return fail(s, PDS_EINVAL, "%s: a radius field is not supported with a count (pds_set_count)", what);
    return 0;
}

}  // namespace pds_capi

#endif
