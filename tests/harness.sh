# harness.sh - the shared frame of the shell test scripts (check-cli.sh,
# check-bench.sh), sourced after they set `name` (for messages) and
# `program` (the executable under test, the script's first argument):
#   . "$(dirname "$0")/harness.sh"
# It checks that the program is executable, makes a scratch directory $tmp
# (removed on exit), counts checks with ok/bad/expect, and `finish` prints
# "NAME: N passed, M failed" and returns non-zero if anything failed.
# (sh has no local variables: each helper uses names of its own.)

case $program in */*) ;; *) program=./$program ;; esac
if [ ! -x "$program" ]; then
    echo "$name: $program is not an executable file" >&2
    exit 2
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/$name.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

passed=0
failed=0

ok() { passed=$((passed + 1)); }
bad() {
    failed=$((failed + 1))
    echo "FAIL: $*" >&2
}
# expect DESCRIPTION COMMAND...: the command (a test) must succeed.
expect() {
    e_desc=$1
    shift
    if "$@"; then ok; else bad "$e_desc"; fi
}

finish() {
    echo "$name: $passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}
