#!/bin/sh
# check-symbols.sh LIB MAP - the shared library exports exactly the names the
# linker version script lists, every one in a PDS_ version node, and nothing else.
set -eu
lib=$1
map=$2
tmp=${TMPDIR:-/tmp}/pds-symbols.$$
trap 'rm -f "$tmp".*' EXIT

nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBRVWi]$/ {print $3}' | sed 's/@.*//' \
    | grep -v '^PDS_[0-9.]*$' | sort -u > "$tmp.exported"
sed -n 's/^[[:space:]]*\(pds_[a-z0-9_]*\);.*/\1/p' "$map" | sort -u > "$tmp.listed"
grep -o '\bpds_[a-z0-9_]*[[:space:]]*(' include/poissondisk.h | sed 's/[[:space:]]*($//' | sort -u > "$tmp.declared"

status=0
if ! cmp -s "$tmp.exported" "$tmp.listed"; then
    echo "check-symbols: exported symbols differ from $map (< exported, > listed):"
    diff "$tmp.exported" "$tmp.listed" || true
    status=1
fi
if ! cmp -s "$tmp.listed" "$tmp.declared"; then
    echo "check-symbols: $map differs from the functions in include/poissondisk.h (< map, > header):"
    diff "$tmp.listed" "$tmp.declared" || true
    status=1
fi
# Every export carries a version node.
unversioned=$(nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBRVW]$/ && $3 ~ /^pds_/ && $3 !~ /@@PDS_/ {print $3}')
if [ -n "$unversioned" ]; then
    echo "check-symbols: exports without a version node: $unversioned"
    status=1
fi
n=$(wc -l < "$tmp.exported")
[ "$status" -eq 0 ] && echo "check-symbols: $n symbols, all pds_*, all versioned, matching the map and the header"
exit "$status"
