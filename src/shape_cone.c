/* SPDX-License-Identifier: MIT */
/* Cone along z: apex (0, 0, h), base disc of radius r at z = -h. The support is
 * the apex or the base-rim point in the direction's xy-part, whichever is
 * further along the direction. */
#include "shape_common.h"

static void cone_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint) {
    const agjk_cone *c = (const agjk_cone *)data;
    (void)hint;
    agjk_vec3 radial = v3_normalize(v3(direction->x, direction->y, 0.0));
    agjk_vec3 rim = v3(c->radius * radial.x, c->radius * radial.y, -c->half_height);
    agjk_vec3 apex = v3(0.0, 0.0, c->half_height);
    *out = v3_dot(*direction, apex) >= v3_dot(*direction, rim) ? apex : rim;
}

agjk_status agjk_shape_cone(agjk_shape *shape, const agjk_cone *cone) {
    if (!shape || !cone || !size_is_valid(cone->radius) || !size_is_valid(cone->half_height))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, cone_support, cone, 0.0);
}
