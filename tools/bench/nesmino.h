/* SPDX-License-Identifier: MIT */
/* NESMINO-style baseline: Nesterov's accelerated projected gradient for the
 * minimum-norm point of a Minkowski difference (Qin and An, "Smoothing
 * algorithms for computing the projection onto a Minkowski sum of convex
 * sets", arXiv 1801.08285), as compared in Montaut et al. 2022, Table II.
 *
 * Qin and An smooth the norm ||a - b|| (Nesterov smoothing) and run the fast
 * gradient method over A x B with projections onto A and B. We minimise the
 * squared norm f(a, b) = 1/2 ||a - b||^2 instead, which is already smooth
 * (gradient Lipschitz constant L = 2), so no smoothing parameter is needed; the
 * iteration is FISTA (Beck and Teboulle 2009) with step 1/L and projections onto
 * ellipsoids (Newton on the Lagrange multiplier) and boxes (clamping). Only
 * ellipsoids and boxes are supported: projecting onto a polytope is itself a
 * QP, which is the paper's point about NESMINO on meshes. */
#ifndef AGJK_BENCH_NESMINO_H
#define AGJK_BENCH_NESMINO_H

#include "problems.h"

typedef enum nesmino_stop {
    /* The paper's rule: stop when ||x_k - x*|| <= sqrt(tolerance), x* given. */
    NESMINO_STOP_SOLUTION = 0,
    /* Stop when the Frank-Wolfe duality gap of x_k = a_k - b_k is <= tolerance
     * (costs one support of each shape per iteration; certified). */
    NESMINO_STOP_GAP = 1
} nesmino_stop;

typedef struct nesmino_result {
    int converged;
    int iterations;
    int support_calls;   /* projections + supports onto A x B */
    double distance;     /* ||a_k - b_k|| */
    double bound;        /* sqrt(gap) when the gap was computed, else -1 */
} nesmino_result;

/* Returns 0, or -1 if a shape kind has no projection. */
int bench_nesmino(const bench_shape *a, const agjk_pose *pa, const bench_shape *b,
                  const agjk_pose *pb, nesmino_stop stop, double tolerance,
                  const agjk_vec3 *xstar, int max_iterations, nesmino_result *out);

#endif
