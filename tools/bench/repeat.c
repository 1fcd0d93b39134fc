/* SPDX-License-Identifier: MIT */
#include "repeat.h"

#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>

#define REPEAT_MAX 9

static double *at(const bench_times *c, int i) {
    return (double *)(void *)((char *)c->first + (size_t)i * c->stride);
}

/* The file: per column its record count, then its times (doubles, this
 * machine's layout: the file never leaves it). */
int bench_times_save(const char *path, const bench_times *t, int n) {
    FILE *f = fopen(path, "wb");
    int c, i, ok;
    if (!f) return -1;
    ok = 1;
    for (c = 0; c < n && ok; ++c) {
        ok = fwrite(&t[c].count, sizeof t[c].count, 1, f) == 1;
        for (i = 0; i < t[c].count && ok; ++i) ok = fwrite(at(&t[c], i), sizeof(double), 1, f) == 1;
    }
    return fclose(f) == 0 && ok ? 0 : -1;
}

/* Reads a child's columns into times (one after the other); 0 when its
 * column sizes match this process's. */
static int load_times(const char *path, const bench_times *t, int n, double *times) {
    FILE *f = fopen(path, "rb");
    int c, ok = f != NULL;
    for (c = 0; c < n && ok; ++c) {
        int count;
        ok = fread(&count, sizeof count, 1, f) == 1 && count == t[c].count &&
             fread(times, sizeof(double), (size_t)count, f) == (size_t)count;
        times += count;
    }
    if (f) fclose(f);
    return ok ? 0 : -1;
}

/* Median of the positive values among v[0..k-1] (reordered); 0 when none. */
static double median_measured(double *v, int k) {
    int i, j, m = 0;
    for (i = 0; i < k; ++i)
        if (v[i] > 0.0) v[m++] = v[i];
    for (i = 1; i < m; ++i)
        for (j = i; j > 0 && v[j - 1] > v[j]; --j) {
            double s = v[j];
            v[j] = v[j - 1];
            v[j - 1] = s;
        }
    if (m == 0) return 0.0;
    return m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]);
}

extern char **environ; /* POSIX: the environment the children inherit */

int bench_repeat(const bench_times *t, int n, int argc, char **argv, const char *dir, int k) {
    size_t total = 0, base;
    double *times[REPEAT_MAX];
    int used = 1, p, c, i;
    char **child_argv;
    static char path[1024];
    if (k > REPEAT_MAX) k = REPEAT_MAX;
    for (c = 0; c < n; ++c) total += (size_t)t[c].count;
    child_argv = calloc((size_t)argc + 3, sizeof *child_argv);
    if (!child_argv) abort();
    for (i = 0; i < argc; ++i) child_argv[i] = argv[i];
    snprintf(path, sizeof path, "%s/comparison-times.bin", dir);
    child_argv[argc] = "--child";
    child_argv[argc + 1] = path;
    for (p = 1; p < k; ++p) {
        pid_t pid;
        int status = 0;
        fprintf(stderr, "agjk-bench: the comparisons again in a fresh process (%d of %d)\n",
                p + 1, k);
        remove(path);
        if (posix_spawn(&pid, argv[0], NULL, NULL, child_argv, environ) != 0 ||
            waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            fprintf(stderr, "  that process failed; its times are left out\n");
            continue;
        }
        times[used] = malloc(sizeof(double) * (total + 1));
        if (!times[used]) abort();
        if (load_times(path, t, n, times[used]) != 0) {
            fprintf(stderr, "  its records differ from this process's; left out\n");
            free(times[used]);
            continue;
        }
        ++used;
    }
    remove(path);
    free(child_argv);
    /* This process's own time, then each record's median. */
    base = 0;
    for (c = 0; c < n; ++c) {
        for (i = 0; i < t[c].count; ++i) {
            double v[REPEAT_MAX];
            double *mine = at(&t[c], i);
            v[0] = *mine;
            for (p = 1; p < used; ++p) v[p] = times[p][base + (size_t)i];
            *mine = median_measured(v, used);
        }
        base += (size_t)t[c].count;
    }
    for (p = 1; p < used; ++p) free(times[p]);
    return used;
}
