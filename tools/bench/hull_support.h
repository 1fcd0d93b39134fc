/* SPDX-License-Identifier: MIT */
/* Hill-climbing support for the benchmark's polytopes: the convex hull (Qhull,
 * through tools/mesh) with its vertex adjacency, as the paper's HPP-FCL does
 * for meshes. Without it agjk scans every vertex at every support call. */
#ifndef AGJK_BENCH_HULL_SUPPORT_H
#define AGJK_BENCH_HULL_SUPPORT_H

#include <stdint.h>

#include "problems.h"

/* A bench_polytope_hook: replaces s->polytope by the hull of s->vertices with
 * adjacency. Keeps scan support (and warns once) if the hull fails. */
void bench_hull_hook(bench_shape *s);
void bench_hull_free(void *aux);
/* The outward triangles (3 indices into s->polytope.vertices each) of a shape
 * the hook gave a solid hull; 0 (and *triangles NULL) otherwise. */
int bench_hull_triangles(const bench_shape *s, const int32_t **triangles);

#endif
