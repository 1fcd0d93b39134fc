/* SPDX-License-Identifier: MIT */
#include "ccd_bench.h"

#include <stdlib.h>

#include "ccd_adapter.h"
#include "guard.h"
#include "solve.h"

typedef struct ctx {
    const bench_set *set;
    const ccd_bench_options *o;
} ctx;

agjk_method ccd_bench_accel_method(int family) {
    return family == BENCH_ELLIPSOIDS ? AGJK_METHOD_NESTEROV : AGJK_METHOD_NESTEROV_NORMALIZED;
}

const char *ccd_bench_column_name(int c) {
    static const char *const names[CB_COUNT] = {"agjk GJK", "agjk accelerated",
                                                "libccd GJK", "libccd MPR"};
    return c >= 0 && c < CB_COUNT ? names[c] : "unknown";
}

static volatile int sink;

static void run_case(void *vctx, int index, void *record) {
    const ctx *c = vctx;
    const bench_problem *p = &c->set->problems[index];
    const bench_shape *a = &c->set->shapes[p->a], *b = &c->set->shapes[p->b];
    ccd_bench_record *rec = record;
    int reps = c->o->reps > 0 ? c->o->reps : 1, col, r;
    double *t = malloc((size_t)reps * sizeof *t);
    if (!t) abort();
    for (col = 0; col < CB_COUNT; ++col) {
        int answer = -1;
        if (c->o->columns && !(c->o->columns & (1u << col))) continue;
        /* Set-up (options, libccd's struct) stays outside the timed region. */
        if (col <= CB_AGJK_ACCEL) {
            agjk_options opt = agjk_default_options();
            agjk_result res;
            opt.method = col == CB_AGJK_GJK ? AGJK_METHOD_GJK : ccd_bench_accel_method(p->family);
            opt.max_iterations = c->o->max_iterations;
            if (c->o->tolerance > 0) opt.tolerance = c->o->tolerance * p->scale * p->scale;
            for (r = 0; r < reps; ++r) {
                double t0 = bench_now_ns();
                agjk_collide(&a->shape, &p->pose_a, &b->shape, &p->pose_b, &opt, &res);
                t[r] = bench_now_ns() - t0;
                sink = (int)res.status;
            }
            rec->status[col] = (int)res.status;
            answer = res.status == AGJK_STATUS_INTERSECTING ? 1
                     : res.status == AGJK_STATUS_SEPARATED ? 0 : -1;
        } else {
            bench_ccd_query q;
            int algorithm = col == CB_CCD_MPR ? CCD_MPR : CCD_GJK;
            bench_ccd_prepare(&q, c->set, p, (unsigned long)c->o->max_iterations);
            for (r = 0; r < reps; ++r) {
                double t0 = bench_now_ns();
                answer = bench_ccd_run(&q, algorithm) != 0;
                t[r] = bench_now_ns() - t0;
                sink = answer;
            }
        }
        rec->answer[col] = answer;
        rec->time_ns[col] = c->o->reps > 0 ? bench_trimmed_mean(t, reps) : 0.0;
    }
    free(t);
}

int ccd_bench_run(const bench_set *set, const ccd_bench_options *o, ccd_bench_record *records,
                  unsigned char *outcome) {
    ctx c;
    c.set = set;
    c.o = o;
    return guard_run(set->problem_count, sizeof *records, run_case, &c, records, outcome,
                     o->timeout_seconds);
}
