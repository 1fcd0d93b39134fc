/* SPDX-License-Identifier: MIT */
/* agjk_signed_distance: GJK on the cores, then EPA when they overlap; margins
 * added analytically; the certified interval in the caller's units. */
#include <string.h>

#include "agjk/penetration.h"
#include "epa.h"
#include "query_setup.h"

/* What EPA needs from GJK, in one place (the solver's internals may change):
 * the outcome, the final iterate with its certified core-distance interval,
 * and the final simplex. */
typedef struct gjk_summary {
    int bad_support;
    int intersecting;     /* the origin is in the final simplex */
    int converged;        /* GJK met its tolerance (absolute: or its floor) */
    double core_upper;    /* certified upper bound on the core distance (solver units) */
    double core_lower;    /* certified lower bound on the core distance (solver units) */
    agjk_vec3 x;          /* final iterate */
    agjk_vec3 toward_x;   /* -x / ||x|| */
    agjk_vec3 normal;     /* unit normal of the plane that certifies core_lower */
    agjk_vec3 a, b;       /* its points on A and B */
    const agjk__vertex *simplex;
    int count;
    int iterations, support_calls;
} gjk_summary;

static void run_gjk(agjk__minkowski *md, agjk__solve_input *in, agjk__solve_output *out,
                    gjk_summary *g) {
    /* want_witness stays the caller's: GJK's points serve only as witness
     * points (separated cores, or EPA's flat and degenerate cases). */
    in->want_simplex = 1; /* EPA starts from GJK's final simplex */
    agjk__solve(md, in, out);
    g->bad_support = out->outcome == AGJK__BAD_SUPPORT;
    g->intersecting = out->outcome == AGJK__INTERSECTING;
    g->converged = out->outcome == AGJK__CONVERGED ||
                   (out->outcome == AGJK__AT_FLOOR && !in->relative);
    g->x = out->x;
    g->a = out->a;
    g->b = out->b;
    g->simplex = out->simplex;
    g->count = out->simplex_count;
    g->iterations = out->iterations;
    g->support_calls = out->support_calls;
    if (g->intersecting) {
        g->core_upper = out->noise;
        g->core_lower = -INFINITY;
        g->toward_x = g->normal = v3(0.0, 0.0, 0.0);
        return;
    }
    /* As agjk_distance (query_setup.c). */
    agjk__core_bounds cb;
    agjk__core_bounds_of(out, &cb);
    g->core_lower = cb.lower;
    g->core_upper = cb.upper;
    g->toward_x = cb.toward_x;
    g->normal = cb.normal;
}

/* A support callback returned a bad point: nothing computed, a zeroed result. */
static agjk_status invalid(agjk_signed_result *r) {
    memset(r, 0, sizeof *r);
    return r->status = AGJK_STATUS_INVALID_INPUT;
}

/* Back in the caller's units (a power of two, exact) the interval may land
 * among subnormal numbers, where the product rounds: widen it by one ulp
 * outwards whenever the units changed. */
static void widen_after_rescale(agjk_signed_result *r, double scale) {
    if (scale == 1.0) return;
    r->lower = nextafter(r->lower, -INFINITY);
    r->upper = nextafter(r->upper, INFINITY);
}

/* The margins' share of the rounding, added outwards to both ends: their
 * sum (margin = margin_a + margin_b, rounded) and its subtraction from a
 * core bound round by half an ulp each, which the cores' own allowance (a
 * few ulps of the cores' size) need not cover: two spheres of radii 0.1 and
 * 0.2 whose centres are 1e-3 apart came out as [-0.29900000000000004,
 * -0.29900000000000004], just beside the exact -0.29900000000000002.
 * 0 without margins, where the cores' interval is the answer's. */
static void widen_for_margins(agjk_signed_result *r, double margin) {
    if (!(margin > 0.0)) return;
    r->lower -= 2.0 * DBL_EPSILON * (margin + fabs(r->lower));
    r->upper += 2.0 * DBL_EPSILON * (margin + fabs(r->upper));
}

/* Whether the final interval (caller's units, every allowance added) meets
 * the width agjk/penetration.h promises: what decides between a verdict and
 * NOT_CONVERGED, whatever GJK's or EPA's own stopping test said. */
static int final_width_met(const agjk_signed_result *r, const agjk__minkowski *md, int relative,
                           double tolerance, double margin) {
    double floor = agjk__signed_floor(md, margin * md->scale);
    /* In the caller's units (a power of two away), with room for the ulps
     * widen_after_rescale may add among subnormal numbers (agjk__signed_
     * floor_rescaled: out of line, see epa.h). */
    if (md->scale != 1.0) floor = agjk__signed_floor_rescaled(floor, md->scale);
    return agjk__signed_width_met(relative, tolerance, 1.0, r->lower, r->upper, floor);
}

static agjk_status finish(agjk_signed_result *r, int converged) {
    if (!converged) return r->status = AGJK_STATUS_NOT_CONVERGED;
    if (r->lower > 0.0) return r->status = AGJK_STATUS_SEPARATED;
    if (r->upper < 0.0) return r->status = AGJK_STATUS_INTERSECTING;
    return r->status = AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
}

/* The answer when the cores are certified disjoint: the GJK distance, minus
 * the margins (as agjk_distance, with the margins subtracted). Returns
 * whether its final interval meets the promised width; the status is left
 * to the caller. */
static int separated_cores(agjk_signed_result *result, const gjk_summary *g,
                           const agjk__minkowski *md, const agjk_pose *pose_a, double margin_a,
                           double margin_b, double margin, int witness, int relative,
                           double tolerance) {
    double inv = 1.0 / md->scale;
    double core = v3_norm(g->x);
    result->signed_distance = core * inv - margin;
    result->upper = g->core_upper * inv - margin;
    result->lower = g->core_lower * inv - margin;
    widen_for_margins(result, margin);
    result->hint_a = md->hint_a;
    result->hint_b = md->hint_b;
    /* The plane that certifies the lower end; the witness points sit on -x. */
    result->normal = m3_mul(&pose_a->rotation[0][0], g->normal);
    agjk_vec3 n = g->toward_x;
    if (witness) {
        agjk_vec3 wa = v3_add(v3_scale(g->a, inv), v3_scale(n, margin_a));
        agjk_vec3 wb = v3_sub(v3_scale(g->b, inv), v3_scale(n, margin_b));
        result->witness_a = agjk__to_world(pose_a, wa);
        result->witness_b = agjk__to_world(pose_a, wb);
    }
    widen_after_rescale(result, md->scale);
    return final_width_met(result, md, relative, tolerance, margin);
}

agjk_status agjk_signed_distance(const agjk_shape *a, const agjk_pose *pose_a,
                                 const agjk_shape *b, const agjk_pose *pose_b,
                                 const agjk_options *options, agjk_signed_result *result) {
    if (!result) return AGJK_STATUS_INVALID_INPUT;
    memset(result, 0, sizeof *result);
    result->status = AGJK_STATUS_INVALID_INPUT;
    agjk__minkowski md;
    agjk__solve_input in;
    if (!agjk__query_prepare(a, pose_a, b, pose_b, options, 0, &md, &in))
        return result->status;
    int witness = in.want_witness;
    double tolerance = in.tolerance; /* the caller's: GJK's may be tightened below */
    /* GJK runs on the cores: the margins (caller's units, md.scale is 1 here)
     * are added to the answer analytically, so that the solver neither stops
     * early when the cores come closer than the margins nor loses the simplex. */
    double margin_a = md.margin_a, margin_b = md.margin_b, margin = md.margin;
    md.margin_a = md.margin_b = md.margin = 0.0;

    agjk__solve_output out;
    gjk_summary g;
    run_gjk(&md, &in, &out, &g);
    result->gjk_iterations = g.iterations;
    result->support_calls = g.support_calls;
    result->hint_a = md.hint_a;
    result->hint_b = md.hint_b;
    if (g.bad_support) return invalid(result);

    /* Cores certified disjoint: the GJK distance minus the margins. The
     * final interval, every rounding allowance added, decides: GJK's
     * tolerance bounds the error relative to the core distance, while the
     * promise is on the signed distance (larger with deep overlap of the
     * margins) and the interval gains the margins' and the units' rounding.
     * When it falls short, GJK is resumed from its last iterate with a
     * proportionally tighter tolerance (twice at most): always with margins,
     * and without them when GJK met its tolerance (else it is at a limit a
     * restart will not pass: the floor, the cap, a stall). */
    for (int round = 0; !g.intersecting && g.core_lower > 0.0; ++round) {
        int met = separated_cores(result, &g, &md, pose_a, margin_a, margin_b, margin, witness,
                                  in.relative, tolerance);
        if (met || round == 2 || !(margin > 0.0 || g.converged)) return finish(result, met);
        double target = agjk__epa_target(in.relative, tolerance, 1.0, result->lower,
                                         result->upper, 0.0);
        in.tolerance *= 0.25 * target / (result->upper - result->lower);
        if (!(in.tolerance > 0.0)) in.tolerance = DBL_MIN;
        in.x0 = g.x; /* solver units: the scale is already set */
        run_gjk(&md, &in, &out, &g);
        result->gjk_iterations += g.iterations;
        result->support_calls += g.support_calls;
        if (g.bad_support) return invalid(result);
    }

    /* The cores overlap or touch: EPA from GJK's simplex. */
    agjk__epa_input ein;
    ein.simplex = g.simplex;
    ein.count = g.count;
    ein.relative = in.relative;
    ein.tolerance = tolerance;
    ein.margin = margin;
    ein.core_distance_upper = g.core_upper;
    ein.max_iterations = in.max_iterations;
    ein.want_witness = witness;
    agjk__epa_output eout;
    agjk__epa(&md, &ein, &eout);
    result->epa_iterations = eout.iterations;
    result->support_calls += eout.support_calls;
    result->hint_a = md.hint_a;
    result->hint_b = md.hint_b;
    if (eout.outcome == AGJK__EPA_BAD_SUPPORT) return invalid(result);
    double inv = 1.0 / md.scale; /* EPA may have lowered the scale */
    result->lower = -eout.upper * inv - margin;
    result->upper = -eout.lower * inv - margin;
    widen_for_margins(result, margin);
    result->signed_distance = -eout.estimate * inv - margin;
    agjk_vec3 n = eout.normal;
    result->normal = m3_mul(&pose_a->rotation[0][0], n);
    if (witness) {
        agjk_vec3 wa, wb;
        if (eout.has_witness) {
            wa = v3_add(v3_scale(eout.a, inv), v3_scale(n, margin_a));
            wb = v3_sub(v3_scale(eout.b, inv), v3_scale(n, margin_b));
        } else {
            /* Flat or degenerate D: the cores touch at GJK's point. */
            wa = v3_add(v3_scale(g.a, inv), v3_scale(n, margin_a));
            wb = v3_sub(v3_scale(g.b, inv), v3_scale(n, margin_b));
        }
        result->witness_a = agjk__to_world(pose_a, wa);
        result->witness_b = agjk__to_world(pose_a, wb);
    }
    widen_after_rescale(result, md.scale);
    /* (EPA stopped on a width test that allowed for these widenings.) */
    return finish(result, final_width_met(result, &md, in.relative, tolerance, margin));
}
