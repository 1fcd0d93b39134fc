/* SPDX-License-Identifier: MIT */
/* agjk-bench: configuration and the report writers shared by its phases. */
#ifndef AGJK_BENCH_BENCH_H
#define AGJK_BENCH_BENCH_H

#include <stdint.h>
#include <stdio.h>

#include "ccd_bench.h"
#include "stats.h"

#define WP_TOL_COUNT 11 /* tolerances 1e-2 ... 1e-12 */

typedef struct bench_config {
    uint64_t seed;
    int pairs, poses;          /* ellipsoids; the other families scale from these */
    int box_pairs, hull_pairs, hull_poses, mesh_pairs, mesh_poses, max_meshes;
    int reps, slow_reps, slow_pairs, slow_max_iterations, max_iterations;
    int wp_pairs, wp_reps, ccd_reps;
    int coal_reps;             /* agjk vs Coal (coal_bench.h); 0 disables it */
    int processes;             /* timed comparisons run in this many processes (repeat.h) */
    const char *child;         /* this process is one of them: save the times here */
    int stress_pairs, stress_poses; /* agjk vs Coal on the stress set (stress.h); 0: off */
    int depth_reps;            /* penetration-depth comparison (depth_bench.h); 0 disables */
    int coherent_pairs, coherent_steps, coherent_reps; /* coherent.c; pairs 0: off */
    double tolerance, mesh_scale, nesmino_mu;
    int quick, no_ccd, no_wp, relative, scan_support;
    const char *out_dir, *mesh_dir, *raw_path, *command_line;
} bench_config;

/* Work-precision point: a method's median error and median time at one tolerance. */
typedef struct wp_point {
    int n, not_converged;
    double err_median, ns_median, it_mean;
} wp_point;

typedef struct bench_report {
    const bench_config *cfg;
    const bench_set *set;
    const bench_record *recs;
    int rec_count;
    wp_point wp[2][BM_COUNT][WP_TOL_COUNT]; /* [ellipsoids, boxes] */
    int wp_problems[2];
    const ccd_bench_record *ccd;
    const unsigned char *ccd_outcome;
    int ccd_count;             /* 0: no libccd part */
    int ccd_processes;         /* its times are medians over this many processes */
    double seconds[6];         /* phase wall times */
    double clock_overhead_ns;  /* cost of an empty timed region (included in all times) */
    const char *mesh_note;
} bench_report;

extern const double wp_tolerances[WP_TOL_COUNT];

/* Writes summary.csv, work-precision.csv/.gp, libccd.csv, iterations.csv/.gp
 * and tables.md into cfg->out_dir. Returns 0 or -1. */
int bench_write_reports(const bench_report *r);

/* Support calls per distance query, mean, per family and category: the four
 * methods of the paper, their best, Coal's best (coal: NULL when Coal did not
 * run) and the adaptive method (calls.c). */
struct coal_bench_data;
void bench_table_support_calls(FILE *f, const bench_report *r, const struct coal_bench_data *coal);

#endif
