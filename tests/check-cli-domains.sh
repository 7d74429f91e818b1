#!/bin/sh
# check-cli-domains.sh - behaviour tests for the shaped domains of the
# poissondisk command-line program: --polygon FILE (GeoJSON or "x y" text,
# even-odd rings), --mask FILE (the dark pixels of a PGM image) and --fixed
# FILE (points already there, with clearances), their pictures, and their
# errors: a malformed file exits 1 naming the file and where, and writes
# nothing.
#
#   sh tests/check-cli-domains.sh build/poissondisk
#
# The patterns are judged by tests/tools/domain_checks.py from the printed
# "x y" lines and the input files alone (its own point-in-polygon, pixel
# lookup and probes), never from the program's report. Small patterns (R =
# 0.02) keep it quick. Ends with "check-cli-domains: N passed, M failed" and
# a non-zero status if anything failed.

set -u

name=check-cli-domains
program=${1:?usage: sh tests/check-cli-domains.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run, lines, usage_case.
. "$(dirname "$0")/cli_cases.sh"
# two_numbers, inside...
. "$(dirname "$0")/pattern_checks.sh"

python=/usr/bin/python3
if [ ! -x "$python" ]; then
    bad "$python is needed to judge the patterns"
    finish
    exit 1
fi
dc() { "$python" "$(dirname "$0")/tools/domain_checks.py" "$@"; }
stat_of() { sed -n "s/^poissondisk: .* $2=\\([^ ]*\\) .*/\\1/p" "$1"; }

# ---- the test files -----------------------------------------------------------------------
# A non-convex outline (a notch down to y = 0.55), a triangular hole, and an islet
# in the notch, each ring closed by repeating its first vertex; the same rings in
# text and in GeoJSON (a Feature of a MultiPolygon), so the same points.
cat > "$tmp/shape.txt" << 'EOF'
# outline, notch from the top
0 0
1 0
1 1
0.5 0.55
0 1
0 0

# the hole
0.3 0.15
0.7 0.15
0.5 0.4
0.3 0.15

0.45 0.9   # the islet
0.55 0.9
0.5 0.8
0.45 0.9
EOF
cat > "$tmp/shape.geojson" << 'EOF'
{"type": "Feature", "properties": {"name": "notched square"},
 "geometry": {"type": "MultiPolygon", "coordinates": [
   [[[0, 0], [1, 0], [1, 1], [0.5, 0.55], [0, 1], [0, 0]],
    [[0.3, 0.15], [0.7, 0.15], [0.5, 0.4], [0.3, 0.15]]],
   [[[0.45, 0.9], [0.55, 0.9], [0.5, 0.8], [0.45, 0.9]]]]}}
EOF
POLY="polygon:$tmp/shape.txt"
# Fixed points: one with the default clearance, an obstacle, one outside the
# domain (in the notch) whose clearance still reaches into it.
cat > "$tmp/fixed.txt" << 'EOF'
0.2 0.3
0.75 0.3 0.12   # an obstacle
0.5 0.6 0.05
EOF
printf '0 0\n1 0\n1 1\n0 1\n' > "$tmp/square.txt"
# A 40 x 30 mask over [0,1.5]x[0,1]: an annulus and a block at the top left (rows
# are written top first), grey levels 0..255 with mid-grey 128 outside.
"$python" - "$tmp/mask.pgm" << 'EOF'
import sys
w, h = 40, 30
rows = []
for j in range(h):
    for i in range(w):
        x, y = (i + 0.5) / w * 1.5, 1 - (j + 0.5) / h
        d = ((x - 0.8) ** 2 + (y - 0.5) ** 2) ** 0.5
        rows.append(20 if 0.15 < d < 0.45 else 127 if (i < 6 and j < 5) else 128)
with open(sys.argv[1], "wb") as f:
    f.write(b"P5\n# annulus and block\n%d %d\n255\n" % (w, h) + bytes(rows))
EOF
MASK="mask:$tmp/mask.pgm:0,0,1.5,1"

# ---- --polygon ---------------------------------------------------------------------------
run poly --radius 0.02 --polygon "$tmp/shape.txt" --verify --stats
expect "--polygon (text) --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--polygon: every line is two numbers" two_numbers "$tmp/poly.out"
expect "--polygon --stats: the bounding box, polygon, maximal and verified" \
    grep -Eq '^poissondisk: N=[0-9]+ R=0\.02 domain=\[0,1\]x\[0,1\] polygon coverage=1\.0+ maximal verified ' \
        "$tmp/poly.err"
expect "--polygon: every point inside the rings (even-odd)" dc inside "$tmp/poly.out" "$POLY"
expect "--polygon: every pair at least R apart" dc spacing "$tmp/poly.out" 0.02 -
expect "--polygon: every probe of the domain and its outline within R of a point" \
    dc covered "$tmp/poly.out" 0.02 "$POLY" - 0.005
area=$(dc area "$POLY")
n=$(lines "$tmp/poly.out")
expect "--polygon --stats: packing pi R^2 N / (4A) with the polygon's area A = $area" \
    awk -v p="$(stat_of "$tmp/poly.err" packing)" -v n="$n" -v a="$area" \
        'BEGIN { want = 3.14159265358979 * 0.0004 * n / (4 * a); exit !(p != "" && (p - want) ^ 2 < 1e-11) }'
expect "--polygon: the islet holds points" \
    eval 'awk "\$2 > 0.8 && \$2 < 0.9 && \$1 > 0.45 && \$1 < 0.55" "$tmp/poly.out" | grep -q .'
# Rings that cross, themselves and each other: a bow tie across a diamond.
printf '0 0\n1 1\n1 0\n0 0.3\n\n0.5 -0.125\n1.125 0.5\n0.5 1.125\n-0.125 0.5\n' > "$tmp/cross.txt"
CROSS="polygon:$tmp/cross.txt"
run cross --radius 0.02 --polygon "$tmp/cross.txt" --verify --stats
expect "--polygon, rings that cross: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/cross.err"'
expect "--polygon, rings that cross: inside (even-odd), spaced, covered" \
    eval 'dc inside "$tmp/cross.out" "$CROSS" && dc spacing "$tmp/cross.out" 0.02 - &&
          dc covered "$tmp/cross.out" 0.02 "$CROSS" - 0.005'
# Rings that meet at vertices a few ulps apart: a square with a hole in its
# corner (the library merges them, so its domain differs from the exact one
# by slivers some 1e-14 wide: no probes of the given outline).
printf '%s\n' '-3.5 -3.5' '-2.5 -3.5' '-2.5 -2.5' '-3.5 -2.5' '' '-3.500000000000016 -3.500000000000007' \
    '-3.5000000000000133 -2.9999999999999867' '-2.8999999999999946 -3.0000000000000133' \
    '-2.9000000000000106 -3.499999999999983' > "$tmp/near.txt"
run near --radius 0.02 --polygon "$tmp/near.txt" --verify --stats
expect "--polygon, rings meeting within rounding: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/near.err"'
expect "--polygon, rings meeting within rounding: inside (even-odd), spaced" \
    eval 'dc inside "$tmp/near.out" "polygon:$tmp/near.txt" && dc spacing "$tmp/near.out" 0.02 -'
# Two unit squares 1000 apart: a grid over their whole box would not fit in
# memory at this radius; the run holds what the squares need.
printf '0 0\n1 0\n1 1\n0 1\n\n1000 1000\n1001 1000\n1001 1001\n1000 1001\n' > "$tmp/far.txt"
run far --radius 0.005 --polygon "$tmp/far.txt" --verify --stats
expect "--polygon, two squares 1000 apart: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/far.err"'
expect "--polygon, two squares 1000 apart: inside, spaced, in both squares" \
    eval 'dc inside "$tmp/far.out" "polygon:$tmp/far.txt" && dc spacing "$tmp/far.out" 0.005 - &&
          [ "$(awk "\$1 > 500" "$tmp/far.out" | wc -l)" -gt 20000 ] &&
          [ "$(awk "\$1 < 500" "$tmp/far.out" | wc -l)" -gt 20000 ]'
# A strip 1e-12 high along the diagonal: far thinner than the outline grid's
# cells, so its first point comes from its slabs, not by rejection over them.
printf '0 0\n1 1\n1 1.000000000001\n0 0.000000000001\n' > "$tmp/strip.txt"
run strip --radius 0.01 --polygon "$tmp/strip.txt" --verify --stats
expect "--polygon, a strip 1e-12 high along the diagonal: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/strip.err"'
expect "--polygon, a strip 1e-12 high along the diagonal: inside, spaced, 70 to 143 points" \
    eval 'dc inside "$tmp/strip.out" "polygon:$tmp/strip.txt" && dc spacing "$tmp/strip.out" 0.01 - &&
          [ "$(wc -l < "$tmp/strip.out")" -gt 70 ] && [ "$(wc -l < "$tmp/strip.out")" -le 143 ]'
# Fixed points on one line, one inside another's clearance (hidden between its
# neighbours in the weighted mesh).
printf '0.67 0.5 0.0155\n0.669 0.5 0.0418\n0.8 0.5 0.0162\n' > "$tmp/online.txt"
run online --radius 0.036 --fixed "$tmp/online.txt" --verify --stats
expect "--fixed on one line, one inside another's clearance: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/online.err"'
# --count past a clearance that covers the square at the first radius.
printf '0.5 0.5 1.0\n' > "$tmp/cover.txt"
run cover --count 3 --fixed "$tmp/cover.txt" --verify --stats
expect "--count 3 with a clearance covering the square: exits 0 with 3 points, verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && [ "$(wc -l < "$tmp/cover.out")" -eq 3 ] && grep -q " verified " "$tmp/cover.err"'
# A clearance that covers the square at one radius: maximal with no point.
run covered --radius 0.05 --fixed "$tmp/cover.txt" --verify --stats
expect "--fixed with a clearance covering the square: exits 0, no point, coverage 1, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && [ ! -s "$tmp/covered.out" ] &&
          grep -Eq "^poissondisk: N=0 .* coverage=1\.0+ maximal verified " "$tmp/covered.err"'
# Fixed points on a mask's pixel lines, computed as X1 * i / w: within rounding
# of the inside pixels' box, they count as on it.
printf '0.0016460905199999999 0.00502654816\n0.00493827156 0.00502654816\n0.00493827156 0.007539822240000001\n0.0016460905199999999 0.007539822240000001\n' > "$tmp/pixline.txt"
printf 'P2\n3 5\n255\n255 255 255\n255 255 255\n255 0 0\n255 255 255\n255 255 255\n' > "$tmp/pixline.pgm"
run pixline --mask "$tmp/pixline.pgm" --domain 0 0 0.00493827156 0.0125663704 --radius 0.000164609052 \
    --fixed "$tmp/pixline.txt" --verify --stats
expect "--fixed on a mask's pixel lines (within rounding of its box): exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " fixed=4 .* maximal verified " "$tmp/pixline.err"'
# A fixed point given twice: one point, the larger clearance.
printf '0.3 0.4 0.05\n0.6 0.6\n0.3 0.4 0.1\n' > "$tmp/twice.txt"
run twice --radius 0.03 --fixed "$tmp/twice.txt" --verify --stats
expect "--fixed with a point given twice: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/twice.err"'
expect "--fixed with a point given twice: every point clear of the larger clearance" \
    eval '[ "$(awk "(\$1 - 0.3) ^ 2 + (\$2 - 0.4) ^ 2 < 0.01" "$tmp/twice.out" | wc -l)" -eq 0 ]'
# A ring 0.02 wide (64-gons of radius 1 and 0.98) under a radius map from
# 0.004 to 0.008: it fills 1/25 of its box, so the field's darts are drawn
# among the cells it meets.
awk 'BEGIN { for (k = 0; k < 64; k++) printf "%.17g %.17g\n", cos(k * atan2(0, -1) / 32), sin(k * atan2(0, -1) / 32)
             print ""
             for (k = 0; k < 64; k++) printf "%.17g %.17g\n", 0.98 * cos(k * atan2(0, -1) / 32), 0.98 * sin(k * atan2(0, -1) / 32) }' \
    > "$tmp/ring.txt"
printf 'P2\n2 1\n255\n0 255\n' > "$tmp/ramp.pgm"
run ringmap --radius-map "$tmp/ramp.pgm" --rmin 0.004 --rmax 0.008 --polygon "$tmp/ring.txt" --verify --stats
expect "--polygon with --radius-map, a thin ring: exits 0, maximal and verified (got $rc)" \
    eval '[ "$rc" -eq 0 ] && grep -q " maximal verified " "$tmp/ringmap.err"'
expect "--polygon with --radius-map, a thin ring: inside, at least rmin apart, 2000 to 8000 points" \
    eval 'dc inside "$tmp/ringmap.out" "polygon:$tmp/ring.txt" && dc spacing "$tmp/ringmap.out" 0.004 - &&
          [ "$(wc -l < "$tmp/ringmap.out")" -gt 2000 ] && [ "$(wc -l < "$tmp/ringmap.out")" -le 8000 ]'
run geo --radius 0.02 --polygon "$tmp/shape.geojson"
expect "--polygon GeoJSON: the same points as the same rings in text" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/poly.out" "$tmp/geo.out"'
run geo7 --radius 0.02 --polygon "$tmp/shape.geojson" --seed 7
expect "--polygon --seed 7: another pattern, inside too" \
    eval '! cmp -s "$tmp/geo.out" "$tmp/geo7.out" && dc inside "$tmp/geo7.out" "$POLY"'
run polycap --radius 0.02 --polygon "$tmp/shape.txt" --max-points 40
head -n 40 "$tmp/poly.out" > "$tmp/poly40.out"
expect "--polygon --max-points 40 prints the first 40 points of the full run" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/poly40.out" "$tmp/polycap.out"'
run polycount --count 400 --polygon "$tmp/shape.txt" --stats
cr=$(sed -n 's/^poissondisk: N=400 R=\([^ ]*\) (chosen for --count) .*/\1/p' "$tmp/polycount.err")
expect "--count 400 --polygon: exactly 400 points (got $rc, $(lines "$tmp/polycount.out"))" \
    eval '[ "$rc" -eq 0 ] && [ "$(lines "$tmp/polycount.out")" -eq 400 ]'
expect "--count 400 --polygon: inside, every pair at least the chosen R='$cr' apart" \
    eval '[ -n "$cr" ] && dc inside "$tmp/polycount.out" "$POLY" && dc spacing "$tmp/polycount.out" "$cr" -'
run polyref --radius 0.04 --refine 0.02 --polygon "$tmp/shape.txt" --verify
expect "--polygon --refine: exits 0, inside, covered at the last radius" \
    eval '[ "$rc" -eq 0 ] && dc inside "$tmp/polyref.out" "$POLY" && dc covered "$tmp/polyref.out" 0.02 "$POLY" - 0.01'

# ---- --fixed -----------------------------------------------------------------------------
run fix --radius 0.02 --polygon "$tmp/shape.txt" --fixed "$tmp/fixed.txt" --verify --stats \
    --svg "$tmp/fix.svg" --png "$tmp/fix.png"
expect "--polygon --fixed --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--fixed --stats: fixed=3, maximal and verified" \
    grep -Eq '^poissondisk: N=[0-9]+ .* polygon fixed=3 coverage=1\.0+ maximal verified ' "$tmp/fix.err"
expect "--fixed: the output holds the N new points only" \
    [ "$(sed -n 's/^poissondisk: N=\([0-9]*\) .*/\1/p' "$tmp/fix.err")" = "$(lines "$tmp/fix.out")" ]
expect "--fixed: inside the polygon" dc inside "$tmp/fix.out" "$POLY"
expect "--fixed: R apart, and each fixed point's clearance kept (none printed)" \
    dc spacing "$tmp/fix.out" 0.02 "$tmp/fixed.txt"
expect "--fixed: every probe within R of a point or in a clearance" \
    dc covered "$tmp/fix.out" 0.02 "$POLY" "$tmp/fixed.txt" 0.005
expect "--fixed: no point in the obstacle's clearance 0.12 (a plain pattern has some)" \
    eval 'awk "(\$1 - 0.75) ^ 2 + (\$2 - 0.3) ^ 2 < 0.0144" "$tmp/poly.out" | grep -q . &&
          ! awk "(\$1 - 0.75) ^ 2 + (\$2 - 0.3) ^ 2 < 0.0144" "$tmp/fix.out" | grep -q .'
expect "--fixed --svg: the outline's rings, the clearances and the fixed points" \
    dc svg "$tmp/fix.svg" "$POLY" "$tmp/fixed.txt" 0.02
expect "--fixed --png: grey outside the polygon, white inside, the points dark" \
    dc png "$tmp/fix.png" "$POLY" "$tmp/fix.out"
# The library scales given clearances with the radius (--refine, --count): the SVG
# draws them at the final radius. Drawn too large, the points break them (spacing);
# drawn too small, the probes between the drawn and the true circle go uncovered.
run fixref --radius 0.04 --refine 0.02 --polygon "$tmp/shape.txt" --fixed "$tmp/fixed.txt" \
    --svg "$tmp/fixref.svg"
printf '0.2 0.3\n0.75 0.3 0.06\n0.5 0.6 0.025\n' > "$tmp/fixed-half.txt"
expect "--fixed --refine 0.04 -> 0.02: the clearances halved, kept and covered" \
    eval '[ "$rc" -eq 0 ] && dc spacing "$tmp/fixref.out" 0.02 "$tmp/fixed-half.txt" &&
          dc covered "$tmp/fixref.out" 0.02 "$POLY" "$tmp/fixed-half.txt" 0.005'
expect "--fixed --refine: the SVG draws the halved clearances" \
    dc svg "$tmp/fixref.svg" "$POLY" "$tmp/fixed-half.txt" 0.02
run fixcount --count 300 --polygon "$tmp/shape.txt" --fixed "$tmp/fixed.txt" --stats \
    --svg "$tmp/fixcount.svg"
fr=$(sed -n 's/^poissondisk: N=300 R=\([^ ]*\) (chosen for --count) .*/\1/p' "$tmp/fixcount.err")
dc clearances "$tmp/fixcount.svg" > "$tmp/fixcount.fixed" 2> /dev/null
expect "--fixed --count 300: 300 points, the SVG's clearances kept by them and covering (R='$fr')" \
    eval '[ "$rc" -eq 0 ] && [ "$(lines "$tmp/fixcount.out")" -eq 300 ] && [ -n "$fr" ] &&
          dc spacing "$tmp/fixcount.out" "$fr" "$tmp/fixcount.fixed" &&
          dc inside "$tmp/fixcount.out" "$POLY"'
run fixsq --radius 0.02 --fixed "$tmp/fixed.txt" --verify
expect "--fixed on the unit square: exit 0, R apart and clearances kept, covered" \
    eval '[ "$rc" -eq 0 ] && dc spacing "$tmp/fixsq.out" 0.02 "$tmp/fixed.txt" &&
          dc covered "$tmp/fixsq.out" 0.02 "polygon:$tmp/square.txt" "$tmp/fixed.txt" 0.01'
printf '# nothing\n\n' > "$tmp/nofixed.txt"
run fixnone --radius 0.02 --fixed "$tmp/nofixed.txt"
run plain --radius 0.02
expect "--fixed with an empty file: the plain pattern" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/plain.out" "$tmp/fixnone.out"'

# ---- --mask ------------------------------------------------------------------------------
run mask --radius 0.02 --mask "$tmp/mask.pgm" --domain 0 0 1.5 1 --verify --stats \
    --svg "$tmp/mask.svg" --png "$tmp/mask.png"
expect "--mask --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--mask --stats: mask, maximal and verified" \
    grep -Eq '^poissondisk: N=[0-9]+ R=0\.02 domain=\[0,1\.5\]x\[0,1\] mask coverage=1\.0+ maximal verified ' \
        "$tmp/mask.err"
expect "--mask: every point in a pixel darker than mid-grey (127 in, 128 out)" \
    dc inside "$tmp/mask.out" "$MASK"
expect "--mask: the block at the top left holds points (the top row is y1)" \
    eval 'awk "\$1 < 0.2 && \$2 > 0.85" "$tmp/mask.out" | grep -q .'
expect "--mask: every pair at least R apart" dc spacing "$tmp/mask.out" 0.02 -
expect "--mask: every probe of the pixels within R of a point" \
    dc covered "$tmp/mask.out" 0.02 "$MASK" - 0.01
expect "--mask --svg: the mask and its pixel outline" dc svg "$tmp/mask.svg" "$MASK" - 0.02
expect "--mask --png: grey outside the pixels, white inside" \
    dc png "$tmp/mask.png" "$MASK" "$tmp/mask.out"

# ---- pictures without a shape stay as they were ----------------------------------------
expect "--fixed only: the box drawn as before (white, outlined), and the fixed group" \
    eval '"$cli" --radius 0.05 --fixed "$tmp/fixed.txt" --svg "$tmp/fsq.svg" > /dev/null &&
          grep -q "<rect id=\"domain\" .* fill=\"white\" stroke=\"black\"" "$tmp/fsq.svg" &&
          grep -q "<g id=\"fixed\"" "$tmp/fsq.svg" && ! grep -q "id=\"outline\"" "$tmp/fsq.svg"'

# ---- options that do not go together, and --help ---------------------------------------
usage_case "--polygon --periodic" '--periodic cannot be used with --polygon: a torus has no outline' \
    --radius 0.02 --polygon "$tmp/shape.txt" --periodic
usage_case "--mask --periodic" '--periodic cannot be used with --mask' \
    --radius 0.02 --mask "$tmp/mask.pgm" --periodic
usage_case "--fixed --periodic" '--periodic cannot be used with --fixed' \
    --radius 0.02 --fixed "$tmp/fixed.txt" --periodic
usage_case "--polygon --mask" '--mask cannot be used with --polygon' \
    --radius 0.02 --polygon "$tmp/shape.txt" --mask "$tmp/mask.pgm"
usage_case "--polygon --domain" "--domain cannot be used with --polygon: the polygon's bounding box" \
    --radius 0.02 --polygon "$tmp/shape.txt" --domain 0 0 2 2
usage_case "--polygon ''" "--polygon: expected a file name, got ''" --radius 0.02 --polygon ''
run help --help
expect "--help lists --polygon, --mask and --fixed" \
    eval 'grep -q "^  --polygon FILE " "$tmp/help.out" && grep -q "^  --mask FILE " "$tmp/help.out" &&
          grep -q "^  --fixed FILE " "$tmp/help.out"'

# ---- malformed files: exit 1, the file and where named, nothing written -------------------
# file_case DESCRIPTION PATTERN ARGS...: the run also asks for --output, --svg and
# --png; none of them may appear, nor anything on stdout.
file_case() {
    f_desc=$1
    f_pattern=$2
    shift 2
    rm -f "$tmp/never.out" "$tmp/never.svg" "$tmp/never.png"
    run file "$@" --output "$tmp/never.out" --svg "$tmp/never.svg" --png "$tmp/never.png"
    expect "$f_desc: exit 1 (got $rc)" [ "$rc" -eq 1 ]
    expect "$f_desc: message matches '$f_pattern'" grep -Eq -- "$f_pattern" "$tmp/file.err"
    expect "$f_desc: no output file, nothing on stdout" \
        eval '[ ! -e "$tmp/never.out" ] && [ ! -e "$tmp/never.svg" ] && [ ! -e "$tmp/never.png" ] && [ ! -s "$tmp/file.out" ]'
}
bad=$tmp/bad
mkdir -p "$bad"
printf '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]\n' > "$bad/unclosed.geojson"
printf '{"type": "Polygon",\n "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0],]]}\n' > "$bad/comma.geojson"
printf '{"type": "Point", "coordinates": [0, 0]}\n' > "$bad/point.geojson"
printf '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0]]]}\n' > "$bad/two.geojson"
printf '{"type": "Polygon", "coordinates": [[[0, 0], [1e999, 0], [1, 1]]]}\n' > "$bad/inf.geojson"
printf '0 0\n1 0\n1 x\n' > "$bad/word.txt"
printf '0 0\n1 0\n1 1 2\n' > "$bad/three.txt"
printf '0 0\n1 0\n1 1\n0 1\n\n2 2\n3 2\n' > "$bad/tworing.txt"
printf '0 0\n1 1\n2 2\n' > "$bad/line.txt"
printf '# nothing but a comment\n\n' > "$bad/empty.txt"
file_case "--polygon, JSON cut short" "--polygon $bad/unclosed.geojson: line 2 column 1: " \
    --radius 0.02 --polygon "$bad/unclosed.geojson"
file_case "--polygon, JSON with a trailing comma" "--polygon $bad/comma.geojson: line 2 column [0-9]+: " \
    --radius 0.02 --polygon "$bad/comma.geojson"
file_case "--polygon, a GeoJSON Point" "--polygon $bad/point.geojson: .*Point" \
    --radius 0.02 --polygon "$bad/point.geojson"
file_case "--polygon, a GeoJSON ring of 2 positions" "--polygon $bad/two.geojson: ring 1: .*3" \
    --radius 0.02 --polygon "$bad/two.geojson"
file_case "--polygon, a GeoJSON coordinate 1e999" "--polygon $bad/inf.geojson: .*finite" \
    --radius 0.02 --polygon "$bad/inf.geojson"
file_case "--polygon, a word for a number" "--polygon $bad/word.txt: line 3: \"x\" is not a number" \
    --radius 0.02 --polygon "$bad/word.txt"
file_case "--polygon, three numbers on a line" "--polygon $bad/three.txt: line 3: expected 2 numbers" \
    --radius 0.02 --polygon "$bad/three.txt"
file_case "--polygon, a text ring of 2 vertices (the library's check, placed at its line)" \
    "--polygon $bad/tworing.txt: line (6|7): .*ring 1" --radius 0.02 --polygon "$bad/tworing.txt"
file_case "--polygon, a ring on one line (encloses nothing)" "--polygon $bad/line.txt: .*ring 0" \
    --radius 0.02 --polygon "$bad/line.txt"
file_case "--polygon, no vertex" "--polygon $bad/empty.txt: no vertices" \
    --radius 0.02 --polygon "$bad/empty.txt"
file_case "--polygon, no such file" "--polygon $bad/missing.txt: cannot open" \
    --radius 0.02 --polygon "$bad/missing.txt"

printf 'P5\n4 2\n255\n' > "$bad/white.pgm"
printf '\377\377\377\377\200\200\200\200' >> "$bad/white.pgm"
printf 'P5\n4 2\n255\n\0\0\0' > "$bad/short.pgm"
printf 'P6\n1 1\n255\n\0\0\0' > "$bad/colour.ppm"
printf 'P2\n2 1\n15\n3 16\n' > "$bad/level.pgm"
file_case "--mask, no pixel darker than mid-grey" "--mask $bad/white.pgm: no pixel is darker than mid-grey" \
    --radius 0.02 --mask "$bad/white.pgm"
file_case "--mask, a truncated raster" "--mask $bad/short.pgm: " --radius 0.02 --mask "$bad/short.pgm"
file_case "--mask, a colour PPM" "--mask $bad/colour.ppm: " --radius 0.02 --mask "$bad/colour.ppm"
file_case "--mask, a grey level above maxval" "--mask $bad/level.pgm: " \
    --radius 0.02 --mask "$bad/level.pgm"

printf '0.5 0.5\n# an obstacle\n0.2 0.2 0.1 7\n' > "$bad/four.txt"
printf '0.5 0.5\n0.5 nan\n' > "$bad/nan.txt"
printf '0.5 0.5 0\n' > "$bad/zero.txt"
printf '0.5 0.5\n\n1.5 0.5\n' > "$bad/outside.txt"
file_case "--fixed, 4 numbers on a line" "--fixed $bad/four.txt: line 3: expected \"x y\" or \"x y clearance\"" \
    --radius 0.02 --fixed "$bad/four.txt"
file_case "--fixed, nan" "--fixed $bad/nan.txt: line 2: " --radius 0.02 --fixed "$bad/nan.txt"
file_case "--fixed, a clearance of 0" "--fixed $bad/zero.txt: line 1: the clearance \"0\" is not > 0" \
    --radius 0.02 --fixed "$bad/zero.txt"
file_case "--fixed, a point outside the bounding box" \
    "--fixed $bad/outside.txt: line 3: the point \(1\.5, 0\.5\) lies outside the domain's bounding box \[0,1\]x\[0,1\]" \
    --radius 0.02 --fixed "$bad/outside.txt"
file_case "--fixed outside the polygon's bounding box" "--fixed $bad/outside.txt: line 3: " \
    --radius 0.02 --polygon "$tmp/shape.txt" --fixed "$bad/outside.txt"
# Inside the mask's rectangle, beyond its dark pixels: a mask's bounding box is
# theirs (the annulus ends in the pixel column ending at x = 1.2375).
printf '1.45 0.5\n' > "$bad/past_mask.txt"
file_case "--fixed beyond the mask's dark pixels" \
    "--fixed $bad/past_mask.txt: line 1: the point \(1\.45, 0\.5\) lies outside the domain's bounding box \[0,1\.2375\]x\[" \
    --radius 0.02 --mask "$tmp/mask.pgm" --domain 0 0 1.5 1 --fixed "$bad/past_mask.txt"
# A bad second file: the first was read, still nothing is written.
file_case "--polygon good, --fixed bad" "--fixed $bad/four.txt: line 3: " \
    --radius 0.02 --polygon "$tmp/shape.txt" --fixed "$bad/four.txt"

# ---- the README's island (make island-picture, make island-data) -----------------------
# Run from the top of the tree: the committed data is what docs/island.py draws, and
# the committed picture what `make island-picture` draws from it.
if [ -f docs/island.py ] && [ -f docs/island.geojson ] && [ -f docs/island.svg ]; then
    expect "docs/island.geojson is what docs/island.py draws" \
        eval '"$python" docs/island.py geojson | cmp -s - docs/island.geojson'
    expect "docs/island.pgm is what docs/island.py draws" \
        eval '"$python" docs/island.py pgm | cmp -s - docs/island.pgm'
    # The Makefile's ISLAND_ARGS.
    run island --polygon docs/island.geojson --radius-map docs/island.pgm --rmin 0.09 \
        --rmax 0.45 --seed 1 --dot-radius 0.05 --svg "$tmp/island.svg" --verify --stats
    expect "the island: exit 0, maximal and verified" \
        eval '[ "$rc" -eq 0 ] && grep -q " polygon coverage=1\.0* maximal verified " "$tmp/island.err"'
    expect "the island: every point on the island or the islet, none in the lake" \
        dc inside "$tmp/island.out" "polygon:docs/island.geojson"
    expect "docs/island.svg is what 'make island-picture' draws now" \
        cmp -s docs/island.svg "$tmp/island.svg"
fi

finish
