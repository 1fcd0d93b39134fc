/* SPDX-License-Identifier: MIT */
/* Convex hull triangles of a small point set by brute force: a triple
 * (i, j, k) is a hull face when every other point lies strictly on one side
 * of its plane (orientation sign in long double). O(n^4): for test fixtures
 * of up to ~100 points in general position (e.g. random points on an
 * ellipsoid), where it is obviously right; independent of any hull library. */
#ifndef AGJK_TEST_BRUTE_HULL_H
#define AGJK_TEST_BRUTE_HULL_H

#include <stdint.h>
#include "agjk/agjk.h"

/* Writes up to max_triangles triangles (3 indices each, outward orientation)
 * to `triangles`; returns their number, or -1 if the points are not in
 * general position (4 coplanar hull points), or there is no room. */
int brute_hull(const agjk_vec3 *points, int n, int32_t *triangles, int max_triangles);

#endif
