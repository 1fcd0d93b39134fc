/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/cache.h
 * @brief Warm start for coherent queries: a caller-owned cache of the last
 *        simplex, as Box2D's simplex cache.
 *
 * @defgroup agjk_cache Warm-start cache
 *
 * Robots and simulators ask about the same pair again and again while things
 * move a little. An agjk_cache, kept by the caller per pair, remembers the final
 * simplex of the previous query as points of A and of B in their own local
 * frames, the support hints and the last two directions of x*. On flat-faced
 * shapes (a vertex met twice: AGJK_CACHE_FLAT) the next query moves those
 * points with the new poses and starts from their projection; on curved ones
 * it starts from the direction extrapolated from the last two queries. After a
 * small motion the first support often certifies the answer already.
 *
 * Answers stay certified whatever the cache holds:
 * - The cache records which pair filled it (the two support functions and data
 *   pointers, in order) and a check value of its simplex. For any other pair,
 *   and for a cache whose check value does not match, or holding NaN, Inf,
 *   out-of-range values or a bad count (zeroed, garbage or edited memory), it
 *   is ignored and the query runs cold. Garbage in the directions, hints or
 *   flags (finite, in range) only changes where the query starts.
 * - Every support found during the query is a plane that no point of the shapes
 *   crosses; a cached point on the wrong side of one is proof that the cache is
 *   stale, and the query restarts cold (its support calls are still counted).
 * - Local points do not depend on poses, so a cache filled at other poses (any
 *   motion, large or small) only changes the speed.
 * What the cache cannot detect: shape data changed in place (new radii, new
 * vertices) behind the same pointer. After such a change, call
 * agjk_cache_init() (a point of the old shape may lie outside the new one).
 *
 * Thread safety: a cache is written by the query that uses it; give each
 * thread its own caches.
 * @{
 */
#ifndef AGJK_CACHE_H
#define AGJK_CACHE_H

#include "agjk/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** agjk_cache::flags: the last query met a point of A or of B twice (a vertex:
 *  flat faces). The next query then restarts from the cached simplex, which on
 *  polytopes often certifies the answer with one support; on curved shapes it
 *  starts from the direction extrapolated from the last two queries instead. */
#define AGJK_CACHE_FLAT 1u

/** Warm-start state of one pair of shapes. Caller-owned, a plain value: copy
 *  it, keep it in an array, zero it. Read the fields for diagnostics only. */
typedef struct agjk_cache {
    /** sizeof(agjk_cache) as the caller compiled it, set by agjk_cache_init()
     *  and by every cached query. 0 (a zeroed cache) is accepted as empty. */
    uint32_t struct_size;
    /** Number of cached simplex vertices, 0 to 4. 0: no simplex; the next query
     *  starts from `direction` if it is non-zero, else cold. Without
     *  AGJK_CACHE_FLAT only a simplex that encloses the origin is kept (curved
     *  shapes start from the direction). */
    int32_t count;
    /** Support hints of A and B at the end of the last query. */
    int32_t hint_a, hint_b;
    /** AGJK_CACHE_* flags of the last query. */
    uint32_t flags;
    /** The pair that filled the cache (A's and B's support and data). */
    agjk_support_fn support_a, support_b;
    const void *data_a, *data_b;
    /** Simplex vertices: points of A's core in A's local frame and of B's core
     *  in B's local frame, length units (the caller's). */
    agjk_vec3 point_a[4], point_b[4];
    /** Estimate of the last x* (a vector of A - B: ||x|| along the normal of
     *  the plane that certified the answer) in A's local frame, length units,
     *  and the one of the query before (zero if none). */
    agjk_vec3 direction, direction_prev;
    /** Check value of `count`, the simplex points and `point_error`, written
     *  by every cached query that changes them: a cache whose simplex does not match it
     *  (garbage, or edited by hand) is ignored. The pair's pointers are
     *  compared with the query's shapes; the directions, hints and flags only
     *  choose where the query starts, and are checked for range. */
    uint64_t check;
    /** How far the cached points of B may lie from B, length units: they are
     *  recovered in B's local frame from the query's points, which rounds,
     *  more so far from the origin, and under a rotation orthonormal only to
     *  within its tolerance. The next query widens its rounding allowances to
     *  cover it. Covered by the check value. */
    double point_error;
    /** Reserved for later versions; written as zero. */
    double reserved[3];
} agjk_cache;

/** Empties `cache` (a cold start next time). `struct_size` must be
 *  sizeof(agjk_cache) as the caller sees it; use agjk_cache_init(). Does
 *  nothing if cache is NULL or struct_size is too small. */
AGJK_API void agjk_cache_init_sized(agjk_cache *cache, size_t struct_size);

/** Empties `cache` (a cold start next time). */
static inline void agjk_cache_init(agjk_cache *cache) { agjk_cache_init_sized(cache, sizeof *cache); }

/** agjk_distance() warm-started from `cache`, which it then updates with this
 *  query's final simplex. Same arguments, checks, statuses and guarantees as
 *  agjk_distance(); `cache` may be NULL (then exactly agjk_distance()). When
 *  the cache is usable, options->use_initial_direction and the option hints are
 *  replaced by the cache's. On AGJK_STATUS_INVALID_INPUT the cache is emptied
 *  (if it was not the invalid argument itself). result->support_calls counts
 *  every support call, including those of a run abandoned for a stale cache. */
AGJK_API agjk_status agjk_distance_cached(const agjk_shape *a, const agjk_pose *pose_a,
                                          const agjk_shape *b, const agjk_pose *pose_b,
                                          const agjk_options *options, agjk_cache *cache,
                                          agjk_result *result);

/** agjk_collide() warm-started from `cache`, which it then updates; see
 *  agjk_distance_cached(). */
AGJK_API agjk_status agjk_collide_cached(const agjk_shape *a, const agjk_pose *pose_a,
                                         const agjk_shape *b, const agjk_pose *pose_b,
                                         const agjk_options *options, agjk_cache *cache,
                                         agjk_result *result);

#ifdef __cplusplus
}
#endif

#endif /* AGJK_CACHE_H */
/** @} */
