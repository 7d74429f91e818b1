#!/bin/sh
# check-pages.sh - keep the man pages and their compiled examples in step.
#
# Usage: sh tests/man_examples/check-pages.sh   (from the top of the tree)
#
# For every section-3 page man/<page>.3, the first literal display of its
# EXAMPLES section, with the mdoc escapes undone, must be byte for byte the
# program tests/man_examples/<page>.c; every such program must have its page.
# man/links.txt must name each extra .Nm of each page exactly once, and
# nothing else. Exit status 0 when all holds, 1 otherwise.

man=man
ex=tests/man_examples
tmp=$(mktemp -d "${TMPDIR:-/tmp}/check-pages.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
status=0

fail() {
    echo "check-pages: $*" >&2
    status=1
}

# The example text of a page: the first ".Bd -literal" block after
# ".Sh EXAMPLES", with \& removed and \e turned back into a backslash.
example_of() {
    awk '
        /^\.Sh / { in_ex = ($0 == ".Sh EXAMPLES") }
        in_ex && !done && /^\.Bd -literal/ { copy = 1; next }
        copy && /^\.Ed/ { copy = 0; done = 1; next }
        copy { gsub(/\\&/, ""); gsub(/\\e/, "\\"); print }
    ' "$1"
}

for page in "$man"/*.3; do
    name=$(basename "$page" .3)
    prog=$ex/$name.c
    if [ ! -f "$prog" ]; then
        fail "$page has no program $prog"
        continue
    fi
    example_of "$page" > "$tmp/$name.c"
    if [ ! -s "$tmp/$name.c" ]; then
        fail "$page has no literal display in EXAMPLES"
    elif ! cmp -s "$tmp/$name.c" "$prog"; then
        fail "$page EXAMPLES differs from $prog:"
        diff -u "$prog" "$tmp/$name.c" >&2
    fi
done

for prog in "$ex"/*.c; do
    name=$(basename "$prog" .c)
    [ -f "$man/$name.3" ] || fail "$prog has no page $man/$name.3"
done

# Links: the names in each page's NAME section besides its own.
for page in "$man"/*.3; do
    own=$(basename "$page" .3)
    awk '/^\.Sh / { in_name = ($0 == ".Sh NAME") }
         in_name && /^\.Nm / { print $2 }' "$page" |
    while read -r nm; do
        [ "$nm" = "$own" ] || echo "$nm.3 $own.3"
    done
done | sort > "$tmp/links.want"
sort "$man/links.txt" > "$tmp/links.have"
if ! cmp -s "$tmp/links.want" "$tmp/links.have"; then
    fail "$man/links.txt does not match the NAME sections (- file, + pages):"
    diff -u "$tmp/links.have" "$tmp/links.want" >&2
fi

[ "$status" -eq 0 ] && echo "check-pages: pages, examples and links agree"
exit "$status"
