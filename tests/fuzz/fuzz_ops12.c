/*
 * fuzz_ops12.c - the operations for the calls added in 1.2 (see fuzz_ops.c):
 * pds_set_periodic, pds_set_count and pds_set_progress. The callback itself
 * and what pds_run must do around it are in fuzz_progress.c. With a radius
 * field (1.3) pds_set_count is PDS_EINVAL; the torus takes one.
 */
#include <stdlib.h>

#include "fuzz.h"

void fz_op_periodic(fz_state *st, fz_reader *r)
{
    const int flag = fz_flag(r);
    const int rc = pds_set_periodic(st->s, flag);

    if (st->s == NULL) {
        fz_codes(st, "pds_set_periodic", rc, FZ_BIT(PDS_EINVAL));
        return;
    }
    /* A polygon or mask is never periodic, nor are fixed points (1.4). */
    fz_codes(st, "pds_set_periodic", rc, st->count > 0 ? FZ_BIT(PDS_ESTATE)
             : flag != 0 && (st->shape.kind != FZ_SHAPE_NONE || st->nfix > 0) ? FZ_BIT(PDS_EINVAL) : FZ_OK);
    if (rc == 0) {
        fz_changed_before_first(st);
        st->periodic = flag != 0;
        fz_set_torus(st);
        fz_count_radius(st); /* count mode: the start radius follows the kind */
    }
    fz_sync(st);
}

void fz_op_count(fz_state *st, fz_reader *r)
{
    const size_t n = fz_count_n(r);
    const int rc = pds_set_count(st->s, n);
    unsigned allowed;

    if (st->s == NULL)
        allowed = FZ_BIT(PDS_EINVAL);
    else if (n == 0 || st->field) /* either check may come first once points exist */
        allowed = FZ_BIT(PDS_EINVAL) | (st->count > 0 ? FZ_BIT(PDS_ESTATE) : 0u);
    else
        allowed = st->count > 0 ? FZ_BIT(PDS_ESTATE) : FZ_OK;
    fz_codes(st, "pds_set_count", rc, allowed);
    if (st->s == NULL) return;
    if (rc == 0) {
        fz_changed_before_first(st);
        st->target = n;
        fz_count_radius(st);
    }
    fz_sync(st);
}

void fz_op_progress(fz_state *st, fz_reader *r)
{
    static const unsigned kEvery[8] = {0, 1, 2, 3, 7, 50, 1000, 1};
    const unsigned sel = fz_u8(r), change = fz_u8(r) % 11;
    pds_progress_fn fn = (sel % 4 >= 2) ? fz_progress_cb : NULL;
    void *user = (sel % 4 == 0) ? NULL : (void *)st;
    const int rc = pds_set_progress(st->s, fn, user);
    const int bad = st->s == NULL || (fn == NULL && user != NULL);

    fz_codes(st, "pds_set_progress", rc, bad ? FZ_BIT(PDS_EINVAL) : FZ_OK);
    if (rc != 0 || st->s == NULL) return;
    st->prog.on = fn != NULL;
    st->prog.cancel_every = kEvery[sel / 4 % 8];
    st->prog.change = change;
    st->prog.calls = 0;
    fz_sync(st);
}
