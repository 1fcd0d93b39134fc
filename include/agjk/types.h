/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/types.h
 * @brief Value types of the agjk API: vectors, poses, shapes, options, results.
 *
 * @defgroup agjk_types Types
 *
 * Conventions used throughout agjk:
 * - Lengths are in the caller's unit (metres, millimetres, ...); agjk never assumes one.
 * - A pose maps a shape's local coordinates to world coordinates:
 *   p_world = rotation * p_local + translation, rotation row-major.
 * - The Minkowski difference D = A - B is formed in the local frame of A.
 *   The solver minimises f(x) = ||x||^2 over D; x* is the point of D closest
 *   to the origin and ||x*|| is the distance between the (core) shapes.
 * - The Frank-Wolfe duality gap at an iterate x with support s = argmin_{s in D} <x, s>
 *   is g(x) = 2 <x, x - s> (Montaut et al. 2022, eq. 12). It certifies
 *   ||x - x*||^2 <= ||x||^2 - ||x*||^2 <= g (eq. 13).
 * @{
 */
#ifndef AGJK_TYPES_H
#define AGJK_TYPES_H

#include "agjk/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest coordinate magnitude agjk accepts anywhere: translations, support
 *  points, sizes, vertices. Products of up to six coordinates (volumes squared)
 *  must not overflow a double; 1e50 leaves room for that. Larger values give
 *  AGJK_STATUS_INVALID_INPUT. */
#define AGJK_MAX_COORDINATE 1e50

/** A 3-vector of doubles. */
typedef struct agjk_vec3 {
    double x, y, z;
} agjk_vec3;

/** A rigid transform: p_world = rotation * p_local + translation.
 *  `rotation` is row-major (rotation[row][column]) and must be a rotation:
 *  rows 0 and 1 orthonormal and row 2 their cross product, each to within
 *  1e-6 per entry (so R R^T is within 6e-6 of I and det R within 4e-6 of
 *  +1); queries reject anything else with AGJK_STATUS_INVALID_INPUT. A
 *  rotation orthonormal only to within e (a float-converted one, say)
 *  stands for the rotation it approximates: B is
 *  taken into A's frame by rotation_A^T, answers are certified for that
 *  relative pose, and world-frame outputs (normal, witness points) come back
 *  through rotation_A, so they carry e: against shapes placed by the matrices
 *  as given, the normal's plane is off by about e times their extent. */
typedef struct agjk_pose {
    double rotation[3][3];
    agjk_vec3 translation;
} agjk_pose;

/** Outcome of a query. Values are fixed forever; new ones are appended. */
typedef enum agjk_status {
    /** The shapes are disjoint, and certified so: a plane separating them was
     *  found (for agjk_distance: the duality gap reached the tolerance and the
     *  lower bound distance - bound is > 0). */
    AGJK_STATUS_SEPARATED = 0,
    /** The shapes share at least one point, certified: the origin lies in a
     *  simplex of D (or the core distance is below the summed margins). */
    AGJK_STATUS_INTERSECTING = 1,
    /** The tolerance was reached but neither separation nor intersection could be
     *  certified: the true distance lies in [0, distance] with distance <= bound.
     *  The shapes touch to within the tolerance. Queries go on past the
     *  tolerance (up to 32 more iterations, never past max_iterations) to decide
     *  the sign, so this answer is kept for shapes within rounding of contact,
     *  or so close that those iterations could not tell. */
    AGJK_STATUS_CONTACT_WITHIN_TOLERANCE = 2,
    /** The iteration cap was hit, floating point stopped making progress
     *  before the tolerance (or, in absolute mode, the floating-point floor) was
     *  reached, or a relative accuracy beyond what double precision certifies was
     *  asked; agjk_result::stop_reason says which. The result still holds the
     *  best iterate and a valid certified bound; no verdict is given. */
    AGJK_STATUS_NOT_CONVERGED = 3,
    /** An argument was invalid (NULL pointer, NaN/Inf, negative size, bad
     *  rotation, tolerance <= 0, max_iterations < 1, unknown enum, a coordinate
     *  beyond AGJK_MAX_COORDINATE, a support function that returned a non-finite
     *  or out-of-range point). Nothing was computed. */
    AGJK_STATUS_INVALID_INPUT = 4,
    /** Success of a function that gives no geometric verdict (the shape
     *  constructors of agjk/shapes.h). Queries never return it. */
    AGJK_STATUS_OK = 5
} agjk_status;

/** Choice of support direction in the Frank-Wolfe family loop
 *  (Montaut et al., "Collision Detection Accelerated: An Optimization
 *  Perspective", RSS 2022, arXiv 2205.09663). */
typedef enum agjk_method {
    /** GJK: fully-corrective Frank-Wolfe on simplices, direction x_k (Alg. 4/5). */
    AGJK_METHOD_GJK = 0,
    /** Nesterov-accelerated GJK (Alg. 6), with the fallback to GJK directions
     *  when the momentum direction stalls. Best on strictly convex shapes. */
    AGJK_METHOD_NESTEROV = 1,
    /** Nesterov-accelerated GJK with normalized directions (Alg. 6 + Alg. 7).
     *  Best on polytopes and other non-strictly convex shapes. */
    AGJK_METHOD_NESTEROV_NORMALIZED = 2,
    /** Polyak (heavy-ball) momentum on the support direction, as in GJK++
     *  (Montaut et al. 2024): d_k = d_{k-1}/(k+1) + (1 - 1/(k+1)) x_k. */
    AGJK_METHOD_POLYAK = 3,
    /** Plain Frank-Wolfe with exact line search (Alg. 1): the active set is
     *  the current iterate only. Slow; kept as the reference of the family. */
    AGJK_METHOD_FRANK_WOLFE = 4,
    /** Adaptive (the default): Polyak momentum while the shapes are far apart
     *  relative to the gap, Nesterov momentum (Alg. 6) once the best support
     *  plane is below 0.9 ||x_k||, plain GJK directions from the first momentum
     *  step that gives a worse support plane than the best so far (adaptive
     *  restart), and a stop as soon as the best support plane met in any
     *  direction certifies the tolerance (no extra support in direction x_k).
     *  See the README for the rule and its measurements. */
    AGJK_METHOD_ADAPTIVE = 5
} agjk_method;

/** How agjk_options::tolerance is read. */
typedef enum agjk_tolerance_mode {
    /** Stop when g <= tolerance. Units: length squared. Certifies
     *  ||x - x*|| <= sqrt(tolerance): tolerance 1e-8 means 1e-4 length units,
     *  i.e. 0.1 mm for a part measured in metres, 1e-4 mm for a part in mm.
     *  This is the paper's criterion. */
    AGJK_TOLERANCE_ABSOLUTE = 0,
    /** Stop when g <= tolerance * ||x|| * d, d = ||x|| - margins the distance:
     *  dimensionless. Certifies a relative distance error of at most
     *  tolerance / 2 (|d - d*| <= d * tolerance / 2), the same for a 1 mm part
     *  and a 10 m part, and still accurate for shapes that nearly touch. When
     *  double precision cannot reach that accuracy (d below about 1e-15 x the
     *  shapes' size / tolerance) the query ends AGJK_STATUS_NOT_CONVERGED with
     *  the bound it did reach. */
    AGJK_TOLERANCE_RELATIVE = 1
} agjk_tolerance_mode;

/** Why a query ended without a verdict (agjk_result::stop_reason). Values are
 *  fixed forever; new ones are appended. */
typedef enum agjk_stop_reason {
    /** The query converged or gave a verdict (status other than NOT_CONVERGED). */
    AGJK_STOP_NONE = 0,
    /** agjk_options::max_iterations iterations ran before the tolerance was met. */
    AGJK_STOP_ITERATION_CAP = 1,
    /** Floating point cannot decrease ||x|| any further: at the iteration
     *  reported in agjk_result::iterations no step made progress and the gap is
     *  still above the tolerance (and, in absolute mode, above the rounding floor). */
    AGJK_STOP_NO_PROGRESS = 2,
    /** The solver met the tolerance (or its floor), but the certified
     *  interval, rounding included, is wider than what was asked: in relative
     *  mode, than the relative accuracy (double precision cannot certify it
     *  for a distance this small compared with the shapes' size); in either
     *  mode, when the active set's own point, which gives the upper bound,
     *  lies off the iterate by more than rounding (an ill-conditioned
     *  projection) and the interval it widens meets neither the tolerance
     *  nor the floating-point floor. */
    AGJK_STOP_BELOW_PRECISION = 3
} agjk_stop_reason;

/** What the distance query computes beyond the distance. Bit flags. */
typedef enum agjk_compute_flags {
    /** Only distance, bound, normal and counters. */
    AGJK_COMPUTE_DISTANCE = 0,
    /** Also the witness points (closest points on A and on B). */
    AGJK_COMPUTE_WITNESS = 1
} agjk_compute_flags;

/** Support function of a convex set in its local frame.
 *
 * Writes to `*out_support` a point p of the set maximising <direction, p>.
 * `direction` is finite and non-zero but not normalised. `hint` points to an
 * integer the callback may read as a warm-start (e.g. a vertex index from the
 * previous call) and update; it is never NULL during a query and starts at the
 * value given in agjk_options (0 by default). The callback must be pure
 * (no side effect but `*hint` and `*out_support`) for queries to be thread-safe.
 * A non-finite output makes the query return AGJK_STATUS_INVALID_INPUT. */
typedef void (*agjk_support_fn)(const void *shape_data, const agjk_vec3 *direction,
                                agjk_vec3 *out_support, int *hint);

/** A convex shape: a support function, its data, and a margin.
 *
 * The shape is the Minkowski sum of the set described by `support` (the core)
 * and a ball of radius `margin` (sphere sweeping): a sphere is a point with a
 * margin, a capsule a segment with a margin. The solver works on the cores and
 * adds the margins analytically. `data` must outlive every query using it. */
typedef struct agjk_shape {
    agjk_support_fn support;
    const void *data;
    double margin; /**< Sphere-swept radius, >= 0, in length units. */
} agjk_shape;

/** Query options. Always start from agjk_default_options() (or
 *  agjk_options_init()) and then change fields: new fields are appended in later
 *  versions and the library reads only those the caller's header knew. */
typedef struct agjk_options {
    /** sizeof(agjk_options) as the caller compiled it; set by the init function. */
    uint32_t struct_size;
    /** Direction policy. Default AGJK_METHOD_ADAPTIVE (AGJK_METHOD_NESTEROV in 0.1). */
    agjk_method method;
    /** How `tolerance` is read. Default AGJK_TOLERANCE_ABSOLUTE. */
    agjk_tolerance_mode tolerance_mode;
    /** Tolerance on the duality gap, > 0 and finite; see agjk_tolerance_mode
     *  for units. Default 1e-8 (the paper's). In absolute mode a value below the
     *  floating-point floor is raised to that floor: g = 2 <x, x - s> (s the
     *  support point in direction x) is resolved only to about
     *  2 (||x|| + ||x - s||) * 4 eps * the size of the problem (x and s each
     *  carry that rounding), which for shapes much closer than their size
     *  (||x|| << ||x - s||) lies far above 2 ||x|| * 4 eps * size; result.gap
     *  and result.bound tell what was reached. */
    double tolerance;
    /** Iteration cap, >= 1. Default 1000 (the paper's benchmark setting). */
    int32_t max_iterations;
    /** AGJK_COMPUTE_* flags for agjk_distance. Default AGJK_COMPUTE_WITNESS.
     *  agjk_collide ignores it and never computes witness points. */
    uint32_t compute;
    /** Non-zero: start from `initial_direction` instead of x_0 = c_A - c_B, the
     *  difference of the shapes' frame origins (warm start; the previous result's
     *  -normal is a good guess for coherent queries). */
    int32_t use_initial_direction;
    /** Warm-start guess of x* (a vector of D = A - B, in world coordinates). */
    agjk_vec3 initial_direction;
    /** Initial support hints passed to the support callbacks of A and of B. */
    int32_t hint_a, hint_b;
} agjk_options;

/** Result of agjk_distance() or agjk_collide(). Every field is always written
 *  (zero where not computed), so a result never holds NaN or stale data. */
typedef struct agjk_result {
    agjk_status status;
    /** Certified upper bound on the distance between the shapes (margins
     *  included), >= 0: the length of a vector of D = A - B, plus an allowance
     *  for the rounding of that vector (a few ulps of the problem's size). 0 when
     *  intersecting. agjk_collide leaves it 0. */
    double distance;
    /** Certified width: the true distance lies in [max(0, distance - bound),
     *  distance], rounding included at both ends. Derived from the final gap:
     *  bound <= min(sqrt(gap), gap / (2 ||x||)) plus the rounding allowances
     *  (a few ulps of the problem's size at each end). agjk_collide leaves it 0. */
    double bound;
    /** Final Frank-Wolfe duality gap g = 2 <x, x - s> in length units squared. */
    double gap;
    /** Closest point on A, world frame (only with AGJK_COMPUTE_WITNESS). */
    agjk_vec3 witness_a;
    /** Closest point on B, world frame (only with AGJK_COMPUTE_WITNESS). */
    agjk_vec3 witness_b;
    /** Unit vector in world frame from A towards B, the normal of the support
     *  plane that certified the answer: for agjk_distance, the direction of
     *  witness_b - witness_a, except when AGJK_METHOD_ADAPTIVE stopped on the
     *  plane of another support direction met on the way (the plane with this
     *  normal then separates the shapes by at least distance - bound); for
     *  agjk_collide when separated, the normal of the separating plane found.
     *  Zero when intersecting, and for a contact within tolerance whose final
     *  iterate is zero (shapes that touch exactly, such as boxes face to
     *  face: no direction is known). */
    agjk_vec3 normal;
    /** Iterations of the solver loop (each computes one or two supports). */
    int32_t iterations;
    /** Calls of the Minkowski support (each calls both shapes' callbacks once). */
    int32_t support_calls;
    /** Iteration at which momentum was switched off and plain GJK directions took
     *  over (Alg. 6 fallback), or -1 if it never was (or the method has no momentum). */
    int32_t momentum_stop_iteration;
    /** Final support hints of A and B: pass them back in agjk_options to warm-start. */
    int32_t hint_a, hint_b;
    /** Why the query ended AGJK_STATUS_NOT_CONVERGED (an agjk_stop_reason);
     *  AGJK_STOP_NONE with every other status. (Occupies what was padding in
     *  0.1.0, which that version wrote as zero.) */
    int32_t stop_reason;
    /** Reserved for fields appended in later versions; written as zero. */
    double reserved[8];
} agjk_result;

#ifdef __cplusplus
}
#endif

#endif /* AGJK_TYPES_H */
/** @} */
