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
} ref_result;

/* Builds the agjk_shape for `s` (pointing into s's own storage, so `s` must outlive it). */
agjk_status ref_make_agjk(ref_shape *s, agjk_shape *out);

/* Reference distance; returns 0 on success (converged or intersecting). */
int ref_distance(const ref_shape *a, const agjk_pose *pose_a,
                 const ref_shape *b, const agjk_pose *pose_b, ref_result *out);

#endif
