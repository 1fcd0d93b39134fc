#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetches the real-mesh set of the benchmark: the 1000 random objects shipped
# in pybullet_data/random_urdfs of the pybullet 3.2.7 wheel (PyPI), as OBJ.
#
#   tools/fetch-meshes.sh [DEST]     (default DEST: out/meshes)
#
# Result: DEST/random_urdfs/NNN/NNN.obj, and the other OBJ meshes of
# pybullet_data (robot links, household objects) in DEST/pybullet_data/ for
# `make check-real-meshes`; `make bench` then adds the mesh
# benchmark (agjk-bench --mesh-dir DEST/random_urdfs). Needs python3 with pip
# and network access (or PYBULLET_WHEEL=/path/to/the/wheel). One object of the set has NaN vertices: it is kept on
# disk as shipped, reported here, and skipped with a warning by agjk-bench.
set -eu

dest=${1:-out/meshes}
python=${PYTHON:-python3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

if [ -n "${PYBULLET_WHEEL:-}" ]; then
    wheel=$PYBULLET_WHEEL   # an already downloaded wheel
else
    echo "fetch-meshes: downloading the pybullet==3.2.7 wheel (about 100 MB)" >&2
    # Any platform's wheel holds the same data files; prefer the local one and
    # fall back to the manylinux cp311 wheel if this Python has none.
    if ! "$python" -m pip download --no-deps --only-binary=:all: pybullet==3.2.7 \
            -d "$tmp" >&2; then
        "$python" -m pip download --no-deps --only-binary=:all: \
            --platform manylinux2014_x86_64 --python-version 311 pybullet==3.2.7 -d "$tmp" >&2
    fi
    wheel=$(ls "$tmp"/pybullet-3.2.7-*.whl | head -n 1)
fi

mkdir -p "$dest"
"$python" - "$wheel" "$dest" <<'PY'
import math, os, re, sys, zipfile
wheel, dest = sys.argv[1], sys.argv[2]
pattern = re.compile(r"^pybullet_data/random_urdfs/([^/]+)/([^/]+\.obj)$")
count = 0
with zipfile.ZipFile(wheel) as z:
    for name in z.namelist():
        m = pattern.match(name)
        if not m:
            continue
        data = z.read(name)
        out_dir = os.path.join(dest, "random_urdfs", m.group(1))
        os.makedirs(out_dir, exist_ok=True)
        with open(os.path.join(out_dir, m.group(2)), "wb") as f:
            f.write(data)
        count += 1
        for line in data.decode("utf-8", "replace").splitlines():
            parts = line.split()
            if parts[:1] != ["v"]:
                continue
            try:
                finite = all(math.isfinite(float(p)) for p in parts[1:4])
            except ValueError:
                finite = False
            if not finite:
                print("fetch-meshes: warning: %s has non-finite vertices "
                      "(agjk-bench skips it)" % name, file=sys.stderr)
                break
print("fetch-meshes: %d OBJ files in %s/random_urdfs" % (count, dest), file=sys.stderr)
if count == 0:
    sys.exit("fetch-meshes: no pybullet_data/random_urdfs/*/*.obj in the wheel")
# The other meshes of pybullet_data (robot links, household objects: CAD-like
# parts with large flat faces), flattened into one directory for
# check_real_meshes (make check-real-meshes).
other = os.path.join(dest, "pybullet_data")
os.makedirs(other, exist_ok=True)
others = 0
with zipfile.ZipFile(wheel) as z:
    for name in z.namelist():
        if (name.startswith("pybullet_data/") and name.lower().endswith(".obj")
                and not name.startswith("pybullet_data/random_urdfs/")):
            flat = name[len("pybullet_data/"):].replace("/", "__")
            with open(os.path.join(other, flat), "wb") as f:
                f.write(z.read(name))
            others += 1
print("fetch-meshes: %d other OBJ files in %s" % (others, other), file=sys.stderr)
PY
