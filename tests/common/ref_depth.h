/* SPDX-License-Identifier: MIT */
/* High-precision references for the signed distance (minus the penetration
 * depth when shapes overlap), independent of the library:
 *
 *   s* = -min over unit n of h_D(n),  h_D(n) = h_A(n) + h_B(-n),  D = A - B
 *
 * (for separated shapes it is the distance, for overlapping ones minus the
 * depth: the shortest translation of B that separates them). */
#ifndef AGJK_TEST_REF_DEPTH_H
#define AGJK_TEST_REF_DEPTH_H

#include "reference.h"

/* Exact separating-axis depth of two overlapping convex polytopes given by
 * their vertices in world frame: the minimum of h_D over the candidate normals
 * of D = A - B (normals of every vertex triple of A and of B, cross products
 * of every vertex-pair direction of A with every one of B), in long double.
 * The facet normals of D are among the candidates, so for an overlapping pair
 * the minimum is the depth; extra candidates only give upper bounds. Returns
 * the signed distance -depth (< 0 when they overlap). O(n^3 + n^4) work: keep
 * n <= 20. */
long double ref_sat_signed_distance(const agjk_vec3 *va, int na, const agjk_vec3 *vb, int nb);

/* Certified bracket on s* for any pair of reference shapes (margins
 * included), by branch and bound over the sphere of directions, in long
 * double. The sphere is cut into cells (squares on the six faces of a cube,
 * projected); for a cell of angular radius t around the unit direction m, with
 * sigma = S_D(m) the support point, convexity gives for every n in the cell
 *   h_D(n) >= <sigma, n> >= |sigma| cos(angle(sigma, m) + t),
 * a lower bound that is tight to second order where sigma is parallel to m
 * (the optimum), so only a few cells per level survive; every h_D(m)
 * evaluated is an upper bound. Stops when the bracket on min h_D is narrower
 * than `width` or after `max_cells` evaluations.
 * Writes lower <= s* <= upper; returns 0 if the width was reached, else 1. */
typedef struct ref_signed_bracket {
    long double lower, upper;
    long double normal[3]; /* unit n (world) of the best upper bound: from A to B */
    int cells;
} ref_signed_bracket;

int ref_signed_distance_bb(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                           const agjk_pose *pose_b, long double width, int max_cells,
                           ref_signed_bracket *out);

#endif
