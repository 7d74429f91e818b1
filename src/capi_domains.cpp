// capi_domains.cpp - the C interface of the domains users have: a polygon,
// a mask, fixed points (poissondisk.h). The same rules as capi.cpp: every
// argument checked, one exception guard, a message naming what is wrong.
#include <cmath>
#include <cstdint>
#include <vector>

#include "capi_handle.hpp"

using namespace pds_capi;  // NOLINT: the shared helpers of every entry point

namespace {

// What a domain shape needs of the sampler's state; 0 when it may be set.
int refuse_shape(pds_sampler* s, const char* what) {
    if (refuses_changes(s)) return refuse_broken(s, what);
    if (s->core->count() != 0)
        return fail(s, PDS_ESTATE, "%s: points exist already (%zu); set the domain before the first point",
                    what, s->core->count());
    return 0;
}

int refuse_periodic(pds_sampler* s, const char* what) {
    if (s->core->frame().periodic())
        return fail(s, PDS_EINVAL, "%s: a polygon or mask domain is not periodic (pds_set_periodic is on)", what);
    return 0;
}

}  // namespace

extern "C" {

PDS_API int pds_set_polygon(pds_sampler* s, const double* xy, const size_t* ring_ends, size_t nrings) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (const int rc = refuse_shape(s, "pds_set_polygon")) return rc;
    if (nrings == 0) {
        return guarded(s, "pds_set_polygon", [&] {
            s->core->set_polygon(nullptr);
            return 0;
        });
    }
    if (xy == nullptr || ring_ends == nullptr)
        return fail(s, PDS_EINVAL, "pds_set_polygon: %s is NULL with %zu rings", xy ? "ring_ends" : "xy", nrings);
    if (const int rc = refuse_periodic(s, "pds_set_polygon")) return rc;
    return guarded(s, "pds_set_polygon", [&] {
        s->core->set_polygon(xy, ring_ends, nrings);
        return 0;
    });
}

PDS_API int pds_set_mask(pds_sampler* s, size_t w, size_t h, const unsigned char* inside) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (const int rc = refuse_shape(s, "pds_set_mask")) return rc;
    if (w == 0 || h == 0) {
        return guarded(s, "pds_set_mask", [&] {
            s->core->set_mask(0, 0, nullptr);
            return 0;
        });
    }
    if (inside == nullptr) return fail(s, PDS_EINVAL, "pds_set_mask: the mask is NULL (%zu x %zu)", w, h);
    if (h > (SIZE_MAX - 1) / 4 || w > (SIZE_MAX - 1) / 4 / (h + 1))
        return fail(s, PDS_EINVAL, "pds_set_mask: a %zu x %zu mask does not fit in memory", w, h);
    if (const int rc = refuse_periodic(s, "pds_set_mask")) return rc;
    return guarded(s, "pds_set_mask", [&] {
        s->core->set_mask(w, h, inside);
        return 0;
    });
}

PDS_API int pds_set_fixed(pds_sampler* s, const double* xy, const double* clearance, size_t n) PDS_NOEXCEPT {
    if (s == nullptr) return PDS_EINVAL;
    if (const int rc = refuse_shape(s, "pds_set_fixed")) return rc;
    if (n != 0 && xy == nullptr) return fail(s, PDS_EINVAL, "pds_set_fixed: xy is NULL with %zu points", n);
    if (n != 0 && s->core->frame().periodic())
        return fail(s, PDS_EINVAL, "pds_set_fixed: fixed points are not supported on a periodic domain");
    if (n > SIZE_MAX / 2 / sizeof(double))
        return fail(s, PDS_EINVAL, "pds_set_fixed: %zu points do not fit in memory", n);
    for (std::size_t k = 0; k < n; ++k) {
        if (!std::isfinite(xy[2 * k]) || !std::isfinite(xy[2 * k + 1]))
            return fail(s, PDS_EINVAL, "pds_set_fixed: point %zu: a coordinate is not finite", k);
        if (clearance != nullptr && !(std::isfinite(clearance[k]) && clearance[k] >= 0.0))
            return fail(s, PDS_EINVAL, "pds_set_fixed: point %zu: the clearance %g must be finite and >= 0", k,
                        clearance[k]);
    }
    return guarded(s, "pds_set_fixed", [&] {
        std::vector<pds::Point> points(n);
        std::vector<double> clearances(n, 0.0);
        for (std::size_t k = 0; k < n; ++k) {
            points[k] = pds::Point{xy[2 * k], xy[2 * k + 1]};
            if (clearance != nullptr) clearances[k] = clearance[k];
        }
        s->core->set_fixed(std::move(points), std::move(clearances));
        return 0;
    });
}

}  // extern "C"
