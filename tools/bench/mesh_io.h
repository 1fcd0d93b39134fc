/* SPDX-License-Identifier: MIT */
/* Vertices of the meshes in a directory (OBJ "v" lines, OFF vertex blocks).
 * The benchmark needs only the vertices: a mesh's shape is their convex hull,
 * which agjk's polytope scan support evaluates exactly. */
#ifndef AGJK_BENCH_MESH_IO_H
#define AGJK_BENCH_MESH_IO_H

#include "problems.h"

/* Reads every *.obj / *.off file under `dir` (and its sub-directories, one
 * level deep, as pybullet_data/random_urdfs/NNN/NNN.obj), in sorted order.
 * Meshes with non-finite vertices or fewer than 4 vertices are skipped with a
 * warning. Each mesh is centred on its bounding-box centre and multiplied by
 * `scale`. Returns the number of meshes read, or -1 if the directory cannot
 * be opened. */
int bench_read_mesh_dir(const char *dir, bench_mesh_source *out, int max_meshes, double scale);
void bench_free_meshes(bench_mesh_source *m);

/* Reads one file; returns the vertex count (>= 0) or -1. Exposed for tests. */
int bench_read_mesh_file(const char *path, agjk_vec3 **vertices);

#endif
