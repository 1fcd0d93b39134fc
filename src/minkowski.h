/* SPDX-License-Identifier: MIT */
/* Internal: the support function of the Minkowski difference D = A - B,
 * expressed in the local frame of A (GJK88; Montaut et al. 2022, eq. 8). */
#ifndef AGJK_SRC_MINKOWSKI_H
#define AGJK_SRC_MINKOWSKI_H

#include "vec3.h"

/* One point of D with the points of A and B it came from (both in A's frame). */
typedef struct agjk__vertex {
    agjk_vec3 w; /* a - b */
    agjk_vec3 a;
    agjk_vec3 b;
} agjk__vertex;

typedef struct agjk__minkowski {
    agjk_support_fn support_a, support_b;
    const void *data_a, *data_b;
    double rotation[3][3]; /* B's local frame -> A's frame: R_A^T R_B */
    /* Everything below is in solver units: the caller's lengths times `scale`,
     * a power of two chosen so that the problem has about unit size (see
     * agjk__minkowski_set_scale). */
    double scale;
    agjk_vec3 translation; /* B's origin in A's frame: R_A^T (t_B - t_A) */
    double margin_a, margin_b;
    double margin;         /* margin_a + margin_b */
    int hint_a, hint_b;
    int bad_support;       /* a callback returned a non-finite or out-of-range point */
    /* Largest |a| + |b| seen, for the floating-point noise estimate. */
    double magnitude;
    /* Product of the factors agjk__minkowski_shrink applied since the solver
     * last looked; the solver multiplies its own state by it and resets it. */
    double rescaled;
} agjk__minkowski;

/* Checks a pose: finite, rotation orthonormal with det +1 (to 1e-6). */
int agjk__pose_is_valid(const agjk_pose *pose);

/* Prepares the relative transform. Shapes and poses must have been validated. */
void agjk__minkowski_init(agjk__minkowski *md, const agjk_shape *a, const agjk_pose *pose_a,
                          const agjk_shape *b, const agjk_pose *pose_b, int hint_a, int hint_b);

/* Solver units keep support points below this (2^100): sixth powers stay finite. */
#define AGJK__SOLVER_SIZE_LIMIT 0x1p100

/* Lowers md->scale by a power of two so that raw * scale is about 1, converts
 * md, and records the factor in md->rescaled. */
void agjk__minkowski_shrink(agjk__minkowski *md, double raw);

/* Chooses the power of two that brings the problem (support points seen so far,
 * B's offset, margins) to unit size and converts md to it. Scaling by a power
 * of two is exact, so answers are equivariant bit for bit, while squares and
 * volumes of the simplex math neither underflow (a 1e-300 problem) nor
 * overflow. Returns the factor applied. */
double agjk__minkowski_set_scale(agjk__minkowski *md);

/* s = argmin_{s in D} <d, s> = S_A(-d) - S_B(d) (paper eq. 7-8), d in A's frame, non-zero. */
static inline void agjk__minkowski_support(agjk__minkowski *md, agjk_vec3 d, agjk__vertex *out) {
    /* Callbacks get directions of sensible size, rescaled to max |d_i| in
     * [1, 2) by a power of two (exact) when needed: a tiny direction times the
     * tiny coordinates of a tiny problem (md->scale > 1) underflows to +-0 and
     * support comparisons lose their sign; a huge one overflows. */
    double dm = v3_maxabs(d);
    if ((dm < 0x1p-60 || dm > 0x1p100 || (md->scale > 1.0 && dm < 1.0)) && dm > 0.0)
        d = v3_scale_to_unit(d, dm);
    agjk_vec3 na = v3_neg(d);
    agjk_vec3 db = m3_tmul(&md->rotation[0][0], d);
    agjk_vec3 pa, pb;
    md->support_a(md->data_a, &na, &pa, &md->hint_a);
    md->support_b(md->data_b, &db, &pb, &md->hint_b);
    if (!v3_in_range(pa) || !v3_in_range(pb)) {
        md->bad_support = 1;
        pa = v3(0.0, 0.0, 0.0);
        pb = v3(0.0, 0.0, 0.0);
    }
    /* A support point far larger than the size the scale was chosen for (a
     * first support at a denormal vertex, say) would overflow: lower the
     * scale first; the solver follows (md->rescaled). */
    double raw = v3_maxabs(pa) + v3_maxabs(pb);
    if (raw * md->scale > AGJK__SOLVER_SIZE_LIMIT) agjk__minkowski_shrink(md, raw);
    pa = v3_scale(pa, md->scale); /* exact: a power of two */
    pb = v3_scale(pb, md->scale);
    double mag = v3_maxabs(pa) + v3_maxabs(pb);
    if (mag > md->magnitude) md->magnitude = mag;
    out->a = pa;
    out->b = v3_add(m3_mul(&md->rotation[0][0], pb), md->translation);
    out->w = v3_sub(out->a, out->b);
}

#endif
