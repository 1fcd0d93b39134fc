/* SPDX-License-Identifier: MIT */
/* Aggregates of benchmark records: mean +- std, medians, error counts. */
#ifndef AGJK_BENCH_STATS_H
#define AGJK_BENCH_STATS_H

#include "evaluate.h"

typedef struct bench_filter {
    int family;        /* -1: any */
    int category;      /* -1: any */
    int target_index;  /* -1: any */
    int method;        /* -1: any */
    int mode;          /* -1: any */
    int tag;           /* -1: any; else shape A's tag (hull N) */
    int near_band;     /* 1: only -0.1 <= target <= 0.1 (the paper's mesh table) */
} bench_filter;

bench_filter bench_filter_any(void);

typedef struct bench_stats {
    int n, judged, violations, wrong, not_converged;
    double it_mean, it_std, calls_mean, us_mean, us_std, ns_median;
    double err_median, err_max;
} bench_stats;

void bench_stats_compute(const bench_set *set, const bench_record *recs, int count,
                         const bench_filter *f, bench_stats *out);

double bench_median(double *v, int n); /* sorts v */

#endif
