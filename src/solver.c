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
 * The problem's scale is settled by the first support, before the loop; the
 * loop itself only meets a rescale in the rare case of a later support point
 * far larger than the first ones (one predicted test per support).
 *
 * Every loop is bounded by max_iterations; the simplex projection is
 * non-iterative. No allocation: the simplex lives on the stack. */
#include "solver.h"

#include "simplex.h"

/* Momentum pays off in the first few dozen iterations (paper, Fig. 4-6); past
 * this many, a momentum direction that has not reached the Alg. 6 fallback is
 * creeping (normalised momentum on smooth overlapping shapes can take ~1000
 * iterations to reach g <= eps), and plain GJK finishes faster. */
#define MOMENTUM_BUDGET 64

/* The loop's state: the active set (points of D in w, and when witness points
 * are wanted the points of A and B they came from), the iterate, momentum. */
typedef struct solver {
    agjk__minkowski *md;
    const agjk__solve_input *in;
    agjk_vec3 w[4], a[4], b[4];
    double lambda[4];
    int count;
    /* The points of A kept (in->keep_points), and of B too: for EPA and the
     * cache. The witness point on B needs none of them: it is taken as
     * sum lambda_i (a_i - w_i) (finish), but for plain Frank-Wolfe, whose
     * one vertex is a combination whose point of D, x, comes from a
     * projection that may clean it up (which keeps B's points too). */
    int keep_a, keep_b, b_from_a;
    agjk_vec3 x;
    double x2;          /* ||x||^2 */
    agjk__momentum m;
    /* The projection's notes: the enclosure's inside test, when
     * inside_reported, and R^T x, when turned_valid. */
    agjk__projection_notes notes;
    int inside_reported;
    double abs_tolerance; /* absolute mode: the tolerance in solver units squared */
    double lie_factor;    /* a gap below -lie_factor ||x|| noise proves a lying support */
    int sign_budget;      /* iterations left to decide the sign after the tolerance */
    int plain_next;       /* plain steps from the next iteration (sign_pending, or a
                           * retried support) */
    /* Plain Frank-Wolfe only: a bound on how far its iterate, carried from
     * step to step as one computed point, may have drifted from the exact
     * convex combination of support points it stands for (update_frank_wolfe);
     * 0 for the other methods, whose active set holds support points. */
    double drift;
} solver;

/* After a support that had to lower the scale (agjk__minkowski_points_slow),
 * brings the solver's own state to the new units. Exact: powers of two. Rare,
 * so out of line. */
static AGJK__NOINLINE AGJK__COLD void follow_rescale(solver *sv, agjk_vec3 *d) {
    agjk__minkowski *md = sv->md;
    double f = md->rescaled;
    md->rescaled = 1.0;
    for (int i = 0; i < sv->count; ++i) {
        sv->w[i] = v3_scale(sv->w[i], f);
        if (sv->keep_a) sv->a[i] = v3_scale(sv->a[i], f);
        if (sv->keep_b) sv->b[i] = v3_scale(sv->b[i], f);
    }
    sv->x = v3_scale(sv->x, f);
    sv->x2 = v3_norm2(sv->x);
    sv->drift *= f;
    sv->notes.turned_valid = 0; /* (x changed units) */
    /* The direction the support just used: scaled with the rest, unless that
     * would push it below DIRECTION_MIN, where it would start to lose bits
     * (a shrink by 2^-600 once left a denormal d whose direction, off by
     * 1e-3, certified a separation the support never saw); its length only
     * weights the momentum, so then it goes to unit size instead (exact). */
    double dm = v3_maxabs(*d);
    if (dm > 0.0) *d = dm * f >= AGJK__DIRECTION_MIN ? v3_scale(*d, f) : v3_scale_to_unit(*d, dm);
    agjk__momentum_rescale(&sv->m, f);
    if (!sv->in->relative) sv->abs_tolerance *= f * f;
}

/* One Minkowski support in direction d (s in the current units), d2 = |d|^2
 * if known, else 0, and db = R^T d if known, else NULL (see
 * agjk__minkowski_support): inline for the loop's own call, out of line for
 * the rare ones (momentum switch-off, final certification), so that the
 * support path is expanded once. Returns 1 when the support has put s->w
 * in the simplex's next slot, sv->w[sv->count], already (see
 * agjk__minkowski_support). */
static AGJK__ALWAYS_INLINE int support(solver *sv, agjk_vec3 *d, double d2, agjk__vertex *s,
                                       int direct, const agjk_vec3 *db) {
    int in_slot = agjk__minkowski_support(sv->md, *d, d2, s, direct, db, 0.0, 0.0,
                                          sv->count < 4 ? &sv->w[sv->count] : NULL);
    if (sv->md->rescaled != 1.0) follow_rescale(sv, d);
    return in_slot;
}
static AGJK__NOINLINE void support_rare(solver *sv, agjk_vec3 *d, agjk__vertex *s) {
    (void)support(sv, d, 0.0, s, AGJK__SUPPORT_CALL_PAIRED, NULL);
}

/* Checks a fresh support s in direction d: a bad callback output ends the
 * query, and in Boolean mode so does a separating plane (Alg. 2). Returns 1
 * when the loop must stop, with out->outcome set. */
static AGJK__NOINLINE int support_ends_query_slow(const solver *sv, agjk_vec3 d,
                                                  const agjk__vertex *s, agjk__solve_output *out) {
    if (sv->md->bad_support) {
        out->outcome = AGJK__BAD_SUPPORT;
        return 1;
    }
    if (agjk__minkowski_separates(sv->md, d, s->w)) {
        out->outcome = AGJK__SEPARATED_EARLY;
        out->direction = d;
        return 1;
    }
    return 0;
}

/* Inline, the common case (distance mode, a good support) is one test. */
static inline int support_ends_query(const solver *sv, agjk_vec3 d, const agjk__vertex *s,
                                     agjk__solve_output *out) {
    if (!(sv->md->bad_support | sv->in->boolean_mode)) return 0;
    return support_ends_query_slow(sv, d, s, out);
}

/* support_ends_query in the loop of the solver's copy that is handed
 * iteration 0's support (from_start: a constant 1 there, and 0 in the
 * other), which only Boolean queries run (agjk__solve_from): there the plane
 * test, made at every iteration, is inline, without a call that passed d
 * through memory (agjk-bench, same-run: boxes in Boolean mode 0.7-2.8%
 * faster; ellipsoids, whose supports take longer, unchanged). The body
 * repeats support_ends_query_slow's: shared through one inline helper, it
 * compiled so that Boolean boxes took 1.4-1.9% longer again. */
static AGJK__ALWAYS_INLINE int loop_support_ends_query(const solver *sv, int from_start,
                                                       agjk_vec3 d, const agjk__vertex *s,
                                                       agjk__solve_output *out) {
    if (!from_start) return support_ends_query(sv, d, s, out);
    if (sv->md->bad_support) {
        out->outcome = AGJK__BAD_SUPPORT;
        return 1;
    }
    if (!agjk__minkowski_separates(sv->md, d, s->w)) return 0;
    out->outcome = AGJK__SEPARATED_EARLY;
    out->direction = d;
    return 1;
}

/* support_ends_query for iteration 0's support taken by the caller, whose
 * plane test (agjk__first_support) has decided already. */
static inline int start_ends_query(const agjk__minkowski *md, const agjk__start *start,
                                   agjk__solve_output *out) {
    if (md->bad_support) {
        out->outcome = AGJK__BAD_SUPPORT;
        return 1;
    }
    if (!start->separated) return 0;
    out->outcome = AGJK__SEPARATED_EARLY;
    out->direction = start->x;
    return 1;
}

/* Whether a gap g at the current iterate meets the tolerance: AGJK__CONVERGED
 * when it meets the requested one, AGJK__AT_FLOOR when it is down to what
 * double precision resolves but above the request, else AGJK__ITERATION_CAP
 * (not met).
 *
 * The floor: x and s carry rounding errors of about `noise` each, so the
 * computed g = 2 <x, x - s> is uncertain by about 2 noise (||x|| + ||x - s||).
 * While iterating, the loop stops only at the tight floor 2 ||x|| noise
 * (xs2 = 0), where further steps cannot change anything; the wide floor, with
 * xs2 = ||x - s||^2, which can be far above it for shapes in close proximity
 * (||x|| << ||x - s||), judges a loop that stopped making progress. */
static inline agjk__outcome gap_verdict(const solver *sv, double g, double xs2) {
    const agjk__minkowski *md = sv->md;
    double requested = sv->abs_tolerance;
    if (sv->in->relative) {
        /* Relative mode promises |d - d*| <= d* t/2 (t the tolerance) with the
         * whole certified interval: the gap's part g / (2 ||x||) plus the
         * rounding allowances (2 noise below, 2 noise above; see query.c). With
         * b = g / (2 ||x||) and d = ||x|| - margins that holds when
         * b + 4 noise <= t/2 (d - b - 2 noise). */
        double x_norm = sqrt(sv->x2);
        double half = 0.5 * sv->in->tolerance;
        double b = (half * (x_norm - md->margin - 2.0 * md->noise) - 4.0 * md->noise) / (1.0 + half);
        requested = b > 0.0 ? 2.0 * x_norm * b : 0.0;
    }
    if (g <= requested) return AGJK__CONVERGED;
    if (g <= 0.0 || g * g <= agjk__gap_floor2(md->noise, sv->x2, xs2)) return AGJK__AT_FLOOR;
    return AGJK__ITERATION_CAP;
}

/* Whether a gap g at x certifies separation: the lower bound ||x|| -
 * g / (2 ||x||), less the rounding, above the margins (as query.c reads it). */
static int gap_separates(const solver *sv, double g) {
    /* ||x|| - g / (2 ||x||) > r  <=>  2 ||x||^2 - g > 2 ||x|| r, squared (r >= 0).
     * A bound that would vanish in the caller's units (a tolerance that is
     * huge for a tiny problem, met by a plane far from the best, found by
     * fuzzing) decides nothing: the plain steps of sign_pending tighten it. */
    double r = agjk__minkowski_separation_level(sv->md) + 2.0 * sv->md->noise,
           t = 2.0 * sv->x2 - g;
    return t > 0.0 && t * t > 4.0 * sv->x2 * r * r;
}

/* A gap g at x that meets the tolerance ends the query only once it also
 * decides the sign: a lower bound above the margins (separated; ||x|| -
 * g / (2 ||x||) less the rounding, as query.c certifies it), or an enclosure
 * of the origin, which the loop tests itself. Near contact (||x||^2 of the
 * order of an absolute tolerance) the tolerance is met long before either,
 * and where the loop happened to stop would then decide between
 * "contact within tolerance" and a verdict: a warm-started query and a cold
 * one of the same problem could disagree. So the loop goes on with plain GJK
 * steps, which enclose the origin or tighten the gap fastest, for at most
 * SIGN_SEEK_ITERATIONS more tolerance-meeting iterations (and never past the
 * iteration cap); only shapes that touch to within what those resolve (or to
 * the floating-point floor, AGJK__AT_FLOOR) end as contact. Measured on the
 * paper's protocol (1e-8, 1e-4 deep overlaps): every "contact" became a
 * verdict, at +0.01 support calls per query for GJK and +0.1 for the
 * adaptive method on overlapping sets; on the coherent-motion benchmark no
 * status differs between cold and warm queries (12 did of 4000 ellipsoid
 * ones; a budget of 8 or 16 left 1 of 24000, 24 and 32 none, 1000 the same
 * as 32). The price is paid by curved shapes that touch exactly, where no
 * budget decides: an ellipsoid pair at distance 0 takes 23.2 support calls
 * instead of 11.8 (ellipsoid and box: 21.4 instead of 11.0; a sphere on a
 * box, 6 instead of 4); budgets of 8 and 16 cost 15.0 and 18.1 there.
 * The budget counts these tests, not iterations: one per iteration for the
 * fixed methods (the gap test), up to three for the adaptive method (its
 * plane test before and after the simplex update, and the gap test), which
 * so gets about a dozen plain iterations (32 tests in 12 iterations on the
 * configuration of settle_overlap). Counting iterations instead decides
 * more nearly touching pairs, but at a price where nothing decides
 * (ellipsoids of the paper's law, 300 pairs per distance, adaptive method:
 * 18.6 -> 37.7 support calls at distance 0; 1e-9 times their scale apart
 * 17.4 -> 23.9, separated 53 -> 297 of 300); settle_overlap decides the
 * overlapping ones for fewer.
 * Returns 1 when the loop must go on (and spends one of the budget). */
#define SIGN_SEEK_ITERATIONS 32
static int sign_pending(solver *sv, double g, int k) {
    if (sv->sign_budget <= 0 || k + 1 >= sv->in->max_iterations || gap_separates(sv, g)) return 0;
    --sv->sign_budget;
    sv->plain_next = 1; /* momentum off at the end of this iteration, not before:
                         * this iteration's support may still be a momentum one */
    return 1;
}

/* Alg. 6 switches momentum off once g(x_k) <= eps. A relative tolerance
 * shrinks with the distance and never fires on overlapping shapes, so
 * momentum would creep on for ever: for this test use it as an absolute one
 * at the problem's own scale. */
static int momentum_stalls(const solver *sv, double g, int k) {
    if (k >= MOMENTUM_BUDGET || gap_verdict(sv, g, 0.0) != AGJK__ITERATION_CAP) return 1;
    if (!sv->in->relative) return 0;
    double scaled = sv->in->tolerance * sv->md->magnitude * sv->md->magnitude;
    return g <= scaled;
}

/* Certified overlap of the cores: the origin deep inside the hull of
 * computed points of D.
 *
 * The computed points are within sqrt(3) noise of exact points of D (noise:
 * agjk__minkowski). If the origin lies deeper than that inside their hull
 * (every plane through it has computed points more than that far on both
 * sides), no plane can separate it from the exact points' hull, which D
 * contains. Depths are tested through facet normals c = e1 x e2 of computed
 * points, with h = <p, c> = depth |c|. Their rounding is charged too: each
 * component of c is off by at most about 3 eps times the same component of
 * |e1| x |e2| taken with absolute values (call that vector k, |k| >= |c|),
 * and h by |p| times that plus 3 eps |p| |c|; with eps |p| <= noise / 4 the
 * depth error is below noise |k| / |c|. With the points' sqrt(3) noise,
 * h > 3 noise |k| suffices (tested squared): a depth of 3 noise for a facet
 * whose normal is computed accurately, more when cancellation blurs it. */
#define DEPTH_FACTOR 3.0

/* h^2 > (DEPTH_FACTOR noise |k|)^2 with h > 0, k as above. */
static int beyond_rounding(double h, agjk_vec3 e1, agjk_vec3 e2, double noise) {
    agjk_vec3 k = v3_abs_cross(e1, e2);
    double limit = DEPTH_FACTOR * noise;
    return h > 0.0 && h * h > limit * limit * v3_norm2(k);
}

/* The faces of a tetrahedron w[0..3], face f without w[f], all listed with
 * one orientation (their normals all point inwards or all outwards). */
static const int tetra_faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/* The tetrahedron w[0..3] (the common end of an overlapping query): the
 * origin beyond each face plane by the margin above. Returns the mask of the
 * faces that fail (bit f: the face without w[f]), 0 when certified.
 *
 * For a face (p, q, r), h = <-p, (q - p) x (r - p)> = -det(p, q, r). The
 * faces are listed with one orientation, so the four h add up to the
 * tetrahedron's signed volume (times 6) and its sign turns them all inwards.
 * A coarse bound first settles the usual case (a problem near the origin,
 * tiny noise) with no face normal at all: |k|^2 <= 2 |e1|^2 |e2|^2 <=
 * 2 (4 max |w_i|^2)^2, so h > sqrt(2) 3 noise 4 max |w_i|^2 would do, and a
 * factor 5 instead of 4 also covers the determinant's own rounding (a few
 * eps |w|^3, at most about 1.3 noise max |w_i|^2). */
static unsigned shallow_faces(const agjk_vec3 w[4], double noise) {
    /* h_f = -det of face f's vertices in tetra_faces' order, from three cross
     * products (a cross product with its factors swapped is the exact
     * negation, so these are the determinants bit for bit). */
    agjk_vec3 c23 = v3_cross(w[2], w[3]), c13 = v3_cross(w[1], w[3]), c12 = v3_cross(w[1], w[2]);
    double h[4] = {-v3_dot(w[1], c23), v3_dot(w[0], c23), -v3_dot(w[0], c13), v3_dot(w[0], c12)};
    double big = v3_norm2(w[0]);
    for (int f = 1; f < 4; ++f) {
        double ww = v3_norm2(w[f]);
        if (ww > big) big = ww;
    }
    double sign = h[0] + h[1] + h[2] + h[3] < 0.0 ? -1.0 : 1.0;
    double coarse = DEPTH_FACTOR * noise * 5.0 * big;
    coarse = 2.0 * coarse * coarse;
    unsigned shallow = 0;
    for (int f = 0; f < 4; ++f) {
        double hf = sign * h[f];
        if (hf > 0.0 && hf * hf > coarse) continue;
        /* Near the bound: h again from the edges, whose rounding the precise
         * test charges (the determinant's grows with |p| |q| |r|). */
        agjk_vec3 p = w[tetra_faces[f][0]];
        agjk_vec3 e1 = v3_sub(w[tetra_faces[f][1]], p), e2 = v3_sub(w[tetra_faces[f][2]], p);
        hf = -sign * v3_dot(p, v3_cross(e1, e2));
        if (!beyond_rounding(hf, e1, e2, noise)) shallow |= 1u << f;
    }
    return shallow;
}

/* shallow_faces(w, noise) == 0, sooner, from what the simplex's inside
 * test computed on its way to the enclosure (agjk__inside): the faces
 * through w[3] have their h from the edges at w[3], as the precise test
 * above takes them, and |k| <= |e_j| |e_k| (for the absolute values as for
 * the edges), so h^2 > (DEPTH_FACTOR noise)^2 g_j g_k, with 1% more for the
 * rounding of g, passes that test wherever it holds. The fourth face gets
 * the precise test itself. Either way the verdict is shallow_faces' (which
 * decides whatever this leaves open): it saves three cross products and most
 * of the products at the last step of an overlapping query. */
static int deep_enclosure(const solver *sv, double noise) {
    if (!sv->inside_reported) return 0;
    const agjk__inside *in = &sv->notes.inside;
    const agjk_vec3 *w = sv->w;
    double limit = DEPTH_FACTOR * noise;
    limit = 1.01 * limit * limit;
    const double *h = in->h, *g = in->g;
    if (!(h[0] * h[0] > limit * g[1] * g[2] && h[1] * h[1] > limit * g[2] * g[0] &&
          h[2] * h[2] > limit * g[0] * g[1]))
        return 0;
    /* The face without w[3], as tetra_faces[3] lists it, oriented as the rest. */
    agjk_vec3 e1 = v3_sub(w[2], w[0]), e2 = v3_sub(w[1], w[0]);
    return beyond_rounding(-in->orientation * v3_dot(w[0], v3_cross(e1, e2)), e1, e2, noise);
}

/* The same test for any set of points: every triple's plane through the
 * origin has points beyond the margin on both sides. Returns 1 when so; else
 * 0 with *shallow the normal of a plane with too little on its side (zero
 * when the points span no plane at all). */
static AGJK__COLD int deep_inside(const agjk_vec3 *p, int n, double noise, agjk_vec3 *shallow) {
    int planes = 0;
    *shallow = v3(0.0, 0.0, 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k) {
                agjk_vec3 e1 = v3_sub(p[j], p[i]), e2 = v3_sub(p[k], p[i]);
                agjk_vec3 c = v3_cross(e1, e2);
                /* A normal computed as zero says nothing about a facet's
                 * direction unless the three points lie exactly on one
                 * axis-parallel line (every product of the cross product
                 * zero): a point a hundred orders of magnitude nearer the
                 * origin than the others vanishes from both differences,
                 * and skipping such triples once certified an overlap of a
                 * point and a needle-shaped ellipsoid 0.12 apart (radii
                 * 1e-8, 10 and 4e43). Such a normal then fails below, as a
                 * normal lost in rounding does. */
                if (v3_norm2(c) == 0.0 && v3_norm2(v3_abs_cross(e1, e2)) == 0.0) continue;
                double hi = -INFINITY, lo = INFINITY;
                for (int m = 0; m < n; ++m) {
                    double v = v3_dot(c, p[m]);
                    if (v > hi) hi = v;
                    if (v < lo) lo = v;
                }
                if (!beyond_rounding(hi, e1, e2, noise)) {
                    *shallow = c;
                    return 0;
                }
                if (!beyond_rounding(-lo, e1, e2, noise)) {
                    *shallow = v3_neg(c);
                    return 0;
                }
                ++planes;
            }
    return planes > 0;
}

/* Points certify_overlap may hold: the simplex (2-4 points), a support the
 * caller already has, and the supports it adds. */
#define CERTIFY_POINTS 8

/* The origin in the active set, or within rounding of it, but not certified
 * by it: x = 0 on a segment or a triangle (boxes aligned with each other
 * often end so), ||x|| <= noise, or a tetrahedron with the origin near a
 * face. More supports, beyond the simplex where the origin is shallow
 * (across a segment, on both sides of a triangle, beyond a tetrahedron's
 * shallow faces, then beyond any plane the test finds shallow), until the
 * test passes, a support shows D itself is shallow there (the origin is near
 * its boundary: touching to rounding), or there is room for no more points.
 * Rare, so out of line; at most CERTIFY_POINTS - 2 supports. `known`, when
 * not NULL, is a point of D beyond a triangle's plane that the caller found
 * already (S_D(x), x the triangle's projection): it stands for the support
 * on its side. Returns 1 when certified (0 also after a bad support or a
 * rescale: the caller then answers what it has). */
static AGJK__NOINLINE AGJK__COLD int certify_overlap(solver *sv, agjk__solve_output *out,
                                                   const agjk_vec3 *known) {
    agjk_vec3 p[CERTIFY_POINTS], dirs[4];
    int n = sv->count, nd = 0;
    double noise = sv->md->noise, scale = sv->md->scale;
    for (int i = 0; i < n; ++i) p[i] = sv->w[i];
    if (n == 3 && known) {
        /* The other side of the triangle only. */
        agjk_vec3 c = v3_cross(v3_sub(p[1], p[0]), v3_sub(p[2], p[0]));
        dirs[nd++] = v3_dot(c, v3_sub(*known, p[0])) > 0.0 ? v3_neg(c) : c;
        p[n++] = *known;
    } else if (n == 2) {
        /* Two directions across the segment. */
        agjk_vec3 u = v3_sub(p[1], p[0]);
        agjk_vec3 ax = fabs(u.x) <= fabs(u.y) && fabs(u.x) <= fabs(u.z) ? v3(1.0, 0.0, 0.0)
                       : fabs(u.y) <= fabs(u.z)                          ? v3(0.0, 1.0, 0.0)
                                                                         : v3(0.0, 0.0, 1.0);
        agjk_vec3 v1 = v3_cross(u, ax), v2 = v3_cross(u, v1);
        dirs[nd++] = v1;
        dirs[nd++] = v3_neg(v1);
        dirs[nd++] = v2;
        dirs[nd++] = v3_neg(v2);
    } else if (n == 3) {
        agjk_vec3 c = v3_cross(v3_sub(p[1], p[0]), v3_sub(p[2], p[0]));
        dirs[nd++] = c;
        dirs[nd++] = v3_neg(c);
    } else if (n == 4) {
        /* Beyond each shallow face: its outward normal. */
        unsigned shallow = shallow_faces(p, noise);
        for (int f = 0; f < 4; ++f) {
            if (!(shallow & (1u << f))) continue;
            agjk_vec3 q = p[tetra_faces[f][0]];
            agjk_vec3 c = v3_cross(v3_sub(p[tetra_faces[f][1]], q), v3_sub(p[tetra_faces[f][2]], q));
            dirs[nd++] = v3_dot(c, v3_sub(p[f], q)) > 0.0 ? v3_neg(c) : c;
        }
    } else {
        return 0; /* x = 0 is a support point: the origin is on the boundary of D */
    }
    for (int round = 0; n < CERTIFY_POINTS; ++round) {
        agjk_vec3 u;
        if (round < nd) {
            u = dirs[round];
        } else if (deep_inside(p, n, noise, &u)) {
            return 1;
        }
        if (v3_maxabs(u) == 0.0 || !v3_isfinite(u)) return 0;
        /* support() minimises <d, .>: d = -u for the farthest point along u. */
        agjk_vec3 d = v3_neg(u);
        agjk__vertex s;
        support_rare(sv, &d, &s);
        ++out->support_calls;
        if (sv->md->bad_support || sv->md->scale != scale) return 0;
        if (round >= nd) {
            /* Nothing beyond the shallow plane: D is shallow there too. */
            double best = -INFINITY;
            for (int i = 0; i < n; ++i)
                if (v3_dot(u, p[i]) > best) best = v3_dot(u, p[i]);
            if (!(v3_dot(u, s.w) > best)) return 0;
        }
        p[n++] = s.w;
    }
    agjk_vec3 unused;
    return deep_inside(p, n, noise, &unused);
}

/* The loop is about to answer "contact within tolerance": a gap g at x that
 * meets the tolerance (or the floor) and decides no sign. Right for shapes
 * that touch, but overlapping ones can end so too: with the origin a hair
 * inside D (two ellipsoids of size 1 overlapping by 1.5e-6) and the
 * simplex's vertices a thousand times farther out, plain GJK keeps landing
 * on triangles that pass near the origin, ||x|| shrinks by a constant factor
 * per step, and sign_pending's budget runs out first; a warm-started query
 * of the same problem, which starts elsewhere, encloses the origin and
 * answers "intersecting" (coherent-motion benchmark, fast ellipsoids, 1 of
 * 4000 steps). A certificate withheld: when the gap's lower bound ||x|| -
 * g / (2 ||x||) is not positive (2 ||x||^2 <= g; a positive one shows the
 * origin outside D), certify_overlap tries a few supports beyond the simplex
 * (there, 2 after the loop's 19). Its price falls on shapes that touch
 * within the tolerance, once per query and at most 5 supports: measured on
 * ellipsoid pairs of the paper's law (300 per distance, tolerance 1e-8),
 * support calls of the adaptive method at distance 0 went from 18.6 to 23.2
 * (GJK: 49.1 to 52.8), at 1e-9 times their scale apart from 17.4 to 21.1
 * (no status changed there), and at 1e-9, 1e-7 and 1e-6 deep the overlaps
 * certified rose from 7, 159, 282 to 47, 246, 299 of 300; the paper's
 * protocol (23400 problems) never reaches it: no status and no support count
 * changed. Returns 1 when the query ends here, with out->outcome set
 * (intersecting, or a bad support); else 0 with g in the solver's units,
 * which certify_overlap's supports may have changed (a rescale, by a power
 * of two: exact). */
static AGJK__NOINLINE AGJK__COLD int settle_overlap(solver *sv, agjk__solve_output *out,
                                                  double *g, const agjk_vec3 *known) {
    double scale = sv->md->scale;
    if (certify_overlap(sv, out, known)) {
        out->outcome = AGJK__INTERSECTING;
        return 1;
    }
    if (sv->md->bad_support) {
        out->outcome = AGJK__BAD_SUPPORT;
        return 1;
    }
    double f = sv->md->scale / scale;
    *g *= f * f;
    return 0;
}

/* Inline, the common case (a positive lower bound, separated shapes) is one
 * test. `known`: S_D(x) when the caller has it (certify_overlap). */
static inline int overlap_after_all(solver *sv, agjk__solve_output *out, double *g,
                                    const agjk_vec3 *known) {
    if (!(2.0 * sv->x2 <= *g) || sv->count < 2) return 0;
    return settle_overlap(sv, out, g, known);
}

/* For each support mask of fewer than four vertices: the kept indices in
 * order, padded with the last one (so that every entry is a kept vertex),
 * and their count. */
static const unsigned char support_order[16][3] = {
    {0, 0, 0}, {0, 0, 0}, {1, 1, 1}, {0, 1, 1}, {2, 2, 2}, {0, 2, 2}, {1, 2, 2}, {0, 1, 2},
    {3, 3, 3}, {0, 3, 3}, {1, 3, 3}, {0, 1, 3}, {2, 3, 3}, {0, 2, 3}, {1, 2, 3}, {0, 1, 2}};
static const unsigned char support_size[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};

/* A point of the active set's hull near x, computed so that it is a point of
 * D to the rounding of the vertices whatever the conditioning of the
 * projection that gave x: sum lambda_i w_i (weights non-negative, adding up
 * to 1 to rounding). When that is farther than x by more than the rounding
 * (a sliver's weights are inaccurate), the nearest point of the hull's edges
 * (each a well-conditioned segment projection) if nearer. Used where ||x||
 * serves as an upper bound on the core distance. */
/* The rare part of member_point: the nearest point of the hull's edges, if
 * nearer than p. */
static AGJK__NOINLINE AGJK__COLD agjk_vec3 nearest_edge_point(const solver *sv, agjk_vec3 p) {
    double pp = v3_norm2(p);
    for (int i = 0; i < sv->count; ++i)
        for (int j = i + 1; j < sv->count; ++j) {
            agjk_vec3 edge[2] = {sv->w[i], sv->w[j]}, q;
            double l[4];
            agjk__simplex_project(edge, 2, l, &q);
            if (v3_norm2(q) < pp) {
                p = q;
                pp = v3_norm2(q);
            }
        }
    return p;
}

/* sum lambda_i w_i over the active set. */
static agjk_vec3 active_combination(const solver *sv) {
    agjk_vec3 p = v3(0.0, 0.0, 0.0);
    for (int i = 0; i < sv->count; ++i) p = v3_add(p, v3_scale(sv->w[i], sv->lambda[i]));
    return p;
}

/* The member point from p = active_combination(sv). */
static agjk_vec3 member_point_from(const solver *sv, agjk_vec3 p) {
    /* p is a member either way; the edges are searched only when p is longer
     * than x by more than about the rounding: (||x|| + 2 noise)^2 bounded
     * with ||x|| <= sqrt(3) max |x_i| (no square root at the end of every
     * query). */
    double n = sv->md->noise, reach2 = sv->x2 + 4.0 * n * (1.7320508075688772 * v3_maxabs(sv->x) + n);
    return v3_norm2(p) <= reach2 ? p : nearest_edge_point(sv, p);
}

static agjk_vec3 member_point(const solver *sv) {
    return member_point_from(sv, active_combination(sv));
}

/* update_simplex's answer for an enclosure whose weights the projection
 * left out (AGJK__WEIGHTS_DEFERRED): x is 0, sv->lambda not written. */
#define ENCLOSED_UNWEIGHED 2

/* Adds s to the active set and projects the origin onto its hull, keeping only
 * the vertices with positive weight (Alg. 4 line 7 / Alg. 5). Returns 1 when
 * the origin is enclosed by a full tetrahedron (ENCLOSED_UNWEIGHED when its
 * weights were left out). in_slot: support() has put
 * s->w in sv->w[sv->count] already. The projection reads the new point from
 * s->w, not from the slot, where a copy would have put it one more
 * store-to-load round trip later (GJK's chain of dependent steps: overlapping
 * Boolean queries 1-2% faster on every shape set). The weights go straight to
 * sv->lambda (compacted in place below): copied from a local array when the
 * origin was enclosed, two of them were read by one 16-byte load from two
 * 8-byte stores, which waited for the cache at the end of every overlapping
 * query. */
static AGJK__ALWAYS_INLINE int update_simplex(solver *sv, const agjk__vertex *s, int in_slot,
                                              agjk_vec3 *x) {
    int n = sv->count;
    if (!in_slot) sv->w[n] = s->w;
    if (sv->keep_a) {
        sv->a[n] = s->a;
        if (sv->keep_b) sv->b[n] = s->b;
    }
    sv->notes.turned_valid = 0;
    if (n == 0) {
        /* One point, its own projection (every cold query's first
         * iteration): no call, and x straight from the support. */
        sv->lambda[0] = 1.0;
        *x = s->w;
        sv->count = 1;
        return 0;
    }
    ++n;
    double *l = sv->lambda;
    unsigned mask = agjk__simplex_project_gjk_noted(sv->w, n, l, x, &sv->notes, &s->w);
    if ((mask & 0xFu) == 0xFu) {
        sv->inside_reported = (mask & AGJK__INSIDE_REPORTED) != 0;
        sv->count = 4;
        return mask & AGJK__WEIGHTS_DEFERRED ? ENCLOSED_UNWEIGHED : 1;
    }
    /* Keep the support set in index order: the kept indices from a table
     * and three slots always written (a 4-vertex set returned above), rather
     * than a test and a branch per vertex. Forward copies with source >=
     * destination, so in place is safe. */
    const unsigned char *from = support_order[mask & 0xFu];
    /* (Written out: -O2 keeps a three-pass loop, with its index loads.) */
    const int f0 = from[0], f1 = from[1], f2 = from[2];
    sv->w[0] = sv->w[f0];
    sv->w[1] = sv->w[f1];
    sv->w[2] = sv->w[f2];
    sv->lambda[0] = l[f0];
    sv->lambda[1] = l[f1];
    sv->lambda[2] = l[f2];
    if (sv->keep_a) {
        sv->a[0] = sv->a[f0];
        sv->a[1] = sv->a[f1];
        sv->a[2] = sv->a[f2];
        if (sv->keep_b) {
            sv->b[0] = sv->b[f0];
            sv->b[1] = sv->b[f1];
            sv->b[2] = sv->b[f2];
        }
    }
    sv->count = support_size[mask & 0xFu];
    return 0;
}

/* Whether an enclosure left without its weights (ENCLOSED_UNWEIGHED) is
 * certified as the loop certifies any enclosure (from the inside test's
 * data, or with no face of the tetrahedron within rounding of the origin).
 * Out of line, as the weighing below (cold): the loop's copy of these tests
 * stays its only inline one. */
static AGJK__NOINLINE int unweighed_overlap(const solver *sv) {
    double noise = sv->md->noise;
    return noise == 0.0 || deep_enclosure(sv, noise) || shallow_faces(sv->w, noise) == 0;
}

/* An enclosure update_simplex left without its weights (ENCLOSED_UNWEIGHED)
 * that the inside test's data did not certify: the projection again, with
 * the weights, which gives what update_simplex would have (the same four
 * points; a thin tetrahedron whose weights fail gets the exhaustive
 * projection's answer). Returns update_simplex's answer. */
static AGJK__NOINLINE AGJK__COLD int weigh_enclosure(solver *sv, agjk_vec3 *x) {
    sv->notes.weights_optional = 0;
    sv->count = 3;
    agjk__vertex s;
    s.w = sv->w[3];
    s.a = sv->keep_a ? sv->a[3] : v3(0.0, 0.0, 0.0); /* (written back as they are) */
    s.b = sv->keep_b ? sv->b[3] : v3(0.0, 0.0, 0.0);
    int enclosed = update_simplex(sv, &s, 1, x);
    sv->notes.weights_optional = 1;
    return enclosed;
}

/* What one Frank-Wolfe step's rounding may move its iterate by, in units of
 * eps (max |x_k| + max |s_k|): the segment foot (1 - t) b + t a, t and 1 - t
 * each rounded, is within about 3 eps (|a| + |b|) of the exact combination
 * with the computed t, and its cleanup along the segment (segment_cleanup)
 * moves it no farther from the segment's exact foot; the 2-norms are at most
 * sqrt(3) times the max norms. */
#define FW_STEP_ROUNDING 8.0

/* Plain Frank-Wolfe with exact line search (Alg. 1): the active set is the
 * iterate itself, stored as one vertex whose a, b accumulate the convex
 * combination so that witness points stay available. That vertex is a
 * computed point, not a support point: each step rounds it anew, hundreds of
 * steps add up (a box and a sphere 3.3e-16 apart were once certified as
 * intersecting through the margins, and a distance came out below the true
 * one), so sv->drift bounds the sum and widens every bound that x serves as
 * a point of D for. A step that lands on the support point itself starts it
 * again from 0. Out of line: Frank-Wolfe is the paper's baseline, and its
 * step only made the loop's two copies larger. */
static AGJK__NOINLINE void update_frank_wolfe(solver *sv, const agjk__vertex *s, agjk_vec3 *x) {
    if (sv->count == 0) {
        sv->w[0] = s->w;
        if (sv->keep_a) {
            sv->a[0] = s->a;
            sv->b[0] = s->b;
        }
    } else {
        agjk_vec3 w[2] = {sv->w[0], s->w};
        double l[4];
        agjk__simplex_project_gjk(w, 2, l, x);
        if (sv->keep_a) {
            sv->a[0] = v3_lerp2(sv->a[0], l[0], s->a, l[1]);
            sv->b[0] = v3_lerp2(sv->b[0], l[0], s->b, l[1]);
        }
        if (x->x == s->w.x && x->y == s->w.y && x->z == s->w.z)
            sv->drift = 0.0;
        else
            sv->drift += FW_STEP_ROUNDING * DBL_EPSILON * (v3_maxabs(w[0]) + v3_maxabs(s->w));
        sv->w[0] = *x;
    }
    sv->count = 1;
    sv->lambda[0] = 1.0;
    *x = sv->w[0];
}

/* A non-zero component whose products with others could underflow (both
 * vectors being brought to unit size first). */
static int tiny_nonzero(double v) { return v != 0.0 && fabs(v) < 0x1p-500; }

/* Whether d is a positive multiple of x, so that a gap computed with d is
 * one at x (a certificate). Conservative: both brought to unit max-norm
 * first (a multiple by a power of two, d = x in particular, stays bit for bit
 * the same), and a component so small that its products could underflow
 * counts as not parallel, since an underflowing cross product reads 0 for
 * directions that differ (a Polyak step of 1e-161 against an x of 1e-7 once
 * passed for parallel and certified a wrong gap). A false "no" costs one
 * support call. */
static AGJK__NOINLINE int parallel(agjk_vec3 d, agjk_vec3 x) {
    /* d = x bit for bit (a warm start certified by its first support): no
     * product, so nothing to underflow. */
    if (d.x == x.x && d.y == x.y && d.z == x.z) return v3_maxabs(x) > 0.0;
    double md = v3_maxabs(d), mx = v3_maxabs(x);
    if (!(md > 0.0) || !(mx > 0.0) || !(v3_dot(d, x) > 0.0)) return 0;
    /* The usual answer, "no" (a momentum direction), without the divisions:
     * in this range nothing below under- or overflows, and a component of
     * d x x above 2^-40 md mx stays far above the rounding of the unit-scaled
     * product below (a few eps), which therefore is not zero either. */
    if (md >= 0x1p-200 && md <= 0x1p200 && mx >= 0x1p-200 && mx <= 0x1p200) {
        agjk_vec3 c = v3_cross(d, x);
        if (v3_maxabs(c) > 0x1p-40 * (md * mx)) return 0;
    }
    d = v3_div(d, md);
    x = v3_div(x, mx);
    if (tiny_nonzero(d.x) || tiny_nonzero(d.y) || tiny_nonzero(d.z) || tiny_nonzero(x.x) ||
        tiny_nonzero(x.y) || tiny_nonzero(x.z))
        return 0;
    agjk_vec3 c = v3_cross(d, x);
    return c.x == 0.0 && c.y == 0.0 && c.z == 0.0;
}

/* Whether g (< 0) proves a lying support: below -lie_factor ||x|| noise. */
static int gap_lies(const solver *sv, double g) {
    double lie = sv->lie_factor * sv->md->noise;
    return g < 0.0 && g * g > lie * lie * sv->x2;
}

/* Adaptive method: stops at x (a point of D) when the best support plane met
 * so far, in any direction, certifies it as the gap does (direction.c), or
 * when that plane lies beyond x, which proves a lying support. Returns 1 with
 * out->outcome set. gp: the plane's gap at x (plane_stops). */
static AGJK__NOINLINE int plane_stops_slow(solver *sv, agjk__solve_output *out, int k,
                                           double gp) {
    const agjk__momentum *m = &sv->m;
    if (gap_lies(sv, gp)) {
        out->outcome = AGJK__BAD_SUPPORT; /* a plane beyond x, a point of D */
        return 1;
    }
    /* A NaN gp (no plane yet at x = 0) fails every test: no stop. */
    agjk__outcome v = gap_verdict(sv, gp, 0.0);
    if (v == AGJK__ITERATION_CAP) return 0;
    if (v == AGJK__CONVERGED && sign_pending(sv, gp, k)) return 0;
    if (overlap_after_all(sv, out, &gp, NULL)) return 1;
    if (!parallel(m->d_best, sv->x)) out->direction = m->d_best;
    out->gap = gp > 0.0 ? gp : 0.0;
    out->gap_valid = 1;
    out->outcome = v;
    return 1;
}

/* Inline, the common case (a plane gap above the tolerance and the floor,
 * with no lie: go on) is three tests, exactly gap_verdict's for an absolute
 * tolerance; the rest out of line. Twice per iteration, the call and the
 * full tests took 150 of the adaptive method's 4080 instructions per query on
 * close boxes. */
static inline int plane_stops(solver *sv, agjk__solve_output *out, int k) {
    double n = sqrt(sv->x2);
    /* 2 ||x|| (||x|| - plane) >= ||x||^2 - ||x*||^2 >= ||x - x*||^2 */
    double gp = 2.0 * n * (n - sv->m.plane);
    /* gap_verdict's answer, "not met", for an absolute tolerance, and no
     * lie (gp > 0); a NaN gp (no plane yet at x = 0) goes on as well. */
    double noise = sv->md->noise;
    if (!sv->in->relative && gp > sv->abs_tolerance && gp * gp > 4.0 * noise * noise * sv->x2)
        return 0;
    if (gp != gp) return 0;
    return plane_stops_slow(sv, out, k, gp);
}

/* Warm start: puts in->warm (projected by agjk__cache_load, cache.c) into
 * the solver as its active set, with its weights and projection x, in one
 * copy. Returns the number of vertices kept; 4 when they enclose the origin
 * (x = 0). */
static int warm_seed(const agjk__solve_input *in, solver *sv) {
    /* Projected by agjk__cache_load already: keep the support set, in order. */
    sv->x = in->warm_x;
    int kept = 0;
    for (int i = 0; i < in->warm_count; ++i) {
        if (!(in->warm_mask & (1u << i))) continue;
        sv->w[kept] = in->warm[i].w;
        sv->lambda[kept] = in->warm_lambda[i];
        ++kept;
    }
    return kept;
}

/* The points of A and B of the vertices warm_seed kept: only when the query
 * goes on past warm_certified, or its answer needs them (most warm queries on
 * flat shapes need neither). */
static void warm_seed_points(const agjk__solve_input *in, solver *sv) {
    int kept = 0;
    for (int i = 0; i < in->warm_count; ++i) {
        if (!(in->warm_mask & (1u << i))) continue;
        sv->a[kept] = in->warm[i].a;
        sv->b[kept] = in->warm[i].b;
        ++kept;
    }
}

/* Warm start: 0 when the plane of the support s found in direction d cuts off
 * one of the points w[0..count-1] (which are then not points of D), else 1. */
static int warm_consistent(const agjk_vec3 *w, int count, agjk_vec3 d, const agjk__vertex *s,
                           double noise) {
    /* s minimises <d, .> over D: every point of D has <d, p> >= <d, s>, up to
     * the rounding of the points (a few ulps of the problem's size). */
    double ds = v3_dot(d, s->w), slack2 = 64.0 * noise * noise * v3_norm2(d);
    for (int i = 0; i < count; ++i) {
        /* <d, w_i> >= <d, s> - 8 noise |d|, without the square root when
         * w_i is on the plane's side (the usual case). */
        double below = ds - v3_dot(d, w[i]);
        if (below > 0.0 && below * below > slack2) return 0;
    }
    return 1;
}

/* Iteration 0's support (agjk__solve_start: it also settles the problem's
 * scale), the caller's or taken here, and the solver's state from it. */
static AGJK__ALWAYS_INLINE void first_support(solver *sv, agjk__vertex *s,
                                              agjk__solve_output *out, const agjk__start *start) {
    if (start) {
        *s = start->s;
        sv->x = start->x;
    } else {
        agjk__first_support(sv->md, sv->in, s, &sv->x, 0);
    }
    sv->x2 = v3_norm2(sv->x);
    sv->abs_tolerance = sv->in->tolerance * sv->md->scale * sv->md->scale;
    ++out->support_calls;
}

/* The solver's output from its final state: the iterate, a member point of
 * D near it, the witness points and the active set. */
static void finish(const solver *sv, agjk__solve_output *out) {
    const agjk__solve_input *in = sv->in;
    out->x = sv->x;
    /* (An overlap has no upper bound to certify, and a separating plane
     * answers with its normal alone: no member point needed.) */
    int member = sv->count > 0 && out->outcome != AGJK__INTERSECTING &&
                 out->outcome != AGJK__SEPARATED_EARLY;
    int b_from_a = in->want_witness && sv->b_from_a;
    /* sum lambda_i w_i, for the member point and B's witness point alike */
    agjk_vec3 p = member || b_from_a ? active_combination(sv) : v3(0.0, 0.0, 0.0);
    out->x_member = member ? member_point_from(sv, p) : sv->x;
    out->noise = sv->md->noise + sv->drift;
    agjk_vec3 a = v3(0.0, 0.0, 0.0), b = v3(0.0, 0.0, 0.0);
    if (in->want_witness) {
        /* B's: sum lambda_i (a_i - w_i), each a_i - w_i being b_i to the
         * rounding of w_i = a_i - b_i; taken so whether or not b_i were
         * kept, so that a warm-started query that ends where a cold one
         * does answers the same bits. */
        for (int i = 0; i < sv->count; ++i) {
            a = v3_add(a, v3_scale(sv->a[i], sv->lambda[i]));
            if (!b_from_a) b = v3_add(b, v3_scale(sv->b[i], sv->lambda[i]));
        }
        if (b_from_a) b = v3_sub(a, p);
    }
    out->a = a;
    out->b = b;
    /* The final active set, for EPA and the cache (a and b with keep_points). */
    int n = in->want_simplex ? sv->count : 0;
    for (int i = 0; i < n && !out->warm_kept; ++i) {
        out->simplex[i].w = sv->w[i];
        out->simplex[i].a = sv->keep_a ? sv->a[i] : v3(0.0, 0.0, 0.0);
        out->simplex[i].b = sv->keep_b ? sv->b[i] : v3(0.0, 0.0, 0.0);
    }
    out->simplex_count = n;
    out->flat = sv->m.flat_seen;
}

/* Warm start on flat shapes, the usual case after a small motion: the first
 * support, in the direction of the cached simplex's projection x, meets no
 * cached point beyond its plane and certifies x with a gap that meets the
 * tolerance and shows the shapes apart. Exactly the loop's verdict at k = 0
 * (its gap test, or for the adaptive method the plane of that same support,
 * which then gives the same gap), without setting up the loop. Returns 1 with
 * out->outcome and the gap set. */
static AGJK__ALWAYS_INLINE int warm_certified(solver *sv, agjk_vec3 d, const agjk__vertex *s,
                                              agjk__solve_output *out) {
    if (sv->count == 4 || !warm_consistent(sv->w, sv->count, d, s, sv->md->noise)) return 0;
    double g = 2.0 * v3_dot(sv->x, v3_sub(sv->x, s->w));
    if (gap_lies(sv, g) || gap_verdict(sv, g, 0.0) != AGJK__CONVERGED || !gap_separates(sv, g))
        return 0;
    out->gap = g;
    out->gap_valid = 1;
    out->outcome = AGJK__CONVERGED;
    return 1;
}

static AGJK__ALWAYS_INLINE void solve(agjk__minkowski *md, const agjk__solve_input *in,
                                      const agjk__start *start, agjk__solve_output *out) {
    solver sv;
    sv.md = md;
    sv.in = in;
    sv.count = 0;
    sv.drift = 0.0;
    sv.notes.rotation = &md->rotation[0][0];
    sv.notes.turned_valid = 0;
    /* (An overlap's weights serve only its witness points.) */
    sv.notes.weights_optional = !in->want_witness;

    out->outcome = AGJK__ITERATION_CAP;
    out->gap = INFINITY;
    out->gap_valid = 0;
    out->xs2 = 0.0;
    out->iterations = 1;
    out->support_calls = 0;
    out->momentum_stop = -1;
    out->direction = v3(0.0, 0.0, 0.0);
    out->simplex_count = 0;
    out->flat = 0;
    out->warm_kept = 0;

    /* Iteration 0's support, and its tests, before any other set-up: distant
     * shapes in Boolean mode end here (a separating plane at once, as in
     * Alg. 2; without a cache the caller has answered them already), paying
     * for no simplex or momentum work. */
    agjk__vertex s;
    first_support(&sv, &s, out, start);
    agjk_vec3 d0 = sv.x; /* direction of the first support */
    if (start ? start_ends_query(md, start, out) : support_ends_query(&sv, d0, &s, out)) {
        out->x = out->x_member = sv.x;
        out->noise = md->noise;
        out->a = out->b = v3(0.0, 0.0, 0.0);
        return;
    }
    /* For warm starts too: on moving ellipsoids (2.8 supports per query)
     * reading the data costs about what the support path's skipped tests
     * save, and B's point then takes the loop's short path (minkowski.h):
     * fast-moving ellipsoid pairs 2-4% faster with the cache. */
    agjk__minkowski_bound_points(md);

    sv.lambda[0] = 1.0;
    sv.lambda[1] = sv.lambda[2] = sv.lambda[3] = 0.0;
    sv.keep_a = in->keep_points;
    sv.b_from_a = in->method != AGJK_METHOD_FRANK_WOLFE;
    sv.keep_b = in->keep_points && (in->want_simplex || !sv.b_from_a);
    int have_x = 0;      /* x is a point of D (after the first projection) */
    int warm = 0, warm_enclosed = 0; /* cached points in the simplex (cache.c) */
    /* Warm-started points carry a few more ulps from their frame changes:
     * warm_consistent lets each lie up to 8 noise beyond a support plane, so a
     * gap (2 ||x|| times the distance beyond the plane) proves a lie only well
     * beyond 16 ||x|| noise. */
    sv.lie_factor = in->warm_count > 0 ? 32.0 : 4.0;
    sv.m.flat_seen = 0;

    /* Warm start: the cached simplex is the active set at k = 0, and plain GJK
     * directions take it from there (cache.c). Only for problems of ordinary
     * size, where x_0, its projection, is used as given. */
    if (in->warm_count > 0 && sv.x.x == in->x0.x && sv.x.y == in->x0.y && sv.x.z == in->x0.z) {
        sv.count = warm_seed(in, &sv);
        sv.x2 = v3_norm2(sv.x);
        have_x = 1;
        warm = 1;
        warm_enclosed = sv.count == 4;
        if (warm_certified(&sv, d0, &s, out)) {
            /* The cached simplex, whole and unmoved, is the answer's: the
             * cache keeps it as it is (no copy, cache.c). */
            out->warm_kept = sv.count == in->warm_count;
            if (in->want_witness || (in->want_simplex && !out->warm_kept))
                warm_seed_points(in, &sv);
            finish(&sv, out);
            return;
        }
        if (sv.keep_a) warm_seed_points(in, &sv);
    }
    /* x_0 in solver units: d_{-1} = s_{-1} = x_0. */
    agjk__momentum_init(&sv.m, in->method, d0, in->x0_given, in->boolean_mode);
    if (warm) sv.m.active = 0;
    int adaptive = in->method == AGJK_METHOD_ADAPTIVE;
    int stalled = 0;     /* consecutive iterations without progress */
    sv.sign_budget = SIGN_SEEK_ITERATIONS;
    sv.plain_next = 0;
    /* x_k, the next plain direction, as a local: sv.x lives in memory (sv's
     * address goes to many functions), and reading it back at the top of
     * the loop put a store-to-load round trip on GJK's chain of dependent
     * steps (close and overlapping ellipsoids 1.5% faster). */
    agjk_vec3 x_dir = sv.x;
    for (int k = 0; k < in->max_iterations; ++k) {
        out->iterations = k + 1;
        agjk_vec3 d = k == 0 ? d0 : x_dir;
        int in_slot = 0; /* support() has put s.w in sv.w[sv.count] */
        if (k > 0) {
            /* A plain step's direction is x itself, whose |x|^2 is known,
             * and R^T x too when the projection turned it (a face). */
            double d2 = sv.x2;
            const agjk_vec3 *db = sv.notes.turned_valid ? &sv.notes.turned : NULL;
            if (sv.m.active) {
                /* A momentum direction whose |d|^2 lies in the support
                 * path's safe range is non-zero and finite, which is all
                 * that agjk__direction_or_gradient tests, and |d|^2 then
                 * settles the support's own range test too: one test of
                 * |d|^2 where there were two of |d|_1 and max |d_i| (the
                 * same directions and bits). */
                d = agjk__momentum_mix(&sv.m, k, x_dir);
                d2 = v3_norm2(d);
                if (!agjk__minkowski_direction_safe(md, d2)) {
                    d = agjk__direction_or_gradient(d, sv.x);
                    d2 = 0.0;
                }
                db = NULL;
            }
            in_slot = support(&sv, &d, d2, &s, AGJK__SUPPORT_DIRECT_LOOP, db);
            ++out->support_calls;
            if (loop_support_ends_query(&sv, start != NULL, d, &s, out)) break;
            /* Adaptive method: a first momentum support that found s_0 again
             * (the simplex's one point, bit for bit) told nothing; once, in
             * another direction (direction.c, agjk__momentum_retry). Its own
             * plane is dropped: only the retried one is recorded. */
            if (k == 1 && sv.m.phase == AGJK__PHASE_POLYAK && sv.m.active && sv.count == 1 &&
                s.w.x == sv.w[0].x && s.w.y == sv.w[0].y && s.w.z == sv.w[0].z &&
                sv.m.plane <= 0.0 && !parallel(d, sv.x)) {
                d = agjk__momentum_retry(&sv.m, sv.x);
                support_rare(&sv, &d, &s);
                in_slot = 0;
                ++out->support_calls;
                if (support_ends_query(&sv, d, &s, out)) break;
                sv.plain_next = 1;
            }
        }
        if (warm) {
            /* A support plane that cuts off a cached point proves the cache
             * stale: go on cold from this support (cache.c). */
            if (!warm_consistent(sv.w, sv.count, d, &s, md->noise)) {
                sv.count = 0;
                in_slot = 0;
                have_x = 0;
                warm = warm_enclosed = 0;
            }
            if (warm_enclosed) {
                /* Cached points carry up to 8 noise more (warm_consistent). */
                if (shallow_faces(sv.w, 9.0 * md->noise) == 0 ||
                    md->margin > 13.0 * md->noise) {
                    out->outcome = AGJK__INTERSECTING;
                    out->warm_kept = 1; /* the cached tetrahedron, as it was */
                    break;
                }
                /* Not deep enough to certify: on cold from this support. */
                sv.count = 0;
                in_slot = 0;
                have_x = 0;
                warm = warm_enclosed = 0;
            }
        }
        /* Adaptive method: every support plane is a lower bound (direction.c),
         * which may certify x as well as the gap does (no extra support in
         * direction x_k once momentum has done its work). */
        if (adaptive) {
            agjk__momentum_plane(&sv.m, d, s.w, sv.x);
            if (have_x && plane_stops(&sv, out, k)) break;
        }
        if (have_x) {
            double g = 2.0 * v3_dot(sv.x, v3_sub(sv.x, s.w)); /* eq. 29 */
            /* (The adaptive method's plain steps, d = x, need no fallback:
             * their g is a true gap, tested by plane_stops already.) */
            if (sv.m.active && momentum_stalls(&sv, g, k) && !(adaptive && parallel(d, sv.x))) {
                /* Alg. 6 lines 5-7: the momentum direction makes no progress. */
                if (parallel(d, sv.x)) {
                    if (overlap_after_all(&sv, out, &g, &s.w)) break;
                    out->gap = g;
                    out->gap_valid = 1;
                    out->xs2 = v3_norm2(v3_sub(sv.x, s.w));
                    agjk__outcome v = gap_verdict(&sv, g, 0.0);
                    out->outcome = v == AGJK__CONVERGED ? v : AGJK__AT_FLOOR;
                    break;
                }
                sv.m.active = 0;
                out->momentum_stop = k;
                d = sv.x;
                support_rare(&sv, &d, &s);
                in_slot = 0;
                ++out->support_calls;
                if (support_ends_query(&sv, d, &s, out)) break;
                if (adaptive) agjk__momentum_plane(&sv.m, d, s.w, sv.x);
                g = 2.0 * v3_dot(sv.x, v3_sub(sv.x, s.w));
            }
            if (!sv.m.active) {
                /* x is in D and s minimises <x, .> over D, so g >= 0 up to
                 * rounding. Clearly negative (below -4 ||x|| noise): the support
                 * function lies. */
                if (gap_lies(&sv, g)) {
                    out->outcome = AGJK__BAD_SUPPORT;
                    break;
                }
                out->gap_valid = 1;
                agjk__outcome v = gap_verdict(&sv, g, 0.0);
                if (v != AGJK__ITERATION_CAP && !(v == AGJK__CONVERGED && sign_pending(&sv, g, k))) {
                    if (overlap_after_all(&sv, out, &g, &s.w)) break;
                    out->outcome = v;
                    out->gap = g; /* a true Frank-Wolfe gap: s = S_D(x) */
                    out->xs2 = v3_norm2(v3_sub(sv.x, s.w));
                    break;
                }
                out->gap = g;
            }
        }
        agjk_vec3 x_new;
        int enclosed;
        if (in->method == AGJK_METHOD_FRANK_WOLFE) {
            update_frank_wolfe(&sv, &s, &x_new);
            enclosed = v3_norm2(x_new) == 0.0;
        } else {
            enclosed = update_simplex(&sv, &s, in_slot, &x_new);
            if (enclosed == ENCLOSED_UNWEIGHED) {
                /* The origin clearly inside a thin tetrahedron: certified
                 * from the inside test's data as below, the overlap needs no
                 * weights; otherwise they are taken after all, and the
                 * iteration goes on as it would have with them. */
                if (unweighed_overlap(&sv)) {
                    sv.x = x_new;
                    sv.x2 = 0.0;
                    out->gap_valid = 0;
                    out->outcome = AGJK__INTERSECTING;
                    break;
                }
                enclosed = weigh_enclosure(&sv, &x_new);
            }
        }
        double x_new2 = v3_norm2(x_new);
        int no_progress = have_x && !enclosed && x_new2 >= sv.x2;
        sv.x = x_new;
        x_dir = x_new;
        sv.x2 = x_new2;
        have_x = 1;
        out->gap_valid = 0;
        double margin = md->margin, noise = md->noise;
        /* The cores overlap, certified: the computed tetrahedron holds the
         * origin deeper than the rounding of its vertices (or nothing was
         * rounded at all). Otherwise an enclosure, or an x = 0 on a face or an
         * edge, only shows the cores within about 2 noise of each other:
         * ||x*|| <= ||x|| + 2 noise, which the margins may still cover. */
        int at_origin = enclosed || x_new2 == 0.0;
        int core_overlap = 0;
        if ((at_origin || x_new2 <= noise * noise) && in->method != AGJK_METHOD_FRANK_WOLFE) {
            /* The origin in the simplex, or within rounding of it: certified
             * if it lies deep inside the points (with a few more if needed). */
            core_overlap = (at_origin && noise == 0.0) ||
                           (enclosed && (deep_enclosure(&sv, noise) ||
                                         shallow_faces(sv.w, noise) == 0)) ||
                           certify_overlap(&sv, out, NULL);
            if (md->bad_support) {
                out->outcome = AGJK__BAD_SUPPORT;
                break;
            }
        } else if (at_origin) {
            core_overlap = noise == 0.0; /* plain FW keeps no simplex to certify with */
        }
        /* Through the margins: the core distance is at most ||x_member|| (up to
         * the points' rounding), or 2 noise with the origin in the simplex. */
        int margins_overlap = 0;
        if (margin > noise && (at_origin || x_new2 < (margin - noise) * (margin - noise))) {
            double m = v3_norm(member_point(&sv));
            double bound = (at_origin && m < 2.0 * noise ? 2.0 * noise : m) + noise + sv.drift;
            margins_overlap = bound < margin;
        }
        if (core_overlap || margins_overlap) {
            out->outcome = AGJK__INTERSECTING;
            break;
        }
        /* x is zero to rounding (||x|| <= noise): the cores touch or overlap
         * within what double precision can tell (plain FW creeps towards such
         * an x forever). */
        if (at_origin || x_new2 <= noise * noise) {
            out->outcome = AGJK__AT_ROUNDING;
            if (at_origin) {
                /* No direction to certify along (below): x = 0 stands, with
                 * the rounding allowance of query.c as its bound. */
                out->gap = 0.0;
                out->gap_valid = 1;
            }
            break;
        }
        if (no_progress) {
            /* With momentum, no progress is the fixed point of eq. 28 (s_k adds
             * nothing to the simplex): switch to GJK directions, even if g has
             * not met the tolerance (a relative tolerance on overlapping shapes
             * never does). Plain directions must decrease ||x||, but near the
             * optimum the decrease can be below the rounding of ||x||^2 while
             * the gap at the new x already meets the tolerance: so stop only
             * after two such iterations in a row (the next gap test decides). */
            if (sv.m.active) {
                sv.m.active = 0;
                out->momentum_stop = k;
            } else if (++stalled >= 2) {
                out->outcome = AGJK__STALLED;
                break;
            }
        } else {
            stalled = 0;
        }
        /* Adaptive method: the planes met so far may certify x_{k+1} already,
         * before any support in its direction. */
        if (adaptive && plane_stops(&sv, out, k)) break;
        /* d_{k-1}, s_{k-1}; the adaptive method may switch phase here, and
         * flat faces are recorded for the cache. */
        if (adaptive || in->track_flat) {
            if (agjk__momentum_update(&sv.m, k, d, &s, sv.x2)) out->momentum_stop = k;
        } else {
            sv.m.d_prev = d;
            sv.m.s_prev = s.w;
        }
        if (sv.plain_next && sv.m.active) {
            sv.m.active = 0;
            out->momentum_stop = k;
        }
    }

    /* Without a valid gap at the final iterate (cap, stall, or momentum still
     * on), one support in direction x certifies what was reached; a gap that
     * meets the tolerance, or the wide floor, then counts, whatever path the
     * loop took. */
    if ((out->outcome == AGJK__ITERATION_CAP || out->outcome == AGJK__STALLED ||
         out->outcome == AGJK__AT_ROUNDING) && have_x && !out->gap_valid) {
        agjk_vec3 d = sv.x;
        support_rare(&sv, &d, &s);
        ++out->support_calls;
        if (!support_ends_query(&sv, d, &s, out)) {
            agjk_vec3 xs = v3_sub(sv.x, s.w);
            out->gap = 2.0 * v3_dot(sv.x, xs);
            out->gap_valid = 1;
            out->xs2 = v3_norm2(xs);
            if (out->outcome != AGJK__AT_ROUNDING) {
                agjk__outcome v = gap_verdict(&sv, out->gap, out->xs2);
                if (v != AGJK__ITERATION_CAP && !overlap_after_all(&sv, out, &out->gap, &s.w))
                    out->outcome = v;
            }
        }
    }

    finish(&sv, out);
}

/* Two copies of the solver, one per source of iteration 0's support: the
 * loop compiles worse in a function that may be handed it (close
 * ellipsoids 15 602 -> 15 695 instructions per query), so distance queries
 * and EPA keep the one that takes its own, and only Boolean queries, which
 * take it before the solver to end distant pairs early, pay for the
 * other. */
AGJK__HOT_ENTRY void agjk__solve(agjk__minkowski *md, const agjk__solve_input *in, agjk__solve_output *out) {
    solve(md, in, NULL, out);
}

AGJK__HOT_ENTRY void agjk__solve_from(agjk__minkowski *md, const agjk__solve_input *in, const agjk__start *start,
                      agjk__solve_output *out) {
    if (!start) {
        agjk__solve(md, in, out);
        return;
    }
    solve(md, in, start, out); /* (with start known non-null: no path of its own) */
}
