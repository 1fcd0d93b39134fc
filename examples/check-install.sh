#!/bin/sh
# Installs agjk into a temporary prefix and builds examples/installed_check.c
# against it with pkg-config only, as a user would; runs it.
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A plain build of its own: variables of a calling make (a sanitizer build's OUT,
# OPT, LDFLAGS) must not leak into what a user would install.
env -u MAKEFLAGS -u MFLAGS -u MAKEOVERRIDES -u MAKELEVEL -u OUT -u OPT -u CFLAGS -u CPPFLAGS -u LDFLAGS \
    make -s -C "$top" OUT="$tmp/out" install PREFIX="$tmp/prefix" >/dev/null
export PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig"
cc=${CC:-cc}
# shellcheck disable=SC2046
$cc -std=c99 -Wall -Wextra -Wpedantic -Werror "$top/examples/installed_check.c" \
    $(pkg-config --cflags --libs agjk) -lm -Wl,-rpath,"$tmp/prefix/lib" -o "$tmp/installed_check"
"$tmp/installed_check"
# The program must have linked the shared library, with its SONAME.
ldd "$tmp/installed_check" | grep -q "libagjk.so.0 => $tmp/prefix/lib" || {
    echo "installed_check did not link the installed libagjk.so.0" >&2; exit 1; }
echo "install smoke test: 1 passed, 0 failed"
