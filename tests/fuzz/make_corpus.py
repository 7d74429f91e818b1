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
}


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(bytes(data))


if __name__ == "__main__":
    main()
