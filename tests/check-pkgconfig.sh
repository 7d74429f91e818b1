#!/bin/sh
# check-pkgconfig.sh - install into a scratch DESTDIR, then build a plain C
# program against the installed copy through pkg-config, shared and static,
# and run both; install the Python package there too and import it against
# the installed library; finally uninstall and check nothing is left behind.
set -eu
top=$(pwd)
stage=$(mktemp -d "${TMPDIR:-/tmp}/pds-install.XXXXXX")
trap 'rm -rf "$stage"' EXIT
prefix=/opt/poissondisk-test

make -s install DESTDIR="$stage" PREFIX="$prefix" >/dev/null
root="$stage$prefix"
export PKG_CONFIG_PATH="$root/lib/pkgconfig"
# pkg-config's sysroot support maps the installed prefix into the stage.
export PKG_CONFIG_SYSROOT_DIR="$stage"

cat > "$stage/prog.c" <<'C'
#include <poissondisk.h>
#include <stdio.h>
int main(void) {
    pds_sampler *s;
    size_t added = 0;
    if (pds_create(&s, 0.05, 7) != 0) return 1;
    if (pds_run(s, 0, &added) != 0 || added == 0 || pds_verify(s) != 0) return 2;
    printf("%zu points, library %s\n", added, pds_version_string());
    pds_destroy(s);
    return 0;
}
C
cc -std=c99 -Wall -Werror "$stage/prog.c" -o "$stage/prog-shared" \
    $(pkg-config --cflags --libs poissondisk) -Wl,-rpath,"$root/lib"
"$stage/prog-shared"
cc -std=c99 -Wall -Werror -static "$stage/prog.c" -o "$stage/prog-static" \
    $(pkg-config --static --cflags --libs poissondisk)
"$stage/prog-static"
ldd "$stage/prog-static" 2>&1 | grep -q 'not a dynamic executable' || { echo "static link is dynamic"; exit 1; }

# The soname chain and the man page links are in place.
[ -L "$root/lib/libpoissondisk.so" ] && [ -L "$root/lib/libpoissondisk.so.1" ]
readelf -d "$root/lib/libpoissondisk.so.1" | grep -q 'SONAME.*libpoissondisk.so.1'
[ -e "$root/share/man/man3/pds_run.3" ] && [ -e "$root/share/man/man1/poissondisk.1" ]

# The Python package, installed by make install-python into the same stage,
# finds the installed library through the loader and gives a numpy array.
make -s install-python DESTDIR="$stage" >/dev/null 2>&1 || { echo "make install-python failed"; exit 1; }
init=$(find "$stage" -path '*-packages/poissondisk/__init__.py' | head -n 1)
[ -n "$init" ] || { echo "check-pkgconfig: make install-python installed no package"; exit 1; }
(cd "$stage" && env -u POISSONDISK_LIBRARY -u PDS_LIBRARY LD_LIBRARY_PATH="$root/lib" \
    PYTHONPATH="$(dirname "$(dirname "$init")")" /usr/bin/python3 -c '
import poissondisk
pts = poissondisk.sample(0.02, seed=7)
assert type(pts).__name__ == "ndarray" and pts.shape[1:] == (2,) and pts.dtype == "float64", pts
assert len(pts) > 1000, len(pts)
') || { echo "check-pkgconfig: the installed Python package does not work"; exit 1; }

make -s uninstall DESTDIR="$stage" PREFIX="$prefix" >/dev/null
left=$(find "$root" -type f -o -type l)
if [ -n "$left" ]; then echo "check-pkgconfig: uninstall left: $left"; exit 1; fi
echo "check-pkgconfig: shared and static builds through pkg-config work; make install-python gives a working package; uninstall is clean"
