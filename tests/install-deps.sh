#!/bin/sh
# install-deps.sh - make sure the tools 'make check' needs are present; on
# Debian, install the missing ones with apt-get (needs root).
#   check (pkg-config module) : the unit-test framework
#   valgrind                  : the memcheck pass
#   mandoc                    : man page lint
#   abidiff (abigail-tools)   : ABI comparison with the committed baseline
#   pkg-config                : install test of poissondisk.pc
#   clang, libclang-rt-N-dev  : make fuzz / check-fuzz (libFuzzer, ASan, UBSan runtimes)
#   python3-venv, -setuptools, -wheel, -pip, -numpy, -scipy : make check-python (the
#                               package is pip-installed offline into a venv of Debian's
#                               /usr/bin/python3, which alone sees Debian's numpy/scipy)
set -eu

missing=""
pkg-config --exists check 2>/dev/null || missing="$missing check"
command -v valgrind >/dev/null 2>&1 || missing="$missing valgrind"
command -v mandoc >/dev/null 2>&1 || missing="$missing mandoc"
command -v abidiff >/dev/null 2>&1 || missing="$missing abigail-tools"
command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
command -v python3 >/dev/null 2>&1 || missing="$missing python3"
sys_py_has() { [ -x /usr/bin/python3 ] && /usr/bin/python3 -c "import $1" >/dev/null 2>&1; }
sys_py_has ensurepip || missing="$missing python3-venv"
sys_py_has setuptools || missing="$missing python3-setuptools"
sys_py_has wheel || missing="$missing python3-wheel"
sys_py_has pip || missing="$missing python3-pip"
sys_py_has numpy || missing="$missing python3-numpy"
sys_py_has scipy || missing="$missing python3-scipy"
# libFuzzer: clang links a trivial fuzz target only when its runtime package (on
# Debian 12, libclang-rt-14-dev, named after clang's major version) is installed.
fuzzer_links() {
    fl_dir=$(mktemp -d "${TMPDIR:-/tmp}/install-deps.XXXXXX") || return 1
    printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
        'int LLVMFuzzerTestOneInput(const uint8_t *p, size_t n) { (void)p; (void)n; return 0; }' \
        > "$fl_dir/f.c"
    clang -fsanitize=fuzzer,address,undefined -o "$fl_dir/f" "$fl_dir/f.c" >/dev/null 2>&1
    fl_rc=$?
    rm -rf "$fl_dir"
    return $fl_rc
}
if ! command -v clang >/dev/null 2>&1; then
    missing="$missing clang libclang-rt-14-dev"
elif ! fuzzer_links; then
    missing="$missing libclang-rt-$(clang -dumpversion | cut -d. -f1)-dev"
fi

[ -z "$missing" ] && exit 0

echo "install-deps: missing:$missing"
if ! command -v apt-get >/dev/null 2>&1; then
    echo "install-deps: no apt-get here; install these yourself:$missing" >&2
    exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps: run 'make check' as root once, or: sudo apt-get install$missing" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null
# shellcheck disable=SC2086
apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "install-deps: installed$missing"
