/* SPDX-License-Identifier: MIT */
/* One benchmark measurement: a method run on a problem, timed as in the paper
 * (the problem solved R times; the mean of the 90% fastest runs). */
#ifndef AGJK_BENCH_SOLVE_H
#define AGJK_BENCH_SOLVE_H

#include "problems.h"

typedef enum bench_method {
    BM_FW = 0, BM_NESMINO, BM_GJK, BM_NESTEROV, BM_NESTEROV_NORMALIZED, BM_POLYAK,
    BM_ADAPTIVE, BM_COUNT
} bench_method;

typedef enum bench_mode { BENCH_DISTANCE = 0, BENCH_BOOLEAN = 1 } bench_mode;

const char *bench_method_name(int method);

typedef struct bench_run {
    int status;        /* agjk_status; for NESMINO: SEPARATED/INTERSECTING when converged,
                          else NOT_CONVERGED */
    int iterations, support_calls;
    double distance, bound; /* bound < 0: none (NESMINO with the paper's rule) */
    double time_ns;    /* mean of the fastest 90% of `reps` runs; 0 if reps == 0 */
} bench_run;

typedef struct bench_solve_options {
    double tolerance;
    int relative;          /* agjk methods: AGJK_TOLERANCE_RELATIVE */
    int max_iterations;
    int reps;              /* R; 0: solve once, untimed */
    int nesmino_gap_stop;  /* NESMINO stops on its duality gap instead of ||x - x*|| */
    double nesmino_mu;     /* NESMINO smoothing parameter; 0: infinite (see nesmino.h) */
} bench_solve_options;

/* Returns 0, or -1 if the method does not apply (NESMINO on polytopes,
 * NESMINO in Boolean mode). */
int bench_solve(const bench_set *set, const bench_problem *p, int method, bench_mode mode,
                const bench_solve_options *o, bench_run *out);

/* Mean of the fastest 90% of n timings (sorts `t`). */
double bench_trimmed_mean(double *t, int n);
/* Nanoseconds from a monotonic clock. */
double bench_now_ns(void);

#endif
