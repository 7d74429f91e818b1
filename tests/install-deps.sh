#!/bin/sh
# install-deps.sh - make sure the tools 'make check' needs are present; on
# Debian, install the missing ones with apt-get (needs root).
#   check (pkg-config module) : the unit-test framework
#   valgrind                  : the memcheck pass
#   mandoc                    : man page lint
#   abidiff (abigail-tools)   : ABI comparison with the committed baseline
#   pkg-config                : install test of poissondisk.pc
set -eu

missing=""
pkg-config --exists check 2>/dev/null || missing="$missing check"
command -v valgrind >/dev/null 2>&1 || missing="$missing valgrind"
command -v mandoc >/dev/null 2>&1 || missing="$missing mandoc"
command -v abidiff >/dev/null 2>&1 || missing="$missing abigail-tools"
command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
command -v python3 >/dev/null 2>&1 || missing="$missing python3"

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
