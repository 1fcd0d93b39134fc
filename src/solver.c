/* SPDX-License-Identifier: MIT */
/* The Frank-Wolfe family loop on D = A - B (Montaut et al., "Collision
 * Detection Accelerated: An Optimization Perspective", RSS 2022).
 *
 *   GJK (Alg. 4/5)      d_k = x_k; active set = smallest sub-simplex holding x_{k+1}
 *   Nesterov (Alg. 6)   d_k from momentum; fallback to d_k = x_k once g(x_k) <= eps
 *   normalized (Alg. 7) the same with normalised momentum terms
 *   Polyak (GJK++)      heavy-ball momentum on d_k, same fallback
 *   FW (Alg. 1)         d_k = x_k; x_{k+1} = projection of 0 onto [x_k, s_k]
 *
 * Stopping uses the Frank-Wolfe duality gap g(x) = 2 <x, x - s>, s = S_D(x)
 * (eq. 12-13), which certifies ||x - x*||^2 <= g. With momentum, g computed with
 * s = S_D(d_k) is not a certificate; it only triggers the fallback (eq. 28-30).
 *
 * Every loop is bounded by max_iterations; the simplex projection is
 * non-iterative. No allocation: the simplex lives on the stack. */
#include "solver.h"

#include "simplex.h"

/* Error scale of a computed point of D: a few ulps of the magnitudes involved
 * (the support points and B's translation in A's frame). */
static double noise_scale(const agjk__minkowski *md) {
    return 4.0 * DBL_EPSILON * (md->magnitude + v3_maxabs(md->translation));
}

/* The requested tolerance on g. Relative mode asks for a distance error of at
 * most tolerance/2 times the distance ||x|| - margins: since the distance error
 * is at most g / (2 ||x||), that is g <= tolerance ||x|| (||x|| - margins). */
static double requested_tolerance(const agjk__solve_input *in, const agjk__minkowski *md,
                                  double x_norm2) {
    /* An absolute tolerance is in the caller's length units squared. (It may
     * overflow to +inf for a tiny problem: any answer then meets it.) */
    if (!in->relative) return in->tolerance * md->scale * md->scale;
    double x_norm = sqrt(x_norm2);
    double gap = x_norm - md->margin;
    return gap > 0.0 ? in->tolerance * x_norm * gap : 0.0;
}

/* What the floating-point evaluation of g can resolve: 2 ||x|| times the error
 * of a support point. Below it the solver would only churn at the noise. */
static double floor_tolerance(double x_norm2, double noise) { return 2.0 * sqrt(x_norm2) * noise; }

/* Momentum pays off in the first few dozen iterations (paper, Fig. 4-6); past
 * this many, a momentum direction that has not reached the Alg. 6 fallback is
 * creeping (normalised momentum on smooth overlapping shapes can take ~1000
 * iterations to reach g <= eps), and plain GJK finishes faster. */
#define MOMENTUM_BUDGET 64

/* Alg. 2: the plane of normal d through s separates D (inflated by the margins)
 * from the origin when <d, s> > ||d|| (margin + rounding). */
static int separates(const agjk__minkowski *md, agjk_vec3 d, agjk_vec3 w) {
    /* The unit direction, as the support function saw it: a denormal d has
     * too few significant bits for <d, w> to mean anything. */
    agjk_vec3 n = v3_normalize(d);
    return v3_dot(n, w) > md->margin + noise_scale(md);
}

/* After a support call that had to lower the scale (agjk__minkowski_shrink),
 * brings the solver's own state to the new units. Exact: powers of two. */
static void follow_rescale(agjk__minkowski *md, agjk__vertex *simplex, int count, agjk_vec3 *x,
                           agjk__momentum *m, agjk_vec3 *d) {
    double f = md->rescaled;
    if (f == 1.0) return;
    md->rescaled = 1.0;
    for (int i = 0; i < count; ++i) {
        simplex[i].w = v3_scale(simplex[i].w, f);
        simplex[i].a = v3_scale(simplex[i].a, f);
        simplex[i].b = v3_scale(simplex[i].b, f);
    }
    *x = v3_scale(*x, f);
    *d = v3_scale(*d, f);
    agjk__momentum_rescale(m, f);
}

/* Checks a fresh support s in direction d: a bad callback output ends the
 * query, and in Boolean mode so does a separating plane (Alg. 2). Returns 1
 * when the loop must stop, with out->outcome set. */
static int support_ends_query(const agjk__minkowski *md, const agjk__solve_input *in, agjk_vec3 d,
                              const agjk__vertex *s, agjk__solve_output *out) {
    if (md->bad_support) {
        out->outcome = AGJK__BAD_SUPPORT;
        return 1;
    }
    if (in->boolean_mode && separates(md, d, s->w)) {
        out->outcome = AGJK__SEPARATED_EARLY;
        out->direction = d;
        return 1;
    }
    return 0;
}

/* Adds s to the active set and projects the origin onto its hull, keeping only
 * the vertices with positive weight (Alg. 4 line 7 / Alg. 5). Returns 1 when
 * the origin is enclosed by a full tetrahedron. */
static int update_simplex(agjk__vertex *simplex, int *count, double lambda[4],
                          const agjk__vertex *s, agjk_vec3 *x) {
    simplex[(*count)++] = *s;
    agjk_vec3 w[4];
    for (int i = 0; i < *count; ++i) w[i] = simplex[i].w;
    double l[4];
    unsigned mask = agjk__simplex_project(w, *count, l, x);
    if (mask == 0xFu) {
        for (int i = 0; i < 4; ++i) lambda[i] = l[i];
        return 1;
    }
    int kept = 0;
    for (int i = 0; i < *count; ++i) {
        if (mask & (1u << i)) {
            simplex[kept] = simplex[i];
            lambda[kept] = l[i];
            ++kept;
        }
    }
    *count = kept;
    return 0;
}

/* Plain Frank-Wolfe with exact line search (Alg. 1): the active set is the
 * iterate itself, stored as one vertex whose a, b accumulate the convex
 * combination so that witness points stay available. */
static void update_frank_wolfe(agjk__vertex *simplex, int *count, double lambda[4],
                               const agjk__vertex *s, agjk_vec3 *x) {
    if (*count == 0) {
        simplex[0] = *s;
    } else {
        agjk_vec3 w[2] = {simplex[0].w, s->w};
        double l[4];
        agjk__simplex_project(w, 2, l, x);
        simplex[0].a = v3_lerp2(simplex[0].a, l[0], s->a, l[1]);
        simplex[0].b = v3_lerp2(simplex[0].b, l[0], s->b, l[1]);
        simplex[0].w = *x;
    }
    *count = 1;
    lambda[0] = 1.0;
    *x = simplex[0].w;
}

/* Below -lie_level, g (or the adaptive plane gap) at x proves that a support
 * function lies. Warm-started points (cache.c) carry a few more ulps of
 * rounding from their frame changes. */
static double lie_level(const agjk__solve_input *in, const agjk__minkowski *md, double x2) {
    return (in->warm_count > 0 ? 16.0 : 4.0) * sqrt(x2) * noise_scale(md);
}

static int parallel(agjk_vec3 d, agjk_vec3 x) {
    agjk_vec3 c = v3_cross(d, x);
    return v3_norm2(c) == 0.0 && v3_dot(d, x) > 0.0;
}

/* Adaptive method: stops at x (a point of D) when the best support plane met
 * so far certifies it (direction.c), or when that plane lies beyond x, which
 * proves a lying support. Returns 1 with out->outcome set. */
static int plane_stops(const agjk__momentum *m, const agjk__solve_input *in,
                       const agjk__minkowski *md, agjk_vec3 x, agjk__solve_output *out) {
    double x2 = v3_norm2(x), n = sqrt(x2), noise = noise_scale(md);
    /* 2 ||x|| (||x|| - plane) >= ||x||^2 - ||x*||^2 >= ||x - x*||^2 */
    double gp = 2.0 * n * (n - m->plane);
    if (gp < -lie_level(in, md, x2)) {
        out->outcome = AGJK__BAD_SUPPORT; /* a plane beyond x, a point of D */
        return 1;
    }
    /* Written so that NaN (no plane yet at x = 0) does not stop. */
    if (!(gp <= floor_tolerance(x2, noise)) && !(gp <= requested_tolerance(in, md, x2))) return 0;
    double requested = requested_tolerance(in, md, x2);
    if (!parallel(m->d_best, x)) out->direction = m->d_best;
    out->gap = gp > 0.0 ? gp : 0.0;
    out->gap_valid = 1;
    out->outcome = gp <= requested ? AGJK__CONVERGED : AGJK__AT_FLOOR;
    return 1;
}

void agjk__solve(agjk__minkowski *md, const agjk__solve_input *in, agjk__solve_output *out) {
    agjk__vertex simplex[4];
    double lambda[4] = {1.0, 0.0, 0.0, 0.0};
    int count = 0;
    agjk_vec3 x = in->x0;
    int have_x = 0; /* x is a point of D (after the first projection) */
    agjk__momentum m;
    agjk__momentum_init(&m, in->method, x, in->x0_given);

    out->outcome = AGJK__ITERATION_CAP;
    out->gap = INFINITY;
    out->gap_valid = 0;
    out->iterations = 0;
    out->support_calls = 0;
    out->momentum_stop = -1;
    out->direction = v3(0.0, 0.0, 0.0);

    /* The first support, in direction x_0 for every method (d_{-1} = s_{-1} =
     * x_0 gives d_0 = x_0), also tells the problem's size: from then on the
     * solver works in units where it is about 1. */
    agjk__vertex s;
    agjk_vec3 d0;                        /* direction of the first support */
    int warm = 0, warm_enclosed = 0;     /* cached points in the simplex (cache.c) */
    {
        /* The problem's size is not known yet: give the callbacks a unit-size
         * direction (exact power-of-two scaling of x_0). */
        double m0 = v3_maxabs(x);
        agjk__minkowski_support(md, m0 > 0.0 ? v3_scale_to_unit(x, m0) : x, &s);
    }
    ++out->support_calls;
    {
        /* A shrink during that first call already put s in new units; x_0,
         * given in the caller's units, needs it too. */
        double shrunk = md->rescaled;
        md->rescaled = 1.0;
        double f = agjk__minkowski_set_scale(md);
        s.a = v3_scale(s.a, f);
        s.b = v3_scale(s.b, f);
        s.w = v3_scale(s.w, f);
        agjk_vec3 x_units = v3_scale(v3_scale(x, shrunk), f);
        /* A guess far off the problem's size (a caller's, or a denormal offset
         * that underflows when scaled) only gives a direction. */
        if (!v3_in_range(x_units) || v3_maxabs(x_units) < 1.0 / AGJK_MAX_COORDINATE)
            x_units = v3_normalize(x);
        x = x_units;
        d0 = x;
        /* Warm start: the cached simplex is the active set at k = 0, and plain
         * GJK directions take it from there (cache.c). Only for problems of
         * ordinary size, where x_0, its projection, is used as given. */
        if (in->warm_count > 0 && x.x == in->x0.x && x.y == in->x0.y && x.z == in->x0.z) {
            count = agjk__warm_seed(in, simplex, lambda, &x);
            have_x = 1;
            warm = 1;
            warm_enclosed = count == 4;
            m.active = 0;
        }
        m.d_prev = x;
        m.s_prev = x;
    }
    for (int k = 0; k < in->max_iterations; ++k) {
        out->iterations = k + 1;
        agjk_vec3 d = k == 0 ? d0 : x;
        if (k > 0) {
            if (m.active) d = agjk__momentum_direction(&m, k, x);
            agjk__minkowski_support(md, d, &s);
            ++out->support_calls;
            follow_rescale(md, simplex, count, &x, &m, &d);
        }
        if (support_ends_query(md, in, d, &s, out)) break;
        /* Warm start: a support plane that cuts off a cached point proves the
         * cache stale; go on cold from this support (cache.c). */
        if (warm && !agjk__warm_consistent(simplex, count, d, &s, noise_scale(md))) {
            count = 0;
            have_x = 0;
            warm = warm_enclosed = 0;
        }
        if (warm_enclosed) { out->outcome = AGJK__INTERSECTING; break; }
        /* Adaptive method: every support plane is a lower bound (direction.c). */
        if (m.method == AGJK_METHOD_ADAPTIVE) agjk__momentum_plane(&m, d, s.w, x);
        if (have_x) {
            double x2 = v3_norm2(x);
            double requested = requested_tolerance(in, md, x2);
            double floor = floor_tolerance(x2, noise_scale(md));
            double tol = requested > floor ? requested : floor;
            double g = 2.0 * v3_dot(x, v3_sub(x, s.w)); /* eq. 29 */
            double lie = lie_level(in, md, x2);
            /* Alg. 6 switches momentum off once g(x_k) <= eps. A relative
             * tolerance shrinks with the distance and never fires on
             * overlapping shapes, so momentum would creep on for ever: for
             * this test use it as an absolute one at the problem's own scale. */
            /* Adaptive method: the best support plane met so far, in whatever
             * direction, certifies x as well as the gap does (no extra support
             * in direction x_k once momentum has done its work). */
            if (m.method == AGJK_METHOD_ADAPTIVE && plane_stops(&m, in, md, x, out)) break;
            double fallback = tol;
            if (in->relative) {
                double scaled = in->tolerance * md->magnitude * md->magnitude;
                if (scaled > fallback) fallback = scaled;
            }
            /* (The adaptive method's plain steps, d = x, need no fallback: their
             * g is a true gap, already tested by plane_stops.) */
            if (m.active && (g <= fallback || k >= MOMENTUM_BUDGET) &&
                !(m.method == AGJK_METHOD_ADAPTIVE && parallel(d, x))) {
                /* Alg. 6 lines 5-7: the momentum direction makes no progress. */
                if (parallel(d, x)) {
                    out->gap = g;
                    out->gap_valid = 1;
                    out->outcome = g <= requested ? AGJK__CONVERGED : AGJK__AT_FLOOR;
                    break;
                }
                m.active = 0;
                out->momentum_stop = k;
                d = x;
                agjk__minkowski_support(md, d, &s);
                ++out->support_calls;
                follow_rescale(md, simplex, count, &x, &m, &d);
                if (support_ends_query(md, in, d, &s, out)) break;
                if (m.method == AGJK_METHOD_ADAPTIVE) agjk__momentum_plane(&m, d, s.w, x);
                /* The support may have changed the units: recompute in them. */
                x2 = v3_norm2(x);
                requested = requested_tolerance(in, md, x2);
                floor = floor_tolerance(x2, noise_scale(md));
                tol = requested > floor ? requested : floor;
                g = 2.0 * v3_dot(x, v3_sub(x, s.w));
                lie = lie_level(in, md, x2);
            }
            if (!m.active) {
                /* x is in D and s minimises <x, .> over D, so g >= 0 up to
                 * rounding. Clearly negative: the support function lies. */
                if (g < -lie) {
                    out->outcome = AGJK__BAD_SUPPORT;
                    break;
                }
                out->gap = g; /* a true Frank-Wolfe gap: s = S_D(x) */
                out->gap_valid = 1;
                if (g <= requested) { out->outcome = AGJK__CONVERGED; break; }
                if (g <= tol) { out->outcome = AGJK__AT_FLOOR; break; }
            }
        }
        agjk_vec3 x_new;
        int enclosed;
        if (in->method == AGJK_METHOD_FRANK_WOLFE) {
            update_frank_wolfe(simplex, &count, lambda, &s, &x_new);
            enclosed = v3_norm2(x_new) == 0.0;
        } else {
            enclosed = update_simplex(simplex, &count, lambda, &s, &x_new);
        }
        double x_new2 = v3_norm2(x_new);
        int no_progress = have_x && !enclosed && x_new2 >= v3_norm2(x);
        x = x_new;
        have_x = 1;
        out->gap_valid = 0;
        if (enclosed || x_new2 == 0.0 ||
            sqrt(x_new2) + noise_scale(md) < md->margin) {
            out->outcome = AGJK__INTERSECTING;
            break;
        }
        /* x is zero to rounding: the cores touch or overlap within what double
         * precision can tell (plain FW creeps towards such an x forever). */
        if (sqrt(x_new2) <= noise_scale(md)) { out->outcome = AGJK__AT_ROUNDING; break; }
        if (no_progress) {
            /* Plain directions must decrease ||x||; if rounding stops that,
             * further iterations would only cycle. With momentum, no progress
             * is the fixed point of eq. 28 (s_k adds nothing to the simplex):
             * switch to GJK directions, even if g has not met the tolerance
             * (a relative tolerance on overlapping shapes never does). */
            if (!m.active) { out->outcome = AGJK__STALLED; break; }
            m.active = 0;
            out->momentum_stop = k;
        }
        /* Adaptive method: the planes met so far may certify x_{k+1} already,
         * before any support in its direction. */
        if (m.method == AGJK_METHOD_ADAPTIVE && plane_stops(&m, in, md, x, out)) break;
        /* d_{k-1}, s_{k-1}; the adaptive method may switch phase here. */
        if (agjk__momentum_update(&m, k, d, &s)) out->momentum_stop = k;
    }

    /* Without a valid gap at the final iterate (cap, stall, or momentum still
     * on), one support in direction x certifies what was reached. */
    if ((out->outcome == AGJK__ITERATION_CAP || out->outcome == AGJK__STALLED ||
         out->outcome == AGJK__AT_ROUNDING) && have_x && !out->gap_valid) {
        agjk_vec3 d = x;
        agjk__minkowski_support(md, x, &s);
        ++out->support_calls;
        follow_rescale(md, simplex, count, &x, &m, &d);
        if (!support_ends_query(md, in, x, &s, out)) {
            out->gap = 2.0 * v3_dot(x, v3_sub(x, s.w));
            out->gap_valid = 1;
        }
    }

    out->x = x;
    out->noise = noise_scale(md);
    out->count = count;
    for (int i = 0; i < count; ++i) out->simplex[i] = simplex[i];
    out->flat = m.flat_seen;
    agjk_vec3 a = v3(0.0, 0.0, 0.0), b = v3(0.0, 0.0, 0.0);
    for (int i = 0; in->want_witness && i < count; ++i) {
        a = v3_add(a, v3_scale(simplex[i].a, lambda[i]));
        b = v3_add(b, v3_scale(simplex[i].b, lambda[i]));
    }
    out->a = a;
    out->b = b;
}
