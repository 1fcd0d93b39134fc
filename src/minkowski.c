/* SPDX-License-Identifier: MIT */
/* Relative pose of B in A's frame, and pose validation. */
#include "minkowski.h"

/* How far from orthonormal a rotation may be: enough for a float-converted or
 * quaternion-built matrix, far too little to hide a scale or shear. */
#define ROTATION_TOLERANCE 1e-6

int agjk__pose_is_valid(const agjk_pose *pose) {
    if (!pose || !v3_in_range(pose->translation)) return 0;
    const double *r = &pose->rotation[0][0]; /* row-major, r[3 * row + column] */
    agjk_vec3 x = v3(r[0], r[1], r[2]), y = v3(r[3], r[4], r[5]), z = v3(r[6], r[7], r[8]);
    /* A rotation: rows x and y orthonormal, and z = x cross y (which makes
     * z orthonormal to both and det R = +1, where a reflection, det -1, would
     * turn the shapes inside out). Cheaper than the six entries of R R^T and
     * the determinant (27 floating-point operations against 44, twice per
     * query), and as strict: within 1e-6 per entry, z is within about 1e-6
     * of a unit vector orthogonal to x and y. Every test is a comparison, so
     * NaN and Inf fail them too. */
    agjk_vec3 e = v3_sub(v3_cross(x, y), z);
    return fabs(v3_dot(x, x) - 1.0) <= ROTATION_TOLERANCE &&
           fabs(v3_dot(y, y) - 1.0) <= ROTATION_TOLERANCE &&
           fabs(v3_dot(x, y)) <= ROTATION_TOLERANCE && fabs(e.x) <= ROTATION_TOLERANCE &&
           fabs(e.y) <= ROTATION_TOLERANCE && fabs(e.z) <= ROTATION_TOLERANCE;
}

/* Limits of the common support path for the current scale (see agjk__minkowski). */
static void set_limits(agjk__minkowski *md) {
    double limit = AGJK__SOLVER_SIZE_LIMIT / md->scale;
    md->point_limit = limit < AGJK_MAX_COORDINATE ? limit : AGJK_MAX_COORDINATE;
    md->raw_limit = md->scale == 1.0 ? md->point_limit : -1.0;
    md->bounded = 0;
    /* A tiny problem (scale > 1) needs unit-size directions: a small direction
     * times its tiny coordinates would underflow and lose the sign. */
    agjk__minkowski_set_direction_min(md, md->scale > 1.0 ? 1.0 : AGJK__DIRECTION_MIN);
}

void agjk__minkowski_init(agjk__minkowski *md, const agjk_shape *a, const agjk_pose *pose_a,
                          const agjk_shape *b, const agjk_pose *pose_b, int hint_a, int hint_b) {
    md->support_a = a->support;
    md->support_b = b->support;
    md->data_a = a->data;
    md->data_b = b->data;
    md->margin_a = a->margin;
    md->margin_b = b->margin;
    md->margin = a->margin + b->margin;
    md->hint_a = hint_a;
    md->hint_b = hint_b;
    md->bad_support = 0;
    md->scale = 1.0;
    md->rescaled = 1.0;
    /* R = R_A^T R_B: entry (i, j) is <column i of R_A, column j of R_B>, so
     * row i of R is sum_k R_A[k][i] (row k of R_B). Written out as rows (the
     * double loop compiled to twice the instructions, a tenth of a distant
     * Boolean query); same sums in the same order. */
    const double *ra = &pose_a->rotation[0][0], *rb = &pose_b->rotation[0][0];
    agjk_vec3 b0 = v3(rb[0], rb[1], rb[2]), b1 = v3(rb[3], rb[4], rb[5]), b2 = v3(rb[6], rb[7], rb[8]);
    /* (The three rows written out too: -O2 keeps a three-pass loop.) */
    agjk_vec3 r0 = v3_add(v3_add(v3_scale(b0, ra[0]), v3_scale(b1, ra[3])), v3_scale(b2, ra[6]));
    agjk_vec3 r1 = v3_add(v3_add(v3_scale(b0, ra[1]), v3_scale(b1, ra[4])), v3_scale(b2, ra[7]));
    agjk_vec3 r2 = v3_add(v3_add(v3_scale(b0, ra[2]), v3_scale(b1, ra[5])), v3_scale(b2, ra[8]));
    md->rotation[0][0] = r0.x;
    md->rotation[0][1] = r0.y;
    md->rotation[0][2] = r0.z;
    md->rotation[1][0] = r1.x;
    md->rotation[1][1] = r1.y;
    md->rotation[1][2] = r1.z;
    md->rotation[2][0] = r2.x;
    md->rotation[2][1] = r2.y;
    md->rotation[2][2] = r2.z;
    /* Stored through a copy, which gcc writes as one 16-byte store of x and y
     * and one of z: the first support reads x and y back with one 16-byte
     * load right after, and from three 8-byte stores (gcc's choice for the
     * plain assignment) the load cannot take its data from the store buffer
     * and waits for the stores to reach the cache: 7 ns of a 63 ns
     * one-support query on ellipsoids, 4 of 50 on boxes. */
    agjk_vec3 t = m3_tmul(ra, v3_sub(pose_b->translation, pose_a->translation));
    double stored[3] = {t.x, t.y, t.z};
    memcpy(&md->translation, stored, sizeof stored);
    md->translation_size = v3_maxabs(md->translation);
    md->noise_floor = 0.0;
    agjk__minkowski_grow(md, 0.0);
    /* The limits of scale 1, except that the problem's size is unknown until
     * the first support: unit-size directions until agjk__minkowski_set_scale
     * has seen it. */
    set_limits(md);
    agjk__minkowski_set_direction_min(md, 1.0);
}

/* Bounds on the 1-norm (*l1) and the max norm (*max) of every support
 * point of a built-in shape whose data bound them: 0 for another shape, or
 * for data a caller changed to be invalid after agjk_shape_*() accepted it
 * (the support path's own tests then catch what it gives). The built-ins
 * are recognised through the weak references of the direct support path:
 * a program without ellipsoids links no ellipsoid code for this either. */
static int point_bounds(agjk_support_fn fn, const void *data, double *l1, double *max) {
#if AGJK__DIRECT_SUPPORT
    if (fn == agjk__point_support) {
        *l1 = *max = 0.0;
        return 1;
    }
    if (!data) return 0;
    if (fn == agjk__box_support) {
        /* Every support point is a corner: these norms exactly. */
        agjk_vec3 h = ((const agjk_box *)data)->half_extents;
        if (!(v3_in_range(h) && h.x >= 0.0 && h.y >= 0.0 && h.z >= 0.0)) return 0;
        *l1 = v3_norm1(h);
        *max = v3_maxabs(h);
        return 1;
    }
    if (fn == agjk__ellipsoid_support) {
        /* |p_i| <= r_i for a support point D^2 d / ||D d||; computed, a few
         * ulps more, which the factor 1 + 2^-40 covers. */
        agjk_vec3 r = ((const agjk_ellipsoid *)data)->radii;
        if (!(v3_in_range(r) && r.x > 0.0 && r.y > 0.0 && r.z > 0.0)) return 0;
        *l1 = v3_norm1(r) * (1.0 + 0x1p-40);
        *max = v3_maxabs(r) * (1.0 + 0x1p-40);
        return 1;
    }
    if (fn == agjk__segment_support) {
        double h = ((const agjk_capsule *)data)->half_height;
        if (!(h >= 0.0 && h <= AGJK_MAX_COORDINATE)) return 0;
        *l1 = *max = h;
        return 1;
    }
#else
    (void)fn;
    (void)data;
    (void)l1;
    (void)max;
#endif
    return 0;
}

void agjk__minkowski_bound_points_from_data(agjk__minkowski *md) {
    double l1_a, max_a, l1_b, max_b;
    if (!point_bounds(md->support_a, md->data_a, &l1_a, &max_a) ||
        !point_bounds(md->support_b, md->data_b, &l1_b, &max_b) || !(l1_a + l1_b <= md->raw_limit))
        return;
    if (max_a + max_b > md->magnitude) agjk__minkowski_grow(md, max_a + max_b);
    md->bounded = 1;
}

/* Multiplies everything md holds in solver units by f (a power of two). */
static void apply_factor(agjk__minkowski *md, double f) {
    md->scale *= f;
    md->translation = v3_scale(md->translation, f);
    md->translation_size *= f;
    md->margin_a *= f;
    md->margin_b *= f;
    md->margin *= f;
    md->noise_floor *= f;
    agjk__minkowski_grow(md, md->magnitude * f);
    set_limits(md);
}

/* 2^-floor(log2(size)), clamped to [2^-1000, 2^1000] so that the factor and
 * its inverse stay finite; by exponent arithmetic (pow2_inverse_floor), which
 * is 0 only beyond the clamp (size denormal, or at least 2^1023). */
static double unit_factor(double size) {
    double f = pow2_inverse_floor(size);
    if (f == 0.0) return size < 1.0 ? 0x1p1000 : 0x1p-1000;
    return f > 0x1p1000 ? 0x1p1000 : (f < 0x1p-1000 ? 0x1p-1000 : f);
}

double agjk__minkowski_rescale_extreme(agjk__minkowski *md, double size) {
    double f = unit_factor(size);
    apply_factor(md, f);
    return f;
}

static void shrink(agjk__minkowski *md, double raw) {
    double f = unit_factor(raw * md->scale); /* < 1 */
    apply_factor(md, f);
    md->rescaled *= f;
}

agjk_vec3 agjk__minkowski_rescue_direction(const agjk__minkowski *md, agjk_vec3 d) {
    (void)md;
    double dm = v3_maxabs(d);
    return dm > 0.0 && dm <= DBL_MAX ? v3_scale_to_unit(d, dm) : d;
}

void agjk__minkowski_points_slow(agjk__minkowski *md, agjk_vec3 *pa, agjk_vec3 *pb) {
    double l1 = v3_norm1(*pa) + v3_norm1(*pb);
    if (!(l1 <= md->point_limit)) {
        if (!v3_in_range(*pa) || !v3_in_range(*pb)) {
            md->bad_support = 1;
            *pa = v3(0.0, 0.0, 0.0);
            *pb = v3(0.0, 0.0, 0.0);
            return; /* the magnitude is at least 0 already */
        }
        /* A support point far larger than the size the scale was chosen for
         * (a first support at a denormal vertex, say) would overflow: lower
         * the scale; the solver follows (md->rescaled). */
        double raw = v3_maxabs(*pa) + v3_maxabs(*pb);
        if (raw * md->scale > AGJK__SOLVER_SIZE_LIMIT) shrink(md, raw);
    }
    double raw = v3_maxabs(*pa) + v3_maxabs(*pb);
    if (md->scale != 1.0) {
        *pa = v3_scale(*pa, md->scale); /* exact: a power of two */
        *pb = v3_scale(*pb, md->scale);
        raw *= md->scale;
    }
    if (raw > md->magnitude) agjk__minkowski_grow(md, raw);
}
