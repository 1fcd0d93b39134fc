#!/bin/sh
# SPDX-License-Identifier: MIT
# The CMake package, as a CMake user meets it: installs agjk into a temporary
# prefix, then configures, builds and runs a consumer project
# (find_package(agjk CONFIG REQUIRED) + target_link_libraries(app agjk::agjk))
# on a small program. Also checks: agjk::agjk is the shared library
# (agjk::agjk_static and agjk_USE_STATIC the static one), a request for
# another major version is refused, and the installed tree still works after
# being moved (relocatable). Exit status 77 (skipped) without cmake.
#
#   tests/build/cmake-package.sh                  installs with make install-lib
#   tests/build/cmake-package.sh --meson BUILDDIR installs BUILDDIR with meson install
set -eu
if ! command -v cmake >/dev/null 2>&1; then
    echo "cmake package: skipped, cmake not found (Debian: apt-get install cmake)"
    exit 77
fi
top=$(cd "$(dirname "$0")/../.." && pwd)
# The consumer must find the library through what CMake recorded, not through
# a search path of the caller's (meson test sets one to its build directory).
unset LD_LIBRARY_PATH
tmp=$(mktemp -d "${TMPDIR:-/tmp}/agjk-cmake.XXXXXX")
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
log=$tmp/log
version=$(sed -n 's/^VERSION *:= *//p' "$top/Makefile")
major=${version%%.*}
fail() {
    echo "cmake package: $*" >&2
    [ -s "$log" ] && tail -n 40 "$log" | sed 's/^/    /' >&2
    exit 1
}

if [ "${1:-}" = "--meson" ]; then
    meson install -C "$2" --no-rebuild --destdir "$tmp/dest" >"$log" 2>&1 ||
        fail "meson install failed"
    config=$(find "$tmp/dest" -name agjkConfig.cmake | head -n 1)
    [ -n "$config" ] || fail "meson install put no agjkConfig.cmake under $tmp/dest"
    # <prefix>/<libdir>/cmake/agjk/agjkConfig.cmake: move the whole destdir.
    installed=$tmp/dest
    prefix_in() { find "$1" -name agjkConfig.cmake | head -n 1 | xargs dirname; }
else
    # A plain build of its own: variables of a calling make (a sanitizer
    # build's OUT, OPT, LDFLAGS) must not leak into what a user would install.
    env -u MAKEFLAGS -u MFLAGS -u MAKEOVERRIDES -u MAKELEVEL -u OUT -u OPT -u CFLAGS \
        -u CPPFLAGS -u LDFLAGS make -s -C "$top" OUT="$tmp/out" install-lib \
        PREFIX="$tmp/prefix" >"$log" 2>&1 || fail "make install-lib failed"
    # install-lib installs what a C user links, and builds nothing else.
    got=$(cd "$tmp/prefix" && find . \( -type f -o -type l \) | sort | tr '\n' ' ')
    want=$({ (cd "$top" && ls include/agjk/*.h) | sed 's|^|./|'
             printf '%s\n' ./lib/cmake/agjk/agjk-created-dirs.txt ./lib/cmake/agjk/agjkConfig.cmake \
                 ./lib/cmake/agjk/agjkConfigVersion.cmake ./lib/libagjk.a ./lib/libagjk.so \
                 "./lib/libagjk.so.$major" "./lib/libagjk.so.$version" ./lib/pkgconfig/agjk.pc
           } | sort | tr '\n' ' ')
    [ "$got" = "$want" ] || fail "make install-lib installed: $got; expected: $want"
    [ ! -d "$tmp/out/tools" ] && [ ! -d "$tmp/out/tests" ] ||
        fail "make install-lib built tools or tests"
    installed=$tmp/prefix
    prefix_in() { echo "$1"; }
fi

mkdir -p "$tmp/app"
# A consumer that needs nothing but agjk (no libm of its own).
cat >"$tmp/app/main.c" <<'EOF_C'
#include <stdio.h>
#include <agjk/agjk.h>

int main(void) {
    agjk_shape a, b;
    agjk_box box = {{0.5, 0.5, 0.5}};
    agjk_pose pa = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
    agjk_pose pb = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {3.5, 4.5, 0.25}};
    agjk_result r;
    if (agjk_version() != AGJK_VERSION_NUMBER) return 1;
    agjk_shape_box(&a, &box);
    agjk_shape_sphere(&b, 1.0);
    /* Box corner region: the sphere's centre is (3, 4, 0) from the box's
     * nearest point (0.5, 0.5, 0.25), 5 away: distance 4. */
    if (agjk_distance(&a, &pa, &b, &pb, NULL, &r) != AGJK_STATUS_SEPARATED) return 2;
    if (r.distance - 4.0 > 1e-12 || 4.0 - r.distance > r.bound + 1e-12) return 3;
    printf("agjk %s: distance %.17g\n", agjk_version_string(), r.distance);
    return 0;
}
EOF_C
cat >"$tmp/app/CMakeLists.txt" <<EOF_CMAKE
cmake_minimum_required(VERSION 3.13)
project(agjk_consumer C)
find_package(agjk $((major + 1)) CONFIG QUIET)
if(agjk_FOUND)
  message(FATAL_ERROR "agjk $version accepted a request for major version $((major + 1))")
endif()
find_package(agjk $version CONFIG REQUIRED)
add_executable(app main.c)
target_link_libraries(app PRIVATE agjk::agjk)
add_executable(app_static main.c)
target_link_libraries(app_static PRIVATE agjk::agjk_static)
EOF_CMAKE

# build NAME PREFIX [CMAKE_ARGS...]: configure and build the consumer.
build() {
    b=$tmp/build-$1
    p=$2
    shift 2
    cmake -S "$tmp/app" -B "$b" -DCMAKE_PREFIX_PATH="$p" "$@" >"$log" 2>&1 ||
        fail "configuring the consumer against $p failed"
    cmake --build "$b" >"$log" 2>&1 || fail "building the consumer failed"
}
# links_shared PROGRAM: 0 if it loads libagjk.so.<major> from the installed tree.
links_shared() { ldd "$1" | grep -q "libagjk\.so\.$major => $tmp/"; }

build shared "$(prefix_in "$installed")"
"$tmp/build-shared/app" >"$log" 2>&1 || fail "app (agjk::agjk) failed"
"$tmp/build-shared/app_static" >"$log" 2>&1 || fail "app_static (agjk::agjk_static) failed"
links_shared "$tmp/build-shared/app" || fail "agjk::agjk did not link the installed libagjk.so.$major"
links_shared "$tmp/build-shared/app_static" && fail "agjk::agjk_static linked libagjk.so"

# Moved elsewhere, with agjk_USE_STATIC: paths come from the config file's place.
mv "$installed" "$tmp/moved"
build moved "$(prefix_in "$tmp/moved")" -Dagjk_USE_STATIC=ON
"$tmp/build-moved/app" >"$log" 2>&1 || fail "app (agjk_USE_STATIC, moved install) failed"
links_shared "$tmp/build-moved/app" && fail "agjk_USE_STATIC=ON still linked libagjk.so"
echo "cmake package: find_package(agjk $version), agjk::agjk (shared), agjk::agjk_static, relocated; 1 passed, 0 failed"
