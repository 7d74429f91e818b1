#!/bin/sh
# check-bench.sh - smoke test of the benchmark program (make check-bench).
#
#   sh tests/check-bench.sh build/bench
#
# First the program's own self-test of its checks (close pairs must fail,
# holes must be seen). Then the benchmark at two small sizes (1000 and 3000
# points, one repeat, well under a second) and judges its CSV with awk: the columns, one row per method
# and size, every method's minimum-distance check passed, the library's
# pattern left nothing uncovered, the baselines' counts and coverage are what
# Bridson and early-stopped dart throwing give (fewer points, small gaps that
# the probes must see). Then the chunked section (one pds_run against one-point
# pds_run and pds_step loops: printed, same points). Also the SVG's shape and
# the argument errors. Timings
# are only checked to be positive: nothing here depends on the machine's speed.
# Last, with a second argument, bench-phases: its --check (the stages called
# one by one give pds_run's points), for the default process and the
# parallel one (--threads), and its tables.
# Ends with "check-bench: N passed, M failed" and a non-zero status on failure.

set -u

name=check-bench
program=${1:?usage: sh tests/check-bench.sh PATH-TO-bench [PATH-TO-bench-phases]}
phases=${2:-}
. "$(dirname "$0")/harness.sh"
bench=$program

header='method,N_target,N_points,radius,seconds_median,ns_per_point,ns_per_NlogN,peak_bytes_per_point,instructions_per_point,uncovered_fraction,uncovered_stderr,min_distance_ok'

# csv_all DESCRIPTION AWK-CONDITION: the condition holds on every data row of
# $tmp/b.csv (fields by name: see the header above); prints the rows where it
# does not.
csv_all() {
    c_desc=$1
    awk -F, "
        NR == 1 { next }
        !($2) { print \"  row \" NR \": \" \$0 > \"/dev/stderr\"; bad = 1 }
        END { exit bad }" "$tmp/b.csv"
    if [ $? -eq 0 ]; then ok; else bad "$c_desc"; fi
}

# field ROW-METHOD N COLUMN: one value from $tmp/b.csv.
field() {
    awk -F, -v m="$1" -v n="$2" -v c="$3" '
        NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
        $1 == m && $2 == n { print $(col[c]); exit }' "$tmp/b.csv"
}

# ---- the checks themselves, on patterns with known answers ----------------------------
"$bench" --self-test > "$tmp/self.out" 2>&1
rc=$?
expect "bench --self-test passes (got $rc: $(grep FAILED "$tmp/self.out" | head -n 3))" [ "$rc" -eq 0 ]

# ---- a normal run ---------------------------------------------------------------------
"$bench" --repeats 1 --csv "$tmp/b.csv" --svg "$tmp/b.svg" 1000 3000 \
    > "$tmp/b.out" 2> "$tmp/b.err"
rc=$?
expect "bench exits 0 (got $rc; stderr: $(head -c 300 "$tmp/b.err"))" [ "$rc" -eq 0 ]
expect "the table is printed" grep -q '^method  *N  *points' "$tmp/b.out"
expect "the table has a row per method and size" \
    [ "$(grep -cE '^(poissondisk|bridson|dart|periodic|field|threads1|threads) +(1000|3000) ' "$tmp/b.out")" -eq 14 ]
expect "the table gives the speed ratios" \
    [ "$(grep -c 'time relative to poissondisk:  bridson [0-9.]*  dart [0-9.]*  periodic [0-9.]*  field [0-9.]*  threads1 [0-9.]*  threads [0-9.]*$' "$tmp/b.out")" -eq 2 ]
expect "the table gives the paired ratios, threads1/threads among them" \
    [ "$(grep -c "paired, the median of each seed's ratio:  bridson/poissondisk [0-9.]*  dart/poissondisk [0-9.]*  periodic/poissondisk [0-9.]*  field/poissondisk [0-9.]*  threads1/poissondisk [0-9.]*  threads/poissondisk [0-9.]*  threads1/threads [0-9.]*$" "$tmp/b.out")" -eq 2 ]
# With one run per method, each paired ratio is the ratio of the medians:
# both lines name the same numbers, method by method.
for n in 1000 3000; do
    plain=$(grep " $n  time relative to poissondisk:" "$tmp/b.out" | sed 's/.*poissondisk://' | awk '{ for (i = 2; i <= NF; i += 2) printf "%s ", $i }')
    paired=$(grep " $n  paired, " "$tmp/b.out" | sed 's/.*ratio://' | awk '{ for (i = 2; i <= NF - 2; i += 2) printf "%s ", $i }')
    expect "at N=$n one run's paired ratios are the plain ones ($paired against $plain)" [ -n "$plain" -a "$plain" = "$paired" ]
done
# threads1 against threads, from the table's own seconds column (printed
# to 4 decimals, a few milliseconds here: within 6%).
for n in 1000 3000; do
    want=$(awk -v n=$n '$2 == n && $1 == "threads1" { a = $5 } $2 == n && $1 == "threads" { b = $5 } END { printf "%.4f", a / b }' "$tmp/b.out")
    got=$(grep " $n  paired, " "$tmp/b.out" | sed 's/.*threads1\/threads //')
    expect "at N=$n threads1/threads is their seconds' ratio ($got, from the rows $want)" \
        awk -v a="$got" -v b="$want" 'BEGIN { exit !(a > 0 && b > 0 && (a / b - 1) ^ 2 < 0.0036) }'
done
expect "the CSV exists" [ -s "$tmp/b.csv" ]
expect "the CSV header is the documented one" [ "$(head -n 1 "$tmp/b.csv")" = "$header" ]
expect "the CSV has 14 data rows" [ "$(wc -l < "$tmp/b.csv" | tr -d ' ')" -eq 15 ]

# The chunked section (bench/chunked.c), at the largest size: one pds_run against
# pds_run(s, 1) and pds_step loops, which must give the same points.
expect "the chunked section is printed at N=3000" grep -q '^chunked runs, N=3000, ' "$tmp/b.out"
expect "the chunked section has a line per way, with a ratio" \
    [ "$(grep -cE '^  (one pds_run\(s, 0\)|pds_run\(s, 1\) until done|pds_step\(s\) until done) +[0-9.]+ s +[0-9.]+x' "$tmp/b.out")" -eq 3 ]
expect "the chunked ways give the same points" \
    [ "$(grep -c 'until done .*x  same points$' "$tmp/b.out")" -eq 2 ]

csv_all "every row has 12 fields" 'NF == 12'
csv_all "every row is one of the seven methods" '$1 == "poissondisk" || $1 == "bridson" || $1 == "dart" || $1 == "periodic" || $1 == "field" || $1 == "threads1" || $1 == "threads"'
csv_all "N_target is 1000 or 3000" '$2 == 1000 || $2 == 3000'
for m in poissondisk bridson dart; do
    for n in 1000 3000; do
        expect "a row for $m at N=$n" [ -n "$(field $m $n N_target)" ]
    done
done
csv_all "the radius is sqrt(0.6966/N)" \
    '$4 > 0 && ($4 * $4 * $2 / 0.6966 - 1) ^ 2 < 1e-12'
csv_all "times are positive numbers" '$5 > 0 && $6 > 0 && $7 > 0'
csv_all "ns_per_point is seconds / points" '(1e9 * $5 / $3 / $6 - 1) ^ 2 < 1e-8'
csv_all "instructions per point: empty or a positive number" '$9 == "" || $9 > 0'
csv_all "the uncovered fraction is in [0, 1) and its error is not negative" \
    '$10 >= 0 && $10 < 1 && $11 >= 0'
csv_all "every method's minimum-distance check passed" '$12 == 1'

# The library: maximal, so no probe is uncovered; and the RSA count (R was
# chosen for about N points; small squares have a few more at the edges).
csv_all "poissondisk leaves nothing uncovered" '$1 != "poissondisk" || ($10 == 0 && $11 == 0)'
# The parallel process: maximal too, and the same points on one thread as on all.
csv_all "the parallel process leaves nothing uncovered" '($1 != "threads1" && $1 != "threads") || ($10 == 0 && $11 == 0)'
for n in 1000 3000; do
    expect "threads1 and threads give the same count at N=$n" \
        [ "$(field threads1 $n N_points)" = "$(field threads $n N_points)" ]
done
csv_all "poissondisk gives about N points" '$1 != "poissondisk" || ($3 >= 0.97 * $2 && $3 <= 1.08 * $2)'
# The 1:4 field's radius was chosen for about N points too (checked maximal
# by pds_verify in the benchmark itself).
csv_all "field gives about N points" '$1 != "field" || ($3 >= 0.9 * $2 && $3 <= 1.2 * $2)'
# The baselines are not maximal: clearly fewer points (about 88% here) and a
# small uncovered fraction that the probes must detect (about 1e-3).
for m in bridson dart; do
    for n in 1000 3000; do
        ours=$(field poissondisk $n N_points)
        theirs=$(field $m $n N_points)
        gap=$(field $m $n uncovered_fraction)
        expect "$m count at N=$n is plausible ($theirs vs poissondisk $ours)" \
            awk -v a="$theirs" -v b="$ours" 'BEGIN { exit !(a >= 0.80 * b && a <= 0.96 * b) }'
        expect "$m leaves a small uncovered fraction at N=$n (got $gap)" \
            awk -v p="$gap" 'BEGIN { exit !(p > 0 && p < 0.01) }'
    done
done

# ---- the chart ------------------------------------------------------------------------
expect "the SVG exists" [ -s "$tmp/b.svg" ]
expect "the SVG is one <svg> element" \
    awk 'NR == 1 && !/^<\?xml / { exit 1 } /<svg / { o++ } /<\/svg>/ { c++ } END { exit !(o == 1 && c == 1) }' "$tmp/b.svg"
expect "the SVG has a line per method" [ "$(grep -c '<polyline' "$tmp/b.svg")" -eq 7 ]
for m in poissondisk bridson dart; do
    expect "the SVG legend names $m" grep -q ">$m</text>" "$tmp/b.svg"
done

# ---- options --------------------------------------------------------------------------
"$bench" --repeats 1 --methods poissondisk --csv - 1000 > "$tmp/o.out" 2> "$tmp/o.err"
rc=$?
expect "--csv -: exit 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--csv -: the CSV on stdout" [ "$(head -n 1 "$tmp/o.out")" = "$header" ]
expect "--methods poissondisk: one row" [ "$(wc -l < "$tmp/o.out" | tr -d ' ')" -eq 2 ]
expect "--csv -: the table on stderr" grep -q '^poissondisk  *1000 ' "$tmp/o.err"

"$bench" --repeats 1 --methods poissondisk --chunked 0 1000 > "$tmp/c.out" 2>&1
rc=$?
expect "--chunked 0: exit 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--chunked 0: no chunked section" sh -c "! grep -q '^chunked' '$tmp/c.out'"
"$bench" --repeats 1 --methods poissondisk --chunked 2000 1000 > "$tmp/c.out" 2>&1
expect "--chunked 2000: the section at N=2000" grep -q '^chunked runs, N=2000, ' "$tmp/c.out"

usage_case() {
    u_desc=$1
    shift
    "$bench" "$@" > "$tmp/u.out" 2> "$tmp/u.err"
    rc=$?
    expect "$u_desc: exit 2 (got $rc)" [ "$rc" -eq 2 ]
    expect "$u_desc: a message and the usage" grep -q '^usage: ' "$tmp/u.err"
}
usage_case "--repeats 0" --repeats 0 1000
usage_case "--methods with an unknown name" --methods poissondisk,nope 1000
usage_case "a size of 5" 5
usage_case "a size that is not a number" 10k
usage_case "an unknown option" --bogus 1000
usage_case "--chunked 5" --chunked 5 1000

# ---- bench-phases ---------------------------------------------------------------------
# The stages timed one by one must be pds_run's own path: --check compares
# every coordinate with pds_run's at the same radius and seed.
if [ -n "$phases" ]; then
    for run in "20000 1" "3000 5"; do
        # shellcheck disable=SC2086
        "$phases" --check $run > "$tmp/p.out" 2>&1
        rc=$?
        expect "bench-phases --check $run: exit 0 (got $rc)" [ "$rc" -eq 0 ]
        expect "bench-phases --check $run: the same points as pds_run" grep -q '^check: pds_run gives [0-9]* points, the same$' "$tmp/p.out"
        for phase in darts 'hand-over order' 'hand-over insert' 'hand-over measure' 'Jones loop' total; do
            expect "bench-phases $run: a '$phase' row" grep -q "^$phase  *[0-9]" "$tmp/p.out"
        done
        # The dart and loop points add up to the total.
        expect "bench-phases $run: the phases' points add up" awk '
            /^darts / { d = $4 } /^Jones loop / { l = $5 } /^total / { t = $4 }
            END { exit !(d > 0 && l > 0 && d + l == t) }' "$tmp/p.out"
        # Each point took a dart or a selection that no stale bound rejected.
        expect "bench-phases $run: the counts are consistent" awk '
            /^darts / { d = $4; thrown = $7 }
            /^Jones loop / { l = $5; sel = $8; stale = $13; zero = $15 }
            END { exit !(thrown >= d && sel - stale >= l && zero <= stale && zero > 0) }' "$tmp/p.out"
    done
    # The parallel process, on 1 and 2 threads (the same points: pds_run's
    # with pds_set_threads).
    for run in "--threads 2 20000 1" "--threads 1 3000 5"; do
        # shellcheck disable=SC2086
        "$phases" --check $run > "$tmp/p.out" 2>&1
        rc=$?
        expect "bench-phases --check $run: exit 0 (got $rc)" [ "$rc" -eq 0 ]
        expect "bench-phases --check $run: the same points as pds_run" grep -q '^check: pds_run gives [0-9]* points, the same$' "$tmp/p.out"
        for phase in 'opening epochs' 'hand-over' 'region epochs' 'region insertions' 'Jones loop' total; do
            expect "bench-phases $run: a '$phase' row" grep -q "^$phase  *[0-9]" "$tmp/p.out"
        done
        # The opening's, the free regions' and the loop's points add up to
        # the total; the opening and the free regions both made some, every
        # point the free regions placed was timed as theirs, and they kept
        # at least a dart for each.
        expect "bench-phases $run: the phases' points add up" awk '
            /^opening epochs / { o = $5 + 0 } /^hand-over / { h = $4 + 0 }
            /^region epochs / { r = $5 + 0; kept = $10 + 0; placed = $13 + 0 }
            /^region insertions / { i = $5 + 0 } /^Jones loop / { l = $5 + 0 } /^total / { t = $4 + 0 }
            END { exit !(o > 0 && r > 0 && h == o && i == r && placed == r && kept >= r && o + r + l == t) }' "$tmp/p.out"
    done
    for args in 50 "--threads 0 1000" "--threads" "--threads 65 1000"; do
        # shellcheck disable=SC2086
        "$phases" $args > "$tmp/p.out" 2> "$tmp/p.err"
        rc=$?
        expect "bench-phases $args: exit 2 (got $rc)" [ "$rc" -eq 2 ]
        expect "bench-phases $args: the usage" grep -q '^usage: ' "$tmp/p.err"
    done
fi

finish
