/* SPDX-License-Identifier: MIT */
/* agjk-depth-work: the depth benchmark's overlapping problems run once each by
 * agjk_signed_distance (the depth benchmark's certified column) or by Coal's
 * GJK + EPA (its "Coal default" column), for instruction counts under
 * valgrind's callgrind. Every query
 * is one call of measured_agjk() or measured_coal():
 *
 *   agjk-depth-work agjk|coal ellipsoids|boxes|hulls [PROBLEMS [METHOD [REPEAT]]]
 *   valgrind --tool=callgrind --collect-atstart=no --toggle-collect=measured_agjk \
 *       agjk-depth-work agjk ellipsoids 200
 *
 * (--toggle-collect=agjk__epa counts EPA alone.) Instructions per query are
 * the total over the PROBLEMS queries divided by their number; stdout lists
 * one line per query: "query I epa_iterations N signed_distance S". The
 * problems are the benchmark's (same generator and seeds as agjk-bench's
 * default run, hulls of 33 and 141 vertices), the first PROBLEMS overlapping
 * ones of the family (default 200). METHOD: an agjk_method number (default:
 * the depth benchmark's, Nesterov for ellipsoids, normalized otherwise; -1 for
 * that). REPEAT: run each query that many times (wall-clock comparisons of
 * two builds with time(1); default 1). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coal_adapter.h"
#include "coal_bench.h"
#include "hull_support.h"
#include "problems.h"
#include "solve.h"

typedef struct agjk_query {
    const bench_shape *a, *b;
    const bench_problem *p;
    agjk_options opt;
} agjk_query;

/* The measured regions; noinline keeps them as functions callgrind can toggle on. */
__attribute__((noinline)) int measured_agjk(const agjk_query *q, agjk_signed_result *r);
__attribute__((noinline)) int measured_coal(void *query);

int measured_agjk(const agjk_query *q, agjk_signed_result *r) {
    return (int)agjk_signed_distance(&q->a->shape, &q->p->pose_a, &q->b->shape, &q->p->pose_b,
                                     &q->opt, r);
}

int measured_coal(void *query) { return coal_adapter_depth_query_run(query); }

int main(int argc, char **argv) {
    static const int hull_sizes[2] = {33, 141};
    int family = -1, max = argc > 3 ? atoi(argv[3]) : 200, n = 0;
    int method = argc > 4 ? atoi(argv[4]) : -1;
    int repeat = argc > 5 ? atoi(argv[5]) : 1;
    if (argc > 2) {
        if (strcmp(argv[2], "ellipsoids") == 0) family = BENCH_ELLIPSOIDS;
        if (strcmp(argv[2], "boxes") == 0) family = BENCH_BOXES;
        if (strcmp(argv[2], "hulls") == 0) family = BENCH_HULLS;
    }
    if (argc < 3 || family < 0 || max < 1 ||
        (strcmp(argv[1], "agjk") != 0 && strcmp(argv[1], "coal") != 0)) {
        fprintf(stderr, "usage: agjk-depth-work agjk|coal ellipsoids|boxes|hulls [PROBLEMS "
                        "[METHOD [REPEAT]]]\n");
        return 2;
    }
    int coal = strcmp(argv[1], "coal") == 0;
    if (coal && !coal_adapter_available()) {
        fprintf(stderr, "agjk-depth-work: no Coal in this build (%s)\n", coal_adapter_version());
        return 3;
    }
    /* agjk-bench's default sizes and seeds (seed 1: stream 4 + family);
     * 4 overlapping targets per pose. */
    int pairs = family == BENCH_ELLIPSOIDS ? 100 : family == BENCH_BOXES ? 50 : 10;
    int poses = family == BENCH_HULLS ? 5 : 10;
    bench_set set;
    bench_rng rng;
    bench_set_init(&set, 2 * pairs * 2 + 8, BENCH_TARGET_COUNT * pairs * poses * 2 + 8);
    if (family == BENCH_HULLS) {
        set.polytope_hook = bench_hull_hook;
        set.aux_free = bench_hull_free;
    }
    bench_rng_seed(&rng, 4 + (uint64_t)family);
    for (int h = 0; h < (family == BENCH_HULLS ? 2 : 1); ++h)
        bench_generate(&set, family, pairs, poses, family == BENCH_HULLS ? hull_sizes[h] : 0,
                       NULL, &rng, 0, 0);
    /* Spread the PROBLEMS queries over the set (every family size and scale). */
    int overlapping = 0;
    for (int i = 0; i < set.problem_count; ++i)
        overlapping += set.problems[i].category == BENCH_OVERLAPPING;
    int stride = overlapping / max > 1 ? overlapping / max : 1, seen = 0;
    for (int i = 0; i < set.problem_count && n < max; ++i) {
        const bench_problem *p = &set.problems[i];
        if (p->category != BENCH_OVERLAPPING || seen++ % stride != 0) continue;
        agjk_query q;
        q.a = &set.shapes[p->a];
        q.b = &set.shapes[p->b];
        q.p = p;
        q.opt = agjk_default_options(); /* as depth_bench.c's certified column */
        q.opt.method = family == BENCH_ELLIPSOIDS ? AGJK_METHOD_NESTEROV
                                                  : AGJK_METHOD_NESTEROV_NORMALIZED;
        if (method >= 0) q.opt.method = (agjk_method)method;
        q.opt.max_iterations = 1000;
        q.opt.tolerance = 1e-8 * p->scale * p->scale;
        int iterations;
        double value;
        if (!coal) {
            agjk_signed_result r;
            for (int k = 0; k < repeat; ++k) measured_agjk(&q, &r);
            iterations = r.epa_iterations;
            value = r.signed_distance;
        } else {
            coal_depth_desc d;
            coal_depth_answer a;
            void *sa = coal_bench_shape(q.a), *sb = coal_bench_shape(q.b);
            memset(&d, 0, sizeof d);
            coal_bench_pose(&p->pose_a, d.rotation_a, d.translation_a);
            coal_bench_pose(&p->pose_b, d.rotation_b, d.translation_b);
            d.gjk_tolerance = 1e-6; /* the depth benchmark's "Coal default" */
            d.gjk_max_iterations = 128;
            d.epa_tolerance = 1e-6;
            d.epa_max_iterations = 64;
            void *cq = coal_adapter_depth_query_new(sa, sb, &d);
            if (!cq) return 3;
            for (int k = 0; k < repeat; ++k) measured_coal(cq);
            coal_adapter_depth_query_answer(cq, &a);
            iterations = a.epa_iterations;
            value = -a.depth;
            coal_adapter_depth_query_free(cq);
            coal_adapter_shape_free(sa);
            coal_adapter_shape_free(sb);
        }
        printf("query %d epa_iterations %d signed_distance %.17g\n", n++, iterations, value);
    }
    bench_set_free(&set);
    return n > 0 ? 0 : 1;
}
