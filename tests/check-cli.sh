#!/bin/sh
# check-cli.sh - behaviour tests for the poissondisk command-line program.
#
#   sh tests/check-cli.sh build/poissondisk
#
# Each check runs the program, then judges its exit status, stdout and stderr
# with standard tools (awk, cmp, grep). Geometric facts (distances, bounds,
# point counts) are recomputed from the printed numbers (pattern_checks.sh)
# rather than taken from the program's own report. Run from the top of the
# tree, it also compares --version with include/poissondisk.h and the options
# with man/poissondisk.1. Checks marked "[core 1.1.1]" need the library
# behaviour of 1.1.1 (see the section "tiny radii"). The run options --count,
# --periodic, --progress and --partial (Ctrl-C) are checked in
# check-cli-features.sh, their argument errors here; the output options
# (--format, --svg, --png, --spectrum...) in check-cli-output.sh, the radius
# map (--radius-map, --rmin, --rmax, --radii, --dot-radius) in
# check-cli-field.sh, --threads in check-cli-threads.sh. Ends with
# "check-cli: N passed, M failed" and a non-zero status if anything failed.

set -u

name=check-cli
program=${1:?usage: sh tests/check-cli.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run, lines, usage_case.
. "$(dirname "$0")/cli_cases.sh"

# The geometric checks: two_numbers, inside, min_dist_ok, covered, min_dist_grid,
# covered_grid.
. "$(dirname "$0")/pattern_checks.sh"

# No line of stdout is a point: --help and --version must not sample.
no_points() { ! grep -Eq '^-?[0-9][0-9.eE+-]* -?[0-9][0-9.eE+-]*$' "$1"; }

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
expect "--version prints nothing on stderr" [ ! -s "$tmp/version.err" ]
# The program links the library statically, so it must report the header's version.
if [ -f include/poissondisk.h ]; then
    hv=$(for f in MAJOR MINOR PATCH; do
             sed -n "s/^#define PDS_VERSION_$f *\([0-9][0-9]*\).*/\1/p" include/poissondisk.h
         done | paste -sd. -)
    expect "--version says 'poissondisk $hv', the version of include/poissondisk.h" \
        grep -qx "poissondisk $hv" "$tmp/version.out"
fi

# help_case NAME ARGS...: --help somewhere in ARGS: exit 0, the same help text
# as plain --help, nothing on stderr, and no pattern printed.
help_case() {
    h_name=$1
    shift
    run "$h_name" "$@"
    expect "$* exits 0 (got $rc)" [ "$rc" -eq 0 ]
    expect "$* prints the same help as --help" cmp -s "$tmp/help.out" "$tmp/$h_name.out"
    expect "$* prints nothing on stderr" [ ! -s "$tmp/$h_name.err" ]
    expect "$* prints no point" no_points "$tmp/$h_name.out"
}
help_case help1 --radius 0.3 --help
help_case help2 --help --radius 0.3
help_case help3 --radius 0.05 --seed 7 --domain 0 0 2 1 --refine 0.04 --max-points 5 \
    --verify --stats --help
help_case help4 --help --bogus extra      # nothing after --help is read
help_case help5 --help --radius -1
help_case help6 --count 5 --periodic --progress --no-progress --partial --help
help_case help7 --help --radius 0.1 --count 5   # a conflict after --help is not read

# version_case NAME ARGS...: likewise for --version.
version_case() {
    v_name=$1
    shift
    run "$v_name" "$@"
    expect "$* exits 0 (got $rc)" [ "$rc" -eq 0 ]
    expect "$* prints the same line as --version" cmp -s "$tmp/version.out" "$tmp/$v_name.out"
    expect "$* prints nothing on stderr" [ ! -s "$tmp/$v_name.err" ]
}
version_case ver1 --radius 0.3 --version
version_case ver2 --version --radius 0.3
version_case ver3 --radius 0.05 --verify --stats --max-points 5 --version
version_case ver4 --version --bogus
version_case ver5 --count 5 --periodic --progress --partial --version
# Left to right: an error before --help or --version still counts.
run helplate --radius abc --help
expect "--radius abc --help: exit 2, the bad value comes first (got $rc)" [ "$rc" -eq 2 ]
expect "--radius abc --help: no help on stdout" [ ! -s "$tmp/helplate.out" ]
run verlate --bogus --version
expect "--bogus --version: exit 2 (got $rc)" [ "$rc" -eq 2 ]

# The help and the parser come from one table: every option the help lists is
# known to the parser, and each has an entry in the manual.
grep -Eo '^  --[a-z-]+' "$tmp/help.out" | tr -d ' ' > "$tmp/help-options"
expect "--help lists the 34 options" [ "$(lines "$tmp/help-options")" -eq 34 ]
sed -n '/^$/q;p' "$tmp/help.out" > "$tmp/help-usage"    # up to the first blank line
while read -r opt; do
    run optknown "$opt"
    expect "$opt, listed by --help, is known to the parser" \
        eval '! grep -q "unknown option" "$tmp/optknown.err"'
    expect "the usage lines show $opt" grep -Eq -- "$opt([] .]|\$)" "$tmp/help-usage"
    if [ -f man/poissondisk.1 ]; then
        expect "man/poissondisk.1 describes $opt" \
            grep -qx "\\.It Fl -${opt#--}.*" man/poissondisk.1
    fi
done < "$tmp/help-options"
run usageonly --bogus
grep -v "^poissondisk: \|^Try " "$tmp/usageonly.err" > "$tmp/error-usage"
expect "an error prints the same usage lines as --help" \
    cmp -s "$tmp/help-usage" "$tmp/error-usage"

# ---- a small run ----------------------------------------------------------------
run base --radius 0.05
n=$(lines "$tmp/base.out")
expect "--radius 0.05 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--radius 0.05: nothing on stderr (not a terminal: no progress line)" \
    [ ! -s "$tmp/base.err" ]
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

run capeq --radius 0.05 --max-points=10
expect "--max-points=10 works like --max-points 10" cmp -s "$tmp/cap.out" "$tmp/capeq.out"

run cap1 --radius 0.05 --max-points 1
expect "--max-points 1 prints the first point (got $rc)" \
    eval '[ "$rc" -eq 0 ] && head -n 1 "$tmp/base.out" | cmp -s - "$tmp/cap1.out"'

run capbig --radius 0.05 --max-points 100000 --stats
expect "a cap above the maximal count changes nothing (got $rc)" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/base.out" "$tmp/capbig.out"'
expect "a cap above the maximal count: --stats says maximal" \
    grep -q "N=$n .* coverage=1\\.0* maximal " "$tmp/capbig.err"

run capexact --radius 0.05 --max-points "$n" --verify --stats
expect "--max-points $n, exactly the maximal count: the whole pattern (got $rc)" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/base.out" "$tmp/capexact.out"'
expect "--max-points $n: --stats says maximal verified" \
    grep -q "N=$n .* coverage=1\\.0* maximal verified" "$tmp/capexact.err"

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

# A cap is a prefix of the uncapped output, also when it ends in a later stage.
for k in 1 $((n + 1)) $((n + 7)); do
    run refcap --radius 0.05 --refine 0.03 --max-points "$k"
    head -n "$k" "$tmp/refine.out" > "$tmp/refine-k.out"
    expect "--refine 0.03 --max-points $k prints the first $k points of --refine 0.03" \
        eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/refine-k.out" "$tmp/refcap.out"'
done

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
# usage_case (cli_cases.sh): exit 2, stderr matches the pattern, nothing on stdout.
usage_case "no --radius" '--radius' --seed 3
usage_case "none of --radius, --count, --radius-map" 'one of --radius, --count or --radius-map is required' --seed 3
usage_case "--radius and --count" '--count cannot be used with --radius' --radius 0.1 --count 5
usage_case "--count and --radius" '--radius cannot be used with --count' --count 5 --radius 0.1
usage_case "--count and --refine" '--refine cannot be used with --count' --count 5 --refine 0.1
usage_case "--count 0" "--count.*'0'" --count 0
usage_case "--count -3" "--count.*'-3'" --count -3
usage_case "--count 1.5" "--count.*'1\\.5'" --count 1.5
usage_case "--count without value" 'option --count needs a value' --count
usage_case "--periodic=1" '--periodic' --radius 0.1 --periodic=1
usage_case "--progress=1" '--progress' --radius 0.1 --progress=1
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
# More bad numbers.
usage_case "--radius ''" "--radius.*''" --radius ''
usage_case "--radius ' 1'" "--radius.*' 1'" --radius ' 1'
usage_case "--radius 1e999 (overflow)" "--radius.*'1e999'" --radius 1e999
usage_case "--radius=-0.5" "--radius.*'-0\\.5'" --radius=-0.5
usage_case "--domain with nan" "--domain.*'nan'" --radius 0.1 --domain 0 nan 1 1
usage_case "--domain with inf" "--domain.*'inf'" --radius 0.1 --domain 0 0 inf 1
usage_case "--domain with 1e999" "--domain.*'1e999'" --radius 0.1 --domain 0 0 1 1e999
usage_case "--seed ''" "--seed.*''" --radius 0.1 --seed ''
usage_case "--seed 0x10" "--seed.*'0x10'" --radius 0.1 --seed 0x10
usage_case "--max-points 1.5" "--max-points.*'1\\.5'" --radius 0.1 --max-points 1.5
usage_case "--max-points abc" "--max-points.*'abc'" --radius 0.1 --max-points abc
usage_case "--max-points 2^64" "--max-points.*'18446744073709551616'" \
    --radius 0.1 --max-points 18446744073709551616
usage_case "--refine 0" "--refine.*'0'" --radius 0.1 --refine 0
usage_case "--refine -0.05" "--refine.*'-0\\.05'" --radius 0.1 --refine -0.05
# Unknown options: no short forms, no abbreviations, names are case-sensitive.
usage_case "-r (short option)" "unknown option '-r'" -r 0.1
usage_case "--rad (abbreviation)" "unknown option '--rad'" --rad 0.1
usage_case "--Radius" "unknown option '--Radius'" --Radius 0.1
usage_case "--bogus=1" "unknown option '--bogus=1'" --radius 0.1 --bogus=1
usage_case "a lone --" "unknown option '--'" --radius 0.1 --
# Missing values.
usage_case "--seed without value" 'option --seed needs a value' --radius 0.1 --seed
usage_case "--refine without value" 'option --refine needs a value' --radius 0.1 --refine
usage_case "--max-points without value" 'option --max-points needs a value' \
    --radius 0.1 --max-points
usage_case "--domain without values" '--domain needs four values .*got none' \
    --radius 0.1 --domain
usage_case "--domain=0 0 followed by an option" '--domain needs four values .*got two' \
    --domain=0 0 --radius 0.1
# Each --refine radius is checked against the one before it, before any sampling.
usage_case "--refine larger than --radius" "--refine 0\\.1 is larger" --radius 0.05 --refine 0.1
usage_case "a second --refine larger than the first" "--refine 0\\.04 is larger" \
    --radius 0.05 --refine 0.03 --refine 0.04

# ---- values the library rejects: exit 2 as well, the library's reason, no output -----
# Rectangles are judged by pds_set_domain (PDS_EINVAL); a radius too small for
# the domain by the library (PDS_ERANGE) when the pair is first used.
usage_case "an inverted --domain" 'domain \[1,0\]x\[0,1\].*empty or inverted' \
    --radius 0.1 --domain 1 0 0 1
usage_case "an empty --domain" 'domain \[0,0\]x\[0,1\]' --radius 0.1 --domain 0 0 0 1
usage_case "an inverted --domain with other options" 'empty or inverted' \
    --radius 0.1 --domain 0 1 1 0 --verify --stats --max-points 3
usage_case "--radius 1e-9 on the unit square (PDS_ERANGE)" \
    'radius 1e-09 is too small for the domain \[0,1\]x\[0,1\]' --radius 1e-9
usage_case "--radius 0.1 far from the origin (PDS_ERANGE)" \
    'radius 0\.1 is too small for the domain' --radius 0.1 --domain 1e300 0 2e300 1
# A maximal pattern at 1e-6 would need ~1e12 points: too many without a cap.
usage_case "--radius 1e-6, no cap (PDS_ERANGE)" 'radius 1e-06 is too small' --radius 1e-6
usage_case "--refine to 1e-9 (PDS_ERANGE)" 'radius 1e-09 is too small' \
    --radius 0.1 --refine 1e-9

# ---- tiny radii: need the 1.1.1 core ------------------------------------------------
# From 1.1.1 on, the library judges the radius against the domain when the pair
# is first used, and a bounded run needs index room only for the points it asks
# for. The 1.1.0 library refuses these radii already in pds_create (PDS_ERANGE,
# exit 2), so the checks marked "[core 1.1.1]" fail until the new core is in.
core="[core 1.1.1]"
run tiny --radius 1e-6 --max-points 1000
expect "$core --radius 1e-6 --max-points 1000 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "$core --radius 1e-6 --max-points 1000 prints 1000 lines (got $(lines "$tmp/tiny.out"))" \
    [ "$(lines "$tmp/tiny.out")" -eq 1000 ]
expect "$core --radius 1e-6: every line is two numbers" two_numbers "$tmp/tiny.out"
expect "$core --radius 1e-6: all points in the unit square" inside "$tmp/tiny.out" 0 0 1 1
expect "$core --radius 1e-6: every pair at least 1e-6 apart" min_dist_ok "$tmp/tiny.out" 1e-6
run tinyv --radius 1e-6 --max-points 1000 --verify --stats
expect "$core --radius 1e-6 --max-points 1000 --verify --stats: the same points" \
    eval '[ "$rc" -eq 0 ] && [ -s "$tmp/tiny.out" ] && cmp -s "$tmp/tiny.out" "$tmp/tinyv.out"'
expect "$core --radius 1e-6 --max-points 1000 --verify --stats: not maximal, verified" \
    grep -q 'N=1000 R=1e-06 .* not maximal verified' "$tmp/tinyv.err"

# The unit-square pattern at R = 0.01 shrunk 1000 times: about 7000 points.
# Covering gives N >= A/(pi R^2) = 3183.1; packing disks of radius R/2 in the
# square grown by R/2 gives N <= (1e-3 + R)^2 * 4 / (sqrt(12) R^2) = 11779.1.
run small --radius 1e-5 --domain 0 0 1e-3 1e-3
m=$(lines "$tmp/small.out")
expect "$core --radius 1e-5 --domain 0 0 1e-3 1e-3 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "$core --radius 1e-5 in [0,1e-3]^2: N=$m within [3184, 11779]" between "$m" 3184 11779
expect "$core --radius 1e-5 in [0,1e-3]^2: all points inside" \
    inside "$tmp/small.out" 0 0 1e-3 1e-3
expect "$core --radius 1e-5 in [0,1e-3]^2: every pair at least 1e-5 apart" \
    min_dist_grid "$tmp/small.out" 1e-5
expect "$core --radius 1e-5 in [0,1e-3]^2: no grid probe farther than R from all points" \
    covered_grid "$tmp/small.out" 1e-5 0 0 1e-3 1e-3 5e-6
run smallv --radius 1e-5 --domain 0 0 1e-3 1e-3 --verify --stats
expect "$core --radius 1e-5 in [0,1e-3]^2 --verify --stats: the same points" \
    eval '[ "$rc" -eq 0 ] && [ -s "$tmp/small.out" ] && cmp -s "$tmp/small.out" "$tmp/smallv.out"'
expect "$core --radius 1e-5 in [0,1e-3]^2: --stats says maximal verified" \
    grep -q "N=$m R=1e-05 domain=\\[0,0\\.001\\]x\\[0,0\\.001\\] coverage=1\\.0* maximal verified" \
        "$tmp/smallv.err"
# A rectangle 1e-200 wide: every disk spans it, so 5 points cover between 0.05
# and 0.1 of it (the coverage comes from the library's free area).
run sliver --radius 0.01 --domain 0 0 1e-200 1 --max-points 5 --partial --stats
expect "$core --radius 0.01 in [0,1e-200]x[0,1] --max-points 5 --partial --stats: exit 0 (got $rc)" \
    [ "$rc" -eq 0 ]
expect "$core --radius 0.01 in [0,1e-200]x[0,1], 5 points: coverage within [0.05, 0.1]" \
    awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^coverage=/) { c = substr($i, 10) + 0; f = 1 } }
         END { exit !(f && c >= 0.05 && c <= 0.1) }' "$tmp/sliver.err"

# ---- library failures: exit 1, "poissondisk: ...: <library message>" -----------------
# A maximal pattern at 1e-4 (~7e6 points) needs about a gigabyte: in 300 MB of
# address space pds_run fails with PDS_ENOMEM, which is no fault of the arguments.
# (ulimit -v is not POSIX, so the shell is asked first.)
if (ulimit -v 300000) 2> /dev/null; then
    (ulimit -v 300000 && exec "$cli" --radius 1e-4) > "$tmp/nomem.out" 2> "$tmp/nomem.err"
    rc=$?
    expect "out of memory (ulimit -v 300000, --radius 1e-4): exit 1 (got $rc)" [ "$rc" -eq 1 ]
    expect "out of memory: the message says so" \
        grep -Eq '^poissondisk: .*: .*out of memory' "$tmp/nomem.err"
    expect "out of memory: nothing on stdout" [ ! -s "$tmp/nomem.out" ]
fi

# ---- write errors -------------------------------------------------------------------
if [ -w /dev/full ]; then
    "$cli" --radius 0.05 > /dev/full 2> "$tmp/full.err"
    rc=$?
    expect "writing to /dev/full exits 1 (got $rc)" [ "$rc" -eq 1 ]
    expect "writing to /dev/full prints an error" grep -q 'poissondisk: ' "$tmp/full.err"
fi

finish
