/* SPDX-License-Identifier: MIT */
/* Judging one result against the certified reference. */
#ifndef AGJK_BENCH_EVALUATE_H
#define AGJK_BENCH_EVALUATE_H

#include "solve.h"

typedef struct bench_record {
    int problem;
    signed char method, mode;
    unsigned char violation;  /* the reference lies outside the result's certified interval */
    unsigned char wrong;      /* a certified verdict (separated/intersecting) the reference refutes */
    unsigned char converged;  /* status is a verdict (not NOT_CONVERGED / INVALID_INPUT) */
    unsigned char judged;     /* the reference converged, so the checks above ran */
    bench_run run;
    double error;             /* |distance - d_ref| in distance mode, else 0 */
} bench_record;

/* What the checks below forgive for the rounding of the double-precision
 * query itself: 1e-12 for the protocol's coordinates (O(10)), more for
 * problems of larger scale or moved far from the origin (length units). */
double bench_rounding_slack(const bench_problem *p);

/* Fills rec's judgement fields from problem p's reference and rec->run. */
void bench_evaluate(const bench_problem *p, bench_record *rec);

#endif
