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
# The escape (operation 15, parameter 7), then a selector: fuzz_api.c's ext_ops[]
# (append only, so no seed changes meaning); a selector past its end does nothing.
EXT_REPLAY = 0  # the determinism check now, on a sampler that goes on
EXT_POLYGON = 1  # pds_set_polygon (fuzz_domains.c's decoding)
EXT_MASK = 2  # pds_set_mask
EXT_THREADS = 3  # pds_set_threads (1.5)
EXT_FIXED = 4  # pds_set_fixed (fuzz_fixed.c's decoding)


def threads(b):  # pds_set_threads: b < 8 picks 0, 1, 2, 3, 8, 1024, 1025, -1; else b % 16
    return extended(EXT_THREADS) + [b]


def op(code, param=0):
    assert (code, param) != (CHECK, 7), "0x7f is the escape: use extended()"
    return [code | param << 4]


def extended(selector):
    return [CHECK | 7 << 4, selector]


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


# ---- 1.3: operation 15 (CHECK) with parameter 8-10, 11-13, 14, 15 ----
# kRatio (fuzz_field.c) indices: rmax / rmin (a map: hi / lo)
R_EQUAL, R_ULP, R_1_5, R_2, R_2_5, R_4, R_10, R_1E4, R_1E300, R_HALF = 0, 2, 4, 5, 6, 7, 8, 10, 12, 13
# map value patterns (vsel % 8); vsel >= 64 means no hostile value is put in
M_UNIFORM, M_GRAD_X, M_GRAD_Y, M_CHECKER, M_NOISE, M_SPIKE, M_HI, M_DIAG = range(8)
# function shapes
F_CONST, F_GRAD, F_DIAG, F_STEP, F_SMOOTH, F_CHECKER, F_RADIAL, F_SPIKE = range(8)


# pds_set_radius_map: dims % 8 is 0 1x1, 1 small (w, h bytes % 8 + 1), 2 (% 64 + 1),
# 3 64 << (byte % 4) each, 4 empty, 5 overflowing (table index, order), 6 NULL map,
# 7 a line; dims >= 0xf0: s NULL. base: radius bytes (fz_radius); the values run
# from base to base * kRatio[ratio]; hostile=(where, hostile bytes) puts one in
# (where % 3: 0 first, 1 last, 2 another cell).
def radius_map(dims, dim_bytes, pattern, base, ratio, hostile=None, spike=0):
    vsel = pattern | spike << 3 | (0 if hostile else 64)
    out = op(CHECK, 8) + [dims, vsel] + dim_bytes + base + [ratio]
    if hostile:
        out += [hostile[0]] + hostile[1]
    return out


# pds_set_radius_fn: rmin from radius bytes, rmax = rmin * kRatio[ratio] (or hostile
# bytes when rmax_hostile); rng 1: constant rmax inside the bounds, 2: inside, touching
# neither; band=(start/256, kBand index): bad values there, of kind `bad` (0 NaN, 1 inf,
# 3 0, 5 just above rmax, 6 just below rmin, ...); change: a call tried from inside
# (1 pds_run ... 9 pds_set_progress); null: 1 s NULL, 2 fn NULL.
def radius_fn(rmin, ratio, shape, param=0, rng=0, band=None, bad=0, change=0, rmax_hostile=None,
              null=0):
    sel = (7 if rmax_hostile is not None else 0) | ({0: 0, 1: 31, 2: 30}[null] << 3)
    out = op(CHECK, 11) + [sel] + rmin
    out += rmax_hostile if rmax_hostile is not None else [ratio]
    b = bad << 2 | (3 if band else 0)
    out += [shape, param, rng, b] + (list(band) if band else []) + [change]
    return out


def radii(arg=0, first=[0], count=[4]):  # pds_radii(fz_size, fz_size)
    return op(CHECK, 14) + [arg] + first + count


def field_bad(kind=0):  # the radius function returns bad value `kind` everywhere
    return op(CHECK, 15) + [1 | kind << 2]


def field_good():
    return op(CHECK, 15) + [0]


def sb(c):  # a coordinate c (a multiple of 1/8 in [-16, 16)) as fuzz_domains.c's sbyte reads it
    return int(round(c * 8)) & 0xff


STAR, SCATTER, SIDES, HOLE = range(4)  # ring modes: a star, small integers, a rectangle's sides, a star
REVERSE, CLOSING, REPEAT, COLLINEAR, TWICE = 1, 2, 4, 8, 16  # ring flags


def ring(nv, mode, flags=0, verts=(), centre=(0, 0), corner=(0, 0), size=(0, 0), hostile_at=None):
    """One ring: nv vertices; verts are star radii (multiples of 1/8, 1/8 .. 4) or (x, y)
    pairs for SCATTER; SIDES uses corner and size (1 + byte/4 each side)."""
    rb = next(b for b in range(256) if b % 10 == nv - 3 and b // 16 % 4 == mode)
    out = [rb, flags | (0xe0 if hostile_at else 0)]
    if mode == STAR:
        out += [sb(centre[0]), sb(centre[1])]
    out += [sb(corner[0]), sb(corner[1]), size[0], size[1]]
    if mode in (STAR, HOLE):
        out += [int(v * 8) - 1 for v in verts]
    elif mode == SCATTER:
        out += [sb(c) for xy in verts for c in xy]
    if hostile_at:
        out += [hostile_at[0]] + hostile(hostile_at[1])
    return out


def polygon(rings, unit=0, offset=(0, 0), centre=(0, 0), bad=0):
    """pds_set_polygon: kUnit[unit], kShapeOffset[offset]; bad 13 decreasing ends, 14
    ring_ends NULL, 15 xy NULL."""
    n = len(rings)
    b = next(b for b in range(256) if b // 16 == bad and (b % 8 == 0) == (n == 0)
             and (n == 0 or b % 3 == n - 1))
    out = extended(EXT_POLYGON) + [b, unit, offset[0], offset[1], sb(centre[0]), sb(centre[1])]
    return out + sum(rings, [])


def mask(w, h, rows=(), fill=2, special=None):
    """pds_set_mask: rows are bit masks (fill 2: read them; 0 all out, 1 all in);
    special 0 w = 0, 1 h = 0, 2 NULL, 3 overflowing size."""
    b = (w - 1) | (h - 1) << 3 | (192 if special is not None else 0)
    f = fill | ((special or 0) << 2)
    return extended(EXT_MASK) + [b, f] + (list(rows) if fill % 4 >= 2 else [])


# fuzz_fixed.c: a point is (kind, a, b): 0 at (a, b) / 255 of the box, 1 corner a % 4,
# 2 on a side, 3 the one before again, 4 on its line, 5 a millionth of R beside it,
# 6 a vertex of the shape, 7 just outside the box, 8 a hostile coordinate (more bytes).
# A clearance: [0] the radius there, [1, k] k / 16 R, [2, i] a factor of R, [3, k] k + 1
# box diagonals (covers it), [4] -R, [5, ...] hostile, [6] a tenth of the diagonal, [7] R.
def fixed(points, clearances=None, xy_null=False):
    n = len(points)
    head = [n] if n < 7 else [7, n - 7]
    flags = (15 if xy_null else 0) | (16 if clearances is None else 0)
    out = extended(EXT_FIXED) + head[:1] + [flags] + head[1:]
    for k, pt in enumerate(points):
        out += list(pt) + (list(clearances[k]) if clearances is not None else [])
    return out


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
    # ---- 1.3 ----
    # A gradient function 0.02 .. 0.04 in the unit square to the end, then every read.
    "field_fn_gradient": radius_factor(0, 8) + [30] + radius_fn(radius_factor(0, 9), R_2, F_GRAD)
    + op(RUN_TO_END) + op(VERIFY) + op(FREE_AREA) + radii(0, SIZE_0, SIZE_MAX)
    + radii(0, SIZE_N_MINUS_1, SIZE_N_PLUS_1) + radii(2) + radii(1) + op(CHECK),
    # A step 0.02 | 0.05 (beyond sqrt 2) on the unit torus, in chunks; refined to 0.7.
    "field_fn_step_torus": radius_factor(0, 8) + [31] + periodic()
    + radius_fn(radius_factor(0, 9), R_2_5, F_STEP) + op(RUN_CHUNKS, 3) + op(REFINE)
    + refine_by(6) + op(RUN_TO_END) + op(CHECK) + radii(0, SIZE_0, SIZE_N),
    # Smooth 0.02 .. 0.08 over [1e15, 1e15 + 1] (2^-26 of 1e15 is 1.5e7: PDS_ERANGE),
    # then over [-0.5, 0.5]^2 after the domain changes.
    "field_fn_smooth_offset": radius_factor(0, 8) + [32]
    + radius_fn(radius_factor(0, 9), R_4, F_SMOOTH, 3) + op(DOMAIN) + domain_absolute(1, 1, 0, 0)
    + op(STEP) + op(DOMAIN) + domain_absolute(4, 4, 0, 0) + op(RUN_TO_END) + op(VERIFY),
    # Bad values in a band x in [0.5, 0.6): a run stops with PDS_EINVAL when a point
    # would go there, the points stay; each later call stops there too.
    "field_fn_bad_band": radius_factor(0, 8) + [33]
    + radius_fn(radius_factor(0, 9), R_2, F_RADIAL, band=(128, 1), bad=5) + op(RUN_TO_END)
    + op(STEP, 3) + op(RUN_CHUNKS, 1) + op(VERIFY) + op(FREE_AREA) + op(CHECK),
    # Bad values everywhere for a while (NaN, then 0, then just below rmin): runs and
    # steps stop with nothing added; then good again, to the end: the replay agrees.
    "field_fn_toggle": radius_factor(0, 8) + [34] + radius_fn(radius_factor(0, 9), R_2, F_DIAG)
    + op(RUN) + MAX_NEW_64 + field_bad(0) + op(RUN) + MAX_NEW_64 + op(STEP, 1) + field_bad(3)
    + op(RUN_TO_END) + field_bad(6) + op(RUN_CHUNKS, 0) + field_good() + op(RUN_CHUNKS, 4)
    + op(RUN_TO_END),
    # The very first point refused, then the domain changes (no points yet) and it runs
    # (open bug field_first_point_rng: the replay is skipped unless PDS_FUZZ_STRICT).
    "field_fn_first_refused": radius_factor(0, 8) + [35]
    + radius_fn(radius_factor(0, 9), R_2, F_GRAD) + field_bad(1) + op(STEP) + op(RUN) + [1]
    + field_good() + op(DOMAIN) + domain_absolute(4, 4, 0, 0) + op(RUN_TO_END),
    # Changing calls from inside the function: PDS_ESTATE (pds_run ... pds_set_progress).
    "field_fn_change_inside": sum(((op(CREATE) if k > 1 else []) + radius_factor(0, 8) + [36 + k]
                                   + radius_fn(radius_factor(0, 9), R_2, F_CHECKER, 2, change=k)
                                   + op(RUN) + MAX_NEW_64 for k in range(1, 10)), []),
    # rmin == rmax (0.03 x 2^-k): the plain sampler's points, refine included; then
    # a constant value inside wider bounds (the weighted path).
    "field_fn_constant": radius_factor(0, 8) + [37] + radius_fn(radius_smooth(0, 5), R_EQUAL, F_GRAD)
    + op(RUN) + MAX_NEW_64 + op(REFINE) + refine_by(5) + op(RUN_TO_END) + radii()
    + op(CREATE) + radius_factor(0, 8) + [37] + radius_fn(radius_factor(0, 9), R_2, F_GRAD, rng=1)
    + op(RUN_TO_END),
    # Bad bounds: rmax NaN, inf, inverted, rmin 0 and negative; fn NULL, s NULL; then a
    # count (EINVAL either way round), then points (ESTATE).
    "field_fn_bad_bounds": radius_factor(0, 8) + [38]
    + radius_fn(radius_factor(0, 9), 0, F_GRAD, rmax_hostile=hostile(0))
    + radius_fn(radius_factor(0, 9), 0, F_GRAD, rmax_hostile=hostile(1))
    + radius_fn(radius_factor(0, 9), R_HALF, F_GRAD) + radius_fn(radius_hostile(3), R_2, F_GRAD)
    + radius_fn(radius_hostile(15), R_2, F_GRAD) + radius_fn(radius_factor(0, 9), R_2, F_GRAD, null=2)
    + radius_fn(radius_factor(0, 9), R_2, F_GRAD, null=1) + count(7)
    + radius_fn(radius_factor(0, 9), R_2, F_GRAD) + op(CREATE) + radius_factor(0, 8) + [38]
    + radius_fn(radius_factor(0, 9), R_2, F_GRAD) + count(7) + op(STEP)
    + radius_fn(radius_factor(0, 9), R_2, F_GRAD) + radius_map(0, [], M_UNIFORM, radius_factor(0, 9), 0)
    + op(NULLS),
    # In [1e15, 2e15]^2 (the limit: 2^-26 x 2^50): rmin at 2^-27 of 2e15 (PDS_ERANGE at
    # the first point), at 2^-26 (x 1 - 2^-53) of it (allowed); then 2^-20 of it
    # (bounded work), refined to 1/100 (PDS_ERANGE).
    "field_fn_precision": radius_hostile(10) + [39] + op(DOMAIN) + domain_absolute(1, 1, 9, 0)
    + radius_fn(radius_precision(6), R_4, F_GRAD) + op(STEP) + radius_fn(radius_precision(0), R_1E4, F_GRAD)
    + op(RUN) + [1] + op(CREATE) + radius_hostile(10) + [39] + op(DOMAIN) + domain_absolute(1, 1, 9, 0)
    + radius_fn(radius_precision(8), R_4, F_SMOOTH) + op(RUN) + MAX_NEW_1000
    + op(REFINE) + refine_by(10) + op(STEP, 3),
    # rmin 1e-5 .. rmax 0.1: the bound at rmin is 1.2e10 points; bounded work, and an
    # unbounded run must fail with PDS_ERANGE.
    "field_fn_tiny_rmin": radius_factor(0, 8) + [40] + radius_fn(radius_hostile(24), R_1E4, F_SPIKE, 0x77)
    + op(RUN) + MAX_NEW_64 + op(RUN) + MAX_NEW_0 + op(STEP, 7) + op(VERIFY) + op(CHECK),
    # A function on a torus whose rmax is above half the period (PDS_ERANGE), then not.
    "field_fn_torus_half": radius_factor(0, 8) + [41] + periodic()
    + radius_fn(radius_factor(0, 6), R_2, F_GRAD) + op(STEP)
    + radius_fn(radius_factor(0, 7), R_4, F_STEP) + op(RUN_TO_END) + op(VERIFY),
    # A 1 x 1 map: the plain sampler's points; refined; pds_radii all equal.
    "field_map_1x1": radius_factor(0, 8) + [42] + radius_map(0, [], M_UNIFORM, radius_factor(0, 9), 0)
    + op(RUN_CHUNKS, 2) + op(REFINE) + refine_by(6) + op(RUN_TO_END) + radii(0, SIZE_0, SIZE_N),
    # A 4 x 3 gradient map 0.02 .. 0.04 and a 5 x 5 checker 0.02 | 0.05.
    "field_map_gradient": radius_factor(0, 8) + [43]
    + radius_map(1, [3, 2], M_GRAD_X, radius_factor(0, 9), R_2) + op(RUN_TO_END) + op(VERIFY)
    + op(CREATE) + radius_factor(0, 8) + [44] + radius_map(1, [4, 4], M_CHECKER, radius_factor(0, 9), R_2_5)
    + op(STEP, 15) + radii(0, SIZE_N_MINUS_1, SIZE_MAX),
    # A 512 x 512 noise map 0.02 .. 0.08, bounded and to the end on a torus.
    "field_map_large": radius_factor(0, 8) + [45] + periodic()
    + radius_map(3, [3, 3], M_NOISE, radius_factor(0, 9), R_4) + op(RUN) + MAX_NEW_1000
    + op(RUN_TO_END) + op(FREE_AREA),
    # Lines 1 x 200 and 200 x 1 (gradients), the y one over a tall domain.
    "field_map_line": radius_factor(0, 8) + [46] + radius_map(7, [199, 1], M_GRAD_X, radius_factor(0, 9), R_2)
    + op(RUN_TO_END) + op(CREATE) + radius_factor(0, 8) + [47] + op(DOMAIN) + domain_absolute(0, 0, 0, 3)
    + radius_map(7, [199, 0], M_GRAD_Y, radius_factor(1, 9), R_2) + op(RUN_TO_END),
    # Hostile maps: NULL, empty, overflowing sizes, NaN / -1 / 0 / inf put in, s NULL;
    # then valid denormal and 1e300 values (PDS_ERANGE at the first point, one point).
    "field_map_hostile": radius_factor(0, 8) + [48]
    + radius_map(6, [1, 1], M_UNIFORM, radius_factor(0, 9), 0) + radius_map(4, [1, 2], M_UNIFORM, radius_factor(0, 9), 0)
    + radius_map(4, [0, 2], M_UNIFORM, radius_factor(0, 9), 0)
    + sum((radius_map(5, [k, 0], M_UNIFORM, radius_factor(0, 9), 0) for k in range(10)), [])
    + radius_map(5, [2, 1], M_UNIFORM, radius_factor(0, 9), 0)
    + radius_map(1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2, hostile=(0, hostile(0)))
    + radius_map(1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2, hostile=(1, hostile(15)))
    + radius_map(1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2, hostile=(2, hostile(3)))
    + radius_map(1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2, hostile=(5, hostile(1)))
    + radius_map(0xf1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2)
    + radius_map(1, [1, 1], M_GRAD_X, radius_factor(0, 9), R_1E300) + op(STEP) + op(CHECK)
    + op(CREATE) + radius_factor(0, 8) + [48]
    + radius_map(1, [1, 1], M_GRAD_X, radius_hostile(5), R_2) + op(RUN) + MAX_NEW_0
    + radius_map(0, [], M_UNIFORM, radius_hostile(10), 0) + op(RUN_TO_END) + op(VERIFY),
    # A map on a torus: a map 0.3 .. 0.6 exceeds half the period (PDS_ERANGE at the
    # first point); a count then map and map then count (EINVAL both).
    "field_map_torus_count": radius_factor(0, 8) + [49] + periodic()
    + radius_map(1, [1, 1], M_DIAG, radius_factor(0, 6), R_2) + op(STEP)
    + radius_map(1, [1, 1], M_DIAG, radius_factor(0, 8), R_2) + count(7) + op(RUN_TO_END)
    + op(CREATE) + radius_factor(0, 8) + [49] + count(7) + radius_map(0, [], M_UNIFORM, radius_factor(0, 9), 0)
    + op(RUN_TO_END),
    # A field with the progress callback: a cancel every third report, resumed, a change
    # tried from inside; and pds_set_radius_* from inside the progress callback.
    "field_progress": radius_factor(0, 8) + [50] + radius_fn(radius_factor(0, 9), R_2, F_SMOOTH)
    + progress(2, 3, 9) + op(RUN_TO_END, RESUME) + op(CREATE) + radius_factor(0, 8) + [51]
    + radius_map(1, [2, 2], M_GRAD_Y, radius_factor(0, 9), R_2) + progress(2, 0, 10) + op(RUN_TO_END),
    # Fixed in 1.3 (found/NOTES): a first point refused by the field, then a change;
    # and pds_run(s, 0) on a maximal pattern of a field declared with a tiny rmin.
    # A function field 0.02 .. 0.04; bad values everywhere: pds_step refuses the first
    # point (PDS_EINVAL); good values again; pds_set_domain([-0.5, 0.5]^2); to the end:
    # 905 points, a fresh sampler with the same seed, domain and field gives 898.
    "regress_field_first_point_rng": radius_factor(0, 8) + [35] + radius_fn(radius_factor(0, 9), R_2, F_GRAD)
    + field_bad(1) + op(STEP) + field_good() + op(DOMAIN) + domain_absolute(4, 4, 0, 0)
    + op(RUN_TO_END),
    # A function 0.1 everywhere declared in [1e-5, 0.1]: maximal after a bounded run of
    # 1000 (PDS_DONE, 74 points); then pds_run(s, 0) returns PDS_ERANGE (Oler's bound at
    # rmin, 1.2e10 points) instead of PDS_DONE.
    "regress_field_run_maximal_range": radius_factor(0, 8) + [40] + radius_fn(radius_hostile(24), R_1E4, F_CONST)
    + op(RUN) + MAX_NEW_1000 + op(RUN) + MAX_NEW_0,
    # ---- extended operations (the escape byte) ----
    # The determinism check mid-input: after 64 points, after a refine and chunks (the
    # sampler goes on), a selector with no call, then a radius function on the torus.
    "extended_replay": radius_factor(0, 8) + [60] + op(RUN) + MAX_NEW_64 + extended(EXT_REPLAY)
    + op(REFINE) + refine_by(7) + op(RUN_CHUNKS, 3) + extended(EXT_REPLAY) + extended(255)
    + op(CREATE) + radius_factor(0, 8) + [61] + periodic() + radius_fn(radius_factor(0, 9), R_2, F_GRAD)
    + op(RUN) + MAX_NEW_64 + extended(EXT_REPLAY) + op(RUN_TO_END) + extended(EXT_REPLAY),
    # ---- polygon and mask domains (1.4) ----
    # A 12-pointed star with a 7-vertex hole around its centre, to the end (R 0.1).
    "polygon_star_hole": radius_factor(0, 7) + [70]
    + polygon([ring(12, STAR, verts=[2, 1.5] * 6), ring(7, HOLE, REVERSE, verts=[0.5] * 7)])
    + op(FREE_AREA) + op(RUN_TO_END) + op(VERIFY) + op(FREE_AREA) + op(CHECK),
    # Rings of small integers that cross (even-odd), in steps and chunks.
    "polygon_crossing": radius_factor(0, 7) + [71]
    + polygon([ring(6, SCATTER, verts=[(-2, -2), (2, 2), (2, -2), (-2, 2), (0, 3), (1, -3)]),
               ring(4, SCATTER, verts=[(-1, 0), (0, -1), (1, 0), (0, 1)])])
    + op(STEP, 3) + op(RUN_CHUNKS, 3) + op(RUN_TO_END) + op(CHECK),
    # Refused: a ring traced twice, a NaN, two distinct vertices, NULL arrays,
    # decreasing ends, periodic either way round; nrings 0 goes back to the rectangle.
    "polygon_refused": radius_factor(0, 7) + [72]
    + polygon([ring(5, STAR, TWICE, verts=[2] * 5)])
    + polygon([ring(5, STAR, 0, verts=[2] * 5, hostile_at=(2, 0))])
    + polygon([ring(3, SCATTER, verts=[(0, 0), (1, 1), (0, 0)])])
    + polygon([ring(4, SIDES, size=(4, 4))], bad=15) + polygon([ring(4, SIDES, size=(4, 4))], bad=14)
    + polygon([ring(4, SIDES, size=(4, 4)), ring(4, SIDES, size=(4, 4))], bad=13)
    + periodic() + polygon([ring(4, SIDES, size=(4, 4))]) + periodic(1)
    + polygon([ring(8, SIDES, COLLINEAR | CLOSING, size=(4, 4))]) + periodic() + polygon([])
    + periodic() + op(RUN_TO_END) + op(CHECK),
    # A rectangle's sides with collinear runs and a repeated closing vertex at 1e15,
    # a hole touching it at a corner; count mode, then a refine (refused) and a step.
    "polygon_offset_count": radius_factor(0, 7) + [73]
    + polygon([ring(8, SIDES, COLLINEAR | CLOSING | REPEAT, size=(12, 12)),
               ring(4, SIDES, REVERSE, size=(4, 4))], offset=(3, 3)) + count(7)
    + op(RUN_TO_END) + op(VERIFY) + op(REFINE) + refine_by(7) + op(STEP) + op(CHECK),
    # A polygon with a radius function (gradient), a domain set after it (no change),
    # a replay mid-input, then the rectangle again.
    "polygon_field": radius_factor(0, 7) + [74]
    + polygon([ring(10, STAR, verts=[3, 2] * 5)], unit=0)
    + op(DOMAIN) + domain_absolute(0, 0, 0, 0)
    + radius_fn(radius_factor(0, 9), R_2, F_GRAD) + op(RUN) + MAX_NEW_64 + extended(EXT_REPLAY)
    + op(RUN_TO_END) + op(VERIFY) + op(CHECK) + radii(0, SIZE_0, SIZE_N)
    + op(CREATE) + radius_factor(0, 7) + [75] + polygon([ring(6, STAR, verts=[2] * 6)]) + polygon([])
    + op(RUN_TO_END),
    # A mask: an 8 x 8 ring of pixels with diagonal neighbours, to the end; then all
    # out (refused), w = 0, NULL, an overflowing size; a domain after it moves it.
    "mask_ring": radius_factor(0, 8) + [76]
    + mask(8, 8, [0x00, 0x7e, 0x42, 0x5a, 0x5a, 0x42, 0x7e, 0x81]) + mask(3, 3, fill=0)
    + mask(2, 2, fill=1, special=2) + mask(2, 2, fill=1, special=3)
    + op(DOMAIN) + domain_absolute(0, 0, 0, 0) + op(FREE_AREA)
    + op(RUN_TO_END) + op(VERIFY) + op(FREE_AREA) + op(CHECK),
    # A 1 x 1 mask (the rectangle itself), a mask then periodic, w = 0; count mode in a mask.
    "mask_count": radius_factor(0, 7) + [77] + mask(1, 1, fill=1) + periodic()
    + mask(3, 2, [5, 2]) + mask(2, 2, special=0) + mask(5, 4, [0x1f, 0x11, 0x11, 0x1f])
    + count(6) + op(RUN_TO_END) + op(VERIFY) + op(CHECK),
    # A mask with a radius map over its box.
    "mask_field": radius_factor(0, 8) + [78] + mask(4, 4, [0x9, 0x6, 0x6, 0x9])
    + radius_map(1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2) + op(RUN_TO_END) + op(CHECK),
    # ---- threads (1.5) ----
    # The parallel process selected before the first point (3 threads), 1025 refused,
    # then the count changed between chunks and after a refine; the replay selects it
    # on one thread and must give the same bytes.
    "threads_selected": radius_factor(0, 8) + [90] + threads(3) + op(RUN) + MAX_NEW_64
    + threads(6) + threads(2) + op(RUN_CHUNKS, 3) + extended(EXT_REPLAY) + threads(0)
    + op(RUN_TO_END) + op(REFINE) + refine_by(7) + threads(1) + op(RUN_TO_END) + op(CHECK),
    # Single-thread points first: pds_set_threads is PDS_ESTATE (1025: EINVAL or ESTATE),
    # and the run goes on in the single-thread process.
    "threads_after_points": radius_factor(0, 8) + [91] + op(RUN) + MAX_NEW_64 + threads(2)
    + threads(6) + op(RUN_TO_END) + threads(1) + op(CHECK),
    # Count mode and the torus with the parallel process selected after the setters.
    "threads_count_torus": radius_factor(0, 8) + [92] + count(7) + threads(4) + op(RUN_TO_END)
    + op(CREATE) + radius_factor(0, 8) + [93] + periodic() + threads(2) + op(RUN_CHUNKS, 3)
    + op(RUN_TO_END),
    # ---- fixed points (1.4) ----
    # Points inside, on a corner, on a side, given twice and on one line, with
    # clearances of R, R/2, 2R and the radius there; maximal, the clearances kept.
    "fixed_points": radius_factor(0, 8) + [94]
    + fixed([(0, 64, 64), (1, 3, 0), (2, 1, 0), (3, 0, 0), (4, 0, 0), (5, 1, 0)],
            [[7], [1, 8], [1, 32], [0], [2, 1], [1, 4]])
    + op(RUN_CHUNKS, 3) + op(RUN_TO_END) + op(REFINE) + refine_by(7) + op(RUN_TO_END) + op(CHECK),
    # A clearance that covers the square: maximal with no point; a refine, then count mode.
    "fixed_covering": radius_factor(0, 8) + [95] + fixed([(0, 128, 128)], [[3, 0]])
    + op(RUN_TO_END) + op(VERIFY) + op(FREE_AREA) + op(REFINE) + refine_by(7) + op(RUN_TO_END)
    + count(7) + op(RUN_TO_END) + op(CHECK),
    # Refused: xy NULL, a NaN coordinate, a negative clearance, on the torus; a point
    # outside the box refused at the first point, then removed (n = 0) and a run.
    "fixed_refused": radius_factor(0, 8) + [96] + fixed([(0, 1, 1)], xy_null=True)
    + fixed([(0, 1, 1), (8, 1, 0, 0)], [[0], [0]]) + fixed([(0, 1, 1), (0, 2, 2)], [[0], [4]])
    + periodic() + fixed([(0, 9, 9)]) + periodic(1) + fixed([(7, 0, 0)]) + op(STEP) + op(RUN) + [1]
    + fixed([]) + op(RUN_TO_END),
    # A polygon with fixed points on its vertices, under a radius map.
    "fixed_polygon_field": radius_factor(0, 7) + [97]
    + polygon([ring(12, STAR, verts=[2, 1.5] * 6), ring(7, HOLE, REVERSE, verts=[0.5] * 7)])
    + fixed([(6, 0, 0), (6, 0, 3), (6, 0, 12), (0, 100, 100)], [[0], [1, 16], [0], [6]])
    + radius_map(1, [3, 3], M_GRAD_X, radius_factor(0, 9), R_2) + op(RUN_TO_END) + op(CHECK),
    # Fixed in 1.7.10: six fixed points (one given twice), an 8 x 7 mask and a uniform
    # 4 x 7 map, refined before the first point: the map's interpolated value at a fixed
    # point was an ulp off the radius, so the replay by a plain sampler differed in the
    # last bits (raw bytes as the fuzzer found them).
    "regress_fixed_constant_map": list(bytes.fromhex(
        "010006747f04060006b0010126061c4f00030d000240005b7406061b990260003e2d067f023702da5c"
        "a9e50a2da98f01406b8e010009040400040b7f000b0f")),
    # Fixed in 1.7.10: a mask, a radius function and nine fixed points, one at the
    # origin whose clearance is the box's rounded diagonal: the far corner was left free
    # by a hair, no draw could reach it, and the run ended "maximal" with no point
    # (pds_verify: PDS_EINTERNAL). The corner now gets the point (raw bytes).
    "regress_fixed_short_of_a_corner": list(bytes.fromhex(
        "010107c1bf000100090400000000007f0229027ba0b18303b07f0407000202f93901ec05580901b304"
        "05ef070084940294061e680318007e100247021084060426bd01e804820402fd0b0b0c0b0b0b0f")),
    # Fixed in 1.7.10: twenty fixed points at R 1e-5, two clearances covering the unit
    # square: a bounded run ends maximal with no point, and an unbounded run after it
    # said PDS_ERANGE (the bound past the index space) instead of PDS_DONE (raw bytes).
    "regress_fixed_covered_past_the_index_space": list(bytes.fromhex(
        "0104f8577f0407000d015b970600b647013503b62500009a4a0701add50606ae1f070322fa060155df01"
        "a0001a98000159d20006f77101d306f4cf06032a84031101760e011000775d0178059c041a0705a6cf03"
        "8e051a3d0701405c00047008030c0b6c0b0b0f")),
    # Harness, 1.7.10: a fixed point with clearance DBL_MAX, then count mode (53 points):
    # the radius goes down with the clearance until the precision limit, PDS_ERANGE with
    # nothing added, which the harness's count-mode model did not allow (raw bytes).
    "regress_fixed_count_past_precision": list(bytes.fromhex(
        "010008010007477f010100000000000072616469757320660c5e03367f0401000320d707b2ffffffffff"
        "ffffffffffffffffffffffffffffffffffffff732066756e6374696f6e00ffffffffffffffffffffffff"
        "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff75"
        "6e6374696f00800000ae0e092b00010008328f01420202ffffff0400017261646975732066756e637469"
        "6f6e00153f351c00706000000000000000f8000701f8080b0b000008303c3c0b0f0f")),
    # Harness, 1.7.10: a mask over [-DBL_MAX, DBL_MAX] x [2.7e180, DBL_MAX]: the model's
    # pixel lines overflowed (hi - lo), so its box went to inf and a point the library
    # placed inside the mask was judged outside (raw bytes).
    "regress_mask_lines_past_dbl_max": list(bytes.fromhex(
        "01007a4e7f021b020906087a6e61740b0001006143067f03023c7f007f245f616c6c6f338f6301652565"
        "65656565656565015325658f656565655374396261645f616c6c6f63656565656565656565656565c165"
        "7a4e7f021b020906087a6e6374696f6e8f01470101010008055e1c0b0101010008055e1c0b0001006124"
        "5f616c6c6f63328f016525656565656565538f0165256565656565655374396261645f65656565656565"
        "65656565656565c7000000000000006542bf0000c00a070118770000000e046f696e742031363a6f6e8f"
        "01470101010008055e1c0b0101010008055e1c0b0001006103067f03023c7f007f245f616c6c6f338f63"
        "016525656565656565538f0165256565656565657f007f245f616c6c6f338f6301652565656565656553"
        "8f0165256565656565655374396261645f616c6c6f63656565656565656565656565c1657a4e7f021b02"
        "0906087a6e6374696f6e8f01470101010008055e1c0b0101010008055e1c0b00010061245f616c6c6f63"
        "328f01652565030072067e656565650905ae020a0b")),
    # Fixed in 1.7.10: three fixed points near (0.3, 0) on the bottom side of a domain
    # spanning [-DBL_MAX, DBL_MAX]: nearly coincident at that scale, the triangles around
    # them were too thin for the cell centres (PDS_EINTERNAL); within 2^-40 R they are now
    # one disk (raw bytes).
    "regress_fixed_nearly_coincident": list(bytes.fromhex(
        "01010892317f02080225487f04030004706f696e742038333a055e1c0b0001006103067f03023c7f007f"
        "245f616c6c6f63338f016525656565656565538f0165256565656565655374396261645f616c6c6f6365"
        "656565656565654e65657a656565c17f021b020100072e5e03ffffffffffffffff1f7f04")),
    # Fixed in 1.7.10: forty fixed points near a corner of a domain 2e6 x 1e6 at R 0.1, a
    # bounded run of 75 points: pds_free_area summed the huge cells to 1e-7 above the
    # domain's area; it is now capped there (raw bytes).
    "regress_free_area_above_the_domain": list(bytes.fromhex(
        "010207357f0407102101db4f029bf501d1a506e89b00909c06d900be93062a3903d7a506696e0319d502"
        "29fffffffeff01ffffffffffffffffffffffffff0400000000000000ffffffffffffffffffffffffffff"
        "ffffffffffffffffffffffffffffffffffffffffffff220627c5004c81021fd89b22a100a392002aba06"
        "f4ec0411370004df0396a304524205e53600c8d702bb5e03e53f0400040b0b0b0f")),
    # Fixed in 1.5.2 (found/NOTES): a 4 x 4 square (sides with collinear runs) at
    # 1e15 was PDS_EINVAL "encloses nothing": the side probes, 2^-20 of an edge
    # away, rounded onto the edge.
    "regress_polygon_below_resolution": radius_factor(0, 7) + [81]
    + polygon([ring(8, SIDES, size=(12, 12))], offset=(3, 3)) + op(RUN_TO_END),
}

# Reproducers of open library bugs (found/NOTES), written into found/: the harness
# tolerates them unless PDS_FUZZ_STRICT is set, so replay them with
#   PDS_FUZZ_STRICT=1 $(B)/fuzz/fuzz_api tests/fuzz/found/NAME
# Once fixed, each moves into SEEDS as regress_NAME.
FOUND = {
    # A ring that turns straight back along its last edge (a spike of zero width,
    # [2.25, 3] x {0}): pds_run never returns (R 0.1, any seed; the Jones loop keeps
    # drawing in OutlineClip::cut_cell). Replay with -timeout=10.
    "polygon_antenna_hang": radius_factor(0, 7) + [79]
    + polygon([ring(5, SCATTER, verts=[(0, 0), (3, 0), (2.25, 0), (2.25, 1.75), (0, 1.75)])])
    + op(RUN_TO_END),
    # A ring that crosses itself (a bowtie of two triangles, area 2 by the even-odd
    # rule, shoelace area 0): PDS_EINVAL "the outline encloses nothing".
    "polygon_bowtie_refused": radius_factor(0, 7) + [80]
    + polygon([ring(4, SCATTER, verts=[(0, 0), (2, 2), (2, 0), (0, 2)])]) + op(RUN_TO_END),
    # Rings that cross: pds_run(s, 0) returns PDS_DONE with no point (seed 71; after
    # steps, pds_verify says PDS_EINTERNAL: part of the domain near the outline uncovered).
    "polygon_crossing_maximal_early": radius_factor(0, 7) + [71]
    + polygon([ring(6, SCATTER, verts=[(-2, -2), (2, 2), (2, -2), (-2, 3), (0, 1), (2, -3)]),
               ring(4, SCATTER, verts=[(-1, 0), (0, -1), (1, 0), (0, -0.125)])])
    + op(RUN_TO_END) + op(STEP, 3) + op(RUN_CHUNKS, 3),
    # A 5-vertex ring (traced twice) with a vertex at y = 2^53, the others within 2 of
    # the origin: pds_set_polygon asks for 9 GB (standalone: over 24 GB, killed) in
    # PolygonIndex, whose rows, sqrt(cells h / w), have no cap for a tall box.
    # Replay only through the fuzz binary (its -malloc_limit_mb reports it).
    "polygon_index_aspect": radius_factor(0, 7) + [83]
    + polygon([ring(5, STAR, TWICE, verts=[2] * 5, hostile_at=(1, 31))]),
    # The same hang with a spike of width ~1e-16 (a ring's first vertex within rounding of
    # the edge from its second to its third), as the fuzzer found it (raw bytes).
    "polygon_thin_spike_hang": list(bytes.fromhex("010007467f010100000000000000000000001200090000000b00000f000f0b0f0b0f0f0b0f0b0f0b"
        "36010000000003030303030303070b06070f")),
    # Two rings at 1e-271 (a star and a rectangle's sides): PDS_EINVAL "ring 0: its vertices
    # lie on one line" (raw bytes as the fuzzer found them).
    "polygon_tiny_collinear": list(bytes.fromhex("010007477f010180000000007261646975732066756e6374696f6e0810e815000000000008010000"
        "000600f80000f80800000834340b0f")),
    # An 8 x 8 mask, then pds_set_domain(1e15, 0, 1e15 + 0.25, 0.3): PDS_EINVAL ("ring 0:
    # 2 distinct vertices": the pixel lines round together), and the refused rectangle
    # stays: a 1 x 1 mask set next lies at 1e15, where pds_run gives PDS_ERANGE.
    "mask_domain_refused": radius_factor(0, 7) + [82]
    + mask(8, 8, [0x49, 0x92, 0x24, 0x49, 0x92, 0x24, 0x49, 0x92])
    + op(DOMAIN) + domain_relative(1, 0, 7, 0) + mask(1, 1, fill=1) + op(RUN) + [1],
}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    for sub, table in (("corpus", SEEDS), ("found", FOUND)):
        out = os.path.join(here, sub)
        os.makedirs(out, exist_ok=True)
        for name, data in table.items():
            with open(os.path.join(out, name), "wb") as f:
                f.write(bytes(data))


if __name__ == "__main__":
    main()
