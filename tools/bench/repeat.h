/* SPDX-License-Identifier: MIT */
/* Timed comparisons repeated in fresh processes (agjk-bench --processes).
 *
 * A process can start in a state where one library is slower throughout:
 * about one run in ten on the development machine, Coal then taking 2200 ns
 * instead of 1380 on close ellipsoids, which moved every cell of that run by
 * a third; libccd's one-support Boolean queries moved by 10-20% between
 * single-process runs of the same code. A forked child inherits its parent's
 * state, so the repetitions are fresh programs (posix_spawn of argv[0]).
 * Each record's times, the median over a few processes, are immune to one
 * slow process. */
#ifndef AGJK_BENCH_REPEAT_H
#define AGJK_BENCH_REPEAT_H

#include <stddef.h>

/* One column of times: record i's time (ns) at
 * *(double *)((char *)first + i * stride), count records. A time <= 0 means
 * "not measured" (a hung libccd case) and is left out of the median. */
typedef struct bench_times {
    double *first;
    int count;
    size_t stride;
} bench_times;

/* Writes the n columns to path (0, or -1 when it cannot): what a child
 * process hands back. */
int bench_times_save(const char *path, const bench_times *t, int n);

/* Runs argv[0] with argv[1..argc-1] and "--child FILE" k - 1 times, one after
 * the other (each child regenerates the same problems, runs the same
 * comparisons and saves the same columns), and replaces every time of the n
 * columns by the median over this process and the children whose column
 * sizes matched. Returns that number of processes (1 when none did). */
int bench_repeat(const bench_times *t, int n, int argc, char **argv, const char *dir, int k);

#endif
