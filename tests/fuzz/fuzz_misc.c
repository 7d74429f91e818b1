/*
 * fuzz_misc.c - the operations of the fuzz harness that need no model of the
 * sampler (see fuzz_ops.c): every function on NULL (1.3's too), the error texts, the
 * version, pds_create with hostile radii on a second handle, and the thread count.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fuzz.h"

void fz_op_nulls(fz_state *st)
{
    double xy[2];
    size_t added = 5;
    FZ_CHECK(pds_count(NULL) == 0, "pds_count(NULL)");
    FZ_CHECK(isnan(pds_radius(NULL)), "pds_radius(NULL) not NaN");
    FZ_CHECK(pds_points(NULL, 0, 1, xy) == 0, "pds_points(NULL)");
    FZ_CHECK(pds_step(NULL) == PDS_EINVAL, "pds_step(NULL)");
    FZ_CHECK(pds_run(NULL, 3, &added) == PDS_EINVAL && added == 0, "pds_run(NULL)");
    FZ_CHECK(pds_refine(NULL, 0.5) == PDS_EINVAL, "pds_refine(NULL)");
    FZ_CHECK(pds_set_domain(NULL, 0, 0, 1, 1) == PDS_EINVAL, "pds_set_domain(NULL)");
    FZ_CHECK(pds_verify(NULL) == PDS_EINVAL, "pds_verify(NULL)");
    FZ_CHECK(pds_create(NULL, 0.1, 1) == PDS_EINVAL, "pds_create(NULL)");
    FZ_CHECK(pds_set_periodic(NULL, 1) == PDS_EINVAL, "pds_set_periodic(NULL)");
    FZ_CHECK(pds_set_count(NULL, 5) == PDS_EINVAL, "pds_set_count(NULL)");
    FZ_CHECK(pds_set_progress(NULL, fz_progress_cb, NULL) == PDS_EINVAL, "pds_set_progress(NULL)");
    FZ_CHECK(pds_set_progress(NULL, NULL, NULL) == PDS_EINVAL, "pds_set_progress(NULL)");
    xy[0] = 0.1;
    FZ_CHECK(pds_set_radius_map(NULL, 1, 1, xy) == PDS_EINVAL, "pds_set_radius_map(NULL)");
    FZ_CHECK(pds_set_radius_fn(NULL, fz_field_cb, NULL, 0.1, 0.2) == PDS_EINVAL,
             "pds_set_radius_fn(NULL)");
    FZ_CHECK(pds_radii(NULL, 0, 2, xy) == 0, "pds_radii(NULL)");
    FZ_CHECK(pds_set_threads(NULL, 2) == PDS_EINVAL, "pds_set_threads(NULL)");
    FZ_CHECK(pds_threads(NULL) == 0, "pds_threads(NULL)");
    FZ_CHECK(pds_errmsg(NULL) != NULL && pds_errmsg(NULL)[0] != '\0', "pds_errmsg(NULL)");
    pds_destroy(NULL);
    fz_check_free_area(st);
}

void fz_op_strerror(fz_state *st, fz_reader *r)
{
    const int code = (int)(uint32_t)fz_u64(r);
    const char *t = pds_strerror(code);
    int c;
    FZ_CHECK(t != NULL && t[0] != '\0', "pds_strerror(%d) is empty", code);
    for (c = -7; c <= 3; c++) {
        t = pds_strerror(c);
        FZ_CHECK(t != NULL && t[0] != '\0', "pds_strerror(%d) is empty", c);
    }
    if (st->s != NULL) fz_codes(st, "pds_errmsg", 0, FZ_OK); /* reading it changes nothing */
}

void fz_op_version(void)
{
    char want[32];
    snprintf(want, sizeof want, "%u.%u.%u", (unsigned)PDS_VERSION_MAJOR,
             (unsigned)PDS_VERSION_MINOR, (unsigned)PDS_VERSION_PATCH);
    FZ_CHECK(pds_version_number() == PDS_VERSION_NUMBER, "pds_version_number %u",
             pds_version_number());
    FZ_CHECK(strcmp(pds_version_string(), want) == 0, "pds_version_string %s",
             pds_version_string());
}

void fz_op_create_bad(fz_state *st, fz_reader *r)
{
    static int not_a_sampler;
    pds_sampler *t = (pds_sampler *)(void *)&not_a_sampler;
    const double radius = fz_hostile(r);
    const int rc = pds_create(&t, radius, fz_u8(r));
    const int valid = isfinite(radius) && radius > 0.0;
    fz_state none;
    memset(&none, 0, sizeof none);
    fz_codes(&none, "pds_create", rc,
             valid ? FZ_OK | FZ_BIT(PDS_ENOMEM) | fz_range_unless_111() : FZ_BIT(PDS_EINVAL));
    FZ_CHECK(rc == 0 ? t != NULL : t == NULL, "pds_create returned %d and *out %p", rc,
             (void *)t);
    pds_destroy(t);
    FZ_CHECK(pds_create(NULL, radius, 1) == PDS_EINVAL, "pds_create(NULL, %g)", radius);
    (void)st;
}

/* Counts around the limits (0: the core count; 1024 the most; 1025 and a
 * wrapped -1 refused) and small ones. The first success must come before the
 * first point and selects the parallel process (fz_replay_check then selects
 * it in its sampler too); after points of the single-thread process the call
 * is PDS_ESTATE. Once selected it is allowed at any time. Either way the
 * points, count and radius stay as they were, and a count set reads back. */
void fz_op_threads(fz_state *st, fz_reader *r)
{
    static const unsigned pick[8] = {0, 1, 2, 3, 8, 1024, 1025, (unsigned)-1};
    const unsigned b = fz_u8(r), n = b < 8 ? pick[b] : b % 16;
    const unsigned before = pds_threads(st->s);
    const int rc = pds_set_threads(st->s, n);

    if (st->s == NULL) {
        fz_codes(st, "pds_set_threads", rc, FZ_BIT(PDS_EINVAL));
        FZ_CHECK(pds_threads(NULL) == 0, "pds_threads(NULL)");
        return;
    }
    {
        const int late = st->count > 0 && !st->parallel; /* single-thread points exist */
        unsigned allowed = n > 1024 ? FZ_BIT(PDS_EINVAL) : late ? 0u : FZ_OK;
        if (late) allowed |= FZ_BIT(PDS_ESTATE); /* either check may come first */
        fz_codes(st, "pds_set_threads", rc, allowed);
    }
    if (rc == 0 && !st->parallel) {
        st->parallel = 1; /* before the first point (st->count was 0) */
        fz_changed_before_first(st);
    }
    if (rc == 0 && n != 0)
        FZ_CHECK(pds_threads(st->s) == n, "pds_set_threads(%u) reads back %u", n, pds_threads(st->s));
    else if (rc == 0)
        FZ_CHECK(pds_threads(st->s) >= 1 && pds_threads(st->s) <= 1024,
                 "pds_set_threads(0) reads back %u", pds_threads(st->s));
    else
        FZ_CHECK(pds_threads(st->s) == before, "a refused pds_set_threads(%u) changed the count "
                 "from %u to %u", n, before, pds_threads(st->s));
    fz_sync(st);
}
