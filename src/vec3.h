/* SPDX-License-Identifier: MIT */
/* Internal: tiny 3-vector helpers. Value semantics, all inline. */
#ifndef AGJK_SRC_VEC3_H
#define AGJK_SRC_VEC3_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "agjk/types.h"

/* Keep a rarely taken path out of line, or compile it for size (GCC and
 * clang optimise a cold function for size and move it away from hot code);
 * force a hot one inline where the compiler's size heuristics would not. */
#if defined(__GNUC__)
#define AGJK__NOINLINE __attribute__((noinline))
#define AGJK__COLD __attribute__((cold))
#define AGJK__ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define AGJK__NOINLINE
#define AGJK__COLD
#define AGJK__ALWAYS_INLINE inline
#endif

/* The hot entry points (the queries, the solver, the GJK projection) start
 * on a 64-byte boundary. Otherwise where each lands depends on how much
 * code the link puts before it, and the front end's fetch and decoded-
 * instruction cache see their loops and branches in another arrangement
 * after any change elsewhere: a change to the simplex code, never run by
 * one-support Boolean queries, moved agjk_collide from a 64-byte boundary
 * to 32 past one and those queries from 62.1 to 62.9-70.5 ns; aligned, they
 * took 62.1 again. (Up to 63 bytes of padding each.) */
#if defined(__GNUC__)
#define AGJK__HOT_ENTRY __attribute__((aligned(64)))
#else
#define AGJK__HOT_ENTRY
#endif

static inline agjk_vec3 v3(double x, double y, double z) {
    agjk_vec3 r;
    r.x = x;
    r.y = y;
    r.z = z;
    return r;
}
static inline agjk_vec3 v3_add(agjk_vec3 a, agjk_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline agjk_vec3 v3_sub(agjk_vec3 a, agjk_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline agjk_vec3 v3_scale(agjk_vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline agjk_vec3 v3_neg(agjk_vec3 a) { return v3(-a.x, -a.y, -a.z); }
static inline double v3_dot(agjk_vec3 a, agjk_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double v3_norm2(agjk_vec3 a) { return v3_dot(a, a); }
static inline double v3_norm(agjk_vec3 a) { return sqrt(v3_dot(a, a)); }
static inline agjk_vec3 v3_cross(agjk_vec3 a, agjk_vec3 b) {
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* |a| x |b| with absolute values: bounds the rounding of a x b, component by
 * component (a few eps times it). */
static inline agjk_vec3 v3_abs_cross(agjk_vec3 a, agjk_vec3 b) {
    return v3(fabs(a.y * b.z) + fabs(a.z * b.y), fabs(a.z * b.x) + fabs(a.x * b.z),
              fabs(a.x * b.y) + fabs(a.y * b.x));
}
/* a * s + b * t */
static inline agjk_vec3 v3_lerp2(agjk_vec3 a, double s, agjk_vec3 b, double t) {
    return v3(a.x * s + b.x * t, a.y * s + b.y * t, a.z * s + b.z * t);
}
static inline int v3_isfinite(agjk_vec3 a) {
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}
/* Finite and within AGJK_MAX_COORDINATE (NaN fails every comparison). */
static inline int v3_in_range(agjk_vec3 a) {
    return fabs(a.x) <= AGJK_MAX_COORDINATE && fabs(a.y) <= AGJK_MAX_COORDINATE &&
           fabs(a.z) <= AGJK_MAX_COORDINATE;
}
/* |a_x| + |a_y| + |a_z|: NaN and Inf propagate (v3_maxabs may drop a NaN). */
static inline double v3_norm1(agjk_vec3 a) { return fabs(a.x) + fabs(a.y) + fabs(a.z); }
static inline double v3_maxabs(agjk_vec3 a) {
    double m = fabs(a.x);
    if (fabs(a.y) > m) m = fabs(a.y);
    if (fabs(a.z) > m) m = fabs(a.z);
    return m;
}
/* 2^-e for 2^e <= m < 2^(e+1), m > 0 finite, or 0 when that power is not a
 * normal double (m denormal, or m >= 2^1023): by exponent arithmetic, since
 * ilogb and ldexp are library calls. */
static inline double pow2_inverse_floor(double m) {
    uint64_t bits;
    memcpy(&bits, &m, sizeof bits);
    int biased = (int)((bits >> 52) & 0x7ff); /* exponent e + 1023 */
    int target = 2046 - biased;                /* -e + 1023 */
    if (biased == 0 || target <= 0 || target >= 0x7ff) return 0.0;
    bits = (uint64_t)target << 52;
    double f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

/* a * 2^-ilogb(m) for m = max |a_i| > 0: max |a_i| lands in [1, 2), exactly
 * (a power of two), in two steps when 2^-ilogb(m) alone would overflow
 * (m denormal). */
static inline agjk_vec3 v3_scale_to_unit(agjk_vec3 a, double m) {
    double f = pow2_inverse_floor(m);
    if (f > 0.0) return v3_scale(a, f);
    int e = -ilogb(m);
    if (e > 1000) {
        a = v3_scale(a, ldexp(1.0, 1000));
        e -= 1000;
    }
    return v3_scale(a, ldexp(1.0, e));
}

/* a / m for m > 0, without overflowing 1/m when m is denormal. */
static inline agjk_vec3 v3_div(agjk_vec3 a, double m) {
    if (m >= 1e-300) return v3_scale(a, 1.0 / m); /* 1/m finite: multiply */
    return v3(a.x / m, a.y / m, a.z / m);
}
/* *p read as three separate 8-byte loads, for a vector stored just before
 * by other code: a load is served from the store buffer only when one store
 * covers it. clang stored x and y together and loaded y and z together, and
 * the load waited for the cache (a query's separating direction: 13 of the
 * 80 ns of a clang-built one-support Boolean query on ellipsoids; the
 * query's x_0: 10 of 57). Three scalar loads are covered whatever the stores
 * were (gcc's code: the same time). */
static inline agjk_vec3 v3_load_scalars(const agjk_vec3 *p) {
    const volatile double *q = &p->x;
    return v3(q[0], q[1], q[2]);
}
/* Unit vector along a, or the zero vector when a is zero. Tiny or huge vectors
 * are scaled first so that the squared norm neither underflows nor overflows;
 * in between, one square root and one division. */
static inline agjk_vec3 v3_normalize(agjk_vec3 a) {
    double n2 = v3_norm2(a);
    if (n2 >= 0x1p-900 && n2 <= 0x1p900) return v3_scale(a, 1.0 / sqrt(n2));
    double m = v3_maxabs(a);
    if (!(m > 0.0)) return v3(0.0, 0.0, 0.0);
    a = v3_div(a, m);
    return v3_scale(a, 1.0 / v3_norm(a));
}
/* R * p and R^T * p for a row-major 3x3 matrix given as 9 doubles
 * (pass &m[0][0]: C99 cannot convert double(*)[3] to const double(*)[3]). */
static inline agjk_vec3 m3_mul(const double *r, agjk_vec3 p) {
    return v3(r[0] * p.x + r[1] * p.y + r[2] * p.z,
              r[3] * p.x + r[4] * p.y + r[5] * p.z,
              r[6] * p.x + r[7] * p.y + r[8] * p.z);
}
static inline agjk_vec3 m3_tmul(const double *r, agjk_vec3 p) {
    return v3(r[0] * p.x + r[3] * p.y + r[6] * p.z,
              r[1] * p.x + r[4] * p.y + r[7] * p.z,
              r[2] * p.x + r[5] * p.y + r[8] * p.z);
}

#endif
