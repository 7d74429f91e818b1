#!/bin/sh
# check-cli-threads.sh - the --threads option of the poissondisk program:
# the points are the same bytes for every thread count, and bad counts are
# refused before anything is sampled.
#
#   sh tests/check-cli-threads.sh build/poissondisk
#
# The outputs of --threads 1, 2, 4 and 0 (one per core) are compared with
# cmp, in each mode: the one-radius rectangle, polygon, mask and torus
# (--periodic), and --fixed, whose dart stage uses the threads (with --count
# and --refine too), --radius-map (in the rectangle, in a polygon and on the
# torus, whose darts go on in the free regions with threads), and a radius
# map whose rmax is over 16 rmin. Without --threads the one-radius modes and
# the radius maps run the single-thread process (other points); the map over
# 16:1 has no dart stage and runs on one thread either way (the same points).
# Ends with "check-cli-threads: N passed, M failed" and a non-zero status if
# anything failed.

set -u

name=check-cli-threads
program=${1:?usage: sh tests/check-cli-threads.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run, lines, usage_case.
. "$(dirname "$0")/cli_cases.sh"

# An L-shaped polygon with a square hole, and a 2 x 2 radius map.
printf '0 0\n2 0\n2 1\n1 1\n1 2\n0 2\n\n0.3 0.3\n0.7 0.3\n0.7 0.7\n0.3 0.7\n' > "$tmp/l.txt"
printf 'P2\n2 2\n255\n0 255\n128 64\n' > "$tmp/map.pgm"
# A 6 x 4 mask: dark pixels inside, a notch and a lone pixel.
printf 'P2\n6 4\n255\n0 0 255 0 0 255\n0 0 0 0 0 255\n0 0 0 0 0 255\n255 0 0 0 255 0\n' > "$tmp/mask.pgm"

# same_for_threads LABEL ARGS...: --threads 1 is the reference; --threads 2,
# 4 and 0, --threads=4 and no --threads must write the same bytes.
same_for_threads() {
    s_label=$1
    shift
    run t1 "$@" --threads 1
    expect "$s_label --threads 1 exits 0 (got $rc)" [ "$rc" -eq 0 ]
    expect "$s_label --threads 1 writes points" [ -s "$tmp/t1.out" ]
    for s_t in 2 4 0; do
        run "t$s_t" "$@" --threads "$s_t"
        expect "$s_label: --threads $s_t exits 0 (got $rc)" [ "$rc" -eq 0 ]
        expect "$s_label: --threads $s_t writes the bytes of --threads 1" \
            cmp -s "$tmp/t1.out" "$tmp/t$s_t.out"
    done
    run teq "$@" --threads=4
    expect "$s_label: --threads=4 writes the bytes of --threads 1" cmp -s "$tmp/t1.out" "$tmp/teq.out"
    run tdefault "$@"
    expect "$s_label: no --threads exits 0 (got $rc)" [ "$rc" -eq 0 ]
    if [ "$s_label" != "${s_label#one radius}" ] || [ "$s_label" != "${s_label#field}" ]; then
        # Without --threads, the single-thread process, whose points are
        # others (the selection happens).
        expect "$s_label: no --threads writes other points than the parallel process" \
            sh -c "! cmp -s '$tmp/t1.out' '$tmp/tdefault.out'"
    else
        expect "$s_label: no --threads writes the bytes of --threads 1 (one thread either way)" \
            cmp -s "$tmp/t1.out" "$tmp/tdefault.out"
    fi
}

same_for_threads "one radius: rectangle R 0.01" --radius 0.01 --domain 0 0 2 1 --seed 3
same_for_threads "one radius: --count 3000" --count 3000 --seed 4
same_for_threads "one radius: --refine" --radius 0.03 --refine 0.02 --refine 0.01 --seed 5
same_for_threads "one radius: --periodic" --radius 0.01 --periodic --seed 6
same_for_threads "one radius: --periodic --refine" --radius 0.03 --refine 0.012 --periodic --domain -0.4 0.2 0.9 0.9 --seed 13
same_for_threads "one radius: --periodic --count 3000" --count 3000 --periodic --seed 14
printf '0.5 0.2\n0.55 0.55 0.2\n0.6 0.6 0.01\n' > "$tmp/fixed.txt"
same_for_threads "one radius: --fixed" --fixed "$tmp/fixed.txt" --radius 0.01 --seed 16
same_for_threads "one radius: --polygon --fixed --verify" --polygon "$tmp/l.txt" --fixed "$tmp/fixed.txt" --radius 0.01 --verify --seed 17
same_for_threads "one radius: --fixed --count 3000" --fixed "$tmp/fixed.txt" --count 3000 --seed 18
same_for_threads "one radius: --periodic --verify" --radius 0.005 --periodic --domain 0 0 3 0.7 --verify --seed 15
same_for_threads "field: --radius-map" --radius-map "$tmp/map.pgm" --rmin 0.01 --rmax 0.03 --seed 7
same_for_threads "field: --radius-map --polygon --verify" --radius-map "$tmp/map.pgm" --rmin 0.01 --rmax 0.03 \
    --polygon "$tmp/l.txt" --verify --seed 19
same_for_threads "field: --radius-map --periodic --verify" --radius-map "$tmp/map.pgm" --rmin 0.01 \
    --rmax 0.03 --periodic --verify --seed 20
same_for_threads "field: --radius-map 1:12 --verify" --radius-map "$tmp/map.pgm" --rmin 0.0025 --rmax 0.03 \
    --verify --seed 22
same_for_threads "--radius-map 1:20 --periodic (one thread either way)" --radius-map "$tmp/map.pgm" \
    --rmin 0.003 --rmax 0.06 --periodic --seed 21
same_for_threads "one radius: --polygon" --polygon "$tmp/l.txt" --radius 0.02 --seed 8
same_for_threads "one radius: --polygon --refine" --polygon "$tmp/l.txt" --radius 0.04 --refine 0.02 --seed 9
same_for_threads "one radius: --polygon --count 2000" --polygon "$tmp/l.txt" --count 2000 --seed 10
same_for_threads "one radius: --mask" --mask "$tmp/mask.pgm" --domain 0 0 1.5 1 --radius 0.01 --seed 11
same_for_threads "one radius: --polygon --verify" --polygon "$tmp/l.txt" --radius 0.01 --verify --seed 12
same_for_threads "one radius: --max-points 5000" --radius 0.01 --max-points 5000 --format bin \
    --output /dev/stdout
same_for_threads "one radius: --verify" --radius 0.02 --verify

# ---- bad counts: exit 2, a message naming the option and the text, no output --------
usage_case "--threads -1" "--threads.*'-1'" --radius 0.1 --threads -1
usage_case "--threads 1025" "--threads.*'1025'" --radius 0.1 --threads 1025
usage_case "--threads 4294967297 (2^32 + 1)" "--threads.*'4294967297'" --radius 0.1 \
    --threads 4294967297
usage_case "--threads x" "--threads.*'x'" --radius 0.1 --threads x
usage_case "--threads 1.5" "--threads.*'1\\.5'" --radius 0.1 --threads 1.5
usage_case "--threads ''" "--threads.*''" --radius 0.1 --threads ''
usage_case "--threads without value" 'option --threads needs a value' --radius 0.1 --threads
usage_case "the limit in the message" "from 0 to 1024" --radius 0.1 --threads 5000
run top --radius 0.1 --threads 1024
expect "--threads 1024 (the most) exits 0 (got $rc)" [ "$rc" -eq 0 ]

finish
