/* SPDX-License-Identifier: MIT */
/* Ellipsoid {p : sum (p_i / r_i)^2 <= 1}: the support in direction d is
 * D^2 d / ||D d|| with D = diag(r). */
#include "shape_common.h"

static void ellipsoid_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                              int *hint) {
    const agjk_ellipsoid *e = (const agjk_ellipsoid *)data;
    (void)hint;
    /* Rescale d first: the result does not depend on |d|, and this keeps
     * ||D d|| away from underflow/overflow for tiny or huge directions. */
    agjk_vec3 d = *direction;
    double m = v3_maxabs(d);
    d = v3_div(d, m);
    agjk_vec3 dd = v3(e->radii.x * d.x, e->radii.y * d.y, e->radii.z * d.z);
    /* Same trick on D d, whose entries may span many orders for stiff radii. */
    double mdd = v3_maxabs(dd);
    agjk_vec3 ddn = v3_div(dd, mdd);
    double norm = v3_norm(ddn);
    *out = v3(e->radii.x * ddn.x / norm, e->radii.y * ddn.y / norm, e->radii.z * ddn.z / norm);
}

agjk_status agjk_shape_ellipsoid(agjk_shape *shape, const agjk_ellipsoid *ellipsoid) {
    if (!shape || !ellipsoid) return AGJK_STATUS_INVALID_INPUT;
    agjk_vec3 r = ellipsoid->radii;
    if (!v3_in_range(r) || !(r.x > 0.0) || !(r.y > 0.0) || !(r.z > 0.0))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, ellipsoid_support, ellipsoid, 0.0);
}
