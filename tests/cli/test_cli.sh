#!/bin/sh
# SPDX-License-Identifier: MIT
# tests/cli: the agjk command-line tool end to end.
#
#   tests/cli/test_cli.sh [AGJK_BINARY [SOURCE_DIR]]
#
# Defaults: the binary next to this script's build copy
# ($(OUT)/tests/cli/test_cli -> $(OUT)/tools/cli/agjk) and the current
# directory as the source tree. Truth comes from geometry worked out here
# (cube gaps, analytic sphere distances with the tessellation error computed
# from the mesh file by python3), never from agjk's own output.
set -u

here=$(cd "$(dirname "$0")" && pwd)
AGJK=${1:-$here/../../tools/cli/agjk}
SRC=${2:-.}
MESHES=$SRC/examples/meshes
fail=0
pass=0
tmp=$(mktemp -d "${TMPDIR:-/tmp}/agjk-cli-test.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM

if [ ! -x "$AGJK" ]; then echo "no agjk binary at $AGJK"; exit 1; fi
if [ ! -f "$MESHES/cube.off" ]; then echo "no sample meshes under $MESHES"; exit 1; fi

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# Sanitizer builds (make check-asan): a report on stderr fails the case, even
# when agjk still exits as expected (say, a memory error in the mesh loader's
# child process). Files that crash assimp on purpose run with $crash_env: the
# loader contains the crash in a child process, which inherits the
# sanitizer's signal handlers; with their default actions restored there the
# contained crash is not reported (memory errors in our code still are).
# Headers that ask assimp for gigabytes hit the sanitizer's allocation cap
# (SAN_ENV in tests/stability/stability.mk) in that child: the sanitizer
# reports the failed C++ `new` as out of memory before the child dies, which
# is the containment working; such reports are allowed in these runs only.
sanitizer_report='^==[0-9]+==ERROR: [A-Za-z]+Sanitizer|^SUMMARY: [A-Za-z]+Sanitizer|runtime error: '
contained_oom='Sanitizer: (allocator is out of memory|out-of-memory|requested allocation size|allocation-size-too-big)'
contained_crashes="ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}handle_segv=0:handle_sigbus=0:handle_abort=0:handle_sigfpe=0:handle_sigill=0"
crash_env=
no_sanitizer_report() {
    if [ -n "$crash_env" ]; then
        grep -E "$sanitizer_report" "$tmp/err" | grep -Evq "$contained_oom" || return 0
    fi
    if grep -Eq "$sanitizer_report" "$tmp/err"; then
        bad "$1: sanitizer report"
        sed 's/^/    stderr: /' "$tmp/err" | head -40
        return 1
    fi
    return 0
}

# run NAME EXPECTED_STATUS ARGS...: runs agjk, keeps stdout/stderr in $tmp.
# (POSIX sh has no local variables: callers must not rely on name/want/got.)
run() {
    name=$1; want=$2; shift 2
    env $crash_env "$AGJK" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    no_sanitizer_report "$name" || return 1
    if [ "$got" -ne "$want" ]; then
        bad "$name: exit status $got, expected $want (agjk $*)"
        sed 's/^/    stderr: /' "$tmp/err" | head -5
        return 1
    fi
    return 0
}

# expect_error NAME ARGS...: exit status 2, a message on stderr, nothing on stdout.
expect_error() {
    name=$1; shift
    run "$name" 2 "$@" || return
    if [ ! -s "$tmp/err" ]; then bad "$name: no message on stderr"; return; fi
    if [ -s "$tmp/out" ]; then bad "$name: unexpected output on stdout"; return; fi
    ok
}

# check_json NAME PYTHON_EXPR: the last output must be one JSON object `r`
# for which the expression is true. Checks are collected and evaluated by one
# python3 process at the end (python's start-up dominates otherwise).
nchecks=0
: >"$tmp/checks"
check_json() {
    nchecks=$((nchecks + 1))
    cp "$tmp/out" "$tmp/json.$nchecks"
    printf '%s\t%s\t%s\n' "$nchecks" "$1" "$2" >>"$tmp/checks"
}

run_json_checks() {
    python3 -c '
import json, math, sys
tmp = sys.argv[1]; good = bad = 0
for line in open(tmp + "/checks"):
    n, name, expr = line.rstrip("\n").split("\t", 2)
    text = open("%s/json.%s" % (tmp, n)).read()
    try:
        r = json.loads(text)
        ok = bool(eval(expr))
    except Exception as e:
        ok = False; expr += "  (%s)" % e
    if ok: good += 1
    else:
        bad += 1; print("FAIL: %s: JSON check failed: %s\n    %s" % (name, expr, text[:600]))
print(good, bad, file=sys.stderr)' "$tmp" 2>"$tmp/counts"
    read -r g b <"$tmp/counts" || { echo "FAIL: JSON checks did not run"; fail=$((fail + 1)); return; }
    pass=$((pass + g)); fail=$((fail + b))
}

# distance_is NAME EXPECTED TOL ARGS...: agjk distance ARGS gives EXPECTED (a
# python expression) to within TOL, with a small certified bound.
distance_is() {
    d_name=$1; d_want=$2; d_tol=$3; shift 3
    run "$d_name" 0 distance "$@" --json || return
    check_json "$d_name" "abs(r['distance'] - ($d_want)) <= $d_tol and r['bound'] <= 1e-4"
}

Q90Z="0.70710678118654757 0 0 0.70710678118654757"   # +90 degrees about z

# --- help and version ---------------------------------------------------------
for c in distance collide info hull; do
    run "help $c" 0 "$c" --help && grep -q "SYNOPSIS" "$tmp/out" && ok || bad "help $c text"
    run "help cmd $c" 0 help "$c" && grep -q "NAME" "$tmp/out" && ok || bad "agjk help $c"
done
run "--help" 0 --help && grep -q "EXIT STATUS" "$tmp/out" && ok || bad "--help text"
run "--version" 0 --version && grep -q "^agjk [0-9]" "$tmp/out" && ok || bad "--version text"
expect_error "no command"
expect_error "unknown command" frobnicate
expect_error "help for unknown" help frobnicate

# --- exact gaps between unit cubes ([-0.5, 0.5]^3) ---------------------------------
C=$MESHES/cube.off
distance_is "cubes 2 apart on x" 2 1e-12 "$C" "$C" --pose-b 3 0 0 1 0 0 0
distance_is "cubes apart diagonally" "math.sqrt(2)" 1e-12 "$C" "$C" --pose-b 2 2 0 1 0 0 0
distance_is "cubes apart, 3 axes" "math.sqrt(3) * 0.25" 1e-12 "$C" "$C" --pose-b 1.25 -1.25 1.25 1 0 0 0
distance_is "cube turned 45 deg about z" "3 - 0.5 - math.sqrt(0.5)" 1e-12 "$C" "$C" \
    --pose-b 3 0 0 0.92387953251128674 0 0 0.38268343236508978
distance_is "both cubes moved" 0.25 1e-12 "$C" "$C" --pose-a -10 5 1 1 0 0 0 --pose-b -8.75 5 1 1 0 0 0
distance_is "scaled cube" 1.5 1e-12 "$C" "$C" --pose-b 3 0 0 1 0 0 0 --scale-b 2
distance_is "scale in mm" 2000 1e-9 "$C" "$C" --pose-b 3000 0 0 1 0 0 0 --scale-a 1000 --scale-b 1000 --relative
for m in adaptive gjk nesterov nesterov-normalized polyak fw; do
    distance_is "method $m" 2 1e-6 "$C" "$C" --pose-b 3 0 0 1 0 0 0 --method "$m" --max-iterations 1000
done
distance_is "scan support" 2 1e-12 "$C" "$C" --pose-b 3 0 0 1 0 0 0 --scan
run "overlapping cubes" 0 distance "$C" "$C" --pose-b 0.5 0.2 0 1 0 0 0 --json &&
    check_json "overlapping cubes" "r['status'] == 'intersecting' and r['distance'] == 0"
# --signed: minus the penetration depth (cubes overlapping by 0.5 on x, 0.8 on y)
run "signed, overlapping cubes" 0 distance "$C" "$C" --pose-b 0.5 0.2 0 1 0 0 0 --signed --json &&
    check_json "signed, overlapping cubes" "r['status'] == 'intersecting' and abs(r['signed_distance'] + 0.5) <= 1e-12 and r['interval'][0] <= -0.5 <= r['interval'][1] and r['normal'] == [1, 0, 0] and abs(r['witness_a'][0] - r['witness_b'][0] - 0.5) <= 1e-12"
run "signed, separated cubes" 0 distance "$C" "$C" --pose-b 3 0 0 1 0 0 0 --signed --json &&
    check_json "signed, separated cubes" "abs(r['signed_distance'] - 2) <= 1e-12 and r['interval'][0] <= 2 <= r['interval'][1] and r['status'] == 'separated'"
run "signed, text" 0 distance "$C" "$C" --pose-b 0 0 0.25 1 0 0 0 --signed &&
    { grep -q '^signed_distance: *-0.75' "$tmp/out" && grep -q '^interval:' "$tmp/out" && ok || bad "signed, text output"; }

# --- quaternion convention: +90 degrees about z turns +x into +y ----------------------
printf 'OFF\n4 4 0\n0 0 0\n2 0 0\n0 0.1 0\n0 0 0.1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >"$tmp/arrow.off"
distance_is "arrow unrotated" "3 - 0.5 - 0.1" 1e-12 "$C" "$tmp/arrow.off" --pose-a 0 3 0 1 0 0 0
distance_is "arrow +90 about z points to +y" 0.5 1e-12 "$C" "$tmp/arrow.off" --pose-a 0 3 0 1 0 0 0 --pose-b 0 0 0 $Q90Z
distance_is "quaternion within rounding" 0.5 1e-5 "$C" "$tmp/arrow.off" --pose-a 0 3 0 1 0 0 0 --pose-b 0 0 0 0.7071068 0 0 0.7071068
distance_is "-q is the same rotation" 0.5 1e-12 "$C" "$tmp/arrow.off" --pose-a 0 3 0 1 0 0 0 --pose-b 0 0 0 -0.70710678118654757 0 0 -0.70710678118654757

# --- collide exit statuses --------------------------------------------------------
run "collide overlapping" 0 collide "$C" "$C" --pose-b 0.9 0 0 1 0 0 0 && ok
run "collide separated" 1 collide "$C" "$C" --pose-b 1.1 0 0 1 0 0 0 && ok
run "collide separated json" 1 collide "$C" "$C" --pose-b 0 0 -5 1 0 0 0 --json &&
    check_json "collide json" "r['status'] == 'separated' and r['colliding'] is False and abs(r['normal'][2]) > 0.5"
run "collide overlapping json" 0 collide "$C" "$MESHES/sphere.obj" --pose-b 1.2 0.3 0 1 0 0 0 --json &&
    check_json "collide json hit" "r['colliding'] is True"
run "not converged exits 3" 3 distance "$MESHES/sphere.obj" "$MESHES/sphere.obj" \
    --pose-b 2.5 0.3 0.1 1 0 0 0 --method fw --max-iterations 2 --tolerance 1e-14 && ok

# --- tessellated sphere against the analytic sphere --------------------------------
# r_in: the smallest distance from the centre to a face plane of sphere.obj.
# The mesh lies between the balls of radius r_in and 1, so its distance to a
# convex set at analytic distance D from the unit ball is in [D, D + (1 - r_in)]
# (twice that for two sphere meshes).
r_in=$(python3 -c '
import sys
v = []; rin = 1.0
for line in open(sys.argv[1]):
    t = line.split()
    if t and t[0] == "v": v.append(tuple(map(float, t[1:4])))
    elif t and t[0] == "f":
        a, b, c = (v[int(x.split("/")[0]) - 1] for x in t[1:4])
        u = [b[i] - a[i] for i in range(3)]; w = [c[i] - a[i] for i in range(3)]
        n = [u[1]*w[2] - u[2]*w[1], u[2]*w[0] - u[0]*w[2], u[0]*w[1] - u[1]*w[0]]
        nn = sum(x * x for x in n) ** 0.5
        rin = min(rin, abs(sum(n[i] * a[i] for i in range(3))) / nn)
print(repr(rin))' "$MESHES/sphere.obj")
S=$MESHES/sphere.obj
# Random rotations (fixed seed) so faces, not only vertices, face each other.
python3 -c '
import math, random
random.seed(7)
for k in range(6):
    q = [random.gauss(0, 1) for _ in range(4)]; n = math.sqrt(sum(x * x for x in q))
    d = random.uniform(2.2, 4.0); u = [random.gauss(0, 1) for _ in range(3)]
    un = math.sqrt(sum(x * x for x in u))
    print(" ".join(repr(x) for x in [d * c / un for c in u] + [x / n for x in q]), d)
' >"$tmp/poses"
while read -r tx ty tz qw qx qy qz d; do
    run "spheres at $d" 0 distance "$S" "$S" --pose-b "$tx" "$ty" "$tz" "$qw" "$qx" "$qy" "$qz" --json &&
        check_json "sphere meshes at centre distance $d" \
            "$d - 2 - 1e-9 <= r['distance'] <= $d - 2 + 2 * (1 - $r_in) + 1e-9"
    run "cube-sphere at $d" 0 distance "$C" "$S" --pose-b "$tx" "$ty" "$tz" "$qw" "$qx" "$qy" "$qz" --json &&
        check_json "cube vs sphere mesh at $d" \
            "(lambda c: c - 1 - 1e-9 <= r['distance'] <= c - 1 + (1 - $r_in) + 1e-9)(math.sqrt(sum(max(abs(x) - 0.5, 0) ** 2 for x in [$tx, $ty, $tz])))"
done <"$tmp/poses"
run "json keys" 0 distance "$C" "$S" --pose-b 2 0 0 1 0 0 0 --json &&
    check_json "json keys" "all(k in r for k in ['status','distance','bound','witness_a','witness_b','normal','iterations','support_calls','gap']) and len(r['witness_a']) == 3"
run "json witness" 0 distance "$C" "$S" --pose-b 2 0 0 1 0 0 0 --json &&
    check_json "witnesses are distance apart" \
        "abs(math.dist(r['witness_a'], r['witness_b']) - r['distance']) <= 1e-9 and abs(r['witness_a'][0] - 0.5) <= 1e-9"

# --- random poses against a brute-force reference (tests/cli/ref_distance.py) ---------
# Exact polytope distances by feature pairs in plain Python; the answer must be
# within agjk's certified bound and 1e-9 relative.
python3 "$SRC/tests/cli/ref_distance.py" mesh 1 "$tmp/ico1.obj"
for pair in "$C $tmp/ico1.obj 1" "$MESHES/tetrahedron.off $C 2" "$tmp/ico1.obj $tmp/ico1.obj 3"; do
    set -- $pair
    pa=$1; pb=$2; seed=$3
    python3 "$SRC/tests/cli/ref_distance.py" case "$seed" 10 "$pa" "$pb" >"$tmp/cases" ||
        bad "reference cases for $pa $pb"
    while read -r tx ty tz qw qx qy qz ref; do
        for m in nesterov gjk; do
            run "random pose $m" 0 distance "$pa" "$pb" --pose-b "$tx" "$ty" "$tz" "$qw" "$qx" "$qy" "$qz" \
                --method $m --json &&
                check_json "$(basename "$pa") vs $(basename "$pb") at $tx $ty $tz ($m): reference $ref" \
                    "(r['status'] == 'intersecting') if $ref == 0 else (r['status'] == 'separated' and abs(r['distance'] - $ref) <= r['bound'] + 1e-13 and abs(r['distance'] - $ref) <= 1e-9 * $ref)"
        done
    done <"$tmp/cases"
done

# --- valid but unusual files --------------------------------------------------------
distance_is "point cloud" 2 1e-12 "$MESHES/points.obj" "$C" --pose-b 3 0 0 1 0 0 0
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nl 1 2\nl 3 4\n' >"$tmp/lines.obj"
distance_is "lines only" 1.5 1e-12 "$tmp/lines.obj" "$C" --pose-b 0 0 3 1 0 0 0
distance_is "flat square" 1.5 1e-12 "$MESHES/square.off" "$C" --pose-b 0 0 2 1 0 0 0
printf '# segment\nv 0 0 -1\nv 0 0 1\nv 0 0 0.5\nl 1 2 3\n' >"$tmp/segment.obj"
distance_is "collinear" 1.5 1e-12 "$tmp/segment.obj" "$C" --pose-b 2 0 0 1 0 0 0
printf '# one point\no p\nv 0.25 0 0\nv 0.25 0 0\nf 1 2 1\n' >"$tmp/point.obj"
distance_is "single point" 2.25 1e-12 "$tmp/point.obj" "$C" --pose-b 3 0 0 1 0 0 0
run "info flat" 0 info "$MESHES/square.off" --json &&
    check_json "info flat" "r['hull'].startswith('flat') and r['hull_dimension'] == 2 and r['hill_climbing'] is False"
run "info sphere" 0 info "$S" --json &&
    check_json "info sphere" "r['hull_vertices'] == 642 and r['hull_triangles'] == 1280 and r['double_precision'] and r['bbox_max'] == [1, 1, 1]"
run "info text" 0 info "$C" && grep -q "hull_vertices: *8" "$tmp/out" && ok || bad "info text"
# Duplicated cube corners and interior points: the hull is still the cube.
python3 -c '
import itertools
pts = [p for p in itertools.product((-0.5, 0.5), repeat=3)] * 3 + [(0.1, 0.2, 0.3), (0, 0, 0)]
print("OFF\n%d 0 0" % len(pts)); [print(*p) for p in pts]' >"$tmp/dups.off"
run "duplicates" 0 info "$tmp/dups.off" --json 2>/dev/null && check_json "duplicates" "r['hull_vertices'] == 8"
# Double precision: coordinates that float cannot hold survive (OFF and OBJ).
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0.10000000000000001\n3 0 1 2\n3 0 1 3\n' >"$tmp/thin.off"
distance_is "double precision coordinates" "3 - 0.10000000000000001 - 0.5" 1e-13 "$tmp/thin.off" "$C" --pose-b 0 0 3 1 0 0 0
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1.00000001\nv 0 0 1.0000000099999999\nf 1 2 3\nf 1 2 5\n' >"$tmp/near.obj"
distance_is "double precision OBJ" "3 - 1.00000001 - 0.5" 1e-13 "$tmp/near.obj" "$C" --pose-b 0 0 3 1 0 0 0
printf 'ply\nformat ascii 1.0\ncomment c\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 0.10000000000000001 4\n3 0 1 2\n3 0 1 3\n' >"$tmp/double.ply"
distance_is "double precision PLY" "2.4" 1e-13 "$tmp/double.ply" "$C" --pose-b 0 0 3 1 0 0 0
sed 's/property double/property float/' "$tmp/double.ply" >"$tmp/float.ply"
# A PLY coordinate declared float is the float nearest 0.1 (python's struct rounds the same way).
distance_is "float PLY stays float" "2.5 - __import__('struct').unpack('f', __import__('struct').pack('f', 0.1))[0]" 1e-13 "$tmp/float.ply" "$C" --pose-b 0 0 3 1 0 0 0

# Other formats through assimp: PLY, binary STL, and glTF with a node
# transform (translation 10, scale 2) that must be applied.
python3 -c '
import itertools, struct, sys
pts = list(itertools.product((-0.5, 0.5), repeat=3))
quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
with open(sys.argv[1] + "/cube.ply", "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
            "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n")
    for p in pts: f.write("%r %r %r\n" % p)
    for q in quads: f.write("4 %d %d %d %d\n" % q)
tris = [(q[0], q[i], q[i + 1]) for q in quads for i in (1, 2)]
with open(sys.argv[1] + "/cube.stl", "wb") as f:
    f.write(b"\0" * 80 + struct.pack("<I", len(tris)))
    for t in tris:
        f.write(struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *pts[i]) for i in t) + b"\0\0")
' "$tmp"
distance_is "PLY cube" 2 1e-12 "$tmp/cube.ply" "$C" --pose-b 3 0 0 1 0 0 0
distance_is "binary STL cube" 2 1e-12 "$tmp/cube.stl" "$C" --pose-b 3 0 0 1 0 0 0
cat >"$tmp/tet.gltf" <<'EOF_GLTF'
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"children": [1], "translation": [10, 0, 0]}, {"mesh": 0, "scale": [2, 2, 2]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}],
 "buffers": [{"byteLength": 48, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/"}],
 "bufferViews": [{"buffer": 0, "byteLength": 48}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]}]}
EOF_GLTF
run "glTF node transforms" 0 info "$tmp/tet.gltf" --json &&
    check_json "glTF node transforms" "r['bbox_min'] == [10, 0, 0] and r['bbox_max'] == [12, 2, 2] and r['hull_vertices'] == 4"
# The tetrahedron (10,0,0) (12,0,0) (10,2,0) (10,0,2) against the cube at the origin.
distance_is "glTF distance" 9.5 1e-12 "$tmp/tet.gltf" "$C"

# Byte order mark, CRLF line ends, a Latin-1 comment: still the same tetrahedron.
printf '\357\273\277v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 0 0 1\r\nf 1 2 3\r\nf 1 2 4\r\n' >"$tmp/bom.obj"
distance_is "UTF-8 BOM + CRLF OBJ" 1.5 1e-12 "$tmp/bom.obj" "$C" --pose-b 0 0 3 1 0 0 0
printf '\357\273\277OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n' >"$tmp/bom.off"
distance_is "UTF-8 BOM OFF" 1.5 1e-12 "$tmp/bom.off" "$C" --pose-b 0 0 3 1 0 0 0
printf 'v 0 0 0\rv 1 0 0\rv 0 1 0\rv 0 0 0.1\rf 1 2 3\rf 1 2 4\r' >"$tmp/cr.obj"
distance_is "CR-only line ends, double precision" 2.4 1e-13 "$tmp/cr.obj" "$C" --pose-b 0 0 3 1 0 0 0
printf '# caf\351 \377 comment\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n' >"$tmp/latin1.obj"
distance_is "Latin-1 comment" 1.5 1e-12 "$tmp/latin1.obj" "$C" --pose-b 0 0 3 1 0 0 0
run "degenerate hull written" 0 hull "$MESHES/square.off" -o "$tmp/sqhull.off" && ok
distance_is "degenerate hull reads back" 1.5 1e-12 "$tmp/sqhull.off" "$C" --pose-b 0 0 2 1 0 0 0

# --- hull output ---------------------------------------------------------------------
run "hull -o" 0 hull "$S" -o "$tmp/hull.off" && ok
run "hull reads back" 0 info "$tmp/hull.off" --json &&
    check_json "hull round trip" "r['hull_vertices'] == 642 and r['double_precision']"
run "hull distance" 0 distance "$tmp/hull.off" "$C" --pose-b 2.5 0.1 0 1 0 0 0 --json && cp "$tmp/out" "$tmp/a.json"
run "mesh distance" 0 distance "$S" "$C" --pose-b 2.5 0.1 0 1 0 0 0 --json &&
    python3 -c 'import json,sys; a,b=(json.load(open(f)) for f in sys.argv[1:]); sys.exit(abs(a["distance"]-b["distance"]) > 1e-12)' \
        "$tmp/a.json" "$tmp/out" && ok || bad "hull file gives the same distance"
run "hull to stdout" 0 hull "$C" -o - && head -1 "$tmp/out" | grep -q '^OFF' && ok || bad "hull -o -"
expect_error "hull without -o" hull "$C"
expect_error "hull unwritable" hull "$C" -o "$tmp/no/such/dir/x.off"

# --- bad files: exit status 2, a message naming the file, no crash -------------------
: >"$tmp/empty.off"
: >"$tmp/empty.obj"
head -c 200 "$S" >"$tmp/trunc.obj"
head -c 70 "$C" >"$tmp/trunc.off"
python3 -c '
import random, sys
random.seed(3)
open(sys.argv[1], "wb").write(bytes(random.randrange(256) for _ in range(5000)))
open(sys.argv[2], "wb").write(bytes(random.randrange(256) for _ in range(5000)))
open(sys.argv[3], "wb").write(open(sys.argv[5]).read().encode("utf-16"))
open(sys.argv[4], "wb").write(b"\x00" * 4096)' \
    "$tmp/garbage.obj" "$tmp/garbage.off" "$tmp/utf16.obj" "$tmp/zeros.off" "$S"
printf 'v 0 0 0\nv 1 0 0\nv nan 0 1\nv 0 1 0\nf 1 2 3\nf 1 2 4\n' >"$tmp/nan.obj"
printf 'OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 inf\n3 0 1 2\n' >"$tmp/inf.off"
printf 'v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n' >"$tmp/overflow.obj"
printf 'OFF\n1000000000 1 0\n0 0 0\n' >"$tmp/hugecount.off"
printf 'ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n' >"$tmp/huge.ply"
printf '# nothing but a comment, long enough for assimp\n' >"$tmp/comments.obj"
printf 'solid broken\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n' >"$tmp/broken.stl"
mkdir -p "$tmp/dir.off"
crash_env=$contained_crashes
for f in empty.off empty.obj trunc.obj trunc.off garbage.obj garbage.off utf16.obj zeros.off \
         nan.obj inf.off overflow.obj hugecount.off huge.ply comments.obj broken.stl dir.off \
         missing.off; do
    expect_error "bad file $f" distance "$tmp/$f" "$C" --timeout 60
    grep -q "$f" "$tmp/err" || bad "message for $f does not name the file"
done
for f in empty.off garbage.obj nan.obj huge.ply; do
    expect_error "bad file $f (info)" info "$tmp/$f" --timeout 60
done
crash_env=
run "nan message" 2 info "$tmp/nan.obj"; grep -q "not finite" "$tmp/err" && ok || bad "NaN message"
run "UTF-16 message" 2 info "$tmp/utf16.obj"; grep -q "UTF-16" "$tmp/err" && ok || bad "UTF-16 message"

# Files that crash or hang assimp 5.2 itself (found by fuzzing; tests/cli/data):
# the import runs in a child process with a time budget, and PLY headers are
# checked first, so they give a message, not a crash or a hang.
crash_env=$contained_crashes
for f in "$SRC"/tests/cli/data/assimp-*; do
    expect_error "assimp crash $(basename "$f")" distance "$f" "$C"
done
crash_env=

# Random corruption of good files: any outcome but a crash or a hang. A
# corrupted file may still be valid, so exit status 0 is allowed too.
python3 -c '
import random, sys
random.seed(11)
for name in sys.argv[2:]:
    data = open(name, "rb").read()
    for k in range(8):
        b = bytearray(data)
        for _ in range(random.choice((1, 5, 40))):
            b[random.randrange(len(b))] = random.randrange(256)
        ext = name.rsplit(".", 1)[1]
        open("%s/mut_%s_%02d.%s" % (sys.argv[1], ext, k, ext), "wb").write(b)' "$tmp" "$C" "$S"
crash_env=$contained_crashes
for f in "$tmp"/mut_*; do
    env $crash_env "$AGJK" distance "$f" "$C" --timeout 60 >/dev/null 2>"$tmp/err"
    s=$?
    if ! no_sanitizer_report "corrupted $(basename "$f")"; then :
    elif [ "$s" -ne 0 ] && [ "$s" -ne 2 ]; then bad "corrupted $(basename "$f"): exit status $s"
    elif [ "$s" -eq 2 ] && [ ! -s "$tmp/err" ]; then bad "corrupted $(basename "$f"): no message"
    else ok; fi
done
crash_env=

# --- mesh reader: strict OFF/OBJ, every vertex, true precision, large files -------------
# Each malformed fixture of tests/cli/data/reader-* is an error (exit 2) whose
# message starts with FILE:LINE: and says what is wrong.
D=$SRC/tests/cli/data
reader_error() {  # FIXTURE LINE PHRASE
    expect_error "reader $1" distance "$D/$1" "$C" || return
    grep -q "$D/$1:$2: .*$3" "$tmp/err" && ok ||
        bad "reader $1: expected '$D/$1:$2: ...$3', got: $(head -c 300 "$tmp/err")"
}
reader_error reader-off-index-range.off 8 "index 99999999 is out of range"
reader_error reader-off-negative-index.off 7 "index -1 is out of range"
reader_error reader-off-empty-faces.off 6 "vertex count '0' is not a positive integer"
reader_error reader-off-short-face.off 8 "declares 3 vertices but lists 2"
reader_error reader-off-missing-face.off 7 "ends after 1 of the 2 faces"
reader_error reader-off-missing-vertex.off 5 "ends after 3 of the 4 vertices"
reader_error reader-off-extra-face.off 8 "unexpected data after the 1 faces"
reader_error reader-off-1e200.off 4 "'1e200' is out of range (limit 1e50)"
reader_error reader-off-not-number.off 5 "'1,5' is not a number"
reader_error reader-off-two-numbers.off 5 "has 2 numbers"
reader_error reader-off-no-face-count.off 2 "face count is missing"
reader_error reader-off-4d.off 1 "unsupported OFF variant '4OFF'"
reader_error reader-obj-1e200.obj 2 "'1e200' is out of range (limit 1e50)"
reader_error reader-obj-nan.obj 4 "'nan' is not finite"
reader_error reader-obj-index-range.obj 4 "v index 4 is out of range"
reader_error reader-obj-relative-range.obj 4 "relative v index -4 .* out of range"
reader_error reader-obj-index-zero.obj 4 "index 0"
reader_error reader-obj-vt-range.obj 5 "vt index 2 is out of range"
reader_error reader-obj-two-numbers.obj 3 "vertex with 2 numbers"
reader_error reader-obj-hex.obj 3 "'0x1p3' is not a number"
reader_error reader-obj-unknown.obj 4 "unknown OBJ statement 'frobnicate'"
reader_error reader-obj-bad-index.obj 4 "'3x' is not a valid index"
reader_error reader-off-crlf-bom.off 6 "'x' is not a number"
run "reader line ends" 0 info "$D/reader-obj-line-ends.obj" --json &&
    check_json "OBJ continuation, CR, CRLF" "r['vertices'] == 4 and r['bbox_max'] == [1, 1, 1] and r['faces'] == 1"
# ASCII PLY: assimp judges the file, then its vertex records are read as text
# (strict numbers, file:line messages; declared float stays float).
reader_error reader-ply-1e200-double.ply 11 "vertex 1: coordinate '1e200' is out of range (limit 1e50)"
reader_error reader-ply-1e45-float.ply 11 "vertex 1: .*out of range for the float the header declares"
run "reader PLY 21-digit integer" 0 info "$D/reader-ply-long-integer.ply" --json &&
    check_json "PLY 21-digit integer read exactly" "r['bbox_max'][0] == 111111111111111111111.0 and r['double_precision']"
# Numbers beyond what float or a fast parser reads: a 21-digit integer (assimp
# read it as 0) and coordinates of 4,100 digits, read as the nearest double.
run "reader long integer" 0 info "$D/reader-obj-long-integer.obj" --json &&
    check_json "21-digit integer read exactly" "r['bbox_max'][0] == 111111111111111111111.0 and r['vertices'] == 4"
run "reader long integer collides" 0 collide "$D/reader-obj-long-integer.obj" "$C" --pose-b 5e19 0 0 1 0 0 0 && ok
python3 -c '
import sys
open(sys.argv[1], "w").write("v 0.%s 0 0\nv 0 1 0\nv 0 0 1\nv -%s 0 0\n" % ("9" * 4100, "1" + "0" * 40 + "." + "0" * 4059))
open(sys.argv[2], "w").write("v 0 0 0\nv 1 0 0\nv 1%s 0 0\n" % ("0" * 4099))
open(sys.argv[3], "w").write("ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
    "property double y\nproperty double z\nend_header\n" + "".join(
    l[2:] + "\n" for l in open(sys.argv[1]).read().splitlines()))' \
    "$tmp/digits.obj" "$tmp/digits-overflow.obj" "$tmp/digits.ply"
run "reader 4100 digits" 0 info "$tmp/digits.obj" --json &&
    check_json "4100-digit coordinates" "r['bbox_max'][0] == 1.0 and r['bbox_min'][0] == -1e40"
run "reader 4100 digits PLY" 0 info "$tmp/digits.ply" --json &&
    check_json "4100-digit coordinates in PLY" "r['bbox_max'][0] == 1.0 and r['bbox_min'][0] == -1e40"
expect_error "reader 4100-digit overflow" info "$tmp/digits-overflow.obj"
grep -q "digits-overflow.obj:3: .*out of range (limit 1e50)" "$tmp/err" && ok || bad "4100-digit overflow message: $(cat "$tmp/err")"
# Vertices no face uses are points of the shape (OFF and OBJ).
run "reader unused OBJ vertices" 0 info "$D/reader-obj-unused.obj" --json &&
    check_json "unused OBJ vertices count" "r['vertices'] == 6 and r['bbox_min'] == [-2, 0, 0] and r['bbox_max'] == [3, 3, 3]"
distance_is "unused OBJ vertex is the closest" 0.5 1e-12 "$D/reader-obj-unused.obj" "$C" --pose-b 3 3 4 1 0 0 0
run "reader unused OFF vertex" 0 info "$D/reader-off-unused.off" --json &&
    check_json "unused OFF vertex counts" "r['vertices'] == 5 and r['bbox_max'] == [1, 1, 5]"
distance_is "unused OFF vertex" 1.5 1e-12 "$D/reader-off-unused.off" "$C" --pose-b 0 0 7 1 0 0 0
# Valid records of all kinds: colours after OFF vertices and faces; vt, vn, groups, l, p in OBJ.
run "reader COFF colours" 0 info "$D/reader-off-colours.off" --json &&
    check_json "COFF" "r['vertices'] == 4 and r['hull_vertices'] == 4"
run "reader OBJ records" 0 info "$D/reader-obj-records.obj" --json &&
    check_json "OBJ records" "r['vertices'] == 4 and r['faces'] == 4 and r['double_precision']"
# Precision report: a PLY declaring float is float; declared double is double.
run "reader float PLY precision" 0 info "$tmp/float.ply" --json &&
    check_json "float PLY is reported float" "r['double_precision'] is False"
run "reader double PLY precision" 0 info "$tmp/double.ply" --json &&
    check_json "double PLY is reported double" "r['double_precision'] is True"
run "reader float PLY text" 0 info "$tmp/float.ply" && grep -q "^precision: *float" "$tmp/out" && ok ||
    bad "agjk info on a float PLY: $(grep precision "$tmp/out")"
# A large point set (above CLI_QUERY_HULL_MAX_POINTS: the query scans the points
# instead of building the hull) and its hull file give the exact distance.
python3 -c '
import math, random, sys
random.seed(5)
with open(sys.argv[1], "w") as f:
    for i in range(70000):
        x, y, z = (random.gauss(0, 1) for _ in range(3)); n = math.sqrt(x*x + y*y + z*z)
        f.write("v %r %r %r\n" % (x / n, y / n, z / n))
    f.write("v 1 0 0\n")' "$tmp/big.obj"
distance_is "large point set" 1.5 1e-12 "$tmp/big.obj" "$C" --pose-b 3 0 0 1 0 0 0
run "large point set hull" 0 hull "$tmp/big.obj" -o "$tmp/bighull.off" && ok
distance_is "large hull file" 1.5 1e-12 "$tmp/bighull.off" "$C" --pose-b 3 0 0 1 0 0 0
run "large hull info" 0 info "$tmp/bighull.off" --json &&
    check_json "large hull info" "r['vertices'] == r['hull_vertices'] and r['hill_climbing'] is True"

# --- bad command lines -----------------------------------------------------------------
expect_error "one file" distance "$C"
expect_error "three files" distance "$C" "$C" "$C"
expect_error "unknown option" distance "$C" "$C" --frobnicate
expect_error "pose too short" distance "$C" "$C" --pose-b 1 2 3
expect_error "pose not a number" distance "$C" "$C" --pose-b 1 2 3x 1 0 0 0
expect_error "pose nan" distance "$C" "$C" --pose-b nan 0 0 1 0 0 0
expect_error "pose inf" distance "$C" "$C" --pose-b 0 inf 0 1 0 0 0
expect_error "pose empty" distance "$C" "$C" --pose-b "" 0 0 1 0 0 0
expect_error "pose leading blank" distance "$C" "$C" --pose-b " 1" 0 0 1 0 0 0
expect_error "pose overflow" distance "$C" "$C" --pose-b 1e999 0 0 1 0 0 0
expect_error "quaternion not unit" distance "$C" "$C" --pose-b 0 0 0 1 1 0 0
expect_error "quaternion zero" distance "$C" "$C" --pose-b 0 0 0 0 0 0 0
expect_error "quaternion 1.001" distance "$C" "$C" --pose-b 0 0 0 1.001 0 0 0
expect_error "method unknown" distance "$C" "$C" --method newton
expect_error "method missing" distance "$C" "$C" --method
expect_error "tolerance zero" distance "$C" "$C" --tolerance 0
expect_error "tolerance negative" distance "$C" "$C" --tolerance -1e-8
expect_error "tolerance text" distance "$C" "$C" --tolerance 1e-8x
expect_error "iterations zero" distance "$C" "$C" --max-iterations 0
expect_error "iterations fraction" distance "$C" "$C" --max-iterations 2.5
expect_error "iterations huge" distance "$C" "$C" --max-iterations 99999999999999
expect_error "scale zero" distance "$C" "$C" --scale-a 0
expect_error "scale negative" distance "$C" "$C" --scale-b -2
expect_error "scale overflow" distance "$C" "$tmp/arrow.off" --scale-b 1e308
expect_error "scale beyond range" distance "$C" "$tmp/arrow.off" --scale-b 1e50
expect_error "translation beyond range" distance "$C" "$C" --pose-b 1e51 0 0 1 0 0 0
printf 'v 0 0 0\nv 1e60 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n' >"$tmp/far.obj"
expect_error "vertex beyond range" distance "$tmp/far.obj" "$C"
expect_error "json on hull" hull "$C" -o "$tmp/x.off" --json
expect_error "timeout negative" info "$C" --timeout -1

# === Output of what a query computed, global options, info's support method ===
# (JSON null / text n/a for values a command does not compute.)
run "collide separated: no distance" 1 collide "$C" "$C" --pose-b 3 0 0 1 0 0 0 --json &&
    check_json "collide separated nulls" "r['distance'] is None and r['bound'] is None and r['witness_a'] is None and r['witness_b'] is None and r['gap'] is None and r['normal'] == [1, 0, 0] and r['colliding'] is False"
run "collide intersecting: no normal" 0 collide "$C" "$C" --pose-b 0.5 0.2 0 1 0 0 0 --json &&
    check_json "collide intersecting nulls" "r['status'] == 'intersecting' and r['normal'] is None and r['distance'] is None and r['gap'] is None and r['colliding'] is True"
run "collide not converged: gap given" 3 collide "$S" "$S" --pose-b 1.9 0.3 0.1 1 0 0 0 --method fw --max-iterations 2 --json &&
    check_json "collide not converged" "r['status'] == 'not converged' and r['colliding'] is None and isinstance(r['gap'], (int, float)) and r['gap'] > 0 and r['distance'] is None and len(r['normal']) == 3"
run "distance intersecting: no normal, no gap" 0 distance "$C" "$C" --pose-b 0.5 0.2 0 1 0 0 0 --json &&
    check_json "distance intersecting nulls" "r['status'] == 'intersecting' and r['normal'] is None and r['gap'] is None and r['distance'] == 0 and len(r['witness_a']) == 3"
run "distance separated: every value" 0 distance "$C" "$C" --pose-b 3 0 0 1 0 0 0 --json &&
    check_json "distance separated values" "all(r[k] is not None for k in r) and r['normal'] == [1, 0, 0]"
run "collide text intersecting" 0 collide "$C" "$C" --pose-b 0.5 0.2 0 1 0 0 0 &&
    grep -q "^normal: *n/a$" "$tmp/out" && ! grep -q "^distance:" "$tmp/out" && ok || bad "collide text: normal n/a, no distance"
run "distance text intersecting" 0 distance "$C" "$C" --pose-b 0.5 0.2 0 1 0 0 0 &&
    grep -q "^normal: *n/a$" "$tmp/out" && grep -q "^gap: *n/a$" "$tmp/out" && grep -q "^distance: *0$" "$tmp/out" &&
    ok || bad "distance text: normal and gap n/a"
# Global options before the command mean the same as after it.
run "--json before the command" 0 --json distance "$C" "$C" --pose-b 3 0 0 1 0 0 0 &&
    check_json "--json before the command" "r['query'] == 'distance' and abs(r['distance'] - 2) <= 1e-12"
run "global limits before the command" 0 --timeout 60 --memory-limit 0 --json info "$C" &&
    check_json "global options, info" "r['hull_vertices'] == 8"
run "global option, text" 1 --timeout 60 collide "$C" "$C" --pose-b 3 0 0 1 0 0 0 &&
    grep -q "^status: *separated$" "$tmp/out" && ok || bad "--timeout before collide"
expect_error "global option without value" --timeout
expect_error "only global options" --json
expect_error "global option a command lacks" --json hull "$C" -o "$tmp/x.off"
expect_error "not a global option before the command" --scan distance "$C" "$C"
# Which support function queries use: a scan below the library's threshold
# (AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES, 32), hill climbing from it on.
run "info support, 8 vertices" 0 info "$C" &&
    grep -q "^support: *scan over the hull vertices" "$tmp/out" && ok || bad "info: cube is scanned"
run "info support, 642 vertices" 0 info "$S" &&
    grep -q "^support: *hill climbing" "$tmp/out" && ok || bad "info: sphere climbs"
run "info json support, 8 vertices" 0 info "$C" --json &&
    check_json "info cube scans" "r['hill_climbing'] is False and r['hull_vertices'] == 8"
run "info json support, 642 vertices" 0 info "$S" --json &&
    check_json "info sphere climbs" "r['hill_climbing'] is True"
python3 -c '
import math
n = 32
print("OFF\n%d 0 0" % n)
for i in range(n):
    t = 2 * math.pi * i / 16
    print(math.cos(t), math.sin(t), 0.5 if i < 16 else -0.5)' >"$tmp/prism32.off"
python3 -c '
import math
n = 31
print("OFF\n%d 0 0" % n)
for i in range(n):
    t = 2 * math.pi * i / 16
    print(math.cos(t), math.sin(t), 0.5 if i < 16 else -0.5)' >"$tmp/prism31.off"
run "info json, 32 hull vertices" 0 info "$tmp/prism32.off" --json &&
    check_json "32 hull vertices climb" "r['hull_vertices'] == 32 and r['hill_climbing'] is True"
run "info json, 31 hull vertices" 0 info "$tmp/prism31.off" --json &&
    check_json "31 hull vertices scan" "r['hull_vertices'] == 31 and r['hill_climbing'] is False"
# Help text: the keys it names for the text output are the keys printed.
run "distance text keys" 0 distance "$C" "$C" --pose-b 3 0 0 1 0 0 0 &&
    keys=$(sed -n 's/^\([a-z_]*\):.*/\1/p' "$tmp/out" | tr '\n' ' ') &&
    "$AGJK" distance --help | tr -s ' \n' ' ' | grep -q "for distance, $(echo "$keys" | sed 's/ $//; s/ /, /g');" &&
    ok || bad "agjk distance --help does not list the text keys: $keys"
run "collide text keys" 1 collide "$C" "$C" --pose-b 3 0 0 1 0 0 0 &&
    keys=$(sed -n 's/^\([a-z_]*\):.*/\1/p' "$tmp/out" | tr '\n' ' ') &&
    "$AGJK" collide --help | tr -s ' \n' ' ' | grep -q "for collide, $(echo "$keys" | sed 's/ $//; s/ /, /g')\." &&
    ok || bad "agjk collide --help does not list the text keys: $keys"
# Binary formats other than OBJ/OFF load (binary PLY and GLB; binary STL above).
python3 -c '
import itertools, json, struct, sys
pts = list(itertools.product((-0.5, 0.5), repeat=3))
with open(sys.argv[1] + "/bin.ply", "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\n"
            b"property float y\nproperty float z\nend_header\n")
    for p in pts: f.write(struct.pack("<3f", *p))
blob = b"".join(struct.pack("<3f", *p) for p in pts)
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
       "nodes": [{"mesh": 0, "translation": [10, 0, 0]}],
       "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}],
       "buffers": [{"byteLength": len(blob)}],
       "bufferViews": [{"buffer": 0, "byteLength": len(blob)}],
       "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                      "min": [-0.5] * 3, "max": [0.5] * 3}]}
js = json.dumps(doc).encode()
js += b" " * (-len(js) % 4)
body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(blob), 0x004E4942) + blob
with open(sys.argv[1] + "/cube.glb", "wb") as f:
    f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)' "$tmp"
distance_is "binary PLY cube" 2 1e-12 "$tmp/bin.ply" "$C" --pose-b 3 0 0 1 0 0 0
distance_is "GLB cube (node translation 10)" 9 1e-12 "$tmp/cube.glb" "$C"
# === end of the output / global options block ===

# --- review findings -------------------------------------------------------------
# Global options before `help` (moved after it) are not its topic.
run "global option before help" 0 --json help distance && grep -q "SYNOPSIS" "$tmp/out" && ok ||
    bad "agjk --json help distance"
# --signed taken out of the arguments must leave them NULL-terminated: a pose
# of six numbers once read a stale last argument as its seventh.
expect_error "signed, six-number pose" distance --signed "$C" "$C" --pose-b 3 0 0.7071068 0 0 0.7071068
expect_error "signed, six-number pose (flag last)" distance "$C" "$C" --pose-b 3 0 0.7071068 0 0 0.7071068 --signed
# Cubes face to face: a contact within tolerance with no direction known;
# the normal is not computed, so null / n/a, not a zero vector.
run "touching cubes, collide" 0 collide "$C" "$C" --pose-b 1 0 0 1 0 0 0 --json &&
    check_json "touching cubes, collide" "r['status'] == 'contact within tolerance' and r['normal'] is None"
run "touching cubes, distance" 0 distance "$C" "$C" --pose-b 1 0 0 1 0 0 0 &&
    grep -Eq '^normal: +n/a$' "$tmp/out" && ok || bad "touching cubes: normal printed as a vector"
# A result that cannot be written: a message and exit status 2, for info too.
if [ -w /dev/full ]; then
    for c in info distance; do
        if [ $c = info ]; then args="$C"; else args="$C $C --pose-b 3 0 0 1 0 0 0"; fi
        # shellcheck disable=SC2086
        "$AGJK" $c $args >/dev/full 2>"$tmp/err"
        got=$?
        [ "$got" -eq 2 ] && [ -s "$tmp/err" ] && ok || bad "$c to a full disk: status $got, stderr '$(cat "$tmp/err")'"
    done
fi
# A cloud 1e-200 across is as solid as the same cloud at 1: its squared
# extents once underflowed, and `info` called it a single point.
python3 -c '
import random, sys
random.seed(3)
pts = [[random.uniform(-1, 1) for _ in range(3)] for i in range(200)]
for name, s in (("unit", 1.0), ("tiny", 1e-200), ("huge", 1e40)):
    with open("%s/cloud-%s.obj" % (sys.argv[1], name), "w") as f:
        f.writelines("v %.17g %.17g %.17g\n" % (x * s, y * s, z * s) for x, y, z in pts)' "$tmp"
run "cloud at scale 1" 0 info "$tmp/cloud-unit.obj" --json && cp "$tmp/out" "$tmp/cloud-unit.json"
run "cloud at scale 1, hull" 0 hull "$tmp/cloud-unit.obj" -o "$tmp/cloud-unit.off"
for sc in tiny huge; do
    run "cloud $sc" 0 info "$tmp/cloud-$sc.obj" --json &&
        python3 -c '
import json, sys
a = json.load(open(sys.argv[1])); b = json.load(open(sys.argv[2]))
sys.exit(0 if b["hull"] == a["hull"] == "solid" and b["hull_vertices"] == a["hull_vertices"] and b["hull_triangles"] == a["hull_triangles"] else 1)' \
            "$tmp/cloud-unit.json" "$tmp/out" && ok || bad "cloud $sc: another hull than at scale 1"
    # The same triangles, the same way round (their orientation was once
    # judged on the points themselves, whose normals underflowed).
    run "cloud $sc, hull" 0 hull "$tmp/cloud-$sc.obj" -o "$tmp/cloud-$sc.off" &&
        [ "$(sed -n '/^3 /p' "$tmp/cloud-unit.off")" = "$(sed -n '/^3 /p' "$tmp/cloud-$sc.off")" ] &&
        ok || bad "cloud $sc: other hull triangles than at scale 1"
done
# Qhull out of memory (a memory limit) is an error, not a flat hull: `info`
# and `hull` once reported "nearly flat" with status 0, and `hull` wrote no
# faces.
# (A sanitizer's build sets no memory limit: tools/cli/cli_guard.c.)
if ! grep -aqE '__(asan|tsan)_init' "$AGJK"; then
    python3 -c '
import math, random, sys
random.seed(1)
with open(sys.argv[1] + "/sphere300k.obj", "w") as f:
    for i in range(300000):
        z = random.uniform(-1, 1); t = random.uniform(0, 2 * math.pi); r = math.sqrt(1 - z * z)
        f.write("v %.17g %.17g %.17g\n" % (r * math.cos(t), r * math.sin(t), z))' "$tmp"
    expect_error "info, Qhull out of memory" info "$tmp/sphere300k.obj" --memory-limit 100
    expect_error "hull, Qhull out of memory" hull "$tmp/sphere300k.obj" --memory-limit 100 -o "$tmp/h300k.off"
    [ ! -e "$tmp/h300k.off" ] && ok || bad "hull, Qhull out of memory: a file was written"
fi

run_json_checks
echo "cli tests: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
