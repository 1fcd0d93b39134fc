/* SPDX-License-Identifier: MIT */
/* Projection of the origin onto a point, segment, triangle or tetrahedron.
 *
 * The method follows the signed-volume idea of Montanari, Petrinic and Barbieri,
 * "Improving the GJK algorithm for faster and more reliable distance queries
 * between convex objects" (ACM TOG 2017): compute the barycentric coordinates of
 * the origin's projection onto the affine hull from signed areas/volumes; if all
 * are positive the projection is interior, otherwise the answer lies on a facet
 * whose opposite coordinate is not positive, and we recurse on those facets
 * only, keeping the closest candidate.
 *
 * Robustness: a facet is declared degenerate when its area (volume) is below a
 * few ulps of the product of its edge lengths. A degenerate simplex carries no
 * information its facets lack, so we recurse on all its facets instead of
 * dividing by a meaningless determinant. Every division is therefore by a
 * quantity known to be well away from zero, and the recursion depth is at most
 * three: the routine cannot loop and cannot produce NaN from finite input. */
#include "simplex.h"

#include "agjk/query.h"

/* Relative size below which an area or volume is treated as zero. */
#define DEGENERATE_RELATIVE (64.0 * DBL_EPSILON)

/* Worst-case error of a triangle's foot, in ulps of its largest vertex,
 * beyond which the foot is not used (project_triangle). */
#define SLIVER_ULPS 4096.0

static void set_vertex(int i, int n, double lambda[4], agjk_vec3 p, agjk_vec3 *point) {
    for (int j = 0; j < n; ++j) lambda[j] = 0.0;
    lambda[i] = 1.0;
    *point = p;
}

/* The foot p of the origin on a segment along e, measured from its end b,
 * is orthogonal to e, but the computed one is off along e by a few ulps of b:
 * nothing when b is near the origin, everything for a needle (b 1e9 away, the
 * foot 1e-2 away), whose next support direction would then tilt along the
 * needle and fetch the same end again (GJK stalls). So when |b| exceeds |p|
 * a million times, p's component along e is removed, leaving an error of a
 * few ulps of |p| itself; otherwise (the usual case, a predicted branch) p
 * stays as computed. */
static inline agjk_vec3 segment_cleanup(agjk_vec3 p, agjk_vec3 b, agjk_vec3 e, double ee) {
    if (!(v3_norm2(b) > 0x1p40 * v3_norm2(p))) return p;
    return v3_sub(p, v3_scale(e, v3_dot(p, e) / ee));
}

/* Segment p[i]-p[j] inside an n-point simplex. */
static unsigned project_segment(const agjk_vec3 *p, int n, int i, int j, double lambda[4],
                                agjk_vec3 *point) {
    agjk_vec3 a = p[i], b = p[j];
    agjk_vec3 e = v3_sub(b, a);
    double ee = v3_norm2(e);
    double t = ee > 0.0 ? -v3_dot(a, e) / ee : 0.0;
    if (!(t > 0.0) || ee == 0.0) {
        /* Origin projects before a (or the segment is a point): closer of a, b. */
        if (ee == 0.0 || v3_norm2(a) <= v3_norm2(b)) {
            set_vertex(i, n, lambda, a, point);
            return 1u << i;
        }
        set_vertex(j, n, lambda, b, point);
        return 1u << j;
    }
    if (t >= 1.0) {
        set_vertex(j, n, lambda, b, point);
        return 1u << j;
    }
    for (int k = 0; k < n; ++k) lambda[k] = 0.0;
    lambda[i] = 1.0 - t;
    lambda[j] = t;
    *point = segment_cleanup(v3_lerp2(a, 1.0 - t, b, t), a, e, ee);
    return (1u << i) | (1u << j);
}

static int count_bits(unsigned mask) {
    int c = 0;
    for (; mask; mask &= mask - 1u) ++c;
    return c;
}

/* Keeps the candidate closer to the origin. */
typedef struct candidate {
    double norm2;
    unsigned mask;
    double lambda[4];
    agjk_vec3 point;
} candidate;

static void keep_best(candidate *best, unsigned mask, const double lambda[4], agjk_vec3 point, int n) {
    double nn = v3_norm2(point);
    /* Ties go to the smaller support set: the smallest sub-simplex holding the point. */
    int fewer = count_bits(mask) < count_bits(best->mask);
    if (nn < best->norm2 || (nn == best->norm2 && fewer)) {
        best->norm2 = nn;
        best->mask = mask;
        best->point = point;
        for (int k = 0; k < n; ++k) best->lambda[k] = lambda[k];
    }
}

/* How far a triangle's weights may put their combination from the foot they
 * stand for, in ulps of the largest vertex: usually a few, as much as the
 * foot's own worst case (SLIVER_ULPS, whose triangles keep their foot) on
 * thin ones; a sliver's cancelled weights are off by a fraction of the
 * triangle. */
#define WEIGHTS_ULPS SLIVER_ULPS

/* The exhaustive paths are cold since the GJK fast path decides almost every
 * call (agjk__simplex_project_gjk): compiled for size. */
static AGJK__COLD unsigned project_triangle(const agjk_vec3 *p, int n, int i, int j, int k,
                                           double lambda[4], agjk_vec3 *point) {
    agjk_vec3 a = p[i], b = p[j], c = p[k];
    agjk_vec3 ab = v3_sub(b, a), bc = v3_sub(c, b), ca = v3_sub(a, c);
    double lab = v3_norm2(ab), lbc = v3_norm2(bc), lca = v3_norm2(ca);
    /* The normal (b-a) x (c-a) = (c-b) x (a-b) = (a-c) x (b-c); its rounding error
     * is about eps |e1| |e2| for the two edges used, so use the two shortest:
     * with one far vertex, the long edges would cancel catastrophically. */
    agjk_vec3 nrm, bound; /* bound: abs_cross of the same two edges */
    double scale;
    if (lbc >= lab && lbc >= lca) {
        nrm = v3_cross(ab, v3_neg(ca));
        bound = v3_abs_cross(ab, ca);
        scale = lab * lca;
    } else if (lca >= lab) {
        nrm = v3_cross(bc, v3_neg(ab));
        bound = v3_abs_cross(bc, ab);
        scale = lbc * lab;
    } else {
        nrm = v3_cross(ca, v3_neg(bc));
        bound = v3_abs_cross(ca, bc);
        scale = lca * lbc;
    }
    double nn = v3_norm2(nrm);
    double edge_sign[3] = {-1.0, -1.0, -1.0}; /* <= 0: try the edge opposite that vertex */
    /* The vertex nearest the origin, and the largest one. */
    double na = v3_norm2(a), nb = v3_norm2(b), nc = v3_norm2(c);
    agjk_vec3 v = a;
    double vv = na, far = na;
    if (nb < vv) { v = b; vv = nb; }
    if (nc < vv) { v = c; vv = nc; }
    if (nb > far) far = nb;
    if (nc > far) far = nc;
    /* Each component of the normal is off by a few eps times the same
     * component of |e1| x |e2| taken with absolute values (bound), so its
     * direction by at most about eps |bound| / |n|, and the foot below by that
     * times |v|. Beyond SLIVER_ULPS ulps of the largest vertex (a sliver far
     * from the origin, nearly collinear with it: the ends of a needle and a
     * point beside its middle, whose foot came out 1e-7 off where the whole
     * answer was 1e-7), the plane is not known well enough and the edges
     * decide, as for a degenerate triangle. (The bound is a worst case, often
     * 100 times the actual error: thin triangles far inside it keep their
     * foot.) */
    if (nn > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * scale &&
        v3_norm2(bound) * vv <= nn * far * (SLIVER_ULPS * SLIVER_ULPS)) {
        /* Foot of the origin on the plane, from the vertex nearest the origin
         * (the error of <n, v> grows with |v|). */
        agjk_vec3 foot = v3_scale(nrm, v3_dot(nrm, v) / nn);
        /* Barycentric coordinates of the foot from signed areas of the
         * sub-triangles, measured from the foot itself (Montanari et al. 2017):
         * lambda_a = <n, (b - f) x (c - f)> / |n|^2, and cyclically. */
        agjk_vec3 fa = v3_sub(a, foot), fb = v3_sub(b, foot), fc = v3_sub(c, foot);
        double la = v3_dot(nrm, v3_cross(fb, fc));
        double lb = v3_dot(nrm, v3_cross(fc, fa));
        double lc = v3_dot(nrm, v3_cross(fa, fb));
        double sum = la + lb + lc;
        if (la > 0.0 && lb > 0.0 && lc > 0.0 && sum > 0.0) {
            double wa = la / sum, wb = lb / sum, wc = lc / sum;
            /* The weights must give the foot back. On a sliver (two
             * vertices a few ulps apart, the third far off) the plane and
             * the foot are right while the signed areas cancel: weights off
             * by tens of percent, whose combination missed the foot by 3% of
             * the triangle. The edges decide then (below), each a
             * well-conditioned segment whose foot lies within the sliver's
             * width of this one. */
            agjk_vec3 back = v3_add(v3_add(v3_scale(a, wa), v3_scale(b, wb)), v3_scale(c, wc));
            double limit = WEIGHTS_ULPS * DBL_EPSILON;
            if (v3_norm2(v3_sub(back, foot)) <= limit * limit * far) {
                for (int q = 0; q < n; ++q) lambda[q] = 0.0;
                lambda[i] = wa;
                lambda[j] = wb;
                lambda[k] = wc;
                *point = foot;
                return (1u << i) | (1u << j) | (1u << k);
            }
            la = lb = lc = -1.0; /* every edge */
        }
        edge_sign[0] = la;
        edge_sign[1] = lb;
        edge_sign[2] = lc;
    }
    const int edges[3][2] = {{j, k}, {i, k}, {i, j}};
    int visible = (edge_sign[0] <= 0.0) + (edge_sign[1] <= 0.0) + (edge_sign[2] <= 0.0);
    if (visible == 1) {
        /* The usual case: the closest point is on the one edge facing the origin. */
        int e = edge_sign[0] <= 0.0 ? 0 : (edge_sign[1] <= 0.0 ? 1 : 2);
        return project_segment(p, n, edges[e][0], edges[e][1], lambda, point);
    }
    candidate best;
    best.norm2 = INFINITY;
    best.mask = 0xFu;
    for (int e = 0; e < 3; ++e) {
        if (edge_sign[e] > 0.0) continue;
        double tmp[4];
        agjk_vec3 pt;
        unsigned m = project_segment(p, n, edges[e][0], edges[e][1], tmp, &pt);
        keep_best(&best, m, tmp, pt, n);
    }
    for (int q = 0; q < n; ++q) lambda[q] = best.lambda[q];
    *point = best.point;
    return best.mask;
}

/* The origin's barycentric coordinates in the tetrahedron p[0..3], times
 * its oriented volume *sum > 0, into w: 0 when the tetrahedron is
 * degenerate. The origin is written as q + mu_1 e_1 + mu_2 e_2 + mu_3 e_3
 * with q the vertex nearest the origin and e_i the edges from it, and
 * solved by Cramer's rule: every rounding error then scales with |q| and the
 * edge lengths rather than with the distance of the far vertices to the
 * origin. */
static inline int apex_coordinates(const agjk_vec3 *p, double w[4], double *sum) {
    int apex = 0;
    for (int v = 1; v < 4; ++v)
        if (v3_norm2(p[v]) < v3_norm2(p[apex])) apex = v;
    int other[3], o = 0;
    for (int v = 0; v < 4; ++v)
        if (v != apex) other[o++] = v;
    agjk_vec3 base = p[apex], nq = v3_neg(base);
    agjk_vec3 e1 = v3_sub(p[other[0]], base), e2 = v3_sub(p[other[1]], base),
              e3 = v3_sub(p[other[2]], base);
    agjk_vec3 c23 = v3_cross(e2, e3);
    double vol = v3_dot(e1, c23);
    double scale2 = v3_norm2(e1) * v3_norm2(e2) * v3_norm2(e3);
    if (!(vol * vol > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * scale2)) return 0;
    double n1 = v3_dot(nq, c23);
    double n2 = v3_dot(e1, v3_cross(nq, e3));
    double n3 = v3_dot(e1, v3_cross(e2, nq));
    double n0 = vol - n1 - n2 - n3;
    /* Orient so that the volume is positive; then a negative coordinate
     * means the origin lies beyond the face opposite that vertex. */
    double sgn = vol > 0.0 ? 1.0 : -1.0;
    w[apex] = sgn * n0;
    w[other[0]] = sgn * n1;
    w[other[1]] = sgn * n2;
    w[other[2]] = sgn * n3;
    *sum = sgn * vol;
    return 1;
}

/* The enclosed origin's weights from them, when every coordinate is
 * positive: 0xF, else 0. */
static inline unsigned enclosed_weights(const double w[4], double sum, double lambda[4],
                                        agjk_vec3 *point) {
    if (!(w[0] > 0.0 && w[1] > 0.0 && w[2] > 0.0 && w[3] > 0.0)) return 0u;
    for (int v = 0; v < 4; ++v) lambda[v] = w[v] / sum;
    *point = v3(0.0, 0.0, 0.0);
    return 0xFu;
}

static AGJK__COLD unsigned project_tetrahedron(const agjk_vec3 *p, double lambda[4], agjk_vec3 *point) {
    double face_sign[4] = {-1.0, -1.0, -1.0, -1.0}; /* <= 0: try the face opposite that vertex */
    double w[4], sum;
    if (apex_coordinates(p, w, &sum)) {
        if (enclosed_weights(w, sum, lambda, point)) return 0xFu;
        for (int v = 0; v < 4; ++v) face_sign[v] = w[v];
    }
    static const int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    int visible = 0, last = 0;
    for (int f = 0; f < 4; ++f)
        if (face_sign[f] <= 0.0) { ++visible; last = f; }
    if (visible == 1) /* the usual case: one face faces the origin */
        return project_triangle(p, 4, faces[last][0], faces[last][1], faces[last][2], lambda, point);
    candidate best;
    best.norm2 = INFINITY;
    best.mask = 0xFu;
    for (int f = 0; f < 4; ++f) {
        if (face_sign[f] > 0.0) continue;
        double tmp[4];
        agjk_vec3 pt;
        unsigned m = project_triangle(p, 4, faces[f][0], faces[f][1], faces[f][2], tmp, &pt);
        keep_best(&best, m, tmp, pt, 4);
    }
    for (int q = 0; q < 4; ++q) lambda[q] = best.lambda[q];
    *point = best.point;
    return best.mask;
}

/* Drops vertices whose weight came out exactly zero from the mask. */
static unsigned tighten(unsigned mask, const double lambda[4], int n) {
    for (int i = 0; i < n; ++i)
        if (lambda[i] <= 0.0) mask &= ~(1u << i);
    return mask;
}

unsigned agjk__simplex_project(const agjk_vec3 *p, int n, double lambda[4], agjk_vec3 *point) {
    unsigned mask;
    switch (n) {
    case 1:
        set_vertex(0, 1, lambda, p[0], point);
        return 1u;
    case 2:
        mask = project_segment(p, 2, 0, 1, lambda, point);
        break;
    case 3:
        mask = project_triangle(p, 3, 0, 1, 2, lambda, point);
        break;
    default:
        mask = project_tetrahedron(p, lambda, point);
        break;
    }
    return tighten(mask, lambda, n);
}

/* ---- The projection specialised for GJK ---------------------------------
 *
 * In GJK the simplex w[0..n-2] is the smallest face holding the previous
 * iterate x, and the new support point a = w[n-1] satisfies <x, a> < |x|^2.
 * The projection onto the enlarged hull is then strictly closer than x, so it
 * lies on a face containing a: the faces opposite a never need testing
 * (Gilbert, Johnson and Keerthi 1988; the Voronoi-region form of Ericson,
 * "Real-Time Collision Detection", 2005, Sec. 5.1.5-5.1.6). The fast path
 * below looks only at the faces through a, with the dot products of the
 * edges e_i = w_i - a and of a with them (Johnson's sub-algorithm in Gram
 * form): on a face (a, w_i, w_j) the origin's foot is
 * a + (l_i e_i + l_j e_j) / det with det = |e_i|^2 |e_j|^2 - <e_i, e_j>^2.
 *
 * It trusts no region test, though: a candidate p on a face S with positive
 * barycentric weights is accepted only when <p, q> >= |p|^2 (up to rounding)
 * for every vertex q outside S, the optimality (KKT) condition of the
 * projection onto the whole hull: the plane through p normal to p then
 * supports the hull. The face and edge paths divide by no volume, so a flat
 * tetrahedron needs no special case there; a face is used only when its
 * angle at a is well away from 0 or pi, and an enclosed origin is declared
 * only when the tetrahedron is well shaped and the origin clearly inside.
 * Otherwise (no candidate passes, the only candidate is an ill-conditioned
 * face, the origin is inside but not clearly, or the simplex is degenerate)
 * the exhaustive projection above decides. So the answer never rests on the
 * GJK assumption (which momentum directions or rounding can break), only the
 * speed does. */

/* Rounding allowance of the optimality test, relative to |p| |q|. Erring
 * on the strict side is safe: a wrongly rejected candidate only costs the
 * exhaustive projection. A candidate accepted within the allowance has
 * <p, q - p> >= -2 eps |p| |q| for every dropped vertex q: what it leaves
 * unexploited adds at most 4 eps |p| |q| to the solver's next gap
 * 2 <p, p - s>, below the floor the solver already attributes to rounding
 * (2 |x| times 4 eps times the magnitude of the support points); and p is
 * still a point of the hull, so the gap certificate holds. On simplices
 * recorded from GJK runs the fallback rate is the same for any allowance
 * from 0 to 8 ulps (measured). */
#define OPTIMALITY_RELATIVE (2.0 * DBL_EPSILON)

/* Smallest sin^2 of the angle at a of a face whose interior the fast path
 * computes: the Gram-form weights lose about eps / sin^2 (relative), so at
 * most ~100 ulps here; thinner faces go to the exhaustive projection, which
 * measures from the shortest edges. */
#define WELL_CONDITIONED 1e-2

/* Smallest (vol / (|e0| |e1| |e2|))^2 of a tetrahedron whose inside the fast
 * path decides (see tetra_inside). */
#define WELL_SHAPED 1e-4

/* The KKT test for one vertex q outside the candidate's face (pp = |p|^2):
 * <p, q> - |p|^2 >= -OPTIMALITY_RELATIVE |p| |q|. */
static int supports(agjk_vec3 p, double pp, agjk_vec3 q) {
    double m = v3_dot(p, q) - pp;
    return m >= 0.0 || m * m <= OPTIMALITY_RELATIVE * OPTIMALITY_RELATIVE * pp * v3_norm2(q);
}

/* Writes weights for a support set of up to three vertices (j, k may repeat
 * i with the same weight when unused). lambda always has four entries. */
static void put(double lambda[4], int i, double wi, int j, double wj, int k, double wk) {
    lambda[0] = lambda[1] = lambda[2] = lambda[3] = 0.0;
    lambda[k] = wk;
    lambda[j] = wj;
    lambda[i] = wi;
}

/* The vertex a = w[n-1] alone, once its KKT test (<a, e_i> >= 0) passed. */
static unsigned vertex_output(const agjk_vec3 *w, int n, double lambda[4], agjk_vec3 *point) {
    put(lambda, n - 1, 1.0, n - 1, 1.0, n - 1, 1.0);
    *point = w[n - 1];
    return 1u << (n - 1);
}

/* The foot of the origin on the segment a-b, a = w[ia] the newest point,
 * b = w[ib] an older one, u = b - a, uu = |u|^2, when it lies strictly
 * inside: its weights on a and b, the point and its squared norm. Measured
 * from b with the weight of a computed directly, exactly as the exhaustive
 * projection does (bit for bit: the solver's path does not depend on which
 * one projects), with the same cleanup along the segment (segment_cleanup,
 * written out here so that |p|^2, which its test needs, serves the caller's
 * KKT test too). Returns 0 otherwise. */
static inline int segment_foot(const agjk_vec3 *w, int ia, int ib, agjk_vec3 u, double uu,
                               double *wa, double *wb, agjk_vec3 *p, double *pp) {
    agjk_vec3 b = w[ib];
    double s = v3_dot(b, u) / uu; /* p = b + s (a - b) */
    agjk_vec3 q = v3_lerp2(b, 1.0 - s, w[ia], s);
    double qq = v3_norm2(q);
    if (v3_norm2(b) > 0x1p40 * qq) {
        q = v3_sub(q, v3_scale(u, v3_dot(q, u) / uu));
        qq = v3_norm2(q);
    }
    *p = q;
    *pp = qq;
    *wa = s;
    *wb = 1.0 - s;
    return s > 0.0 && s < 1.0; /* also false for uu = 0 */
}

/* Candidate on the edge a-b, a = w[n-1], b = w[ib], with ra = <a, b - a> and
 * gbb = |b - a|^2: the foot of the origin when it lies strictly inside the
 * edge and passes the KKT test for w[o1], w[o2] (indices < 0: none). Returns
 * the support mask, or 0. */
static AGJK__ALWAYS_INLINE unsigned edge_candidate(const agjk_vec3 *w, int n, int ib, double ra,
                                                   double gbb, int o1, int o2, double lambda[4],
                                                   agjk_vec3 *point) {
    int ia = n - 1;
    double wa, wb, pp;
    agjk_vec3 p;
    if (!(-ra > 0.0 && -ra < gbb)) return 0u; /* the foot is outside the edge */
    if (!segment_foot(w, ia, ib, v3_sub(w[ib], w[ia]), gbb, &wa, &wb, &p, &pp)) return 0u;
    if ((o1 >= 0 && !supports(p, pp, w[o1])) || (o2 >= 0 && !supports(p, pp, w[o2]))) return 0u;
    put(lambda, ia, wa, ib, wb, ib, wb);
    *point = p;
    return (1u << ia) | (1u << ib);
}

/* The same, out of line, for the tetrahedron's rare edge cases. */
static AGJK__NOINLINE unsigned edge_output(const agjk_vec3 *w, int n, int ib, double ra,
                                           double gbb, int o1, int o2, double lambda[4],
                                           agjk_vec3 *point) {
    return edge_candidate(w, n, ib, ra, gbb, o1, o2, lambda, point);
}

/* A face (a, w[i], w[j]) through the newest point a = w[n-1] that holds
 * the answer by the Gram tests: its Gram weights li, lj, la (times det > 0,
 * all positive), the vertex w[iq] of the face nearest the origin, and the
 * vertex w[o] outside it (o < 0: none). */
typedef struct {
    int n, i, j, iq, o;
    double det, li, lj, la;
} gram_face;

/* The candidate in a gram_face: the foot n <n, q> / |n|^2 from the face's
 * normal n = e[i] x e[j] (e[m] = w[m] - a) and the vertex q = w[iq] (the
 * error of <n, q> grows with |q|; accurate even when the foot is much
 * nearer the origin than a), if it passes the KKT test for w[o]; the foot
 * turned into B's frame too when notes ask (agjk__projection_notes).
 * Returns the support mask, or 0. Out of line, with the face by reference:
 * inlined, queries took 2-5% longer (close and overlapping ellipsoids,
 * boxes, hulls) for 7% fewer simplex instructions; called with its vectors
 * and weights as arguments, a quarter of its instructions passed them
 * through the stack. n and q, though, come as six doubles, in registers:
 * the caller forms them from its edges, which it holds in registers, where
 * reading the edges from memory here put a store-to-load round trip on
 * GJK's chain of dependent steps (and two of them, read by one 16-byte
 * load from two 8-byte stores, waited for the cache): close and
 * overlapping ellipsoid queries 3% faster than so, 1.5% faster than with
 * the edges read by 8-byte loads. */
static AGJK__NOINLINE unsigned face_output(const agjk_vec3 *w, const gram_face *face,
                                           double lambda[4], agjk_vec3 *point,
                                           agjk__projection_notes *notes, double nx, double ny,
                                           double nz, double qx, double qy, double qz) {
    int ia = face->n - 1, ib = face->i, ic = face->j;
    agjk_vec3 nrm = v3(nx, ny, nz);
    double t = v3_dot(nrm, v3(qx, qy, qz)) / v3_norm2(nrm);
    agjk_vec3 f = v3_scale(nrm, t);
    agjk_vec3 turned = v3(0.0, 0.0, 0.0);
    if (notes && notes->rotation) turned = v3_scale(m3_tmul(notes->rotation, nrm), t);
    double inv = 1.0 / face->det;
    double wa = face->la * inv, wb = face->li * inv, wc = face->lj * inv;
    if (!(wa > 0.0 && wb > 0.0 && wc > 0.0)) return 0u;
    if (face->o >= 0 && !supports(f, v3_norm2(f), w[face->o])) return 0u;
    put(lambda, ia, wa, ib, wb, ic, wc);
    *point = f;
    if (notes && notes->rotation) {
        notes->turned = turned;
        notes->turned_valid = 1;
    }
    return (1u << ia) | (1u << ib) | (1u << ic);
}

/* No fast answer: 0, or the exhaustive projection when asked for. */
static unsigned decline(const agjk_vec3 *w, int n, int exhaustive, double lambda[4],
                        agjk_vec3 *point) {
    return exhaustive ? agjk__simplex_project(w, n, lambda, point) : 0u;
}

/* The fast path for n = 2, 3, 4 points; on failure, decline(). */
static unsigned gjk_segment(const agjk_vec3 *w, int exhaustive, double lambda[4],
                            agjk_vec3 *point) {
    agjk_vec3 a = w[1], u = v3_sub(w[0], a);
    double ra = v3_dot(a, u);
    if (ra >= 0.0) return vertex_output(w, 2, lambda, point); /* <a, b - a> >= 0 */
    double wa, wb, pp; /* as edge_output, with no vertex outside */
    if (!segment_foot(w, 1, 0, u, v3_norm2(u), &wa, &wb, point, &pp))
        return decline(w, 2, exhaustive, lambda, point);
    put(lambda, 1, wa, 0, wb, 0, wb);
    return 3u;
}

static unsigned gjk_triangle(const agjk_vec3 *w, const agjk_vec3 *newest, int exhaustive,
                             double lambda[4], agjk_vec3 *point, agjk__projection_notes *notes) {
    agjk_vec3 a = *newest, e[2];
    e[0] = v3_sub(w[0], a);
    e[1] = v3_sub(w[1], a);
    agjk_vec3 u = e[0], v = e[1];
    double ru = v3_dot(a, u), rv = v3_dot(a, v);
    if (ru >= 0.0 && rv >= 0.0) return vertex_output(w, 3, lambda, point);
    double uu = v3_norm2(u), vv = v3_norm2(v), uv = v3_dot(u, v);
    double det = uu * vv - uv * uv;
    double lb = rv * uv - ru * vv, lc = ru * uv - rv * uu, la = det - lb - lc;
    if (lb > 0.0 && lc > 0.0 && la > 0.0) {
        /* |w_i|^2 - |a|^2 = 2 r_i + g_ii: the vertex nearest the origin */
        double db = 2.0 * ru + uu, dc = 2.0 * rv + vv;
        int iq = db < dc ? (db < 0.0 ? 0 : 2) : (dc < 0.0 ? 1 : 2);
        gram_face face = {3, 0, 1, iq, -1, det, lb, lc, la};
        agjk_vec3 nrm = v3_cross(u, v), q = iq == 2 ? a : w[iq];
        unsigned mask = det > WELL_CONDITIONED * uu * vv
                            ? face_output(w, &face, lambda, point, notes, nrm.x, nrm.y, nrm.z,
                                          q.x, q.y, q.z)
                            : 0u;
        return mask ? mask : decline(w, 3, exhaustive, lambda, point);
    }
    /* Outside the triangle: on its edges through a (the edge b-c belongs to
     * the previous simplex, which held the previous, farther iterate); first
     * the one beyond whose line the foot lies. */
    unsigned mask = 0u;
    for (int t = 0, ib = lc <= 0.0 ? 0 : 1; t < 2 && !mask; ++t, ib = 1 - ib)
        mask = edge_candidate(w, 3, ib, ib ? rv : ru, ib ? vv : uu, 1 - ib, -1, lambda, point);
    return mask ? mask : decline(w, 3, exhaustive, lambda, point);
}

/* In the tetrahedron (a = w[3], w0, w1, w2) with e_i = w_i - a, g_ij =
 * <e_i, e_j> and r_i = <a, e_i>: whether the face (a, w_i, w_j), k the
 * third index, holds the answer by the Gram tests: the foot of the origin
 * lies inside it (its Gram weights positive) and the Gram form of the KKT
 * test for w_k (<p, e_k> det = r_k det + l_i g_ik + l_j g_jk >= 0) passes;
 * if so, *face describes it. *inward is set to 1 when the foot lies inside
 * the face but w_k is on the origin's side of it (the KKT test fails: the
 * origin may be inside the tetrahedron). The face leaving out w_k is
 * (a, w_i, w_j) with i = k + 1, j = k + 2 (mod 3). The Gram matrix comes as
 * its diagonal gd[m] = g_mm and its off-diagonal gx[m] = g of the other two
 * indices (g12, g02, g01). The caller takes the first face that passes
 * (in exact arithmetic at most one does: the answer lies in one face
 * through a) and forms its candidate once, at one place. */
static AGJK__ALWAYS_INLINE int tetra_face_holds(const double *gd, const double *gx,
                                                const double *r, int k, int *inward,
                                                gram_face *face) {
    int i = k == 2 ? 0 : k + 1, j = k == 0 ? 2 : k - 1;
    double gii = gd[i], gjj = gd[j], gij = gx[k], ri = r[i], rj = r[j];
    double det = gii * gjj - gij * gij;
    double li = rj * gij - ri * gjj, lj = ri * gij - rj * gii;
    double la = det - li - lj;
    if (!(li > 0.0 && lj > 0.0 && la > 0.0)) return 0;
    if (!(r[k] * det + li * gx[j] + lj * gx[i] >= 0.0)) {
        *inward = 1;
        return 0;
    }
    /* |w_i|^2 - |a|^2 = 2 r_i + g_ii: the vertex nearest the origin */
    double di = 2.0 * ri + gii, dj = 2.0 * rj + gjj;
    face->n = 4;
    face->i = i;
    face->j = j;
    face->iq = di < dj ? (di < 0.0 ? i : 3) : (dj < 0.0 ? j : 3);
    face->o = k;
    face->det = det;
    face->li = li;
    face->lj = lj;
    face->la = la;
    return 1;
}

/* The edge a-w_i of the tetrahedron: its candidate when the Gram form of the
 * KKT test (<p, e_j> = r_j + t g_ij >= 0, t = -r_i / g_ii) passes for the two
 * other vertices. */
static unsigned tetra_edge(const agjk_vec3 *w, int i, int j, int k, double gii, double gij,
                           double gik, double ri, double rj, double rk, double lambda[4],
                           agjk_vec3 *point) {
    double t = -ri / gii;
    if (!(t > 0.0 && t < 1.0)) return 0u;
    if (!(rj + t * gij >= 0.0 && rk + t * gik >= 0.0)) return 0u;
    return edge_output(w, 4, i, ri, gii, j, k, lambda, point);
}

/* The origin strictly inside the tetrahedron, decided from a: -a = sum mu_i
 * e_i with mu_i vol = <-a, e_j x e_k> (Cramer's rule), accepted only when
 * every signed volume clears its own rounding error (a few ulps of the
 * products of the lengths involved) by a wide margin, and when the
 * tetrahedron is well shaped at a (vol^2 > WELL_SHAPED |e0|^2 |e1|^2
 * |e2|^2: the weights then reproduce the origin to ~300 ulps of |a|);
 * other cases are left to the exhaustive projection. The edges e_i = w_i - a
 * and their squared lengths gd[i] come from the caller, which has them.
 * *thin is set to 1 when the origin is clearly inside by the signed volumes
 * but the tetrahedron is too flat at a: the caller then takes the
 * exhaustive projection's answer at once (thin_inside, which measures from
 * the vertex nearest the origin) rather than trying the faces and edges
 * through a first, which never held the answer in such a case on the
 * protocol's runs (the origin clearly inside, their KKT tests fail). */
static unsigned tetra_inside(const agjk_vec3 *w, const agjk_vec3 *e, const double *gd,
                             double lambda[4], agjk_vec3 *point,
                             agjk__projection_notes *notes, int *thin) {
    agjk_vec3 a = w[3];
    /* (Scalar loads: the caller has just stored e and gd 8 bytes at a time,
     * and a 16-byte load of two of them waited for the cache: at the last
     * step of every overlapping query, 0.5% of its time.) */
    agjk_vec3 e0 = v3_load_scalars(&e[0]), e1 = v3_load_scalars(&e[1]);
    agjk_vec3 e2 = v3_load_scalars(&e[2]);
    const volatile double *gv = gd;
    double g00 = gv[0], g11 = gv[1], g22 = gv[2];
    agjk_vec3 c12 = v3_cross(e1, e2), c20 = v3_cross(e2, e0), c01 = v3_cross(e0, e1);
    double vol = v3_dot(e0, c12);
    double n0 = -v3_dot(a, c12), n1 = -v3_dot(a, c20), n2 = -v3_dot(a, c01);
    double orientation = 1.0;
    if (vol < 0.0) {
        orientation = -1.0;
        vol = -vol;
        n0 = -n0;
        n1 = -n1;
        n2 = -n2;
    }
    double na = vol - n0 - n1 - n2, aa = v3_norm2(a);
    const double m2 = DEGENERATE_RELATIVE * DEGENERATE_RELATIVE;
    int clear = n0 > 0.0 && n0 * n0 > m2 * aa * g11 * g22 && n1 > 0.0 &&
                n1 * n1 > m2 * aa * g22 * g00 && n2 > 0.0 && n2 * n2 > m2 * aa * g00 * g11 &&
                na > DEGENERATE_RELATIVE * (vol + n0 + n1 + n2);
    if (!clear) {
        *thin = 0;
        return 0u;
    }
    /* The signed volumes hold for a thin tetrahedron too: the overlap's
     * certification may read them either way (thin_inside). */
    if (notes) {
        agjk__inside *inside = &notes->inside;
        inside->h[0] = n0;
        inside->h[1] = n1;
        inside->h[2] = n2;
        inside->g[0] = g00;
        inside->g[1] = g11;
        inside->g[2] = g22;
        inside->orientation = orientation;
    }
    if (!(vol * vol > WELL_SHAPED * g00 * g11 * g22)) {
        *thin = 1;
        return 0u;
    }
    double inv = 1.0 / vol;
    lambda[0] = n0 * inv;
    lambda[1] = n1 * inv;
    lambda[2] = n2 * inv;
    lambda[3] = na * inv;
    *point = v3(0.0, 0.0, 0.0);
    return notes ? 0xFu | AGJK__INSIDE_REPORTED : 0xFu;
}

/* A thin tetrahedron's projection (tetra_inside's *thin): what the
 * exhaustive projection gives, its enclosed case computed here, in the hot
 * path (as a call to the exhaustive projection, kept with the cold code,
 * it cost overlapping ellipsoids with Nesterov 5% of their time). An
 * enclosure is reported with tetra_inside's data when notes ask. */
static unsigned thin_inside(const agjk_vec3 *w, int exhaustive, double lambda[4],
                            agjk_vec3 *point, const agjk__projection_notes *notes) {
    double c[4], sum;
    if (apex_coordinates(w, c, &sum)) {
        unsigned mask = enclosed_weights(c, sum, lambda, point);
        if (mask) {
            mask = tighten(mask, lambda, 4); /* as agjk__simplex_project */
            /* (notes->inside holds tetra_inside's signed volumes) */
            return mask == 0xFu && notes ? mask | AGJK__INSIDE_REPORTED : mask;
        }
    }
    return decline(w, 4, exhaustive, lambda, point);
}

/* tetra_inside's thin case: thin_inside's answer, or, when the caller can
 * do without weights (notes->weights_optional), the enclosure without them
 * (AGJK__WEIGHTS_DEFERRED): an overlap the solver certifies from the inside
 * test's data needs none, and thin_inside's apex coordinates were about a
 * tenth of such a query's instructions, on the chain to its answer
 * (overlapping ellipsoids with Nesterov, Boolean and distance without
 * witness points: 3-4% faster). */
static unsigned thin_answer(const agjk_vec3 *w, int exhaustive, double lambda[4],
                            agjk_vec3 *point, const agjk__projection_notes *notes) {
    if (notes && notes->weights_optional) {
        *point = v3(0.0, 0.0, 0.0);
        return 0xFu | AGJK__INSIDE_REPORTED | AGJK__WEIGHTS_DEFERRED;
    }
    return thin_inside(w, exhaustive, lambda, point, notes);
}

/* The thin face of the tetrahedron leaving out w_k (taken = 1 + k), which
 * holds the answer by the Gram tests: its projection by the exhaustive
 * triangle routine (the face's own degeneracy-proof case analysis, vertices
 * in index order as the exhaustive projection takes them), accepted when it
 * passes the KKT test for every vertex outside its support set. Cheaper than
 * the whole exhaustive projection, which would examine every visible face. */
static unsigned thin_face(const agjk_vec3 *w, int taken, double lambda[4], agjk_vec3 *point) {
    int k = taken - 1, i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
    unsigned mask = tighten(project_triangle(w, 4, i, j, 3, lambda, point), lambda, 4);
    double pp = v3_norm2(*point);
    for (int q = 0; q < 4; ++q)
        if (!(mask & (1u << q)) && !supports(*point, pp, w[q])) return 0u;
    return mask;
}

static unsigned gjk_tetrahedron(const agjk_vec3 *w, const agjk_vec3 *newest, int exhaustive,
                                double lambda[4], agjk_vec3 *point,
                                agjk__projection_notes *notes) {
    agjk_vec3 a = *newest;
    agjk_vec3 e[3];
    e[0] = v3_sub(w[0], a);
    e[1] = v3_sub(w[1], a);
    e[2] = v3_sub(w[2], a);
    double r[3];
    r[0] = v3_dot(a, e[0]);
    r[1] = v3_dot(a, e[1]);
    r[2] = v3_dot(a, e[2]);
    if (r[0] >= 0.0 && r[1] >= 0.0 && r[2] >= 0.0) return vertex_output(w, 4, lambda, point);
    /* The Gram matrix: diagonal gd[m] = g_mm, off-diagonal gx[m] = g of the
     * two indices other than m. */
    double gd[3], gx[3];
    gd[0] = v3_norm2(e[0]);
    gd[1] = v3_norm2(e[1]);
    gd[2] = v3_norm2(e[2]);
    gx[2] = v3_dot(e[0], e[1]);
    gx[0] = v3_dot(e[1], e[2]);
    gx[1] = v3_dot(e[2], e[0]);
    /* The faces through a, then its edges: the first that holds the answer;
     * then the inside; else (beyond the previous face, borderline cases):
     * the exhaustive projection. The face tried first leaves out the vertex
     * with the largest <a, e_k>, the one farthest back along a (right ~90%
     * of the time in GJK runs on ellipsoids and boxes); then the others in
     * index order. */
    int back = r[0] >= r[1] ? (r[0] >= r[2] ? 0 : 2) : (r[1] >= r[2] ? 1 : 2);
    int k = back, inward = 0, ignored = 0;
    gram_face face;
    int holds = tetra_face_holds(gd, gx, r, k, &inward, &face);
    unsigned mask = 0u;
    /* The origin over that face, on the side of the vertex it leaves out:
     * inside the tetrahedron, as at GJK's last step on overlapping shapes
     * (else the answer is on another face). The inside test then comes
     * first: it accepts only an origin inside by a wide margin, where no
     * face or edge passes its KKT test, so the order changes no answer, and
     * the last step skips two faces and three edges (overlapping ellipsoids:
     * about 150 instructions per query). */
    if (!holds && inward) {
        int thin = 0;
        mask = tetra_inside(w, e, gd, lambda, point, notes, &thin);
        if (mask) return mask;
        /* Flat momentum steps near enclosure: on overlapping ellipsoids
         * with Nesterov, about one query in two ends so (before, every
         * time inside by the exhaustive projection after every face and
         * edge had failed). */
        if (thin) return thin_answer(w, exhaustive, lambda, point, notes);
    }
    if (!holds) {
        k = back == 0 ? 1 : 0;
        holds = tetra_face_holds(gd, gx, r, k, &ignored, &face);
    }
    if (!holds) {
        k = back == 2 ? 1 : 2;
        holds = tetra_face_holds(gd, gx, r, k, &ignored, &face);
    }
    if (holds) {
        /* The face through a that holds the answer; too thin for the Gram
         * weights, or its candidate failing the exact KKT test: the face's
         * own degeneracy-proof projection. */
        if (face.det > WELL_CONDITIONED * gd[face.i] * gd[face.j]) {
            agjk_vec3 nrm = k == 0   ? v3_cross(e[1], e[2])
                            : k == 1 ? v3_cross(e[2], e[0])
                                     : v3_cross(e[0], e[1]);
            agjk_vec3 q = face.iq == 3 ? a : w[face.iq];
            mask = face_output(w, &face, lambda, point, notes, nrm.x, nrm.y, nrm.z, q.x, q.y,
                               q.z);
        }
        if (!mask) mask = thin_face(w, 1 + k, lambda, point);
        return mask ? mask : decline(w, 4, exhaustive, lambda, point);
    }
    mask = tetra_edge(w, 0, 1, 2, gd[0], gx[2], gx[1], r[0], r[1], r[2], lambda, point);
    if (!mask) mask = tetra_edge(w, 1, 2, 0, gd[1], gx[0], gx[2], r[1], r[2], r[0], lambda, point);
    if (!mask) mask = tetra_edge(w, 2, 0, 1, gd[2], gx[1], gx[0], r[2], r[0], r[1], lambda, point);
    /* GJK's last step on overlapping shapes: the origin enclosed (unless
     * the inside test has answered already). */
    if (!mask && !inward) {
        int thin = 0;
        mask = tetra_inside(w, e, gd, lambda, point, notes, &thin);
        if (thin) return thin_answer(w, exhaustive, lambda, point, notes);
    }
    return mask ? mask : decline(w, 4, exhaustive, lambda, point);
}

unsigned agjk__simplex_project_gjk_fast(const agjk_vec3 *w, int n, double lambda[4],
                                        agjk_vec3 *point) {
    switch (n) {
    case 1: return vertex_output(w, 1, lambda, point);
    case 2: return gjk_segment(w, 0, lambda, point);
    case 3: return gjk_triangle(w, &w[2], 0, lambda, point, NULL);
    default: return gjk_tetrahedron(w, &w[3], 0, lambda, point, NULL);
    }
}

AGJK__HOT_ENTRY unsigned agjk__simplex_project_gjk_noted(const agjk_vec3 *w, int n, double lambda[4],
                                         agjk_vec3 *point, agjk__projection_notes *notes,
                                         const agjk_vec3 *newest) {
    /* Largest first: a tetrahedron is the usual case on curved shapes. */
    if (n >= 4) return gjk_tetrahedron(w, newest, 1, lambda, point, notes);
    if (n == 3) return gjk_triangle(w, newest, 1, lambda, point, notes);
    if (n == 2) return gjk_segment(w, 1, lambda, point);
    return vertex_output(w, 1, lambda, point);
}

unsigned agjk__simplex_project_gjk(const agjk_vec3 *w, int n, double lambda[4], agjk_vec3 *point) {
    return agjk__simplex_project_gjk_noted(w, n, lambda, point, NULL, &w[n - 1]);
}

agjk_status agjk_simplex_project_origin(const agjk_vec3 *vertices, int count,
                                        agjk_simplex_projection *projection) {
    if (!projection) return AGJK_STATUS_INVALID_INPUT;
    projection->point = v3(0.0, 0.0, 0.0);
    for (int i = 0; i < 4; ++i) projection->weights[i] = 0.0;
    projection->support_mask = 0;
    projection->support_count = 0;
    if (!vertices || count < 1 || count > 4) return AGJK_STATUS_INVALID_INPUT;
    for (int i = 0; i < count; ++i)
        if (!v3_isfinite(vertices[i])) return AGJK_STATUS_INVALID_INPUT;
    double lambda[4] = {0.0, 0.0, 0.0, 0.0};
    agjk_vec3 point;
    unsigned mask = agjk__simplex_project(vertices, count, lambda, &point);
    projection->point = point;
    for (int i = 0; i < count; ++i) projection->weights[i] = lambda[i];
    projection->support_mask = mask;
    projection->support_count = count_bits(mask);
    return (mask == 0xFu || v3_norm2(point) == 0.0) ? AGJK_STATUS_INTERSECTING
                                                     : AGJK_STATUS_SEPARATED;
}
