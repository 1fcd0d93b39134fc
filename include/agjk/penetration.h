/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/penetration.h
 * @brief Signed distance: the distance when separated, minus the penetration
 *        depth when overlapping, with a certified interval either way.
 *
 * @defgroup agjk_penetration Penetration depth and signed distance
 *
 * The penetration depth of two overlapping convex shapes A and B is the length
 * of the shortest translation of B that brings them to touching:
 * depth = min over unit n of h_D(n), h_D the support function of
 * D = A - B. agjk computes it with the Expanding Polytope Algorithm
 * (G. van den Bergen, "Proximity queries and penetration depth computation on
 * 3D game objects", GDC 2001; "Collision Detection in Interactive 3D
 * Environments", 2003), started from the simplex GJK ends with, and certifies
 * it: the polytope grown inside D proves a lower bound (the distance from the
 * origin to its nearest face), the support of D in the best face normal an
 * upper bound.
 *
 * Like the rest of agjk: reentrant, thread-safe, no allocation (the polytope
 * lives on the stack: AGJK_EPA_MAX_VERTICES vertices, about 46 KB), every loop
 * bounded. A program that never calls agjk_signed_distance links none of this
 * code.
 * @{
 */
#ifndef AGJK_PENETRATION_H
#define AGJK_PENETRATION_H

#include "agjk/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Capacity of the expanding polytope: vertices (faces: twice as many). EPA
 *  adds one vertex per iteration; when the store is full the query ends
 *  AGJK_STATUS_NOT_CONVERGED with the interval reached. */
#define AGJK_EPA_MAX_VERTICES 128

/** Result of agjk_signed_distance(). Every field is always written (zero where
 *  not computed), so a result never holds NaN or stale data. Lengths are in the
 *  caller's unit. */
typedef struct agjk_signed_result {
    /** SEPARATED (certified: lower > 0), INTERSECTING (certified: upper < 0),
     *  CONTACT_WITHIN_TOLERANCE (the tolerance was met but the interval holds 0:
     *  touching), NOT_CONVERGED (the final interval, every rounding allowance
     *  included, is wider than the tolerance asks: iteration cap, full
     *  polytope store, rounding stopped progress first, or an accuracy beyond
     *  what double precision certifies for this problem; lower and upper are
     *  still certified), INVALID_INPUT (as agjk_distance). A verdict is given
     *  exactly when the final interval meets the width asked (see
     *  agjk_signed_distance), whether or not agjk_distance would give one on
     *  the same shapes: its criterion is the gap, and its floor can be wider. */
    agjk_status status;
    /** Signed distance: the distance (margins included) when separated, minus
     *  the penetration depth when overlapping. It lies in [lower, upper].
     *  Separated: the GJK distance, an upper estimate, as agjk_distance gives.
     *  Overlapping: minus the support value of D in `normal`, a lower estimate:
     *  translating B by -signed_distance * normal brings the shapes to touching
     *  (to rounding). */
    double signed_distance;
    /** Certified interval: lower <= true signed distance <= upper (a rounding
     *  allowance of a few ulps of the problem's size included). */
    double lower, upper;
    /** Unit vector in world frame from A towards B: when separated, the
     *  direction of witness_b - witness_a; when overlapping, the direction in
     *  which B moves out of A along the shortest way. */
    agjk_vec3 normal;
    /** Witness points, world frame (only with AGJK_COMPUTE_WITNESS). Separated:
     *  the closest points, as agjk_distance. Overlapping: the deepest point of A
     *  along normal and of B along -normal, so that witness_a - witness_b is
     *  about depth * normal. */
    agjk_vec3 witness_a, witness_b;
    /** Iterations of the GJK loop. */
    int32_t gjk_iterations;
    /** Iterations of EPA (support calls on a face normal; 0 if not run). */
    int32_t epa_iterations;
    /** Calls of the Minkowski support over the whole query (GJK, EPA and the
     *  blow-up of a degenerate start). */
    int32_t support_calls;
    /** Final support hints of A and B (see agjk_result). */
    int32_t hint_a, hint_b;
    /** Reserved for fields appended in later versions; written as zero. */
    double reserved[8];
} agjk_signed_result;

/** Signed distance between two convex shapes, with penetration depth.
 *
 * Runs GJK as agjk_distance() does (same options) on the cores; if the cores
 * are certified disjoint the answer is the distance (margins subtracted
 * analytically, so shapes closer than their margins get a negative value
 * without EPA). Otherwise EPA computes the depth of the cores and the margins
 * are added to it.
 *
 * Tolerance (`options->tolerance`), on the width upper - lower of the interval:
 * - AGJK_TOLERANCE_ABSOLUTE (length units squared, as for distances):
 *   width <= min(sqrt(tolerance), tolerance / (2 |signed_distance|)), the error
 *   agjk_distance certifies at that distance with that gap. The default 1e-8
 *   gives about 5e-7 at a depth of 0.01, 5e-8 at a depth of 0.1. A width
 *   below the floating-point floor is raised to it: 1040 DBL_EPSILON (about
 *   1000 ulps) times the problem's size, that is the largest coordinates of
 *   the cores' support points (A's and B's added, in A's frame) plus the
 *   largest coordinate of the offset between the frames plus the margins.
 *   Where double precision cannot reach even that (the final gap of GJK
 *   resolved only to agjk_distance's floor, much wider for shapes far closer
 *   than their size, see agjk_options::tolerance), the status is
 *   AGJK_STATUS_NOT_CONVERGED with the interval reached.
 * - AGJK_TOLERANCE_RELATIVE (dimensionless): width <= tolerance / 2 *
 *   |signed_distance| (with the smallest |s| of the interval, 0 when it
 *   holds 0); when double precision cannot reach it the status is
 *   AGJK_STATUS_NOT_CONVERGED with the interval reached.
 * The width is that of the final interval, after the margins and their
 * rounding are added; |signed_distance| is taken at the interval's end
 * farthest from 0 in absolute mode (the safe side).
 * `options->max_iterations` caps the GJK loop and, separately, the EPA loop.
 *
 * Degenerate cases (touching shapes, shapes whose difference is flat, such as
 * two coplanar squares, GJK ending on a point, segment or triangle) are handled
 * by extra support calls; a flat difference has depth 0 (certified by the two
 * support planes). Returns result->status; if `result` is NULL returns
 * AGJK_STATUS_INVALID_INPUT and writes nothing. */
AGJK_API agjk_status agjk_signed_distance(const agjk_shape *a, const agjk_pose *pose_a,
                                          const agjk_shape *b, const agjk_pose *pose_b,
                                          const agjk_options *options,
                                          agjk_signed_result *result);

#ifdef __cplusplus
}
#endif

#endif /* AGJK_PENETRATION_H */
/** @} */
