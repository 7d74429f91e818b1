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
#   lld, wasi-libc, libc++-N-dev-wasm32, libc++abi-N-dev-wasm32, libclang-rt-N-dev-wasm32
#                             : make js (the library in WebAssembly, with clang)
#   nodejs (>= 18), npm, chromium : make check-js (node --test; the demo page in headless
#                               chromium through puppeteer-core, which npm installs)
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

# make js: clang for wasm32 needs wasm-ld and the wasm32 C and C++ libraries of the
# same major version as clang (Debian 12: 14).
clang_major=$(clang -dumpversion 2>/dev/null | cut -d. -f1)
clang_major=${clang_major:-14}
command -v wasm-ld >/dev/null 2>&1 || missing="$missing lld"
[ -f /usr/lib/wasm32-wasi/libc.a ] || missing="$missing wasi-libc"
[ -f /usr/lib/llvm-$clang_major/lib/wasm32-wasi/libc++.a ] || \
    missing="$missing libc++-$clang_major-dev-wasm32"
[ -f /usr/lib/llvm-$clang_major/lib/wasm32-wasi/libc++abi.a ] || \
    missing="$missing libc++abi-$clang_major-dev-wasm32"
ls /usr/lib/llvm-$clang_major/lib/clang/*/lib/wasi/libclang_rt.builtins-wasm32.a \
    >/dev/null 2>&1 || missing="$missing libclang-rt-$clang_major-dev-wasm32"
command -v node >/dev/null 2>&1 || missing="$missing nodejs"
command -v npm >/dev/null 2>&1 || missing="$missing npm"
command -v chromium >/dev/null 2>&1 || missing="$missing chromium"

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
