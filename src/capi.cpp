// capi.cpp - the C interface: the only extern "C" code in the library.
//
// Each entry point checks its arguments, runs the core under one exception
// guard (std::bad_alloc -> PDS_ENOMEM, anything else -> PDS_EINTERNAL and the
// handle turns read-only), and records a message in a fixed buffer inside the
// handle, so reporting an error can never itself fail. No exception crosses
// this file's functions: they are all noexcept.
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#if !defined(__wasi__)
#include <thread>
#endif

#include "capi_handle.hpp"

namespace {

#define PDS_STR2(x) #x
#define PDS_STR(x) PDS_STR2(x)
constexpr const char kVersionString[] =
    PDS_STR(PDS_VERSION_MAJOR) "." PDS_STR(PDS_VERSION_MINOR) "." PDS_STR(PDS_VERSION_PATCH);

// The most threads pds_set_threads takes: far above any core count a run
// could use, low enough that a wrapped negative number is refused.
constexpr unsigned kMaxThreads = 1024;

// What pds_set_threads(s, 0) means: one thread per online core.
unsigned online_cores() {
#if defined(__wasi__)
    return 1;  // wasm32-wasi has no threads
#else
    const unsigned n = std::thread::hardware_concurrency();  // 0: cannot tell
    return n == 0 ? 1 : n < kMaxThreads ? n : kMaxThreads;
#endif
}

}  // namespace

using namespace pds_capi;  // NOLINT: the shared helpers of every entry point

extern "C" {

PDS_API int pds_create(pds_sampler** out, double radius, uint64_t seed) PDS_NOEXCEPT {
    if (out == nullptr) return PDS_EINVAL;
    *out = nullptr;
    if (!std::isfinite(radius) || radius <= 0.0) return PDS_EINVAL;
    // The radius is judged with the domain when both are first used (sampler.hpp).
    try {
        *out = new pds_sampler(std::make_unique<pds::Sampler>(radius, seed));
        return 0;
    } catch (...) {
        return PDS_ENOMEM;
    }
}

PDS_API void pds_destroy(pds_sampler* s) PDS_NOEXCEPT { delete s; }

PDS_API int pds_set_domain(pds_sampler* s, double x0, double y0, double x1, double y1) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_set_domain");
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
        return fail(s, PDS_EINVAL, "pds_set_domain: coordinates must be finite");
    if (!(x0 < x1) || !(y0 < y1))
        return fail(s, PDS_EINVAL,
                    "pds_set_domain: the rectangle [%g,%g]x[%g,%g] is empty or inverted "
                    "(need x0 < x1 and y0 < y1)",
                    x0, x1, y0, y1);
    if (s->core->count() != 0)
        return fail(s, PDS_ESTATE, "pds_set_domain: points exist already (%zu); set the domain "
                    "before the first point", s->core->count());
    const pds::Box box{x0, y0, x1, y1};
    return guarded(s, "pds_set_domain", [&] {
        s->core->set_domain(box);
        return 0;
    });
}

PDS_API int pds_set_periodic(pds_sampler* s, int periodic) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_set_periodic");
    if (s->core->count() != 0)
        return fail(s, PDS_ESTATE, "pds_set_periodic: points exist already (%zu); choose the "
                    "domain's kind before the first point", s->core->count());
    if (periodic != 0 && s->core->has_shape())
        return fail(s, PDS_EINVAL, "pds_set_periodic: a polygon or mask domain (pds_set_polygon, pds_set_mask) "
                    "is not periodic");
    if (periodic != 0 && s->core->has_fixed())
        return fail(s, PDS_EINVAL, "pds_set_periodic: fixed points (pds_set_fixed) are not supported on a "
                    "periodic domain");
    return guarded(s, "pds_set_periodic", [&] {
        s->core->set_periodic(periodic != 0);
        return 0;
    });
}

PDS_API int pds_set_count(pds_sampler* s, size_t n) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_set_count");
    if (n == 0) return fail(s, PDS_EINVAL, "pds_set_count: the count must be at least 1");
    if (s->core->count() != 0)
        return fail(s, PDS_ESTATE, "pds_set_count: points exist already (%zu); set the count "
                    "before the first point", s->core->count());
    if (s->core->has_field())
        return fail(s, PDS_EINVAL, "pds_set_count: a count is not supported with a radius field");
    return guarded(s, "pds_set_count", [&] {
        s->core->set_count(n);
        return 0;
    });
}

PDS_API int pds_set_radius_map(pds_sampler* s, size_t w, size_t h, const double* r) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (r == nullptr) return fail(s, PDS_EINVAL, "pds_set_radius_map: the map is NULL");
    if (w == 0 || h == 0) return fail(s, PDS_EINVAL, "pds_set_radius_map: the map is empty (%zu x %zu)", w, h);
    if (w > SIZE_MAX / sizeof(double) / h)
        return fail(s, PDS_EINVAL, "pds_set_radius_map: a %zu x %zu map does not fit in memory", w, h);
    if (const int rc = refuse_field(s, "pds_set_radius_map")) return rc;
    for (std::size_t k = 0; k < w * h; ++k)
        if (!std::isfinite(r[k]) || r[k] <= 0.0)
            return fail(s, PDS_EINVAL,
                        "pds_set_radius_map: the radius at row %zu, column %zu is %g; radii must be finite "
                        "and > 0",
                        k / w, k % w, r[k]);
    return guarded(s, "pds_set_radius_map", [&] {
        s->core->set_field(pds::RadiusField::map(w, h, r));
        return 0;
    });
}

PDS_API int pds_set_radius_fn(pds_sampler* s, pds_radius_fn fn, void* user, double rmin, double rmax) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (fn == nullptr) return fail(s, PDS_EINVAL, "pds_set_radius_fn: the function is NULL");
    if (!std::isfinite(rmin) || !std::isfinite(rmax) || !(rmin > 0.0) || !(rmin <= rmax))
        return fail(s, PDS_EINVAL,
                    "pds_set_radius_fn: the bounds [%g, %g] must be finite with 0 < rmin <= rmax", rmin, rmax);
    if (const int rc = refuse_field(s, "pds_set_radius_fn")) return rc;
    return guarded(s, "pds_set_radius_fn", [&] {
        s->core->set_field(pds::RadiusField::function(radius_trampoline, s, rmin, rmax));
        s->radius_fn = fn;
        s->radius_user = user;
        return 0;
    });
}

PDS_API size_t pds_radii(const pds_sampler* s, size_t first, size_t count, double* r) PDS_NOEXCEPT {
    if (s == nullptr || r == nullptr) return 0;
    return s->core->copy_radii(first, count, r);
}

PDS_API int pds_set_progress(pds_sampler* s, pds_progress_fn fn, void* user) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (s->in_callback != nullptr) return refuse_broken(s, "pds_set_progress");
    if (fn == nullptr && user != nullptr)
        return fail(s, PDS_EINVAL, "pds_set_progress: user data given without a function");
    s->progress = fn;
    s->progress_user = user;
    pds::ProgressHook hook;
    if (fn != nullptr) hook = pds::ProgressHook{progress_trampoline, s};
    s->core->set_progress(hook);
    return 0;
}

PDS_API int pds_set_threads(pds_sampler* s, unsigned n) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_set_threads");
    if (n > kMaxThreads)
        return fail(s, PDS_EINVAL, "pds_set_threads: %u threads asked for; the most is %u (0 means one "
                    "per online core)", n, kMaxThreads);
    // The first call selects the parallel opening, so it must come before
    // the first point; then no points depend on n, which may change at any time.
    if (!s->core->parallel() && s->core->count() != 0)
        return fail(s, PDS_ESTATE, "pds_set_threads: points exist already (%zu) from the single-thread "
                    "process; call it before the first point to run with threads", s->core->count());
    const unsigned resolved = n == 0 ? online_cores() : n;
    return guarded(s, "pds_set_threads", [&] {
        s->core->set_threads(resolved);
        return 0;
    });
}

PDS_API unsigned pds_threads(const pds_sampler* s) PDS_NOEXCEPT { return s ? s->core->threads() : 0; }

PDS_API int pds_step(pds_sampler* s) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_step");
    return guarded(s, "pds_step", [&] { return s->core->step() ? PDS_MORE : PDS_DONE; });
}

PDS_API int pds_run(pds_sampler* s, size_t max_new, size_t* added) PDS_NOEXCEPT {
    if (added != nullptr) *added = 0;
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_run");
    const std::size_t before = s->core->count();
    const int rc = guarded(s, "pds_run", [&] {
        std::size_t n = 0;
        switch (s->core->run(max_new, &n)) {
            case pds::Sampler::RunEnd::complete:
                return PDS_DONE;
            case pds::Sampler::RunEnd::limit:
                return PDS_MORE;
            case pds::Sampler::RunEnd::canceled:
                break;
        }
        return fail(s, PDS_ECANCELED, "pds_run: canceled by the progress callback after %zu points",
                    s->core->count());
    });
    if (added != nullptr) *added = s->core->count() - before;
    return rc;
}

PDS_API int pds_refine(pds_sampler* s, double radius) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (refuses_changes(s)) return refuse_broken(s, "pds_refine");
    if (!std::isfinite(radius) || radius <= 0.0)
        return fail(s, PDS_EINVAL, "pds_refine: the radius must be finite and > 0 (got %g)", radius);
    const double current = s->core->radius();
    if (radius > current)
        return fail(s, PDS_EINVAL, "pds_refine: the radius %g is larger than the current %g",
                    radius, current);
    if (s->core->count_target() != 0)
        return fail(s, PDS_ESTATE, "pds_refine: the sampler chooses the radius in count mode "
                    "(pds_set_count)");
    if (radius == current) return 0;
    return guarded(s, "pds_refine", [&] {
        s->core->refine(radius);
        return 0;
    });
}

PDS_API size_t pds_count(const pds_sampler* s) PDS_NOEXCEPT { return s ? s->core->count() : 0; }

PDS_API size_t pds_points(const pds_sampler* s, size_t first, size_t count, double* xy) PDS_NOEXCEPT {
    if (s == nullptr || xy == nullptr) return 0;
    return s->core->copy_points(first, count, xy);
}

PDS_API double pds_radius(const pds_sampler* s) PDS_NOEXCEPT {
    return s ? s->core->radius() : std::numeric_limits<double>::quiet_NaN();
}

PDS_API double pds_free_area(const pds_sampler* s) PDS_NOEXCEPT {
    if (s == nullptr) return std::numeric_limits<double>::quiet_NaN();
    // Early in a run this builds a triangulation, which may run out of memory.
    try {
        return s->core->free_area();
    } catch (...) {
        return std::numeric_limits<double>::quiet_NaN();
    }
}

PDS_API int pds_verify(pds_sampler* s) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    return guarded(
        s, "pds_verify",
        [&] {
            const pds::VerifyReport rep = s->core->verify();
            if (!rep.valid)
                return fail(s, PDS_EINTERNAL, "pds_verify: check failed (please report): %s",
                            rep.failure.c_str());
            return rep.maximal ? PDS_DONE : PDS_MORE;
        },
        false);
}

PDS_API const char* pds_strerror(int code) PDS_NOEXCEPT {
    switch (code) {
        case 0:
            return "success";
        case PDS_EINVAL:
            return "invalid argument";
        case PDS_ENOMEM:
            return "out of memory";
        case PDS_ESTATE:
            return "operation not allowed in the sampler's current state";
        case PDS_ERANGE:
            return "radius too small for the domain";
        case PDS_EINTERNAL:
            return "internal error";
        case PDS_ECANCELED:
            return "canceled by the progress callback";
        default:
            return code > 0 ? "not an error (a positive status)" : "unknown error code";
    }
}

PDS_API const char* pds_errmsg(const pds_sampler* s) PDS_NOEXCEPT {
    return s ? s->message : "invalid sampler handle (NULL)";
}

PDS_API unsigned pds_version_number(void) PDS_NOEXCEPT { return PDS_VERSION_NUMBER; }

PDS_API const char* pds_version_string(void) PDS_NOEXCEPT { return kVersionString; }

}  // extern "C"
