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

static void set_vertex(int i, int n, double lambda[4], agjk_vec3 p, agjk_vec3 *point) {
    for (int j = 0; j < n; ++j) lambda[j] = 0.0;
    lambda[i] = 1.0;
    *point = p;
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
    *point = v3_lerp2(a, 1.0 - t, b, t);
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

static unsigned project_triangle(const agjk_vec3 *p, int n, int i, int j, int k, double lambda[4],
                                 agjk_vec3 *point) {
    agjk_vec3 a = p[i], b = p[j], c = p[k];
    agjk_vec3 ab = v3_sub(b, a), bc = v3_sub(c, b), ca = v3_sub(a, c);
    double lab = v3_norm2(ab), lbc = v3_norm2(bc), lca = v3_norm2(ca);
    /* The normal (b-a) x (c-a) = (c-b) x (a-b) = (a-c) x (b-c); its rounding error
     * is about eps |e1| |e2| for the two edges used, so use the two shortest:
     * with one far vertex, the long edges would cancel catastrophically. */
    agjk_vec3 nrm;
    double scale;
    if (lbc >= lab && lbc >= lca) {
        nrm = v3_cross(ab, v3_neg(ca));
        scale = lab * lca;
    } else if (lca >= lab) {
        nrm = v3_cross(bc, v3_neg(ab));
        scale = lbc * lab;
    } else {
        nrm = v3_cross(ca, v3_neg(bc));
        scale = lca * lbc;
    }
    double nn = v3_norm2(nrm);
    double edge_sign[3] = {-1.0, -1.0, -1.0}; /* <= 0: try the edge opposite that vertex */
    if (nn > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * scale) {
        /* Foot of the origin on the plane, from the vertex nearest the origin
         * (the error of <n, v> grows with |v|). */
        agjk_vec3 v = a;
        if (v3_norm2(b) < v3_norm2(v)) v = b;
        if (v3_norm2(c) < v3_norm2(v)) v = c;
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
            for (int q = 0; q < n; ++q) lambda[q] = 0.0;
            lambda[i] = la / sum;
            lambda[j] = lb / sum;
            lambda[k] = lc / sum;
            *point = foot;
            return (1u << i) | (1u << j) | (1u << k);
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

static unsigned project_tetrahedron(const agjk_vec3 *p, double lambda[4], agjk_vec3 *point) {
    /* Write the origin as q + mu_1 e_1 + mu_2 e_2 + mu_3 e_3 with q the vertex
     * nearest the origin and e_i the edges from it, and solve by Cramer's rule:
     * every rounding error then scales with |q| and the edge lengths rather than
     * with the distance of the far vertices to the origin. */
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
    double face_sign[4] = {-1.0, -1.0, -1.0, -1.0}; /* <= 0: try the face opposite that vertex */
    if (vol * vol > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * scale2) {
        double n1 = v3_dot(nq, c23);
        double n2 = v3_dot(e1, v3_cross(nq, e3));
        double n3 = v3_dot(e1, v3_cross(e2, nq));
        double n0 = vol - n1 - n2 - n3;
        /* Orient so that the volume is positive; then a negative coordinate
         * means the origin lies beyond the face opposite that vertex. */
        double sgn = vol > 0.0 ? 1.0 : -1.0;
        double w[4];
        w[apex] = sgn * n0;
        w[other[0]] = sgn * n1;
        w[other[1]] = sgn * n2;
        w[other[2]] = sgn * n3;
        double sum = sgn * vol;
        if (w[0] > 0.0 && w[1] > 0.0 && w[2] > 0.0 && w[3] > 0.0) {
            for (int v = 0; v < 4; ++v) lambda[v] = w[v] / sum;
            *point = v3(0.0, 0.0, 0.0);
            return 0xFu;
        }
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
 * below looks only at the faces through a, measured from a.
 *
 * It trusts no region test, though: a candidate p on a face S with positive
 * barycentric weights is accepted only when <p, q> >= |p|^2 (up to rounding)
 * for every vertex q outside S, the optimality (KKT) condition of the
 * projection onto the whole hull: the plane through p normal to p then
 * supports the hull. When no candidate passes, when the simplex is degenerate
 * or ill-conditioned at a, or when the origin may be inside the tetrahedron,
 * the exhaustive projection above decides. So the answer never rests on the
 * GJK assumption (which momentum directions or rounding can break), only the
 * speed does. */

/* Rounding allowance of the optimality test, relative to |p| |q|. A wrongly
 * rejected candidate only costs the exhaustive projection; one accepted
 * within the allowance is worse than the optimum by far less than the
 * rounding error the solver already attributes to its iterate. */
#define OPTIMALITY_RELATIVE (8.0 * DBL_EPSILON)

/* Smallest sin^2 of the angle at a for which the fast path computes a foot
 * and weights from the edges at a (see face_candidate). */
#define WELL_CONDITIONED 1e-2

/* The KKT test: <p, q> - |p|^2 >= -OPTIMALITY_RELATIVE |p| |q| for every
 * vertex q of w[0..n-1] outside the support mask `keep`. */
static inline int optimal(const agjk_vec3 *w, int n, unsigned keep, agjk_vec3 p) {
    double pp = v3_norm2(p);
    for (int i = 0; i < n; ++i) {
        if (keep & (1u << i)) continue;
        double m = v3_dot(p, w[i]) - pp;
        if (m >= 0.0) continue;
        if (m * m > OPTIMALITY_RELATIVE * OPTIMALITY_RELATIVE * pp * v3_norm2(w[i])) return 0;
    }
    return 1;
}

/* Writes weights for a support set of up to three vertices (j, k may repeat
 * i with weight 0 when unused). lambda always has four entries. */
static inline void put(double lambda[4], int i, double wi, int j, double wj, int k, double wk) {
    lambda[0] = lambda[1] = lambda[2] = lambda[3] = 0.0;
    lambda[k] = wk;
    lambda[j] = wj;
    lambda[i] = wi;
}

/* Candidate on the edge a-b, a = w[ia], b = w[ib], u = b - a, au = <a, u>:
 * the foot a + t u, t = -au / |u|^2, when 0 < t < 1 and it passes the KKT
 * test. Returns the support mask, or 0. */
static inline unsigned edge_candidate(const agjk_vec3 *w, int n, int ia, int ib, agjk_vec3 u, double au,
                               double lambda[4], agjk_vec3 *point) {
    if (!(au < 0.0)) return 0u;
    double t = -au / v3_norm2(u);
    if (!(t > 0.0 && t < 1.0)) return 0u; /* also rejects u = 0 */
    agjk_vec3 p = v3_lerp2(w[ia], 1.0 - t, w[ib], t);
    unsigned mask = (1u << ia) | (1u << ib);
    if (n > 2 && !optimal(w, n, mask, p)) return 0u;
    put(lambda, ia, 1.0 - t, ib, t, ib, t);
    *point = p;
    return mask;
}

/* Candidate on the triangle a, b, c = w[n-1], w[ib], w[ic] of edges
 * u = e[ib] = b - a, v = e[ic] = c - a, normal *nrm = u x v of squared norm
 * nn > 0, and uv2 = |u|^2 |v|^2: its interior, else the edges a-b, a-c, else
 * the vertex a, the first that passes the KKT test. Returns the support
 * mask, or 0. */
static unsigned face_candidate(const agjk_vec3 *w, int n, int ib, int ic, const agjk_vec3 *e,
                               const agjk_vec3 *nrm, double nn, double uv2, double lambda[4],
                               agjk_vec3 *point) {
    int ia = n - 1;
    agjk_vec3 a = w[ia], u = e[ib], v = e[ic], nv = *nrm;
    /* The foot f of the origin on the plane is a + (lb u + lc v) / |n|^2 with
     * lb = <-a, v x n> and lc = <-a, n x u> (signed areas measured from a:
     * the normal component of -a drops out). */
    double lb = -v3_dot(a, v3_cross(v, nv));
    double lc = -v3_dot(a, v3_cross(nv, u));
    double la = nn - lb - lc;
    if (lb > 0.0 && lc > 0.0 && la > 0.0) {
        /* u x v carries an error of a few ulps of |u| |v|: with a small angle
         * at a, the foot and weights would be far less accurate than the
         * exhaustive projection's (which measures from the shortest edges). */
        if (!(nn > WELL_CONDITIONED * uv2)) return 0u;
        double inv = 1.0 / nn;
        double wa = la * inv, wb = lb * inv, wc = lc * inv;
        agjk_vec3 f = v3_scale(nv, v3_dot(nv, a) * inv);
        if (!(wa > 0.0 && wb > 0.0 && wc > 0.0)) return 0u;
        if (n == 4) { /* the KKT test for the fourth vertex, as in optimal() */
            agjk_vec3 q = w[3 - ib - ic];
            double pp = v3_norm2(f), m = v3_dot(f, q) - pp;
            if (m < 0.0 && m * m > OPTIMALITY_RELATIVE * OPTIMALITY_RELATIVE * pp * v3_norm2(q))
                return 0u;
        }
        put(lambda, ia, wa, ib, wb, ic, wc);
        *point = f;
        return (1u << ia) | (1u << ib) | (1u << ic);
    }
    /* Outside the triangle: its boundary through a (the edge b-c belongs to
     * the previous simplex, which held the previous, farther iterate). */
    double au = v3_dot(a, u), av = v3_dot(a, v);
    unsigned mask = 0u;
    if (lc <= 0.0) mask = edge_candidate(w, n, ia, ib, u, au, lambda, point);
    if (!mask && lb <= 0.0) mask = edge_candidate(w, n, ia, ic, v, av, lambda, point);
    if (!mask && au >= 0.0 && av >= 0.0 && optimal(w, n, 1u << ia, a)) {
        put(lambda, ia, 1.0, ia, 1.0, ia, 1.0);
        *point = a;
        mask = 1u << ia;
    }
    return mask;
}

static unsigned gjk_segment(const agjk_vec3 *w, double lambda[4], agjk_vec3 *point) {
    agjk_vec3 a = w[1], u = v3_sub(w[0], a);
    double au = v3_dot(a, u);
    if (au >= 0.0) { /* <a, b - a> >= 0: the KKT condition of the vertex a */
        put(lambda, 1, 1.0, 1, 1.0, 1, 1.0);
        *point = a;
        return 2u;
    }
    return edge_candidate(w, 2, 1, 0, u, au, lambda, point);
}

static unsigned gjk_triangle(const agjk_vec3 *w, double lambda[4], agjk_vec3 *point) {
    agjk_vec3 a = w[2];
    agjk_vec3 e[2] = {v3_sub(w[0], a), v3_sub(w[1], a)};
    agjk_vec3 nrm = v3_cross(e[0], e[1]);
    double uv2 = v3_norm2(e[0]) * v3_norm2(e[1]), nn = v3_norm2(nrm);
    if (!(nn > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * uv2)) return 0u;
    return face_candidate(w, 3, 0, 1, e, &nrm, nn, uv2, lambda, point);
}

static unsigned gjk_tetrahedron(const agjk_vec3 *w, double lambda[4], agjk_vec3 *point) {
    agjk_vec3 a = w[3];
    /* Face f through a is (a, w[f], w[g]), g = f + 1 mod 3, with edges e[f],
     * e[g] and normal nrm[f] = e[f] x e[g]; vol = det(e0, e1, e2) is
     * <e[h], nrm[f]> for the third index h. */
    agjk_vec3 e[3] = {v3_sub(w[0], a), v3_sub(w[1], a), v3_sub(w[2], a)};
    agjk_vec3 nrm[3] = {v3_cross(e[0], e[1]), v3_cross(e[1], e[2]), v3_cross(e[2], e[0])};
    double ee0 = v3_norm2(e[0]), ee1 = v3_norm2(e[1]), ee2 = v3_norm2(e[2]);
    double vol = v3_dot(e[0], nrm[1]);
    if (!(vol * vol > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * ee0 * ee1 * ee2)) return 0u;
    /* -a = sum mu_h e[h] gives mu_h vol = -<a, nrm[f]>: the origin is beyond
     * face f (the face faces it) when s[f] = <a, nrm[f]> sign(vol) > 0. Its
     * distance to the plane of f is then s[f] / |nrm[f]|; the face with the
     * largest one is tried first, as it nearly always holds the projection.
     * A non-degenerate tetrahedron has non-degenerate faces
     * (|nrm[f]| >= |vol| / |e[h]|), so face_candidate may divide by |nrm|^2. */
    double s[3] = {v3_dot(a, nrm[0]), v3_dot(a, nrm[1]), v3_dot(a, nrm[2])};
    if (vol < 0.0) {
        s[0] = -s[0];
        s[1] = -s[1];
        s[2] = -s[2];
    }
    double nn[3] = {0.0, 0.0, 0.0};
    int best = -1;
    for (int f = 0; f < 3; ++f) {
        if (!(s[f] > 0.0)) continue;
        nn[f] = v3_norm2(nrm[f]);
        if (best < 0 || s[f] * s[f] * nn[best] > s[best] * s[best] * nn[f]) best = f;
    }
    /* No face through a faces the origin: the origin is inside (or beyond the
     * previous face), which the exhaustive projection settles. */
    if (best < 0) return 0u;
    const double uv2[3] = {ee0 * ee1, ee1 * ee2, ee2 * ee0};
    for (int k = 0; k < 3; ++k) {
        int f = best + k < 3 ? best + k : best + k - 3;
        if (k > 0 && !(s[f] > 0.0)) continue;
        unsigned mask = face_candidate(w, 4, f, f < 2 ? f + 1 : 0, e, &nrm[f], nn[f], uv2[f],
                                       lambda, point);
        if (mask) return mask;
    }
    return 0u;
}

static unsigned gjk_fast(const agjk_vec3 *w, int n, double lambda[4], agjk_vec3 *point) {
    switch (n) {
    case 1:
        put(lambda, 0, 1.0, 0, 1.0, 0, 1.0);
        *point = w[0];
        return 1u;
    case 2:
        return gjk_segment(w, lambda, point);
    case 3:
        return gjk_triangle(w, lambda, point);
    default:
        return gjk_tetrahedron(w, lambda, point);
    }
}

unsigned agjk__simplex_project_gjk_fast(const agjk_vec3 *w, int n, double lambda[4],
                                        agjk_vec3 *point) {
    return gjk_fast(w, n, lambda, point);
}

unsigned agjk__simplex_project_gjk(const agjk_vec3 *w, int n, double lambda[4], agjk_vec3 *point) {
    unsigned mask = gjk_fast(w, n, lambda, point);
    return mask ? mask : agjk__simplex_project(w, n, lambda, point);
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
