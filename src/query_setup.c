/* SPDX-License-Identifier: MIT */
/* Argument checks and solver setup shared by the public queries. The poses'
 * validation and B's pose relative to A's are here, with their one caller:
 * the relative transform then compiles inline into it (its call and the
 * stores around it took 4% of a one-support Boolean query on boxes). */
#include "agjk/query.h"
#include "query_setup.h"

static int shape_is_valid(const agjk_shape *shape) {
    return shape && shape->support && shape->margin >= 0.0 && shape->margin <= AGJK_MAX_COORDINATE;
}

/* How far from orthonormal a rotation may be: enough for a float-converted or
 * quaternion-built matrix, far too little to hide a scale or shear. */
#define ROTATION_TOLERANCE 1e-6

/* Rotations orthonormal to rounding (a double-precision quaternion's matrix
 * is within a few ulps): their transposes are their inverses to a few tens
 * of ulps, so that B's direction may be turned from the world offset by
 * R_B^T alone rather than by R^T after R_A^T (agjk__solve_input.x0_b). */
#define RIGID_TOLERANCE (16.0 * DBL_EPSILON)

/* A pose's deviations from a rotation: rows x and y of R orthonormal, and
 * z = x cross y (which makes z orthonormal to both and det R = +1, where a
 * reflection, det -1, would turn the shapes inside out). Cheaper than the six
 * entries of R R^T and the determinant (27 floating-point operations against
 * 44, twice per query), and as strict: within 1e-6 per entry, z is within
 * about 1e-6 of a unit vector orthogonal to x and y. */
typedef struct {
    double xx, yy, xy; /* |x|^2 - 1, |y|^2 - 1, <x, y> */
    agjk_vec3 e;       /* x cross y - z */
} pose_deviation;

static AGJK__ALWAYS_INLINE pose_deviation deviation_of(const agjk_pose *pose) {
    const double *r = &pose->rotation[0][0]; /* row-major, r[3 * row + column] */
    agjk_vec3 x = v3(r[0], r[1], r[2]), y = v3(r[3], r[4], r[5]), z = v3(r[6], r[7], r[8]);
    pose_deviation d;
    d.xx = v3_dot(x, x) - 1.0;
    d.yy = v3_dot(y, y) - 1.0;
    d.xy = v3_dot(x, y);
    d.e = v3_sub(v3_cross(x, y), z);
    return d;
}

/* The documented test, entry by entry: translation in range, every
 * deviation within 1e-6. */
static AGJK__NOINLINE AGJK__COLD int pose_is_valid(const agjk_pose *pose) {
    pose_deviation d = deviation_of(pose);
    return v3_in_range(pose->translation) && fabs(d.xx) <= ROTATION_TOLERANCE &&
           fabs(d.yy) <= ROTATION_TOLERANCE && fabs(d.xy) <= ROTATION_TOLERANCE &&
           fabs(d.e.x) <= ROTATION_TOLERANCE && fabs(d.e.y) <= ROTATION_TOLERANCE &&
           fabs(d.e.z) <= ROTATION_TOLERANCE;
}

/* The sum of the squared deviations of both poses. */
#if defined(__GNUC__)
/* Side by side, pose A in lane 0 and B in lane 1 of the GNU vector extension
 * (gcc and clang; SSE2 on x86-64): half the arithmetic instructions. Each
 * lane computes what deviation_of does. */
typedef double pose_pair __attribute__((vector_size(16)));

static AGJK__ALWAYS_INLINE double squared_deviations(const agjk_pose *pose_a,
                                                     const agjk_pose *pose_b) {
    const double *ra = &pose_a->rotation[0][0], *rb = &pose_b->rotation[0][0];
    pose_pair x0 = {ra[0], rb[0]}, x1 = {ra[1], rb[1]}, x2 = {ra[2], rb[2]};
    pose_pair y0 = {ra[3], rb[3]}, y1 = {ra[4], rb[4]}, y2 = {ra[5], rb[5]};
    pose_pair z0 = {ra[6], rb[6]}, z1 = {ra[7], rb[7]}, z2 = {ra[8], rb[8]};
    pose_pair one = {1.0, 1.0};
    pose_pair xx = x0 * x0 + x1 * x1 + x2 * x2 - one;
    pose_pair yy = y0 * y0 + y1 * y1 + y2 * y2 - one;
    pose_pair xy = x0 * y0 + x1 * y1 + x2 * y2;
    pose_pair e0 = x1 * y2 - x2 * y1 - z0;
    pose_pair e1 = x2 * y0 - x0 * y2 - z1;
    pose_pair e2 = x0 * y1 - x1 * y0 - z2;
    pose_pair sum = xx * xx + yy * yy + xy * xy + (e0 * e0 + e1 * e1 + e2 * e2);
    return sum[0] + sum[1];
}
#else
static double squared_deviation(pose_deviation d) {
    return d.xx * d.xx + d.yy * d.yy + d.xy * d.xy + v3_norm2(d.e);
}

static double squared_deviations(const agjk_pose *pose_a, const agjk_pose *pose_b) {
    return squared_deviation(deviation_of(pose_a)) + squared_deviation(deviation_of(pose_b));
}
#endif

/* poses_are_valid's answers besides 0: valid, and valid with both
 * rotations within RIGID_TOLERANCE of orthonormal. */
#define POSES_VALID 1
#define POSES_RIGID 2

/* Both poses, non-null. The usual pair passes at once: the twelve
 * deviations' squares summing to at most the tolerance squared bound each
 * of them, and the translations' 1-norms summing to at most the range bound
 * every entry (one comparison each, where NaN and Inf fail too). Otherwise the
 * documented test decides, pose by pose: the same verdicts. One call for
 * both, out of line: inline, the query's set-up compiled worse (one-support
 * Boolean queries on boxes: 36.0 ns against 33.3 out of line, 35.8 with
 * the poses taken one after the other). */
static AGJK__NOINLINE int poses_are_valid(const agjk_pose *pose_a, const agjk_pose *pose_b) {
    double sum = squared_deviations(pose_a, pose_b);
    double reach = v3_norm1(pose_a->translation) + v3_norm1(pose_b->translation);
    if ((sum <= ROTATION_TOLERANCE * ROTATION_TOLERANCE) & (reach <= AGJK_MAX_COORDINATE))
        return sum <= RIGID_TOLERANCE * RIGID_TOLERANCE ? POSES_RIGID : POSES_VALID;
    return pose_is_valid(pose_a) && pose_is_valid(pose_b) ? POSES_VALID : 0;
}

/* x0 = R_A^T (t_A - t_B) has the world offset's 2-norm, to the rounding
 * of an orthonormal R_A, so max |x0_i| lies within sqrt(3) of the offset's
 * max |t_i| = m: twice the power of two that brings m to [1, 2) brings x0
 * to [1, 8) (agjk__solve_input.x0_unit), from m's exponent bits. 0 for
 * offsets near underflow or overflow, and for concentric frames. */
static double offset_unit(double m) {
    /* pow2_inverse_floor's exponent arithmetic with its range tests folded
     * into this one: through it, distant ellipsoid Boolean queries took
     * 0.6 ns more (62.1 -> 62.7, same runs). */
    uint64_t bits;
    memcpy(&bits, &m, sizeof bits);
    int biased = (int)(bits >> 52); /* m >= 0: exponent e + 1023 */
    if (biased < 1023 - 900 || biased > 1023 + 900) return 0.0;
    bits = (uint64_t)(2047 - biased) << 52; /* 2^(1 - e) */
    double unit;
    memcpy(&unit, &bits, sizeof unit);
    return unit;
}

/* Prepares the relative transform (shapes and poses validated); also returns
 * the world offset t_B - t_A and offset_unit's factor for it. */
static void minkowski_init(agjk__minkowski *md, const agjk_shape *a, const agjk_pose *pose_a,
                           const agjk_shape *b, const agjk_pose *pose_b, int hint_a, int hint_b,
                           agjk_vec3 *offset, double *unit) {
    md->support_a = a->support;
    md->support_b = b->support;
    md->data_a = a->data;
    md->data_b = b->data;
    md->margin_a = a->margin;
    md->margin_b = b->margin;
    md->margin = a->margin + b->margin;
    md->hint_a = hint_a;
    md->hint_b = hint_b;
    md->bad_support = 0;
    md->scale = 1.0;
    md->rescaled = 1.0;
    /* R = R_A^T R_B: entry (i, j) is <column i of R_A, column j of R_B>, so
     * row i of R is sum_k R_A[k][i] (row k of R_B). Written out as rows (the
     * double loop compiled to twice the instructions, a tenth of a distant
     * Boolean query); same sums in the same order. */
    const double *ra = &pose_a->rotation[0][0], *rb = &pose_b->rotation[0][0];
    agjk_vec3 b0 = v3(rb[0], rb[1], rb[2]), b1 = v3(rb[3], rb[4], rb[5]), b2 = v3(rb[6], rb[7], rb[8]);
    /* (The three rows written out too: -O2 keeps a three-pass loop.) */
    agjk_vec3 r0 = v3_add(v3_add(v3_scale(b0, ra[0]), v3_scale(b1, ra[3])), v3_scale(b2, ra[6]));
    agjk_vec3 r1 = v3_add(v3_add(v3_scale(b0, ra[1]), v3_scale(b1, ra[4])), v3_scale(b2, ra[7]));
    agjk_vec3 r2 = v3_add(v3_add(v3_scale(b0, ra[2]), v3_scale(b1, ra[5])), v3_scale(b2, ra[8]));
    md->rotation[0][0] = r0.x;
    md->rotation[0][1] = r0.y;
    md->rotation[0][2] = r0.z;
    md->rotation[1][0] = r1.x;
    md->rotation[1][1] = r1.y;
    md->rotation[1][2] = r1.z;
    md->rotation[2][0] = r2.x;
    md->rotation[2][1] = r2.y;
    md->rotation[2][2] = r2.z;
    /* Stored through a copy, which gcc writes as one 16-byte store of x and y
     * and one of z: the first support reads x and y back with one 16-byte
     * load right after, and from three 8-byte stores (gcc's choice for the
     * plain assignment) the load cannot take its data from the store buffer
     * and waits for the stores to reach the cache: 7 ns of a 63 ns
     * one-support query on ellipsoids, 4 of 50 on boxes. */
    agjk_vec3 delta = v3_sub(pose_b->translation, pose_a->translation);
    *offset = delta;
    *unit = offset_unit(v3_maxabs(delta));
    agjk_vec3 t = m3_tmul(ra, delta);
    double stored[3] = {t.x, t.y, t.z};
    memcpy(&md->translation, stored, sizeof stored);
    md->translation_size = v3_maxabs(md->translation);
    md->noise_floor = 0.0;
    agjk__minkowski_grow(md, 0.0);
    /* The limits of scale 1, except that the problem's size is unknown until
     * the first support: unit-size directions until agjk__minkowski_set_scale
     * has seen it. */
    agjk__minkowski_set_limits(md);
    agjk__minkowski_set_direction_min(md, 1.0);
}

/* Reads the caller's options (or the defaults for NULL) into the solver
 * input and the starting hints, straight from the caller's struct: no copy of
 * it, whatever version of agjk_options the caller compiled against. */
static int read_options(const agjk_options *o, agjk__solve_input *in, int *hint_a, int *hint_b) {
    if (!o) o = &agjk__default_options;
    /* Every field of this version is required (struct_size covers them all):
     * an older, smaller struct would need its missing fields defaulted here. */
    else if (o->struct_size < sizeof(agjk_options)) return 0; /* uninitialised or too old */
    switch (o->method) {
    case AGJK_METHOD_GJK: case AGJK_METHOD_NESTEROV: case AGJK_METHOD_NESTEROV_NORMALIZED:
    case AGJK_METHOD_POLYAK: case AGJK_METHOD_FRANK_WOLFE: case AGJK_METHOD_ADAPTIVE: break;
    default: return 0;
    }
    if (o->tolerance_mode != AGJK_TOLERANCE_ABSOLUTE &&
        o->tolerance_mode != AGJK_TOLERANCE_RELATIVE)
        return 0;
    /* (NaN fails the comparison; the upper limit rejects +Inf.) */
    if (!(o->tolerance > 0.0 && o->tolerance <= DBL_MAX)) return 0;
    if (o->max_iterations < 1) return 0;
    if ((o->compute & ~(uint32_t)AGJK_COMPUTE_WITNESS) != 0) return 0;
    in->x0_given = o->use_initial_direction != 0;
    if (in->x0_given && !v3_isfinite(o->initial_direction)) return 0;
    in->method = o->method;
    in->want_witness = (o->compute & AGJK_COMPUTE_WITNESS) != 0;
    in->relative = o->tolerance_mode == AGJK_TOLERANCE_RELATIVE;
    in->tolerance = o->tolerance;
    in->max_iterations = o->max_iterations;
    in->x0 = o->initial_direction; /* world frame until initial_guess */
    *hint_a = o->hint_a;
    *hint_b = o->hint_b;
    return 1;
}

/* x_0: the caller's guess (in->x0, world frame, when in->x0_given), else
 * c_A - c_B (the frame origins, paper Sec. IV), else any axis when the
 * shapes are concentric (where c_A - c_B = 0 would give no direction at all). */
static agjk_vec3 initial_guess(const agjk__solve_input *in, const agjk_pose *pose_a,
                               const agjk__minkowski *md) {
    agjk_vec3 x0 = v3_neg(md->translation);
    if (in->x0_given) {
        x0 = m3_tmul(&pose_a->rotation[0][0], in->x0);
        /* Only its direction and rough size matter (it seeds the momentum):
         * bring an absurdly tiny or huge guess to unit length. */
        double m = v3_maxabs(x0);
        if (m > AGJK_MAX_COORDINATE || (m > 0.0 && m < 1.0 / AGJK_MAX_COORDINATE))
            x0 = v3_normalize(x0);
    }
    if (v3_maxabs(x0) == 0.0) x0 = v3(1.0, 0.0, 0.0);
    return x0;
}

int agjk__query_prepare(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                        const agjk_pose *pose_b, const agjk_options *options, int boolean_mode,
                        agjk__minkowski *md, agjk__solve_input *in) {
    int hint_a, hint_b, poses = 0;
    if (!read_options(options, in, &hint_a, &hint_b) || !shape_is_valid(a) ||
        !shape_is_valid(b) || !pose_a || !pose_b || !(poses = poses_are_valid(pose_a, pose_b)))
        return 0;
    agjk_vec3 offset;
    double unit;
    minkowski_init(md, a, pose_a, b, pose_b, hint_a, hint_b, &offset, &unit);
    if (!isfinite(md->margin)) return 0;
    in->boolean_mode = boolean_mode;
    in->x0 = initial_guess(in, pose_a, md);
    in->x0_along = 0;
    /* Only a Boolean query's first support is on the chain to its answer: a
     * distance query's takes the general path, and its answers stay what
     * they were bit for bit (warm starts move by their last bits). */
    in->x0_unit = boolean_mode && !in->x0_given ? unit : 0.0;
    /* (Rigid poses only: R_B^T stands for R^T R_A^T there, to rounding.) */
    in->x0_b_given =
        in->x0_unit > 0.0 && poses == POSES_RIGID && agjk__is_ellipsoid(md->support_b);
    if (in->x0_b_given) {
        agjk_vec3 x0_b = m3_tmul(&pose_b->rotation[0][0], v3_neg(offset));
        double stored[3] = {x0_b.x, x0_b.y, x0_b.z}; /* (see md->translation's) */
        memcpy(&in->x0_b, stored, sizeof stored);
    }
    in->keep_points = in->want_witness;
    in->track_flat = 0;
    in->want_simplex = 0;
    in->warm_count = 0;
    return 1;
}

void agjk__core_bounds_of(const agjk__solve_output *out, agjk__core_bounds *b) {
    double x2 = v3_norm2(out->x), core = sqrt(x2);
    double gap = out->gap_valid && out->gap > 0.0 ? out->gap : 0.0;
    /* The rounding of x and of the support points (the relative transform, the
     * combination of simplex vertices): the exact point of D that x stands for
     * lies within this of x, so it widens the interval at both ends. */
    double rounding = 2.0 * out->noise;
    /* Two certified lower bounds on the core distance ||x*||: the support plane,
     * ||x|| - g / (2 ||x||) = <x, s> / ||x||, and ||x|| - sqrt(g) (eq. 13). */
    /* The plane's is the larger one when g <= 4 ||x||^2 (the usual case, g
     * small), so the square root is taken only otherwise. Either bound is
     * certified, so rounding at the switch does not matter. */
    double lower;
    if (core > 0.0 && gap <= 4.0 * core * core)
        lower = core - gap / (2.0 * core);
    else
        lower = core - sqrt(gap);
    b->core = core;
    b->gap = gap;
    b->lower = lower - rounding;
    /* ||x*|| <= ||p|| for p in D: the active set's own point, which x equals to
     * the rounding unless the projection was ill-conditioned. The plane bound
     * above holds whatever x is. */
    /* Within one noise of ||x|| (the usual case, decided in squares), ||x|| +
     * 2 noise covers the member point and its own rounding. */
    double reach = core + out->noise, member2 = v3_norm2(out->x_member);
    b->inexact = member2 > reach * reach;
    b->upper = (b->inexact ? sqrt(member2) : core) + rounding;
    /* From A towards B: v3_normalize(-x), with the square root already
     * taken in its usual range; v3_normalize itself copes with a denormal x
     * (zero stays zero). */
    b->toward_x = x2 >= 0x1p-900 && x2 <= 0x1p900 ? v3_scale(v3_neg(out->x), 1.0 / core)
                                                  : v3_normalize(v3_neg(out->x));
    /* The plane that certified the lower bound: -x, or the support direction
     * the adaptive method stopped on (solver.c). */
    b->normal = v3_maxabs(out->direction) > 0.0 ? v3_normalize(v3_neg(out->direction))
                                                : b->toward_x;
}
