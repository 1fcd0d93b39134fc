/* SPDX-License-Identifier: MIT */
/* Brute-force projection of the origin onto conv(W), |W| <= 4, long double.
 *
 * conv(W) is the union of the convex hulls of its affinely independent
 * subsets (Caratheodory), so the closest point is the best of the affine
 * projections onto each subset's hull that falls inside the subset (all
 * barycentric weights >= 0). This deliberately shares nothing with the
 * library's case analysis (Johnson / signed volumes): it is slow and obvious.
 * Affine projections use modified Gram-Schmidt with one re-orthogonalisation
 * (error ~ cond(E) eps rather than cond(E)^2 eps of the normal equations). */
#include <math.h>
#include <stddef.h>
#include "ref_internal.h"

/* A subset is treated as degenerate (skipped; its smaller subsets cover it)
 * when an edge is parallel to the others to within this sine. Skipping a
 * subset that thin moves the answer by at most this fraction of its edges. */
#define REF_THIN 1e-14L

/* Affine projection of the origin onto aff(w[idx[0..k-1]]). Writes the
 * weights (in subset order) and the point; returns 0 if degenerate. */
static int subset_project(const ref_v3 *w, const int *idx, int k, ref_real lambda[4],
                          ref_v3 *point) {
    int base = 0;
    for (int j = 1; j < k; j++)
        if (ref_v3_norm(w[idx[j]]) < ref_v3_norm(w[idx[base]])) base = j;
    ref_v3 b = w[idx[base]];
    ref_v3 e[3], q[3];
    ref_real r[3][3] = {{0.0L}};
    int col[3], m = 0;
    for (int j = 0; j < k; j++) {
        if (j == base) continue;
        e[m] = rv_sub(w[idx[j]], b);
        col[m++] = j;
    }
    for (int j = 0; j < m; j++) {
        ref_real en = ref_v3_norm(e[j]);
        if (en == 0.0L) return 0;
        ref_v3 v = e[j];
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < j; i++) {
                ref_real c = rv_dot(q[i], v);
                r[i][j] += c;
                v = rv_sub(v, rv_scale(q[i], c));
            }
        }
        r[j][j] = ref_v3_norm(v);
        if (r[j][j] <= REF_THIN * en) return 0;
        q[j] = rv_scale(v, 1.0L / r[j][j]);
    }
    /* Least squares b + E mu ~ 0: R mu = -Q^T b, back substitution. */
    ref_real mu[3];
    for (int j = m - 1; j >= 0; j--) {
        ref_real c = -rv_dot(q[j], b);
        for (int i = j + 1; i < m; i++) c -= r[j][i] * mu[i];
        mu[j] = c / r[j][j];
    }
    ref_real sum = 0.0L;
    ref_v3 p = b;
    for (int j = 0; j < m; j++) {
        lambda[col[j]] = mu[j];
        sum += mu[j];
        p = rv_add(p, rv_scale(e[j], mu[j]));
    }
    lambda[base] = 1.0L - sum;
    *point = p;
    return 1;
}

void ref_project_ld(const ref_v3 *w, int n, ref_projection *out) {
    ref_real scale2 = 0.0L;
    for (int i = 0; i < n; i++) {
        ref_real s = rv_dot(w[i], w[i]);
        if (s > scale2) scale2 = s;
    }
    int have = 0;
    ref_real best = 0.0L;
    /* Subsets by increasing size, so that on a tie the smallest support set
     * (the minimal face holding the point) wins. */
    for (int size = 1; size <= n; size++) {
        for (unsigned mask = 1; mask < (1u << n); mask++) {
            int idx[4], k = 0;
            for (int i = 0; i < n; i++)
                if (mask & (1u << i)) idx[k++] = i;
            if (k != size) continue;
            ref_real lambda[4];
            ref_v3 p;
            if (!subset_project(w, idx, k, lambda, &p)) continue;
            int inside = 1;
            for (int j = 0; j < k; j++)
                if (!(lambda[j] >= 0.0L)) inside = 0;
            if (!inside) continue;
            ref_real d2 = rv_dot(p, p);
            /* Strictly better by more than rounding, else keep the smaller set. */
            if (have && !(d2 < best * (1.0L - 1e-18L) - 1e-36L * scale2)) continue;
            have = 1;
            best = d2;
            out->point[0] = p.x;
            out->point[1] = p.y;
            out->point[2] = p.z;
            for (int i = 0; i < 4; i++) out->weights[i] = 0.0L;
            for (int j = 0; j < k; j++) out->weights[idx[j]] = lambda[j];
            out->mask = mask;
            out->count = k;
        }
    }
    /* Singletons are never degenerate, so `have` is always set. */
    out->distance = ref_v3_norm(rv(out->point[0], out->point[1], out->point[2]));
}

int ref_project_origin(const agjk_vec3 *vertices, int count, ref_projection *out) {
    if (vertices == NULL || out == NULL || count < 1 || count > 4) return -1;
    ref_v3 w[4];
    for (int i = 0; i < count; i++) w[i] = rv_from(vertices[i]);
    ref_project_ld(w, count, out);
    return 0;
}

static ref_real det3(ref_v3 a, ref_v3 b, ref_v3 c) { return rv_dot(a, rv_cross(b, c)); }

int ref_tetra_barycentric(const ref_v3 *w, ref_real bary[4]) {
    ref_v3 c1 = rv_sub(w[1], w[0]), c2 = rv_sub(w[2], w[0]), c3 = rv_sub(w[3], w[0]);
    ref_real det = det3(c1, c2, c3);
    ref_real size = ref_v3_norm(c1) * ref_v3_norm(c2) * ref_v3_norm(c3);
    if (!(fabsl(det) > 1e-15L * size)) return 0;
    /* Cramer's rule for w0 + [c1 c2 c3] mu = 0. */
    ref_v3 rhs = rv_scale(w[0], -1.0L);
    bary[1] = det3(rhs, c2, c3) / det;
    bary[2] = det3(c1, rhs, c3) / det;
    bary[3] = det3(c1, c2, rhs) / det;
    bary[0] = 1.0L - bary[1] - bary[2] - bary[3];
    return 1;
}
