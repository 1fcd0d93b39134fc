/* SPDX-License-Identifier: MIT */
/* agjk against Coal on a stress set: the comparison of coal_bench.h (same
 * methods, tolerance, cap, clock; agjk timed right before Coal) on problems
 * outside the paper's comfortable range, each judged by the certified
 * reference:
 *   stiff ellipsoids   needles (two radii x 1e-3) and pancakes (one x 1e-3)
 *   flat boxes         one half extent x 1e-4, or exactly 0 (plates)
 *   tiny, huge         the protocol's ellipsoids and boxes at scale 1e-4, 1e4
 *                      (tolerance x scale^2: the same relative accuracy)
 *   far                the protocol's ellipsoids and boxes, both poses moved
 *                      1e4 ... 1e6 (log-uniform, random direction) from the origin
 *   nearly touching    the protocol's ellipsoids and boxes at signed distances
 *                      -1e-6, -1e-9 (overlapping), 1e-9, 1e-6 (close)
 * The others use the protocol's 12 signed distances (times the scale). */
#ifndef AGJK_BENCH_STRESS_H
#define AGJK_BENCH_STRESS_H

#include "bench.h"

typedef struct bench_stress bench_stress;

/* Generates the stress set (cfg->stress_pairs pairs x cfg->stress_poses poses
 * per family) and runs it through both libraries (R = cfg->coal_reps). NULL
 * when Coal is not built in, cfg->coal_reps <= 0 or cfg->stress_pairs <= 0. */
bench_stress *bench_stress_run(const bench_config *cfg);

/* Appends the section "agjk vs Coal on a stress set" to <out>/tables.md (or
 * why it was not measured), writes <out>/stress.csv, prints the ratio table
 * and the summary on stdout. Returns 0 or -1. */
int bench_stress_write(const bench_config *cfg, const bench_stress *s);

/* The Coal comparisons of the stress set's families (repeated: repeat.h), up
 * to cap of them; returns their number. */
struct coal_bench_data;
int bench_stress_coal_data(bench_stress *s, struct coal_bench_data **out, int cap);

void bench_stress_free(bench_stress *s);

#endif
