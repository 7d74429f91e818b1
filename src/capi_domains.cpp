// capi_domains.cpp - the C interface of the domains users have: a polygon,
// a mask, fixed points (poissondisk.h). The same rules as capi.cpp: every
// argument checked, one exception guard, a message naming what is wrong.
#include <cmath>
#include <cstdint>
#include <memory>

#include "capi_handle.hpp"
#include "domain/polygon.hpp"

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
        s->core->set_polygon(std::make_shared<const pds::Polygon>(xy, ring_ends, nrings));
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
    if (w > (SIZE_MAX - 1) / 4 / (h + 1))
        return fail(s, PDS_EINVAL, "pds_set_mask: a %zu x %zu mask does not fit in memory", w, h);
    if (const int rc = refuse_periodic(s, "pds_set_mask")) return rc;
    return guarded(s, "pds_set_mask", [&] {
        s->core->set_mask(w, h, inside);
        return 0;
    });
}

}  // extern "C"
