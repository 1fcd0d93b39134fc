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
    int want_witness;            /* compute the deepest points a, b (else has_witness 0) */
} agjk__epa_input;

typedef struct agjk__epa_output {
    agjk__epa_outcome outcome;
    int converged;        /* width <= target (raised to the floor in absolute mode) */
    /* Certified bounds on the penetration depth of the cores, solver units
     * (md->scale at the end), rounding included: lower <= depth <= upper. */
    double lower, upper;
    double estimate;      /* support value in `normal`, within [lower, upper] */
    agjk_vec3 normal;     /* unit, A's frame: the direction of `estimate` */
    int has_witness;      /* a, b below are set (only when asked: want_witness) */
    agjk_vec3 a, b;       /* deepest core points of A and B, A's frame, solver units */
    int iterations;
    int support_calls;
} agjk__epa_output;

void agjk__epa(agjk__minkowski *md, const agjk__epa_input *in, agjk__epa_output *out);

/* The face slots EPA's nearest-face search visits: the polytope's faces whose
 * key (the lower bound a face proves, +inf for a free slot) was below the
 * bound (EPA's upper bound) when offered or last scanned. A face at or beyond
 * the upper bound is never expanded in absolute mode (were it nearest, the
 * bounds would have met), and on smooth shapes most faces are. Every face
 * left out has key >= excluded. */
#define AGJK__EPA_MAX_FACES (2 * AGJK_EPA_MAX_VERTICES)
typedef struct agjk__epa_scan {
    int slot[AGJK__EPA_MAX_FACES];
    unsigned char listed[AGJK__EPA_MAX_FACES];
    int count;
    double excluded;
} agjk__epa_scan;

static inline void agjk__epa_scan_init(agjk__epa_scan *sc) {
    sc->count = 0;
    sc->excluded = INFINITY;
}

/* A slot used for the first time. */
static inline void agjk__epa_scan_fresh(agjk__epa_scan *sc, int slot) { sc->listed[slot] = 0; }

/* Slot `slot` received a face of key `key` (a listed slot stays listed). */
static inline void agjk__epa_scan_offer(agjk__epa_scan *sc, int slot, double key, double bound) {
    if (sc->listed[slot]) return;
    if (key < bound) {
        sc->slot[sc->count++] = slot;
        sc->listed[slot] = 1;
    } else if (key < sc->excluded) {
        sc->excluded = key;
    }
}

/* The slot of least key among key[0 .. nslots - 1] (-1 if all are +inf), its
 * key in *low. Visits the listed slots, drops those at or beyond `bound`, and
 * lists every slot again when the listed ones cannot prove theirs the least. */
static inline int agjk__epa_scan_nearest(agjk__epa_scan *sc, const double *key, int nslots,
                                         double bound, double *low) {
    for (int pass = 0; pass < 2; ++pass) {
        int best = -1, kept = 0;
        double least = INFINITY;
        for (int i = 0; i < sc->count; ++i) {
            int fi = sc->slot[i];
            double k = key[fi];
            if (k < bound) {
                sc->slot[kept++] = fi;
                if (k < least) {
                    least = k;
                    best = fi;
                }
            } else {
                sc->listed[fi] = 0;
                if (k < sc->excluded) sc->excluded = k;
            }
        }
        sc->count = kept;
        /* The slots left out hold keys >= excluded. */
        if (best >= 0 && least <= sc->excluded) {
            *low = least;
            return best;
        }
        /* Every slot again; the second pass keeps them all. */
        sc->count = 0;
        sc->excluded = INFINITY;
        for (int fi = 0; fi < nslots; ++fi) {
            sc->listed[fi] = key[fi] < INFINITY;
            if (sc->listed[fi]) sc->slot[sc->count++] = fi;
        }
        bound = INFINITY;
    }
    *low = INFINITY;
    return -1;
}

/* Width the interval on the signed distance must reach (solver units), given
 * the interval [s_lo, s_hi] on the signed distance with margins (solver units)
 * and the tolerance; the floating-point floor raises it in absolute mode.
 * Inline: EPA asks at every iteration the cheaper cap of width_met leaves open. */
static inline double agjk__epa_target(int relative, double tolerance, double scale, double s_lo,
                                       double s_hi, double floor) {
    double lo = fabs(s_lo), hi = fabs(s_hi);
    double big = lo > hi ? lo : hi;
    if (relative) {
        /* The smallest |s| the interval allows (0 when it holds 0). */
        double small = (s_lo > 0.0 || s_hi < 0.0) ? (lo < hi ? lo : hi) : 0.0;
        return 0.5 * tolerance * small;
    }
    /* What agjk_distance certifies at distance |s| with gap <= tolerance:
     * min(sqrt(g), g / (2 |s|)); the largest |s| of the interval is the safe one. */
    double tol = tolerance * scale * scale;
    double target = sqrt(tol);
    if (big > 0.0 && tol / (2.0 * big) < target) target = tol / (2.0 * big);
    return target > floor ? target : floor;
}

/* Floating-point floor of the interval width for the problem md (solver units). */
double agjk__epa_floor(const agjk__minkowski *md);

/* The floor of the signed distance's final interval, in DBL_EPSILON of the
 * problem's size: the largest coordinates of the cores' points met
 * (md->magnitude, |a| + |b| in max norm) plus the offset of the frames plus
 * the margins. EPA's and GJK's own floor on the cores' interval is 1024
 * (agjk__epa_floor, 256 noise); the 16 more cover what agjk_signed_distance
 * adds to it afterwards, the rounding of the margins' sum and subtraction
 * (4 eps (margin + |s|) over both ends) and of the change of units (an ulp
 * of |s| at each end), with |s| at most sqrt(3) times the size. Stated in
 * agjk/penetration.h. */
#define AGJK__SIGNED_FLOOR_EPS 1040.0

/* That floor in solver units, for a margin sum margin_s in solver units. */
static inline double agjk__signed_floor(const agjk__minkowski *md, double margin_s) {
    return AGJK__SIGNED_FLOOR_EPS * DBL_EPSILON *
           (md->magnitude + md->translation_size + margin_s);
}

/* The part of agjk__signed_allowance for a change of units (scale != 1),
 * and the final floor in the caller's units: each holds a subnormal
 * constant, for the ulps among subnormal numbers, so each is out of line
 * and called only when the units change. Inline, a compiler may evaluate
 * it on both arms of the test (clang does), and on ordinary problems a
 * subnormal operand costs a microcode assist on x86 (tests/core/
 * test_subnormals.c). */
double agjk__signed_allowance_rescaled(double big, double scale);
double agjk__signed_floor_rescaled(double floor, double scale);

/* An upper bound, per end, on what agjk_signed_distance adds to a signed
 * interval with ends of magnitude at most big after the cores' bounds
 * (solver units, margin sum margin_s): twice widen_for_margins' (2 eps
 * (margin + |s|)), and when the units change an ulp of |s| in the caller's
 * units, subnormal ones included (widen_after_rescale). */
static inline double agjk__signed_allowance(double margin_s, double big, double scale) {
    double a = margin_s > 0.0 ? 4.0 * DBL_EPSILON * (margin_s + big) : 0.0;
    if (scale != 1.0) a += agjk__signed_allowance_rescaled(big, scale);
    return a;
}

/* Whether a signed interval [s_lo, s_hi] (units whose squared tolerance is
 * tolerance * scale^2) meets the width agjk/penetration.h promises:
 * relative mode tolerance / 2 * min |s| over the interval (0 when it holds
 * 0), absolute mode min(sqrt(tolerance), tolerance / (2 max |s|)) raised to
 * floor. */
static inline int agjk__signed_width_met(int relative, double tolerance, double scale,
                                         double s_lo, double s_hi, double floor) {
    double target = agjk__epa_target(relative, tolerance, scale, s_lo, s_hi,
                                     relative ? 0.0 : floor);
    return s_hi - s_lo <= target;
}

/* Error scale of a computed point of D (as the solver's), solver units. */
double agjk__epa_noise(const agjk__minkowski *md);

#endif
