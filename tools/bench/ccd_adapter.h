/* SPDX-License-Identifier: MIT */
/* The benchmark's problems seen through libccd (Debian libccd-dev, 2.x).
 *
 * Both libraries get the same support functions (agjk's shape callbacks,
 * evaluated in the shape's local frame), so a comparison measures the
 * algorithms, not the support code. */
#ifndef AGJK_BENCH_CCD_ADAPTER_H
#define AGJK_BENCH_CCD_ADAPTER_H

#include <ccd/ccd.h>

#include "problems.h"

enum { CCD_GJK = 0, CCD_MPR = 1 };

/* 0 if libccd was built with double precision (ccd_real_t is double), which
 * the comparison needs; else prints why and returns -1. */
int bench_ccd_check(void);

typedef struct bench_ccd_object {
    const bench_shape *shape;
    const agjk_pose *pose;
    int *hint; /* warm-start hint of agjk's callback (written through the pointer) */
} bench_ccd_object;

/* A libccd query set up once, so that timing covers only the call. It points
 * into itself: do not copy it after bench_ccd_prepare(). */
typedef struct bench_ccd_query {
    ccd_t ccd;
    bench_ccd_object a, b;
    int hint_a, hint_b;
} bench_ccd_query;

/* max_iterations is always set (libccd's default is unbounded). */
void bench_ccd_prepare(bench_ccd_query *q, const bench_set *set, const bench_problem *p,
                       unsigned long max_iterations);
/* libccd's Boolean answer: 1 intersecting, 0 not. Support hints restart at 0
 * on every call, as agjk's do with default options. */
int bench_ccd_run(bench_ccd_query *q, int algorithm);

/* Prepare + run in one call. */
int bench_ccd_intersect(const bench_set *set, const bench_problem *p, int algorithm,
                        unsigned long max_iterations);

#endif
