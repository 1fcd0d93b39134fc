/* SPDX-License-Identifier: MIT */
/* Internal: the Frank-Wolfe family loop (GJK, accelerated GJK, plain FW) and
 * its direction policy. */
#ifndef AGJK_SRC_SOLVER_H
#define AGJK_SRC_SOLVER_H

#include "minkowski.h"

/* Direction policy state (Montaut et al. 2022, Alg. 6/7; GJK++ for Polyak;
 * the adaptive rule of direction.c). */
typedef struct agjk__momentum {
    agjk_method method;
    int active;       /* momentum still in use (0 after the Alg. 6 fallback) */
    agjk_vec3 d_prev; /* d_{k-1} */
    agjk_vec3 s_prev; /* s_{k-1} */
    /* AGJK_METHOD_ADAPTIVE only (see direction.c). */
    int phase;        /* AGJK__PHASE_* */
    double plane;     /* best lower bound max <d_i, s_i> / ||d_i|| on ||x*||, solver units */
    double plane_before; /* plane before the last support */
    double omega;     /* <d, s> / ||d|| of the last support */
    agjk_vec3 x_k;    /* iterate at which the last support was asked */
    agjk_vec3 d_best; /* direction of the best plane */
    uint64_t a_seen[2], b_seen[2]; /* keys of the points of A and B of the last two
                                      supports (direction.c) */
    double x0_norm2;  /* ||x_0||^2, solver units (-1 before the first support) */
    int flat_seen;    /* a point of A or B came back bit for bit (any method) */
    int plain_steps;  /* adaptive: iterations that may take plain steps when far */
    int boolean;      /* Boolean mode (Alg. 2): the adaptive method's first-support test */
    int guard_from;   /* adaptive: first iteration of the Nesterov phase's restart and
                         plain-step tests (direction.c, ADAPTIVE_BOOLEAN_FREE) */
} agjk__momentum;

/* Phases of the adaptive method; the other methods stay in AGJK__PHASE_FIXED. */
enum { AGJK__PHASE_FIXED = 0, AGJK__PHASE_POLYAK, AGJK__PHASE_NESTEROV, AGJK__PHASE_FINAL };

/* Prepares the policy for a query started at x_0; given: x_0 is a caller's or
 * a cache's guess of x* (the adaptive method then trusts it from the start);
 * boolean: the query stops at the first separating plane (Alg. 2). */
void agjk__momentum_init(agjk__momentum *m, agjk_method method, agjk_vec3 x0, int given,
                         int boolean);

/* Momentum weights for the first AGJK__MOMENTUM_TABLE iterations, as
 * constants (direction.c): Nesterov's delta_k = (k+1)/(k+3) and Polyak's
 * 1/(k+1), the very values the divisions give (correctly rounded either
 * way). Those divisions sat at the start of every iteration, ahead of the
 * direction the next support waits for, on the unit that the supports'
 * square roots and divisions and the projection's divisions need too
 * (close Boolean ellipsoids with Nesterov: 3% of their time). */
#define AGJK__MOMENTUM_TABLE 64
#define AGJK__NESTEROV_DELTA(k) (((k) + 1.0) / ((k) + 3.0))
#define AGJK__POLYAK_DELTA(k) (1.0 / ((k) + 1.0))
extern const double agjk__nesterov_delta[AGJK__MOMENTUM_TABLE];
extern const double agjk__polyak_delta[AGJK__MOMENTUM_TABLE];

static inline double agjk__nesterov_weight(int k) {
    return k < AGJK__MOMENTUM_TABLE ? agjk__nesterov_delta[k] : AGJK__NESTEROV_DELTA((double)k);
}

static inline double agjk__polyak_weight(int k) {
    return k < AGJK__MOMENTUM_TABLE ? agjk__polyak_delta[k] : AGJK__POLYAK_DELTA((double)k);
}

/* Alg. 6 lines 1-3: delta_k = (k+1)/(k+3),
 * y_k = delta_k x_k + (1 - delta_k) s_{k-1},
 * d_k = delta_k d_{k-1} + (1 - delta_k) grad f(y_k). */
static inline agjk_vec3 agjk__nesterov_mix(const agjk__momentum *m, int k, agjk_vec3 x) {
    double delta = agjk__nesterov_weight(k), rest = 1.0 - delta;
    /* Expanded, d_k = delta (1 - delta) x_k + c with c = delta d_{k-1} +
     * (1 - delta)^2 s_{k-1}: c is ready before x_k, so x_k reaches d_k
     * through one multiplication and one addition instead of two of each
     * (GJK's chain of dependent steps, from one support to the next). */
    agjk_vec3 c = v3_lerp2(m->d_prev, delta, m->s_prev, rest * rest);
    return v3_add(v3_scale(x, delta * rest), c);
}

/* GJK++ (Montaut et al.): heavy-ball momentum on the direction,
 * d_k = delta d_{k-1} + (1 - delta) x_k (delta_k = 1/(k+1) for Polyak). */
static inline agjk_vec3 agjk__polyak_mix(const agjk__momentum *m, double delta, agjk_vec3 x) {
    return v3_lerp2(m->d_prev, delta, x, 1.0 - delta);
}

/* x itself, out of line (direction.c): called only when a momentum
 * combination carries no direction, so that the test below compiles to a
 * branch, predicted, rather than to a select the next support's direction
 * would wait for (agjk-bench, same-run: overlapping Boolean boxes with
 * Polyak 3.1% faster, hulls 1-3%). */
agjk_vec3 agjk__gradient_instead(agjk_vec3 x);

/* A zero or non-finite combination carries no direction: the gradient x
 * instead. (One test: the 1-norm is NaN or Inf with any such coordinate, and
 * 0 only for the zero vector.) */
static inline agjk_vec3 agjk__direction_or_gradient(agjk_vec3 d, agjk_vec3 x) {
    double n1 = v3_norm1(d);
    return n1 > 0.0 && n1 <= DBL_MAX ? d : agjk__gradient_instead(x);
}

/* Normalised Nesterov and the adaptive rule (direction.c), untested as
 * agjk__momentum_mix's. */
agjk_vec3 agjk__momentum_direction_other(const agjk__momentum *m, int k, agjk_vec3 x);

/* Support direction d_k for iterate x_k at iteration k while momentum is
 * active, before the test of agjk__direction_or_gradient, which the caller
 * makes (see solve() in solver.c). Nesterov's and Polyak's mixes inline: a
 * few operations, where the call took 3% of a Nesterov query on overlapping
 * ellipsoids. */
static AGJK__ALWAYS_INLINE agjk_vec3 agjk__momentum_mix(const agjk__momentum *m, int k,
                                                        agjk_vec3 x) {
    if (m->method == AGJK_METHOD_NESTEROV) return agjk__nesterov_mix(m, k, x);
    if (m->method == AGJK_METHOD_POLYAK)
        return agjk__polyak_mix(m, agjk__polyak_weight(k), x);
    return agjk__momentum_direction_other(m, k, x);
}

/* Adaptive method, iteration 1 of the Polyak phase: the direction in which
 * to retry a support that returned s_0 again (direction.c). */
agjk_vec3 agjk__momentum_retry(const agjk__momentum *m, agjk_vec3 x);

/* <d, s> / ||d|| for a direction whose squared norm leaves [2^-900, 2^900]
 * (direction.c). */
double agjk__plane_of_extreme(agjk_vec3 d, agjk_vec3 s);

/* Adaptive method: records the support plane of s (a point of D) found in
 * direction d at iterate x (before the stopping tests). Inline: the call
 * passed three vectors through memory on every iteration (1.3-1.5% of an
 * adaptive query's time on close ellipsoids and boxes). */
static inline void agjk__momentum_plane(agjk__momentum *m, agjk_vec3 d, agjk_vec3 s,
                                        agjk_vec3 x) {
    double n2 = v3_norm2(d);
    if (n2 >= 0x1p-900 && n2 <= 0x1p900)
        m->omega = v3_dot(d, s) / sqrt(n2);
    else
        m->omega = agjk__plane_of_extreme(d, s);
    m->plane_before = m->plane;
    if (m->x0_norm2 < 0.0) m->x0_norm2 = v3_norm2(x); /* the first plane: x = x_0 */
    if (m->omega > m->plane) {
        m->plane = m->omega;
        m->d_best = d;
    }
    m->x_k = x;
}

/* End of iteration k, which searched direction d and found s, and moved the
 * iterate to x_{k+1} of squared norm x2_new: keeps d and s as d_{k-1},
 * s_{k-1}, and lets the adaptive method switch phase. Returns 1 when the
 * adaptive method switched momentum off for good. */
int agjk__momentum_update(agjk__momentum *m, int k, agjk_vec3 d, const agjk__vertex *s,
                          double x2_new);

/* Multiplies the policy's stored vectors by the power of two f (rescaling). */
void agjk__momentum_rescale(agjk__momentum *m, double f);

/* Whether a method uses momentum at all. */
int agjk__method_has_momentum(agjk_method method);

typedef enum agjk__outcome {
    AGJK__CONVERGED,      /* duality gap met the requested tolerance */
    AGJK__AT_FLOOR,       /* gap down to what double precision resolves, above the request */
    AGJK__INTERSECTING,   /* origin enclosed (or core distance below the margins) */
    AGJK__SEPARATED_EARLY,/* Boolean mode: a separating plane was found */
    AGJK__ITERATION_CAP,
    AGJK__STALLED,        /* no decrease of ||x|| in floating point */
    AGJK__AT_ROUNDING,    /* ||x|| below the rounding level: touching to rounding */
    AGJK__BAD_SUPPORT     /* a support callback returned a non-finite point */
} agjk__outcome;

typedef struct agjk__solve_input {
    agjk_method method;
    int boolean_mode;   /* early exit on a separating plane (Alg. 2) */
    int want_witness;   /* combine the simplex's points of A and B at the end */
    int relative;       /* tolerance relative to ||x||^2 */
    double tolerance;
    int max_iterations;
    agjk_vec3 x0;       /* initial guess (A's frame), non-zero */
    int x0_given;       /* x0 is a caller's or a cache's guess, not c_A - c_B */
    /* With x0_along set, a vector along x0 (finite, non-zero) that is known
     * before x0's length: the first support is taken along it, and its
     * result is x0's (the cache's extrapolated direction, whose weight
     * takes square roots and divisions that the support need not wait for). */
    agjk_vec3 along;
    int x0_along;
    /* A power of two that brings x0 (c_A - c_B, no guess) to a unit-size
     * direction, max |x0_i| in [1, 8): known from the world offset before
     * x0 is (agjk__query_prepare), so that the first support need not wait
     * for x0's own max and exponent. 0 when not known: distance queries
     * (agjk__query_prepare), a guess, and a warm start's x0 (cache.c). */
    double x0_unit;
    /* With x0_unit and B an ellipsoid (x0_b_given): x0 turned into B's
     * frame, R^T x0, formed from the world offset as R_B^T (t_A - t_B), so
     * that B's first direction need not wait for x0 and then for its turn
     * (a rounding of R^T x0, as a face's turned foot is; see
     * agjk__minkowski_support's db_given). B's ellipsoid support is on the
     * chain to a Boolean query's first plane test; for other shapes the
     * turn is not, and its instructions would only cost. */
    agjk_vec3 x0_b;
    int x0_b_given;
    /* Keep the points of A and B of the active set (witness points, EPA, the
     * cache); otherwise only the points of D move. */
    int keep_points;
    /* Record whether a point of A or B came back (flat faces; the cache keeps it). */
    int track_flat;
    /* Copy the final active set to the output (EPA, the cache); otherwise
     * simplex_count is 0. */
    int want_simplex;
    /* Warm start (cache.c): up to 4 points of D in A's frame, caller units,
     * whose projection is x0; warm_count 0 for a cold start. */
    int warm_count;
    agjk__vertex warm[4];
    unsigned warm_mask;       /* their projection: support mask, weights, point */
    double warm_lambda[4];
    agjk_vec3 warm_x;
} agjk__solve_input;

typedef struct agjk__solve_output {
    agjk__outcome outcome;
    agjk_vec3 x;         /* final iterate (A's frame) */
    /* sum lambda_i w_i over the final active set: a point of D up to the
     * rounding of the points, however ill-conditioned the projection that
     * gave x was (a sliver's foot can be far off its plane); ||x_member||
     * is the certified upper bound on the core distance. x itself after an
     * overlap (AGJK__INTERSECTING), which has no upper bound to certify. */
    agjk_vec3 x_member;
    agjk_vec3 a, b;      /* core points on A and B with a - b = x (A's frame) */
    agjk_vec3 direction; /* separating direction (SEPARATED_EARLY), or the normal of
                            the support plane that certified x when it is not x
                            itself (adaptive method), else zero */
    double gap;          /* duality gap at x; valid when gap_valid */
    int gap_valid;
    /* ||x - s||^2 for the support s that gave that gap, where the query
     * ended on one (else 0): the measure of gap_verdict's wide floor, which
     * query.c applies to an interval widened by an inexact member point. */
    double xs2;
    double noise;        /* floating-point error scale of w, length units */
    int iterations;
    int support_calls;
    int momentum_stop;
    /* The final active set (A's frame, solver units; a and b only when
     * keep_points): EPA starts from it, the cache keeps it. */
    agjk__vertex simplex[4];
    int simplex_count;
    /* The final active set is the warm start's, whole and in its order
     * (in->warm[0 .. warm_count - 1], simplex_count of them): then `simplex`
     * is not written. */
    int warm_kept;
    int flat;            /* a point of A or B came back (flat faces), for the cache */
} agjk__solve_output;

/* The square of the floor a gap g at x is resolved to (noise: the
 * floating-point error scale of the points): g <= 2 noise (||x|| +
 * ||x - s||), squared and bounded above by 8 noise^2 (||x||^2 + ||x - s||^2),
 * for xs2 = ||x - s||^2 of the support s that gave it; 4 noise^2 ||x||^2
 * where none did (xs2 = 0). The solver's verdict on a gap and query.c's on
 * an interval widened by an inexact member point use it alike. */
static inline double agjk__gap_floor2(double noise, double x2, double xs2) {
    double noise2 = noise * noise;
    return xs2 > 0.0 ? 8.0 * noise2 * (x2 + xs2) : 4.0 * noise2 * x2;
}

/* Iteration 0's outcome: the support point s, the direction x it was taken
 * in (x_0 in solver units), and in Boolean mode whether its plane already
 * separates the shapes (Alg. 2). */
typedef struct agjk__start {
    agjk__vertex s;
    agjk_vec3 x;
    int separated; /* 0, 1, or AGJK__START_APART */
} agjk__start;

/* The support value h(d) = max <d, p> over a built-in ellipsoid (||D d||,
 * D its radii: agjk__ellipsoid_root) or box (sum h_i |d_i|, h its half
 * extents), computed without the point. For an ellipsoid, *root is ||D d||
 * too, for its support point (agjk__ellipsoid_from_root); d and -d give
 * the same values. Returns 0 for other shapes, and for an ellipsoid whose
 * ||D d||^2 lies near underflow or overflow. */
static AGJK__ALWAYS_INLINE int agjk__support_value(agjk_support_fn fn, const void *data,
                                                   agjk_vec3 d, double *h, double *root) {
    if (agjk__is_box(fn)) {
        agjk_vec3 e = ((const agjk_box *)data)->half_extents;
        *h = e.x * fabs(d.x) + e.y * fabs(d.y) + e.z * fabs(d.z);
        return 1;
    }
    if (agjk__is_ellipsoid(fn) && agjk__ellipsoid_root((const agjk_ellipsoid *)data, d, root)) {
        *h = *root;
        return 1;
    }
    return 0;
}

/* The largest |p_i| over such a shape: its largest radius or half extent. */
static AGJK__ALWAYS_INLINE double agjk__extent(agjk_support_fn fn, const void *data) {
    return agjk__is_box(fn) ? v3_maxabs(((const agjk_box *)data)->half_extents)
                            : v3_maxabs(((const agjk_ellipsoid *)data)->radii);
}

/* Ellipsoids and boxes in a Boolean query started at x_0 = c_A - c_B:
 * Alg. 2's first plane test from the shapes' support values
 * (agjk__support_value) instead of from the support points. With u the
 * unit-size x_0 and u_B its turn into B's frame, the plane of normal u
 * through the support point s has <u, s> = <u, x_0> - h_A(u) - h_B(u_B):
 * for ellipsoids two square roots, where the points take a square root and
 * then a division each before the test can start, and for boxes no point,
 * no rotation of B's into A's frame and no product with u (one-support
 * Boolean queries: ellipsoids 62.8 -> 53.0 ns, boxes 56.6 -> 52.4).
 * The allowance, 128 eps (max extent of A + that of B + max |t_i|) besides
 * the margins, is 32 times the support path's for these points (whose
 * coordinates the extents bound) and covers what this test rounds besides:
 * the support values (a few ulps of h <= max extent ||u||_1), <u, x_0> and
 * the offset's turn into A's frame (a few ulps of ||u|| ||t||), and u_B
 * being R^T u only to some 50 ulps of ||u|| when turned from the world
 * offset by R_B^T for rotations orthonormal to 16 ulps (x0_b_given
 * requires that; tests/core/test_collide.c finds false planes with an
 * allowance of 1 eps, none with 2). A query it does not settle takes the
 * support as ever, with the same bits (an ellipsoid's ||D u|| in *root_a or
 * *root_b for agjk__minkowski_support, left 0 otherwise). Problems of
 * ordinary size only (the scale of 1 that agjk__minkowski_set_scale would
 * keep). Returns 1 when the plane separates, else 0 (the points' own test
 * then decides, as it always did). */
static AGJK__ALWAYS_INLINE int agjk__start_apart(const agjk__minkowski *md, agjk_vec3 u,
                                                 agjk_vec3 ub, double reach, double *root_a,
                                                 double *root_b) {
    double ha, hb;
    if (!agjk__support_value(md->support_a, md->data_a, u, &ha, root_a) ||
        !agjk__support_value(md->support_b, md->data_b, ub, &hb, root_b))
        return 0;
    double dw = reach - ha - hb;
    /* (The extents only when the plane may separate: shapes whose extents
     * along u overlap, as in a query that goes on, pay for no more.) */
    if (!(dw > 0.0)) return 0;
    double size = agjk__extent(md->support_a, md->data_a) +
                  agjk__extent(md->support_b, md->data_b) + md->translation_size;
    double r = md->margin + 128.0 * DBL_EPSILON * size;
    return size >= 0x1p-100 && size <= 0x1p100 && dw * dw > v3_norm2(u) * r * r;
}

/* Shapes whose support values agjk__start_apart takes. */
static inline int agjk__has_support_value(agjk_support_fn fn) {
    return agjk__is_box(fn) || agjk__is_ellipsoid(fn);
}

/* agjk__first_support's answer when the support values of ellipsoids or
 * boxes decided (agjk__start_apart): separated, with no support point
 * written (only x). */
#define AGJK__START_APART 2

/* Iteration 0: the support in direction x_0 for every method (d_{-1} =
 * s_{-1} = x_0 gives d_0 = x_0), which also tells the problem's size: from
 * then on the solver works in units where it is about 1
 * (agjk__minkowski_set_scale). Writes the support point to *s and the
 * direction, x_0 in solver units, to *x_out; returns 1 when, in Boolean
 * mode, its plane already separates the shapes, and AGJK__START_APART when
 * try_apart (the caller answers such a start with the world offset's
 * normal) and the support values of two ellipsoids or boxes showed that
 * before any support was taken (agjk__start_apart). Such a start ends the
 * query before the solver sets anything up: its caller answers from it
 * alone (a tenth of a one-support query's instructions; inline, so that the
 * point stays in registers). */
static AGJK__ALWAYS_INLINE int agjk__first_support(agjk__minkowski *md,
                                                   const agjk__solve_input *in, agjk__vertex *s,
                                                   agjk_vec3 *x_out, int try_apart) {
    agjk_vec3 x = v3_load_scalars(&in->x0); /* (written just before, by other code) */
    /* The problem's size is not known yet: give the callbacks a unit-size
     * direction (exact power-of-two scaling of x_0, or of a vector along it). */
    agjk_vec3 along = in->x0_along ? v3_load_scalars(&in->along) : x;
    /* (One call site: the support path is expanded once here.) */
    agjk_vec3 unit, db = x;
    int db_given = 0;
    double root_a = 0.0, root_b = 0.0;
    if (!in->x0_given && in->x0_unit > 0.0) {
        unit = v3_scale(x, in->x0_unit);
        if (in->x0_b_given) {
            db = v3_scale(v3_load_scalars(&in->x0_b), in->x0_unit);
            db_given = 1;
        }
        if (try_apart && agjk__has_support_value(md->support_a) &&
            agjk__has_support_value(md->support_b)) {
            /* (B's direction, which the support then takes as given.) */
            if (!db_given) {
                db = m3_tmul(&md->rotation[0][0], unit);
                db_given = 1;
            }
            /* (<u, x_0> = x0_unit ||x_0||^2.) */
            if (agjk__start_apart(md, unit, db, in->x0_unit * v3_norm2(x), &root_a, &root_b)) {
                *x_out = x;
                return AGJK__START_APART;
            }
        }
    } else {
        unit = v3_scale_to_unit(along, v3_maxabs(along));
    }
    agjk__minkowski_support(md, unit, 0.0, s, AGJK__SUPPORT_DIRECT_FIRST, db_given ? &db : NULL,
                            root_a, root_b, NULL);
    /* A shrink during that first call already put s in new units; x_0, given
     * in the caller's units, needs it too. */
    double shrunk = md->rescaled;
    md->rescaled = 1.0;
    double f = agjk__minkowski_set_scale(md);
    if (f != 1.0) {
        s->w = v3_scale(s->w, f);
        s->a = v3_scale(s->a, f);
        s->b = v3_scale(s->b, f);
    }
    if (shrunk != 1.0 || f != 1.0) {
        agjk_vec3 x_units = v3_scale(v3_scale(x, shrunk), f);
        /* A guess far off the problem's size (a caller's, or a denormal offset
         * that underflows when scaled) only gives a direction. */
        if (!v3_in_range(x_units) || v3_maxabs(x_units) < 1.0 / AGJK_MAX_COORDINATE)
            x_units = v3_normalize(x);
        x = x_units;
    }
    *x_out = x;
    return in->boolean_mode && !md->bad_support && agjk__minkowski_separates(md, x, s->w);
}

/* The same into `start`. */
static AGJK__ALWAYS_INLINE int agjk__solve_start(agjk__minkowski *md, const agjk__solve_input *in,
                                                 agjk__start *start, int try_apart) {
    return start->separated = agjk__first_support(md, in, &start->s, &start->x, try_apart);
}

/* The solver from iteration 0's support on, `start` (for a separated start
 * it only writes the early exit's output). */
void agjk__solve_from(agjk__minkowski *md, const agjk__solve_input *in, const agjk__start *start,
                      agjk__solve_output *out);

/* The whole query's solver run, iteration 0 included. */
void agjk__solve(agjk__minkowski *md, const agjk__solve_input *in, agjk__solve_output *out);

#endif
