/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/query.h
 * @brief Distance and Boolean collision queries, options, and the simplex sub-algorithm.
 *
 * @defgroup agjk_query Queries
 *
 * All functions are reentrant and thread-safe: they keep no global state and
 * never allocate. Shapes and poses may be shared between threads as long as
 * nobody writes them during a query.
 * @{
 */
#ifndef AGJK_QUERY_H
#define AGJK_QUERY_H

#include "agjk/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Fills `options` with the defaults. `struct_size` must be sizeof(agjk_options)
 *  as the caller sees it; use agjk_options_init() or agjk_default_options(),
 *  which pass it for you. Does nothing if options is NULL or struct_size is too small. */
AGJK_API void agjk_options_init_sized(agjk_options *options, size_t struct_size);

/** Fills `options` with the defaults (see agjk_options for each one). */
static inline void agjk_options_init(agjk_options *options) {
    agjk_options_init_sized(options, sizeof *options);
}

/** The default options, by value. */
static inline agjk_options agjk_default_options(void) {
    agjk_options options;
    agjk_options_init_sized(&options, sizeof options);
    return options;
}

/** Distance between two convex shapes.
 *
 * Runs the method of `options` (NULL: defaults) on D = A - B until the duality
 * gap meets the tolerance, the origin is found inside D, or the iteration cap
 * is reached. Fills `result` (see agjk_result) and returns result->status; if
 * `result` is NULL returns AGJK_STATUS_INVALID_INPUT and writes nothing.
 * Intersecting shapes get distance 0 (penetration depth is not computed). */
AGJK_API agjk_status agjk_distance(const agjk_shape *a, const agjk_pose *pose_a,
                                   const agjk_shape *b, const agjk_pose *pose_b,
                                   const agjk_options *options, agjk_result *result);

/** Boolean collision test with early exit (Montaut et al. 2022, Alg. 2).
 *
 * Stops at the first support plane that separates D from the origin
 * (AGJK_STATUS_SEPARATED, result->normal is that plane's normal), or when the
 * origin is enclosed by the simplex (AGJK_STATUS_INTERSECTING). A query whose
 * duality gap meets the tolerance first goes on, as agjk_distance() does, until
 * a separating plane or an enclosure decides (at most 32 more iterations);
 * shapes within rounding of contact, or too close for those iterations, end
 * with AGJK_STATUS_CONTACT_WITHIN_TOLERANCE (see agjk_status). Computes no
 * witness points and no distance. */
AGJK_API agjk_status agjk_collide(const agjk_shape *a, const agjk_pose *pose_a,
                                  const agjk_shape *b, const agjk_pose *pose_b,
                                  const agjk_options *options, agjk_result *result);

/** Projection of the origin onto a simplex (the GJK "distance sub-algorithm"). */
typedef struct agjk_simplex_projection {
    /** The point of conv(vertices) closest to the origin. */
    agjk_vec3 point;
    /** Barycentric weights of `point`, one per input vertex, >= 0, summing to 1;
     *  zero for vertices outside the support set. */
    double weights[4];
    /** Bit i set when vertex i belongs to the smallest sub-simplex holding
     *  `point` (the vertices with a non-zero weight). */
    uint32_t support_mask;
    /** Number of bits in support_mask (1 to 4); 4 means the origin is inside a
     *  full-dimensional tetrahedron. */
    int32_t support_count;
} agjk_simplex_projection;

/** Projects the origin onto conv(vertices[0..count-1]), 1 <= count <= 4.
 *  Robust on degenerate simplices (repeated, collinear or coplanar points): the
 *  result is always finite for finite input. Returns AGJK_STATUS_INVALID_INPUT
 *  for NULL pointers, count outside 1..4 or non-finite vertices, else
 *  AGJK_STATUS_INTERSECTING when the origin lies in the simplex and
 *  AGJK_STATUS_SEPARATED otherwise. */
AGJK_API agjk_status agjk_simplex_project_origin(const agjk_vec3 *vertices, int count,
                                                 agjk_simplex_projection *projection);

/** A static English string naming `status` ("separated", ...); "unknown status"
 *  for values not in agjk_status. Never NULL. */
AGJK_API const char *agjk_status_string(agjk_status status);

/** A static string naming `method` ("gjk", "nesterov", "nesterov-normalized",
 *  "polyak", "fw", "adaptive"), or "unknown" for values not in agjk_method. Never NULL. */
AGJK_API const char *agjk_method_name(agjk_method method);

#ifdef __cplusplus
}
#endif

#endif /* AGJK_QUERY_H */
/** @} */
