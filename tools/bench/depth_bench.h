/* SPDX-License-Identifier: MIT */
/* Penetration depth side by side: agjk_signed_distance (certified EPA) against
 * libccd's ccdGJKPenetration (GJK + EPA) and ccdMPRPenetration, and Coal's
 * GJK + EPA when the build has Coal (coal_adapter.h), on the overlapping
 * problems of the benchmark, judged against a long double reference
 * (tests/common/ref_depth.h). libccd's EPA loop ignores max_iterations, so
 * every case runs under the watchdog of guard.h. */
#ifndef AGJK_BENCH_DEPTH_BENCH_H
#define AGJK_BENCH_DEPTH_BENCH_H

#include "problems.h"

enum {
    DB_AGJK = 0,      /* agjk_signed_distance, the benchmark's tolerance */
    DB_AGJK_1E4 = 1,  /* agjk_signed_distance asked for libccd's default accuracy: an
                         interval of width <= 1e-4 x scale (relative tolerance
                         2e-4 x scale / depth) */
    DB_CCD_EPA = 2,   /* ccdGJKPenetration, libccd's default epa_tolerance 1e-4 */
    DB_CCD_EPA_T = 3, /* ccdGJKPenetration, epa_tolerance tightened to agjk's accuracy */
    DB_CCD_MPR = 4,   /* ccdMPRPenetration, default mpr_tolerance */
    DB_COAL = 5,      /* Coal's GJK + EPA (coal::details::EPA), its narrowphase defaults:
                         EPA tolerance 1e-6, 64 iterations (when Coal is built in) */
    DB_COAL_T = 6,    /* the same, EPA tolerance matched to agjk's width, max_iterations */
    DB_COUNT = 7
};

typedef struct depth_bench_options {
    int reps;               /* timing repetitions (mean of the fastest 90%) */
    int max_iterations;
    double tolerance;       /* agjk's absolute tolerance at scale 1 (times scale^2) */
    double timeout_seconds; /* per case */
    const char *out_dir;    /* depth.md and depth.csv go there */
} depth_bench_options;

/* Runs every overlapping problem of `set`; writes out_dir/depth.md and
 * out_dir/depth.csv and prints the table on stderr. Returns the number of
 * agjk intervals that miss the reference (0 expected), or -1 on failure. */
int depth_bench_run(const bench_set *set, const depth_bench_options *o);

#endif
