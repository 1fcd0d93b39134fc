/* SPDX-License-Identifier: MIT */
/* Reference support functions, long double, written from the shapes'
 * definitions in include/agjk/shapes.h (not from src/). The margin (sphere
 * sweeping) is kept apart so the reference can add it analytically, as the
 * definition of a swept shape says: S + B(0, m) has support
 * s_S(d) + m d / |d|. */
#include <math.h>
#include "ref_internal.h"

ref_real ref_v3_norm(ref_v3 a) {
    /* Scaled to avoid overflow/underflow with 1e-9 .. 1e9 coordinates. */
    ref_real m = fabsl(a.x);
    if (fabsl(a.y) > m) m = fabsl(a.y);
    if (fabsl(a.z) > m) m = fabsl(a.z);
    if (m == 0.0L) return 0.0L;
    a = rv_scale(a, 1.0L / m);
    return m * sqrtl(rv_dot(a, a));
}

static ref_real sgn_half(ref_real v) {
    /* Any point of the face is a support when v == 0; take +1 so the result
     * is a vertex (a fixed, deterministic choice). */
    return v < 0.0L ? -1.0L : 1.0L;
}

/* Ellipsoid {p : sum (p_i / r_i)^2 <= 1}: the maximiser of <d, p> is
 * p_i = r_i^2 d_i / sqrt(sum r_i^2 d_i^2) (Lagrange condition d = lambda grad). */
static ref_v3 ellipsoid_support(const double *r, ref_v3 d) {
    ref_v3 rd = rv(r[0] * d.x, r[1] * d.y, r[2] * d.z);
    ref_real n = ref_v3_norm(rd);
    if (n == 0.0L) return rv(r[0], 0.0L, 0.0L);
    return rv(r[0] * rd.x / n, r[1] * rd.y / n, r[2] * rd.z / n);
}

/* Cylinder: disc support in the xy plane plus the end cap chosen by sign(d_z). */
static ref_v3 cylinder_support(ref_real radius, ref_real hh, ref_v3 d) {
    ref_real n = ref_v3_norm(rv(d.x, d.y, 0.0L));
    ref_v3 p = rv(0.0L, 0.0L, sgn_half(d.z) * hh);
    if (n > 0.0L) {
        p.x = radius * d.x / n;
        p.y = radius * d.y / n;
    }
    return p;
}

/* Cone: conv(apex, base circle); the support is the apex or a rim point,
 * whichever has the larger <d, p>. */
static ref_v3 cone_support(ref_real radius, ref_real hh, ref_v3 d) {
    ref_real n = ref_v3_norm(rv(d.x, d.y, 0.0L));
    ref_v3 rim = rv(0.0L, 0.0L, -hh);
    ref_v3 apex = rv(0.0L, 0.0L, hh);
    if (n > 0.0L) {
        rim.x = radius * d.x / n;
        rim.y = radius * d.y / n;
    } else if (radius > 0.0L) {
        rim.x = radius; /* any rim point when d is along the axis */
    }
    return rv_dot(d, apex) >= rv_dot(d, rim) ? apex : rim;
}

static ref_v3 polytope_support(const ref_shape *s, ref_v3 d) {
    int best = 0;
    ref_real best_dot = rv_dot(d, rv_from(s->vertices[0]));
    for (int i = 1; i < s->vertex_count; i++) {
        ref_real v = rv_dot(d, rv_from(s->vertices[i]));
        if (v > best_dot) {
            best_dot = v;
            best = i;
        }
    }
    return rv_from(s->vertices[best]);
}

ref_v3 ref_core_support(const ref_shape *s, ref_v3 d) {
    switch (s->kind) {
    case REF_POINT:
    case REF_SPHERE:
        return rv(0.0L, 0.0L, 0.0L);
    case REF_ELLIPSOID:
        return ellipsoid_support(s->p, d);
    case REF_BOX:
        return rv(sgn_half(d.x) * s->p[0], sgn_half(d.y) * s->p[1], sgn_half(d.z) * s->p[2]);
    case REF_CAPSULE:
        return rv(0.0L, 0.0L, sgn_half(d.z) * s->p[1]);
    case REF_CYLINDER:
        return cylinder_support(s->p[0], s->p[1], d);
    case REF_CONE:
        return cone_support(s->p[0], s->p[1], d);
    case REF_POLYTOPE:
        return polytope_support(s, d);
    }
    return rv(0.0L, 0.0L, 0.0L);
}

ref_real ref_total_margin(const ref_shape *s) {
    ref_real m = s->margin;
    if (s->kind == REF_SPHERE || s->kind == REF_CAPSULE) m += s->p[0];
    return m;
}

void ref_support_local(const ref_shape *s, const long double direction[3], long double out[3]) {
    ref_v3 d = rv(direction[0], direction[1], direction[2]);
    ref_v3 p = ref_core_support(s, d);
    ref_real n = ref_v3_norm(d);
    ref_real m = ref_total_margin(s);
    if (n > 0.0L && m > 0.0L) p = rv_add(p, rv_scale(d, m / n));
    out[0] = p.x;
    out[1] = p.y;
    out[2] = p.z;
}
