/* SPDX-License-Identifier: MIT */
/* Report writers: paper-style Markdown tables, CSV, gnuplot scripts. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "guard.h"

static FILE *open_out(const bench_config *c, const char *name) {
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", c->out_dir, name);
    f = fopen(path, "w");
    if (!f) perror(path);
    return f;
}

#define FAST_COUNT 5
static const int fast_methods[FAST_COUNT] = {BM_GJK, BM_NESTEROV, BM_NESTEROV_NORMALIZED,
                                             BM_POLYAK, BM_ADAPTIVE};

static bench_stats stats_of(const bench_report *r, int family, int category, int target,
                            int method, int mode, int tag, int near) {
    bench_filter f = bench_filter_any();
    bench_stats s;
    f.family = family;
    f.category = category;
    f.target_index = target;
    f.method = method;
    f.mode = mode;
    f.tag = tag;
    f.near_band = near;
    bench_stats_compute(r->set, r->recs, r->rec_count, &f, &s);
    return s;
}

/* "a +- b" with a precision fit for the magnitude (paper style: 7 +- 2, 14.3k). */
static void pm(FILE *f, double mean, double std, int n) {
    if (n == 0) { fprintf(f, " - |"); return; }
    if (mean >= 1e4) fprintf(f, " %.1fk +- %.1fk |", mean / 1e3, std / 1e3);
    else if (mean >= 10) fprintf(f, " %.0f +- %.0f |", mean, std);
    else fprintf(f, " %.2g +- %.2g |", mean, std);
}

static int family_present(const bench_report *r, int family) {
    int i;
    for (i = 0; i < r->set->problem_count; ++i)
        if (r->set->problems[i].family == family) return 1;
    return 0;
}

/* Paper Table II: rows = distance category, columns = methods. */
static void table_methods(FILE *f, const bench_report *r, int family, int mode, int what) {
    int c, m;
    fprintf(f, "| %s, %s | ", mode ? "Boolean" : "distance", what == 0 ? "iterations" : "us");
    for (m = 0; m < BM_COUNT; ++m) fprintf(f, "%s | ", bench_method_name(m));
    fprintf(f, "\n|---|");
    for (m = 0; m < BM_COUNT; ++m) fprintf(f, "---|");
    fprintf(f, "\n");
    for (c = 0; c < BENCH_CATEGORY_COUNT; ++c) {
        fprintf(f, "| %s |", bench_category_name(c));
        for (m = 0; m < BM_COUNT; ++m) {
            bench_stats s = stats_of(r, family, c, -1, m, mode, -1, 0);
            if (what == 0) pm(f, s.it_mean, s.it_std, s.n);
            else pm(f, s.us_mean, s.us_std, s.n);
        }
        fprintf(f, "\n");
    }
    fprintf(f, "\n");
}

static void table_headline(FILE *f, const bench_report *r, int family) {
    int c, m, mode;
    fprintf(f, "| mode | category |");
    for (m = 0; m < FAST_COUNT; ++m) fprintf(f, " %s |", bench_method_name(fast_methods[m]));
    fprintf(f, "\n|---|---|");
    for (m = 0; m < FAST_COUNT; ++m) fprintf(f, "---|");
    fprintf(f, "\n");
    for (mode = 0; mode < 2; ++mode)
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c) {
            fprintf(f, "| %s | %s |", mode ? "Boolean" : "distance", bench_category_name(c));
            for (m = 0; m < FAST_COUNT; ++m) {
                bench_stats s = stats_of(r, family, c, -1, fast_methods[m], mode, -1, 0);
                fprintf(f, " %.0f |", s.ns_median);
            }
            fprintf(f, "\n");
        }
    fprintf(f, "\n");
}

/* Paper Table I: hulls by vertex count N, -0.1 <= d <= 0.1, microseconds. */
static void table_hulls(FILE *f, const bench_report *r) {
    static const int sizes[4] = {33, 141, 626, 2500};
    int h, m, mode;
    fprintf(f, "| N | mode |");
    for (m = 0; m < FAST_COUNT; ++m) fprintf(f, " %s us | it |", bench_method_name(fast_methods[m]));
    fprintf(f, "\n|---|---|");
    for (m = 0; m < FAST_COUNT; ++m) fprintf(f, "---|---|");
    fprintf(f, "\n");
    for (h = 0; h < 4; ++h)
        for (mode = 0; mode < 2; ++mode) {
            fprintf(f, "| %d | %s |", sizes[h], mode ? "Boolean" : "distance");
            for (m = 0; m < FAST_COUNT; ++m) {
                bench_stats s = stats_of(r, BENCH_HULLS, -1, -1, fast_methods[m], mode,
                                         sizes[h], 1);
                pm(f, s.us_mean, s.us_std, s.n);
                pm(f, s.it_mean, s.it_std, s.n);
            }
            fprintf(f, "\n");
        }
    fprintf(f, "\n");
}

static const bench_record *find(const bench_report *r, int problem, int method, int mode,
                                const int *index) {
    int k = index[(problem * BM_COUNT + method) * 2 + mode];
    return k >= 0 ? &r->recs[k] : NULL;
}

/* Ratio GJK / accelerated on the same problem (paper Fig. 8): > 1 is a speed-up. */
static void table_ratios(FILE *f, FILE *csv, const bench_report *r, const int *index) {
    int fam, c, mode, a, i;
    static const int accel[2] = {BM_NESTEROV, BM_NESTEROV_NORMALIZED};
    fprintf(f, "| family | mode | category | accelerated | n | iterations ratio mean +- std "
               "(median) | time ratio mean +- std (median) |\n|---|---|---|---|---|---|---|\n");
    fprintf(csv, "family,mode,category,accelerated,n,it_ratio_mean,it_ratio_std,it_ratio_median,"
                 "time_ratio_mean,time_ratio_std,time_ratio_median\n");
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam) {
        if (!family_present(r, fam)) continue;
        for (mode = 0; mode < 2; ++mode)
            for (c = 0; c < BENCH_CATEGORY_COUNT; ++c)
                for (a = 0; a < 2; ++a) {
                    int n = 0;
                    double si = 0, si2 = 0, st = 0, st2 = 0, mi, mt, sdi, sdt, medi, medt;
                    double *vi = malloc((size_t)r->set->problem_count * sizeof *vi + 8);
                    double *vt = malloc((size_t)r->set->problem_count * sizeof *vt + 8);
                    if (!vi || !vt) abort();
                    for (i = 0; i < r->set->problem_count; ++i) {
                        const bench_problem *p = &r->set->problems[i];
                        const bench_record *g, *x;
                        double ri, rt;
                        if (p->family != fam || p->category != c) continue;
                        g = find(r, i, BM_GJK, mode, index);
                        x = find(r, i, accel[a], mode, index);
                        if (!g || !x || x->run.iterations <= 0 || x->run.time_ns <= 0) continue;
                        ri = (double)g->run.iterations / x->run.iterations;
                        rt = g->run.time_ns / x->run.time_ns;
                        vi[n] = ri;
                        vt[n] = rt;
                        si += ri; si2 += ri * ri; st += rt; st2 += rt * rt;
                        ++n;
                    }
                    mi = n ? si / n : 0; mt = n ? st / n : 0;
                    sdi = n ? sqrt(fmax(0, si2 / n - mi * mi)) : 0;
                    sdt = n ? sqrt(fmax(0, st2 / n - mt * mt)) : 0;
                    medi = bench_median(vi, n);
                    medt = bench_median(vt, n);
                    fprintf(f, "| %s | %s | %s | %s | %d | %.2f +- %.2f (%.2f) | %.2f +- %.2f "
                               "(%.2f) |\n", bench_family_name(fam), mode ? "Boolean" : "distance",
                            bench_category_name(c), bench_method_name(accel[a]), n, mi, sdi,
                            medi, mt, sdt, medt);
                    fprintf(csv, "%s,%s,%s,%s,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n",
                            bench_family_name(fam), mode ? "boolean" : "distance",
                            bench_category_name(c), bench_method_name(accel[a]), n, mi, sdi,
                            medi, mt, sdt, medt);
                    free(vi);
                    free(vt);
                }
    }
    fprintf(f, "\n");
}

static void table_accuracy(FILE *f, const bench_report *r) {
    int fam, m, mode;
    fprintf(f, "| family | method | mode | results | judged | median \\|d - d_ref\\| | "
               "max \\|d - d_ref\\| | outside certified bound | wrong verdicts | "
               "not converged |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (m = 0; m < BM_COUNT; ++m)
            for (mode = 0; mode < 2; ++mode) {
                bench_stats s = stats_of(r, fam, -1, -1, m, mode, -1, 0);
                if (s.n == 0) continue;
                if (mode == BENCH_DISTANCE)
                    fprintf(f, "| %s | %s | distance | %d | %d | %.2e | %.2e | %d%s | %d | %d |\n",
                            bench_family_name(fam), bench_method_name(m), s.n, s.judged,
                            s.err_median, s.err_max, s.violations,
                            m == BM_NESMINO ? " (no bound)" : "", s.wrong, s.not_converged);
                else
                    fprintf(f, "| %s | %s | Boolean | %d | %d | - | - | - | %d | %d |\n",
                            bench_family_name(fam), bench_method_name(m), s.n, s.judged, s.wrong,
                            s.not_converged);
            }
    fprintf(f, "\n");
}

static void write_summary_csv(const bench_report *r) {
    FILE *f = open_out(r->cfg, "summary.csv");
    int fam, t, m, mode;
    if (!f) return;
    fprintf(f, "family,target,category,method,mode,n,iterations_mean,iterations_std,"
               "support_calls_mean,us_mean,us_std,ns_median,error_median,error_max,judged,"
               "outside_bound,wrong_verdicts,not_converged\n");
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (t = -1; t < BENCH_TARGET_COUNT; ++t)
            for (m = 0; m < BM_COUNT; ++m)
                for (mode = 0; mode < 2; ++mode) {
                    /* t == -1: one row per category, else one per signed distance. */
                    int c, c0 = 0, c1 = t < 0 ? BENCH_CATEGORY_COUNT : 1;
                    for (c = c0; c < c1; ++c) {
                        bench_stats s = stats_of(r, fam, t < 0 ? c : -1, t, m, mode, -1, 0);
                        char target[32] = "all";
                        if (s.n == 0) continue;
                        if (t >= 0) snprintf(target, sizeof target, "%g", bench_targets[t]);
                        fprintf(f, "%s,%s,%s,%s,%s,%d,%.3f,%.3f,%.3f,%.4f,%.4f,%.1f,%.3e,%.3e,"
                                   "%d,%d,%d,%d\n",
                                bench_family_name(fam),
                                target,
                                bench_category_name(t < 0 ? c : bench_target_category(t)),
                                bench_method_name(m), mode ? "boolean" : "distance", s.n,
                                s.it_mean, s.it_std, s.calls_mean, s.us_mean, s.us_std,
                                s.ns_median, s.err_median, s.err_max, s.judged, s.violations,
                                s.wrong, s.not_converged);
                    }
                }
    fclose(f);
}

/* Iterations against signed distance for ellipsoids (paper Fig. 3). */
static void write_iterations(const bench_report *r) {
    FILE *f = open_out(r->cfg, "iterations.dat"), *g;
    int mode, m, t;
    static const int methods[2] = {BM_GJK, BM_NESTEROV};
    if (!f) return;
    fprintf(f, "# ellipsoids: signed distance, mean iterations, std (blocks: distance GJK, "
               "distance Nesterov, Boolean GJK, Boolean Nesterov)\n");
    for (mode = 0; mode < 2; ++mode)
        for (m = 0; m < 2; ++m) {
            fprintf(f, "# %s %s\n", mode ? "boolean" : "distance", bench_method_name(methods[m]));
            for (t = 0; t < BENCH_TARGET_COUNT; ++t) {
                bench_stats s = stats_of(r, BENCH_ELLIPSOIDS, -1, t, methods[m], mode, -1, 0);
                fprintf(f, "%d %g %.3f %.3f\n", t, bench_targets[t], s.it_mean, s.it_std);
            }
            fprintf(f, "\n\n");
        }
    fclose(f);
    g = open_out(r->cfg, "iterations.gp");
    if (!g) return;
    fprintf(g,
        "# gnuplot script written by agjk-bench (run from the output directory)\n"
        "set terminal pngcairo size 1100,420 font ',10'\n"
        "set output 'iterations.png'\n"
        "set multiplot layout 1,2 title 'Ellipsoids: iterations vs signed distance (mean, "
        "bars = std)'\n"
        "set xtics ('-0.1' 0, '-1e-2' 1, '-1e-3' 2, '-1e-4' 3, '1e-4' 4, '1e-3' 5, '1e-2' 6, "
        "'0.1' 7, '0.5' 8, '1' 9, '2.5' 10, '5' 11) rotate by -45\n"
        "set ylabel 'iterations'; set grid; set key top left\n"
        "set title 'distance'\n"
        "plot 'iterations.dat' index 0 using 1:3:4 with yerrorlines title 'GJK', "
        "'' index 1 using 1:3:4 with yerrorlines title 'Nesterov'\n"
        "set title 'Boolean'\n"
        "plot 'iterations.dat' index 2 using 1:3:4 with yerrorlines title 'GJK', "
        "'' index 3 using 1:3:4 with yerrorlines title 'Nesterov'\n"
        "unset multiplot\n");
    fclose(g);
}

static void write_work_precision(const bench_report *r, FILE *md) {
    FILE *csv = open_out(r->cfg, "work-precision.csv"), *dat = open_out(r->cfg,
                                                                         "work-precision.dat");
    FILE *gp = open_out(r->cfg, "work-precision.gp");
    int fam, m, t;
    if (!csv || !dat || !gp) {
        if (csv) fclose(csv);
        if (dat) fclose(dat);
        if (gp) fclose(gp);
        return;
    }
    fprintf(csv, "family,method,tolerance,problems,not_converged,median_error,median_ns,"
                 "mean_iterations\n");
    for (fam = 0; fam < 2; ++fam)
        for (m = 0; m < BM_COUNT; ++m) {
            fprintf(dat, "# %s %s: tolerance, median time (us), median error (floored at "
                         "1e-17 for the log scale)\n", bench_family_name(fam), bench_method_name(m));
            for (t = 0; t < WP_TOL_COUNT; ++t) {
                const wp_point *w = &r->wp[fam][m][t];
                if (w->n == 0) continue;
                fprintf(csv, "%s,%s,%g,%d,%d,%.3e,%.1f,%.2f\n", bench_family_name(fam),
                        bench_method_name(m), wp_tolerances[t], w->n, w->not_converged,
                        w->err_median, w->ns_median, w->it_mean);
                fprintf(dat, "%g %.5g %.5g\n", wp_tolerances[t], w->ns_median * 1e-3,
                        fmax(w->err_median, 1e-17));
            }
            fprintf(dat, "\n\n");
        }
    fprintf(gp,
        "# gnuplot script written by agjk-bench (run from the output directory)\n"
        "set terminal pngcairo size 1100,450 font ',10'\n"
        "set output 'work-precision.png'\n"
        "set multiplot layout 1,2 title 'Work-precision: median |d - d_{ref}| vs median time, "
        "tolerance 1e-2 ... 1e-12 (error 0 drawn at 1e-17)'\n"
        "set logscale xy; set grid; set format y '10^{%%L}'\n"
        "set xlabel 'median time per query (us)'; set ylabel 'median error'\n"
        "set key top right font ',8'\n");
    for (fam = 0; fam < 2; ++fam) {
        fprintf(gp, "set title '%s'\nplot ", bench_family_name(fam));
        for (m = 0; m < BM_COUNT; ++m)
            fprintf(gp, "%s'work-precision.dat' index %d using 2:3 with linespoints title '%s'",
                    m ? ", " : "", fam * BM_COUNT + m, bench_method_name(m));
        fprintf(gp, "\n");
    }
    fprintf(gp, "unset multiplot\n");
    fclose(csv);
    fclose(dat);
    fclose(gp);

    fprintf(md, "Median |d - d_ref| / median time in us, first pose of %d pairs per family "
                "(all 12 signed distances); NESMINO stops on its own duality gap here.\n\n",
            r->cfg->wp_pairs);
    for (fam = 0; fam < 2; ++fam) {
        fprintf(md, "**%s**\n\n| tolerance |", bench_family_name(fam));
        for (m = 0; m < BM_COUNT; ++m) fprintf(md, " %s |", bench_method_name(m));
        fprintf(md, "\n|---|");
        for (m = 0; m < BM_COUNT; ++m) fprintf(md, "---|");
        fprintf(md, "\n");
        for (t = 0; t < WP_TOL_COUNT; ++t) {
            fprintf(md, "| %g |", wp_tolerances[t]);
            for (m = 0; m < BM_COUNT; ++m) {
                const wp_point *w = &r->wp[fam][m][t];
                if (w->n == 0) fprintf(md, " - |");
                else fprintf(md, " %.1e / %.2f%s |", w->err_median, w->ns_median * 1e-3,
                             w->not_converged ? "*" : "");
            }
            fprintf(md, "\n");
        }
        fprintf(md, "\n");
    }
    fprintf(md, "`*`: some runs hit the iteration cap.\n\n");
}

/* libccd: answers against the certified reference, and time ratios. */
static void write_ccd(const bench_report *r, FILE *md) {
    FILE *csv = open_out(r->cfg, "libccd.csv");
    int fam, c, col, i;
    if (!csv) return;
    fprintf(csv, "family,category,cases,guard_failures,");
    for (col = 0; col < CB_COUNT; ++col)
        fprintf(csv, "ns_median_%d,wrong_%d,no_verdict_%d,", col, col, col);
    fprintf(csv, "ratio_agjk_accel_over_ccd_gjk,ratio_agjk_accel_over_ccd_mpr,"
                 "ratio_agjk_gjk_over_ccd_gjk\n");
    fprintf(md, "| family | category | cases | agjk GJK ns | agjk accel. ns | libccd GJK ns | "
                "libccd MPR ns | agjk accel./libccd GJK | agjk accel./libccd MPR | wrong: agjk "
                "GJK / accel. / ccd GJK / ccd MPR | hung |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c) {
            int n = 0, bad = 0, wrong[CB_COUNT] = {0}, nov[CB_COUNT] = {0}, nr = 0;
            double *t[CB_COUNT], *ra = malloc(sizeof(double) * (size_t)r->ccd_count + 8);
            double *rm = malloc(sizeof(double) * (size_t)r->ccd_count + 8);
            double *rg = malloc(sizeof(double) * (size_t)r->ccd_count + 8);
            double med[CB_COUNT], mra, mrm, mrg;
            for (col = 0; col < CB_COUNT; ++col)
                t[col] = malloc(sizeof(double) * (size_t)r->ccd_count + 8);
            for (i = 0; i < r->ccd_count; ++i) {
                const bench_problem *p = &r->set->problems[i];
                const ccd_bench_record *k = &r->ccd[i];
                if (p->family != fam || p->category != c) continue;
                if (r->ccd_outcome[i] != GUARD_OK) { ++bad; continue; }
                for (col = 0; col < CB_COUNT; ++col) {
                    t[col][n] = k->time_ns[col];
                    if (k->answer[col] < 0) nov[col]++;
                    else if (p->ref_ok && ((k->answer[col] == 1 && p->ref.lower > 1e-12 &&
                                            !p->ref.intersecting) ||
                                           (k->answer[col] == 0 && p->ref.intersecting)))
                        wrong[col]++;
                }
                if (k->time_ns[CB_CCD_GJK] > 0 && k->time_ns[CB_CCD_MPR] > 0) {
                    ra[nr] = k->time_ns[CB_AGJK_ACCEL] / k->time_ns[CB_CCD_GJK];
                    rm[nr] = k->time_ns[CB_AGJK_ACCEL] / k->time_ns[CB_CCD_MPR];
                    rg[nr] = k->time_ns[CB_AGJK_GJK] / k->time_ns[CB_CCD_GJK];
                    ++nr;
                }
                ++n;
            }
            if (n + bad > 0) {
                for (col = 0; col < CB_COUNT; ++col) med[col] = bench_median(t[col], n);
                mra = bench_median(ra, nr);
                mrm = bench_median(rm, nr);
                mrg = bench_median(rg, nr);
                fprintf(md, "| %s | %s | %d | %.0f | %.0f | %.0f | %.0f | %.2f | %.2f | %d / %d / "
                            "%d / %d | %d |\n", bench_family_name(fam), bench_category_name(c),
                        n, med[0], med[1], med[2], med[3], mra, mrm, wrong[0], wrong[1],
                        wrong[2], wrong[3], bad);
                fprintf(csv, "%s,%s,%d,%d,", bench_family_name(fam), bench_category_name(c), n,
                        bad);
                for (col = 0; col < CB_COUNT; ++col)
                    fprintf(csv, "%.1f,%d,%d,", med[col], wrong[col], nov[col]);
                fprintf(csv, "%.4f,%.4f,%.4f\n", mra, mrm, mrg);
            }
            for (col = 0; col < CB_COUNT; ++col) free(t[col]);
            free(ra);
            free(rm);
            free(rg);
        }
    fprintf(md, "\nTimes: median over problems of the per-problem mean of the fastest 90%% of "
                "R = %d runs (each library's R runs of a problem in a row), the whole "
                "comparison run in %d process%s, each problem's times the median over them "
                "(see tools/bench/repeat.h); ratios: median of per-problem ratios (< 1: agjk "
                "faster). \"wrong\": a verdict the certified reference refutes (agjk's "
                "contact-within-tolerance answers are not verdicts and are not counted).\n\n",
            r->cfg->ccd_reps, r->ccd_processes, r->ccd_processes == 1 ? "" : "es");
    fclose(csv);
}

int bench_write_reports(const bench_report *r) {
    FILE *md = open_out(r->cfg, "tables.md");
    int *index, i, fam, mode;
    time_t now = time(NULL);
    char date[64];
    if (!md) return -1;
    index = malloc(sizeof(int) * (size_t)r->set->problem_count * BM_COUNT * 2 + 8);
    if (!index) abort();
    for (i = 0; i < r->set->problem_count * BM_COUNT * 2; ++i) index[i] = -1;
    for (i = 0; i < r->rec_count; ++i)
        index[(r->recs[i].problem * BM_COUNT + r->recs[i].method) * 2 + r->recs[i].mode] = i;
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));

    fprintf(md, "# agjk benchmark results\n\n"
                "Made by `%s` (agjk %s, %s). Seed %llu. %d problems: ellipsoids %d pairs x %d "
                "poses, boxes %d x %d, hulls %d x %d per N in {33, 141, 626, 2500}%s%s, each at "
                "the 12 signed distances of the paper. Tolerance %g (%s, on the duality "
                "gap), at most %d iterations (FW, NESMINO: %d). Times: per problem, the mean of "
                "the fastest 90%% of R = %d runs (FW, NESMINO: R = %d, on the first pose of the "
                "first %d pairs); tables give mean +- std over problems. The machine is shared: "
                "compare methods within this run, not with other runs. Each run is timed alone; "
                "an empty timed region costs %.0f ns, included in every time. Polytope support: "
                "%s. "
                "Phase times: "
                "problems+reference %.0f s, queries %.0f s, work-precision %.0f s, libccd "
                "%.0f s; total %.0f s.\n\n",
            r->cfg->command_line, agjk_version_string(), date,
            (unsigned long long)r->cfg->seed, r->set->problem_count, r->cfg->pairs,
            r->cfg->poses, r->cfg->box_pairs, r->cfg->poses, r->cfg->hull_pairs,
            r->cfg->hull_poses, r->mesh_note[0] ? "; meshes: " : "", r->mesh_note,
            r->cfg->tolerance, r->cfg->relative ? "relative: g <= tol ||x||^2" : "absolute",
            r->cfg->max_iterations, r->cfg->slow_max_iterations,
            r->cfg->reps, r->cfg->slow_reps, r->cfg->slow_pairs, r->clock_overhead_ns,
            r->cfg->scan_support ? "scan over all vertices"
                                 : "hill climbing on the Qhull hull's vertex graph (agjk "
                                   "scans small hulls itself)",
            r->seconds[0], r->seconds[1],
            r->seconds[2], r->seconds[3], r->seconds[4]);

    {
        int ok = 0;
        for (i = 0; i < r->set->problem_count; ++i) ok += r->set->problems[i].ref_ok;
        fprintf(md, "Reference (tests/common, long double, certified by its own duality gap): "
                    "%d problems judged, of which %d where it stalled with certified bounds "
                    "within 1e-9 of each other; %d excluded (no usable reference).\n\n",
                ok, r->set->ref_stalled, r->set->problem_count - ok);
    }
    fprintf(md, "## Headline: median ns per query, ellipsoids\n\n");
    table_headline(md, r, BENCH_ELLIPSOIDS);
    fprintf(md, "## Headline: median ns per query, boxes\n\n");
    table_headline(md, r, BENCH_BOXES);

    for (fam = 0; fam < 2; ++fam)
        for (mode = 0; mode < 2; ++mode) {
            fprintf(md, "## %s, %s: iterations (mean +- std) [paper Table II]\n\n",
                    bench_family_name(fam), mode ? "Boolean" : "distance");
            table_methods(md, r, fam, mode, 0);
            fprintf(md, "## %s, %s: microseconds (mean +- std)\n\n", bench_family_name(fam),
                    mode ? "Boolean" : "distance");
            table_methods(md, r, fam, mode, 1);
        }
    fprintf(md, "## Hulls of N random points on ellipsoids, -0.1 <= d <= 0.1: microseconds "
                "and iterations (mean +- std) [paper Table I]\n\n");
    table_hulls(md, r);
    if (family_present(r, BENCH_MESHES))
        for (mode = 0; mode < 2; ++mode) {
            fprintf(md, "## Meshes (%s), %s: iterations and microseconds\n\n", r->mesh_note,
                    mode ? "Boolean" : "distance");
            table_methods(md, r, BENCH_MESHES, mode, 0);
            table_methods(md, r, BENCH_MESHES, mode, 1);
        }
    fprintf(md, "## Ratio GJK / accelerated on the same problem [paper Fig. 8]\n\n");
    {
        FILE *csv = open_out(r->cfg, "ratios.csv");
        if (csv) {
            table_ratios(md, csv, r, index);
            fclose(csv);
        }
    }
    fprintf(md, "## Accuracy against the certified long-double reference\n\n");
    table_accuracy(md, r);
    if (r->cfg->wp_pairs > 0) {
        fprintf(md, "## Work-precision (work-precision.png, work-precision.csv)\n\n");
        write_work_precision(r, md);
    }
    if (r->ccd_count > 0) {
        fprintf(md, "## Boolean queries: agjk vs libccd\n\n");
        write_ccd(r, md);
    }
    write_summary_csv(r);
    write_iterations(r);
    free(index);
    fclose(md);
    return 0;
}
