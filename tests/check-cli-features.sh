#!/bin/sh
# check-cli-features.sh - behaviour tests for the run options of the
# poissondisk command-line program: --count, --periodic, the progress line,
# and Ctrl-C with --partial. The argument errors of these options, and
# everything else the program does, are in check-cli.sh.
#
#   sh tests/check-cli-features.sh build/poissondisk
#
# Checks are judged as in check-cli.sh: the program's exit status, stdout and
# stderr with standard tools, geometric facts recomputed from the printed
# numbers (pattern_checks.sh). Checks marked "[core periodic]" need the
# periodic domain of 1.2. Ends with "check-cli-features: N passed, M failed"
# and a non-zero status if anything failed.

set -u

name=check-cli-features
program=${1:?usage: sh tests/check-cli-features.sh PATH-TO-poissondisk}
. "$(dirname "$0")/harness.sh"
cli=$program

# run, lines, usage_case.
. "$(dirname "$0")/cli_cases.sh"
# The geometric checks: two_numbers, inside, min_dist_ok, covered, and the
# torus checks inside_torus, min_dist_torus, covered_torus.
. "$(dirname "$0")/pattern_checks.sh"

# The plain unit-square pattern the periodic one is compared with (judged in
# check-cli.sh).
run base --radius 0.05

# ---- --count: the library chooses the radius for exactly N points -------------------
# The radius comes from --stats (written with the fewest digits that read back
# exactly); every pair must be at least that far apart, and the pattern is
# maximal at the radius before the last one, 1/0.99 times larger.
stats_radius() { sed -n 's/^poissondisk: N=[0-9]* R=\([^ ]*\) (chosen for --count) .*/\1/p' "$1"; }

run count --count 1000 --stats
cr=$(stats_radius "$tmp/count.err")
expect "--count 1000 exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--count 1000 prints exactly 1000 lines (got $(lines "$tmp/count.out"))" \
    [ "$(lines "$tmp/count.out")" -eq 1000 ]
expect "--count 1000: every line is two numbers" two_numbers "$tmp/count.out"
expect "--count 1000: all points in the unit square" inside "$tmp/count.out" 0 0 1 1
expect "--count 1000 --stats reports the chosen radius ('$cr')" [ -n "$cr" ]
expect "--count 1000: every pair at least the reported R=$cr apart" \
    min_dist_ok "$tmp/count.out" "${cr:-1}"
expect "--count 1000: no probe farther than R/0.99 from all points" \
    covered "$tmp/count.out" "$(awk -v r="${cr:-0}" 'BEGIN { printf "%.17g", r / 0.99 }')" \
        0 0 1 1 0.005
run count2 --count 1000
expect "--count 1000 twice gives identical output" cmp -s "$tmp/count.out" "$tmp/count2.out"
run countcap --count 1000 --max-points 10
head -n 10 "$tmp/count.out" > "$tmp/count10.out"
expect "--count 1000 --max-points 10 prints the first 10 points of --count 1000" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/count10.out" "$tmp/countcap.out"'
run countv --count 1000 --verify --stats
expect "--count 1000 --verify exits 0 with the same points (got $rc)" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/count.out" "$tmp/countv.out"'
expect "--count 1000 --verify --stats: N=1000, verified" \
    grep -q '^poissondisk: N=1000 R=.* verified ' "$tmp/countv.err"
run countdom --count 500 --domain -2 1 3 2.5 --seed 9
expect "--count 500 --domain -2 1 3 2.5: exit 0 and exactly 500 lines (got $rc)" \
    eval '[ "$rc" -eq 0 ] && [ "$(lines "$tmp/countdom.out")" -eq 500 ]'
expect "--count 500 --domain: all points inside" inside "$tmp/countdom.out" -2 1 3 2.5
# Sides near DBL_MAX: the start radius would overflow; it is capped at the
# largest double, so a small count ends (an infinite radius lowered by 1%
# stays infinite) and the reported radius is finite. timeout: a hang fails.
timeout 120 "$cli" --count 3 --domain -1.7976931348623157e308 -1.7976931348623157e308 \
    1.7976931348623157e308 1.7976931348623157e308 --stats > "$tmp/counthuge.out" 2> "$tmp/counthuge.err"
rc=$?
hr=$(stats_radius "$tmp/counthuge.err")
expect "--count 3 on [-DBL_MAX, DBL_MAX]^2: exit 0 and exactly 3 lines (got $rc)" \
    eval '[ "$rc" -eq 0 ] && [ "$(lines "$tmp/counthuge.out")" -eq 3 ]'
expect "--count 3 on [-DBL_MAX, DBL_MAX]^2: a finite radius reported ('$hr')" \
    awk -v r="$hr" 'BEGIN { exit !(r != "" && r + 0 > 0 && r + 0 <= 1.7976931348623157e308) }'

# ---- --periodic: a flat torus ---------------------------------------------------------
# Every pair at least R apart also across the wrap, the points in the half-open
# rectangle, and the torus covered; the plain checks would pass a pattern that
# is not periodic, the wrapped ones do not.
per="[core periodic]"
run per --radius 0.05 --periodic --verify --stats
expect "$per --radius 0.05 --periodic --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "$per --periodic: every line is two numbers" two_numbers "$tmp/per.out"
expect "$per --periodic: all points in [0,1)x[0,1)" inside_torus "$tmp/per.out" 0 0 1 1
expect "$per --periodic: every pair at least 0.05 apart, wrapped" \
    min_dist_torus "$tmp/per.out" 0.05 0 0 1 1
expect "$per --periodic: no probe farther than 0.05 from all points, wrapped" \
    covered_torus "$tmp/per.out" 0.05 0 0 1 1 0.01
expect "$per --periodic --stats: a periodic domain, maximal and verified" \
    grep -Eq '^poissondisk: N=[0-9]+ R=0\.05 domain=\[0,1\)x\[0,1\) periodic coverage=1\.0+ maximal verified ' \
        "$tmp/per.err"
expect "$per --periodic gives another pattern than the plain square" \
    eval '! cmp -s "$tmp/base.out" "$tmp/per.out"'
run perdom --radius 0.1 --domain -2 1 3 2.5 --periodic --verify
expect "$per --periodic --domain -2 1 3 2.5 --verify exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "$per --periodic --domain: all points in [-2,3)x[1,2.5)" \
    inside_torus "$tmp/perdom.out" -2 1 3 2.5
expect "$per --periodic --domain: every pair at least 0.1 apart, wrapped" \
    min_dist_torus "$tmp/perdom.out" 0.1 -2 1 3 2.5
expect "$per --periodic --domain: the torus is covered" \
    covered_torus "$tmp/perdom.out" 0.1 -2 1 3 2.5 0.05
run percap --radius 0.05 --periodic --max-points 20
head -n 20 "$tmp/per.out" > "$tmp/per20.out"
expect "$per --periodic --max-points 20 prints the first 20 points of --periodic" \
    eval '[ "$rc" -eq 0 ] && cmp -s "$tmp/per20.out" "$tmp/percap.out"'
run percount --count 700 --periodic --verify --stats
pr=$(stats_radius "$tmp/percount.err")
expect "$per --count 700 --periodic --verify: exit 0, exactly 700 lines (got $rc)" \
    eval '[ "$rc" -eq 0 ] && [ "$(lines "$tmp/percount.out")" -eq 700 ]'
expect "$per --count 700 --periodic: all points in [0,1)x[0,1)" \
    inside_torus "$tmp/percount.out" 0 0 1 1
expect "$per --count 700 --periodic: every pair at least the reported R='$pr' apart, wrapped" \
    eval '[ -n "$pr" ] && min_dist_torus "$tmp/percount.out" "$pr" 0 0 1 1'
usage_case "$per --periodic, R over half the side (PDS_ERANGE)" \
    'radius 0\.6 does not suit the periodic domain \[0,1\)x\[0,1\)' --radius 0.6 --periodic
usage_case "$per --periodic with an empty domain: the domain written half-open" \
    'cannot set domain \[0,0\)x\[0,1\): ' --radius 0.1 --domain 0 0 0 1 --periodic

# ---- the progress line ------------------------------------------------------------------
# Drawn on stderr, redrawn with \r, wiped at the end; never a change to stdout.
run plain --radius 0.01
run prog --radius 0.01 --progress
tr '\r' '\n' < "$tmp/prog.err" > "$tmp/prog.lines"
expect "--progress exits 0 (got $rc)" [ "$rc" -eq 0 ]
expect "--progress leaves stdout byte-for-byte unchanged" cmp -s "$tmp/plain.out" "$tmp/prog.out"
expect "--progress draws 'poissondisk: P% N points' lines on stderr" \
    grep -Eq '^poissondisk: +[0-9]+% [0-9]+ points *$' "$tmp/prog.lines"
expect "--progress redraws one line: no newline on stderr" [ "$(lines "$tmp/prog.err")" -eq 0 ]
expect "--progress ends at 100% and all $(lines "$tmp/plain.out") points" \
    grep -Eq "^poissondisk: 100% $(lines "$tmp/plain.out") points *\$" "$tmp/prog.lines"
expect "--progress wipes its line at the end (blanks, then \\r)" \
    eval 'tail -n 1 "$tmp/prog.lines" | grep -q "^ *\$" && [ "$(tail -c 1 "$tmp/prog.err" | od -An -c | tr -d " ")" = "\\r" ]'
run progoff --radius 0.01 --progress --no-progress
expect "--progress --no-progress: the last one counts, nothing on stderr" \
    eval '[ "$rc" -eq 0 ] && [ ! -s "$tmp/progoff.err" ] && cmp -s "$tmp/plain.out" "$tmp/progoff.out"'
run progon --radius 0.01 --no-progress --progress
expect "--no-progress --progress: the last one counts, a progress line" \
    grep -q '%' "$tmp/progon.err"
run progstats --radius 0.01 --progress --stats
expect "--progress --stats: the --stats line comes after the wiped progress line" \
    eval 'tr "\\r" "\\n" < "$tmp/progstats.err" | tail -n 1 | grep -q "^poissondisk: N="'
run progcount --count 2000 --progress
expect "--count 2000 --progress counts towards 2000" \
    eval 'tr "\\r" "\\n" < "$tmp/progcount.err" | grep -Eq "^poissondisk: 100% 2000/2000 points"'
run progref --radius 0.02 --refine 0.01 --progress
expect "--refine --progress names the stages" \
    eval 'tr "\\r" "\\n" < "$tmp/progref.err" | grep -q "^poissondisk: stage 2/2 "'
# On a terminal the line is drawn by default. script(1) gives the program one
# (util-linux; skipped where it or a pseudo-terminal is missing).
if script -qec true /dev/null < /dev/null > /dev/null 2>&1; then
    script -qfec "'$cli' --radius 0.01 > '$tmp/tty.out'" /dev/null < /dev/null > "$tmp/tty.log" 2>&1
    expect "stderr a terminal: the progress line is drawn without --progress" \
        grep -q 'poissondisk: 100% ' "$tmp/tty.log"
    expect "stderr a terminal: stdout unchanged" cmp -s "$tmp/plain.out" "$tmp/tty.out"
    script -qfec "'$cli' --radius 0.01 --no-progress > /dev/null" /dev/null < /dev/null \
        > "$tmp/ttyoff.log" 2>&1
    expect "stderr a terminal, --no-progress: no progress line" \
        eval '! grep -q "%" "$tmp/ttyoff.log"'
fi

# ---- Ctrl-C: SIGINT stops the run, exit 130 -------------------------------------------
# A background job of a shell without job control starts with SIGINT ignored,
# which the program respects (like nohup); $tmp/sigdfl puts the default back
# before it starts. The pattern is large (about 7.7 million points, 25 s here):
# SIGINT is sent as soon as the first progress report is on stderr, and the
# run stops at its next report. Where it lands varies; the checks do not
# depend on it.
# interrupt NAME COMMAND...: like run, with SIGINT after the first report.
# interrupt_at TEXT NAME COMMAND...: the same, once stderr holds TEXT.
interrupt() { interrupt_at '' "$@"; }
interrupt_at() {
    i_text=$1
    i_name=$2
    shift 2
    : > "$tmp/$i_name.err"
    "$tmp/sigdfl" "$@" > "$tmp/$i_name.out" 2> "$tmp/$i_name.err" &
    i_pid=$!
    i_polls=0
    while ! grep -q -- "$i_text" "$tmp/$i_name.err" && [ "$i_polls" -lt 1200 ] \
          && kill -0 "$i_pid" 2> /dev/null
    do
        sleep 0.05
        i_polls=$((i_polls + 1))
    done
    kill -INT "$i_pid" 2> /dev/null
    wait "$i_pid"
    rc=$?
}
if env --default-signal=INT true 2> /dev/null; then
    printf '#!/bin/sh\nexec env --default-signal=INT "$@"\n' > "$tmp/sigdfl"
elif command -v perl > /dev/null 2>&1; then
    printf '#!/bin/sh\nexec perl -e '\''$SIG{INT} = "DEFAULT"; exec @ARGV or die'\'' "$@"\n' \
        > "$tmp/sigdfl"
fi
if [ -f "$tmp/sigdfl" ]; then
    chmod +x "$tmp/sigdfl"
    interrupt int "$cli" --radius 0.0003 --progress
    expect "SIGINT during a run: exit 130 (got $rc)" [ "$rc" -eq 130 ]
    expect "SIGINT without --partial: nothing on stdout" [ ! -s "$tmp/int.out" ]
    expect "SIGINT: stderr says 'interrupted after N points'" \
        grep -Eq 'poissondisk: interrupted after [0-9]+ points$' "$tmp/int.err"
    # The run stops at its next report, long before the end: no 100% report.
    expect "SIGINT: the run stopped before the end (no 100% report)" \
        eval '! grep -q "100%" "$tmp/int.err"'

    interrupt intp "$cli" --radius 0.0003 --progress --partial
    k=$(lines "$tmp/intp.out")
    expect "SIGINT with --partial: exit 130 (got $rc)" [ "$rc" -eq 130 ]
    expect "SIGINT with --partial: some points written ($k)" [ "$k" -gt 0 ]
    expect "SIGINT with --partial: stderr names the $k points written" \
        grep -q "interrupted after $k points; writing them" "$tmp/intp.err"
    expect "SIGINT with --partial: every line is two numbers" two_numbers "$tmp/intp.out"
    expect "SIGINT with --partial: the run stopped before the end (no 100% report)" \
        eval '! grep -q "100%" "$tmp/intp.err"'
    # --max-points k prints the first k lines of the uninterrupted output.
    if [ "$k" -gt 0 ]; then
        run intref --radius 0.0003 --max-points "$k"
        expect "SIGINT with --partial: the $k lines are the start of the uninterrupted output" \
            cmp -s "$tmp/intref.out" "$tmp/intp.out"
    fi

    # --patterns K: Ctrl-C once the first pattern is complete (its 100% report),
    # while the spectrum's sums or its other patterns are being made (100000
    # patterns would take hours): the first pattern is not written either.
    spec="--radius 0.02 --periodic --progress --patterns 100000 --spectrum $tmp/intspec.png"
    # shellcheck disable=SC2086
    interrupt_at "100%" intspec "$cli" $spec
    expect "SIGINT during --patterns: exit 130 (got $rc)" [ "$rc" -eq 130 ]
    expect "SIGINT during --patterns without --partial: nothing on stdout" \
        [ ! -s "$tmp/intspec.out" ]
    expect "SIGINT during --patterns: stderr says no spectrum was written" \
        grep -q 'interrupted while making pattern [0-9]* of 100000 for the spectrum; no spectrum written' \
        "$tmp/intspec.err"
    expect "SIGINT during --patterns: no spectrum file" [ ! -e "$tmp/intspec.png" ]
    # shellcheck disable=SC2086
    interrupt_at "100%" intspecp "$cli" $spec --partial
    expect "SIGINT during --patterns with --partial: exit 130 (got $rc)" [ "$rc" -eq 130 ]
    run intspecref --radius 0.02 --periodic
    expect "SIGINT during --patterns with --partial: the whole first pattern is written" \
        cmp -s "$tmp/intspecref.out" "$tmp/intspecp.out"

    # Without a progress line the callback still listens for Ctrl-C. Nothing
    # shows when the handler is in place, so on Linux its bit in SigCgt is
    # awaited (elsewhere a second), once the process runs the program: just
    # after the fork it is still this shell, whose 'exit 130' trap shows the
    # same bit, and a SIGINT it swallows there never reaches the program. A
    # SIGINT that came too early would end the program by the signal: status
    # 130 too, but no message.
    "$tmp/sigdfl" "$cli" --radius 0.0003 > "$tmp/intq.out" 2> "$tmp/intq.err" &
    i_pid=$!
    if [ -r "/proc/$i_pid/status" ]; then
        i_polls=0
        i_exe=$(readlink -f "$cli")
        until { [ "$(readlink "/proc/$i_pid/exe" 2> /dev/null)" = "$i_exe" ] &&
                sed -n 's/^SigCgt:[[:space:]]*//p' "/proc/$i_pid/status" 2> /dev/null \
                    | grep -q '[2367abefABEF]$'; } || [ "$i_polls" -ge 1200 ]; do
            sleep 0.05
            i_polls=$((i_polls + 1))
        done
    else
        sleep 1
    fi
    kill -INT "$i_pid" 2> /dev/null
    wait "$i_pid"
    rc=$?
    expect "SIGINT without a progress line: exit 130 (got $rc)" [ "$rc" -eq 130 ]
    expect "SIGINT without a progress line: nothing on stdout" [ ! -s "$tmp/intq.out" ]
    expect "SIGINT without a progress line: handled, 'interrupted after N points'" \
        grep -q 'interrupted after [0-9]* points$' "$tmp/intq.err"

    # No leak and no invalid access on the way out (Valgrind exits 99 if so).
    if command -v valgrind > /dev/null 2>&1; then
        interrupt intvg valgrind -q --error-exitcode=99 --leak-check=full \
            --errors-for-leak-kinds=all "$cli" --radius 0.002 --progress --partial
        expect "SIGINT with --partial under Valgrind: exit 130, no leak or error (got $rc)" \
            [ "$rc" -eq 130 ]
        expect "SIGINT with --partial under Valgrind: handled" \
            grep -q 'interrupted after [0-9]* points; writing them' "$tmp/intvg.err"
    fi
else
    echo "$name: neither 'env --default-signal' nor perl: SIGINT checks skipped" >&2
fi

finish
