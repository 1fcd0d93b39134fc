/* SPDX-License-Identifier: MIT */
/* Internal: the support points of the simplest built-in shapes, inline, for
 * their callbacks (shape_*.c) and for the Minkowski support, which computes
 * them in place of the call through the pointer (minkowski.h): one body, so
 * both give the same bits. */
#ifndef AGJK_SRC_SHAPE_POINTS_H
#define AGJK_SRC_SHAPE_POINTS_H

#include "agjk/shapes.h"
#include "vec3.h"

/* The extent h >= 0 of a box-like support with the sign of d: +h for
 * d >= +0, -h for d < 0 or -0 (any choice maximises when d == 0). A branch,
 * not copysign: predicted, it lets the support point be formed before d is
 * known, which shortens GJK's chain of dependent steps (measured on close
 * boxes: copysign took 8% more time per query for 4% fewer instructions).
 * clang turns a plain conditional into a select (vectorised, d's sign bits
 * as a mask): the empty asm statement in one arm, which cannot be executed
 * speculatively, keeps it a branch (clang-built close box queries 226 ->
 * 200 ns; gcc branches anyway, and its code is the same). */
static inline double signed_extent(double h, double d) {
    if (signbit(d)) {
#if defined(__GNUC__)
        __asm__ volatile("");
#endif
        return -h;
    }
    return h;
}

/* Axis-aligned box centred at the origin: the corner whose signs match d. */
static inline agjk_vec3 agjk__box_point(const agjk_box *b, agjk_vec3 d) {
    return v3(signed_extent(b->half_extents.x, d.x), signed_extent(b->half_extents.y, d.y),
              signed_extent(b->half_extents.z, d.z));
}

/* Capsule core: the segment z in [-h, h]. */
static inline agjk_vec3 agjk__segment_point(const agjk_capsule *c, agjk_vec3 d) {
    return v3(0.0, 0.0, signed_extent(c->half_height, d.z));
}

/* Ellipsoid {p : sum (p_i / r_i)^2 <= 1}: its support value is ||D d||
 * with D = diag(r). Its square, unchecked: */
static inline double agjk__ellipsoid_root2(const agjk_ellipsoid *e, agjk_vec3 d) {
    agjk_vec3 r = e->radii;
    double x = r.x * d.x, y = r.y * d.y, z = r.z * d.z; /* D d */
    return x * x + y * y + z * z;
}
/* ||D d|| itself into *root when ||D d||^2 lies far from underflow and
 * overflow; returns 0, with nothing written, otherwise (tiny or huge
 * directions, stiff radii: shape_ellipsoid.c rescales first). */
static inline int agjk__ellipsoid_root(const agjk_ellipsoid *e, agjk_vec3 d, double *root) {
    double n2 = agjk__ellipsoid_root2(e, d);
    if (!(n2 >= 0x1p-900 && n2 <= 0x1p900)) return 0;
    *root = sqrt(n2);
    return 1;
}

/* Its support point is D^2 d / ||D d||: q = D^2 d and *inv = 1 / ||D d||
 * from the root above (one square root and one division), formed as
 * ||D d|| / ||D d||^2: the division needs only the square, so it runs
 * alongside the square root instead of after it, which takes the
 * division's latency off GJK's chain of dependent steps (ellipsoid cells
 * 2-3% faster, every category and mode). One rounding more: the support
 * value <d, q inv> within 4.4 units of roundoff of ||D d||, against 4.2
 * for 1 / ||D d|| (20 million random radii and directions, long double).
 * Power-of-two scalings of d or of the radii scale every step exactly, so
 * answers stay bit-equivariant. */
static inline void agjk__ellipsoid_from_root(const agjk_ellipsoid *e, agjk_vec3 d, double root,
                                             agjk_vec3 *q, double *inv) {
    agjk_vec3 r = e->radii;
    *inv = root * (1.0 / agjk__ellipsoid_root2(e, d));
    *q = v3(r.x * (r.x * d.x), r.y * (r.y * d.y), r.z * (r.z * d.z));
}

/* Both: q and *inv, or 0 as agjk__ellipsoid_root. */
static inline int agjk__ellipsoid_unnormalized(const agjk_ellipsoid *e, agjk_vec3 d, agjk_vec3 *q,
                                               double *inv) {
    double root;
    if (!agjk__ellipsoid_root(e, d, &root)) return 0;
    agjk__ellipsoid_from_root(e, d, root, q, inv);
    return 1;
}

/* The same for a direction and radii that keep ||D d||^2 far from
 * underflow and overflow by construction (the bounded path of
 * agjk__minkowski_support): the same operations and bits, without the
 * range test, whose comparisons and branch on the square root's argument
 * sat in GJK's chain of dependent steps (close and overlapping ellipsoid
 * queries 1-2% faster without them). */
static inline void agjk__ellipsoid_unnormalized_in_range(const agjk_ellipsoid *e, agjk_vec3 d,
                                                         agjk_vec3 *q, double *inv) {
    agjk__ellipsoid_from_root(e, d, sqrt(agjk__ellipsoid_root2(e, d)), q, inv);
}

/* The support point itself, q / ||D d||. */
static inline int agjk__ellipsoid_point(const agjk_ellipsoid *e, agjk_vec3 d, agjk_vec3 *out) {
    agjk_vec3 q;
    double inv;
    if (!agjk__ellipsoid_unnormalized(e, d, &q, &inv)) return 0;
    *out = v3_scale(q, inv);
    return 1;
}

/* The callbacks of these shapes (shape_*.c). */
void agjk__point_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint);
void agjk__box_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out, int *hint);
void agjk__segment_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                           int *hint);
void agjk__ellipsoid_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                             int *hint);
void agjk__polytope_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                            int *hint);
/* Both supports of two polytopes at once (shape_polytope.c). */
void agjk__polytope_pair_support(const void *data_a, const agjk_vec3 *direction_a,
                                 agjk_vec3 *out_a, int *hint_a, const void *data_b,
                                 const agjk_vec3 *direction_b, agjk_vec3 *out_b, int *hint_b);
void agjk__prepared_polytope_support(const void *data, const agjk_vec3 *direction,
                                     agjk_vec3 *out, int *hint);
void agjk__prepared_polytope_pair_support(const void *data_a, const agjk_vec3 *direction_a,
                                          agjk_vec3 *out_a, int *hint_a, const void *data_b,
                                          const agjk_vec3 *direction_b, agjk_vec3 *out_b,
                                          int *hint_b, int first);

#endif
