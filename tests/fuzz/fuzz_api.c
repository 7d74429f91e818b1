/*
 * fuzz_api.c - libFuzzer harness for the public API (C99, sees only the header).
 *
 *   make fuzz                      fuzz for FUZZ_SECONDS (default 300)
 *   make check-fuzz                the same for 30 s (part of make check)
 *   $(B)/fuzz/fuzz_api CRASH_FILE  replay one input (crashes land in $(B)/fuzz/)
 *
 * The seeds are tests/fuzz/corpus/ (made by make_corpus.py); make fuzz works on
 * a copy in $(B)/fuzz/corpus-work, so the repository never gains new files.
 *
 * Input: the first bytes make a sampler (pds_create with a decoded radius and
 * seed); then each byte names an operation (low 4 bits) with a small parameter
 * (high 4 bits), and the operation reads its own arguments (fuzz_decode.c).
 * Operation 14 with parameter 0 is the version check; with 1-4 it is
 * pds_set_periodic, 5-9 pds_set_count, 10-15 pds_set_progress (1.2).
 * Operation 15 with parameter 0-6 is the pattern check; with 8-10 it is
 * pds_set_radius_map, 11-13 pds_set_radius_fn, 14 pds_radii, 15 makes the
 * radius function return bad values everywhere, or stop doing so (1.3).
 * Past the end every read gives zeros; at most 64 operations.
 *
 * Every byte value above has its call, so new calls go behind an escape:
 * operation 15 with parameter 7 (the byte 0x7f, a pattern check until the
 * escape took it; no seed used it) is "extended", and the next byte selects
 * the call in ext_ops[] below; a selector with no call there does nothing.
 * A new call is appended to ext_ops[] with the next selector, so every
 * existing input, the seeds of corpus/ among them, decodes to the same calls
 * as before (make_corpus.py's extended() writes the two bytes). Selectors:
 *   0  replay: the determinism check of fuzz_replay.c now, mid-input, on a
 *      sampler that then goes on (costs the read budget, as verify does)
 *   1  pds_set_polygon with 0-3 decoded rings (1.4, fuzz_domains.c)
 *   2  pds_set_mask with a raster of up to 8 x 8 (1.4)
 *   3  pds_set_threads with a hostile count, read back by pds_threads (1.5);
 *      PDS_ESTATE after points of the single-thread process; a success before
 *      the first point selects the parallel process, whose points must not
 *      depend on the count (the replay selects it too, on one thread)
 *   4  pds_set_fixed with up to 63 decoded points and clearances (1.4,
 *      fuzz_fixed.c)
 *
 * Checked after every call (fuzz_check.c): the code is one the header allows
 * for that call in that situation; pds_strerror and pds_errmsg are sane; a
 * failed call leaves count, radius and points as they were; points never move
 * once returned and lie inside the closed domain. After "maximal": every pair
 * at least R apart, pds_verify 0, pds_free_area 0, nothing more can be added.
 * On the torus: points in [x0,x1)x[y0,y1) on the quantum grid, distances
 * wrapped (fuzz_torus.c). In count mode: PDS_DONE exactly at n points, the
 * documented start radius, pairs at least the (lowered) radius apart. The
 * progress callback's reports and cancels: fuzz_progress.c. Radius fields:
 * pds_radii, each radius the field's value, later points outside earlier
 * disks, a maximal pattern's disks covering the domain, bad values from the
 * function stopping runs (fuzz_field.c). A polygon or mask (1.4): points in
 * the closed domain and a maximal pattern covering it, by the harness's own
 * geometry (fuzz_shape.c), its area as pds_free_area's start, periodic
 * refused (fuzz_domains.c). Fixed points (1.4): every point keeps each
 * clearance (scaled as the radius is), a maximal pattern's coverage counts
 * their disks, a point outside the box is refused at the first point
 * (fuzz_fixed.c). Before a sampler
 * is dropped, a second one replays its calls without the splits and the
 * callback and must give the same bytes (fuzz_replay.c); with a constant field,
 * so must a plain sampler at that radius.
 * Any violation calls abort(), which libFuzzer reports with the input.
 *
 * Bounded work (an input must run in milliseconds): calls that add points
 * follow the policy in fuzz_ops.c; the reads asked for by operations
 * (pds_verify, pds_free_area, the pair check, the extended replay) share a
 * budget of FZ_READS point visits per input, while the checks after "maximal"
 * and at the end always run. Under ASan and libFuzzer's tracing a maximal
 * pattern costs some 20 us per point (pds_verify on a 1e6:1 strip about ten
 * times that).
 *
 * PDS_FUZZ_TRACE=1 in the environment prints each operation and its byte(s)
 * (for replays).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

#define FZ_READS 20000 /* points the O(n) reads (verify, free area, check) may visit */
#define FZ_MAX_OPS 64

static int tracing = -1;

/* code: the operation's byte(s), so a trace shows how the input decoded. */
static void trace(const fz_state *st, const char *what, unsigned code)
{
    if (tracing < 0) tracing = getenv("PDS_FUZZ_TRACE") != NULL;
    if (tracing)
        fprintf(stderr, "fuzz: %-14s %04x count %zu R %.17g domain [%.17g,%.17g]x[%.17g,%.17g] "
                "bound %.3g%s\n", what, code, st->count, st->radius, st->dom[0], st->dom[2],
                st->dom[1], st->dom[3], fz_count_bound(st), st->s ? "" : " (no sampler)");
}

/* Whether an O(n) read fits the input's read budget (and spend it). */
static int afford_read(fz_state *st, size_t *reads)
{
    const size_t cost = st->count + 1;
    if (cost > *reads) return 0;
    *reads -= cost;
    return 1;
}

/* ---- extended operations (the escape byte, then a selector) ---------------- */

#define FZ_ESCAPE 0x7f

static void ext_replay(fz_state *st, fz_reader *r, size_t *reads)
{
    (void)r;
    if (afford_read(st, reads)) fz_replay_check(st);
}

static void ext_polygon(fz_state *st, fz_reader *r, size_t *reads)
{
    (void)reads;
    fz_op_polygon(st, r);
}

static void ext_mask(fz_state *st, fz_reader *r, size_t *reads)
{
    (void)reads;
    fz_op_mask(st, r);
}

static void ext_threads(fz_state *st, fz_reader *r, size_t *reads)
{
    (void)reads;
    fz_op_threads(st, r);
}

static void ext_fixed(fz_state *st, fz_reader *r, size_t *reads)
{
    (void)reads;
    fz_op_fixed(st, r);
}

/* Append only: a selector keeps its call for good (see the header comment). */
static const struct {
    const char *name;
    void (*fn)(fz_state *st, fz_reader *r, size_t *reads);
} ext_ops[] = {
    {"ext/replay", ext_replay},
    {"ext/polygon", ext_polygon},
    {"ext/mask", ext_mask},
    {"ext/threads", ext_threads},
    {"ext/fixed", ext_fixed},
};
#define FZ_EXT_OPS (sizeof ext_ops / sizeof ext_ops[0])

static void extended(fz_state *st, fz_reader *r, size_t *reads)
{
    const unsigned sel = fz_u8(r);
    trace(st, sel < FZ_EXT_OPS ? ext_ops[sel].name : "ext/none", FZ_ESCAPE << 8 | sel);
    if (sel < FZ_EXT_OPS) ext_ops[sel].fn(st, r, reads);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_reader r;
    fz_state st;
    int ops;
    size_t reads = FZ_READS;

    r.p = data;
    r.n = size;
    memset(&st, 0, sizeof st);
    st.budget = FZ_BUDGET;
    fz_reset(&st, NULL, 1.0);
    fz_op_create(&st, &r, 0);
    for (ops = 0; ops < FZ_MAX_OPS && r.n > 0; ops++) {
        const unsigned b = fz_u8(&r), arg = b >> 4;
        fz_cap_thin_budget(&st);
        static const char *const names[16] = {
            "create", "set_domain", "step", "run", "refine", "points", "verify", "free_area",
            "nulls", "strerror", "destroy", "run_to_end", "run_chunks", "create_bad",
            "version/1.2", "check/1.3"};
        if (b == FZ_ESCAPE) {
            extended(&st, &r, &reads);
            continue;
        }
        trace(&st, names[b & 15], b);
        switch (b & 15) {
            case 0: fz_op_create(&st, &r, arg); break;
            case 1: fz_op_domain(&st, &r); break;
            case 2: fz_op_step(&st, arg); break;
            case 3: fz_op_run(&st, &r, arg); break;
            case 4: fz_op_refine(&st, &r); break;
            case 5: fz_op_points(&st, &r, arg); break;
            case 6: /* a maximal pattern already verified would only repeat itself */
                if (!st.checked && afford_read(&st, &reads)) fz_op_verify(&st);
                break;
            case 7: if (afford_read(&st, &reads)) fz_check_free_area(&st); break;
            case 8: fz_op_nulls(&st); break;
            case 9: fz_op_strerror(&st, &r); break;
            case 10:
                fz_replay_check(&st);
                pds_destroy(st.s);
                fz_reset(&st, NULL, 1.0);
                break;
            case 11: fz_op_run_to_end(&st, arg); break;
            case 12: fz_op_run_chunks(&st, arg); break;
            case 13: fz_op_create_bad(&st, &r); break;
            case 14:
                if (arg == 0)
                    fz_op_version();
                else if (arg <= 4)
                    fz_op_periodic(&st, &r);
                else if (arg <= 9)
                    fz_op_count(&st, &r);
                else
                    fz_op_progress(&st, &r);
                break;
            default:
                if (arg >= 8 && arg <= 10)
                    fz_op_radius_map(&st, &r);
                else if (arg >= 11 && arg <= 13)
                    fz_op_radius_fn(&st, &r);
                else if (arg == 14)
                    fz_op_radii(&st, &r, fz_u8(&r));
                else if (arg == 15)
                    fz_op_field_bad(&st, &r);
                else {
                    fz_sync(&st);
                    if (afford_read(&st, &reads)) fz_check_pattern(&st);
                }
                break;
        }
    }
    trace(&st, "end", 0);
    /* Whatever the sequence left: a Poisson-disk set inside the domain. */
    fz_sync(&st);
    fz_check_pattern(&st);
    fz_replay_check(&st);
    pds_destroy(st.s);
    fz_field_reset(&st);
    fz_shape_free(&st.shape);
    fz_fixed_reset(&st);
    free(st.pts);
    free(st.tmp);
    free(st.rad);
    free(st.rad_tmp);
    return 0;
}
