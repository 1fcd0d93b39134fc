#!/bin/sh
# Sets up what agjk needs on Debian and runs the main job: a distance query
# between two of the bundled sample meshes with the agjk CLI.
#
# As root, installs missing packages with apt-get (without recommended
# packages, apt's output in /tmp/agjk-setup-apt.log); otherwise prints the
# exact command to run and stops. gnuplot is optional: `make bench` draws its
# plots with it when it is there (apt-get install --no-install-recommends
# gnuplot-nox).
set -eu
cd "$(dirname "$0")/.."

packages="build-essential pkg-config check libassimp-dev libqhull-dev libccd-dev \
meson ninja-build abigail-tools python3"
missing=""
for p in $packages; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
        missing="$missing $p"
done
if [ -n "$missing" ]; then
    if [ "$(id -u)" -eq 0 ]; then
        log=/tmp/agjk-setup-apt.log
        echo "setup: installing:$missing (apt output: $log)"
        if ! { apt-get update -qq &&
               DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
                   $missing; } >"$log" 2>&1; then
            tail -n 20 "$log" >&2
            echo "setup: apt-get failed (full output: $log)" >&2
            exit 1
        fi
    else
        echo "setup: missing Debian packages:$missing" >&2
        echo "setup: run this, then run me again:" >&2
        echo "  sudo apt-get install -y --no-install-recommends$missing" >&2
        exit 1
    fi
fi

echo "setup: building (make)"
make -s -j2
echo "\$ out/tools/cli/agjk distance examples/meshes/cube.off examples/meshes/sphere.obj --pose-b 2 0.3 0 1 0 0 0"
out/tools/cli/agjk distance examples/meshes/cube.off examples/meshes/sphere.obj --pose-b 2 0.3 0 1 0 0 0
