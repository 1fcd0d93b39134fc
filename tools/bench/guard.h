/* SPDX-License-Identifier: MIT */
/* Runs a list of cases in a child process with a watchdog.
 *
 * libccd's MPR portal refinement and EPA loops are unbounded (they ignore
 * max_iterations), so one bad case could hang the whole suite. The cases run
 * in a forked child that reports one fixed-size record per case through a
 * pipe; if no record arrives within the timeout, or the child dies, the case
 * in progress is marked and a new child resumes after it. */
#ifndef AGJK_BENCH_GUARD_H
#define AGJK_BENCH_GUARD_H

#include <stddef.h>

enum { GUARD_OK = 0, GUARD_HUNG = 1, GUARD_CRASHED = 2 };

/* Computes case `index` into `record` (record_size bytes). Runs in the child. */
typedef void (*guard_case_fn)(void *ctx, int index, void *record);

/* Runs cases 0..n-1; records[i * record_size] receives case i's record and
 * outcome[i] one of GUARD_*. Returns the number of cases not GUARD_OK, or -1
 * if no child could be started. */
int guard_run(int n, size_t record_size, guard_case_fn fn, void *ctx, void *records,
              unsigned char *outcome, double timeout_seconds);

#endif
