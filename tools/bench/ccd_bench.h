/* SPDX-License-Identifier: MIT */
/* Boolean queries side by side: agjk_collide against libccd's GJK and MPR,
 * each case run in a watchdog child (see guard.h). Shared by the benchmark
 * (timing) and tests/ccd (correctness). */
#ifndef AGJK_BENCH_CCD_BENCH_H
#define AGJK_BENCH_CCD_BENCH_H

#include "problems.h"

enum { CB_AGJK_GJK = 0, CB_AGJK_ACCEL = 1, CB_CCD_GJK = 2, CB_CCD_MPR = 3, CB_COUNT = 4 };

typedef struct ccd_bench_record {
    int answer[CB_COUNT];     /* 1 intersecting, 0 separated, -1 no verdict (agjk) */
    int status[2];            /* agjk statuses of CB_AGJK_GJK and CB_AGJK_ACCEL */
    double time_ns[CB_COUNT]; /* mean of the fastest 90% of reps (0 if reps == 0) */
} ccd_bench_record;

typedef struct ccd_bench_options {
    int reps;                 /* 0: answer only, untimed */
    int max_iterations;       /* for both libraries */
    double tolerance;         /* agjk's absolute gap tolerance at scale 1; a problem
                                 generated at scale s uses tolerance * s^2 (the same
                                 relative accuracy); 0: agjk's default */
    double timeout_seconds;   /* per case */
    unsigned columns;         /* bit c: run column c; 0 means all */
} ccd_bench_options;

/* The accelerated agjk method used for a family: Nesterov on strictly convex
 * shapes, Nesterov with normalization on polytopes and boxes (paper Sec. IV). */
agjk_method ccd_bench_accel_method(int family);
const char *ccd_bench_column_name(int column);

/* Runs problems[0..n-1] of set; fills records[i] and outcome[i] (GUARD_*).
 * Returns the number of hung or crashed cases, -1 on fork failure. */
int ccd_bench_run(const bench_set *set, const ccd_bench_options *o, ccd_bench_record *records,
                  unsigned char *outcome);

#endif
