/* SPDX-License-Identifier: MIT */
#include "shape_common.h"

agjk_status agjk_shape_set_margin(agjk_shape *shape, double margin) {
    if (!shape || !size_is_valid(margin)) return AGJK_STATUS_INVALID_INPUT;
    shape->margin = margin;
    return AGJK_STATUS_OK;
}
