/* SPDX-License-Identifier: MIT */
/* Internal: the Frank-Wolfe family loop (GJK, accelerated GJK, plain FW) and
 * its direction policy. */
#ifndef AGJK_SRC_SOLVER_H
#define AGJK_SRC_SOLVER_H

#include "minkowski.h"

/* Direction policy state (Montaut et al. 2022, Alg. 6/7; GJK++ for Polyak). */
typedef struct agjk__momentum {
    agjk_method method;
    int active;       /* momentum still in use (0 after the Alg. 6 fallback) */
    agjk_vec3 d_prev; /* d_{k-1} */
    agjk_vec3 s_prev; /* s_{k-1} */
} agjk__momentum;

/* Support direction d_k for iterate x_k at iteration k while momentum is active. */
agjk_vec3 agjk__momentum_direction(const agjk__momentum *m, int k, agjk_vec3 x);

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
} agjk__solve_input;

typedef struct agjk__solve_output {
    agjk__outcome outcome;
    agjk_vec3 x;         /* final iterate (A's frame) */
    agjk_vec3 a, b;      /* core points on A and B with a - b = x (A's frame) */
    agjk_vec3 direction; /* separating direction (SEPARATED_EARLY) */
    double gap;          /* duality gap at x; valid when gap_valid */
    int gap_valid;
    double noise;        /* floating-point error scale of w, length units */
    int iterations;
    int support_calls;
    int momentum_stop;
    /* The final active set (A's frame, solver units): EPA starts from it. */
    agjk__vertex simplex[4];
    int simplex_count;
} agjk__solve_output;

void agjk__solve(agjk__minkowski *md, const agjk__solve_input *in, agjk__solve_output *out);

#endif
