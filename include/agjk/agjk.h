/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/agjk.h
 * @brief Umbrella header: include this one.
 *
 * agjk: distance and collision between convex shapes by (accelerated) GJK.
 * See README.md for an overview and a worked example.
 */
#ifndef AGJK_AGJK_H
#define AGJK_AGJK_H

#include "agjk/base.h"
#include "agjk/types.h"
#include "agjk/shapes.h"
#include "agjk/query.h"
#include "agjk/polytope.h"
#include "agjk/penetration.h"
#include "agjk/cache.h"

#endif /* AGJK_AGJK_H */
