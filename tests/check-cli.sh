#!/bin/sh
# check-cli.sh - behaviour tests for the poissondisk command-line program.
#
#   sh tests/check-cli.sh build/poissondisk
#
# Each check runs the program, then judges its exit status, stdout and stderr
# with standard tools (awk, cmp, grep). Geometric facts (distances, bounds,
# point counts) are recomputed here from the printed numbers rather than
# taken from the program's own report. Ends with "check-cli: N passed, M failed"
# and a non-zero status if anything failed.

set -u

name=check-cli
program=${1:?usage: sh tests/check-cli.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run NAME ARGS...: run the program; stdout in $tmp/NAME.out, stderr in
# $tmp/NAME.err, exit status in $rc.
run() {
    r_name=$1
    shift
    "$cli" "$@" > "$tmp/$r_name.out" 2> "$tmp/$r_name.err"
    rc=$?
}

lines() { wc -l < "$1" | tr -d ' '; }

# Every line is exactly two decimal floating-point numbers.
two_numbers() {
    awk 'BEGIN { num = "^-?[0-9]+(\\.[0-9]+)?([eE][-+]?[0-9]+)?$"; bad = 0 }
         NF != 2 || $1 !~ num || $2 !~ num { bad = 1; exit }
         END { exit bad }' "$1"
}

# inside FILE X0 Y0 X1 Y1: every point lies in the closed rectangle.
inside() {
    awk -v x0="$2" -v y0="$3" -v x1="$4" -v y1="$5" '
        $1 < x0 + 0 || $1 > x1 + 0 || $2 < y0 + 0 || $2 > y1 + 0 { bad = 1; exit }
        END { exit bad }' "$1"
}

# min_dist_ok FILE R: brute force over all pairs, every pair at least R apart.
# The tolerance only absorbs awk's rounding when printing/reading; a pair
# genuinely closer than R by more than 1e-12 relative fails.
min_dist_ok() {
    awk -v r="$2" '
        { x[NR] = $1; y[NR] = $2 }
        END {
            r2 = r * r * (1 - 1e-12)
            for (i = 1; i <= NR; i++)
                for (j = i + 1; j <= NR; j++) {
                    dx = x[i] - x[j]; dy = y[i] - y[j]
                    if (dx * dx + dy * dy < r2) {
                        printf "points %d and %d closer than %s\n", i, j, r > "/dev/stderr"
                        exit 1
                    }
                }
        }' "$1"
}

# covered FILE R X0 Y0 X1 Y1 STEP: every probe of a STEP grid over the
# rectangle is within R of some point (a necessary condition for maximality,
# checked independently of the library).
covered() {
    awk -v r="$2" -v x0="$3" -v y0="$4" -v x1="$5" -v y1="$6" -v h="$7" '
        { x[NR] = $1; y[NR] = $2 }
        END {
            r2 = r * r
            nx = int((x1 - x0) / h + 0.5); ny = int((y1 - y0) / h + 0.5)
            for (a = 0; a <= nx; a++)
                for (b = 0; b <= ny; b++) {
                    px = x0 + (x1 - x0) * a / nx; py = y0 + (y1 - y0) * b / ny
                    hit = 0
                    for (i = 1; i <= NR && !hit; i++) {
                        dx = x[i] - px; dy = y[i] - py
                        if (dx * dx + dy * dy <= r2) hit = 1
                    }
                    if (!hit) {
                        printf "probe (%g, %g) is farther than %s from every point\n",
                               px, py, r > "/dev/stderr"
                        exit 1
                    }
                }
        }' "$1"
}

# between N LO HI (integers)
between() { [ "$1" -ge "$2" ] && [ "$1" -le "$3" ]; }

# ---- --help and --version ---------------------------------------------------------
run help --help
expect "--help exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--help prints usage with --radius to stdout" grep -q -- '--radius' "$tmp/help.out"
expect "--help prints nothing on stderr" [ ! -s "$tmp/help.err" ]

run version --version
expect "--version exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--version prints 'poissondisk MAJOR.MINOR.PATCH'" \
    grep -Eqx 'poissondisk [0-9]+\.[0-9]+\.[0-9]+' "$tmp/version.out"
expect "--version prints one line" [ "$(lines "$tmp/version.out")" -eq 1 ]

# ---- a small run ----------------------------------------------------------------
run base --radius 0.05
n=$(lines "$tmp/base.out")
expect "--radius 0.05 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--radius 0.05: every line is two numbers" two_numbers "$tmp/base.out"
# Maximal means the disks of radius R cover the square: N >= 1/(pi R^2) = 127.3.
# Disks of radius R/2 cannot overlap and lie in the square grown by R/2, so by
# the hexagonal packing density N <= (1+R)^2 * 4 / (sqrt(12) R^2) = 509.2.
expect "--radius 0.05: N=$n within the covering/packing bounds [128, 509]" \
    between "$n" 128 509
expect "--radius 0.05: all points in the unit square" inside "$tmp/base.out" 0 0 1 1
expect "--radius 0.05: every pair at least 0.05 apart" min_dist_ok "$tmp/base.out" 0.05
expect "--radius 0.05: no grid probe farther than R from all points" \
    covered "$tmp/base.out" 0.05 0 0 1 1 0.02

run eqform --radius=0.05 --seed=1
expect "--radius=0.05 --seed=1 gives the same points as the defaults" \
    cmp -s "$tmp/base.out" "$tmp/eqform.out"

run same --radius 0.05 --seed 1
expect "the same seed gives identical output" cmp -s "$tmp/base.out" "$tmp/same.out"

run other --radius 0.05 --seed 2
expect "--seed 2 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "a different seed gives different output" \
    eval '! cmp -s "$tmp/base.out" "$tmp/other.out"'

run bigseed --radius 0.05 --seed 18446744073709551615
expect "--seed 2^64-1 is accepted (got $rc)" [ "$rc" -eq 0 ]

# ---- --domain ---------------------------------------------------------------------
run dom --radius 0.1 --domain -2 1 3 2.5
expect "--domain -2 1 3 2.5 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--domain: every line is two numbers" two_numbers "$tmp/dom.out"
expect "--domain: all points inside [-2,3]x[1,2.5]" inside "$tmp/dom.out" -2 1 3 2.5
expect "--domain: every pair at least 0.1 apart" min_dist_ok "$tmp/dom.out" 0.1
# Covering is the check that the points fill the rectangle, not the unit square.
expect "--domain: the points cover the whole rectangle" \
    covered "$tmp/dom.out" 0.1 -2 1 3 2.5 0.05

run domeq --radius 0.1 --domain=-2 1 3 2.5
expect "--domain=X0 Y0 X1 Y1 works like --domain X0 Y0 X1 Y1" \
    cmp -s "$tmp/dom.out" "$tmp/domeq.out"

# ---- --max-points -------------------------------------------------------------------
run cap --radius 0.05 --max-points 10
expect "--max-points 10 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--max-points 10 prints exactly 10 lines (got $(lines "$tmp/cap.out"))" \
    [ "$(lines "$tmp/cap.out")" -eq 10 ]
head -n 10 "$tmp/base.out" > "$tmp/base10.out"
expect "--max-points 10 prints the first 10 points of the full run" \
    cmp -s "$tmp/base10.out" "$tmp/cap.out"

# ---- --refine ---------------------------------------------------------------------
run refine --radius 0.05 --refine 0.03
m=$(lines "$tmp/refine.out")
expect "--refine 0.03 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--refine 0.03 gives more points ($m) than without ($n)" [ "$m" -gt "$n" ]
head -n "$n" "$tmp/refine.out" > "$tmp/refine-head.out"
expect "--refine keeps the first $n points unchanged" \
    cmp -s "$tmp/base.out" "$tmp/refine-head.out"
expect "--refine: every pair at least 0.03 apart" min_dist_ok "$tmp/refine.out" 0.03
expect "--refine: no grid probe farther than 0.03 from all points" \
    covered "$tmp/refine.out" 0.03 0 0 1 1 0.02

run refine2 --radius 0.05 --refine 0.04 --refine 0.03 --max-points 400 --verify --stats
expect "two --refine stages and a cap exit 0 (got $rc)" [ "$rc" -eq 0 ]
expect "the cap holds across --refine stages (got $(lines "$tmp/refine2.out"))" \
    [ "$(lines "$tmp/refine2.out")" -le 400 ]
expect "--stats reports the last --refine radius" grep -q 'R=0\.03 ' "$tmp/refine2.err"

# ---- --verify --stats ---------------------------------------------------------------
run stats --radius 0.05 --verify --stats
expect "--verify --stats exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--verify --stats does not change the points" cmp -s "$tmp/base.out" "$tmp/stats.out"
expect "--stats prints exactly one line on stderr" [ "$(lines "$tmp/stats.err")" -eq 1 ]
expect "--stats line says maximal and verified" \
    grep -Eq '^poissondisk: .* maximal verified ' "$tmp/stats.err"
expect "--stats line gives N=$n, R=0.05 and full coverage" \
    grep -Eq "N=$n R=0\\.05 domain=\\[0,1\\]x\\[0,1\\] coverage=1\\.0+ " "$tmp/stats.err"

run capstats --radius 0.05 --max-points 10 --verify --stats
expect "--max-points 10 --verify --stats exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--stats says 'not maximal' under a cap" grep -q 'N=10 .* not maximal verified' \
    "$tmp/capstats.err"

run nostats --radius 0.05 --stats
expect "--stats without --verify does not say verified" \
    eval '! grep -q verified "$tmp/nostats.err"'

# ---- bad arguments: exit 2, a message naming the option and the text, no output -----
# usage_case DESCRIPTION PATTERN ARGS...: exit 2, stderr matches PATTERN (grep -E).
usage_case() {
    u_desc=$1
    u_pattern=$2
    shift 2
    run usage "$@"
    expect "$u_desc: exit 2 (got $rc)" [ "$rc" -eq 2 ]
    expect "$u_desc: message matches '$u_pattern'" grep -Eq -- "$u_pattern" "$tmp/usage.err"
    expect "$u_desc: nothing on stdout" [ ! -s "$tmp/usage.out" ]
}
usage_case "no --radius" '--radius' --seed 3
usage_case "--radius -1" "--radius.*'-1'" --radius -1
usage_case "--radius 0" "--radius.*'0'" --radius 0
usage_case "--radius nan" "--radius.*'nan'" --radius nan
usage_case "--radius inf" "--radius.*'inf'" --radius inf
usage_case "--radius abc" "--radius.*'abc'" --radius abc
usage_case "--radius 0.1x" "--radius.*'0\\.1x'" --radius 0.1x
usage_case "--radius without value" '--radius' --radius
usage_case "unknown option" "--bogus" --radius 0.1 --bogus
usage_case "--domain with 3 values" '--domain' --radius 0.1 --domain 0 0 1
usage_case "--domain followed by an option" '--domain' --domain 0 0 1 --radius 0.1
usage_case "--domain with a word" "--domain.*'x'" --radius 0.1 --domain 0 0 1 x
usage_case "--seed -5" "--seed.*'-5'" --radius 0.1 --seed -5
usage_case "--seed 2^64" "--seed.*'18446744073709551616'" --radius 0.1 --seed 18446744073709551616
usage_case "--seed 1.5" "--seed.*'1\\.5'" --radius 0.1 --seed 1.5
usage_case "--max-points 0" "--max-points.*'0'" --radius 0.1 --max-points 0
usage_case "--max-points -3" "--max-points.*'-3'" --radius 0.1 --max-points -3
usage_case "--refine nan" "--refine.*'nan'" --radius 0.1 --refine nan
usage_case "--verify=1" '--verify' --radius 0.1 --verify=1
usage_case "a stray argument" "'extra'" --radius 0.1 extra

# ---- library errors: exit 1, "poissondisk: ...: <library message>" -----------------
lib_case() {
    l_desc=$1
    shift
    run lib "$@"
    expect "$l_desc: exit 1 (got $rc)" [ "$rc" -eq 1 ]
    expect "$l_desc: a 'poissondisk: ...: ...' message" \
        grep -Eq '^poissondisk: [^:]+: .+' "$tmp/lib.err"
    expect "$l_desc: nothing on stdout" [ ! -s "$tmp/lib.out" ]
}
lib_case "--refine larger than --radius" --radius 0.05 --refine 0.1
lib_case "--radius 1e-9 on the unit square (PDS_ERANGE)" --radius 1e-9 --domain 0 0 1 1
lib_case "an inverted --domain" --radius 0.1 --domain 1 0 0 1
lib_case "an empty --domain" --radius 0.1 --domain 0 0 0 1

# ---- write errors -------------------------------------------------------------------
if [ -w /dev/full ]; then
    "$cli" --radius 0.05 > /dev/full 2> "$tmp/full.err"
    rc=$?
    expect "writing to /dev/full exits 1 (got $rc)" [ "$rc" -eq 1 ]
    expect "writing to /dev/full prints an error" grep -q 'poissondisk: ' "$tmp/full.err"
fi

finish
