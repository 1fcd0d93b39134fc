/* SPDX-License-Identifier: MIT */
/* Axis-aligned box centred at the origin: the support picks the corner whose
 * signs match the direction. */
#include "shape_common.h"

static void box_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint) {
    const agjk_box *b = (const agjk_box *)data;
    (void)hint;
    *out = v3(signed_extent(b->half_extents.x, direction->x),
              signed_extent(b->half_extents.y, direction->y),
              signed_extent(b->half_extents.z, direction->z));
}

agjk_status agjk_shape_box(agjk_shape *shape, const agjk_box *box) {
    if (!shape || !box) return AGJK_STATUS_INVALID_INPUT;
    agjk_vec3 h = box->half_extents;
    if (!size_is_valid(h.x) || !size_is_valid(h.y) || !size_is_valid(h.z))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, box_support, box, 0.0);
}
