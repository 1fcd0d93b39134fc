/* SPDX-License-Identifier: MIT */
/* Point and sphere: a sphere is a point swept by its radius (the margin), so the
 * solver converges on its centre in one step and adds the radius analytically. */
#include "shape_common.h"

void agjk__point_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint) {
    (void)data;
    (void)direction;
    (void)hint;
    *out = v3(0.0, 0.0, 0.0);
}

agjk_status agjk_shape_point(agjk_shape *shape) {
    if (!shape) return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__point_support, NULL, 0.0);
}

agjk_status agjk_shape_sphere(agjk_shape *shape, double radius) {
    if (!shape || !size_is_valid(radius)) return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__point_support, NULL, radius);
}
