/* SPDX-License-Identifier: MIT */
/* Ellipsoid {p : sum (p_i / r_i)^2 <= 1}: the support in direction d is
 * D^2 d / ||D d|| with D = diag(r). */
#include "shape_common.h"

/* Tiny or huge directions, or stiff radii spanning many orders: rescale d,
 * then D d, before taking norms (the result does not depend on |d|). Out of
 * line, so that the common path keeps nothing for it. */
static AGJK__NOINLINE void ellipsoid_support_rescaled(agjk_vec3 r, agjk_vec3 d, agjk_vec3 *out) {
    d = v3_div(d, v3_maxabs(d));
    agjk_vec3 dd = v3(r.x * d.x, r.y * d.y, r.z * d.z);
    agjk_vec3 ddn = v3_div(dd, v3_maxabs(dd));
    double norm = v3_norm(ddn);
    *out = v3(r.x * ddn.x / norm, r.y * ddn.y / norm, r.z * ddn.z / norm);
}

void agjk__ellipsoid_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                             int *hint) {
    const agjk_ellipsoid *e = (const agjk_ellipsoid *)data;
    (void)hint;
    if (agjk__ellipsoid_point(e, *direction, out)) return; /* the common case */
    ellipsoid_support_rescaled(e->radii, *direction, out);
}

agjk_status agjk_shape_ellipsoid(agjk_shape *shape, const agjk_ellipsoid *ellipsoid) {
    if (!shape || !ellipsoid) return AGJK_STATUS_INVALID_INPUT;
    agjk_vec3 r = ellipsoid->radii;
    if (!v3_in_range(r) || !(r.x > 0.0) || !(r.y > 0.0) || !(r.z > 0.0))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__ellipsoid_support, ellipsoid, 0.0);
}
