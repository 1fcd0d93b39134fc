/* SPDX-License-Identifier: MIT */
/* Public queries: argument checks, the solver run, and the result in world frame. */
#include <string.h>

#include "agjk/query.h"
#include "cache.h"
#include "solver.h"

static int shape_is_valid(const agjk_shape *shape) {
    return shape && shape->support && shape->margin >= 0.0 && shape->margin <= AGJK_MAX_COORDINATE;
}

/* Reads the caller's options, whatever version of agjk_options it compiled
 * against: fields past its struct_size keep their defaults. */
static int read_options(const agjk_options *given, agjk_options *opts) {
    if (!given) {
        agjk_options_init_sized(opts, sizeof *opts);
        return 1;
    }
    /* Every field of this version is required (struct_size covers them all):
     * an older, smaller struct would need its missing fields defaulted here. */
    if (given->struct_size < sizeof(agjk_options)) return 0; /* uninitialised or too old */
    memcpy(opts, given, sizeof *opts);
    opts->struct_size = (uint32_t)sizeof *opts;
    switch (opts->method) {
    case AGJK_METHOD_GJK: case AGJK_METHOD_NESTEROV: case AGJK_METHOD_NESTEROV_NORMALIZED:
    case AGJK_METHOD_POLYAK: case AGJK_METHOD_FRANK_WOLFE: case AGJK_METHOD_ADAPTIVE: break;
    default: return 0;
    }
    if (opts->tolerance_mode != AGJK_TOLERANCE_ABSOLUTE &&
        opts->tolerance_mode != AGJK_TOLERANCE_RELATIVE)
        return 0;
    if (!isfinite(opts->tolerance) || !(opts->tolerance > 0.0)) return 0;
    if (opts->max_iterations < 1) return 0;
    if ((opts->compute & ~(uint32_t)AGJK_COMPUTE_WITNESS) != 0) return 0;
    if (opts->use_initial_direction && !v3_isfinite(opts->initial_direction)) return 0;
    return 1;
}

static agjk_vec3 to_world(const agjk_pose *pose, agjk_vec3 p) {
    return v3_add(m3_mul(&pose->rotation[0][0], p), pose->translation);
}

/* x_0: the caller's guess, else c_A - c_B (the frame origins, paper Sec. IV),
 * else any axis when the shapes are concentric (where c_A - c_B = 0 would give
 * no direction at all). */
static agjk_vec3 initial_guess(const agjk_options *opts, const agjk_pose *pose_a,
                               const agjk__minkowski *md) {
    agjk_vec3 x0 = v3_neg(md->translation);
    if (opts->use_initial_direction) {
        x0 = m3_tmul(&pose_a->rotation[0][0], opts->initial_direction);
        /* Only its direction and rough size matter (it seeds the momentum):
         * bring an absurdly tiny or huge guess to unit length. */
        double m = v3_maxabs(x0);
        if (m > AGJK_MAX_COORDINATE || (m > 0.0 && m < 1.0 / AGJK_MAX_COORDINATE))
            x0 = v3_normalize(x0);
    }
    if (v3_maxabs(x0) == 0.0) x0 = v3(1.0, 0.0, 0.0);
    return x0;
}

static agjk_status run(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                       const agjk_pose *pose_b, const agjk_options *options,
                       agjk_result *result, int boolean_mode, agjk_cache *cache) {
    if (!result) return AGJK_STATUS_INVALID_INPUT;
    memset(result, 0, sizeof *result);
    result->momentum_stop_iteration = -1;
    result->status = AGJK_STATUS_INVALID_INPUT;
    agjk_options opts;
    if (!read_options(options, &opts) || !shape_is_valid(a) || !shape_is_valid(b) ||
        !agjk__pose_is_valid(pose_a) || !agjk__pose_is_valid(pose_b))
        return result->status;

    agjk__minkowski md;
    agjk__minkowski_init(&md, a, pose_a, b, pose_b, opts.hint_a, opts.hint_b);
    if (!isfinite(md.margin)) return result->status;

    agjk__solve_input in;
    in.method = opts.method;
    in.boolean_mode = boolean_mode;
    in.want_witness = !boolean_mode && (opts.compute & AGJK_COMPUTE_WITNESS);
    in.relative = opts.tolerance_mode == AGJK_TOLERANCE_RELATIVE;
    in.tolerance = opts.tolerance;
    in.max_iterations = opts.max_iterations;
    in.x0 = initial_guess(&opts, pose_a, &md);
    in.x0_given = opts.use_initial_direction != 0;
    in.warm_count = 0;
    if (cache) agjk__cache_load(cache, a, b, &md, &in); /* warm start (cache.c) */

    agjk__solve_output out;
    agjk__solve(&md, &in, &out);
    if (cache) {
        if (out.outcome == AGJK__BAD_SUPPORT) agjk_cache_init(cache);
        else agjk__cache_save(cache, a, b, &md, &out);
    }

    result->iterations = out.iterations;
    result->support_calls = out.support_calls;
    result->momentum_stop_iteration = out.momentum_stop;
    result->hint_a = md.hint_a;
    result->hint_b = md.hint_b;
    if (out.outcome == AGJK__BAD_SUPPORT) return result->status = AGJK_STATUS_INVALID_INPUT;
    /* The solver worked in units scaled by md.scale (a power of two): back to
     * the caller's. */
    double inv = 1.0 / md.scale;
    if (out.outcome == AGJK__INTERSECTING) {
        if (in.want_witness) {
            agjk_vec3 mid = to_world(pose_a, v3_scale(v3_add(out.a, out.b), 0.5 * inv));
            result->witness_a = mid;
            result->witness_b = mid;
        }
        return result->status = AGJK_STATUS_INTERSECTING;
    }
    if (out.outcome == AGJK__SEPARATED_EARLY) {
        agjk_vec3 n = v3_normalize(v3_neg(out.direction));
        result->normal = m3_mul(&pose_a->rotation[0][0], n);
        return result->status = AGJK_STATUS_SEPARATED;
    }

    /* Converged, capped or stalled: x != 0 and gap_valid (see the solver). */
    double core = v3_norm(out.x);
    double gap = out.gap_valid && out.gap > 0.0 ? out.gap : 0.0;
    /* Two certified lower bounds on the core distance ||x*||: the support plane,
     * ||x|| - g / (2 ||x||) = <x, s> / ||x||, and ||x|| - sqrt(g) (eq. 13). */
    double lower = core - sqrt(gap);
    if (core > 0.0) {
        double plane = core - gap / (2.0 * core); /* may be -inf for a denormal x */
        if (plane > lower) lower = plane;
    }
    lower -= 2.0 * out.noise; /* rounding of x and of the support points */
    /* From A towards B; v3_normalize copes with a denormal x (zero stays zero). */
    agjk_vec3 n_local = v3_normalize(v3_neg(out.x));
    /* At the floating-point floor an absolute tolerance counts as met (the
     * tolerance is documented to be raised to the floor); a relative one does
     * not, since the relative accuracy it promises was not reached. */
    int converged = out.outcome == AGJK__CONVERGED ||
                    (out.outcome == AGJK__AT_FLOOR && !in.relative);
    agjk_status status;
    if (out.outcome == AGJK__AT_ROUNDING)
        status = AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    else if (converged)
        status = lower > md.margin ? AGJK_STATUS_SEPARATED : AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    else
        status = AGJK_STATUS_NOT_CONVERGED;
    result->gap = gap * inv * inv; /* a rounding-level negative gap is reported as 0 */
    /* The normal is that of the plane that certified the lower bound: -x, or
     * the support direction the adaptive method stopped on (solver.c). */
    agjk_vec3 n_plane = v3_maxabs(out.direction) > 0.0 ? v3_normalize(v3_neg(out.direction)) : n_local;
    result->normal = m3_mul(&pose_a->rotation[0][0], n_plane);
    if (!boolean_mode) {
        double distance = core - md.margin;
        double low = lower - md.margin;
        if (distance < 0.0) distance = 0.0;
        if (low < 0.0) low = 0.0;
        result->distance = distance * inv;
        result->bound = (distance - low) * inv;
        if (in.want_witness) {
            agjk_vec3 wa = v3_scale(v3_add(out.a, v3_scale(n_local, md.margin_a)), inv);
            agjk_vec3 wb = v3_scale(v3_sub(out.b, v3_scale(n_local, md.margin_b)), inv);
            result->witness_a = to_world(pose_a, wa);
            result->witness_b = to_world(pose_a, wb);
        }
    }
    return result->status = status;
}

agjk_status agjk_distance(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                          const agjk_pose *pose_b, const agjk_options *options,
                          agjk_result *result) {
    return run(a, pose_a, b, pose_b, options, result, 0, NULL);
}

agjk_status agjk_collide(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                         const agjk_pose *pose_b, const agjk_options *options,
                         agjk_result *result) {
    return run(a, pose_a, b, pose_b, options, result, 1, NULL);
}

/* The warm-started queries of agjk/cache.h. */
agjk_status agjk_distance_cached(const agjk_shape *a, const agjk_pose *pose_a,
                                 const agjk_shape *b, const agjk_pose *pose_b,
                                 const agjk_options *options, agjk_cache *cache,
                                 agjk_result *result) {
    agjk_status status = run(a, pose_a, b, pose_b, options, result, 0, cache);
    if (status == AGJK_STATUS_INVALID_INPUT && cache) agjk_cache_init(cache);
    return status;
}

agjk_status agjk_collide_cached(const agjk_shape *a, const agjk_pose *pose_a,
                                const agjk_shape *b, const agjk_pose *pose_b,
                                const agjk_options *options, agjk_cache *cache,
                                agjk_result *result) {
    agjk_status status = run(a, pose_a, b, pose_b, options, result, 1, cache);
    if (status == AGJK_STATUS_INVALID_INPUT && cache) agjk_cache_init(cache);
    return status;
}
