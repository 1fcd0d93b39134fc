/* SPDX-License-Identifier: MIT */
/* Relative pose of B in A's frame, and pose validation. */
#include "minkowski.h"

/* How far from orthonormal a rotation may be: enough for a float-converted or
 * quaternion-built matrix, far too little to hide a scale or shear. */
#define ROTATION_TOLERANCE 1e-6

int agjk__pose_is_valid(const agjk_pose *pose) {
    if (!pose || !v3_in_range(pose->translation)) return 0;
    const double *r = &pose->rotation[0][0]; /* row-major, r[3 * row + column] */
    /* R R^T = I: the six distinct entries. Written so that NaN or Inf (which
     * fail every comparison) are rejected by the same tests. */
    double r00 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    double r11 = r[3] * r[3] + r[4] * r[4] + r[5] * r[5];
    double r22 = r[6] * r[6] + r[7] * r[7] + r[8] * r[8];
    double r01 = r[0] * r[3] + r[1] * r[4] + r[2] * r[5];
    double r02 = r[0] * r[6] + r[1] * r[7] + r[2] * r[8];
    double r12 = r[3] * r[6] + r[4] * r[7] + r[5] * r[8];
    if (!(fabs(r00 - 1.0) <= ROTATION_TOLERANCE && fabs(r11 - 1.0) <= ROTATION_TOLERANCE &&
          fabs(r22 - 1.0) <= ROTATION_TOLERANCE && fabs(r01) <= ROTATION_TOLERANCE &&
          fabs(r02) <= ROTATION_TOLERANCE && fabs(r12) <= ROTATION_TOLERANCE))
        return 0;
    /* det R = +1 (a reflection would turn the shapes inside out): with
     * orthonormal rows, det = <row 2, row 0 x row 1> is +-1. */
    double det = r[6] * (r[1] * r[5] - r[2] * r[4]) + r[7] * (r[2] * r[3] - r[0] * r[5]) +
                 r[8] * (r[0] * r[4] - r[1] * r[3]);
    return det > 0.0;
}

/* Limits of the common support path for the current scale (see agjk__minkowski). */
static void set_limits(agjk__minkowski *md) {
    double limit = AGJK__SOLVER_SIZE_LIMIT / md->scale;
    md->point_limit = limit < AGJK_MAX_COORDINATE ? limit : AGJK_MAX_COORDINATE;
    md->raw_limit = md->scale == 1.0 ? md->point_limit : -1.0;
    /* A tiny problem (scale > 1) needs unit-size directions: a small direction
     * times its tiny coordinates would underflow and lose the sign. */
    md->direction_min = md->scale > 1.0 ? 1.0 : AGJK__DIRECTION_MIN;
    md->direction_floor2 = 4.0 * md->direction_min * md->direction_min;
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
    md->translation = m3_tmul(ra, v3_sub(pose_b->translation, pose_a->translation));
    md->translation_size = v3_maxabs(md->translation);
    md->noise_floor = 0.0;
    agjk__minkowski_grow(md, 0.0);
    /* set_limits for scale 1, except that the problem's size is unknown until
     * the first support: unit-size directions until agjk__minkowski_set_scale
     * has seen it. */
    md->point_limit = AGJK__SOLVER_SIZE_LIMIT < AGJK_MAX_COORDINATE ? AGJK__SOLVER_SIZE_LIMIT
                                                                     : AGJK_MAX_COORDINATE;
    md->raw_limit = md->point_limit;
    md->direction_min = 1.0;
    md->direction_floor2 = 4.0;
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

/* 2^-floor(log2(size)), clamped so that the factor and its inverse stay finite. */
static double unit_factor(double size) {
    int e = -ilogb(size);
    if (e > 1000) e = 1000;
    if (e < -1000) e = -1000;
    return ldexp(1.0, e);
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
