#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetches Coal 3.0.3 (the C++ library of HPP-FCL's successor) for the
# benchmark's agjk/Coal comparison: headers and shared libraries from the PyPI
# wheels, unpacked into a local folder. No Python is needed at run time: the
# benchmark links libcoal.so directly.
#
#   tools/fetch-coal.sh [DEST]     (default DEST: $AGJK_COAL_DIR, else out/coal)
#
# Result: DEST/cmeel.prefix/include/{coal,eigen3,boost,...} and
# DEST/cmeel.prefix/lib/libcoal.so with the libraries it needs; `make bench`
# then builds tools/bench/coal_adapter.cpp and adds the Coal columns
# (`make bench BENCH_COAL_DIR=DEST` if DEST is not the default).
#
# The wheels (manylinux_2_28 x86_64): `coal==3.0.3` on PyPI is the Python
# binding; its C++ library and headers are the `libcoal==3.0.3` wheel it
# requires. libcoal.so needs cmeel-boost, cmeel-assimp, cmeel-octomap and
# cmeel-qhull at run time (found with `pip download --no-deps` and ldd); the
# headers need Eigen (cmeel-eigen) and Boost's. eigenpy, the coal wheel
# itself and the cmeel Python package are not needed. Versions are pinned to
# the ones the comparison was made with; override with COAL_WHEEL_SPECS.
# Offline: COAL_WHEELS=/dir holding those .whl files skips the download.
# Needs python3 with pip (for the download and to unzip) and about 300 MB.
set -eu

dest=${1:-${AGJK_COAL_DIR:-out/coal}}
python=${PYTHON:-python3}
specs=${COAL_WHEEL_SPECS:-"libcoal==3.0.3 cmeel-eigen==3.4.1 cmeel-boost==1.90.0 cmeel-assimp==6.0.5 cmeel-octomap==1.10.0 cmeel-qhull==8.0.2.1"}

die() { echo "fetch-coal: $*" >&2; exit 1; }

case "$(uname -s)-$(uname -m)" in
    Linux-x86_64) ;;
    *) die "the Coal wheels used here are for Linux x86_64 only (this is $(uname -s)-$(uname -m))" ;;
esac
command -v "$python" >/dev/null 2>&1 || die "$python not found (set PYTHON=...)"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

if [ -n "${COAL_WHEELS:-}" ]; then
    wheels=$COAL_WHEELS
    [ -d "$wheels" ] || die "COAL_WHEELS=$wheels is not a directory"
else
    "$python" -m pip --version >/dev/null 2>&1 || die "pip is missing: $python -m pip --version fails"
    wheels=$tmp
    echo "fetch-coal: downloading $specs (about 65 MB)" >&2
    # --platform/--python-version: the same manylinux wheels whatever the
    # local Python is (only cmeel-boost is tagged with a CPython version, for
    # its boost_python library, which is not used).
    # shellcheck disable=SC2086
    if ! "$python" -m pip download --no-deps --only-binary=:all: \
            --platform manylinux_2_28_x86_64 --python-version 3.11 \
            --timeout 30 --retries 1 -d "$wheels" $specs >"$tmp/pip.log" 2>&1; then
        tail -n 5 "$tmp/pip.log" >&2
        die "pip could not download the wheels (no network, or no access to PyPI?). Without network, download them elsewhere with
    pip download --no-deps --only-binary=:all: --platform manylinux_2_28_x86_64 --python-version 3.11 $specs
and run: COAL_WHEELS=/that/dir tools/fetch-coal.sh"
    fi
fi

mkdir -p "$dest"
"$python" - "$wheels" "$dest" <<'PY'
import glob, os, re, stat, sys, zipfile
wheels, dest = sys.argv[1], sys.argv[2]
found = sorted(glob.glob(os.path.join(wheels, "*.whl")))
if not any(os.path.basename(w).startswith("libcoal-") for w in found):
    sys.exit("fetch-coal: no libcoal-*.whl in %s" % wheels)
# Headers, shared libraries and licences; no Python modules, CMake files,
# static archives or executables.
keep = re.compile(r"^cmeel\.prefix/(include/.+|lib/lib[^/]+\.so(\.[0-9.]+)?)$")
for w in found:
    n_files = 0
    name = os.path.basename(w)
    with zipfile.ZipFile(w) as z:
        for info in z.infolist():
            f = info.filename
            lic = re.match(r"^[^/]+\.dist-info/licenses?/(.+)$", f) or \
                  re.match(r"^[^/]+\.dist-info/(LICEN[CS]E[^/]*)$", f)
            if lic:
                out = os.path.join(dest, "licenses", name.split("-")[0], lic.group(1))
            elif keep.match(f) and not f.endswith("/"):
                out = os.path.join(dest, f)
            else:
                continue
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with z.open(info) as src, open(out, "wb") as dst:
                dst.write(src.read())
            if f.endswith(".so") or ".so." in f:
                os.chmod(out, 0o755)
            n_files += 1
    print("fetch-coal: %-60s %5d files" % (name, n_files), file=sys.stderr)
PY

prefix=$dest/cmeel.prefix
[ -f "$prefix/lib/libcoal.so" ] || die "no cmeel.prefix/lib/libcoal.so after unpacking"
[ -f "$prefix/include/coal/narrowphase/gjk.h" ] || die "no coal/narrowphase/gjk.h after unpacking"
[ -d "$prefix/include/eigen3/Eigen" ] || die "no Eigen headers after unpacking (cmeel-eigen)"
[ -d "$prefix/include/boost" ] || die "no Boost headers after unpacking (cmeel-boost)"
version=$(sed -n 's/^# *define COAL_VERSION "\(.*\)"/\1/p' "$prefix/include/coal/config.hh" | head -n 1)

echo "fetch-coal: Coal ${version:-?} in $prefix"
echo "  headers:   $prefix/include (coal, eigen3, boost)"
echo "  library:   $prefix/lib/libcoal.so (RUNPATH \$ORIGIN/../lib)"
if command -v ldd >/dev/null 2>&1; then
    missing=$(ldd "$prefix/lib/libcoal.so" | grep 'not found' || true)
    if [ -n "$missing" ]; then
        echo "$missing" >&2
        die "libcoal.so still misses libraries (listed above)"
    fi
    echo "  runtime:   $(ldd "$prefix/lib/libcoal.so" | awk '/=>/ && $3 ~ /cmeel/ {printf "%s ", $1}')"
fi
echo "  size:      $(du -sh "$dest" | cut -f1)"
echo "fetch-coal: done; \`make bench\` now adds the Coal columns (BENCH_COAL_DIR=$dest)."
