/* SPDX-License-Identifier: MIT */
/* The reference distance: plain GJK (fully-corrective Frank-Wolfe, Montaut
 * et al. 2022 Alg. 4) in long double on D = A - B in the world frame, with the
 * brute-force projection of ref_simplex.c, run until its own duality gap
 * certifies the distance to ~1e-15 of the problem's size.
 *
 * Certificates (eq. 13 of the paper, with lower bound from the support plane):
 *   upper = |x_k|               (x_k is a point of D)
 *   lower = max_k <x_k, s_k>/|x_k|  (the plane through s_k with normal x_k
 *                                    separates D from the origin by that much)
 * "intersecting" needs a proof: the origin strictly inside a tetrahedron of
 * support points (all barycentric weights > REF_INSIDE), or the core
 * distance certified below the summed margins. */
#include <math.h>
#include <string.h>
#include "ref_internal.h"

#define REF_MAX_ITER 2000
#define REF_REL_TOL 1e-15L   /* target upper - lower, relative to the size */
#define REF_INSIDE 1e-12L    /* least barycentric weight to call the origin inside */

/* A pose in long double, applied exactly as p_world = R p + t. */
typedef struct ref_pose {
    ref_real r[3][3];
    ref_v3 t;
} ref_pose;

typedef struct ref_problem {
    const ref_shape *a, *b;
    ref_pose pa, pb;
} ref_problem;

/* One support point of D with its parts on A and B (world frame). */
typedef struct ref_vertex {
    ref_v3 w, a, b;
} ref_vertex;

static void to_ref_pose(const agjk_pose *p, ref_pose *out) {
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) out->r[i][j] = p->rotation[i][j];
    out->t = rv_from(p->translation);
}

static ref_v3 rot(const ref_pose *p, ref_v3 v) {
    return rv(p->r[0][0] * v.x + p->r[0][1] * v.y + p->r[0][2] * v.z,
              p->r[1][0] * v.x + p->r[1][1] * v.y + p->r[1][2] * v.z,
              p->r[2][0] * v.x + p->r[2][1] * v.y + p->r[2][2] * v.z);
}

static ref_v3 rot_t(const ref_pose *p, ref_v3 v) {
    return rv(p->r[0][0] * v.x + p->r[1][0] * v.y + p->r[2][0] * v.z,
              p->r[0][1] * v.x + p->r[1][1] * v.y + p->r[2][1] * v.z,
              p->r[0][2] * v.x + p->r[1][2] * v.y + p->r[2][2] * v.z);
}

/* Core support of D = A - B maximising <d, w>: for the linear image R S + t
 * the support is R s_S(R^T d) + t (exact for any matrix R). */
static ref_vertex support_d(const ref_problem *pr, ref_v3 d) {
    ref_vertex v;
    v.a = rv_add(rot(&pr->pa, ref_core_support(pr->a, rot_t(&pr->pa, d))), pr->pa.t);
    v.b = rv_add(rot(&pr->pb, ref_core_support(pr->b, rot_t(&pr->pb, rv_scale(d, -1.0L)))),
                 pr->pb.t);
    v.w = rv_sub(v.a, v.b);
    return v;
}

static ref_v3 any_perpendicular(ref_v3 u) {
    ref_v3 axis = fabsl(u.x) < fabsl(u.y) ? (fabsl(u.x) < fabsl(u.z) ? rv(1, 0, 0) : rv(0, 0, 1))
                                          : (fabsl(u.y) < fabsl(u.z) ? rv(0, 1, 0) : rv(0, 0, 1));
    ref_v3 p = rv_cross(u, axis);
    return rv_scale(p, 1.0L / ref_v3_norm(p));
}

/* Tries to prove the origin strictly inside D once GJK has driven x to ~0 on
 * the simplex w[0..n-1]: adds the supports of D in the directions normal to
 * the simplex's affine hull (both signs; for a tetrahedron, normal to the face
 * opposite its least-weight vertex) and looks for any tetrahedron of the
 * collected points that holds the origin with all weights > REF_INSIDE. */
static int enclose_origin(const ref_problem *pr, const ref_v3 *w, int n, const ref_real *weight) {
    ref_v3 pts[16];
    ref_v3 dirs[6];
    int np = 0, nd = 0;
    for (int i = 0; i < n; i++) pts[np++] = w[i];
    if (n == 1) {
        dirs[nd++] = rv(1, 0, 0); dirs[nd++] = rv(0, 1, 0); dirs[nd++] = rv(0, 0, 1);
    } else if (n == 2) {
        ref_v3 u = rv_sub(w[1], w[0]);
        ref_v3 p1 = any_perpendicular(u);
        dirs[nd++] = p1;
        dirs[nd++] = rv_cross(rv_scale(u, 1.0L / ref_v3_norm(u)), p1);
    } else {
        int skip = -1;
        if (n == 4) {
            skip = 0;
            for (int i = 1; i < 4; i++)
                if (weight[i] < weight[skip]) skip = i;
        }
        ref_v3 f[3];
        int nf = 0;
        for (int i = 0; i < n; i++)
            if (i != skip) f[nf++] = w[i];
        dirs[nd++] = rv_cross(rv_sub(f[1], f[0]), rv_sub(f[2], f[0]));
    }
    for (int i = 0; i < nd; i++) {
        pts[np++] = support_d(pr, dirs[i]).w;
        pts[np++] = support_d(pr, rv_scale(dirs[i], -1.0L)).w;
    }
    for (int i = 0; i < np; i++)
        for (int j = i + 1; j < np; j++)
            for (int k = j + 1; k < np; k++)
                for (int l = k + 1; l < np; l++) {
                    ref_v3 t[4] = {pts[i], pts[j], pts[k], pts[l]};
                    ref_real bary[4];
                    if (!ref_tetra_barycentric(t, bary)) continue;
                    if (bary[0] > REF_INSIDE && bary[1] > REF_INSIDE && bary[2] > REF_INSIDE &&
                        bary[3] > REF_INSIDE)
                        return 1;
                }
    return 0;
}

static void finish(const ref_problem *pr, const ref_vertex *simplex, const ref_real *weight,
                   int n, ref_real core_upper, ref_real core_lower, ref_result *out) {
    ref_real ma = ref_total_margin(pr->a), mb = ref_total_margin(pr->b);
    ref_real msum = ma + mb;
    ref_v3 pa = rv(0, 0, 0), pb = rv(0, 0, 0);
    for (int i = 0; i < n; i++) {
        pa = rv_add(pa, rv_scale(simplex[i].a, weight[i]));
        pb = rv_add(pb, rv_scale(simplex[i].b, weight[i]));
    }
    ref_v3 x = rv_sub(pa, pb);
    ref_real nx = ref_v3_norm(x);
    memset(&out->normal, 0, sizeof out->normal);
    if (!out->intersecting && nx > 0.0L) {
        ref_v3 nrm = rv_scale(x, -1.0L / nx); /* from A towards B */
        out->normal = rv_to(nrm);
        pa = rv_add(pa, rv_scale(nrm, ma));
        pb = rv_sub(pb, rv_scale(nrm, mb));
    }
    out->witness_a = rv_to(pa);
    out->witness_b = rv_to(pb);
    if (out->intersecting) {
        out->distance = out->lower = out->upper = 0.0L;
    } else {
        out->upper = out->distance = core_upper > msum ? core_upper - msum : 0.0L;
        out->lower = core_lower > msum ? core_lower - msum : 0.0L;
    }
}

static int shape_ok(const ref_shape *s) {
    if (s == NULL) return 0;
    if (s->kind == REF_POLYTOPE && (s->vertices == NULL || s->vertex_count < 1)) return 0;
    return 1;
}

int ref_distance(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                 const agjk_pose *pose_b, ref_result *out) {
    if (out == NULL) return -1;
    memset(out, 0, sizeof *out);
    if (!shape_ok(a) || !shape_ok(b) || pose_a == NULL || pose_b == NULL) return -1;
    ref_problem pr;
    pr.a = a;
    pr.b = b;
    to_ref_pose(pose_a, &pr.pa);
    to_ref_pose(pose_b, &pr.pb);
    ref_real msum = ref_total_margin(a) + ref_total_margin(b);

    /* x_0 = c_A - c_B (any point of D would do; this one is the library's too). */
    ref_v3 x = rv_sub(pr.pa.t, pr.pb.t);
    if (ref_v3_norm(x) == 0.0L) x = rv(1, 0, 0);
    ref_vertex simplex[4];
    ref_real weight[4] = {1, 0, 0, 0};
    int n = 1;
    simplex[0] = support_d(&pr, rv_scale(x, -1.0L));
    x = simplex[0].w;
    ref_real scale = ref_v3_norm(x), lower = 0.0L, upper = scale;
    int stalls = 0, it;
    for (it = 1; it <= REF_MAX_ITER; it++) {
        ref_real nx = ref_v3_norm(x);
        upper = nx < upper ? nx : upper;
        if (nx <= 1e-18L * scale) {
            /* x ~ 0: touching or overlapping; only a tetrahedron proves which. */
            ref_v3 w[4];
            for (int i = 0; i < n; i++) w[i] = simplex[i].w;
            out->intersecting = enclose_origin(&pr, w, n, weight);
            out->converged = 1;
            break;
        }
        if (upper < msum && msum - upper > 1e-14L * (scale > msum ? scale : msum)) {
            out->intersecting = 1; /* cores closer than the summed margins */
            out->converged = 1;
            break;
        }
        ref_vertex s = support_d(&pr, rv_scale(x, -1.0L));
        ref_real sn = ref_v3_norm(s.w);
        if (sn > scale) scale = sn;
        ref_real lk = rv_dot(x, s.w) / nx;
        if (lk > lower) lower = lk;
        if (n == 3 && upper - lower > REF_REL_TOL * scale) {
            /* A second certificate from the plane of the current triangle.
             * When |x| << size, x carries an absolute rounding error of
             * ~eps * size, so its direction is off by eps * size / |x| and
             * the plane with normal x under-certifies by that angle times the
             * face's extent (1e-14 of the size at |x| = 1e-7). The cross
             * product of two edges is accurate to eps in direction. */
            ref_v3 nrm = rv_cross(rv_sub(simplex[1].w, simplex[0].w), rv_sub(simplex[2].w, simplex[0].w));
            ref_real nn = ref_v3_norm(nrm);
            if (nn > 0.0L) {
                if (rv_dot(nrm, x) < 0.0L) nrm = rv_scale(nrm, -1.0L);
                nrm = rv_scale(nrm, 1.0L / nn);
                ref_real lp = rv_dot(nrm, support_d(&pr, rv_scale(nrm, -1.0L)).w);
                if (lp > lower) lower = lp;
            }
        }
        if (upper - lower <= REF_REL_TOL * scale) {
            out->converged = 1;
            break;
        }
        int repeated = 0;
        for (int i = 0; i < n; i++)
            if (ref_v3_norm(rv_sub(s.w, simplex[i].w)) <= 1e-19L * scale) repeated = 1;
        if (repeated) break; /* no new support: GJK cannot progress further */
        simplex[n++] = s;
        ref_v3 w[4];
        for (int i = 0; i < n; i++) w[i] = simplex[i].w;
        ref_projection pj;
        ref_project_ld(w, n, &pj);
        if (pj.count == 4) {
            ref_real bary[4];
            int ok = ref_tetra_barycentric(w, bary);
            if (ok && bary[0] > REF_INSIDE && bary[1] > REF_INSIDE && bary[2] > REF_INSIDE &&
                bary[3] > REF_INSIDE) {
                out->intersecting = 1;
                out->converged = 1;
                for (int i = 0; i < 4; i++) weight[i] = pj.weights[i];
                break;
            }
        }
        ref_real nnew = pj.distance;
        if (!(nnew < nx)) {
            if (++stalls >= 3) break; /* rounding floor reached */
        } else {
            stalls = 0;
        }
        /* Keep only the support set of the projection (fully corrective step). */
        int m = 0;
        for (int i = 0; i < n; i++) {
            if (!(pj.mask & (1u << i))) continue;
            simplex[m] = simplex[i];
            weight[m] = pj.weights[i];
            m++;
        }
        n = m;
        x = rv(pj.point[0], pj.point[1], pj.point[2]);
    }
    out->iterations = it > REF_MAX_ITER ? REF_MAX_ITER : it;
    out->scale = scale;
    finish(&pr, simplex, weight, n, upper, lower, out);
    return (out->converged || out->intersecting) ? 0 : 1;
}
