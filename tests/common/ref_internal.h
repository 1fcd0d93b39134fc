/* SPDX-License-Identifier: MIT */
/* Internal to the reference solver (tests/common): long double 3-vectors and
 * the pieces reference.c is built from. Not used by the library. */
#ifndef AGJK_TEST_REF_INTERNAL_H
#define AGJK_TEST_REF_INTERNAL_H

#include "reference.h"

typedef long double ref_real;

typedef struct ref_v3 {
    ref_real x, y, z;
} ref_v3;

static inline ref_v3 rv(ref_real x, ref_real y, ref_real z) {
    ref_v3 r;
    r.x = x; r.y = y; r.z = z;
    return r;
}
static inline ref_v3 rv_add(ref_v3 a, ref_v3 b) { return rv(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline ref_v3 rv_sub(ref_v3 a, ref_v3 b) { return rv(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline ref_v3 rv_scale(ref_v3 a, ref_real s) { return rv(a.x * s, a.y * s, a.z * s); }
static inline ref_real rv_dot(ref_v3 a, ref_v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline ref_v3 rv_cross(ref_v3 a, ref_v3 b) {
    return rv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline ref_v3 rv_from(agjk_vec3 v) { return rv(v.x, v.y, v.z); }
static inline agjk_vec3 rv_to(ref_v3 v) {
    agjk_vec3 r;
    r.x = (double)v.x; r.y = (double)v.y; r.z = (double)v.z;
    return r;
}

ref_real ref_v3_norm(ref_v3 a);

/* Core support (margin excluded) of `s` in its local frame, and the total
 * margin (the sphere/capsule radius plus s->margin). */
ref_v3 ref_core_support(const ref_shape *s, ref_v3 direction);
ref_real ref_total_margin(const ref_shape *s);

/* Brute-force projection of the origin onto conv(w[0..n-1]), n in 1..4. */
void ref_project_ld(const ref_v3 *w, int n, ref_projection *out);

/* Barycentric coordinates of the origin in the tetrahedron w[0..3]; returns 0
 * if the tetrahedron is flat to working precision. */
int ref_tetra_barycentric(const ref_v3 *w, ref_real bary[4]);

#endif
