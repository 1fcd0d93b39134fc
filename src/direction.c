/* SPDX-License-Identifier: MIT */
/* Direction policies with momentum for the Frank-Wolfe family loop.
 *
 * We minimise f(x) = ||x||^2 and only the direction of the gradient matters to
 * the support function (paper eq. 9), so we use grad f(y)/2 = y, as the
 * reference implementation does (Coal); d_{-1} = s_{-1} = x_0.
 *
 * The adaptive method (AGJK_METHOD_ADAPTIVE) chains these policies by what the
 * supports reveal, measured on the benchmark (README, "The adaptive method"):
 *
 *   1. Polyak phase: heavy-ball directions (GJK++), best while the shapes are
 *      far apart relative to their size (plain GJK converges fast there and
 *      Nesterov's momentum only delays it).
 *   2. Nesterov phase (Alg. 6): entered at the end of the first iteration whose
 *      best support plane is below 0.9 ||x_k|| (a relative gap of 10% or more:
 *      close or overlapping shapes, where momentum pays).
 *      In both phases, iterations 1 and 2 take plain GJK steps while the best
 *      plane says far apart (ADAPTIVE_PLAIN_STEPS; in the Nesterov phase only
 *      while ||x_k|| >= 0.3 ||x_0||, ADAPTIVE_FAR_SIZE), and iteration 1 also
 *      when s_0 lies opposite x_0 (ADAPTIVE_OPPOSITE_RATIO).
 *      A given x_0 (a cache's or a caller's guess) starts in the Nesterov
 *      phase; in Boolean mode so does, from iteration 1 and with its first
 *      step unguarded, a cold start whose s_0 lies shallow behind the plane
 *      of x_0 (ADAPTIVE_BOOLEAN_SHALLOW: near contact, not deep overlap).
 *      A Nesterov direction against the gradient x_k (or nearly across it at
 *      iteration 2 after a plain step) is replaced by a plain step
 *      (ADAPTIVE_AGAINST_COS).
 *   3. Plain GJK to the end: after the Alg. 6 fallback; after iteration 1 of
 *      the Polyak phase when its support was s_0 again (retried once in the
 *      normalised Nesterov direction, agjk__momentum_retry); as soon as a Nesterov
 *      support gives a worse lower bound <d_k, s_k> / ||d_k|| than the best so
 *      far (the momentum overshoots: adaptive restart in the sense of
 *      O'Donoghue and Candes, "Adaptive restart for accelerated gradient
 *      schemes", 2015, here restarting to the gradient direction for good),
 *      or from iteration 8 on as soon as a Nesterov step closes too little
 *      of the gap the best plane leaves (ADAPTIVE_CREEP);
 *      or as soon as a support point of A or of B repeats exactly (a vertex:
 *      flat faces, where GJK's exact steps beat momentum).
 *
 * Every support s found in a direction d gives the plane <d, .> >= <d, s> that
 * bounds D, hence ||x*|| >= <d, s> / ||d||, whatever d was (momentum or not).
 * The solver stops as soon as the best such plane certifies x_k; this removes
 * the extra support in direction x_k that Alg. 6 pays to get a duality gap. */
#include "solver.h"

/* (solver.h: agjk__nesterov_weight, agjk__polyak_weight) The formulas at
 * k = 0 ... 63, folded by the compiler: an exact integer in k converts to
 * the same double as at run time, and the division rounds the same way. */
#define AGJK__TABLE4(f, k) f(k), f(k + 1), f(k + 2), f(k + 3)
#define AGJK__TABLE16(f, k) AGJK__TABLE4(f, k), AGJK__TABLE4(f, k + 4), AGJK__TABLE4(f, k + 8), \
                            AGJK__TABLE4(f, k + 12)
#define AGJK__TABLE64(f) AGJK__TABLE16(f, 0), AGJK__TABLE16(f, 16), AGJK__TABLE16(f, 32), \
                         AGJK__TABLE16(f, 48)
const double agjk__nesterov_delta[AGJK__MOMENTUM_TABLE] = {AGJK__TABLE64(AGJK__NESTEROV_DELTA)};
const double agjk__polyak_delta[AGJK__MOMENTUM_TABLE] = {AGJK__TABLE64(AGJK__POLYAK_DELTA)};

/* The shapes count as far apart while the best support plane is at least this
 * fraction of ||x_k|| (a relative gap below 10%); below it the Polyak phase
 * hands over to Nesterov (measured: 0.8 ... 0.97 give the same means to
 * +-0.2 support calls). */
#define ADAPTIVE_CLOSE_RATIO 0.9

/* Far apart, iterations 1 and 2 take plain GJK directions: on polytopes the
 * closest points are often two vertices, which GJK certifies with its second
 * support, while any mix of x_0 and x_1 lands on the same vertex again (a
 * normal cone is convex) and wastes a support. Measured (seeds 1-4, support
 * calls per query, distant boxes): 4.14 -> 3.65-3.86, the plain GJK figure;
 * 3 steps or more cost distant ellipsoids 0.3-1.3 calls. The test is made at
 * each of these iterations, also after an early switch to Nesterov: a
 * Nesterov step at iteration 2 with the best plane back above 0.9 ||x_2||
 * lost 0.03-0.05 calls on distant boxes (a plain step at iteration 1 instead,
 * whatever the plane, loses 0.2 there: x_0 in the momentum pays). */

/* ... but only while ||x_k|| is still at least this fraction of ||x_0||: on
 * curved shapes whose iterate has already shrunk well below the centre
 * distance, the Nesterov step at iteration 2 pays (without this test: close
 * ellipsoids 8.76 -> 9.37 calls, distant 7.66 -> 7.86; seeds 1-6, 0.3 keeps
 * them within 0.06 and distant boxes 0.001-0.05 below GJK, 0.4 and 0.5 leave
 * seed 1 at or 0.002 above it). */
#define ADAPTIVE_FAR_SIZE 0.3
#define ADAPTIVE_PLAIN_STEPS 2

/* At iteration 1, a first support point nearly opposite x_0 (its plane below
 * -0.9 ||x_1||: overlapping shapes, s_0 = x_1 deep along -x_0) leaves the
 * momentum mix of x_0 and x_1 on the line of x_0, where it finds s_0 again on
 * a polytope (a wasted support); a plain step then. Measured (seeds 1-6,
 * overlapping boxes): 0.9 saves 0.02-0.03 calls, 0.5 and 0.7 lose on boxes and
 * cost ellipsoids 0.03-0.1. */
#define ADAPTIVE_OPPOSITE_RATIO 0.9

/* A repeated point of A or B is looked for among the last two supports (a
 * box's vertex often comes back two supports later): seeds 1-4, distant
 * boxes, 0.02-0.03 calls fewer than with the last support alone; the last
 * four gave the same counts to 0.007. */

/* A Nesterov direction d_k with <d_k, x_k> < 0 points away from the descent
 * direction: the momentum has overshot (the gradient test of O'Donoghue and
 * Candes' adaptive restart). Its support is wasted: on stiff ellipsoids
 * (needles, pancakes) the iterate zigzags within a segment of D for a dozen
 * supports while each plane is a little better than the last, so the plane
 * test never fires. A plain step in direction x_k instead, whose plane then
 * usually is worse than the best and restarts to GJK for good. At iteration
 * 2 right after a plain step at iteration 1 (s_0 was opposite x_0, or the
 * shapes far apart) already when the cosine of d_k and x_k is below this:
 * the mix, dominated by the long x_0, there often lands on s_0 again (flat
 * boxes, overlapping). Measured (support calls per distance query, seeds
 * 1-3; stress set at 60 pairs x 5 poses): stiff ellipsoids overlapping
 * 12.95 / 13.15 / 13.37 -> 11.87 / 11.85 / 12.05 (GJK 11.97 / 12.16 /
 * 12.32), close 13.37 / 12.37 / 12.62 -> 13.32 / 12.00 / 12.16, flat boxes
 * overlapping 5.25 / 5.29 / 5.25 -> 5.12 / 5.13 / 5.09 (GJK 5.16 / 5.10 /
 * 5.10); the protocol's overlapping boxes 4.91 / 4.91 / 4.98 -> 4.77 /
 * 4.75 / 4.80, hulls 5.58 / 5.74 / 5.75 -> 5.40 / 5.57 / 5.64, meshes
 * 5.58 / 5.58 / 5.53 -> 5.45 / 5.44 / 5.39, ellipsoids 5.41 / 5.49 / 5.52
 * -> 5.23 / 5.34 / 5.34, no row of the protocol higher (on the stress set
 * touching ellipsoids overlapping +0.01-0.13, still 1.3 below the best of
 * the four). The test at 0 gives flat boxes 0.06-0.08 of their gain, the
 * iteration-2 test the rest; there 0.1, 0.3, 0.5 and 0.8 gave the same means
 * to 0.02. Rejected (measured with a restart on small progress also in
 * place): a cosine threshold of 0.1 at every iteration (close ellipsoids
 * +0.1-0.16, touching ellipsoids +0.3-0.7), or 0.1 at iteration 2 whatever
 * the step before (close ellipsoids +0.1); and (without it) the test after
 * the support instead of before, a restart once the support is paid: stiff
 * ellipsoids overlapping 12.34 / 12.32 / 12.44. */
#define ADAPTIVE_AGAINST_COS 0.3

/* From iteration ADAPTIVE_CREEP_FROM on, restart (plain GJK to the end)
 * after a Nesterov step that shrinks ||x|| by less than ADAPTIVE_CREEP of the
 * gap ||x_k|| - max(plane, 0) that the best support plane leaves. The
 * momentum term, a mix of the early, much longer iterates, swamps the
 * gradient once ||x|| has shrunk by orders of magnitude, and the iterate
 * creeps along a face for tens of iterations while every plane still
 * improves, so the plane test never fires (stiff ellipsoids: 59 supports
 * instead of GJK's 20 on one overlapping needle pair). Relative to the gap,
 * not to ||x||: near the optimum of close shapes ||x|| barely moves while the
 * gap halves at each step (a test on ||x|| alone, 1% of it, cost the
 * protocol's close ellipsoids 8.77 -> 10.32 calls). Measured (support calls
 * per distance query, seeds 1 / 2 / 3; stress set at 60 pairs x 5 poses):
 * stiff ellipsoids overlapping 11.87 / 11.85 / 12.05 -> 11.63 / 11.77 /
 * 11.85, close 13.32 / 12.00 / 12.16 -> 12.39 / 11.10 / 11.07, distant
 * 10.07 / 9.18 / 8.75 -> 9.46 / 8.53 / 8.34; every row of the protocol the
 * same to 0.005. From iteration 0 (the gains 0.1-0.5 calls larger) it cost
 * the protocol's close ellipsoids 8.77 / 8.81 / 8.91 -> 8.78 / 8.85 / 8.96
 * and close hulls (seed 3) 7.33 -> 7.36, from iteration 4 8.77 / 8.82 / 8.94
 * and 7.34, from 6 8.92 on seed 3; thresholds 0.1 and 0.2 from iteration 8
 * gave the stiff rows within 0.1 of 0.05. */
#define ADAPTIVE_CREEP_FROM 8
#define ADAPTIVE_CREEP 0.05

/* Weight of d_0 in the first Polyak step (Polyak: 1/2). Measured, seeds 1-4:
 * 0.3 brings close and overlapping boxes and meshes from 0.1-0.3 calls above
 * the best of GJK / Nesterov / normalised Nesterov / Polyak to at or below it,
 * at the price of 1.5 calls on close ellipsoids (still 2 below the best). */
#define ADAPTIVE_POLYAK_FIRST 0.3

/* Boolean mode (Alg. 2: the query ends at the first separating plane), cold
 * start, s_0 not separating: when s_0 lies shallow behind the plane through
 * the origin normal to x_0, -<x_0, s_0> < ADAPTIVE_BOOLEAN_SHALLOW ||s_0||^2
 * (at 0.5: ||x_0 + s_0|| > ||x_0||), the Nesterov phase from iteration 1 with
 * no plain steps, its first step (the mix (x_0 + s_0) / 2) taken whatever its
 * direction and plane: the restart and plain-step tests apply from iteration
 * ADAPTIVE_BOOLEAN_FREE on. Near contact the separating normal is x_0 turned
 * a little toward s_0, which that mix reaches one or two supports before the
 * Polyak phase's 0.3 x_0 + 0.7 s_0 (one ellipsoid pair 1e-3 apart: planes at
 * -2e-4 against -0.09). A deep s_0 (overlaps, long shapes across each other)
 * keeps the rules above, whose steps toward x_k grow GJK's tetrahedron about
 * the origin; the cosine of x_0 and s_0 alone does not tell the two apart
 * (ellipsoids 1e-3 apart and 1e-3 overlapping: medians -0.09 and -0.10).
 * Measured (support calls per Boolean query; seeds 1 / 2 tuned, 3 / 4 held
 * out): close ellipsoids 2.86 / 2.93 / 2.93 / 2.93 -> 2.37 / 2.42 / 2.44 /
 * 2.35 (Nesterov 2.16-2.22), overlapping 5.23-5.34 -> 4.99-5.16; close hulls
 * 3.56 / 3.65 / 4.20 / 3.71 -> 3.33 / 3.35 / 3.70 / 3.45; close meshes down
 * 0.09-0.13, boxes close 0.07-0.16, overlapping shapes 0.01-0.2, distant
 * boxes to Nesterov's figure; seed 4's overlapping hulls up 0.04 (5.40 ->
 * 5.44, the best fixed method 6.32). Thresholds 0.4 / 0.6: close ellipsoids
 * 2.54 / 2.24, overlapping 5.07 / 5.43. Tests from iteration 1: close
 * ellipsoids 2.43; from 3 to 6: overlapping boxes worse; never: overlapping
 * ellipsoids worse. Rejected: Alg. 6 for every start (close ellipsoids 2.16,
 * overlapping 6.73), the Polyak phase's first weight 0.5 (overlapping 7.00:
 * the restart tests hand them to plain GJK, which creeps). */
#define ADAPTIVE_BOOLEAN_SHALLOW 0.5
#define ADAPTIVE_BOOLEAN_FREE 2

/* Iteration 1 of the Polyak phase, close or overlapping shapes: once
 * ||x_1|| << ||x_0||, the x_0 term dominates the heavy-ball mix, whose
 * support then often is s_0 again on a polytope (x_1 = s_0: the simplex
 * gains nothing, and Alg. 6's fallback then leaves plain GJK, which creeps
 * when the origin lies just inside D). That support is retried once in the
 * first direction of normalised Nesterov (Alg. 7: x_0 and x_1 at equal unit
 * weights, which reaches across the origin), and plain GJK steps follow.
 * Measured (paper's protocol, support calls per distance query, seeds 1-3):
 * overlapping meshes 5.64 / 5.65 / 5.62 -> 5.58 / 5.58 / 5.53, close meshes
 * 5.85 / 5.65 / 5.70 -> 5.79 / 5.61 / 5.61, overlapping boxes 4.99 / 4.98 /
 * 5.07 -> 4.91 / 4.91 / 4.98, no row higher; curved shapes never meet s_0
 * again bit for bit, so ellipsoids are unchanged. Only while the best
 * support plane is not positive (s_0 did not show the shapes apart): without
 * that test distant boxes take 3.80 calls, above GJK's 3.76. Rejected (seed
 * 1): the x_0 term scaled down to ||x_1|| as the retry (overlapping meshes
 * 5.60), keeping momentum after the retry (5.58-5.68, and boxes above GJK),
 * retrying a repeat at iterations 2 or 3 too (5.61, 5.60). */
agjk_vec3 agjk__momentum_retry(const agjk__momentum *m, agjk_vec3 x) {
    agjk_vec3 d = v3_lerp2(v3_normalize(m->d_prev), 0.5, v3_normalize(x), 0.5);
    /* (A zero mix, x_1 opposite x_0, carries no direction: the gradient.) */
    return v3_isfinite(d) && v3_maxabs(d) > 0.0 ? d : x;
}

/* A point's key: a mix of its coordinates' bits, so that "met again, bit for
 * bit" is one integer comparison (this runs at every iteration). Equal points
 * have equal keys; distinct points sharing one (a coincidence of bit
 * patterns) would only steer the method, never the certificates. */
#define EMPTY_KEY UINT64_MAX
static uint64_t point_key(agjk_vec3 p) {
    uint64_t x, y, z;
    memcpy(&x, &p.x, sizeof x);
    memcpy(&y, &p.y, sizeof y);
    memcpy(&z, &p.z, sizeof z);
    /* The three words rotated apart, so that no two coordinates' signs or
     * exponents land on the same bits (a plain xor would give a box's
     * vertices (h, h, c) and (-h, -h, c) one key). */
    return x ^ ((y << 21) | (y >> 43)) ^ ((z << 42) | (z >> 22));
}

int agjk__method_has_momentum(agjk_method method) {
    return method == AGJK_METHOD_NESTEROV || method == AGJK_METHOD_NESTEROV_NORMALIZED ||
           method == AGJK_METHOD_POLYAK || method == AGJK_METHOD_ADAPTIVE;
}

void agjk__momentum_init(agjk__momentum *m, agjk_method method, agjk_vec3 x0, int given,
                         int boolean) {
    m->method = method;
    m->active = agjk__method_has_momentum(method);
    m->d_prev = x0;
    m->s_prev = x0;
    /* A given x_0 (a cache's or a caller's guess of x*) is close to the
     * answer: Nesterov from the start, which keeps it in the momentum and
     * restarts when it overshoots (coherent-motion benchmark, ellipsoids,
     * support calls per query slow / fast: cache 3.0 / 2.8 -> 1.9 / 2.9 with
     * the weights of cache.c; hint and direction 4.2 / 6.1 -> 3.3 / 4.4). */
    if (method != AGJK_METHOD_ADAPTIVE)
        m->phase = AGJK__PHASE_FIXED;
    else
        m->phase = given ? AGJK__PHASE_NESTEROV : AGJK__PHASE_POLYAK;
    m->plane = -INFINITY;
    m->plane_before = -INFINITY;
    m->omega = -INFINITY;
    m->x_k = x0;
    m->d_best = x0;
    m->a_seen[0] = m->a_seen[1] = m->b_seen[0] = m->b_seen[1] = EMPTY_KEY;
    m->x0_norm2 = -1.0;
    m->flat_seen = 0;
    /* A guess of x* (a cache's, a caller's) is worth keeping in the momentum:
     * plain steps would drop it at once. */
    m->plain_steps = given ? 0 : ADAPTIVE_PLAIN_STEPS;
    m->boolean = boolean;
    m->guard_from = 0; /* the tests at every iteration (ADAPTIVE_BOOLEAN_FREE) */
}

void agjk__momentum_rescale(agjk__momentum *m, double f) {
    m->d_prev = v3_scale(m->d_prev, f);
    m->s_prev = v3_scale(m->s_prev, f);
    m->x_k = v3_scale(m->x_k, f);
    m->plane *= f;
    m->plane_before *= f;
    m->omega *= f;
    m->x0_norm2 *= f * f;
    /* (The keys of points seen before are not rescaled: a repetition across
     * a rescale, which is rare, goes unnoticed.) */
}

double agjk__plane_of_extreme(agjk_vec3 d, agjk_vec3 s) {
    /* <d, s> / ||d|| with d brought to unit size first: x_0 = c_A - c_B is
     * used as given, and frame origins 1e-159 apart gave a squared norm in
     * the subnormals whose few bits put this plane 1e-17 (6e-11 relative)
     * beyond the support it bounds (fuzz). */
    return v3_maxabs(d) > 0.0 ? v3_dot(v3_normalize(d), s) : -INFINITY;
}

/* Whether the Nesterov step from x_k (m->x_k) to x_{k+1} (squared norm
 * x2_new) closed less than ADAPTIVE_CREEP of the gap ||x_k|| - max(plane, 0)
 * that the best support plane leaves. */
static int creeps(const agjk__momentum *m, double x2_new) {
    double xk = v3_norm(m->x_k);
    double lower = m->plane > 0.0 ? m->plane : 0.0;
    double level = xk - ADAPTIVE_CREEP * (xk - lower); /* >= 0 */
    return x2_new > level * level;
}

int agjk__momentum_update(agjk__momentum *m, int k, agjk_vec3 d, const agjk__vertex *s,
                          double x2_new) {
    int stopped = 0;
    /* A point of A or of B met again, bit for bit, in another direction: a
     * vertex, so a flat-faced shape, where momentum directions keep landing on
     * vertices already in the simplex (each such support is wasted) and plain
     * GJK steps land exactly on the optimal face. */
    int flat = 0;
    if (!m->flat_seen) {
        /* Once seen, nothing more to learn: the adaptive method is already in
         * its final phase, and the cache only keeps the flag. */
        uint64_t ka = point_key(s->a), kb = point_key(s->b);
        flat = (ka == m->a_seen[0]) | (ka == m->a_seen[1]) | (kb == m->b_seen[0]) |
               (kb == m->b_seen[1]);
        m->a_seen[1] = m->a_seen[0];
        m->a_seen[0] = ka;
        m->b_seen[1] = m->b_seen[0];
        m->b_seen[0] = kb;
        m->flat_seen = flat;
    }
    if (m->method == AGJK_METHOD_ADAPTIVE && k > 0 && m->phase != AGJK__PHASE_FINAL) {
        if (!m->active) {
            m->phase = AGJK__PHASE_FINAL; /* the solver's Alg. 6 fallback */
        } else if (flat ||
                   (m->phase == AGJK__PHASE_NESTEROV && k >= m->guard_from &&
                    (m->omega < m->plane_before ||
                     (k >= ADAPTIVE_CREEP_FROM && creeps(m, x2_new))))) {
            /* Restart to plain GJK directions for good (flat faces, a
             * momentum step whose plane is worse than the best so far, or,
             * late, one that closed too little of the gap: ADAPTIVE_CREEP). */
            m->phase = AGJK__PHASE_FINAL;
            m->active = 0;
            stopped = 1;
        } else if (m->phase == AGJK__PHASE_POLYAK &&
                   m->plane < ADAPTIVE_CLOSE_RATIO * v3_norm(m->x_k)) {
            m->phase = AGJK__PHASE_NESTEROV;
        }
    } else if (k == 0 && m->boolean && m->phase == AGJK__PHASE_POLYAK && m->active &&
               v3_dot(d, s->w) > -ADAPTIVE_BOOLEAN_SHALLOW * v3_norm2(s->w)) {
        /* Boolean mode, s_0 shallow behind the plane of x_0: Nesterov from
         * iteration 1, unguarded at first (ADAPTIVE_BOOLEAN_FREE). (d = x_0.) */
        m->phase = AGJK__PHASE_NESTEROV;
        m->plain_steps = 0;
        m->guard_from = ADAPTIVE_BOOLEAN_FREE;
    }
    m->d_prev = d;
    m->s_prev = s->w;
    return stopped;
}

agjk_vec3 agjk__momentum_direction_other(const agjk__momentum *m, int k, agjk_vec3 x) {
    double kk = (double)k;
    agjk_vec3 d;
    switch (m->method) {
    case AGJK_METHOD_NESTEROV_NORMALIZED: {
        /* Alg. 7 (eq. 31): Nesterov's mix with both terms normalised, so that
         * the momentum does not swamp the gradient as ||d|| grows relative to
         * ||y|| (which stalls momentum early on polytopes). */
        double delta = AGJK__NESTEROV_DELTA(kk);
        agjk_vec3 y = v3_lerp2(x, delta, m->s_prev, 1.0 - delta);
        agjk_vec3 dn = v3_normalize(m->d_prev);
        double yy = v3_norm2(y);
        if (yy >= 0x1p-900 && yy <= 0x1p900) {
            /* The same direction times ||y||: a square root and no division
             * between x and d (d_prev's unit vector is ready before x). The
             * support depends on the direction alone, and the next step
             * normalises d again. */
            d = v3_lerp2(dn, delta * sqrt(yy), y, 1.0 - delta);
            break;
        }
        agjk_vec3 yn = v3_normalize(y);
        if (v3_norm2(yn) == 0.0) yn = v3_normalize(x);
        d = v3_lerp2(dn, delta, yn, 1.0 - delta);
        break;
    }
    case AGJK_METHOD_ADAPTIVE: {
        int plain = 0;
        if (k <= m->plain_steps) {
            /* Far apart, or s_0 opposite x_0: plain GJK steps first. */
            double xn = v3_norm(x);
            int far = m->plane >= ADAPTIVE_CLOSE_RATIO * xn &&
                      (m->phase == AGJK__PHASE_POLYAK ||
                       xn * xn >= ADAPTIVE_FAR_SIZE * ADAPTIVE_FAR_SIZE * m->x0_norm2);
            plain = far || (k == 1 && m->plane <= -ADAPTIVE_OPPOSITE_RATIO * xn);
        }
        if (plain) {
            d = x;
        } else if (m->phase == AGJK__PHASE_POLYAK) { /* with a lighter first momentum step */
            d = agjk__polyak_mix(m, k == 1 ? ADAPTIVE_POLYAK_FIRST : AGJK__POLYAK_DELTA(kk), x);
        } else {
            d = agjk__nesterov_mix(m, k, x);
            /* A Nesterov direction against the gradient (or, right after a
             * plain step at iteration 1, nearly across it): a plain step
             * instead (ADAPTIVE_AGAINST_COS). */
            double dx = v3_dot(d, x);
            if (k >= m->guard_from &&
                (dx < 0.0 ||
                 (k == 2 && m->d_prev.x == m->x_k.x && m->d_prev.y == m->x_k.y &&
                  m->d_prev.z == m->x_k.z &&
                  dx < ADAPTIVE_AGAINST_COS * sqrt(v3_norm2(d) * v3_norm2(x)))))
                d = x;
        }
        break;
    }
    default:
        d = x;
        break;
    }
    return d; /* (the caller tests it: agjk__momentum_mix) */
}

/* (solver.h: agjk__direction_or_gradient's rare case.) */
AGJK__NOINLINE AGJK__COLD agjk_vec3 agjk__gradient_instead(agjk_vec3 x) { return x; }
