/* SPDX-License-Identifier: MIT */
/* The Minkowski support's units and limits: the scale of extreme problems,
 * the rare paths of the support, and a priori bounds of built-in shapes. */
#include "minkowski.h"

/* Sum and largest of three numbers in [0, AGJK_MAX_COORDINATE] (0 itself
 * excluded unless zero_allowed): 1 with them, else 0 (NaN fails too).
 * Non-negative, so no absolute values: the same bits as v3_norm1 and
 * v3_maxabs. */
static int extents(agjk_vec3 h, int zero_allowed, double *sum, double *largest) {
    int low = zero_allowed ? h.x >= 0.0 && h.y >= 0.0 && h.z >= 0.0
                           : h.x > 0.0 && h.y > 0.0 && h.z > 0.0;
    if (!(low && h.x <= AGJK_MAX_COORDINATE && h.y <= AGJK_MAX_COORDINATE &&
          h.z <= AGJK_MAX_COORDINATE))
        return 0;
    double m = h.x > h.y ? h.x : h.y;
    *largest = m > h.z ? m : h.z;
    *sum = h.x + h.y + h.z;
    return 1;
}

/* Bounds on the 1-norm (*l1) and the max norm (*max) of every support
 * point of a built-in shape whose data bound them: 0 for another shape, or
 * for data a caller changed to be invalid after agjk_shape_*() accepted it
 * (the support path's own tests then catch what it gives). The built-ins
 * are recognised through the weak references of the direct support path:
 * a program without ellipsoids links no ellipsoid code for this either. */
static int point_bounds(agjk_support_fn fn, const void *data, double *l1, double *max) {
#if AGJK__DIRECT_SUPPORT
    if (fn == agjk__point_support) {
        *l1 = *max = 0.0;
        return 1;
    }
    if (!data) return 0;
    if (fn == agjk__ellipsoid_support) {
        /* |p_i| <= r_i for a support point D^2 d / ||D d||; computed, a few
         * ulps more, which the factor 1 + 2^-40 covers. */
        agjk_vec3 r = ((const agjk_ellipsoid *)data)->radii;
        if (!extents(r, 0, l1, max)) return 0;
        /* Bounded also promises ||D d||^2 in range for every direction the
         * support path lets through, which then skips its range test
         * (agjk__ellipsoid_unnormalized_in_range): |d|^2 in [2^-120,
         * 2^202] (max |d_i| in [AGJK__DIRECTION_MIN, AGJK__DIRECTION_MAX];
         * B's direction turned from it has |d| to a few ulps) and radii in
         * [2^-380, 2^340] keep it within [2^-880, 2^882]. A plate thinner
         * than that, at the scale of 1, keeps the test (the point along its
         * thin axis underflows: test_shapes, ellipsoid plates). */
        double smallest = r.x < r.y ? r.x : r.y;
        if (r.z < smallest) smallest = r.z;
        if (!(smallest >= 0x1p-380 && *max <= 0x1p340)) return 0;
        *l1 *= 1.0 + 0x1p-40;
        *max *= 1.0 + 0x1p-40;
        return 1;
    }
    if (fn == agjk__box_support) /* every support point a corner: these norms exactly */
        return extents(((const agjk_box *)data)->half_extents, 1, l1, max);
    if (fn == agjk__segment_support) {
        double h = ((const agjk_capsule *)data)->half_height;
        if (!(h >= 0.0 && h <= AGJK_MAX_COORDINATE)) return 0;
        *l1 = *max = h;
        return 1;
    }
#else
    (void)fn;
    (void)data;
    (void)l1;
    (void)max;
#endif
    return 0;
}

void agjk__minkowski_bound_points_from_data(agjk__minkowski *md) {
    double l1_a, max_a, l1_b, max_b;
    if (!point_bounds(md->support_a, md->data_a, &l1_a, &max_a) ||
        !point_bounds(md->support_b, md->data_b, &l1_b, &max_b) || !(l1_a + l1_b <= md->raw_limit))
        return;
    if (max_a + max_b > md->magnitude) agjk__minkowski_grow(md, max_a + max_b);
    md->bounded = agjk__is_ellipsoid(md->support_b) ? AGJK__BOUNDED_ELLIPSOID_B : AGJK__BOUNDED;
}

/* Multiplies everything md holds in solver units by f (a power of two). */
static void apply_factor(agjk__minkowski *md, double f) {
    md->scale *= f;
    md->translation = v3_scale(md->translation, f);
    md->translation_size *= f;
    md->margin_a *= f;
    md->margin_b *= f;
    md->margin *= f;
    md->noise_floor *= f;
    agjk__minkowski_grow(md, md->magnitude * f);
    agjk__minkowski_set_limits(md);
}

/* 2^-floor(log2(size)), clamped to [2^-1000, 2^1000] so that the factor and
 * its inverse stay finite; by exponent arithmetic (pow2_inverse_floor), which
 * is 0 only beyond the clamp (size denormal, or at least 2^1023). */
static double unit_factor(double size) {
    double f = pow2_inverse_floor(size);
    if (f == 0.0) return size < 1.0 ? 0x1p1000 : 0x1p-1000;
    return f > 0x1p1000 ? 0x1p1000 : (f < 0x1p-1000 ? 0x1p-1000 : f);
}

double agjk__minkowski_rescale_extreme(agjk__minkowski *md, double size) {
    double f = unit_factor(size);
    apply_factor(md, f);
    return f;
}

static void shrink(agjk__minkowski *md, double raw) {
    double f = unit_factor(raw * md->scale); /* < 1 */
    apply_factor(md, f);
    md->rescaled *= f;
}

agjk_vec3 agjk__minkowski_rescue_direction(const agjk__minkowski *md, agjk_vec3 d) {
    (void)md;
    double dm = v3_maxabs(d);
    return dm > 0.0 && dm <= DBL_MAX ? v3_scale_to_unit(d, dm) : d;
}

void agjk__minkowski_points_slow(agjk__minkowski *md, agjk_vec3 *pa, agjk_vec3 *pb) {
    double l1 = v3_norm1(*pa) + v3_norm1(*pb);
    if (!(l1 <= md->point_limit)) {
        if (!v3_in_range(*pa) || !v3_in_range(*pb)) {
            md->bad_support = 1;
            *pa = v3(0.0, 0.0, 0.0);
            *pb = v3(0.0, 0.0, 0.0);
            return; /* the magnitude is at least 0 already */
        }
        /* A support point far larger than the size the scale was chosen for
         * (a first support at a denormal vertex, say) would overflow: lower
         * the scale; the solver follows (md->rescaled). */
        double raw = v3_maxabs(*pa) + v3_maxabs(*pb);
        if (raw * md->scale > AGJK__SOLVER_SIZE_LIMIT) shrink(md, raw);
    }
    double raw = v3_maxabs(*pa) + v3_maxabs(*pb);
    if (md->scale != 1.0) {
        *pa = v3_scale(*pa, md->scale); /* exact: a power of two */
        *pb = v3_scale(*pb, md->scale);
        raw *= md->scale;
    }
    if (raw > md->magnitude) agjk__minkowski_grow(md, raw);
}
