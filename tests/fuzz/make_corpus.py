#!/usr/bin/env python3
"""make_corpus.py - write the seed corpus of the fuzz harness into tests/fuzz/corpus/.

Each seed exercises one path; the byte layout is the one fuzz_api.c and
fuzz_decode.c read (an operation byte = op | param << 4, then its arguments;
table indices refer to the tables in fuzz_decode.c). Run it again after
changing those tables:  python3 tests/fuzz/make_corpus.py
"""
import os

# operations (low 4 bits of an operation byte)
CREATE, DOMAIN, STEP, RUN, REFINE, POINTS, VERIFY, FREE_AREA = range(8)
NULLS, STRERROR, DESTROY, RUN_TO_END, RUN_CHUNKS, CREATE_BAD, VERSION, CHECK = range(8, 16)
# 1.2: operation 14 (VERSION) with parameter 1-4, 5-9, 10-15
EXT = VERSION
RESUME = 2  # RUN_TO_END parameter bit: run again after PDS_ECANCELED


def op(code, param=0):
    return [code | param << 4]


def hostile(index):  # kHostile[index]: 0 NaN, 1 inf, 3 0.0, 5 2^-1074, 10 1e300, 24 1e-5
    return [index * 8]


def radius_factor(side, index):  # side (0 w, 1 h, 2 min, 3 diagonal) * kFactor[index]
    return [1, side, index]


def radius_hostile(index):
    return [0] + hostile(index)


def radius_smooth(side, k, b=0):  # side * 2^-k * (1 + b/256)
    return [5, side, k, b]


def radius_offset_precision(offset, index):  # kOffset[offset] * kPrecision[index]
    return [4, offset, index]


def radius_precision(index):  # largest |coordinate| * kPrecision[index]
    return [3, index]


def domain_relative(offx, offy, span, aspect, flags=0):  # kOffset, kOffset, kSpan * R, kAspect
    return [1 | flags, offx, offy, span, aspect]


def domain_absolute(offx, offy, width, aspect, flags=0):  # kOffset, kOffset, kWidth, kAspect
    return [3 | flags, offx, offy, width, aspect]


def refine_by(index):  # current R * kRefine[index]: 0 equal, 1 just above, 7 half
    return [0, index]


def refine_to(radius_bytes):
    return [2] + radius_bytes


def periodic(flag=0):  # pds_set_periodic(kFlag[flag]): 0 -> 1, 1 -> 0, 5 -> INT_MIN
    return op(EXT, 1) + [flag]


# pds_set_count(kCount[index]): 0 -> 0, 6 -> 37, 7 -> 100, 9 -> 1000, 18 -> 1e9, 22 -> SIZE_MAX
def count(index):
    return op(EXT, 5) + [index * 4]


def count_small(n):  # pds_set_count(n), 1 <= n <= 64
    return op(EXT, 5) + [3, n - 1]


# pds_set_progress: mode 0 removes it, 1 is NULL with user data (EINVAL), 2 sets the
# callback; it asks to stop at every kEvery[every]-th call (0 never, 1 every, 3 third,
# 5 fiftieth) and tries changing call `change` from inside (0 none, 1 pds_run ...
# 8 pds_set_progress).
def progress(mode, every=0, change=0):
    return op(EXT, 10) + [mode | every << 2, change]


MAX_NEW_0, MAX_NEW_64, MAX_NEW_1000, MAX_NEW_SIZE_MAX = [0], [4], [5], [6]
SIZE_0, SIZE_N_MINUS_1, SIZE_N, SIZE_N_PLUS_1, SIZE_MAX = [0], [3], [4], [5], [7]

SEEDS = {
    # R = 0.02 in the unit square to the end, then every read-only call.
    "maximal": radius_factor(0, 9) + [7] + op(RUN) + MAX_NEW_0 + op(VERIFY) + op(FREE_AREA)
    + op(POINTS) + SIZE_0 + SIZE_MAX + op(POINTS) + SIZE_N_MINUS_1 + SIZE_N_PLUS_1 + op(CHECK),
    # Maximal at 0.05, refine to half, equal (no-op) and larger (EINVAL), chunks of 7.
    "refine": radius_factor(0, 8) + [3] + op(RUN_TO_END) + op(REFINE) + refine_by(7)
    + op(RUN_CHUNKS, 3) + op(REFINE) + refine_by(0) + op(REFINE) + refine_by(1)
    + op(REFINE) + refine_by(5) + op(STEP, 15) + op(VERIFY),
    # Three steps, then pds_set_domain (PDS_ESTATE), then to the end.
    "domain_after_points": radius_factor(0, 7) + [1] + op(STEP, 2)
    + op(DOMAIN) + domain_relative(0, 0, 8, 0) + op(POINTS, 2) + SIZE_N + SIZE_N
    + op(RUN_TO_END) + op(FREE_AREA),
    # NaN, infinities, zeros and denormals wherever a double goes.
    "nan_args": radius_hostile(0) + [0] + op(NULLS) + op(CREATE) + radius_factor(0, 7) + [2]
    + op(DOMAIN) + [0] + hostile(0) + hostile(1) + hostile(2) + hostile(3)
    + op(REFINE) + refine_to(radius_hostile(0)) + op(REFINE) + refine_to(radius_hostile(4))
    + op(CREATE_BAD) + hostile(5) + [9] + op(STRERROR) + [0x80, 0, 0, 0x80, 0, 0, 0, 0]
    + op(RUN) + MAX_NEW_64 + op(VERSION),
    # [1e15, 2e15] x [1e15+0.5, 2e15+0.5] at R = 1e13 (a bounded run: ~7000 would be
    # maximal), then R near 2^-26 of 2e15 (PDS_ERANGE before 1.1.1; after, bounded only).
    "offset_1e15": radius_hostile(10) + [4] + op(DOMAIN) + domain_absolute(1, 13, 9, 0)
    + op(REFINE) + refine_to(radius_factor(0, 10)) + op(RUN_TO_END) + op(CHECK)
    + op(REFINE) + refine_to(radius_precision(0)) + op(RUN) + MAX_NEW_1000 + op(RUN_TO_END),
    # R = 2^-26 * 1e15, the precision limit, in [1e15, 1e15 + 30 R]^2; then half of
    # it (PDS_ERANGE, nothing changes) and 0.9 of it (allowed).
    "precision_edge": radius_offset_precision(1, 1) + [12] + op(DOMAIN)
    + domain_relative(1, 1, 9, 0) + op(RUN_TO_END) + op(REFINE) + refine_by(7)
    + op(REFINE) + refine_by(5) + op(RUN_TO_END) + op(POINTS) + SIZE_0 + SIZE_N,
    # [0, 1] x [0, 1e6] with R = 1e6 / 8192: a thin strip, to the end.
    "aspect_1e6": radius_hostile(10) + [5] + op(DOMAIN) + domain_absolute(0, 0, 0, 1)
    + op(REFINE) + refine_to(radius_smooth(1, 13)) + op(RUN_TO_END) + op(VERIFY),
    # R just below the side (a few points), then just above the diagonal (one point).
    "radius_vs_size": radius_factor(0, 0) + [6] + op(RUN) + MAX_NEW_SIZE_MAX + op(CHECK)
    + op(CREATE) + radius_factor(3, 2) + [6] + op(STEP, 3) + op(FREE_AREA)
    + op(DOMAIN) + domain_relative(3, 4, 1, 0, 4) + op(RUN_TO_END),
    # Coordinates near 2^-890, the smallest the library accepts.
    "tiny_coords": radius_hostile(10) + [8] + op(DOMAIN) + domain_absolute(8, 8, 7, 0)
    + op(REFINE) + refine_to(radius_factor(0, 8)) + op(RUN_TO_END) + op(FREE_AREA),
    # R = 1e-5 in the unit square: only bounded work (1.1.1: no PDS_ERANGE for it).
    "bounded_huge": radius_hostile(24) + [9] + op(RUN) + MAX_NEW_64 + op(STEP, 7)
    + op(VERIFY) + op(FREE_AREA) + op(RUN_TO_END) + op(RUN) + MAX_NEW_SIZE_MAX,
    # One point at a time to the end, then a refine and single steps.
    "chunks": radius_factor(0, 8) + [11] + op(RUN_CHUNKS, 0) + op(REFINE) + refine_by(8)
    + op(STEP, 15) + op(POINTS) + SIZE_N_MINUS_1 + SIZE_MAX + op(DESTROY) + op(RUN) + [1],
    # ---- 1.2 ----
    # The unit torus at R = 0.05 to the end, then every read; INT_MIN and 0 flags first.
    "torus_maximal": radius_factor(0, 8) + [13] + periodic(5) + periodic(1) + periodic(0)
    + op(RUN_TO_END) + op(VERIFY) + op(FREE_AREA) + op(CHECK) + op(STEP, 1),
    # R just above half the period (PDS_ERANGE at the first point), then exactly half.
    "torus_half_period": radius_smooth(0, 1, 1) + [14] + periodic() + op(STEP) + op(RUN)
    + MAX_NEW_0 + op(CREATE) + radius_factor(0, 5) + [14] + periodic() + op(RUN_TO_END)
    + op(CHECK),
    # [12345.678, +3] x [0.25, +6]: periods that are not binary fractions, rounded to q;
    # refined twice; then pds_set_periodic after points (PDS_ESTATE).
    "torus_offset": radius_hostile(10) + [15] + op(DOMAIN) + domain_absolute(12, 15, 8, 3)
    + periodic() + op(REFINE) + refine_to(radius_factor(2, 8)) + op(RUN_CHUNKS, 3)
    + op(REFINE) + refine_by(7) + op(RUN_TO_END) + periodic(1) + op(CHECK),
    # A torus 300 R x 150 R at an offset of 1e15 (R = 2^-20 of it), bounded work only.
    "torus_strip": radius_offset_precision(1, 8) + [16] + op(DOMAIN)
    + domain_relative(1, 1, 11, 4) + periodic() + op(RUN) + MAX_NEW_1000 + op(CHECK),
    # 100 points in the unit square, then refine (PDS_ESTATE), step and run (PDS_DONE).
    "count_small": radius_factor(0, 8) + [17] + count(7) + op(RUN_TO_END) + op(VERIFY)
    + op(REFINE) + refine_by(7) + op(STEP) + op(RUN) + MAX_NEW_64 + op(CHECK),
    # 37 points on a torus over [-0.5, 0.5] x [1, 2], by steps and chunks.
    "count_torus": radius_factor(0, 8) + [18] + op(DOMAIN) + domain_absolute(4, 3, 0, 0)
    + periodic() + count(6) + op(STEP, 3) + op(RUN_CHUNKS, 2) + op(STEP, 15) + op(CHECK),
    # n = 0 (EINVAL), 1e9 (PDS_ERANGE unbounded), SIZE_MAX (precision), then 2 points
    # after 10 (the radius follows the last pds_set_count), then 5 after points (ESTATE).
    "count_range": radius_factor(0, 8) + [19] + count(0) + count(18) + op(RUN) + MAX_NEW_0
    + op(RUN) + [1] + count(22) + op(STEP) + count(5) + count(2) + op(RUN_TO_END)
    + count_small(5) + op(CHECK),
    # Count mode just above the precision limit: R0 = 1.03 x 2^-26 of 1e15 (n = 37 in a
    # square 3 x 2^-26 x 1e15 wide at 1e15): the lowered radius crosses the limit and
    # pds_run returns PDS_ERANGE after adding 23 points (found/NOTES; minimized).
    "regress_count_below_precision": radius_offset_precision(1, 1) + [20] + op(DOMAIN)
    + domain_relative(1, 1, 7, 0) + count(6) + op(RUN_TO_END),
    # 7 points on the unit torus at R = 1e-5, then pds_verify: it allocates a dense
    # grid of 65536^2 buckets, 32 GB (found/NOTES; ASan reports out-of-memory).
    "regress_torus_verify_grid": radius_hostile(24) + [9] + periodic() + op(RUN) + [3]
    + op(VERIFY),
    # Cancel at every report and resume until the end; the replay must match.
    # (Each resumed run stops after one point: its first report comes at once.)
    "progress_cancel": radius_factor(0, 9) + [21] + progress(2, 1) + op(RUN_TO_END, RESUME)
    + progress(2, 5) + op(RUN_TO_END, RESUME) + op(CHECK) + op(REFINE) + refine_by(6)
    + op(RUN_TO_END, RESUME),
    # Each changing call from inside the callback (PDS_ESTATE), in chunks and runs;
    # then NULL with user data (EINVAL) and removal.
    "progress_change": radius_factor(0, 9) + [22]
    + progress(2, 0, 1) + op(RUN) + [11, 40] + progress(2, 0, 2) + op(RUN) + [11, 40]
    + progress(2, 0, 3) + op(RUN) + [11, 40] + progress(2, 0, 4) + op(RUN) + [11, 40]
    + progress(2, 0, 5) + op(RUN) + [11, 40] + progress(2, 0, 6) + op(RUN) + [11, 40]
    + progress(2, 0, 7) + op(RUN) + [11, 40] + progress(2, 0, 8) + op(RUN_CHUNKS, 4)
    + progress(1) + progress(0) + op(RUN_TO_END) + op(NULLS),
    # Count mode on the torus with a cancel at every third report and changes refused.
    "progress_count": radius_factor(0, 8) + [23] + periodic() + count(9)
    + progress(2, 3, 6) + op(RUN_TO_END, RESUME) + op(RUN_TO_END, RESUME) + op(VERIFY),
}


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(bytes(data))


if __name__ == "__main__":
    main()
