/* SPDX-License-Identifier: MIT */
/* Support calls per distance query: the adaptive method (AGJK_METHOD_ADAPTIVE,
 * the default) against GJK, Nesterov, normalised Nesterov and Polyak on every
 * family and distance category of the benchmark. A support call is one call
 * of the Minkowski support (both shapes' callbacks), including the extra one
 * that Alg. 6 makes when momentum stops. */
#include "bench.h"

void bench_table_support_calls(FILE *f, const bench_report *r) {
    static const int methods[4] = {BM_GJK, BM_NESTEROV, BM_NESTEROV_NORMALIZED, BM_POLYAK};
    int fam, c, m, rows = 0, worse = 0, worse_than_gjk = 0;
    fprintf(f, "\n## Support calls per distance query (mean): the adaptive method\n\n"
               "| set | category | GJK | Nesterov | Nesterov-normalized | Polyak | best of "
               "the four | Adaptive |\n|---|---|---|---|---|---|---|---|\n");
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (c = BENCH_CATEGORY_COUNT - 1; c >= 0; --c) {
            double v[4], best = 0, gjk = 0, ad;
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
            fprintf(f, " %.2f | **%.2f** |\n", best, ad);
            ++rows;
            worse += ad > best;
            worse_than_gjk += ad > gjk;
        }
    fprintf(f, "\nAdaptive above the best of the four in %d of %d rows, above GJK in %d.\n",
            worse, rows, worse_than_gjk);
}
