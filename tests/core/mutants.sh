#!/bin/sh
# SPDX-License-Identifier: MIT
# Mutation check of tests/core: builds copies of the library with one
# deliberate bug each (in a temporary directory; the tree is not touched) and
# runs the core tests against each copy. Every mutant must be caught by at
# least one test, or the tests cannot see that kind of bug. A mutant whose
# pattern no longer matches src/, or that no longer builds, fails the check
# too ("not applied", "does not build": update it), so that the list cannot
# go stale unnoticed.
# Not part of `make check` (a few minutes): run `make mutants-core`.
#   usage: tests/core/mutants.sh [OUT]   (OUT: the build dir, default out)
set -u
OUT=${1:-out}
ROOT=$(pwd)
CC=${CC:-cc}
CHECK_FLAGS=$(pkg-config --cflags --libs check)
COMMON=$ROOT/$OUT/tests/common/libtestcommon.a
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
[ -f "$COMMON" ] || { echo "build $COMMON first (make $OUT/tests/common/libtestcommon.a)"; exit 2; }

# name | file | sed expression (the bug)
MUTANTS='
separating-plane-epsilon|src/minkowski.h|s/double r = md->margin + md->noise;/double r = md->margin - 1e-7;/
separated-without-certificate|src/query.c|s/status = lower > agjk__minkowski_separation_level(&md)/status = cb.core > md.margin/
bound-too-small|src/query.c|s/result->bound = (distance - low) \* inv;/result->bound = 0.1 * (distance - low) * inv;/
ellipsoid-radius-typo|src/shape_points.h|s/r.z \* (r.z \* d.z)/r.y * (r.z * d.z)/
ellipsoid-support-biased|src/shape_points.h|s/    \*inv = root \* (1.0 \/ agjk__ellipsoid_root2(e, d));/    *inv = root * (1.0 \/ agjk__ellipsoid_root2(e, d)) * (1.0 + 4.0 * DBL_EPSILON);/
ellipsoid-plate-unchecked|src/minkowski.c|s/smallest >= 0x1p-380/smallest >= 0.0/
relative-tolerance-ignores-margins|src/solver.c|s/double b = (half \* (x_norm - md->margin - 2.0 \* md->noise)/double b = (half * (x_norm - 2.0 * md->noise)/
witness-without-margin|src/query.c|s/agjk_vec3 wa = v3_scale(v3_add(out.a, v3_scale(cb.toward_x, md.margin_a)), inv);/agjk_vec3 wa = v3_scale(out.a, inv);/
simplex-origin-on-face-not-inside|src/simplex.c|s/return (mask == 0xFu || v3_norm2(point) == 0.0) ? AGJK_STATUS_INTERSECTING/return (mask == 0xFu) ? AGJK_STATUS_INTERSECTING/
simplex-weights-permuted|src/simplex.c|s/projection->weights\[i\] = lambda\[i\];/projection->weights[i] = lambda[count - 1 - i];/
cone-support-biased|src/shape_cone.c|s/v3_dot(\*direction, apex) >= v3_dot(\*direction, rim)/v3_dot(*direction, apex) >= 0.9 * v3_dot(*direction, rim)/
climb-certification-skipped|src/shape_polytope.c|s/    if (!cut \&\& clear) {/    if (1) {/
climb-rising-edge-ignored|src/shape_polytope.c|s/            if (c == EDGE_UP) return -1 - u;/            if (c == EDGE_UP) continue;/
climb-rounding-not-allowed|src/shape_polytope.c|s/    return c->near < c->current_dot - DOT_ROUNDING \* own - 0x1p-1000;/    return c->near < c->current_dot - 0x1p-1000;/;s/double high = bounded ? dot : dot + DOT_ROUNDING \* (fabs(px) + fabs(py) + fabs(pz));/double high = dot;/
prepared-climb-rounding-not-allowed|src/shape_polytope.c|s/    if (bounded) return c->near < c->current_dot - DOT_ROUNDING \* (2.0 \* c->far) - 0x1p-1000;/    if (bounded) return c->near < c->current_dot - 0x1p-1000;/
prepared-starts-unchecked|src/shape_polytope.c|s/        if (prepared->starts\[k\] < 0 || prepared->starts\[k\] >= prepared->polytope.vertex_count)/        if (prepared->starts[k] < 0)/
prepared-bound-unchecked|src/shape_polytope.c|s/        !(bound <= prepared->coordinate_bound) ||/        !(0.0 <= prepared->coordinate_bound) ||/
rotation-check-loose|src/query_setup.c|s/#define ROTATION_TOLERANCE 1e-6/#define ROTATION_TOLERANCE 1e-1/
gjk-projection-kkt-ignored|src/simplex.c|s/return m >= 0.0 || m \* m <= OPTIMALITY_RELATIVE/return 1 || m * m <= OPTIMALITY_RELATIVE/
gjk-projection-inside-unchecked|src/simplex.c|s/na > DEGENERATE_RELATIVE \* (vol + n0 + n1 + n2)/na > -vol/
gjk-projection-vertex-early|src/simplex.c|s/if (r\[0\] >= 0.0 \&\& r\[1\] >= 0.0 \&\& r\[2\] >= 0.0) return vertex_output/if (r[0] >= 0.0 \&\& r[1] >= 0.0) return vertex_output/
gjk-projection-thin-face|src/simplex.c|s/#define WELL_CONDITIONED 1e-2/#define WELL_CONDITIONED 0.0/
gjk-projection-foot-from-newest|src/simplex.c|s/agjk_vec3 q = face.iq == 3 ? a : w\[face.iq\];/agjk_vec3 q = a;/
gjk-projection-edge-weight-by-difference|src/simplex.c|s/double s = v3_dot(b, u) \/ uu;/double s = 1.0 - (1.0 - v3_dot(b, u) \/ uu);/
ellipsoids-apart-without-allowance|src/solver.h|s/double r = md->margin + 128.0 \* DBL_EPSILON \* size;/double r = md->margin;/
frank-wolfe-drift-unreported|src/solver.c|s/out->noise = sv->md->noise + sv->drift;/out->noise = sv->md->noise;/
frank-wolfe-drift-not-in-margins|src/solver.c|s/ + noise + sv.drift;/ + noise;/
deferred-enclosure-uncertified|src/solver.c|s/    return noise == 0.0 || deep_enclosure(sv, noise) || shallow_faces(sv->w, noise) == 0;/    return 1;/
triangle-weights-unchecked|src/simplex.c|s/if (v3_norm2(v3_sub(back, foot)) <= limit \* limit \* far) {/if (1) {/
signed-distance-margins-unwidened|src/penetration.c|s/    if (!(margin > 0.0)) return;/    return;/
'
TESTS="simplex shapes api analytic methods properties collide verdicts penetration"
escaped=0
echo "$MUTANTS" | while IFS='|' read -r name file expr; do
    [ -n "$name" ] || continue
    d=$TMP/$name
    mkdir -p "$d"
    cp -r "$ROOT/src" "$ROOT/include" "$d/"
    sed -i "$expr" "$d/$file"
    if cmp -s "$ROOT/$file" "$d/$file"; then
        echo "$name: not applied (pattern gone from $file)"
        echo x >> "$TMP/stale"
        continue
    fi
    ok=1
    for f in "$d"/src/*.c; do
        $CC -std=c99 -O2 -ffp-contract=off -I"$d/include" -c "$f" -o "${f%.c}.o" || ok=0
    done
    [ $ok = 1 ] || { echo "$name: does not build"; echo x >> "$TMP/stale"; continue; }
    ar rcs "$d/libagjk.a" "$d"/src/*.o
    caught=""
    for t in $TESTS; do
        $CC -std=c99 -O2 -D_POSIX_C_SOURCE=200809L -I"$ROOT/include" -I"$ROOT/tests/common" \
            "$ROOT/tests/core/test_$t.c" -o "$d/test_$t" "$COMMON" "$d/libagjk.a" $CHECK_FLAGS -lm
        if ! "$d/test_$t" >/dev/null 2>&1; then caught="$caught $t"; fi
    done
    if [ -n "$caught" ]; then echo "$name: caught by$caught"; else echo "$name: ESCAPED"; echo x >> "$TMP/escaped"; fi
done
if [ -f "$TMP/escaped" ]; then echo "some mutants escaped the tests"; exit 1; fi
if [ -f "$TMP/stale" ]; then echo "some mutants no longer apply to src/: update them"; exit 1; fi
echo "all $(echo "$MUTANTS" | grep -c '|') mutants caught"
