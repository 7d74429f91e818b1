#!/bin/sh
# check-layers.sh - the library's folders form layers, and a file includes only
# from its own folder or from a folder below it. The order, top to bottom, is
# the one src/README.md explains; src/capi.cpp (the C face) sits above them all.
# Fails naming each include that points upwards, or a folder missing from the list.
set -u
cd "$(dirname "$0")/.." || exit 1
layers="sampler darts jones radius verify cells domain mesh core"

rank() {  # prints the layer's position from the bottom (core = 1), or nothing
    n=0; found=""
    for l in $layers; do n=$((n + 1)); [ "$l" = "$1" ] && found=$n; done
    total=$n
    [ -n "$found" ] && echo $((total - found + 1))
}

bad=0
for dir in src/*/; do
    d=$(basename "$dir")
    if [ -z "$(rank "$d")" ]; then
        echo "check-layers: src/$d/ is not in the layer list (tests/check-layers.sh, src/README.md)"
        bad=1
    fi
done
for f in src/*/*.cpp src/*/*.hpp; do
    d=$(basename "$(dirname "$f")")
    own=$(rank "$d")
    [ -n "$own" ] || continue
    for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f"); do
        case "$inc" in
            */*) to=${inc%%/*} ;;
            poissondisk.h) echo "check-layers: $f includes the public header (only src/capi.cpp does)"; bad=1; continue ;;
            *) echo "check-layers: $f includes \"$inc\" without its folder"; bad=1; continue ;;
        esac
        r=$(rank "$to")
        if [ -z "$r" ]; then
            echo "check-layers: $f includes \"$inc\" from an unknown folder"; bad=1
        elif [ "$r" -gt "$own" ]; then
            echo "check-layers: $f ($d) includes \"$inc\" from the layer above it ($to)"; bad=1
        fi
    done
done
if [ "$bad" -ne 0 ]; then
    echo "check-layers: FAILED"
    exit 1
fi
echo "check-layers: every include points to its own layer or below ($layers)"
