/* SPDX-License-Identifier: MIT */
#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

bench_filter bench_filter_any(void) {
    bench_filter f;
    f.family = f.category = f.target_index = f.method = f.mode = f.tag = -1;
    f.near_band = 0;
    return f;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_median(double *v, int n) {
    if (n <= 0) return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static int matches(const bench_set *set, const bench_record *r, const bench_filter *f) {
    const bench_problem *p = &set->problems[r->problem];
    if (f->family >= 0 && p->family != f->family) return 0;
    if (f->category >= 0 && p->category != f->category) return 0;
    if (f->target_index >= 0 && p->target_index != f->target_index) return 0;
    if (f->method >= 0 && r->method != f->method) return 0;
    if (f->mode >= 0 && r->mode != f->mode) return 0;
    if (f->tag >= 0 && set->shapes[p->a].tag != f->tag) return 0;
    if (f->near_band && (p->target < -0.1 || p->target > 0.1)) return 0;
    return 1;
}

void bench_stats_compute(const bench_set *set, const bench_record *recs, int count,
                         const bench_filter *f, bench_stats *s) {
    double *ns = malloc((size_t)(count ? count : 1) * sizeof *ns);
    double *err = malloc((size_t)(count ? count : 1) * sizeof *err);
    double sit = 0, sit2 = 0, sus = 0, sus2 = 0, scalls = 0;
    int i, ne = 0;
    memset(s, 0, sizeof *s);
    if (!ns || !err) abort();
    for (i = 0; i < count; ++i) {
        const bench_record *r = &recs[i];
        double us;
        if (!matches(set, r, f)) continue;
        us = r->run.time_ns * 1e-3;
        ns[s->n] = r->run.time_ns;
        s->n++;
        sit += r->run.iterations;
        sit2 += (double)r->run.iterations * r->run.iterations;
        scalls += r->run.support_calls;
        sus += us;
        sus2 += us * us;
        s->violations += r->violation;
        s->wrong += r->wrong;
        s->not_converged += !r->converged;
        if (r->judged) {
            s->judged++;
            if (r->mode == BENCH_DISTANCE) err[ne++] = r->error;
        }
    }
    if (s->n > 0) {
        s->it_mean = sit / s->n;
        s->it_std = sqrt(fmax(0.0, sit2 / s->n - s->it_mean * s->it_mean));
        s->calls_mean = scalls / s->n;
        s->us_mean = sus / s->n;
        s->us_std = sqrt(fmax(0.0, sus2 / s->n - s->us_mean * s->us_mean));
        s->ns_median = bench_median(ns, s->n);
    }
    s->err_median = ne ? bench_median(err, ne) : NAN;
    s->err_max = 0;
    for (i = 0; i < ne; ++i) s->err_max = fmax(s->err_max, err[i]);
    if (!ne) s->err_max = NAN;
    free(ns);
    free(err);
}
