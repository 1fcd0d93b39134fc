/* SPDX-License-Identifier: MIT */
/* Internal: projection of the origin onto a simplex of up to four points
 * (GJK's distance sub-algorithm). */
#ifndef AGJK_SRC_SIMPLEX_H
#define AGJK_SRC_SIMPLEX_H

#include "vec3.h"

/* Projects the origin onto conv(p[0..n-1]), 1 <= n <= 4, p finite.
 * Writes the closest point to *point and barycentric weights lambda[0..n-1]
 * (>= 0, summing to 1, zero outside the support set). Returns the support
 * mask: bit i set when lambda[i] > 0. A mask of all four bits means the origin
 * is inside the (non-degenerate) tetrahedron; *point is then exactly zero. */
unsigned agjk__simplex_project(const agjk_vec3 *p, int n, double lambda[4], agjk_vec3 *point);

/* The same projection, with the same output contract, for GJK's use: w[n-1]
 * is the support point just added and w[0..n-2] the previous simplex (the
 * smallest face holding the previous iterate). Fast when the projection lies
 * on a face containing w[n-1], as GJK makes likely, or when the origin is
 * clearly inside the tetrahedron; every such answer is checked for
 * optimality (KKT), and agjk__simplex_project decides whenever the check
 * fails or the simplex is degenerate or ill-conditioned, so the result holds
 * for any finite input, in any order. */
unsigned agjk__simplex_project_gjk(const agjk_vec3 *w, int n, double lambda[4], agjk_vec3 *point);

/* What the fast path's inside test knew when it found the origin inside the
 * tetrahedron w[0..3] (w[3] the newest point, e_i = w_i - w_3): for the face
 * without w_i (i < 3), h[i] = -<w_3, e_j x e_k> oriented to be positive (the
 * origin's depth below that face times twice its area, from the edges at
 * w_3), g[i] = |e_i|^2, and `orientation` the sign (+1 or -1) that turned
 * them: the sign of det(e_0, e_1, e_2). */
typedef struct agjk__inside {
    double h[3], g[3], orientation;
} agjk__inside;

/* What the GJK projection tells its caller besides its answer: the inside
 * test's data (above), and the projection's point turned into B's frame,
 * R^T x, the direction of the solver's next support of B after a plain step.
 * The point is turned when a face holds the answer (GJK's usual case), as
 * (R^T n) t from the face's normal n and x = n t: R^T n is computed while
 * t's division runs, where R^T x could only start after it (B's path is the
 * longer one in GJK's chain of dependent steps: close ellipsoids 7% faster).
 * rotation NULL: nothing is turned. (One struct, with the rotation behind
 * the inside data: passed as a separate argument, it made the projection
 * compile worse, close boxes 8% slower.) */
typedef struct agjk__projection_notes {
    agjk__inside inside;
    const double *rotation; /* R, row-major */
    agjk_vec3 turned;       /* R^T x, when turned_valid */
    int turned_valid;
    /* The caller can do without an enclosure's weights (below). */
    int weights_optional;
} agjk__projection_notes;

/* Set in the mask (with the four vertex bits) by
 * agjk__simplex_project_gjk_noted when it wrote notes->inside. */
#define AGJK__INSIDE_REPORTED 0x10u
/* Set with AGJK__INSIDE_REPORTED when the inside test found the origin
 * clearly inside a tetrahedron too thin for its own weights and
 * notes->weights_optional: *point is 0, lambda is not written. The same
 * call without weights_optional gives the weights (or, where they fail,
 * the exhaustive projection's answer). */
#define AGJK__WEIGHTS_DEFERRED 0x20u

/* agjk__simplex_project_gjk, with notes (or NULL): notes->inside as above
 * when that test found the origin inside (the mask then has
 * AGJK__INSIDE_REPORTED too, also when the tetrahedron was too thin for the
 * test's own weights and the exhaustive projection's are given; otherwise
 * it is not written, and the overlap certification does its own tests),
 * and notes->turned with turned_valid set to 1 when the point was turned
 * (else turned_valid is left as it was: the caller clears it). `newest`
 * holds w[n-1]'s value, where the caller has it (its fast path reads the
 * new point from there). */
unsigned agjk__simplex_project_gjk_noted(const agjk_vec3 *w, int n, double lambda[4],
                                         agjk_vec3 *point, agjk__projection_notes *notes,
                                         const agjk_vec3 *newest);

/* The fast path of agjk__simplex_project_gjk alone: the same output when it
 * finds a candidate that passes the optimality check, else 0 with lambda and
 * *point unspecified (for tests and measurements of the fallback rate). */
unsigned agjk__simplex_project_gjk_fast(const agjk_vec3 *w, int n, double lambda[4],
                                        agjk_vec3 *point);

#endif
