/* SPDX-License-Identifier: MIT */
/**
 * @file agjk/shapes.h
 * @brief Built-in convex shapes and their support functions.
 *
 * @defgroup agjk_shapes Built-in shapes
 *
 * Each built-in shape is a small value struct describing the shape in its local
 * frame (centred at the origin, axis-aligned) plus an agjk_shape_* function that
 * validates it and fills an agjk_shape pointing at it. The struct must outlive
 * the agjk_shape; after changing it, call the agjk_shape_* function again.
 * Constructors return AGJK_STATUS_OK, or AGJK_STATUS_INVALID_INPUT (NULL pointer,
 * NaN/Inf or negative size), in which case `shape` is left unchanged.
 * Each shape lives in its own object file, so a static link pulls in only the
 * shapes a program uses.
 * @{
 */
#ifndef AGJK_SHAPES_H
#define AGJK_SHAPES_H

#include "agjk/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest vertex count accepted for a polytope. */
#define AGJK_POLYTOPE_MAX_VERTICES (1 << 24)

/** Ellipsoid with semi-axes `radii` along the local x, y, z axes (each > 0). */
typedef struct agjk_ellipsoid {
    agjk_vec3 radii;
} agjk_ellipsoid;

/** Box with half extents along the local axes (each >= 0; zero gives a plate,
 *  a segment or a point). */
typedef struct agjk_box {
    agjk_vec3 half_extents;
} agjk_box;

/** Capsule along the local z axis: the segment z in [-half_height, half_height]
 *  swept by a sphere of `radius` (both >= 0). */
typedef struct agjk_capsule {
    double radius;
    double half_height;
} agjk_capsule;

/** Cylinder along the local z axis, z in [-half_height, half_height] (both >= 0). */
typedef struct agjk_cylinder {
    double radius;
    double half_height;
} agjk_cylinder;

/** Cone along the local z axis: base disc of `radius` at z = -half_height,
 *  apex at z = +half_height (both >= 0). */
typedef struct agjk_cone {
    double radius;
    double half_height;
} agjk_cone;

/** Convex polytope given by its vertices (the convex hull of the points is the
 *  shape; interior and duplicate points are allowed but cost time).
 *
 * Support is found by a scan over all vertices, or, when `neighbor_offsets` and
 * `neighbors` are given, by hill climbing over the vertex adjacency graph of the
 * hull starting from the hint (warm start). The adjacency is in CSR form: the
 * neighbours of vertex i are neighbors[neighbor_offsets[i] .. neighbor_offsets[i+1]-1].
 * Hill climbing is exact only when the graph is the edge graph of the convex
 * hull of `vertices` (every vertex on the hull); see agjk_polytope_build_adjacency. */
typedef struct agjk_polytope {
    const agjk_vec3 *vertices;
    int32_t vertex_count;           /**< 1 .. AGJK_POLYTOPE_MAX_VERTICES */
    const int32_t *neighbor_offsets; /**< NULL, or vertex_count + 1 entries */
    const int32_t *neighbors;        /**< NULL, or neighbor_offsets[vertex_count] entries */
} agjk_polytope;

/** Polytopes with an adjacency find support points by hill climbing from this
 *  many vertices on; below it the vertices are scanned even when an adjacency
 *  is given (a scan is faster there). */
#define AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES 32

/** A single point at the local origin. */
AGJK_API agjk_status agjk_shape_point(agjk_shape *shape);
/** A sphere of `radius` >= 0 centred at the local origin (a point with a margin). */
AGJK_API agjk_status agjk_shape_sphere(agjk_shape *shape, double radius);
/** An ellipsoid; `ellipsoid` must outlive `shape`. */
AGJK_API agjk_status agjk_shape_ellipsoid(agjk_shape *shape, const agjk_ellipsoid *ellipsoid);
/** A box; `box` must outlive `shape`. */
AGJK_API agjk_status agjk_shape_box(agjk_shape *shape, const agjk_box *box);
/** A capsule (a segment with a margin); `capsule` must outlive `shape`. */
AGJK_API agjk_status agjk_shape_capsule(agjk_shape *shape, const agjk_capsule *capsule);
/** A cylinder; `cylinder` must outlive `shape`. */
AGJK_API agjk_status agjk_shape_cylinder(agjk_shape *shape, const agjk_cylinder *cylinder);
/** A cone; `cone` must outlive `shape`. */
AGJK_API agjk_status agjk_shape_cone(agjk_shape *shape, const agjk_cone *cone);
/** A convex polytope. Checks every vertex is finite and, when adjacency is
 *  given, that it is well formed (O(vertices + edges), once). `polytope` and
 *  the arrays it points to must outlive `shape`. */
AGJK_API agjk_status agjk_shape_polytope(agjk_shape *shape, const agjk_polytope *polytope);

/** Sets the margin (sphere-swept radius, finite and >= 0) of any shape: rounds
 *  a box, a polytope, etc. */
AGJK_API agjk_status agjk_shape_set_margin(agjk_shape *shape, double margin);

#ifdef __cplusplus
}
#endif

#endif /* AGJK_SHAPES_H */
/** @} */
