/* SPDX-License-Identifier: MIT */
/* Internal: projection of the origin onto a simplex of up to four points
 * (GJK's distance sub-algorithm). */
#ifndef AGJK_SRC_SIMPLEX_H
#define AGJK_SRC_SIMPLEX_H

#include "vec3.h"

/* Projects the origin onto conv(p[0..n-1]), 1 <= n <= 4, p finite.
 * Writes the closest point to *point and barycentric weights lambda[0..n-1]
 * (>= 0, summing to 1, zero outside the support set). Returns the support
 * mask: bit i set when lambda[i] > 0. A mask of all four bits means the origin
 * is inside the (non-degenerate) tetrahedron; *point is then exactly zero. */
unsigned agjk__simplex_project(const agjk_vec3 *p, int n, double lambda[4], agjk_vec3 *point);

#endif
