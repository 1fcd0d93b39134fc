/* SPDX-License-Identifier: MIT */
/* Internal: helpers shared by the built-in shapes (header-only, so a program
 * linking one shape pulls in no other shape's object file). */
#ifndef AGJK_SRC_SHAPE_COMMON_H
#define AGJK_SRC_SHAPE_COMMON_H

#include "shape_points.h"

static inline int size_is_valid(double v) { return v >= 0.0 && v <= AGJK_MAX_COORDINATE; }

static inline agjk_status shape_fill(agjk_shape *shape, agjk_support_fn support, const void *data,
                                     double margin) {
    shape->support = support;
    shape->data = data;
    shape->margin = margin;
    return AGJK_STATUS_OK;
}

#endif
