/* SPDX-License-Identifier: MIT */
/* Argument checks and solver setup shared by the public queries. */
#include "agjk/query.h"
#include "query_setup.h"

static int shape_is_valid(const agjk_shape *shape) {
    return shape && shape->support && shape->margin >= 0.0 && shape->margin <= AGJK_MAX_COORDINATE;
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
                        const agjk_pose *pose_b, const agjk_options *options,
                        agjk__minkowski *md, agjk__solve_input *in) {
    int hint_a, hint_b;
    if (!read_options(options, in, &hint_a, &hint_b) || !shape_is_valid(a) ||
        !shape_is_valid(b) || !agjk__pose_is_valid(pose_a) || !agjk__pose_is_valid(pose_b))
        return 0;
    agjk__minkowski_init(md, a, pose_a, b, pose_b, hint_a, hint_b);
    if (!isfinite(md->margin)) return 0;
    in->boolean_mode = 0;
    in->x0 = initial_guess(in, pose_a, md);
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
