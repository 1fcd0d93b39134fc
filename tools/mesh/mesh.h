/* SPDX-License-Identifier: MIT */
/* Mesh files -> point sets -> convex hulls, for the agjk tools only.
 *
 * This small library links assimp (file formats) and Qhull (hulls); the core
 * library never does. Every function reports failure as a return value of 0
 * (or NULL) plus a one-line message in a caller buffer that names the file,
 * and never prints. */
#ifndef AGJK_TOOLS_MESH_H
#define AGJK_TOOLS_MESH_H

#include <stddef.h>
#include <stdio.h>

#include "agjk/agjk.h"
#include "agjk/polytope.h"

/* Room for one error message. */
#define MESH_ERROR_SIZE 512

/* The points of a mesh file: every vertex of every mesh of the scene, in the
 * scene's root frame (node transforms applied), duplicates allowed. */
typedef struct mesh_points {
    agjk_vec3 *points;
    size_t count;
    size_t mesh_count;   /* meshes merged */
    size_t face_count;   /* faces of all kinds (points, lines, polygons) */
    /* 1: coordinates were re-read from the text in double precision (OFF, OBJ,
     * ASCII PLY; a PLY coordinate declared float is rounded to float);
     * 0: they are assimp's single-precision floats. */
    int double_precision;
    char format[16];     /* file extension as assimp saw it, e.g. "off" */
} mesh_points;

/* Loads `path` with assimp. Returns 1 on success; 0 with a message in `err`
 * for a missing/unreadable/empty file, a format assimp cannot read, a scene
 * without vertices, or a non-finite vertex.
 *
 * assimp itself crashes on some malformed files (found by fuzzing: OFF files
 * with extra vertex lines, PLY files with out-of-range face indices), so the
 * import runs in a child process (mesh_isolate.c): a crash there becomes an
 * error message here. Set the environment variable AGJK_MESH_IN_PROCESS=1 to
 * load in-process instead (debuggers, coverage-guided fuzzers). */
int mesh_load(const char *path, mesh_points *out, char *err, size_t err_size);
/* The same, always in this process. */
int mesh_load_in_process(const char *path, mesh_points *out, char *err, size_t err_size);
void mesh_points_free(mesh_points *points);

/* Re-reads the vertex coordinates of an OFF, OBJ or ASCII PLY file in double precision
 * and replaces assimp's float coordinates by them (see mesh_refine.c). Returns
 * 1 if every point was matched and replaced, 0 (points unchanged) otherwise,
 * -1 if the file holds a non-finite coordinate (index in *nonfinite_vertex). */
int mesh_refine_double(const char *path, const char *format, mesh_points *points,
                       long *nonfinite_vertex);

/* assimp rejects an OFF file with no faces, yet such a file is a valid point
 * cloud: reads it directly. Returns 1 (points in `out`) if `path` is an OFF
 * file declaring 0 faces whose vertices all parse; -1 if one of them is not
 * finite (its index in *nonfinite_vertex); 0 otherwise. */
int mesh_read_off_point_cloud(const char *path, mesh_points *out, long *nonfinite_vertex);

/* 0 if `path` starts with an OFF header whose vertex and face counts cannot
 * fit in `file_size` bytes (a truncated file, or a count meant to exhaust
 * memory: assimp would reserve it before reading); 1 otherwise. */
int mesh_off_counts_plausible(const char *path, long file_size);

/* Convex hull of a point set. */
typedef struct mesh_hull {
    /* Affine dimension of the input: 3 for a solid hull; 0 (one point),
     * 1 (collinear) or 2 (coplanar) for a degenerate one. */
    int dimension;
    /* dimension 3: the hull's extreme vertices; otherwise the distinct input
     * points (the support function of a point set is valid for any set). */
    agjk_vec3 *vertices;
    int32_t vertex_count;
    /* Solid hull: outward-oriented triangles (3 indices each); else none. */
    int32_t *triangles;
    int32_t triangle_count;
    /* The shape data: vertices, plus the hill-climbing adjacency when the
     * hull is solid. Pass &polytope to agjk_shape_polytope(). */
    agjk_polytope polytope;
    agjk_vec3 bbox_min, bbox_max; /* of the input points */
    /* 1: dimension 3 by our test, but Qhull found the set too thin for a
     * solid hull; the points are kept as for a degenerate set. */
    int qhull_failed;
} mesh_hull;

/* Builds the hull of points[0..count-1] (count >= 1, all finite) with Qhull.
 * `with_adjacency`: also build the CSR vertex graph for hill climbing.
 * Returns 1 on success, 0 with a message in `err`. */
int mesh_hull_build(const agjk_vec3 *points, size_t count, int with_adjacency, mesh_hull *hull,
                    char *err, size_t err_size);
void mesh_hull_free(mesh_hull *hull);

/* "solid", "flat (coplanar)", "collinear", "single point". */
const char *mesh_hull_kind(const mesh_hull *hull);

/* Writes the hull as OFF: the solid hull's vertices and triangles, or for a
 * degenerate hull its points with no faces. Returns 1 on success. */
int mesh_hull_write_off(const mesh_hull *hull, FILE *out);

#endif /* AGJK_TOOLS_MESH_H */
