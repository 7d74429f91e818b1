#!/bin/sh
# check-cli-field.sh - behaviour tests for the variable radius of the
# poissondisk command-line program: --radius-map FILE with --rmin and --rmax
# (a grey-scale PGM image, black dense, white sparse), --radii (each point's
# radius as a third value), --dot-radius, and what every output and --stats
# make of a map.
#
#   sh tests/check-cli-field.sh build/poissondisk
#
# The test images are written by tests/output_checks.py (pgm), which also
# judges the patterns from the printed "x y r" lines: the radii, the rule (a
# later point keeps out of every earlier point's disk, |p_j - p_i| >= r_i for
# i < j), coverage by the disks (maximality) and the radius the map gives at
# each point; and the files, as in check-cli-output.sh. Run from the top of
# the tree, it also checks that docs/stipple.svg is what `make
# stipple-picture` draws. Ends with "check-cli-field: N passed, M failed" and
# a non-zero status if anything failed.

set -u

name=check-cli-field
program=${1:?usage: sh tests/check-cli-field.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run, lines, usage_case.
. "$(dirname "$0")/cli_cases.sh"
# two_numbers, inside, min_dist_ok, covered...
. "$(dirname "$0")/pattern_checks.sh"

python=/usr/bin/python3
judge="$(dirname "$0")/output_checks.py"
if [ ! -x "$python" ]; then
    bad "$python is needed to write the test images and read the output files"
    finish
    exit 1
fi
py() { "$python" "$judge" "$@"; }

# Every line is three decimal numbers.
three_numbers() {
    awk 'BEGIN { num = "^-?[0-9]+(\\.[0-9]+)?([eE][-+]?[0-9]+)?$"; bad = 0 }
         NF != 3 || $1 !~ num || $2 !~ num || $3 !~ num { bad = 1; exit }
         END { exit bad }' "$1"
}
# The first two columns.
xy_of() { awk '{ print $1, $2 }' "$1"; }

# The test images: a horizontal gradient (grey = column, black at the left) in
# each encoding, the same grey levels; halves black at the top or the bottom; a
# dark blob; a constant grey.
img=$tmp/img
mkdir -p "$img"
for enc in p2 p5 p5-16 p2-comments p5-comments; do
    py pgm "$img/grad-$enc.pgm" hgrad "$enc" 256 4
done
py pgm "$img/top.pgm" topdark p5 16 16
py pgm "$img/bottom.pgm" bottomdark p2 16 16
py pgm "$img/blob.pgm" blob p5 40 30
py pgm "$img/const.pgm" const128 p5 3 2
MAP="--radius-map $img/grad-p5.pgm --rmin 0.01 --rmax 0.04"

# ---- a map run: valid, maximal, verified --------------------------------------------
run grad $MAP --radii --verify --stats
expect "--radius-map --verify --stats exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--radii: every line is three numbers" three_numbers "$tmp/grad.out"
expect "--radius-map: --stats says maximal verified, R=0.01..0.04 (radius map)" \
    grep -Eq '^poissondisk: N=[0-9]+ R=0\.01\.\.0\.04 \(radius map\) .* maximal verified ' \
        "$tmp/grad.err"
expect "--radius-map: radii within [rmin, rmax], the rule between all pairs, disks covering" \
    py field "$tmp/grad.out" 0.01 0.04 0 0 1 1 0.01
expect "--radius-map: the radius at each point is the map's (linear in x, black at the left)" \
    py gradient "$tmp/grad.out" 0.01 0.04 256
expect "--radius-map --stats: packing, min_dist (the rule) and mean_nn in units of the radii" \
    py stats "$tmp/grad.err" "$tmp/grad.out" map 0 0 1 1 0
n=$(lines "$tmp/grad.out")
left=$(awk '$1 < 0.5' "$tmp/grad.out" | wc -l)
expect "--radius-map: black at the left, more points there ($left of $n)" \
    [ "$left" -gt $((2 * (n - left))) ]

run gradplain $MAP
xy_of "$tmp/grad.out" > "$tmp/grad-xy.out"
expect "without --radii the same points as \"x y\" lines" \
    eval '[ "$rc" -eq 0 ] && two_numbers "$tmp/gradplain.out" && cmp -s "$tmp/grad-xy.out" "$tmp/gradplain.out"'
run gradagain $MAP --radii
expect "the same map and seed give the same output" cmp -s "$tmp/grad.out" "$tmp/gradagain.out"
run gradseed $MAP --radii --seed 2
expect "another seed gives another pattern" eval '! cmp -s "$tmp/grad.out" "$tmp/gradseed.out"'

# ---- the encodings of one image give the same pattern -----------------------------------
for enc in p2 p5-16 p2-comments p5-comments; do
    run "enc-$enc" --radius-map "$img/grad-$enc.pgm" --rmin 0.01 --rmax 0.04 --radii
    expect "$enc: the same output as P5 (got $rc)" \
        eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/grad.out" "$tmp/enc-$enc.out"'
done
"$cli" --radius-map - --rmin 0.01 --rmax 0.04 --radii < "$img/grad-p5.pgm" > "$tmp/stdin.out" 2> "$tmp/stdin.err"
rc=$?
expect "--radius-map - reads the image from standard input (got $rc)" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/grad.out" "$tmp/stdin.out"'

# ---- the image's top row is the domain's top (y1) --------------------------------------
run top --radius-map "$img/top.pgm" --rmin 0.01 --rmax 0.04 --radii --verify
above=$(awk '$2 > 0.5' "$tmp/top.out" | wc -l)
below=$(awk '$2 < 0.5' "$tmp/top.out" | wc -l)
expect "a map dark at the top: more points in the upper half ($above against $below; got $rc)" \
    eval '[ "$rc" -eq 0 ] && [ "$above" -gt $((3 * below)) ]'
expect "a map dark at the top: radius rmin at the top edge, rmax at the bottom edge" \
    eval 'awk '\''function off(a, b) { return a - b > 1e-12 || b - a > 1e-12 }
                ($2 > 0.97 && off($3, 0.01)) || ($2 < 0.03 && off($3, 0.04)) { bad = 1 }
                END { exit bad }'\'' "$tmp/top.out"'
run bottom --radius-map "$img/bottom.pgm" --rmin 0.01 --rmax 0.04 --radii --verify
above=$(awk '$2 > 0.5' "$tmp/bottom.out" | wc -l)
below=$(awk '$2 < 0.5' "$tmp/bottom.out" | wc -l)
expect "a map dark at the bottom: more points in the lower half ($below against $above)" \
    eval '[ "$rc" -eq 0 ] && [ "$below" -gt $((3 * above)) ]'

# ---- --stats when the radii span a wide ratio ---------------------------------------------
# One black pixel of four: radii 7e-4 in a quarter, 0.3 elsewhere (about 90000 points).
# The nearest neighbours are searched per group of radii, linear in the points whatever
# the ratio; one grid for all radii searched about (0.3 / 0.0033)^2 cells for each point
# (tens of seconds). The limit is only there to end such a run, far above the work.
printf 'P2\n2 2\n255\n0 255\n255 255\n' > "$img/corner.pgm"
rc=0
timeout 20 "$cli" --radius-map "$img/corner.pgm" --rmin 7e-4 --rmax 0.3 --radii --stats \
    > "$tmp/wide.out" 2> "$tmp/wide.err" || rc=$?
expect "--radius-map with radii 7e-4..0.3 --stats ends (exit $rc; 124 is the 20 s limit)" \
    [ "$rc" -eq 0 ]
expect "--radius-map with radii 7e-4..0.3: --stats matches a k-d tree's nearest neighbours" \
    py stats "$tmp/wide.err" "$tmp/wide.out" map 0 0 1 1 0

# ---- the map spans --domain ---------------------------------------------------------------
run dom --radius-map "$img/blob.pgm" --rmin 0.05 --rmax 0.2 --domain -2 1 2 4 --radii --verify --stats
expect "--radius-map with --domain -2 1 2 4 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--radius-map with --domain: the rule, the radii and coverage of the rectangle" \
    py field "$tmp/dom.out" 0.05 0.2 -2 1 2 4 0.04
expect "--radius-map with --domain: --stats in units of the radii" \
    py stats "$tmp/dom.err" "$tmp/dom.out" map -2 1 2 4 0
# At the ends of the double range (disks pi r^2 over 1e600 or 1e-398 in user units).
for dom in "1e299 -1e300 -1e300 1e300 1e300" "1e-200 0 0 1e-199 1e-199"; do
    xr=${dom%% *}
    xbox=${dom#* }
    # shellcheck disable=SC2086
    run domx --radius-map "$img/blob.pgm" --rmin "$xr" --rmax "$(awk "BEGIN { print 4 * $xr }")" \
        --domain $xbox --radii --stats
    # shellcheck disable=SC2086
    expect "--radius-map on $xbox --stats: finite, in units of the radii (got $rc)" \
        eval '[ "$rc" -eq 0 ] && py stats "$tmp/domx.err" "$tmp/domx.out" map $xbox 0'
done

# ---- a map on the torus ----------------------------------------------------------------
run tor $MAP --periodic --radii --verify
expect "--radius-map --periodic --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--radius-map --periodic: points in [0,1)^2, radii within [rmin, rmax]" \
    awk '$1 < 0 || $1 >= 1 || $2 < 0 || $2 >= 1 || $3 < 0.01 || $3 > 0.04 { bad = 1 } END { exit bad || NR < 100 }' "$tmp/tor.out"
"$cli" --help | tr -s ' \n' ' ' > "$tmp/help.txt"
expect "--help: --radius-map works with --periodic, its limit named" \
    grep -q -- '--radius-map FILE .* with --periodic the map spans the torus, --rmax at most half the shorter side' \
    "$tmp/help.txt"
# Refused for its largest radius: the message names the radii and the half-open torus,
# not the smallest radius as too small.
usage_case "--radius-map --periodic, --rmax over half the side (PDS_ERANGE)" \
    'the radii of --radius-map .*grad-p5\.pgm, 0\.01 to 0\.6, do not suit the periodic domain \[0,1\)x\[0,1\): .*half the shorter period' \
    --radius-map "$img/grad-p5.pgm" --rmin 0.01 --rmax 0.6 --periodic
expect "--radius-map --periodic, --rmax over half the side: not called too small" \
    eval '! grep -q "too small" "$tmp/usage.err"'

# ---- a constant map is the plain sampler ---------------------------------------------------
run const --radius-map "$img/const.pgm" --rmin 0.05 --rmax 0.05
run constplain --radius 0.05
expect "a constant map (rmin = rmax = 0.05) gives the points of --radius 0.05" \
    eval '[ "$rc" -eq 0 ] && [ -s "$tmp/const.out" ] && cmp -s "$tmp/const.out" "$tmp/constplain.out"'
run constradii --radius 0.05 --radii
expect "--radii without a map: R as the third value" \
    eval 'awk '\''$3 != 0.05 { bad = 1 } END { exit bad }'\'' "$tmp/constradii.out"'

# ---- the run options with a map -------------------------------------------------------------
run cap $MAP --radii --max-points 50
head -n 50 "$tmp/grad.out" > "$tmp/grad50.out"
expect "--max-points 50 with a map: the first 50 lines of the whole run" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/grad50.out" "$tmp/cap.out"'
# --refine R2: R2 is the new largest radius, every radius (the old points' too)
# scaled by R2 over the largest; the old points stay first.
run refine $MAP --radii --refine 0.02 --verify --stats
expect "--radius-map --refine 0.02 --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
head -n "$n" "$tmp/refine.out" | awk '{ print $1, $2 }' > "$tmp/refine-xy.out"
expect "--refine with a map keeps the first $n points" cmp -s "$tmp/grad-xy.out" "$tmp/refine-xy.out"
expect "--refine 0.02: the rule and coverage at radii from 0.005 to 0.02" \
    py field "$tmp/refine.out" 0.005 0.02 0 0 1 1 0.005
expect "--refine 0.02: --stats shows the scaled radii" grep -q 'R=0\.005\.\.0\.02 (radius map)' "$tmp/refine.err"

# ---- outputs ----------------------------------------------------------------------------------
mkdir -p "$tmp/fmt"
for f in txt csv json bin npy; do
    run "fmt-$f" $MAP --radii --format "$f" --output "$tmp/fmt/p.$f"
    expect "--radii --format $f exits 0 (got $rc)" [ "$rc" -eq 0 ]
done
expect "--radii --format txt is the default output" cmp -s "$tmp/grad.out" "$tmp/fmt/p.txt"
expect "--radii: csv x,y,r, json [x, y, r], bin triples, npy (N, 3) hold the same values" \
    py formats "$tmp/grad.out" "$tmp/fmt" 0.04 0 0 1 1 0 1
mkdir -p "$tmp/fmt2"
for f in txt csv json bin npy; do
    run "fmt2-$f" $MAP --format "$f" --output "$tmp/fmt2/p.$f"
done
expect "a map without --radii: every format as without a map (json radius: the largest)" \
    py formats "$tmp/gradplain.out" "$tmp/fmt2" 0.04 0 0 1 1 0

run svg $MAP --svg "$tmp/d.svg" --disks
expect "--svg --disks with a map exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--svg --disks with a map: each disk of its point's radius r/2, dots of rmin/8" \
    py svg "$tmp/d.svg" "$tmp/grad.out" 0.04 0 0 1 1 1 0 1 0.00125
expect "--svg with a map: the title names the radius map" \
    grep -q '<title>poissondisk: [0-9]* points, radius map from 0.01 to 0.04,' "$tmp/d.svg"
run svgdot $MAP --svg "$tmp/dot.svg" --dot-radius 0.003
expect "--dot-radius 0.003: every dot of that radius" \
    py svg "$tmp/dot.svg" "$tmp/grad.out" 0.04 0 0 1 1 0 0 1 0.003
run svgplain --radius 0.05 --svg "$tmp/p.svg" --dot-radius 0.01
expect "--dot-radius without a map too" \
    py svg "$tmp/p.svg" "$tmp/constplain.out" 0.05 0 0 1 1 0 0 0 0.01
run png $MAP --png "$tmp/m.png" --size 256 --dot-radius 0.004
expect "--png with a map: a dark pixel under every point" \
    py png "$tmp/m.png" "$tmp/grad.out" 0 0 1 1 256 256
run spec $MAP --spectrum "$tmp/s.png" --spectrum-csv "$tmp/s.csv" --spectrum-plot "$tmp/s.svg" \
    --size 64 --patterns 2
expect "the spectrum outputs with a map (2 patterns) exit 0 (got $rc)" [ "$rc" -eq 0 ]
expect "the spectrum with a map: frequency_r in units of rmin (1 at 1/0.01)" \
    grep -q '^100,1,' "$tmp/s.csv"
expect "the spectrum with a map: the plot" py plot "$tmp/s.svg"

# ---- images that are not valid PGM: exit 1, the file and the reason, nothing on stdout -------
# bad_case DESCRIPTION PATTERN PRINTF-FORMAT: the image printf writes.
bad_case() {
    printf "$3" > "$tmp/bad.pgm"
    run badimg --radius-map "$tmp/bad.pgm" --rmin 0.01 --rmax 0.04
    expect "$1: exit 1 (got $rc)" [ "$rc" -eq 1 ]
    expect "$1: message names the file and matches '$2'" \
        grep -Eq -- "^poissondisk: --radius-map $tmp/bad.pgm: .*$2" "$tmp/badimg.err"
    expect "$1: nothing on stdout" [ ! -s "$tmp/badimg.out" ]
}
bad_case "an empty file" 'the file is empty' ''
bad_case "a text file" 'not a PGM image' 'hello\n'
bad_case "P6 (PPM)" 'PPM image \(P6\), not a grey-scale PGM' 'P6\n2 2\n255\n'
bad_case "P4 (PBM)" 'PBM image \(P4\)' 'P4\n2 2\n'
bad_case "P5x" 'not a PGM image: P5 followed by' 'P5x 2 2 255\n'
bad_case "the magic alone" 'ends before the width' 'P5\n'
bad_case "no maxval" 'ends before maxval' 'P5\n4 4\n'
bad_case "a word for the height" "expected the height, a decimal number, found 'x'" 'P2\n4 x\n255\n'
bad_case "a negative width" "expected the width, a decimal number, found '-'" 'P2\n-4 4\n255\n'
bad_case "a width of 0" 'image is empty \(0 x 4 pixels\)' 'P5\n0 4\n255\n'
bad_case "a height of 0" 'image is empty \(4 x 0 pixels\)' 'P2\n4 0\n255\n'
bad_case "an oversized image" 'too large: 100000 x 100000 pixels' 'P5\n100000 100000\n255\n'
bad_case "a width that overflows" 'the width is too large' 'P5\n99999999999999999999999 4\n255\n'
bad_case "maxval 0" 'maxval 0 is out of range' 'P5\n2 2\n0\n\0\0\0\0'
bad_case "maxval 65536" 'maxval 65536 is out of range' 'P5\n2 2\n65536\n'
bad_case "P5 with no pixels" 'ends after 0 of 16 pixels \(truncated\)' 'P5\n4 4\n255\n'
bad_case "a truncated P5" 'ends after 3 of 16 pixels \(truncated\)' 'P5\n4 4\n255\nabc'
bad_case "a truncated 16-bit P5" 'ends after 1 of 4 pixels' 'P5\n2 2\n1000\n\001\002\003'
bad_case "a truncated P2" 'ends before the pixel at row 2, column 2' 'P2\n2 2\n255\n1 2 3'
bad_case "a word among P2 pixels" "expected the pixel at row 2, column 1 .*found 'z'" 'P2\n2 2\n255\n1 2 z 4\n'
bad_case "a P2 pixel above maxval" 'row 2, column 2 is 300, above maxval 255' 'P2\n2 2\n255\n1 2 3 300\n'
bad_case "a P5 pixel above maxval" 'row 1, column 2 is 200, above maxval 100' 'P5\n2 1\n100\n\001\310'
bad_case "a 16-bit pixel above maxval" 'is 1001, above maxval 1000' 'P5\n1 1\n1000\n\003\351'
run nofile --radius-map "$tmp/no-such.pgm" --rmin 0.01 --rmax 0.04
expect "a missing file: exit 1 and the system's reason (got $rc)" \
    eval '[ "$rc" -eq 1 ] && grep -q "no-such.pgm: cannot read it: " "$tmp/nofile.err"'
run dir --radius-map "$tmp" --rmin 0.01 --rmax 0.04
expect "a directory: exit 1 and a message (got $rc)" \
    eval '[ "$rc" -eq 1 ] && grep -q "^poissondisk: --radius-map $tmp: " "$tmp/dir.err"'
head -c 4096 /dev/urandom > "$tmp/noise.pgm" 2> /dev/null
run noise --radius-map "$tmp/noise.pgm" --rmin 0.01 --rmax 0.04
expect "random bytes: exit 1 and a message (got $rc)" \
    eval '[ "$rc" -eq 1 ] && grep -q "^poissondisk: --radius-map " "$tmp/noise.err"'
# Prefixes of a valid image are truncated ones (but a P2 image cut inside its
# last number, "...255" cut to "...25", is valid: P2 needs no blank at its end).
size=$(wc -c < "$img/grad-p2.pgm")
for cut in 1 2 3 8 12 100 $((size / 2)) $((size - 5)); do
    head -c "$cut" "$img/grad-p2.pgm" > "$tmp/cut.pgm"
    run cut --radius-map "$tmp/cut.pgm" --rmin 0.01 --rmax 0.04
    expect "the first $cut bytes of a P2 image: exit 1 and a message (got $rc)" \
        eval '[ "$rc" -eq 1 ] && grep -q "^poissondisk: --radius-map " "$tmp/cut.err"'
done
size=$(wc -c < "$img/grad-p5-16.pgm")
for cut in 5 14 15 $((size / 2)) $((size - 1)); do
    head -c "$cut" "$img/grad-p5-16.pgm" > "$tmp/cut.pgm"
    run cut --radius-map "$tmp/cut.pgm" --rmin 0.01 --rmax 0.04
    expect "the first $cut bytes of a 16-bit P5 image: exit 1 and a message (got $rc)" \
        eval '[ "$rc" -eq 1 ] && grep -q "^poissondisk: --radius-map " "$tmp/cut.err"'
done

# ---- command lines refused: exit 2, a message, the usage, nothing on stdout -----------------
G=$img/grad-p5.pgm
usage_case "--radius-map with --count" '--count cannot be used with --radius-map' \
    --radius-map "$G" --rmin 0.01 --rmax 0.04 --count 100
usage_case "--count with --radius-map" '--radius-map cannot be used with --count' \
    --count 100 --radius-map "$G" --rmin 0.01 --rmax 0.04
usage_case "--radius-map with --radius" '--radius cannot be used with --radius-map' \
    --radius-map "$G" --rmin 0.01 --rmax 0.04 --radius 0.05
usage_case "--radius with --radius-map" '--radius-map cannot be used with --radius' \
    --radius 0.05 --radius-map "$G" --rmin 0.01 --rmax 0.04
usage_case "--radius-map without --rmin and --rmax" '--radius-map needs --rmin and --rmax' \
    --radius-map "$G"
usage_case "--radius-map without --rmax" '--radius-map needs --rmin and --rmax' \
    --radius-map "$G" --rmin 0.01
usage_case "--rmin without --radius-map" '--rmin needs --radius-map' --radius 0.05 --rmin 0.01
usage_case "--rmax without --radius-map" '--rmax needs --radius-map' --radius 0.05 --rmax 0.01
usage_case "--rmin above --rmax" '--rmin 0\.05 is larger than --rmax 0\.01' \
    --radius-map "$G" --rmin 0.05 --rmax 0.01
usage_case "--rmin 0" "--rmin.*'0'" --radius-map "$G" --rmin 0 --rmax 0.01
usage_case "--rmax -1" "--rmax.*'-1'" --radius-map "$G" --rmin 0.01 --rmax -1
usage_case "--rmin nan" "--rmin.*'nan'" --radius-map "$G" --rmin nan --rmax 0.01
usage_case "--radius-map ''" "--radius-map.*''" --radius-map '' --rmin 0.01 --rmax 0.04
usage_case "--radius-map without a value" 'option --radius-map needs a value' --radius-map
usage_case "--radius-map with --spectrum-from" '--radius-map cannot be used with --spectrum-from' \
    --radius-map "$G" --rmin 0.01 --rmax 0.04 --spectrum-from "$tmp/x.txt" --spectrum-csv "$tmp/x.csv"
usage_case "--radii with --spectrum-from" '--radii cannot be used with --spectrum-from' \
    --radius 0.05 --spectrum-from "$tmp/x.txt" --spectrum-csv "$tmp/x.csv" --radii
usage_case "--radii=1" '--radii takes no value' --radius 0.05 --radii=1
usage_case "--dot-radius without a picture" '--dot-radius needs --svg or --png' \
    --radius 0.05 --dot-radius 0.01
usage_case "--dot-radius 0" "--dot-radius.*'0'" --radius 0.05 --svg "$tmp/x.svg" --dot-radius 0
usage_case "--refine above --rmax" '--refine 0\.05 is larger than the radius before it, 0\.04' \
    --radius-map "$G" --rmin 0.01 --rmax 0.04 --refine 0.05
# The constant image (grey 128) has no white pixel: its largest radius,
# 0.05 + 0.15 * 128/255, is below --rmax.
usage_case "--refine above the map's largest radius" \
    "--refine 0\\.15 is larger than the largest radius of --radius-map .*const\\.pgm, 0\\.125294" \
    --radius-map "$img/const.pgm" --rmin 0.05 --rmax 0.2 --refine 0.15
# The library judges the smallest radius against the domain (PDS_ERANGE): exit 2.
usage_case "--rmin 1e-9 (PDS_ERANGE)" \
    'the smallest radius of --radius-map .*, 1e-09, is too small for the domain \[0,1\]x\[0,1\]' \
    --radius-map "$G" --rmin 1e-9 --rmax 0.04

# ---- the stippling picture of the README ----------------------------------------------------
# `make stipple-picture` runs this command; the picture committed must be its output.
if [ -f docs/stipple.pgm ] && [ -f docs/stipple.svg ]; then
    run stipple --radius-map docs/stipple.pgm --rmin 0.004 --rmax 0.03 --seed 1 \
        --svg "$tmp/stipple.svg" --dot-radius 0.002 --verify --stats
    expect "the stippling example verifies (got $rc)" \
        eval '[ "$rc" -eq 0 ] && grep -q "maximal verified" "$tmp/stipple.err"'
    expect "docs/stipple.svg is what 'make stipple-picture' draws now" \
        cmp -s docs/stipple.svg "$tmp/stipple.svg"
fi

finish
