/* SPDX-License-Identifier: MIT */
/* Capsule: the segment z in [-h, h] swept by the radius (the shape's margin). */
#include "shape_common.h"

void agjk__segment_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                           int *hint) {
    (void)hint;
    *out = agjk__segment_point((const agjk_capsule *)data, *direction);
}

agjk_status agjk_shape_capsule(agjk_shape *shape, const agjk_capsule *capsule) {
    if (!shape || !capsule || !size_is_valid(capsule->radius) ||
        !size_is_valid(capsule->half_height))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__segment_support, capsule, capsule->radius);
}
