/* SPDX-License-Identifier: MIT */
/* Internal: the Expanding Polytope Algorithm (van den Bergen, GDC 2001 and
 * "Collision Detection in Interactive 3D Environments", 2003, sec. 4.3.8) with a
 * certified depth interval. */
#ifndef AGJK_SRC_EPA_H
#define AGJK_SRC_EPA_H

#include "agjk/penetration.h"
#include "minkowski.h"

typedef enum agjk__epa_outcome {
    AGJK__EPA_CONVERGED,   /* width of the interval met the target */
    AGJK__EPA_FLAT,        /* D has no volume (within rounding): depth 0 */
    AGJK__EPA_NO_PROGRESS, /* the nearest face lies on D's boundary to rounding */
    AGJK__EPA_FULL,        /* the vertex store is full */
    AGJK__EPA_CAP,         /* iteration cap */
    AGJK__EPA_DEGENERATE,  /* an insertion would have broken the polytope */
    AGJK__EPA_BAD_SUPPORT  /* a support callback returned a non-finite point */
} agjk__epa_outcome;

typedef struct agjk__epa_input {
    const agjk__vertex *simplex; /* GJK's final active set, solver units */
    int count;                   /* 1 to 4 */
    int relative;                /* tolerance relative to |signed distance| */
    double tolerance;            /* caller's units: length^2 (absolute) or none */
    double margin;               /* margins of A and B summed, caller's units */
    /* A certified upper bound on the signed distance of the cores (GJK's),
     * solver units: depth >= -it. */
    double core_distance_upper;
    int max_iterations;
} agjk__epa_input;

typedef struct agjk__epa_output {
    agjk__epa_outcome outcome;
    int converged;        /* width <= target (raised to the floor in absolute mode) */
    /* Certified bounds on the penetration depth of the cores, solver units
     * (md->scale at the end), rounding included: lower <= depth <= upper. */
    double lower, upper;
    double estimate;      /* support value in `normal`, within [lower, upper] */
    agjk_vec3 normal;     /* unit, A's frame: the direction of `estimate` */
    int has_witness;      /* a, b below are set */
    agjk_vec3 a, b;       /* deepest core points of A and B, A's frame, solver units */
    int iterations;
    int support_calls;
} agjk__epa_output;

void agjk__epa(agjk__minkowski *md, const agjk__epa_input *in, agjk__epa_output *out);

/* Width the interval on the signed distance must reach (solver units), given
 * the interval [s_lo, s_hi] on the signed distance with margins (solver units)
 * and the tolerance; the floating-point floor raises it in absolute mode. */
double agjk__epa_target(int relative, double tolerance, double scale, double s_lo,
                        double s_hi, double floor);

/* Floating-point floor of the interval width for the problem md (solver units). */
double agjk__epa_floor(const agjk__minkowski *md);

/* Error scale of a computed point of D (as the solver's), solver units. */
double agjk__epa_noise(const agjk__minkowski *md);

#endif
