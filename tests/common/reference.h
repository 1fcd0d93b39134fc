/* SPDX-License-Identifier: MIT */
/* High-precision reference distance for tests and the benchmark.
 *
 * Independent of the library: its own support functions and its own simplex
 * projection (brute-force subset enumeration), all in long double, iterated
 * until its own Frank-Wolfe duality gap certifies the answer. Used as ground
 * truth by tests/core, tests/stability, tests/ccd and tools/bench. */
#ifndef AGJK_TEST_REFERENCE_H
#define AGJK_TEST_REFERENCE_H

#include "agjk/agjk.h"

typedef enum ref_kind {
    REF_POINT, REF_SPHERE, REF_ELLIPSOID, REF_BOX, REF_CAPSULE,
    REF_CYLINDER, REF_CONE, REF_POLYTOPE
} ref_kind;

/* One description of a shape both the reference and agjk can use.
 * p[0..2]: sphere radius in p[0]; ellipsoid radii; box half extents;
 * capsule/cylinder/cone radius in p[0], half height in p[1]. */
typedef struct ref_shape {
    ref_kind kind;
    double p[3];
    const agjk_vec3 *vertices; /* REF_POLYTOPE only */
    int vertex_count;
    double margin;             /* extra sphere-swept radius on top of the shape */
    /* storage for the agjk side (filled by ref_make_agjk) */
    agjk_ellipsoid ellipsoid; agjk_box box; agjk_capsule capsule;
    agjk_cylinder cylinder; agjk_cone cone; agjk_polytope polytope;
} ref_shape;

typedef struct ref_result {
    int intersecting;      /* 1: certified overlap (origin strictly inside D) */
    int converged;         /* 1: certified within the requested accuracy */
    long double distance;  /* best upper estimate of the distance (0 if intersecting) */
    long double lower;     /* certified lower bound on the distance */
    long double upper;     /* certified upper bound on the distance */
    int iterations;
    /* --- appended fields --- */
    /* Unit vector, world frame, from A towards B along the closest points
     * (-x / |x| for the core closest point x of D = A - B); zero when the
     * core distance is zero or the shapes intersect. */
    agjk_vec3 normal;
    /* Closest points on A and on B (margins included), world frame; when the
     * shapes intersect, a common point of the cores is not known: both are
     * then the core points found last (not meaningful). */
    agjk_vec3 witness_a, witness_b;
    /* Characteristic size used for the stopping test: the largest norm of a
     * support point of D met during the run (length units). */
    long double scale;
} ref_result;

/* Builds the agjk_shape for `s` (pointing into s's own storage, so `s` must outlive it). */
agjk_status ref_make_agjk(ref_shape *s, agjk_shape *out);

/* Reference distance; returns 0 on success (converged or intersecting).
 * Converged means upper - lower <= 1e-15 x scale. The bounds are certified
 * even when it is not reached; measured misses (seed 99, 1600 pairs each):
 * none for ellipsoids (also 1e5:1 stiff ones), boxes, capsules, margins at
 * 1e-8 ... 5; 25 of 1600 polytope pairs (500 vertices) at distance 1e-8 x
 * size stop with upper - lower <= 1.4e-14 x scale (edge simplex, the
 * direction of x limited by long double when |x| << size); cylinder-cone
 * pairs at 1e-8 ... 1e-6 may stall at up to 3e-12 x scale. Use lower/upper. */
int ref_distance(const ref_shape *a, const agjk_pose *pose_a,
                 const ref_shape *b, const agjk_pose *pose_b, ref_result *out);

/* Support point of the whole shape `s` (margin included) in its local frame,
 * in long double: a point p of s maximising <direction, p>. For tests of
 * support functions. `direction` need not be normalised; zero gives the core
 * support in an arbitrary fixed direction. */
void ref_support_local(const ref_shape *s, const long double direction[3],
                       long double out[3]);

/* Projection of the origin onto conv(vertices[0..count-1]), 1 <= count <= 4,
 * by brute force: the affine projection of every one of the 2^count - 1
 * subsets is solved in long double, candidates with all weights >= 0 are kept,
 * the one of least norm wins (ties to the smallest subset). */
typedef struct ref_projection {
    long double point[3];
    long double weights[4];
    long double distance;   /* |point| */
    unsigned mask;          /* vertices of the winning subset */
    int count;              /* bits in mask */
} ref_projection;

/* Returns 0 on success, -1 for count outside 1..4 or a NULL pointer. */
int ref_project_origin(const agjk_vec3 *vertices, int count, ref_projection *out);

#endif
