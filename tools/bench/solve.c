/* SPDX-License-Identifier: MIT */
#include "solve.h"

#include <stdlib.h>
#include <time.h>

#include "nesmino.h"

const char *bench_method_name(int m) {
    static const char *const names[BM_COUNT] = {"FW", "NESMINO", "GJK", "Nesterov",
                                                 "Nesterov-normalized", "Polyak", "Adaptive"};
    return m >= 0 && m < BM_COUNT ? names[m] : "unknown";
}

double bench_now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_trimmed_mean(double *t, int n) {
    int keep, i;
    double sum = 0.0;
    if (n <= 0) return 0.0;
    qsort(t, (size_t)n, sizeof *t, cmp_double);
    keep = (n * 9 + 9) / 10; /* ceil(0.9 n): at least one */
    for (i = 0; i < keep; ++i) sum += t[i];
    return sum / keep;
}

static agjk_method agjk_method_of(int m) {
    switch (m) {
    case BM_FW: return AGJK_METHOD_FRANK_WOLFE;
    case BM_NESTEROV: return AGJK_METHOD_NESTEROV;
    case BM_NESTEROV_NORMALIZED: return AGJK_METHOD_NESTEROV_NORMALIZED;
    case BM_POLYAK: return AGJK_METHOD_POLYAK;
    case BM_ADAPTIVE: return AGJK_METHOD_ADAPTIVE;
    default: return AGJK_METHOD_GJK;
    }
}

/* Keeps the optimiser from discarding a result it thinks unused. */
static volatile double bench_sink;

int bench_solve(const bench_set *set, const bench_problem *p, int method, bench_mode mode,
                const bench_solve_options *o, bench_run *out) {
    const bench_shape *a = &set->shapes[p->a], *b = &set->shapes[p->b];
    double stack_times[128], *times = stack_times;
    int r, reps = o->reps > 0 ? o->reps : 1;
    if (reps > 128) {
        times = malloc((size_t)reps * sizeof *times);
        if (!times) return -1;
    }
    if (method == BM_NESMINO) {
        nesmino_result nr;
        if (mode != BENCH_DISTANCE) return -1;
        for (r = 0; r < reps; ++r) {
            double t0 = bench_now_ns();
            if (bench_nesmino(a, &p->pose_a, b, &p->pose_b,
                              o->nesmino_gap_stop ? NESMINO_STOP_GAP : NESMINO_STOP_SOLUTION,
                              o->tolerance, &p->xstar, o->max_iterations, o->nesmino_mu, &nr) != 0) {
                if (times != stack_times) free(times);
                return -1;
            }
            times[r] = bench_now_ns() - t0;
            bench_sink = nr.distance;
        }
        out->status = !nr.converged ? AGJK_STATUS_NOT_CONVERGED
                      : p->target > 0 ? AGJK_STATUS_SEPARATED : AGJK_STATUS_INTERSECTING;
        out->iterations = nr.iterations;
        out->support_calls = nr.support_calls;
        out->distance = nr.distance;
        out->bound = nr.bound;
    } else {
        agjk_options opt = agjk_default_options();
        agjk_result res;
        opt.method = agjk_method_of(method);
        opt.tolerance = o->tolerance;
        opt.tolerance_mode = o->relative ? AGJK_TOLERANCE_RELATIVE : AGJK_TOLERANCE_ABSOLUTE;
        opt.max_iterations = o->max_iterations;
        opt.compute = AGJK_COMPUTE_DISTANCE; /* the paper times the distance alone */
        for (r = 0; r < reps; ++r) {
            double t0 = bench_now_ns();
            if (mode == BENCH_DISTANCE)
                agjk_distance(&a->shape, &p->pose_a, &b->shape, &p->pose_b, &opt, &res);
            else
                agjk_collide(&a->shape, &p->pose_a, &b->shape, &p->pose_b, &opt, &res);
            times[r] = bench_now_ns() - t0;
            bench_sink = res.distance;
        }
        out->status = (int)res.status;
        out->iterations = res.iterations;
        out->support_calls = res.support_calls;
        out->distance = res.distance;
        out->bound = mode == BENCH_DISTANCE ? res.bound : -1.0;
    }
    out->time_ns = o->reps > 0 ? bench_trimmed_mean(times, reps) : 0.0;
    if (times != stack_times) free(times);
    return 0;
}
