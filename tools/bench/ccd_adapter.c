/* SPDX-License-Identifier: MIT */
#include "ccd_adapter.h"

#include <stdio.h>

typedef bench_ccd_object ccd_obj;

int bench_ccd_check(void) {
    if (sizeof(ccd_real_t) != sizeof(double)) {
        fprintf(stderr, "libccd was built with %u-byte reals, not double: comparison skipped\n",
                (unsigned)sizeof(ccd_real_t));
        return -1;
    }
    return 0;
}

/* World support: d_local = R^T d, p = R s(d_local) + t. */
static void ccd_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out) {
    const ccd_obj *o = obj;
    const double (*r)[3] = o->pose->rotation;
    const double *d = dir->v;
    agjk_vec3 l, s;
    l.x = r[0][0] * d[0] + r[1][0] * d[1] + r[2][0] * d[2];
    l.y = r[0][1] * d[0] + r[1][1] * d[1] + r[2][1] * d[2];
    l.z = r[0][2] * d[0] + r[1][2] * d[1] + r[2][2] * d[2];
    o->shape->shape.support(o->shape->shape.data, &l, &s, o->hint);
    out->v[0] = r[0][0] * s.x + r[0][1] * s.y + r[0][2] * s.z + o->pose->translation.x;
    out->v[1] = r[1][0] * s.x + r[1][1] * s.y + r[1][2] * s.z + o->pose->translation.y;
    out->v[2] = r[2][0] * s.x + r[2][1] * s.y + r[2][2] * s.z + o->pose->translation.z;
}

/* MPR needs an interior point: every benchmark shape is centred at its origin. */
static void ccd_center(const void *obj, ccd_vec3_t *c) {
    const ccd_obj *o = obj;
    c->v[0] = o->pose->translation.x;
    c->v[1] = o->pose->translation.y;
    c->v[2] = o->pose->translation.z;
}

void bench_ccd_prepare(bench_ccd_query *q, const bench_set *set, const bench_problem *p,
                       unsigned long max_iterations) {
    q->hint_a = q->hint_b = 0;
    q->a.shape = &set->shapes[p->a];
    q->a.pose = &p->pose_a;
    q->a.hint = &q->hint_a;
    q->b.shape = &set->shapes[p->b];
    q->b.pose = &p->pose_b;
    q->b.hint = &q->hint_b;
    CCD_INIT(&q->ccd);
    q->ccd.support1 = ccd_support;
    q->ccd.support2 = ccd_support;
    q->ccd.center1 = ccd_center;
    q->ccd.center2 = ccd_center;
    q->ccd.max_iterations = max_iterations;
}

int bench_ccd_run(bench_ccd_query *q, int algorithm) {
    q->hint_a = q->hint_b = 0;
    return algorithm == CCD_MPR ? ccdMPRIntersect(&q->a, &q->b, &q->ccd)
                                : ccdGJKIntersect(&q->a, &q->b, &q->ccd);
}

int bench_ccd_intersect(const bench_set *set, const bench_problem *p, int algorithm,
                        unsigned long max_iterations) {
    bench_ccd_query q;
    bench_ccd_prepare(&q, set, p, max_iterations);
    return bench_ccd_run(&q, algorithm);
}
