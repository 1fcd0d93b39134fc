/* SPDX-License-Identifier: MIT */
/* Coherent motion: the same pair queried again and again along a smooth
 * trajectory, cold, with the hint and initial direction of agjk_options, and
 * with the warm-start cache of agjk/cache.h. */
#ifndef AGJK_BENCH_COHERENT_H
#define AGJK_BENCH_COHERENT_H

#include "bench.h"
#include "repeat.h"

/* Runs the coherent-motion benchmark on up to `pairs` pairs of each family of
 * `set` (starting from each pair's first pose at signed distance 1e-3 x scale),
 * `steps` poses per trajectory, timing `reps` passes over each trajectory. */
typedef struct bench_coherent bench_coherent;
bench_coherent *bench_coherent_run(const bench_config *cfg, const bench_set *set, int pairs,
                                   int steps, int reps);

/* Its times, one column per set x motion x mode, the rows its pairs (for
 * bench_repeat; at most BENCH_COHERENT_COLUMNS); returns their number. The
 * number of processes they became medians over goes into the report. */
#define BENCH_COHERENT_COLUMNS 18
int bench_coherent_times(bench_coherent *c, bench_times *out);
void bench_coherent_set_processes(bench_coherent *c, int processes);

/* Appends its table to cfg->out_dir/tables.md, writes coherent.csv there and
 * prints the table to stderr. Returns the number of contradictory verdicts
 * (separated vs intersecting) or distances outside the certified bounds. */
int bench_coherent_write(const bench_config *cfg, bench_coherent *c);
void bench_coherent_free(bench_coherent *c);

#endif
