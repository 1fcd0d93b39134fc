/* SPDX-License-Identifier: MIT */
/* agjk-callgrind-work: a small fixed workload of the benchmark's problems run
 * by agjk or by Coal, for instruction counts under valgrind's callgrind
 * (tools/bench/callgrind.sh). Every query is one call of measured_agjk() or
 * measured_coal(), the functions the script collects (--toggle-collect) and
 * dumps after (--dump-after), so each dump holds one query. The query is the
 * benchmark's timed region: agjk_distance / agjk_collide with the options of
 * bench_solve(), or Coal's MinkowskiDiff::set + GJK::evaluate.
 *
 *   agjk-callgrind-work agjk|coal WORKLOAD [PROBLEMS]
 *
 * WORKLOAD: ellipsoids-close, boxes-close (GJK, distance), ellipsoids-distant,
 * boxes-distant (GJK, Boolean). stdout: one line per query, "query I
 * support_calls N verdict V", in dump order. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coal_adapter.h"
#include "problems.h"
#include "solve.h"

typedef struct workload {
    const char *name;
    int family, category, mode;
} workload;

static const workload workloads[] = {
    {"ellipsoids-close", BENCH_ELLIPSOIDS, BENCH_CLOSE, BENCH_DISTANCE},
    {"boxes-close", BENCH_BOXES, BENCH_CLOSE, BENCH_DISTANCE},
    {"ellipsoids-distant", BENCH_ELLIPSOIDS, BENCH_DISTANT, BENCH_BOOLEAN},
    {"boxes-distant", BENCH_BOXES, BENCH_DISTANT, BENCH_BOOLEAN},
};

typedef struct agjk_query {
    const bench_shape *a, *b;
    const bench_problem *p;
    agjk_options opt;
    int boolean;
} agjk_query;

/* The measured regions. noinline keeps them as the functions callgrind
 * toggles on; the queries' own code is not affected. */
__attribute__((noinline)) int measured_agjk(const agjk_query *q, agjk_result *res);
__attribute__((noinline)) int measured_coal(void *query);

int measured_agjk(const agjk_query *q, agjk_result *res) {
    if (q->boolean)
        return (int)agjk_collide(&q->a->shape, &q->p->pose_a, &q->b->shape, &q->p->pose_b,
                                 &q->opt, res);
    return (int)agjk_distance(&q->a->shape, &q->p->pose_a, &q->b->shape, &q->p->pose_b,
                              &q->opt, res);
}

int measured_coal(void *query) { return coal_adapter_query_run(query); }

static void *coal_shape_of(const bench_shape *s) {
    coal_shape_desc d;
    memset(&d, 0, sizeof d);
    d.kind = s->kind == REF_ELLIPSOID ? COAL_SHAPE_ELLIPSOID : COAL_SHAPE_BOX;
    d.size[0] = s->size.x;
    d.size[1] = s->size.y;
    d.size[2] = s->size.z;
    return coal_adapter_shape_new(&d);
}

static void pose_to(const agjk_pose *p, double r[9], double t[3]) {
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) r[3 * i + j] = p->rotation[i][j];
    t[0] = p->translation.x;
    t[1] = p->translation.y;
    t[2] = p->translation.z;
}

int main(int argc, char **argv) {
    const workload *w = NULL;
    bench_set set;
    bench_rng rng;
    int i, n = 0, max = argc > 3 ? atoi(argv[3]) : 40, coal;
    if (argc < 3 || (strcmp(argv[1], "agjk") != 0 && strcmp(argv[1], "coal") != 0)) {
        fprintf(stderr, "usage: agjk-callgrind-work agjk|coal WORKLOAD [PROBLEMS]\n"
                        "WORKLOAD: ellipsoids-close boxes-close ellipsoids-distant "
                        "boxes-distant\n");
        return 2;
    }
    coal = strcmp(argv[1], "coal") == 0;
    for (i = 0; i < (int)(sizeof workloads / sizeof workloads[0]); ++i)
        if (strcmp(argv[2], workloads[i].name) == 0) w = &workloads[i];
    if (!w || max < 1) {
        fprintf(stderr, "agjk-callgrind-work: unknown workload '%s' or bad count\n", argv[2]);
        return 2;
    }
    if (coal && !coal_adapter_available()) {
        fprintf(stderr, "agjk-callgrind-work: no Coal in this build (%s)\n",
                coal_adapter_version());
        return 3;
    }
    /* The benchmark's generator and seed: 12 targets per pose, 4 per category. */
    bench_set_init(&set, 2 * (max / 4 + 2), BENCH_TARGET_COUNT * (max / 4 + 2));
    bench_rng_seed(&rng, 4 * 1 + (uint64_t)w->family);
    bench_generate(&set, w->family, max / 4 + 1, 1, 0, NULL, &rng, 0, 0);
    for (i = 0; i < set.problem_count && n < max; ++i) {
        const bench_problem *p = &set.problems[i];
        agjk_query q;
        agjk_result res;
        int verdict, calls, k;
        if (p->category != w->category) continue;
        q.a = &set.shapes[p->a];
        q.b = &set.shapes[p->b];
        q.p = p;
        q.boolean = w->mode == BENCH_BOOLEAN;
        q.opt = agjk_default_options(); /* as bench_solve() */
        q.opt.method = AGJK_METHOD_GJK;
        q.opt.tolerance = 1e-8;
        q.opt.max_iterations = 1000;
        q.opt.compute = AGJK_COMPUTE_DISTANCE;
        if (!coal) {
            measured_agjk(&q, &res);
            calls = res.support_calls;
            verdict = res.status == AGJK_STATUS_INTERSECTING ? 1
                      : res.status == AGJK_STATUS_SEPARATED  ? 0 : -1;
        } else {
            coal_query_desc d;
            coal_answer a;
            void *sa = coal_shape_of(q.a), *sb = coal_shape_of(q.b), *cq;
            memset(&d, 0, sizeof d);
            pose_to(&p->pose_a, d.rotation_a, d.translation_a);
            pose_to(&p->pose_b, d.rotation_b, d.translation_b);
            d.method = COAL_GJK;
            d.boolean = q.boolean;
            d.tolerance = 1e-8;
            d.max_iterations = 1000;
            d.reps = 0;
            d.now_ns = bench_now_ns;
            d.trimmed_mean = bench_trimmed_mean;
            cq = coal_adapter_query_new(sa, sb, &d);
            if (!cq || coal_adapter_run(sa, sb, &d, &a) != 0) return 3; /* counts the calls */
            verdict = measured_coal(cq);
            calls = a.support_calls;
            coal_adapter_query_free(cq);
            coal_adapter_shape_free(sa);
            coal_adapter_shape_free(sb);
        }
        k = n++;
        printf("query %d support_calls %d verdict %d\n", k, calls, verdict);
    }
    bench_set_free(&set);
    return n > 0 ? 0 : 1;
}
