/* SPDX-License-Identifier: MIT */
/* NESMINO-style baseline: Nesterov's accelerated projected gradient for the
 * minimum-norm point of a Minkowski difference (Qin and An, "Smoothing
 * algorithms for computing the projection onto a Minkowski sum of convex
 * sets", arXiv 1801.08285), as compared in Montaut et al. 2022, Table II.
 *
 * Qin and An minimise Nesterov's smoothing of the norm over A x B,
 *   f_mu(a, b) = max_{||u|| <= 1} <u, a - b> - mu/2 ||u||^2
 * (a Huber function of x = a - b: ||x||^2 / (2 mu) when ||x|| <= mu, else
 * ||x|| - mu/2; gradient u = x / max(mu, ||x||), Lipschitz constant L = 2/mu
 * on the pair), with Nesterov's fast gradient method (here FISTA, Beck and
 * Teboulle 2009, step 1/L) and projections onto A and B: onto ellipsoids by
 * Newton on the Lagrange multiplier, onto boxes by clamping. u converges to the
 * common normal (minus the dual solution).
 *
 * mu = 0 below means mu = infinity in effect (mu >= ||x_k|| throughout): f is
 * then the squared distance / (2 mu) and the step moves both points to their
 * midpoint before projecting; this is the best-conditioned member of the
 * family and our default, so the comparison does not handicap NESMINO by a
 * badly chosen mu. A finite mu (--nesmino-mu) shows the cost of smoothing.
 * Only ellipsoids and boxes are supported: projecting onto a polytope is
 * itself a QP, which is the paper's point about NESMINO on meshes. */
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
                  const agjk_vec3 *xstar, int max_iterations, double mu,
                  nesmino_result *out);

#endif
