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
 * WORKLOAD: ellipsoids-close, boxes-close, hulls-close, ellipsoids-overlapping
 * (GJK, distance),
 * ellipsoids-distant, boxes-distant, hulls-distant (GJK, Boolean); also
 * boxes-overlapping (distance), boxes-overlapping-boolean, boxes-close-boolean,
 * ellipsoids-close-boolean, ellipsoids-distant-distance, hulls-overlapping
 * (for timing other cells); hulls: 141
 * points on an ellipsoid, hill climbing on the Qhull hull's vertex graph (agjk)
 * and Coal's own graph of the same hull, as in the benchmark. stdout: one line per query, "query I
 * support_calls N verdict V", in dump order. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coal_adapter.h"
#include "coal_bench.h"
#include "ccd_adapter.h"
#include "hull_support.h"
#include "mesh_io.h"
#include "problems.h"
#include "solve.h"

typedef struct workload {
    const char *name;
    int family, category, mode;
    int hull_n; /* BENCH_HULLS: points per hull */
} workload;

static const workload workloads[] = {
    {"ellipsoids-close", BENCH_ELLIPSOIDS, BENCH_CLOSE, BENCH_DISTANCE, 0},
    {"boxes-close", BENCH_BOXES, BENCH_CLOSE, BENCH_DISTANCE, 0},
    {"hulls-close", BENCH_HULLS, BENCH_CLOSE, BENCH_DISTANCE, 141},
    {"ellipsoids-overlapping", BENCH_ELLIPSOIDS, BENCH_OVERLAPPING, BENCH_DISTANCE, 0},
    {"ellipsoids-distant", BENCH_ELLIPSOIDS, BENCH_DISTANT, BENCH_BOOLEAN, 0},
    {"boxes-distant", BENCH_BOXES, BENCH_DISTANT, BENCH_BOOLEAN, 0},
    {"hulls-distant", BENCH_HULLS, BENCH_DISTANT, BENCH_BOOLEAN, 141},
    /* Not in callgrind.sh's table; for same-run timing of other cells. */
    {"boxes-overlapping", BENCH_BOXES, BENCH_OVERLAPPING, BENCH_DISTANCE, 0},
    {"boxes-overlapping-boolean", BENCH_BOXES, BENCH_OVERLAPPING, BENCH_BOOLEAN, 0},
    {"boxes-close-boolean", BENCH_BOXES, BENCH_CLOSE, BENCH_BOOLEAN, 0},
    {"ellipsoids-close-boolean", BENCH_ELLIPSOIDS, BENCH_CLOSE, BENCH_BOOLEAN, 0},
    {"ellipsoids-overlapping-boolean", BENCH_ELLIPSOIDS, BENCH_OVERLAPPING, BENCH_BOOLEAN, 0},
    {"ellipsoids-distant-distance", BENCH_ELLIPSOIDS, BENCH_DISTANT, BENCH_DISTANCE, 0},
    {"hulls-overlapping", BENCH_HULLS, BENCH_OVERLAPPING, BENCH_DISTANCE, 141},
    {"hulls-distant-distance", BENCH_HULLS, BENCH_DISTANT, BENCH_DISTANCE, 141},
    /* Real meshes: AGJK_WORK_MESH_DIR (default out/meshes/random_urdfs, as
     * tools/fetch-meshes.sh leaves them), scaled as agjk-bench scales them. */
    {"meshes-distant-distance", BENCH_MESHES, BENCH_DISTANT, BENCH_DISTANCE, 0},
    {"meshes-overlapping-boolean", BENCH_MESHES, BENCH_OVERLAPPING, BENCH_BOOLEAN, 0},
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

/* The method of both libraries: plain GJK, or AGJK_WORK_METHOD=nesterov,
 * normalized or polyak in the environment (a quick look at the momentum
 * variants; the callgrind table is plain GJK), or adaptive (agjk's default;
 * Coal then runs Nesterov). */
static int work_method(void) {
    const char *m = getenv("AGJK_WORK_METHOD");
    if (m && strcmp(m, "nesterov") == 0) return 1;
    if (m && strcmp(m, "polyak") == 0) return 2;
    if (m && strcmp(m, "adaptive") == 0) return 3;
    if (m && strcmp(m, "normalized") == 0) return 4;
    return 0;
}

/* The query as bench_solve() asks it: plain GJK (see work_method),
 * tolerance 1e-8, cap 1000, no witness points (agjk computes them too with
 * AGJK_WORK_WITNESS set in the environment, a look at their cost; Coal's
 * query is the same either way); and the same for Coal. */
static void agjk_query_init(agjk_query *q, const bench_set *set, const bench_problem *p,
                            const workload *w) {
    q->a = &set->shapes[p->a];
    q->b = &set->shapes[p->b];
    q->p = p;
    q->boolean = w->mode == BENCH_BOOLEAN;
    q->opt = agjk_default_options();
    q->opt.method = (const agjk_method[]){AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV,
                                          AGJK_METHOD_POLYAK, AGJK_METHOD_ADAPTIVE,
                                          AGJK_METHOD_NESTEROV_NORMALIZED}[work_method()];
    q->opt.tolerance = 1e-8;
    q->opt.max_iterations = 1000;
    q->opt.compute = getenv("AGJK_WORK_WITNESS") ? AGJK_COMPUTE_WITNESS : AGJK_COMPUTE_DISTANCE;
}

static void coal_desc_init(coal_query_desc *d, const agjk_query *q) {
    memset(d, 0, sizeof *d);
    coal_bench_pose(&q->p->pose_a, d->rotation_a, d->translation_a);
    coal_bench_pose(&q->p->pose_b, d->rotation_b, d->translation_b);
    d->method = (const int[]){COAL_GJK, COAL_NESTEROV, COAL_POLYAK, COAL_NESTEROV,
                              COAL_NESTEROV_NORMALIZED}[work_method()];
    d->boolean = q->boolean;
    d->tolerance = 1e-8;
    d->max_iterations = 1000;
    d->now_ns = bench_now_ns;
    d->trimmed_mean = bench_trimmed_mean;
}

/* Timing mode (not for callgrind): each problem run REPS times in a row by
 * agjk, then by Coal, alternating in rounds; per problem the fastest round's
 * mean. A quick same-run comparison while working on the kernel; the
 * benchmark (make bench) is the reference. Back-to-back runs measure
 * throughput, where the benchmark times each run alone (closer to latency):
 * short queries can differ a lot between the two (README, libccd section). */
#define TIME_MAX 4096
#define TIME_ROUNDS 5
typedef struct time_stats {
    double agjk_ns[TIME_MAX], coal_ns[TIME_MAX];
    int count;
} time_stats;

/* AGJK_WORK_PERRUN in the environment: each run timed alone and a round's
 * time the mean of its fastest 90% of runs, as the benchmark times them. */
static int per_run(void) { return getenv("AGJK_WORK_PERRUN") != NULL; }

static double best_round(int (*run)(const void *), const void *q, int reps) {
    static double times[1024];
    double best = 1e300;
    int alone = per_run() && reps <= 1024;
    for (int r = 0; r < TIME_ROUNDS; ++r) {
        double t;
        if (alone) {
            for (int k = 0; k < reps; ++k) {
                double t0 = bench_now_ns();
                run(q);
                times[k] = bench_now_ns() - t0;
            }
            t = bench_trimmed_mean(times, reps);
        } else {
            double t0 = bench_now_ns();
            for (int k = 0; k < reps; ++k) run(q);
            t = (bench_now_ns() - t0) / reps;
        }
        if (t < best) best = t;
    }
    return best;
}

static int run_agjk(const void *q) {
    agjk_result res;
    return measured_agjk(q, &res);
}
static int run_coal(const void *q) { return measured_coal((void *)(uintptr_t)q); }

static int run_mpr(const void *q) {
    return bench_ccd_run((bench_ccd_query *)(uintptr_t)q, CCD_MPR);
}

/* AGJK_WORK_VS=mpr in the environment: the other library is libccd's MPR
 * (Boolean answers; issue 8's one-support target), not Coal. */
static int versus_mpr(void) {
    const char *v = getenv("AGJK_WORK_VS");
    return v && strcmp(v, "mpr") == 0;
}

/* AGJK_WORK_VS=mode: the other is agjk itself in the other mode (distance
 * for a Boolean workload and the reverse), on the same problems: what one
 * mode costs over the other for the same support calls. */
static int versus_mode(void) {
    const char *v = getenv("AGJK_WORK_VS");
    return v && strcmp(v, "mode") == 0;
}

static void time_one(const bench_set *set, const bench_problem *p, const workload *w, int reps,
                     time_stats *st) {
    agjk_query q;
    coal_query_desc d;
    agjk_query_init(&q, set, p, w);
    if (versus_mode()) {
        agjk_query other = q;
        other.boolean = !q.boolean;
        if (st->count < TIME_MAX) {
            st->agjk_ns[st->count] = best_round(run_agjk, &q, reps);
            st->coal_ns[st->count] = best_round(run_agjk, &other, reps);
            ++st->count;
        }
        return;
    }
    if (versus_mpr()) {
        static bench_ccd_query cq; /* points into itself: set up in place */
        bench_ccd_prepare(&cq, set, p, 1000);
        if (st->count < TIME_MAX) {
            st->agjk_ns[st->count] = best_round(run_agjk, &q, reps);
            st->coal_ns[st->count] = best_round(run_mpr, &cq, reps);
            ++st->count;
        }
        return;
    }
    coal_desc_init(&d, &q);
    void *sa = coal_bench_shape(q.a), *sb = coal_bench_shape(q.b);
    void *cq = coal_adapter_query_new(sa, sb, &d);
    if (cq && st->count < TIME_MAX) {
        st->agjk_ns[st->count] = best_round(run_agjk, &q, reps);
        st->coal_ns[st->count] = best_round(run_coal, (const void *)(uintptr_t)cq, reps);
        ++st->count;
    }
    coal_adapter_query_free(cq);
    coal_adapter_shape_free(sa);
    coal_adapter_shape_free(sb);
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void time_report(time_stats *st, const char *name) {
    static double ratio[TIME_MAX];
    double sa = 0.0, sc = 0.0;
    for (int i = 0; i < st->count; ++i) {
        ratio[i] = st->agjk_ns[i] / st->coal_ns[i];
        sa += st->agjk_ns[i];
        sc += st->coal_ns[i];
    }
    /* Per problem, in the order of the queries `agjk` mode prints (their
     * support calls tell fixed from per-iteration cost). */
    if (getenv("AGJK_WORK_PER_PROBLEM"))
        for (int i = 0; i < st->count; ++i)
            fprintf(stderr, "problem %d agjk_ns %.2f other_ns %.2f\n", i, st->agjk_ns[i],
                    st->coal_ns[i]);
    qsort(ratio, (size_t)st->count, sizeof ratio[0], cmp_double);
    const char *other = versus_mode() ? "agjk-other-mode" : versus_mpr() ? "mpr" : "coal";
    printf("%s: %d problems, mean ns agjk %.1f %s %.1f, median ratio agjk/%s %.3f\n", name,
           st->count, sa / st->count, other, sc / st->count, other,
           st->count ? ratio[st->count / 2] : 0.0);
}

int main(int argc, char **argv) {
    const workload *w = NULL;
    bench_set set;
    bench_mesh_source meshes = {0};
    bench_rng rng;
    time_stats stats = {0};
    int i, n = 0, max = argc > 3 ? atoi(argv[3]) : 40, coal, timing;
    if (argc < 3 || (strcmp(argv[1], "agjk") != 0 && strcmp(argv[1], "coal") != 0 &&
                     strcmp(argv[1], "time") != 0)) {
        fprintf(stderr, "usage: agjk-callgrind-work agjk|coal WORKLOAD [PROBLEMS]\n"
                        "       agjk-callgrind-work time WORKLOAD [PROBLEMS [REPS]]\n"
                        "environment: AGJK_WORK_METHOD=nesterov|normalized|polyak|adaptive, "
                        "AGJK_WORK_WITNESS=1, AGJK_WORK_VS=mpr (time: libccd's MPR "
                        "instead of Coal) or mode (time: agjk in the other mode), AGJK_WORK_PER_PROBLEM=1 (time: each "
                        "problem's times on stderr)\n"
                        "WORKLOAD:");
        /* (from the table: the list cannot go stale) */
        for (i = 0; i < (int)(sizeof workloads / sizeof workloads[0]); ++i)
            fprintf(stderr, " %s", workloads[i].name);
        fprintf(stderr, "\n");
        return 2;
    }
    coal = strcmp(argv[1], "coal") == 0;
    timing = strcmp(argv[1], "time") == 0;
    for (i = 0; i < (int)(sizeof workloads / sizeof workloads[0]); ++i)
        if (strcmp(argv[2], workloads[i].name) == 0) w = &workloads[i];
    if (!w || max < 1) {
        fprintf(stderr, "agjk-callgrind-work: unknown workload '%s' or bad count\n", argv[2]);
        return 2;
    }
    if ((coal || timing) && !coal_adapter_available()) {
        fprintf(stderr, "agjk-callgrind-work: no Coal in this build (%s)\n",
                coal_adapter_version());
        return 3;
    }
    /* The benchmark's generator and seed: 12 targets per pose, 4 per category. */
    bench_set_init(&set, 2 * (max / 4 + 2), BENCH_TARGET_COUNT * (max / 4 + 2));
    set.polytope_hook = bench_hull_hook; /* as agjk-bench: the hull's vertex graph */
    set.aux_free = bench_hull_free;
    bench_rng_seed(&rng, 4 * 1 + (uint64_t)w->family);
    if (w->family == BENCH_MESHES) {
        const char *dir = getenv("AGJK_WORK_MESH_DIR");
        if (bench_read_mesh_dir(dir ? dir : "out/meshes/random_urdfs", &meshes, 1000, 0.1) < 1) {
            fprintf(stderr, "agjk-callgrind-work: no meshes (set AGJK_WORK_MESH_DIR)\n");
            return 3;
        }
    }
    bench_generate(&set, w->family, max / 4 + 1, 1, w->hull_n, &meshes, &rng, 0, 0);
    for (i = 0; i < set.problem_count && n < max; ++i) {
        const bench_problem *p = &set.problems[i];
        agjk_query q;
        agjk_result res;
        int verdict, calls, k;
        if (p->category != w->category) continue;
        if (timing) {
            time_one(&set, p, w, argc > 4 ? atoi(argv[4]) : 200, &stats);
            ++n;
            continue;
        }
        agjk_query_init(&q, &set, p, w);
        if (!coal) {
            measured_agjk(&q, &res);
            calls = res.support_calls;
            verdict = res.status == AGJK_STATUS_INTERSECTING ? 1
                      : res.status == AGJK_STATUS_SEPARATED  ? 0 : -1;
        } else {
            coal_query_desc d;
            coal_answer a;
            void *sa = coal_bench_shape(q.a), *sb = coal_bench_shape(q.b), *cq;
            coal_desc_init(&d, &q);
            cq = coal_adapter_query_new(sa, sb, &d);
            if (!cq || coal_adapter_run(sa, sb, &d, &a) != 0) return 3; /* counts the calls */
            /* Once unmeasured first: Coal sizes its hill-climbing buffers (an
             * allocation) on a query object's first use, and the benchmark
             * times the runs after it. */
            coal_adapter_query_run(cq);
            verdict = measured_coal(cq);
            calls = a.support_calls;
            coal_adapter_query_free(cq);
            coal_adapter_shape_free(sa);
            coal_adapter_shape_free(sb);
        }
        k = n++;
        printf("query %d support_calls %d verdict %d\n", k, calls, verdict);
    }
    if (timing) time_report(&stats, argv[2]);
    bench_set_free(&set);
    bench_free_meshes(&meshes);
    return n > 0 ? 0 : 1;
}
