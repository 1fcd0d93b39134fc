/* SPDX-License-Identifier: MIT */
/* Public queries: argument checks, the solver run, and the result in world frame. */
#include <stddef.h>
#include <string.h>

#include "agjk/query.h"
#include "query_setup.h"

/* Every field zero (the documented "zero where not computed"), the status
 * INVALID_INPUT. Field by field: a memset of the whole struct compiles to
 * `rep stos` (gcc, x86-64), whose start-up cost was 4-8 ns, a tenth of a
 * distant Boolean query. The padding after `status` (the struct's only one)
 * is zeroed with it, so that equal answers compare equal bytewise. */
static AGJK__ALWAYS_INLINE void result_reset(agjk_result *r) {
    agjk_vec3 zero = v3(0.0, 0.0, 0.0);
    memset(r, 0, offsetof(agjk_result, distance)); /* one 8-byte store */
    r->status = AGJK_STATUS_INVALID_INPUT;
    r->distance = r->bound = r->gap = 0.0;
    r->witness_a = r->witness_b = r->normal = zero;
    r->iterations = r->support_calls = 0;
    r->momentum_stop_iteration = -1;
    r->hint_a = r->hint_b = 0;
    r->stop_reason = AGJK_STOP_NONE;
    for (int i = 0; i < 8; ++i) r->reserved[i] = 0.0;
}

/* The normal of a separating plane found along x, -x / ||x|| in world frame. */
static AGJK__ALWAYS_INLINE agjk_vec3 plane_normal(const agjk_pose *pose_a, agjk_vec3 x) {
    return m3_mul(&pose_a->rotation[0][0], v3_normalize(v3_neg(x)));
}

/* The same for iteration 0's separating plane,
 * x in the direction of x_0 (a power-of-two multiple of it, or x_0
 * normalised, when the first support changed the units). When x_0 is
 * c_A - c_B as the query set it (no guess given, the frames' origins
 * apart), it was R_A^T (t_A - t_B), and the normal is the world offset
 * t_B - t_A normalised: R_A's rotation back would only add rounding (a few
 * ulps either way). Taken from the translations, it skips that rotation and
 * needs nothing the support computes: distant Boolean queries 1.5-2 ns
 * faster (of 33-44). Offsets near underflow, whose rotation may have lost
 * digits, take the rotation. */
static AGJK__ALWAYS_INLINE int start_normal_from_offset(const agjk__minkowski *md,
                                                        const agjk__solve_input *in) {
    return !in->x0_given && md->translation_size >= 0x1p-900;
}
static AGJK__ALWAYS_INLINE agjk_vec3 offset_normal(const agjk_pose *pose_a,
                                                   const agjk_pose *pose_b) {
    return v3_normalize(v3_sub(pose_b->translation, pose_a->translation));
}
static AGJK__ALWAYS_INLINE agjk_vec3 start_normal(const agjk_pose *pose_a, const agjk_pose *pose_b,
                                                  const agjk__minkowski *md,
                                                  const agjk__solve_input *in, agjk_vec3 x) {
    if (start_normal_from_offset(md, in)) return offset_normal(pose_a, pose_b);
    return plane_normal(pose_a, x);
}

/* The query, compiled once per entry point: agjk_distance() and
 * agjk_collide() each get a copy with their mode and no cache folded in, so
 * that a program calling only one of them links neither the other's code
 * (the Boolean exit's inline first support, about 3.7 KB) nor the cache's
 * branches; the cached queries share the general one (agjk__query_run). */
static AGJK__ALWAYS_INLINE agjk_status run_query(const agjk_shape *a, const agjk_pose *pose_a,
                                                 const agjk_shape *b, const agjk_pose *pose_b,
                                                 const agjk_options *options, agjk_result *result,
                                                 int boolean_mode, struct agjk_cache *cache,
                                                 const agjk__warm_hooks *hooks) {
    if (!result) return AGJK_STATUS_INVALID_INPUT;
    result_reset(result);
    agjk__minkowski md;
    agjk__solve_input in;
    if (!agjk__query_prepare(a, pose_a, b, pose_b, options, boolean_mode, &md, &in))
        return result->status;
    in.boolean_mode = boolean_mode; /* (as set there: a constant for the code below) */
    in.want_witness = in.want_witness && !boolean_mode;
    in.keep_points = in.want_witness || cache; /* the cache keeps the simplex */
    in.track_flat = cache != NULL;
    in.want_simplex = cache != NULL;
    if (cache) hooks->load(cache, a, b, &md, &in); /* warm start (cache.c) */

    /* In Boolean mode, iteration 0's support is taken here: distant shapes end
     * on its plane (Alg. 2), answered from it alone, before the solver sets
     * anything up (a cache records the solver's output, so cached queries
     * take the solver's path for that end too). Distance queries leave it to
     * the solver, which then keeps its point in registers. */
    agjk__solve_output out;
    int on_start_plane = 0; /* the solver ended on iteration 0's plane */
    if (boolean_mode) {
        /* The normal of a separating start from the offset, taken before the
         * support rather than after its plane test: its square root and
         * division then run alongside the support instead of at the end of
         * the query (one-support Boolean queries: boxes 59 -> 56 ns, hulls
         * 115 -> 108; ellipsoids, whose support's own square root and
         * division are the longer chain, do not move). Wasted when the start
         * does not separate: a few cycles of a query that goes on for
         * hundreds. */
        int early = !cache && start_normal_from_offset(&md, &in);
        agjk_vec3 normal = early ? offset_normal(pose_a, pose_b) : v3(0.0, 0.0, 0.0);
        agjk__start start;
        /* (Ellipsoids and boxes: the first plane test from their support
         * values, before the support is taken at all, agjk__start_apart;
         * its answer is the offset's normal, so only with it.) */
        if (agjk__solve_start(&md, &in, &start, early) && !cache) {
            result->iterations = 1;
            result->support_calls = 1;
            result->hint_a = md.hint_a;
            result->hint_b = md.hint_b;
            result->normal = early ? normal : start_normal(pose_a, pose_b, &md, &in, start.x);
            return result->status = AGJK_STATUS_SEPARATED;
        }
        /* (A cached query: the solver ends at once on a separating start.) */
        on_start_plane = start.separated;
        agjk__solve_from(&md, &in, &start, &out);
    } else {
        agjk__solve(&md, &in, &out);
    }
    if (cache) {
        if (out.outcome == AGJK__BAD_SUPPORT) hooks->reset(cache);
        else hooks->save(cache, a, b, &md, &in, &out);
    }

    result->iterations = out.iterations;
    result->support_calls = out.support_calls;
    result->momentum_stop_iteration = out.momentum_stop;
    result->hint_a = md.hint_a;
    result->hint_b = md.hint_b;
    if (out.outcome == AGJK__BAD_SUPPORT) return result->status = AGJK_STATUS_INVALID_INPUT;
    /* The solver worked in units scaled by md.scale (a power of two): back to
     * the caller's. */
    double inv = md.scale == 1.0 ? 1.0 : 1.0 / md.scale; /* (no division in the usual case) */
    if (out.outcome == AGJK__INTERSECTING) {
        if (in.want_witness) {
            agjk_vec3 mid = agjk__to_world(pose_a, v3_scale(v3_add(out.a, out.b), 0.5 * inv));
            result->witness_a = mid;
            result->witness_b = mid;
        }
        return result->status = AGJK_STATUS_INTERSECTING;
    }
    if (out.outcome == AGJK__SEPARATED_EARLY) {
        agjk_vec3 x = v3_load_scalars(&out.direction);
        result->normal = on_start_plane ? start_normal(pose_a, pose_b, &md, &in, x)
                                        : plane_normal(pose_a, x);
        return result->status = AGJK_STATUS_SEPARATED;
    }

    /* Converged, capped or stalled: x != 0 and gap_valid (see the solver). */
    agjk__core_bounds cb;
    agjk__core_bounds_of(&out, &cb);
    double gap = cb.gap, lower = cb.lower;
    /* At the floating-point floor an absolute tolerance counts as met (the
     * tolerance is documented to be raised to the floor); a relative one does
     * not, since the relative accuracy it promises was not reached. Shapes
     * within rounding of contact (AT_ROUNDING) are a contact in either mode. */
    int at_rounding = out.outcome == AGJK__AT_ROUNDING;
    int converged = out.outcome == AGJK__CONVERGED || at_rounding ||
                    (out.outcome == AGJK__AT_FLOOR && !in.relative);
    double distance = cb.upper - md.margin;
    double low = lower - md.margin;
    if (distance < 0.0) distance = 0.0;
    if (low < 0.0) low = 0.0;
    /* An inexact member point (farther from the origin than x by more than
     * rounding) raised the upper end: the interval is wider than the gap
     * showed, and counts only if it still holds what was promised. In the
     * gap's terms, ||p||^2 - ||x*||^2 <= upper^2 - lower^2 (cores): within an
     * absolute tolerance, or within the floor such a tolerance is raised to
     * (gap_verdict's, agjk__gap_floor2), which is also what "within rounding
     * of contact" means. A relative
     * tolerance away from contact: the width test below. */
    if (converged && cb.inexact && (!in.relative || at_rounding)) {
        double lo = lower > 0.0 ? lower : 0.0;
        double spread = (cb.upper - lo) * (cb.upper + lo);
        double tol = in.relative ? 0.0 : in.tolerance * md.scale * md.scale;
        converged = spread <= tol ||
                    spread * spread <= agjk__gap_floor2(out.noise, cb.core * cb.core, out.xs2);
    }
    /* Relative mode claims |distance - d*| <= d* tolerance / 2 only when the
     * whole certified interval, rounding included, shows it. */
    if (converged && in.relative && !at_rounding &&
        !(distance - low <= 0.5 * in.tolerance * low))
        converged = 0;
    agjk_status status;
    if (at_rounding && converged)
        status = AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    else if (converged)
        status = lower > agjk__minkowski_separation_level(&md)
                     ? AGJK_STATUS_SEPARATED : AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    else
        status = AGJK_STATUS_NOT_CONVERGED;
    /* An outcome that met the tolerance (or the floor) but whose certified
     * interval does not show it: beyond what double precision certifies. */
    if (status == AGJK_STATUS_NOT_CONVERGED)
        result->stop_reason = out.outcome == AGJK__ITERATION_CAP ? AGJK_STOP_ITERATION_CAP
                              : out.outcome == AGJK__STALLED      ? AGJK_STOP_NO_PROGRESS
                                                                  : AGJK_STOP_BELOW_PRECISION;
    result->gap = gap * inv * inv; /* a rounding-level negative gap is reported as 0 */
    /* The normal is that of the plane that certified the lower bound. */
    result->normal = m3_mul(&pose_a->rotation[0][0], cb.normal);
    if (!boolean_mode) {
        result->distance = distance * inv;
        result->bound = (distance - low) * inv;
        if (in.want_witness) {
            agjk_vec3 wa = v3_scale(v3_add(out.a, v3_scale(cb.toward_x, md.margin_a)), inv);
            agjk_vec3 wb = v3_scale(v3_sub(out.b, v3_scale(cb.toward_x, md.margin_b)), inv);
            result->witness_a = agjk__to_world(pose_a, wa);
            result->witness_b = agjk__to_world(pose_a, wb);
        }
    }
    return result->status = status;
}

AGJK__HOT_ENTRY agjk_status agjk__query_run(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                            const agjk_pose *pose_b, const agjk_options *options,
                            agjk_result *result, int boolean_mode, struct agjk_cache *cache,
                            const agjk__warm_hooks *hooks) {
    /* (One copy per mode here too: a warm distance query is short, and the
     * Boolean exit's code in its way cost it 2-3%.) */
    if (boolean_mode) return run_query(a, pose_a, b, pose_b, options, result, 1, cache, hooks);
    return run_query(a, pose_a, b, pose_b, options, result, 0, cache, hooks);
}

AGJK__HOT_ENTRY agjk_status agjk_distance(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                          const agjk_pose *pose_b, const agjk_options *options,
                          agjk_result *result) {
    return run_query(a, pose_a, b, pose_b, options, result, 0, NULL, NULL);
}

AGJK__HOT_ENTRY agjk_status agjk_collide(const agjk_shape *a, const agjk_pose *pose_a, const agjk_shape *b,
                         const agjk_pose *pose_b, const agjk_options *options,
                         agjk_result *result) {
    return run_query(a, pose_a, b, pose_b, options, result, 1, NULL, NULL);
}
