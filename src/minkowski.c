/* SPDX-License-Identifier: MIT */
/* Relative pose of B in A's frame, and pose validation. */
#include "minkowski.h"

/* How far from orthonormal a rotation may be: enough for a float-converted or
 * quaternion-built matrix, far too little to hide a scale or shear. */
#define ROTATION_TOLERANCE 1e-6

int agjk__pose_is_valid(const agjk_pose *pose) {
    if (!pose || !v3_in_range(pose->translation)) return 0;
    const double *r = &pose->rotation[0][0]; /* row-major, r[3 * row + column] */
    for (int i = 0; i < 9; ++i)
        if (!isfinite(r[i])) return 0;
    /* R R^T = I */
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double dot = r[3 * i] * r[3 * j] + r[3 * i + 1] * r[3 * j + 1] + r[3 * i + 2] * r[3 * j + 2];
            if (fabs(dot - (i == j ? 1.0 : 0.0)) > ROTATION_TOLERANCE) return 0;
        }
    }
    /* det R = +1: a reflection would turn the shapes inside out. */
    double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) +
                 r[2] * (r[3] * r[7] - r[4] * r[6]);
    return det > 0.0;
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
    md->magnitude = 0.0;
    /* R = R_A^T R_B */
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            md->rotation[i][j] = pose_a->rotation[0][i] * pose_b->rotation[0][j] +
                                 pose_a->rotation[1][i] * pose_b->rotation[1][j] +
                                 pose_a->rotation[2][i] * pose_b->rotation[2][j];
    md->translation = m3_tmul(&pose_a->rotation[0][0], v3_sub(pose_b->translation, pose_a->translation));
}
