/* SPDX-License-Identifier: MIT */
/* Cylinder along z: the rim point in the direction's xy-part, on the cap the
 * direction's z points to. */
#include "shape_common.h"

static void cylinder_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                             int *hint) {
    const agjk_cylinder *c = (const agjk_cylinder *)data;
    (void)hint;
    agjk_vec3 radial = v3_normalize(v3(direction->x, direction->y, 0.0));
    *out = v3(c->radius * radial.x, c->radius * radial.y,
              signed_extent(c->half_height, direction->z));
}

agjk_status agjk_shape_cylinder(agjk_shape *shape, const agjk_cylinder *cylinder) {
    if (!shape || !cylinder || !size_is_valid(cylinder->radius) ||
        !size_is_valid(cylinder->half_height))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, cylinder_support, cylinder, 0.0);
}
