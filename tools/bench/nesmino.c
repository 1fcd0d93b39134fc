/* SPDX-License-Identifier: MIT */
#include "nesmino.h"

#include <math.h>

typedef agjk_vec3 v3;

static v3 v3_make(double x, double y, double z) { v3 v; v.x = x; v.y = y; v.z = z; return v; }
static v3 v3_add(v3 a, v3 b) { return v3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static v3 v3_sub(v3 a, v3 b) { return v3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static v3 v3_scale(v3 a, double s) { return v3_make(a.x * s, a.y * s, a.z * s); }
static double v3_dot(v3 a, v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

static v3 to_local(const agjk_pose *p, v3 w) { /* R^T (w - t) */
    const double (*r)[3] = p->rotation;
    v3 d = v3_sub(w, p->translation);
    return v3_make(r[0][0] * d.x + r[1][0] * d.y + r[2][0] * d.z,
                   r[0][1] * d.x + r[1][1] * d.y + r[2][1] * d.z,
                   r[0][2] * d.x + r[1][2] * d.y + r[2][2] * d.z);
}

static v3 rotate(const agjk_pose *p, v3 l) { /* R l */
    const double (*r)[3] = p->rotation;
    return v3_make(r[0][0] * l.x + r[0][1] * l.y + r[0][2] * l.z,
                   r[1][0] * l.x + r[1][1] * l.y + r[1][2] * l.z,
                   r[2][0] * l.x + r[2][1] * l.y + r[2][2] * l.z);
}

static v3 rotate_t(const agjk_pose *p, v3 w) { /* R^T w */
    const double (*r)[3] = p->rotation;
    return v3_make(r[0][0] * w.x + r[1][0] * w.y + r[2][0] * w.z,
                   r[0][1] * w.x + r[1][1] * w.y + r[2][1] * w.z,
                   r[0][2] * w.x + r[1][2] * w.y + r[2][2] * w.z);
}

/* Projection of q onto the ellipsoid sum (x_i / r_i)^2 <= 1. Outside, the
 * KKT conditions give x_i = r_i^2 q_i / (r_i^2 + lambda) with lambda > 0 the
 * root of F(lambda) = sum (r_i q_i / (r_i^2 + lambda))^2 - 1, convex and
 * decreasing: Newton from lambda = 0 increases monotonically to the root. */
static v3 project_ellipsoid(v3 r, v3 q) {
    double rr[3] = {r.x * r.x, r.y * r.y, r.z * r.z};
    double rq[3] = {r.x * q.x, r.y * q.y, r.z * q.z};
    double qq[3] = {q.x, q.y, q.z};
    double lambda = 0.0, level;
    int it, i;
    level = (q.x / r.x) * (q.x / r.x) + (q.y / r.y) * (q.y / r.y) + (q.z / r.z) * (q.z / r.z);
    if (level <= 1.0) return q;
    for (it = 0; it < 100; ++it) {
        double f = -1.0, df = 0.0, step;
        for (i = 0; i < 3; ++i) {
            double t = rq[i] / (rr[i] + lambda);
            f += t * t;
            df -= 2.0 * t * t / (rr[i] + lambda);
        }
        if (f <= 0.0 || df >= 0.0) break;
        step = -f / df;
        lambda += step;
        if (step <= 1e-15 * lambda) break;
    }
    for (i = 0; i < 3; ++i) qq[i] = rr[i] * qq[i] / (rr[i] + lambda);
    return v3_make(qq[0], qq[1], qq[2]);
}

static double clampd(double x, double h) { return x < -h ? -h : x > h ? h : x; }

/* Projection onto a shape placed by a pose: P(y) = R P0(R^T (y - t)) + t. */
static v3 project(const bench_shape *s, const agjk_pose *p, v3 y) {
    v3 q = to_local(p, y), l;
    if (s->kind == REF_ELLIPSOID) l = project_ellipsoid(s->size, q);
    else l = v3_make(clampd(q.x, s->size.x), clampd(q.y, s->size.y), clampd(q.z, s->size.z));
    return v3_add(rotate(p, l), p->translation);
}

/* Support point (world) of a placed ellipsoid or box in world direction d. */
static v3 support(const bench_shape *s, const agjk_pose *p, v3 d) {
    v3 l = rotate_t(p, d), out;
    if (s->kind == REF_ELLIPSOID) {
        v3 rd = v3_make(s->size.x * l.x, s->size.y * l.y, s->size.z * l.z);
        double n = sqrt(v3_dot(rd, rd));
        out = n > 0 ? v3_make(s->size.x * rd.x / n, s->size.y * rd.y / n, s->size.z * rd.z / n)
                    : v3_make(0, 0, 0);
    } else {
        out = v3_make(l.x >= 0 ? s->size.x : -s->size.x, l.y >= 0 ? s->size.y : -s->size.y,
                      l.z >= 0 ? s->size.z : -s->size.z);
    }
    return v3_add(rotate(p, out), p->translation);
}

int bench_nesmino(const bench_shape *a, const agjk_pose *pa, const bench_shape *b,
                  const agjk_pose *pb, nesmino_stop stop, double tolerance,
                  const agjk_vec3 *xstar, int max_iterations, double mu,
                  nesmino_result *out) {
    v3 xa = pa->translation, xb = pb->translation; /* x_0: the shapes' centres */
    v3 ya = xa, yb = xb;
    double t = 1.0;
    int k;
    out->converged = 0;
    out->iterations = 0;
    out->support_calls = 0;
    out->bound = -1.0;
    if ((a->kind != REF_ELLIPSOID && a->kind != REF_BOX) ||
        (b->kind != REF_ELLIPSOID && b->kind != REF_BOX))
        return -1;
    for (k = 1; k <= max_iterations; ++k) {
        /* Gradient step 1/L = mu/2 along u = x / max(mu, ||x||), x = y_a - y_b:
         * a moves by -mu/2 u, b by +mu/2 u. With mu >= ||x|| (mu = 0 here)
         * the step is x/2: both points go to their midpoint. */
        v3 x0 = v3_sub(ya, yb), step;
        double nx = sqrt(v3_dot(x0, x0));
        v3 na, nb;
        step = (mu <= 0.0 || nx <= mu) ? v3_scale(x0, 0.5) : v3_scale(x0, 0.5 * mu / nx);
        na = project(a, pa, v3_sub(ya, step));
        nb = project(b, pb, v3_add(yb, step));
        double t_next = 0.5 * (1.0 + sqrt(1.0 + 4.0 * t * t));
        double beta = (t - 1.0) / t_next;
        v3 x;
        ya = v3_add(na, v3_scale(v3_sub(na, xa), beta));
        yb = v3_add(nb, v3_scale(v3_sub(nb, xb), beta));
        xa = na;
        xb = nb;
        t = t_next;
        out->iterations = k;
        out->support_calls++;
        x = v3_sub(xa, xb);
        if (stop == NESMINO_STOP_SOLUTION) {
            v3 e = v3_sub(x, *xstar);
            if (v3_dot(e, e) <= tolerance) { out->converged = 1; break; }
        } else {
            /* FW duality gap g = 2 <x, x - s>, s = s_A(-x) - s_B(x) (eq. 12). */
            v3 s = v3_sub(support(a, pa, v3_scale(x, -1.0)), support(b, pb, x));
            double g = 2.0 * v3_dot(x, v3_sub(x, s));
            out->support_calls++;
            out->bound = sqrt(fmax(g, 0.0));
            if (g <= tolerance) { out->converged = 1; break; }
        }
    }
    out->distance = sqrt(v3_dot(v3_sub(xa, xb), v3_sub(xa, xb)));
    return 0;
}
