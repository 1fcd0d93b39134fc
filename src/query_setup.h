/* SPDX-License-Identifier: MIT */
/* Internal: argument checks and solver setup shared by the public queries
 * (agjk_distance, agjk_collide in query.c; agjk_signed_distance in penetration.c). */
#ifndef AGJK_SRC_QUERY_SETUP_H
#define AGJK_SRC_QUERY_SETUP_H

#include "solver.h"

/* Checks the arguments (shapes, poses, options of any caller version) and, when
 * they are valid, fills *opts (the caller's options, or the defaults), *md (the
 * relative transform) and *in (the solver input for a distance query: no
 * Boolean exit, witness points as opts->compute asks). Returns 0 for invalid
 * input, with nothing computed. */
int agjk__query_prepare(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                        const agjk_pose *pose_b, const agjk_options *options,
                        agjk_options *opts, agjk__minkowski *md, agjk__solve_input *in);

#endif
