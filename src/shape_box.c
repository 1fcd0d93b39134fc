/* SPDX-License-Identifier: MIT */
/* Axis-aligned box centred at the origin: the support picks the corner whose
 * signs match the direction. */
#include "shape_common.h"

void agjk__box_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint) {
    (void)hint;
    *out = agjk__box_point((const agjk_box *)data, *direction);
}

agjk_status agjk_shape_box(agjk_shape *shape, const agjk_box *box) {
    if (!shape || !box) return AGJK_STATUS_INVALID_INPUT;
    agjk_vec3 h = box->half_extents;
    if (!size_is_valid(h.x) || !size_is_valid(h.y) || !size_is_valid(h.z))
        return AGJK_STATUS_INVALID_INPUT;
    return shape_fill(shape, agjk__box_support, box, 0.0);
}
