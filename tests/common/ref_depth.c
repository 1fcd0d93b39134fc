/* SPDX-License-Identifier: MIT */
/* Signed-distance references (see ref_depth.h): the separating-axis depth of
 * polytopes, and a branch and bound over the sphere of directions. */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "ref_depth.h"

typedef long double real;

static void lv(const agjk_vec3 *v, real out[3]) {
    out[0] = v->x;
    out[1] = v->y;
    out[2] = v->z;
}
static real ldot(const real a[3], const real b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void lcross(const real a[3], const real b[3], real c[3]) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static void lsub(const real a[3], const real b[3], real c[3]) {
    c[0] = a[0] - b[0];
    c[1] = a[1] - b[1];
    c[2] = a[2] - b[2];
}

/* h_D(n) / |n| for D = A - B given by vertex lists. */
static real sat_h(const agjk_vec3 *va, int na, const agjk_vec3 *vb, int nb, const real n[3]) {
    real len = sqrtl(ldot(n, n));
    if (!(len > 0.0L)) return INFINITY;
    real ha = -INFINITY, hb = -INFINITY;
    for (int i = 0; i < na; ++i) {
        real p[3];
        lv(&va[i], p);
        real d = ldot(n, p);
        if (d > ha) ha = d;
    }
    for (int i = 0; i < nb; ++i) {
        real p[3];
        lv(&vb[i], p);
        real d = -ldot(n, p);
        if (d > hb) hb = d;
    }
    return (ha + hb) / len;
}

static real triple_normals(const agjk_vec3 *v, int n, const agjk_vec3 *va, int na,
                           const agjk_vec3 *vb, int nb, real best) {
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k) {
                real p0[3], p1[3], p2[3], e1[3], e2[3], c[3], m[3];
                lv(&v[i], p0);
                lv(&v[j], p1);
                lv(&v[k], p2);
                lsub(p1, p0, e1);
                lsub(p2, p0, e2);
                lcross(e1, e2, c);
                real h = sat_h(va, na, vb, nb, c);
                if (h < best) best = h;
                m[0] = -c[0];
                m[1] = -c[1];
                m[2] = -c[2];
                h = sat_h(va, na, vb, nb, m);
                if (h < best) best = h;
            }
    return best;
}

long double ref_sat_signed_distance(const agjk_vec3 *va, int na, const agjk_vec3 *vb, int nb) {
    real best = INFINITY;
    best = triple_normals(va, na, va, na, vb, nb, best);
    best = triple_normals(vb, nb, va, na, vb, nb, best);
    for (int i = 0; i < na; ++i)
        for (int j = i + 1; j < na; ++j)
            for (int k = 0; k < nb; ++k)
                for (int l = k + 1; l < nb; ++l) {
                    real a0[3], a1[3], b0[3], b1[3], ea[3], eb[3], c[3], m[3];
                    lv(&va[i], a0);
                    lv(&va[j], a1);
                    lv(&vb[k], b0);
                    lv(&vb[l], b1);
                    lsub(a1, a0, ea);
                    lsub(b1, b0, eb);
                    lcross(ea, eb, c);
                    real h = sat_h(va, na, vb, nb, c);
                    if (h < best) best = h;
                    m[0] = -c[0];
                    m[1] = -c[1];
                    m[2] = -c[2];
                    h = sat_h(va, na, vb, nb, m);
                    if (h < best) best = h;
                }
    return -best;
}

/* ---- Branch and bound over the sphere of directions. ---- */

typedef struct bb_problem {
    const ref_shape *a, *b;
    const agjk_pose *pa, *pb;
} bb_problem;

/* World support of a posed shape in world direction n. */
static void posed_support(const ref_shape *s, const agjk_pose *p, const real n[3], real out[3]) {
    real d[3], q[3];
    for (int i = 0; i < 3; ++i) /* R^T n */
        d[i] = (real)p->rotation[0][i] * n[0] + (real)p->rotation[1][i] * n[1] +
               (real)p->rotation[2][i] * n[2];
    ref_support_local(s, d, q);
    real t[3];
    lv(&p->translation, t);
    for (int i = 0; i < 3; ++i)
        out[i] = (real)p->rotation[i][0] * q[0] + (real)p->rotation[i][1] * q[1] +
                 (real)p->rotation[i][2] * q[2] + t[i];
}

/* sigma = S_D(n) = S_A(n) - S_B(-n). */
static real support_d(const bb_problem *pr, const real n[3], real sigma[3]) {
    real sa[3], sb[3], m[3] = {-n[0], -n[1], -n[2]};
    posed_support(pr->a, pr->pa, n, sa);
    posed_support(pr->b, pr->pb, m, sb);
    lsub(sa, sb, sigma);
    return sqrtl(ldot(sa, sa)) + sqrtl(ldot(sb, sb));
}

typedef struct bb_cell {
    int face;
    real u0, v0, size; /* square [u0, u0 + size] x [v0, v0 + size] on the face */
    real lower;
} bb_cell;

/* Direction of (u, v) on cube face f (0..5), normalised. */
static void face_dir(int f, real u, real v, real n[3]) {
    real s = f & 1 ? -1.0L : 1.0L;
    int ax = f >> 1;
    real p[3];
    p[ax] = s;
    p[(ax + 1) % 3] = u;
    p[(ax + 2) % 3] = v;
    real len = sqrtl(ldot(p, p));
    for (int i = 0; i < 3; ++i) n[i] = p[i] / len;
}

static real angle_between(const real a[3], const real b[3]) {
    real c[3];
    lcross(a, b, c);
    return atan2l(sqrtl(ldot(c, c)), ldot(a, b));
}

typedef struct bb_state {
    const bb_problem *pr;
    bb_cell *heap;
    int count, cap;
    real upper; /* min h_D seen */
    real best_n[3];
    int cells;
} bb_state;

static void heap_push(bb_state *st, bb_cell c) {
    if (st->count == st->cap) {
        st->cap = st->cap ? 2 * st->cap : 1024;
        st->heap = realloc(st->heap, (size_t)st->cap * sizeof *st->heap);
        if (!st->heap) abort();
    }
    int i = st->count++;
    while (i > 0 && st->heap[(i - 1) / 2].lower > c.lower) {
        st->heap[i] = st->heap[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    st->heap[i] = c;
}

static bb_cell heap_pop(bb_state *st) {
    bb_cell top = st->heap[0], last = st->heap[--st->count];
    int i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= st->count) break;
        if (c + 1 < st->count && st->heap[c + 1].lower < st->heap[c].lower) ++c;
        if (st->heap[c].lower >= last.lower) break;
        st->heap[i] = st->heap[c];
        i = c;
    }
    if (st->count > 0) st->heap[i] = last;
    return top;
}

static void evaluate(bb_state *st, bb_cell c) {
    real m[3], sigma[3];
    face_dir(c.face, c.u0 + c.size / 2, c.v0 + c.size / 2, m);
    real magnitude = support_d(st->pr, m, sigma);
    ++st->cells;
    real h = ldot(m, sigma);
    if (h < st->upper) {
        st->upper = h;
        for (int i = 0; i < 3; ++i) st->best_n[i] = m[i];
    }
    /* Angular radius: the farthest corner (the cell is a convex spherical
     * quadrilateral, its farthest point from m is a vertex). */
    real t = 0.0L;
    for (int k = 0; k < 4; ++k) {
        real q[3];
        face_dir(c.face, c.u0 + (k & 1 ? c.size : 0), c.v0 + (k & 2 ? c.size : 0), q);
        real a = angle_between(m, q);
        if (a > t) t = a;
    }
    t *= 1.0L + 1e-15L; /* rounding of the angles */
    real norm = sqrtl(ldot(sigma, sigma));
    real alpha = norm > 0.0L ? angle_between(sigma, m) : 0.0L;
    real ang = alpha + t;
    c.lower = ang >= 3.14159265358979323846L ? -norm : norm * cosl(ang);
    /* Long double rounding of the support and the products. */
    c.lower -= 64.0L * LDBL_EPSILON * magnitude;
    heap_push(st, c);
}

int ref_signed_distance_bb(const ref_shape *a, const agjk_pose *pose_a, const ref_shape *b,
                           const agjk_pose *pose_b, long double width, int max_cells,
                           ref_signed_bracket *out) {
    bb_problem pr = {a, b, pose_a, pose_b};
    bb_state st = {&pr, NULL, 0, 0, INFINITY, {0, 0, 0}, 0};
    const int grid = 8;
    for (int f = 0; f < 6; ++f)
        for (int i = 0; i < grid; ++i)
            for (int j = 0; j < grid; ++j) {
                bb_cell c = {f, -1.0L + 2.0L * i / grid, -1.0L + 2.0L * j / grid, 2.0L / grid, 0};
                evaluate(&st, c);
            }
    int reached = 0;
    real lower = -INFINITY;
    while (st.count > 0) {
        lower = st.heap[0].lower;
        if (st.upper - lower <= width) {
            reached = 1;
            break;
        }
        if (st.cells >= max_cells) break;
        bb_cell c = heap_pop(&st);
        real h = c.size / 2;
        for (int k = 0; k < 4; ++k) {
            bb_cell d = {c.face, c.u0 + (k & 1 ? h : 0), c.v0 + (k & 2 ? h : 0), h, 0};
            evaluate(&st, d);
        }
    }
    out->lower = -st.upper;
    out->upper = -lower;
    for (int i = 0; i < 3; ++i) out->normal[i] = st.best_n[i];
    out->cells = st.cells;
    free(st.heap);
    return reached ? 0 : 1;
}
