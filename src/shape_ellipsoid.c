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

static void ellipsoid_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                              int *hint) {
    const agjk_ellipsoid *e = (const agjk_ellipsoid *)data;
    (void)hint;
    agjk_vec3 r = e->radii, d = *direction;
    double x = r.x * d.x, y = r.y * d.y, z = r.z * d.z; /* D d */
    double n2 = x * x + y * y + z * z;
    /* The common case: ||D d||^2 far from underflow and overflow, so one
     * square root and one division. (Power-of-two scalings of d or of the
     * radii scale every step exactly: answers stay bit-equivariant.) */
    if (!(n2 >= 0x1p-900 && n2 <= 0x1p900)) {
        ellipsoid_support_rescaled(e->radii, *direction, out);
        return;
    }
    double inv = 1.0 / sqrt(n2);
    out->x = r.x * x * inv;
    out->y = r.y * y * inv;
    out->z = r.z * z * inv;
}

agjk_status agjk_shape_ellipsoid(agjk_shape *shape, const agjk_ellipsoid *ellipsoid) {
    if (!shape || !ellipsoid) return AGJK_STATUS_INVALID_INPUT;
    agjk_vec3 r = ellipsoid->radii;
    if (!v3_in_range(r) || !(r.x > 0.0) || !(r.y > 0.0) || !(r.z > 0.0))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, ellipsoid_support, ellipsoid, 0.0);
}
