/* SPDX-License-Identifier: MIT */
/* Internal: the support function of the Minkowski difference D = A - B,
 * expressed in the local frame of A (GJK88; Montaut et al. 2022, eq. 8). */
#ifndef AGJK_SRC_MINKOWSKI_H
#define AGJK_SRC_MINKOWSKI_H

#include "shape_points.h"
#include "vec3.h"

/* One point of D with the points of A and B it came from (both in A's frame). */
typedef struct agjk__vertex {
    agjk_vec3 w; /* a - b */
    agjk_vec3 a;
    agjk_vec3 b;
} agjk__vertex;

typedef struct agjk__minkowski {
    agjk_support_fn support_a, support_b;
    const void *data_a, *data_b;
    double rotation[3][3]; /* B's local frame -> A's frame: R_A^T R_B */
    /* Everything below is in solver units: the caller's lengths times `scale`,
     * a power of two chosen so that the problem has about unit size (see
     * agjk__minkowski_set_scale). For problems of ordinary size scale is 1. */
    double scale;
    agjk_vec3 translation; /* B's origin in A's frame: R_A^T (t_B - t_A) */
    double translation_size; /* max |translation_i| */
    double margin_a, margin_b;
    double margin;         /* margin_a + margin_b */
    int hint_a, hint_b;
    int bad_support;       /* a callback returned a non-finite or out-of-range point */
    /* Largest |a| + |b| (max norms) seen, and the floating-point error scale of
     * a computed point of D that follows from it: noise = 4 eps (magnitude +
     * translation_size). Updated only when a support point is larger. */
    double magnitude;
    double noise;
    /* A lower bound on noise set by a warm start whose cached points lie
     * farther from the shapes than the rounding of fresh ones (cache.c). */
    double noise_floor;
    /* The common path of agjk__minkowski_support needs no rescue when the raw
     * support points' 1-norms add up to at most raw_limit (caller's units) and the
     * direction's max |d_i| lies in [direction_min, AGJK__DIRECTION_MAX].
     * point_limit is that bound for the current scale; raw_limit equals it at
     * scale 1 and is -1 otherwise, so that the common path never multiplies
     * by the scale (agjk__minkowski_points_slow does). */
    double raw_limit;
    double point_limit;
    /* Set by agjk__minkowski_bound_points when both shapes are built-ins
     * whose data bound every support point within raw_limit: the support
     * path then checks nothing (see there). AGJK__BOUNDED_ELLIPSOID_B when B
     * is an ellipsoid, whose point the solver's loop then forms in A's frame
     * directly (agjk__minkowski_support). Cleared by any change of scale. */
    int bounded;
    double direction_min;
    /* 4 direction_min^2: a direction whose computed squared norm lies in
     * [direction_floor2, AGJK__DIRECTION_NORM2_MAX] has max |d_i| in
     * [direction_min, AGJK__DIRECTION_MAX] (see agjk__minkowski_support). */
    double direction_floor2;
    /* Product of the factors agjk__minkowski_shrink applied since the solver
     * last looked; the solver multiplies its own state by it and resets it. */
    double rescaled;
    /* Where a support callback writes its point (agjk__shape_support). */
    agjk_vec3 callback_point;
} agjk__minkowski;

/* Values of md->bounded besides 0. */
#define AGJK__BOUNDED 1
#define AGJK__BOUNDED_ELLIPSOID_B 2

/* Values of the support path's `direct`: every support through the shape's
 * pointer, the simplest built-in shapes' points computed in place, and the
 * latter with B's ellipsoid point formed in A's frame (the solver's loop). */
#define AGJK__SUPPORT_CALL 0
#define AGJK__SUPPORT_DIRECT 1
#define AGJK__SUPPORT_DIRECT_LOOP 2
/* AGJK__SUPPORT_DIRECT for a cold query's first support: given B's
 * direction, B's ellipsoid point is formed in A's frame as in the loop (see
 * agjk__minkowski_support). */
#define AGJK__SUPPORT_DIRECT_FIRST 3
/* Through the shapes' pointers, as AGJK__SUPPORT_CALL, but two polytopes'
 * climbs taken in turns (agjk__polytope_pair_support): the solver's rare
 * supports (momentum switch-off, final certification), out of line. */
#define AGJK__SUPPORT_CALL_PAIRED 4

/* Solver units keep support points below this (2^100): sixth powers stay finite. */
#define AGJK__SOLVER_SIZE_LIMIT 0x1p100
/* Directions handed to callbacks keep max |d_i| in [2^-60, 2^100] (or [1, 2^100]
 * while the problem's size is unknown or tiny): products with support
 * coordinates then neither underflow nor overflow. */
#define AGJK__DIRECTION_MIN 0x1p-60
#define AGJK__DIRECTION_MAX 0x1p100
/* (AGJK__DIRECTION_MAX / 2)^2: a squared norm up to this keeps every |d_i|
 * below AGJK__DIRECTION_MAX, rounding included. */
#define AGJK__DIRECTION_NORM2_MAX 0x1p198

/* Chooses the power of two that brings the problem (support points seen so far,
 * B's offset, margins) to unit size and converts md to it. Scaling by a power
 * of two is exact, so answers are equivariant bit for bit, while squares and
 * volumes of the simplex math neither underflow (a 1e-300 problem) nor
 * overflow. Returns the factor applied (1 for problems of ordinary size). */
static inline double agjk__minkowski_set_scale(agjk__minkowski *md); /* below */
/* Its rare part, out of line: converts md to the power of two that brings
 * `size` (outside [2^-100, 2^100]) to about 1. */
double agjk__minkowski_rescale_extreme(agjk__minkowski *md, double size);

/* The rare paths of agjk__minkowski_support, out of line: a direction outside
 * the safe range is brought to unit size; raw support points beyond
 * point_limit are either rejected (non-finite or beyond AGJK_MAX_COORDINATE:
 * bad_support, both points then zero) or make the scale shrink
 * (md->rescaled records the factor); then (any point past raw_limit comes
 * here, so every one when the scale is not 1) the points are brought to
 * solver units and the magnitude grows to their max norms if larger. */
agjk_vec3 agjk__minkowski_rescue_direction(const agjk__minkowski *md, agjk_vec3 d);
void agjk__minkowski_points_slow(agjk__minkowski *md, agjk_vec3 *pa, agjk_vec3 *pb);

/* The part of agjk__minkowski_bound_points (below) that reads the shapes'
 * data, for pairs with an ellipsoid (minkowski.c). */
void agjk__minkowski_bound_points_from_data(agjk__minkowski *md);

/* Directions handed to callbacks keep max |d_i| >= dmin from now on: records
 * it with 4 dmin^2, its test on a squared norm (agjk__minkowski_support). */
static inline void agjk__minkowski_set_direction_min(agjk__minkowski *md, double dmin) {
    md->direction_min = dmin;
    md->direction_floor2 = 4.0 * dmin * dmin;
}

/* Whether a direction's computed squared norm d2 puts it in the support
 * path's safe range (max |d_i| in [direction_min, AGJK__DIRECTION_MAX]);
 * false for 0, NaN and Inf too. */
static inline int agjk__minkowski_direction_safe(const agjk__minkowski *md, double d2) {
    return d2 >= md->direction_floor2 && d2 <= AGJK__DIRECTION_NORM2_MAX;
}

static inline double agjk__minkowski_set_scale(agjk__minkowski *md) {
    double size = md->magnitude;
    if (md->translation_size > size) size = md->translation_size;
    if (md->margin > size) size = md->margin;
    /* The scale is 1 here, or below 1 after a shrink by the first support
     * (which set raw_limit already): either way directions may now be as
     * small as AGJK__DIRECTION_MIN. */
    agjk__minkowski_set_direction_min(md, AGJK__DIRECTION_MIN);
    /* Problems of ordinary size stay in the caller's units (no cost, and power-
     * of-two scalings commute with rounding anyway); only extreme ones move. */
    if (!(size > 0.0) || (size >= 0x1p-100 && size <= 0x1p100)) return 1.0;
    return agjk__minkowski_rescale_extreme(md, size);
}

/* Records a larger magnitude (solver units) and the noise that follows. */
static inline void agjk__minkowski_grow(agjk__minkowski *md, double magnitude) {
    md->magnitude = magnitude;
    double noise = 4.0 * DBL_EPSILON * (magnitude + md->translation_size);
    md->noise = noise > md->noise_floor ? noise : md->noise_floor;
}

/* Limits of the common support path for the current scale (see agjk__minkowski). */
static inline void agjk__minkowski_set_limits(agjk__minkowski *md) {
    double limit = AGJK__SOLVER_SIZE_LIMIT / md->scale;
    md->point_limit = limit < AGJK_MAX_COORDINATE ? limit : AGJK_MAX_COORDINATE;
    md->raw_limit = md->scale == 1.0 ? md->point_limit : -1.0;
    md->bounded = 0;
    /* A tiny problem (scale > 1) needs unit-size directions: a small direction
     * times its tiny coordinates would underflow and lose the sign. */
    agjk__minkowski_set_direction_min(md, md->scale > 1.0 ? 1.0 : AGJK__DIRECTION_MIN);
}

/* The smallest positive length in the caller's units (the least subnormal),
 * in solver units: a lower bound on a distance must exceed a few of these to
 * stay positive once scaled back (a problem 1e-312 across, scaled up by the
 * largest factor, 2^1000, is still 1e-11 in solver units). Below a scale of
 * 2^52 the rounding allowance of any problem (4 eps of its size, at least
 * 2^-102 in the caller's units) dwarfs it: 0 then. No subnormal is formed on
 * the way (as operand or result, one costs a hundred cycles on x86: it took
 * a warm box query from 140 to 300 ns). Built from the scale's exponent bits
 * (a power of two), with no floating-point arithmetic at all: a compiler may
 * evaluate both arms of a conditional without a branch, and clang 14 did,
 * forming 2^-1074 and multiplying it in every query and every gap test
 * (clang-built close box queries took 420 ns instead of 252); an integer
 * select forms no subnormal whatever it evaluates
 * (tests/core/test_subnormals.c). */
static inline double agjk__minkowski_caller_granule(const agjk__minkowski *md) {
    uint64_t bits;
    memcpy(&bits, &md->scale, sizeof bits);
    /* scale = 2^e: the granule 2^(e - 1074) has the biased exponent
     * (e + 1023) - 1074, a normal number when that is positive. */
    int64_t biased = (int64_t)((bits >> 52) & 0x7ff) - 1074;
    bits = biased > 0 ? (uint64_t)biased << 52 : 0;
    double granule;
    memcpy(&granule, &bits, sizeof granule);
    return granule;
}

/* What a certified lower bound on the distance (solver units, rounding taken
 * off) must exceed to prove the shapes apart: the margins, plus a few caller
 * granules so that it stays positive in the caller's units. */
static inline double agjk__minkowski_separation_level(const agjk__minkowski *md) {
    return md->margin + 4.0 * agjk__minkowski_caller_granule(md);
}

/* Direct support of the simplest built-in shapes: the call through the
 * pointer, with the direction and the point passed through memory, took
 * 3-5% of a query's time on boxes and ellipsoids. Their callbacks are referenced
 * weakly: a program that never creates such a shape links none of its code,
 * the reference is then null, and no callback ever matches it. Where weak
 * references are not available (non-ELF targets), every support goes
 * through the pointer, with the same answers. */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__ELF__)
#define AGJK__DIRECT_SUPPORT 1
__attribute__((weak)) void agjk__point_support(const void *, const agjk_vec3 *, agjk_vec3 *, int *);
__attribute__((weak)) void agjk__box_support(const void *, const agjk_vec3 *, agjk_vec3 *, int *);
__attribute__((weak)) void agjk__segment_support(const void *, const agjk_vec3 *, agjk_vec3 *,
                                                 int *);
__attribute__((weak)) void agjk__ellipsoid_support(const void *, const agjk_vec3 *, agjk_vec3 *,
                                                   int *);
__attribute__((weak)) void agjk__polytope_support(const void *, const agjk_vec3 *, agjk_vec3 *,
                                                  int *);
__attribute__((weak)) void agjk__polytope_pair_support(const void *, const agjk_vec3 *,
                                                       agjk_vec3 *, int *, const void *,
                                                       const agjk_vec3 *, agjk_vec3 *, int *);
__attribute__((weak)) void agjk__prepared_polytope_support(const void *, const agjk_vec3 *,
                                                           agjk_vec3 *, int *);
__attribute__((weak)) void agjk__prepared_polytope_pair_support(const void *, const agjk_vec3 *,
                                                                agjk_vec3 *, int *, const void *,
                                                                const agjk_vec3 *, agjk_vec3 *,
                                                                int *, int);
#else
#define AGJK__DIRECT_SUPPORT 0
#endif

/* fn(data, &d, &point, hint), computed in place when `direct` (a constant:
 * the hot call sites; the rare ones keep one call, and the code small) and
 * fn is a built-in one. Returned by value, and the callback given this
 * function's own copy of d and md->callback_point to write: no address of
 * the caller's point or direction is ever taken, so that they stay in
 * registers on the inline paths (with `out` the caller's own point, clang
 * kept it on the stack on every path: clang-built close box queries took
 * 250 ns instead of 222; gcc's support path 217 instructions per call on
 * ellipsoids instead of 185). */
static AGJK__ALWAYS_INLINE agjk_vec3 agjk__shape_support(agjk__minkowski *md, agjk_support_fn fn,
                                                         const void *data, agjk_vec3 d, int *hint,
                                                         int direct) {
#if AGJK__DIRECT_SUPPORT
    if (!direct || direct == AGJK__SUPPORT_CALL_PAIRED) {
        /* (the call below) */
    } else if (fn == agjk__box_support) {
        return agjk__box_point((const agjk_box *)data, d);
    } else if (fn == agjk__ellipsoid_support) {
        if (direct == AGJK__SUPPORT_DIRECT_LOOP && md->bounded) {
            /* (in range: agjk__minkowski_bound_points_from_data) */
            agjk_vec3 q;
            double inv;
            agjk__ellipsoid_unnormalized_in_range((const agjk_ellipsoid *)data, d, &q, &inv);
            return v3_scale(q, inv);
        }
        agjk_vec3 p;
        if (agjk__ellipsoid_point((const agjk_ellipsoid *)data, d, &p)) return p;
    } else if (fn == agjk__point_support) {
        return v3(0.0, 0.0, 0.0);
    } else if (fn == agjk__segment_support) {
        return agjk__segment_point((const agjk_capsule *)data, d);
    }
#else
    (void)direct;
#endif
    fn(data, &d, &md->callback_point, hint);
    return md->callback_point;
}

/* A box, a capsule's segment or a point: every support point has the same
 * 1-norm and max norm, whatever the direction. */
static inline int agjk__constant_norms(agjk_support_fn fn) {
#if AGJK__DIRECT_SUPPORT
    return fn == agjk__box_support || fn == agjk__point_support || fn == agjk__segment_support;
#else
    (void)fn;
    return 0;
#endif
}

static inline int agjk__is_box(agjk_support_fn fn) {
#if AGJK__DIRECT_SUPPORT
    return fn == agjk__box_support;
#else
    (void)fn;
    return 0;
#endif
}

static inline int agjk__is_ellipsoid(agjk_support_fn fn) {
#if AGJK__DIRECT_SUPPORT
    return fn == agjk__ellipsoid_support;
#else
    (void)fn;
    return 0;
#endif
}

/* After the first support has come back good and set the scale, for the
 * rest of the query: sets md->bounded when the scale is 1 and both shapes
 * are built-ins whose every support point is known to pass the support
 * path's tests, which are then skipped. For boxes, segments and points that
 * is known from the first support already, since every later one has the
 * same norms (and the magnitude stays where it is); with an ellipsoid it
 * takes the shapes' data, which also raise the magnitude to the bound they
 * give (agjk__minkowski_bound_points_from_data). */
static inline void agjk__minkowski_bound_points(agjk__minkowski *md) {
    if (md->scale != 1.0 || md->bad_support) return;
    int constant_a = agjk__constant_norms(md->support_a);
    int constant_b = agjk__constant_norms(md->support_b);
    if (constant_a && constant_b)
        md->bounded = AGJK__BOUNDED;
    else if ((constant_a || agjk__is_ellipsoid(md->support_a)) &&
             (constant_b || agjk__is_ellipsoid(md->support_b)))
        agjk__minkowski_bound_points_from_data(md);
}

/* s = argmin_{s in D} <d, s> = S_A(-d) - S_B(d) (paper eq. 7-8), d in A's frame,
 * non-zero and finite, with the points of A and B it came from. d2 is
 * v3_norm2(d) when the caller has it at hand (the solver's iterate), else 0;
 * db_given R^T d, B's direction, when the caller has it (the projection
 * turns a face's foot into B's frame alongside it: agjk__projection_notes),
 * else NULL; direct is one of AGJK__SUPPORT_* (a constant at each call
 * site); root_a and root_b, for AGJK__SUPPORT_DIRECT_FIRST with two
 * ellipsoids and B's direction given, ||D_A d|| and ||D_B d_B|| when the
 * caller has them (agjk__start_apart), else 0. slot: where the solver puts
 * its next simplex vertex (NULL: nowhere). The bounded path of an ellipsoid
 * B in the loop writes out->w there too, from the registers that formed
 * it, and returns 1 (else 0, slot untouched): copied from *out by the
 * solver after the path's exits had joined, the point went through memory
 * twice on GJK's chain of dependent steps (close and overlapping ellipsoids
 * 1-2% faster). Written on the other paths too, it made box, hull and mesh
 * queries 1-4% slower. */
static AGJK__ALWAYS_INLINE int agjk__minkowski_support(agjk__minkowski *md, agjk_vec3 d,
                                                        double d2, agjk__vertex *out,
                                                        int direct, const agjk_vec3 *db_given,
                                                        double root_a, double root_b,
                                                        agjk_vec3 *slot) {
    /* The direction's range, from d2 when it settles it: the computed
     * squared norm is within 3 eps of |d|^2 (far from underflow), so
     * d2 >= 4 dmin^2 gives max |d_i| >= |d| / sqrt(3) > dmin, and
     * d2 <= 2^198 gives max |d_i| <= |d| < 2^100. Otherwise (d2 = 0 when
     * unknown, or outside) the test on max |d_i| itself decides, as it
     * always did: the rescue runs exactly when it did. */
    if (!agjk__minkowski_direction_safe(md, d2)) {
        double dm = v3_maxabs(d);
        if (!(dm >= md->direction_min && dm <= AGJK__DIRECTION_MAX)) {
            d = agjk__minkowski_rescue_direction(md, d);
            /* (for the direction before its rescue; a first support's
             * unit-size direction never needs one) */
            db_given = NULL;
            root_a = root_b = 0.0;
        }
    }
    agjk_vec3 na = v3_neg(d);
    /* (The first support's is the caller's local: a plain load, which the
     * compiler keeps in registers.) */
    agjk_vec3 db = !db_given ? m3_tmul(&md->rotation[0][0], d)
                   : direct == AGJK__SUPPORT_DIRECT_FIRST ? *db_given
                                                         : v3_load_scalars(db_given);
    agjk_vec3 pa, pb, pair_b = v3(0.0, 0.0, 0.0);
    int paired = 0;
#if AGJK__DIRECT_SUPPORT
    /* Two polytopes, both plain or both prepared: both supports in one
     * call, two climbs taken in turns (agjk__polytope_pair_support; through
     * copies, as below). Hulls of
     * 141 points: one-support Boolean queries 133 -> 114 ns, close pairs
     * 600 -> 540, overlapping 612 -> 523. */
    if (direct &&
        (md->support_a == agjk__polytope_support ||
         md->support_a == agjk__prepared_polytope_support) &&
        md->support_b == md->support_a) {
        agjk_vec3 da = na, dbc = db, qa, qb;
        if (md->support_a == agjk__polytope_support)
            agjk__polytope_pair_support(md->data_a, &da, &qa, &md->hint_a, md->data_b, &dbc, &qb,
                                        &md->hint_b);
        else
            agjk__prepared_polytope_pair_support(md->data_a, &da, &qa, &md->hint_a, md->data_b,
                                                 &dbc, &qb, &md->hint_b,
                                                 direct == AGJK__SUPPORT_DIRECT_FIRST);
        pa = qa;
        pair_b = qb;
        paired = 1;
    } else if (direct == AGJK__SUPPORT_DIRECT_FIRST && root_a > 0.0) {
        agjk_vec3 qa;
        double inv_a;
        agjk__ellipsoid_from_root((const agjk_ellipsoid *)md->data_a, na, root_a, &qa, &inv_a);
        pa = v3_scale(qa, inv_a);
    } else
#endif
        pa = agjk__shape_support(md, md->support_a, md->data_a, na, &md->hint_a, direct);
#if AGJK__DIRECT_SUPPORT
    /* B an ellipsoid, in the solver's loop: its point in A's frame,
     * R D^2 d_B / ||D d_B|| + t, is formed as (R q) inv + t with q = D^2 d_B
     * and inv = 1 / ||D d_B||. R q is computed while the square root and the
     * division run, so that a multiplication and two additions follow them
     * where the point's scaling and then its rotation did: B's path is the
     * longer of the two in GJK's chain of dependent steps (each cycle taken
     * from it shows in a close ellipsoid query's time; 8 cycles more on A's
     * show barely), and this makes close ellipsoid queries 2.5% faster. The
     * same rounding error (a few ulps of each product), other bits. Checked
     * before B's dispatch and stored b first: other arrangements made the
     * loop compile worse for every other pair (close boxes 3-12% slower). */
    if (direct == AGJK__SUPPORT_DIRECT_LOOP && md->bounded == AGJK__BOUNDED_ELLIPSOID_B) {
        agjk_vec3 q;
        double inv;
        agjk__ellipsoid_unnormalized_in_range((const agjk_ellipsoid *)md->data_b, db, &q, &inv);
        agjk_vec3 b = v3_add(v3_scale(m3_mul(&md->rotation[0][0], q), inv), md->translation);
        agjk_vec3 w = v3_sub(pa, b);
        out->b = b;
        out->a = pa;
        out->w = w;
        if (!slot) return 0;
        *slot = w;
        return 1;
    }
#endif
    agjk_vec3 q_first = v3(0.0, 0.0, 0.0);
    double inv_first = 0.0;
    int fused = 0;
    /* B's ellipsoid point in A's frame for a cold query's first support too
     * (B's direction given, from the world offset: agjk__solve_input.x0_b),
     * whose points are not bounded yet: pb is formed for the tests below,
     * which decide as they always did, and b, on the chain to a Boolean
     * query's plane test, is not formed from it. One-support Boolean queries
     * on ellipsoids: 70 -> 62 ns, with the direction's unit factor and B's
     * turn taken from the world offset. */
#if AGJK__DIRECT_SUPPORT
    if (paired) {
        pb = pair_b;
    } else if (direct == AGJK__SUPPORT_DIRECT_FIRST && root_b > 0.0) {
        agjk__ellipsoid_from_root((const agjk_ellipsoid *)md->data_b, db, root_b, &q_first,
                                  &inv_first);
        pb = v3_scale(q_first, inv_first);
        fused = 1;
    } else if (direct == AGJK__SUPPORT_DIRECT_FIRST && db_given &&
        md->support_b == agjk__ellipsoid_support &&
        agjk__ellipsoid_unnormalized((const agjk_ellipsoid *)md->data_b, db, &q_first,
                                     &inv_first)) {
        pb = v3_scale(q_first, inv_first);
        fused = 1;
    } else
#endif
        pb = agjk__shape_support(md, md->support_b, md->data_b, db, &md->hint_b, direct);
    if (!md->bounded) {
        /* One test covers NaN, Inf, AGJK_MAX_COORDINATE, the solver's size
         * limit and a scale other than 1: the 1-norm propagates NaN and
         * bounds every coordinate. */
        double l1 = v3_norm1(pa) + v3_norm1(pb);
        if (l1 <= md->raw_limit) {
            /* The magnitude: the largest sum of max norms. (Taking the max
             * norms only when l1 exceeds the magnitude, which bounds them,
             * filtered almost nothing: the 1-norm of a support point is well
             * above its max norm, and the test cost more than it saved.) */
            /* (max_i |q_i inv| is max_i |q_i| times inv, bit for bit:
             * rounding is monotonic. Taken so, it runs with the square
             * root: the plane test waits for the noise that follows.) */
            double raw = v3_maxabs(pa) + (fused ? v3_maxabs(q_first) * inv_first : v3_maxabs(pb));
            if (raw > md->magnitude) agjk__minkowski_grow(md, raw);
        } else {
            /* (Through copies: pa and pb themselves never have their
             * address taken, so that they stay in registers.) */
            agjk_vec3 qa = pa, qb = pb;
            agjk__minkowski_points_slow(md, &qa, &qb);
            pa = qa;
            pb = qb;
            fused = 0;
        }
    }
    agjk_vec3 b = fused ? v3_add(v3_scale(m3_mul(&md->rotation[0][0], q_first), inv_first),
                                 md->translation)
                        : v3_add(m3_mul(&md->rotation[0][0], pb), md->translation);
    out->w = v3_sub(pa, b);
    out->a = pa;
    out->b = b;
    return 0;
}

/* Alg. 2: the plane of normal d through s separates D (inflated by the margins)
 * from the origin when <d, s> > ||d|| (margin + rounding): squared, with no
 * square root, when d has a safe size (the support path keeps directions in
 * [2^-60, 2^100], so this is the common case). The size is told by the
 * squared norm the test needs anyway: |d|^2 in [2^-118, 2^198] puts
 * max |d_i| in [2^-60, 2^99] (|d| / sqrt(3) <= max |d_i| <= |d|), where
 * max |d_i| itself took three absolute values and two comparisons more at
 * every iteration of a Boolean query. */
static inline int agjk__minkowski_separates(const agjk__minkowski *md, agjk_vec3 d,
                                            agjk_vec3 w) {
    double r = md->margin + md->noise;
    double n2 = v3_norm2(d);
    if (n2 >= 0x1p-118 && n2 <= 0x1p198) {
        double dw = v3_dot(d, w);
        return dw > 0.0 && dw * dw > n2 * r * r;
    }
    /* The unit direction, as the support function saw it: a denormal d has
     * too few significant bits for <d, w> to mean anything. */
    return v3_dot(v3_normalize(d), w) > r;
}

#endif
