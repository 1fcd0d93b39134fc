/* SPDX-License-Identifier: MIT */
/* The benchmark's problems seen through libccd (Debian libccd-dev, 2.x).
 *
 * Both libraries get the same support functions (agjk's shape callbacks,
 * evaluated in the shape's local frame), so a comparison measures the
 * algorithms, not the support code. */
#ifndef AGJK_BENCH_CCD_ADAPTER_H
#define AGJK_BENCH_CCD_ADAPTER_H

#include "problems.h"

enum { CCD_GJK = 0, CCD_MPR = 1 };

/* 0 if libccd was built with double precision (ccd_real_t is double), which
 * the comparison needs; else prints why and returns -1. */
int bench_ccd_check(void);

/* libccd's Boolean answer for the problem: 1 intersecting, 0 not.
 * max_iterations is always set (libccd's default is unbounded). */
int bench_ccd_intersect(const bench_set *set, const bench_problem *p, int algorithm,
                        unsigned long max_iterations);

#endif
