#!/bin/sh
# Installs agjk into a temporary prefix and builds examples/installed_check.c
# against it with pkg-config only, as a user would; runs it. Then checks what
# make install put there (and built for it) and that make uninstall removes
# it all.
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
# make install: the library, the CLI and the man pages, and no benchmark or
# test program built for it.
for f in bin/agjk share/man/man1/agjk.1 share/man/man3/agjk.3 lib/cmake/agjk/agjkConfig.cmake; do
    [ -e "$tmp/prefix/$f" ] || { echo "make install did not install $f" >&2; exit 1; }
done
if [ -e "$tmp/out/tools/bench" ] || [ -e "$tmp/out/tests" ] || [ -e "$tmp/out/examples" ]; then
    echo "make install built more than the library and the CLI:" $(ls "$tmp/out/tools" "$tmp/out") >&2
    exit 1
fi
# make uninstall removes every file and the directories install created.
env -u MAKEFLAGS -u MFLAGS -u MAKEOVERRIDES -u MAKELEVEL -u OUT -u OPT -u CFLAGS -u CPPFLAGS -u LDFLAGS \
    make -s -C "$top" OUT="$tmp/out" uninstall PREFIX="$tmp/prefix" >/dev/null
if [ -e "$tmp/prefix" ]; then
    echo "make uninstall left:" >&2
    find "$tmp/prefix" >&2
    exit 1
fi
echo "install smoke test: 1 passed, 0 failed"
