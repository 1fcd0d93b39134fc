/* SPDX-License-Identifier: MIT */
/* Support calls per distance query: the adaptive method (AGJK_METHOD_ADAPTIVE,
 * the default) against GJK, Nesterov, normalised Nesterov and Polyak on every
 * family and distance category of the benchmark, and against Coal's best
 * variant on the same problems when Coal ran (coal_bench.c). A support call
 * is one call of the Minkowski support (both shapes' callbacks), including
 * the extra one that Alg. 6 makes when momentum stops; Coal's are counted the
 * same way, through a wrapper of its support function. */
#include "bench.h"
#include "coal_bench.h"

static const int methods[4] = {BM_GJK, BM_NESTEROV, BM_NESTEROV_NORMALIZED, BM_POLYAK};
static const char *const coal_names[4] = {"GJK", "Nesterov", "Nest.-norm.", "Polyak"};

/* Coal's mean support calls per method in one family and category; returns
 * the index of the best method, or -1 when Coal did not run there. */
static int coal_best(const bench_report *r, const coal_bench_data *d, int fam, int c,
                     double *best) {
    double sum[4] = {0, 0, 0, 0};
    int n[4] = {0, 0, 0, 0}, i, m, arg = -1;
    for (i = 0; d && i < d->count; ++i) {
        const bench_record *cr = &d->recs[i].coal;
        const bench_problem *p = &r->set->problems[cr->problem];
        if (cr->mode != BENCH_DISTANCE || p->family != fam || p->category != c) continue;
        for (m = 0; m < 4; ++m)
            if (cr->method == methods[m]) {
                sum[m] += cr->run.support_calls;
                n[m]++;
            }
    }
    for (m = 0; m < 4; ++m)
        if (n[m] > 0 && (arg < 0 || sum[m] / n[m] < *best)) {
            *best = sum[m] / n[m];
            arg = m;
        }
    return arg;
}

void bench_table_support_calls(FILE *f, const bench_report *r, const coal_bench_data *coal) {
    int fam, c, m, rows = 0, worse = 0, worse_than_gjk = 0, coal_rows = 0, worse_than_coal = 0;
    fprintf(f, "\n## Support calls per distance query (mean): the adaptive method\n\n"
               "| set | category | GJK | Nesterov | Nesterov-normalized | Polyak | best of "
               "the four | Coal's best | Adaptive |\n|---|---|---|---|---|---|---|---|---|\n");
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (c = BENCH_CATEGORY_COUNT - 1; c >= 0; --c) {
            double v[4], best = 0, gjk = 0, ad, cb = 0;
            int cm;
            bench_filter flt = bench_filter_any();
            bench_stats s;
            flt.family = fam;
            flt.category = c;
            flt.mode = BENCH_DISTANCE;
            flt.method = BM_ADAPTIVE;
            bench_stats_compute(r->set, r->recs, r->rec_count, &flt, &s);
            if (s.n == 0) continue;
            ad = s.calls_mean;
            fprintf(f, "| %s | %s |", bench_family_name(fam), bench_category_name(c));
            for (m = 0; m < 4; ++m) {
                flt.method = methods[m];
                bench_stats_compute(r->set, r->recs, r->rec_count, &flt, &s);
                v[m] = s.calls_mean;
                if (m == 0 || v[m] < best) best = v[m];
                if (m == 0) gjk = v[m];
                fprintf(f, " %.2f |", v[m]);
            }
            cm = coal_best(r, coal, fam, c, &cb);
            if (cm >= 0)
                fprintf(f, " %.2f | %.2f (%s) | **%.2f** |\n", best, cb, coal_names[cm], ad);
            else
                fprintf(f, " %.2f | - | **%.2f** |\n", best, ad);
            ++rows;
            worse += ad > best;
            worse_than_gjk += ad > gjk;
            coal_rows += cm >= 0;
            worse_than_coal += cm >= 0 && ad > cb;
        }
    fprintf(f, "\nAdaptive above the best of the four in %d of %d rows, above GJK in %d",
            worse, rows, worse_than_gjk);
    if (coal_rows > 0)
        fprintf(f, ", above Coal's best in %d of %d.\n", worse_than_coal, coal_rows);
    else
        fprintf(f, " (Coal did not run: no Coal column).\n");
}
