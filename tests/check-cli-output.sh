#!/bin/sh
# check-cli-output.sh - behaviour tests for the output options of the
# poissondisk command-line program: --format and --output, the pictures
# (--svg, --disks, --png, --size), the spectrum (--spectrum, --patterns,
# --spectrum-plot, --spectrum-csv, --spectrum-from) and the spacing fields of
# --stats.
#
#   sh tests/check-cli-output.sh build/poissondisk
#
# The program's exit status and streams are judged as in check-cli.sh; its
# files are judged by tests/output_checks.py with /usr/bin/python3 (standard
# library: json, csv, xml.etree, zlib, struct; numpy.load too when numpy is
# importable), against the plain "x y" output. The spectrum checks can fail:
# a maximal pattern must show the blue-noise dip and peak, and white noise
# (uniform random points made by output_checks.py, read with
# --spectrum-from) must not. Ends with "check-cli-output: N passed, M
# failed" and a non-zero status if anything failed.

set -u

name=check-cli-output
program=${1:?usage: sh tests/check-cli-output.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run, lines, usage_case.
. "$(dirname "$0")/cli_cases.sh"

python=/usr/bin/python3
judge="$(dirname "$0")/output_checks.py"
if [ ! -x "$python" ]; then
    bad "$python is needed to read the output files"
    finish
    exit 1
fi
# py CHECK ARGS...: one judgement of output_checks.py (its message on stderr).
py() { "$python" "$judge" "$@"; }

# ---- --format and --output ----------------------------------------------------------
# fmt_cases NAME ARGS...: the five formats of one pattern, against its txt output.
fmt_cases() {
    f_name=$1
    shift
    run "$f_name" "$@"
    mkdir -p "$tmp/$f_name.d"
    for f in txt csv json bin npy; do
        run "$f_name-$f" "$@" --format "$f" --output "$tmp/$f_name.d/p.$f"
        expect "$* --format $f --output FILE exits 0 (got $rc)" [ "$rc" -eq 0 ]
        expect "$* --format $f --output FILE: nothing on stdout" [ ! -s "$tmp/$f_name-$f.out" ]
    done
    expect "$*: --format txt gives the default output" \
        cmp -s "$tmp/$f_name.out" "$tmp/$f_name.d/p.txt"
}
fmt_cases square --radius 0.05
expect "csv, json, bin and npy hold the txt points exactly (R=0.05)" \
    py formats "$tmp/square.out" "$tmp/square.d" 0.05 0 0 1 1 0
fmt_cases torus --radius 0.1 --domain -2 1 3 2.5 --periodic --max-points 40
expect "csv, json, bin and npy hold the txt points exactly (periodic, --domain, capped)" \
    py formats "$tmp/torus.out" "$tmp/torus.d" 0.1 -2 1 3 2.5 1
run csvout --radius 0.05 --format csv
expect "--format csv without --output writes to stdout what --output gets" \
    cmp -s "$tmp/csvout.out" "$tmp/square.d/p.csv"
run npyout --radius 0.05 --format=npy
expect "--format npy to a redirected stdout: the same bytes as --output" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/npyout.out" "$tmp/square.d/p.npy"'
# Binary data is refused on a terminal, unless --output is given (script(1) gives
# the program a terminal; skipped where it is missing).
if script -qec true /dev/null < /dev/null > /dev/null 2>&1; then
    script -qec "'$cli' --radius 0.1 --format npy" /dev/null < /dev/null > "$tmp/tty.log" 2>&1
    rc=$?
    expect "--format npy on a terminal: exit 2 (got $rc)" [ "$rc" -eq 2 ]
    expect "--format npy on a terminal: says to use --output" grep -q -- '--output FILE' "$tmp/tty.log"
    script -qec "'$cli' --radius 0.1 --format bin --output '$tmp/tty.bin'" /dev/null < /dev/null \
        > "$tmp/tty2.log" 2>&1
    rc=$?
    expect "--format bin --output FILE on a terminal: exit 0 (got $rc)" \
        eval '[ "$rc" -eq 0 ] && [ -s "$tmp/tty.bin" ]'
fi

# ---- --svg, --disks ---------------------------------------------------------------------
run svg --radius 0.05 --svg "$tmp/p.svg"
expect "--svg exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--svg does not change the points" cmp -s "$tmp/square.out" "$tmp/svg.out"
expect "--svg: valid XML, the domain, one circle per point at (x, y0+y1-y)" \
    py svg "$tmp/p.svg" "$tmp/square.out" 0.05 0 0 1 1 0 0
run disks --radius 0.1 --domain -2 1 3 2.5 --svg "$tmp/d.svg" --disks
expect "--svg --disks exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--svg --disks: a disk of radius R/2 per point, none overlapping (--domain)" \
    py svg "$tmp/d.svg" "$tmp/disks.out" 0.1 -2 1 3 2.5 1 0
run tdisks --radius 0.05 --periodic --svg "$tmp/t.svg" --disks
expect "--periodic --svg: the title gives the half-open domain" \
    grep -q '<title>poissondisk: [0-9]* points, R = 0.05, domain \[0,1)x\[0,1), periodic</title>' \
    "$tmp/t.svg"
expect "--periodic --svg --disks: disks and their copies across the sides" \
    py svg "$tmp/t.svg" "$tmp/tdisks.out" 0.05 0 0 1 1 1 1
if command -v xmllint > /dev/null 2>&1; then
    expect "--svg: xmllint reads the file" xmllint --noout "$tmp/t.svg"
fi

# ---- --png, --size --------------------------------------------------------------------
run png --radius 0.05 --png "$tmp/p.png" --size 300
expect "--png --size 300 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--png: signature, CRCs, 300x300 grey, a dark pixel under every point" \
    py png "$tmp/p.png" "$tmp/square.out" 0 0 1 1 300 300
run pngw --radius 0.05 --domain 0 0 2 1 --png "$tmp/w.png" --size 256
expect "--png of a 2x1 domain keeps the aspect ratio: 256x128" \
    py png "$tmp/w.png" "$tmp/pngw.out" 0 0 2 1 256 128
run pngd --radius 0.1 --png "$tmp/d.png"
expect "--png without --size: 512x512" py png "$tmp/d.png" "$tmp/pngd.out" 0 0 1 1 512 512

# ---- the spectrum ----------------------------------------------------------------------
# A maximal pattern on the torus, 4 patterns: the blue-noise dip and the ring.
run spec --periodic --radius 0.02 --patterns 4 --spectrum "$tmp/s.png" --size 256 \
    --spectrum-csv "$tmp/s.csv" --spectrum-plot "$tmp/s.svg"
expect "--spectrum --patterns 4 exits 0 (got $rc)" [ "$rc" -eq 0 ]
run specplain --periodic --radius 0.02
expect "--spectrum does not change the points (those of the first seed)" \
    cmp -s "$tmp/specplain.out" "$tmp/spec.out"
expect "blue noise: power far below 1 under 0.5/R, a peak above 1.3 near 1/R" \
    py spectrum-csv "$tmp/s.csv" blue 4
expect "blue noise: the PNG is white at f = 0 and dark inside the ring" \
    py spectrum-png "$tmp/s.png" 256 1
expect "--spectrum-plot: an SVG with the two curves" py plot "$tmp/s.svg"
# The same four patterns read back with --spectrum-from give the same numbers.
for s in 1 2 3 4; do "$cli" --periodic --radius 0.02 --seed "$s"; echo; done > "$tmp/own.txt"
run own --radius 0.02 --spectrum-from "$tmp/own.txt" --spectrum-csv "$tmp/own.csv"
expect "--spectrum-from the txt output of seeds 1-4 = --patterns 4 (got $rc)" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/own.csv" "$tmp/s.csv"'
# White noise: 4 patterns of as many uniform points. No dip, no peak.
py white "$tmp/white.txt" 4 1735 11
run white --radius 0.02 --spectrum-from "$tmp/white.txt" --spectrum-csv "$tmp/w.csv" \
    --spectrum "$tmp/w.png" --size 256
expect "--spectrum-from white noise exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "white noise: power about 1 below 0.5/R and near 1/R" py spectrum-csv "$tmp/w.csv" white 4
expect "white noise: the PNG is flat around the centre" py spectrum-png "$tmp/w.png" 256 0
run stdin --radius 0.02 --spectrum-from - --spectrum-csv "$tmp/w2.csv" < "$tmp/white.txt"
expect "--spectrum-from - reads standard input" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/w.csv" "$tmp/w2.csv"'
printf '0.1 0.2\n0.3,0.4\nzzz\n' > "$tmp/badin.txt"
run badin --radius 0.02 --spectrum-from "$tmp/badin.txt" --spectrum-csv "$tmp/x.csv"
expect "--spectrum-from a file with a bad line: exit 1 naming line 3 (got $rc)" \
    eval '[ "$rc" -eq 1 ] && grep -q "line 3: not a point" "$tmp/badin.err"'
run nofile --radius 0.02 --spectrum-from "$tmp/none.txt" --spectrum-csv "$tmp/x.csv"
expect "--spectrum-from a missing file: exit 1 (got $rc)" [ "$rc" -eq 1 ]

# ---- --stats: packing, min_dist and mean_nn recomputed by brute force -----------------
run stats --radius 0.05 --stats
expect "--stats: packing = pi R^2 N / 4A, min_dist and mean_nn as brute force" \
    py stats "$tmp/stats.err" "$tmp/stats.out" 0.05 0 0 1 1 0
run tstats --radius 0.1 --domain -2 1 3 2.5 --periodic --stats
expect "--periodic --stats: the distances wrap around" \
    py stats "$tmp/tstats.err" "$tmp/tstats.out" 0.1 -2 1 3 2.5 1
run stats1 --radius 0.05 --max-points 1 --stats
# A strip far thinner than R: one row of cells, so the search for a nearest
# neighbour must widen along the strip only (widening by the strip's height
# took hours); the timeout turns such a search into a failure.
timeout 120 "$cli" --radius 0.001 --domain 0 0 2 5e-8 --stats > "$tmp/thin.out" 2> "$tmp/thin.err"
rc=$?
expect "--stats on a strip 5e-5 R high: exits 0 (got $rc), figures as brute force" \
    eval '[ "$rc" -eq 0 ] && py stats "$tmp/thin.err" "$tmp/thin.out" 0.001 0 0 2 5e-8 0'
expect "--stats with one point: min_dist=- mean_nn=-" \
    grep -q 'N=1 .* min_dist=- mean_nn=- ' "$tmp/stats1.err"
# At the ends of the double range: squared distances and areas in user units would
# overflow (1e300) or underflow (1e-199); a capped pattern's free area may too, and
# then its coverage is "-". The widest domain the library takes needs its side,
# 3.2e308, computed in scaled units as well.
for case in "1e299 -1e300 -1e300 1e300 1e300" "1e-200 0 0 1e-199 1e-199" \
            "1e307 -1.6e308 -1.6e308 1.6e308 1.6e308"; do
    xr=${case%% *}
    xbox=${case#* }
    for extra in "" --periodic "--max-points 10"; do
        # shellcheck disable=SC2086
        run xstats --radius "$xr" --domain $xbox $extra --stats
        periodic=0
        [ "$extra" = --periodic ] && periodic=1
        # shellcheck disable=SC2086
        expect "--radius $xr --domain $xbox $extra --stats: finite, as brute force (got $rc)" \
            eval '[ "$rc" -eq 0 ] && py stats "$tmp/xstats.err" "$tmp/xstats.out" "$xr" $xbox $periodic'
    done
done

# ---- errors ------------------------------------------------------------------------------
usage_case "--format xml" "--format.*'xml'" --radius 0.1 --format xml
usage_case "--size 0" "--size.*'0'" --radius 0.1 --png "$tmp/x.png" --size 0
usage_case "--size 20000" "--size.*'20000'" --radius 0.1 --size 20000
usage_case "--patterns 0" "--patterns.*'0'" --radius 0.1 --patterns 0
usage_case "--svg ''" "--svg.*''" --radius 0.1 --svg ''
usage_case "--disks without --svg" '--disks needs --svg' --radius 0.1 --disks
usage_case "--patterns without a spectrum output" '--patterns needs --spectrum' \
    --radius 0.1 --patterns 3
usage_case "--spectrum-from without a spectrum output" '--spectrum-from needs --spectrum' \
    --radius 0.1 --spectrum-from "$tmp/white.txt"
usage_case "--spectrum-from with --svg" '--svg cannot be used with --spectrum-from' \
    --radius 0.1 --spectrum-from "$tmp/white.txt" --spectrum-csv "$tmp/x.csv" --svg "$tmp/x.svg"
usage_case "--spectrum-from with --stats" '--stats cannot be used with --spectrum-from' \
    --radius 0.1 --spectrum-from "$tmp/white.txt" --spectrum-csv "$tmp/x.csv" --stats
run outerr --radius 0.1 --output "$tmp/no/such/dir.txt"
expect "--output in a missing directory: exit 1 and a message (got $rc)" \
    eval '[ "$rc" -eq 1 ] && grep -q "cannot write .*no/such/dir.txt" "$tmp/outerr.err"'
run svgerr --radius 0.1 --svg "$tmp/no/such/dir.svg"
expect "--svg in a missing directory: exit 1 and a message (got $rc)" \
    eval '[ "$rc" -eq 1 ] && grep -q "cannot write .*no/such/dir.svg" "$tmp/svgerr.err"'
run specerr --radius 0.1 --spectrum "$tmp/no/such/dir.png"
expect "--spectrum in a missing directory: exit 1 (got $rc)" [ "$rc" -eq 1 ]

finish
