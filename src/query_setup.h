/* SPDX-License-Identifier: MIT */
/* Internal: argument checks and solver setup shared by the public queries
 * (agjk_distance, agjk_collide in query.c; agjk_signed_distance in penetration.c). */
#ifndef AGJK_SRC_QUERY_SETUP_H
#define AGJK_SRC_QUERY_SETUP_H

#include "solver.h"

/* What agjk_options_init gives (options.c); a NULL options pointer means these. */
extern const agjk_options agjk__default_options;

/* Checks the arguments (shapes, poses, options of any caller version: NULL
 * for the defaults) and, when they are valid, fills *md (the relative
 * transform) and *in (the solver input: the options' method, tolerance, cap
 * and witness flag, x_0, the Boolean exit when boolean_mode). Returns 0 for
 * invalid input. */
int agjk__query_prepare(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                        const agjk_pose *pose_b, const agjk_options *options, int boolean_mode,
                        agjk__minkowski *md, agjk__solve_input *in);

/* A point of A's frame in world frame (witness points). */
static inline agjk_vec3 agjk__to_world(const agjk_pose *pose, agjk_vec3 p) {
    return v3_add(m3_mul(&pose->rotation[0][0], p), pose->translation);
}

/* The certified interval on the core distance ||x*|| (solver units) after a
 * solve that ended with x != 0 (converged, capped, stalled, at rounding), and
 * the unit normal, in A's frame from A towards B, of the support plane that
 * certifies its lower end: -x, or the direction the adaptive method stopped
 * on. Shared by agjk_distance and agjk_signed_distance. */
typedef struct agjk__core_bounds {
    double core;          /* ||x|| */
    double gap;           /* the duality gap used (0 when none is valid) */
    double lower, upper;  /* rounding (2 noise) included at both ends */
    /* x itself was off the active set by more than the rounding (an ill-
     * conditioned projection): the upper end comes from the active set's own
     * point, and no accuracy can be claimed from the gap at x. */
    int inexact;
    agjk_vec3 toward_x;   /* -x / ||x||: the witness points' offset direction */
    agjk_vec3 normal;     /* the certifying plane's unit normal */
} agjk__core_bounds;
void agjk__core_bounds_of(const agjk__solve_output *out, agjk__core_bounds *b);

/* The warm-start cache's part of a query (cache.c), reached through pointers
 * so that a program without cached queries links no cache code. */
struct agjk_cache;
typedef struct agjk__warm_hooks {
    int (*load)(const struct agjk_cache *cache, const agjk_shape *a, const agjk_shape *b,
                agjk__minkowski *md, agjk__solve_input *in);
    void (*save)(struct agjk_cache *cache, const agjk_shape *a, const agjk_shape *b,
                 const agjk__minkowski *md, const agjk__solve_input *in,
                 const agjk__solve_output *out);
    void (*reset)(struct agjk_cache *cache);
} agjk__warm_hooks;

/* agjk_distance (boolean_mode 0) and agjk_collide (1), warm-started from
 * `cache` through `hooks` when cache is not NULL (query.c). */
agjk_status agjk__query_run(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                            const agjk_pose *pose_b, const agjk_options *options,
                            agjk_result *result, int boolean_mode, struct agjk_cache *cache,
                            const agjk__warm_hooks *hooks);

#endif
