/* SPDX-License-Identifier: MIT */
/* Capsule: the segment z in [-h, h] swept by the radius (the shape's margin). */
#include "shape_common.h"

static void segment_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                            int *hint) {
    const agjk_capsule *c = (const agjk_capsule *)data;
    (void)hint;
    *out = v3(0.0, 0.0, signed_extent(c->half_height, direction->z));
}

agjk_status agjk_shape_capsule(agjk_shape *shape, const agjk_capsule *capsule) {
    if (!shape || !capsule || !size_is_valid(capsule->radius) ||
        !size_is_valid(capsule->half_height))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, segment_support, capsule, capsule->radius);
}
