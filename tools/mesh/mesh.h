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

/* The points of a mesh file: every vertex record of the file (OFF, OBJ: also
 * vertices no face uses, duplicates kept), or for the formats read by assimp
 * every vertex of every mesh of the scene in the scene's root frame (node
 * transforms applied; assimp may merge identical vertices). */
typedef struct mesh_points {
    agjk_vec3 *points;
    size_t count;
    size_t mesh_count;   /* meshes merged */
    size_t face_count;   /* faces of all kinds (points, lines, polygons) */
    /* 1: every coordinate is the double nearest to the number written in the
     * file (OFF and OBJ by our reader, ASCII PLY whose x, y, z are declared
     * double); 0: single precision (assimp's floats, or a PLY coordinate
     * declared float: the float nearest to the text). */
    int double_precision;
    char precision_note[64]; /* how the coordinates were read, for `agjk info` */
    char format[16];     /* file extension, lower case, e.g. "off" */
} mesh_points;

/* Loads `path`. OFF and OBJ files are read by the strict reader of
 * mesh_text.c; other formats by assimp. Returns 1 on success; 0 with a
 * message in `err` (naming the file, and the line for OFF and OBJ) for a
 * missing/unreadable/empty file, a malformed record, a number that is not
 * finite or beyond AGJK_MAX_COORDINATE, a face index out of range, a format
 * assimp cannot read, a scene without vertices, or a non-finite vertex.
 *
 * assimp itself crashes on some malformed files (found by fuzzing: OFF files
 * with extra vertex lines, PLY files with out-of-range face indices), so its
 * import runs in a child process (mesh_isolate.c): a crash there becomes an
 * error message here. Set the environment variable AGJK_MESH_IN_PROCESS=1 to
 * load in-process instead (debuggers, coverage-guided fuzzers). */
int mesh_load(const char *path, mesh_points *out, char *err, size_t err_size);
/* The same, always in this process. */
int mesh_load_in_process(const char *path, mesh_points *out, char *err, size_t err_size);
void mesh_points_free(mesh_points *points);

/* The strict OFF / OBJ reader (format "off" or "obj"; see mesh_text.c).
 * Returns 1 with every vertex of the file in `out`, in double; 0 with a
 * message "FILE:LINE: what is wrong" in `err`. */
int mesh_read_text(const char *path, const char *format, mesh_points *out, char *err,
                   size_t err_size);

/* The numbers of the text formats: [+-] digits [. digits] [(e|E) [+-] digits],
 * converted by strtod (the double nearest to the text). Returns MESH_NUMBER_OK
 * with *value set, or why the token is not a coordinate. */
enum {
    MESH_NUMBER_OK = 0,
    MESH_NUMBER_NOT_A_NUMBER,
    MESH_NUMBER_NOT_FINITE,  /* NaN, Inf */
    MESH_NUMBER_OUT_OF_RANGE /* magnitude beyond AGJK_MAX_COORDINATE */
};
int mesh_parse_coordinate(const char *token, double *value);
/* The message for a code of mesh_parse_coordinate(), quoting the token. */
void mesh_coordinate_error(int code, const char *token, char *msg, size_t size);

/* ASCII PLY: replaces assimp's float points by every vertex record of the
 * file, read as text (see mesh_refine.c): a coordinate declared double is the
 * double nearest to the text, one declared float the float nearest to it;
 * sets double_precision and precision_note accordingly. Returns 1 if done; 0
 * (points unchanged) for another format or a layout this reader declines; -1
 * with "FILE:LINE: what is wrong" in `err` for a malformed vertex record. */
int mesh_refine_double(const char *path, const char *format, mesh_points *points, char *err,
                       size_t err_size);

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
     * hull is solid; and the same prepared (agjk_polytope_prepare). Pass
     * &prepared to agjk_shape_prepared_polytope(). */
    agjk_polytope polytope;
    agjk_prepared_polytope prepared;
    agjk_vec3 bbox_min, bbox_max; /* of the input points */
    /* 1: dimension 3 by our test, but Qhull found the set too thin for a
     * solid hull; the points are kept as for a degenerate set. */
    int qhull_failed;
    /* 1: built by mesh_hull_points_only(): no hull was computed, `vertices`
     * are all the input points (dimension is still the affine dimension). */
    int points_only;
} mesh_hull;

/* Builds the hull of points[0..count-1] (count >= 1, all finite) with Qhull.
 * `with_adjacency`: also build the CSR vertex graph for hill climbing.
 * Returns 1 on success, 0 with a message in `err`. */
int mesh_hull_build(const agjk_vec3 *points, size_t count, int with_adjacency, mesh_hull *hull,
                    char *err, size_t err_size);
/* The shape data without a hull: every input point is a vertex and the
 * support is a scan (exact: the support function of a point set is that of
 * its hull). Costs O(count), where Qhull took 6.5 to 9 microseconds of CPU
 * per point on 1,000,000 points of a sphere: the cheaper choice for a few
 * queries on a large set. Returns 1 on success, 0 with a message in `err`. */
int mesh_hull_points_only(const agjk_vec3 *points, size_t count, mesh_hull *hull, char *err,
                          size_t err_size);
void mesh_hull_free(mesh_hull *hull);

/* "solid", "flat (coplanar)", "collinear", "single point", or for
 * mesh_hull_points_only() "not computed (...)". */
const char *mesh_hull_kind(const mesh_hull *hull);

/* Writes the hull as OFF: the solid hull's vertices and triangles, or for a
 * degenerate hull its points with no faces. Returns 1 on success. */
int mesh_hull_write_off(const mesh_hull *hull, FILE *out);

#endif /* AGJK_TOOLS_MESH_H */
