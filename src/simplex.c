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
    agjk_vec3 ab = v3_sub(b, a), ac = v3_sub(c, a);
    agjk_vec3 nrm = v3_cross(ab, ac);
    double nn = v3_norm2(nrm);
    double scale = v3_norm2(ab) * v3_norm2(ac);
    double edge_sign[3] = {-1.0, -1.0, -1.0}; /* <= 0: try the edge opposite that vertex */
    if (nn > DEGENERATE_RELATIVE * DEGENERATE_RELATIVE * scale) {
        /* Barycentric coordinates of the origin's projection onto the plane:
         * lambda_a = <n, b x c> / |n|^2 etc. (invariant under moving the origin
         * along n). Normalising by their sum keeps the weights summing to 1. */
        double la = v3_dot(nrm, v3_cross(b, c));
        double lb = v3_dot(nrm, v3_cross(c, a));
        double lc = v3_dot(nrm, v3_cross(a, b));
        double sum = la + lb + lc;
        if (la > 0.0 && lb > 0.0 && lc > 0.0 && sum > 0.0) {
            for (int q = 0; q < n; ++q) lambda[q] = 0.0;
            lambda[i] = la / sum;
            lambda[j] = lb / sum;
            lambda[k] = lc / sum;
            /* The point is the plane's foot of the origin: n <n, a> / |n|^2 is
             * more accurate than the weighted sum when the triangle is far away. */
            *point = v3_scale(nrm, v3_dot(nrm, a) / nn);
            return (1u << i) | (1u << j) | (1u << k);
        }
        edge_sign[0] = la;
        edge_sign[1] = lb;
        edge_sign[2] = lc;
    }
    candidate best;
    best.norm2 = INFINITY;
    best.mask = 0xFu;
    double tmp[4];
    agjk_vec3 pt;
    unsigned m;
    if (edge_sign[0] <= 0.0) { m = project_segment(p, n, j, k, tmp, &pt); keep_best(&best, m, tmp, pt, n); }
    if (edge_sign[1] <= 0.0) { m = project_segment(p, n, i, k, tmp, &pt); keep_best(&best, m, tmp, pt, n); }
    if (edge_sign[2] <= 0.0) { m = project_segment(p, n, i, j, tmp, &pt); keep_best(&best, m, tmp, pt, n); }
    for (int q = 0; q < n; ++q) lambda[q] = best.lambda[q];
    *point = best.point;
    return best.mask;
}

static unsigned project_tetrahedron(const agjk_vec3 *p, double lambda[4], agjk_vec3 *point) {
    agjk_vec3 a = p[0], b = p[1], c = p[2], d = p[3];
    agjk_vec3 ab = v3_sub(b, a), ac = v3_sub(c, a), ad = v3_sub(d, a);
    double vol = v3_dot(ab, v3_cross(ac, ad));
    double scale = v3_norm(ab) * v3_norm(ac) * v3_norm(ad);
    double face_sign[4] = {-1.0, -1.0, -1.0, -1.0}; /* <= 0: try the face opposite that vertex */
    if (fabs(vol) > DEGENERATE_RELATIVE * scale) {
        /* Signed volumes with the origin replacing each vertex in turn. */
        agjk_vec3 na = v3_neg(a);
        double v0 = v3_dot(b, v3_cross(c, d));
        double v1 = v3_dot(na, v3_cross(ac, ad));
        double v2 = v3_dot(ab, v3_cross(na, ad));
        double v3v = v3_dot(ab, v3_cross(ac, na));
        double sum = v0 + v1 + v2 + v3v;
        /* Orient so that the full volume is positive. */
        if (sum < 0.0) {
            v0 = -v0; v1 = -v1; v2 = -v2; v3v = -v3v; sum = -sum;
        }
        if (v0 > 0.0 && v1 > 0.0 && v2 > 0.0 && v3v > 0.0 && sum > 0.0) {
            lambda[0] = v0 / sum;
            lambda[1] = v1 / sum;
            lambda[2] = v2 / sum;
            lambda[3] = v3v / sum;
            *point = v3(0.0, 0.0, 0.0);
            return 0xFu;
        }
        face_sign[0] = v0;
        face_sign[1] = v1;
        face_sign[2] = v2;
        face_sign[3] = v3v;
    }
    static const int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
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
