/* SPDX-License-Identifier: MIT */
#include "coal_bench.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "coal_adapter.h"
#include "guard.h"
#include "hull_support.h"

/* The methods both libraries have, in bench_method order. */
const int coal_bench_methods[4] = {BM_GJK, BM_NESTEROV, BM_NESTEROV_NORMALIZED, BM_POLYAK};
const char *const coal_bench_method_short[4] = {"GJK", "Nesterov", "Nest.-norm.", "Polyak"};
static const int coal_codes[4] = {COAL_GJK, COAL_NESTEROV, COAL_NESTEROV_NORMALIZED, COAL_POLYAK};

void *coal_bench_shape(const bench_shape *s) {
    coal_shape_desc d;
    memset(&d, 0, sizeof d);
    d.size[0] = s->size.x;
    d.size[1] = s->size.y;
    d.size[2] = s->size.z;
    if (s->kind == REF_ELLIPSOID) {
        d.kind = COAL_SHAPE_ELLIPSOID;
    } else if (s->kind == REF_BOX) {
        d.kind = COAL_SHAPE_BOX;
    } else {
        /* The very hull agjk climbs: its vertices (agjk_vec3 is three doubles)
         * and Qhull's triangles, from which Coal builds its own vertex graph. */
        d.kind = COAL_SHAPE_CONVEX;
        d.triangle_count = bench_hull_triangles(s, &d.triangles);
        if (d.triangle_count == 0) return NULL;
        d.vertices = &s->polytope.vertices[0].x;
        d.vertex_count = s->polytope.vertex_count;
    }
    return coal_adapter_shape_new(&d);
}

void coal_bench_pose(const agjk_pose *p, double r[9], double t[3]) {
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) r[3 * i + j] = p->rotation[i][j];
    t[0] = p->translation.x;
    t[1] = p->translation.y;
    t[2] = p->translation.z;
}

/* A converged distance farther from the reference than the duality gap
 * allows: ||x - x*||^2 <= g <= tolerance bounds the error by sqrt(tolerance). */
static unsigned char off_tolerance(const bench_record *r, double tolerance, double slack) {
    if (r->mode != BENCH_DISTANCE || !r->judged || !r->converged) return 0;
    return r->error > sqrt(tolerance) + slack;
}

static void progress(const char *label, int done, int total, double t0) {
    static double last;
    double now = bench_now_ns();
    if (done < total && now - last < 1e9) return;
    last = now;
    fprintf(stderr, "\r  %s: %d/%d (%.0f s)%s", label, done, total, (now - t0) * 1e-9,
            done >= total ? "\n" : "");
    fflush(stderr);
}

coal_bench_data *coal_bench_run(const bench_config *cfg, const bench_set *set) {
    if (!coal_adapter_available()) {
        fprintf(stderr, "agjk-bench: no Coal in this build (%s)\n", coal_adapter_version());
        return NULL;
    }
    if (cfg->coal_reps <= 0) return NULL;
    fprintf(stderr, "agjk-bench: agjk vs Coal %s, same methods and problems (R = %d)\n",
            coal_adapter_version(), cfg->coal_reps);
    return coal_bench_run_set(cfg, set, "agjk vs Coal");
}

coal_bench_data *coal_bench_run_set(const bench_config *cfg, const bench_set *set,
                                    const char *label) {
    coal_bench_data *d;
    void **shapes;
    int i, m, mode;
    double t0 = bench_now_ns();
    if (!coal_adapter_available() || cfg->coal_reps <= 0) return NULL;
    d = calloc(1, sizeof *d);
    shapes = calloc((size_t)set->shape_count + 1, sizeof *shapes);
    if (!d || !shapes) abort();
    d->recs = calloc((size_t)set->problem_count * 8 + 1, sizeof *d->recs);
    if (!d->recs) abort();
    d->version = coal_adapter_version();
    d->processes = 1;
    for (i = 0; i < set->shape_count; ++i) shapes[i] = coal_bench_shape(&set->shapes[i]);
    for (i = 0; i < set->problem_count; ++i) {
        const bench_problem *p = &set->problems[i];
        /* The same relative accuracy at every scale (1 for the protocol). */
        double tolerance = cfg->tolerance * p->scale * p->scale;
        if (!shapes[p->a] || !shapes[p->b]) {
            d->skipped_problems++;
            continue;
        }
        for (m = 0; m < 4; ++m)
            for (mode = 0; mode < 2; ++mode) {
                coal_bench_record *r = &d->recs[d->count];
                bench_solve_options o;
                coal_query_desc q;
                coal_answer a;
                memset(r, 0, sizeof *r);
                memset(&o, 0, sizeof o);
                o.tolerance = tolerance;
                o.relative = 0; /* Coal is run with the absolute duality gap */
                o.max_iterations = cfg->max_iterations;
                o.reps = cfg->coal_reps;
                if (bench_solve(set, p, coal_bench_methods[m], (bench_mode)mode, &o,
                                &r->agjk.run) != 0)
                    continue;
                memset(&q, 0, sizeof q);
                coal_bench_pose(&p->pose_a, q.rotation_a, q.translation_a);
                coal_bench_pose(&p->pose_b, q.rotation_b, q.translation_b);
                q.method = coal_codes[m];
                q.boolean = mode;
                q.tolerance = tolerance;
                q.max_iterations = cfg->max_iterations;
                q.reps = cfg->coal_reps;
                q.now_ns = bench_now_ns;
                q.trimmed_mean = bench_trimmed_mean;
                if (coal_adapter_run(shapes[p->a], shapes[p->b], &q, &a) != 0) {
                    d->failed_runs++;
                    continue;
                }
                r->agjk.problem = r->coal.problem = i;
                r->agjk.method = r->coal.method = (signed char)coal_bench_methods[m];
                r->agjk.mode = r->coal.mode = (signed char)mode;
                r->coal.run.status = a.verdict == 1   ? AGJK_STATUS_INTERSECTING
                                     : a.verdict == 0 ? AGJK_STATUS_SEPARATED
                                                      : AGJK_STATUS_NOT_CONVERGED;
                r->coal.run.iterations = a.iterations;
                r->coal.run.support_calls = a.support_calls;
                r->coal.run.distance = a.distance;
                r->coal.run.bound = -1.0;
                r->coal.run.time_ns = a.time_ns;
                r->coal_status = a.coal_status;
                bench_evaluate(p, &r->agjk);
                bench_evaluate(p, &r->coal);
                r->agjk_off = off_tolerance(&r->agjk, tolerance, bench_rounding_slack(p));
                r->coal_off = off_tolerance(&r->coal, tolerance, bench_rounding_slack(p));
                d->count++;
            }
        progress(label, i + 1, set->problem_count, t0);
    }
    for (i = 0; i < set->shape_count; ++i) coal_adapter_shape_free(shapes[i]);
    free(shapes);
    d->seconds = (bench_now_ns() - t0) * 1e-9;
    if (d->skipped_problems)
        fprintf(stderr, "  %d problems skipped (a polytope without a solid hull)\n",
                d->skipped_problems);
    if (d->failed_runs) fprintf(stderr, "  %d runs where Coal threw\n", d->failed_runs);
    return d;
}

int coal_bench_times(coal_bench_data *d, bench_times out[2]) {
    out[0].first = &d->recs[0].agjk.run.time_ns;
    out[1].first = &d->recs[0].coal.run.time_ns;
    out[0].count = out[1].count = d->count;
    out[0].stride = out[1].stride = sizeof d->recs[0];
    return d->count > 0 ? 2 : 0;
}

void coal_bench_free(coal_bench_data *d) {
    if (!d) return;
    free(d->recs);
    free(d);
}

coal_bench_group coal_bench_group_of(const bench_set *set, const coal_bench_data *d, int family,
                                     int category, int method, int mode, double *buf_ratio,
                                     double *buf_a, double *buf_c) {
    coal_bench_group g;
    double sa = 0, sc = 0;
    int i;
    memset(&g, 0, sizeof g);
    for (i = 0; i < d->count; ++i) {
        const coal_bench_record *r = &d->recs[i];
        const bench_problem *p = &set->problems[r->agjk.problem];
        if (p->family != family || p->category != category || r->agjk.method != method ||
            r->agjk.mode != mode)
            continue;
        buf_a[g.n] = r->agjk.run.time_ns;
        buf_c[g.n] = r->coal.run.time_ns;
        buf_ratio[g.n] = r->coal.run.time_ns > 0 ? r->agjk.run.time_ns / r->coal.run.time_ns : NAN;
        sa += r->agjk.run.time_ns;
        sc += r->coal.run.time_ns;
        g.agjk_it += r->agjk.run.iterations;
        g.coal_it += r->coal.run.iterations;
        g.agjk_calls += r->agjk.run.support_calls;
        g.coal_calls += r->coal.run.support_calls;
        g.agjk_wrong += r->agjk.wrong;
        g.coal_wrong += r->coal.wrong;
        g.agjk_off += r->agjk_off;
        g.coal_off += r->coal_off;
        g.agjk_nc += !r->agjk.converged;
        g.agjk_violations += r->agjk.violation;
        g.coal_nc += !r->coal.converged;
        g.slower += r->agjk.run.time_ns > r->coal.run.time_ns;
        g.n++;
    }
    if (g.n > 0) {
        g.ratio_median = bench_median(buf_ratio, g.n);
        g.ratio_of_means = sc > 0 ? sa / sc : NAN;
        g.agjk_ns = bench_median(buf_a, g.n);
        g.coal_ns = bench_median(buf_c, g.n);
        g.agjk_it /= g.n;
        g.coal_it /= g.n;
        g.agjk_calls /= g.n;
        g.coal_calls /= g.n;
    }
    return g;
}

/* Median per-problem ratios agjk / libccd (Boolean) of one set x category:
 * [0] agjk accelerated / libccd MPR, [1] agjk GJK / libccd GJK. */
static int ccd_ratios(const bench_report *r, int family, int category, double out[2],
                      double *buf0, double *buf1) {
    int i, n = 0;
    if (!r->ccd || r->ccd_count <= 0) return 0;
    for (i = 0; i < r->ccd_count; ++i) {
        const bench_problem *p = &r->set->problems[i];
        const ccd_bench_record *k = &r->ccd[i];
        if (p->family != family || p->category != category || r->ccd_outcome[i] != GUARD_OK)
            continue;
        if (k->time_ns[CB_CCD_MPR] <= 0 || k->time_ns[CB_CCD_GJK] <= 0) continue;
        buf0[n] = k->time_ns[CB_AGJK_ACCEL] / k->time_ns[CB_CCD_MPR];
        buf1[n] = k->time_ns[CB_AGJK_GJK] / k->time_ns[CB_CCD_GJK];
        ++n;
    }
    if (n == 0) return 0;
    out[0] = bench_median(buf0, n);
    out[1] = bench_median(buf1, n);
    return n;
}

void coal_bench_cell(FILE *f, double v, int differ) {
    const char *mark = differ ? "\xe2\x80\xa0" : "";
    if (isnan(v)) fprintf(f, " - |");
    else if (v > 1.0) fprintf(f, " **%.2f**%s |", v, mark);
    else fprintf(f, " %.2f%s |", v, mark);
}

int coal_bench_different_work(const coal_bench_group *g) {
    return g->n > 0 && fabs(g->agjk_calls - g->coal_calls) > 0.05 * g->coal_calls;
}

void coal_bench_ratio_head(FILE *f, const char *first, const char *const *extra, int n_extra) {
    int m, mode;
    fprintf(f, "| %s | category |", first);
    for (mode = 0; mode < 2; ++mode)
        for (m = 0; m < 4; ++m)
            fprintf(f, " %s %s |", mode ? "Boolean" : "distance", coal_bench_method_short[m]);
    for (m = 0; m < n_extra; ++m) fprintf(f, " %s |", extra[m]);
    fprintf(f, "\n|---|---|");
    for (m = 0; m < 8 + n_extra; ++m) fprintf(f, "---|");
    fprintf(f, "\n");
}

void coal_bench_detail_row(FILE *md, FILE *csv, const char *set, int category, int mode, int m,
                           const coal_bench_group *g, int with_misses) {
    int k;
    for (k = 0; k < 2; ++k) {
        FILE *f = k ? csv : md;
        if (!f) continue;
        fprintf(f,
                k ? "%s,%s,%s,%s,%d,%.1f,%.1f,%.4f,%.4f,%d,%.3f,%.3f,%.3f,%.3f,%d,%d,%d,%d,%d,%d"
                  : "| %s | %s | %s | %s | %d | %.0f | %.0f | %.2f | %.2f | %d | %.1f / %.1f | "
                    "%.1f / %.1f | %d / %d | %d / %d | %d / %d |",
                set, bench_category_name(category),
                mode ? (k ? "boolean" : "Boolean") : "distance",
                bench_method_name(coal_bench_methods[m]), g->n, g->agjk_ns, g->coal_ns,
                g->ratio_median, g->ratio_of_means, g->slower, g->agjk_it, g->coal_it,
                g->agjk_calls, g->coal_calls, g->agjk_wrong, g->coal_wrong, g->agjk_off,
                g->coal_off, g->agjk_nc, g->coal_nc);
        if (with_misses) fprintf(f, k ? ",%d" : " %d |", g->agjk_violations);
        fprintf(f, "\n");
    }
}

FILE *coal_bench_details_open(FILE *md, const char *path, const char *set_title,
                              const char *set_column, int with_misses) {
    FILE *csv;
    fprintf(md, "| %s | category | mode | method | problems | agjk ns | Coal ns | ratio (median) "
                "| ratio of means | agjk slower on | iterations agjk / Coal | support calls "
                "agjk / Coal | wrong verdicts agjk / Coal | distance off by > sqrt(tol) agjk / "
                "Coal | no verdict agjk / Coal |%s\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|%s\n",
            set_title, with_misses ? " agjk bound misses |" : "", with_misses ? "---|" : "");
    csv = fopen(path, "w");
    if (!csv) {
        perror(path);
        return NULL;
    }
    fprintf(csv, "%s,category,mode,method,problems,agjk_ns_median,coal_ns_median,ratio_median,"
                 "ratio_of_means,agjk_slower,agjk_iterations,coal_iterations,agjk_support_calls,"
                 "coal_support_calls,agjk_wrong,coal_wrong,agjk_off,coal_off,agjk_no_verdict,"
                 "coal_no_verdict%s\n",
            set_column, with_misses ? ",agjk_bound_misses" : "");
    return csv;
}

void coal_bench_count_answers(const coal_bench_data *d, coal_bench_answers *a) {
    int i;
    for (i = 0; i < d->count; ++i) {
        const coal_bench_record *x = &d->recs[i];
        a->agjk_wrong += x->agjk.wrong;
        a->coal_wrong += x->coal.wrong;
        a->agjk_off += x->agjk_off;
        a->coal_off += x->coal_off;
        a->agjk_nc += !x->agjk.converged;
        a->coal_nc += !x->coal.converged;
        a->agjk_violations += x->agjk.violation;
        a->agjk_contact += x->agjk.run.status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    }
    a->runs += d->count;
}

void coal_bench_tally_init(coal_bench_tally *t) { memset(t, 0, sizeof *t); }

void coal_bench_tally_add(coal_bench_tally *t, const coal_bench_group *g, const char *set,
                          const char *category, int mode, int m) {
    double v = g->ratio_median;
    int l = v > 1.0 ? 0 : 1;
    if (!g->n) return;
    if (coal_bench_different_work(g)) { /* not the same computation */
        ++t->differ;
        return;
    }
    ++t->cells;
    t->target += v <= 0.8;
    t->slower += v > 1.0;
    if (t->len[l] + 100 < sizeof t->list[l])
        t->len[l] += (size_t)snprintf(t->list[l] + t->len[l], sizeof t->list[l] - t->len[l],
                                      "%s%s %s %s %s %.2f", t->len[l] ? "; " : "", set, category,
                                      mode ? "Boolean" : "distance", coal_bench_method_short[m], v);
}

void coal_bench_tally_write(FILE *f, const coal_bench_tally *t, const char *lead,
                            const char *where) {
    fprintf(f, "%s the %d cells where both libraries made the same support calls "
               "(%d \xe2\x80\xa0 cells left out): ", lead, t->cells, t->differ);
    if (t->slower == 0)
        fprintf(f, "agjk is as fast as Coal or faster in all.\n");
    else if (t->slower == t->cells)
        fprintf(f, "agjk is slower than Coal in all.\n");
    else if (2 * t->slower > t->cells)
        fprintf(f, "agjk is slower than Coal in %d; as fast or faster only in: %s.\n", t->slower,
                t->list[1]);
    else
        fprintf(f, "agjk is slower than Coal in %d: %s.\n", t->slower, t->list[0]);
    fprintf(f, "Target of issue 8 (agjk <= 0.8 x Coal)%s: met in %d of %d.\n\n", where, t->target,
            t->cells);
}

/* The compact ratio table (the README's), to each of the n streams. */
static void ratio_table(FILE **out, int nout, const bench_report *r, const coal_bench_data *d,
                        double *b0, double *b1, double *b2) {
    static const char *const ccd_columns[2] = {"Boolean: agjk accel. / libccd MPR",
                                               "agjk GJK / libccd GJK"};
    int fam, c, m, mode, k;
    coal_bench_tally t;
    coal_bench_tally_init(&t);
    for (k = 0; k < nout; ++k) coal_bench_ratio_head(out[k], "set", ccd_columns, 2);
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c) {
            coal_bench_group g[2][4];
            double ccd[2] = {NAN, NAN};
            int any = 0;
            for (mode = 0; mode < 2; ++mode)
                for (m = 0; m < 4; ++m) {
                    g[mode][m] = coal_bench_group_of(r->set, d, fam, c, coal_bench_methods[m],
                                                     mode, b0, b1, b2);
                    any += g[mode][m].n;
                }
            if (!any) continue;
            if (!ccd_ratios(r, fam, c, ccd, b0, b1)) ccd[0] = ccd[1] = NAN;
            for (k = 0; k < nout; ++k) {
                fprintf(out[k], "| %s | %s |", bench_family_name(fam), bench_category_name(c));
                for (mode = 0; mode < 2; ++mode)
                    for (m = 0; m < 4; ++m)
                        coal_bench_cell(out[k], g[mode][m].n ? g[mode][m].ratio_median : NAN,
                                        coal_bench_different_work(&g[mode][m]));
                coal_bench_cell(out[k], ccd[0], 0);
                coal_bench_cell(out[k], ccd[1], 0);
                fprintf(out[k], "\n");
            }
            for (mode = 0; mode < 2; ++mode)
                for (m = 0; m < 4; ++m)
                    coal_bench_tally_add(&t, &g[mode][m], bench_family_name(fam),
                                         bench_category_name(c), mode, m);
        }
    for (k = 0; k < nout; ++k) {
        fprintf(out[k], "\nagjk time / Coal %s time for the same method on the same problem "
                        "(median over problems of the per-problem ratio; each time the mean of "
                        "the fastest 90%% of the runs); < 1: agjk faster, **bold**: agjk slower. "
                        "The libccd columns are Boolean queries (agjk accelerated: Nesterov on "
                        "ellipsoids, normalized Nesterov on polytopes). \xe2\x80\xa0: the two libraries "
                        "made different numbers of support calls (means more than 5%% apart): "
                        "their variants differ there, so the ratio compares different work.\n\n",
                d->version);
        coal_bench_tally_write(out[k], &t, "Of", "");
    }
}

int coal_bench_write(const bench_report *r, const coal_bench_data *d) {
    char path[1024];
    FILE *md, *csv;
    double *b0, *b1, *b2;
    int fam, c, m, mode;
    snprintf(path, sizeof path, "%s/tables.md", r->cfg->out_dir);
    md = fopen(path, "a");
    if (!md) { perror(path); return -1; }
    fprintf(md, "## agjk vs Coal: time ratios for the same method\n\n");
    if (!d) {
        fprintf(md, "Not measured: %s. Run `tools/fetch-coal.sh` (downloads Coal 3.0.3 from "
                    "PyPI into out/coal) and `make bench` again for the agjk/Coal columns.\n\n",
                coal_adapter_available() ? "Coal runs disabled (--coal-reps 0)"
                                         : "this agjk-bench was built without Coal");
        fclose(md);
        printf("agjk/Coal ratios: not measured (no Coal in this build). Run tools/fetch-coal.sh, "
               "then make bench.\n");
        return 0;
    }
    b0 = malloc(sizeof(double) * ((size_t)d->count + (size_t)r->ccd_count + 8));
    b1 = malloc(sizeof(double) * ((size_t)d->count + (size_t)r->ccd_count + 8));
    b2 = malloc(sizeof(double) * ((size_t)d->count + (size_t)r->ccd_count + 8));
    if (!b0 || !b1 || !b2) abort();
    fprintf(md, "Coal %s (PyPI wheel libcoal, fetched by tools/fetch-coal.sh), linked into "
                "agjk-bench through tools/bench/coal_adapter.cpp: Coal's Ellipsoid, Box and "
                "Convex (the same Qhull hull as agjk, with Coal's vertex graph), "
                "coal::details::GJK with the same variant (Nesterov with Coal's normalization "
                "heuristic forced off, Nesterov-normalized with it forced on), duality-gap "
                "criterion with absolute tolerance %g, at most %d iterations, initial guess "
                "x0 = c_A - c_B, early exit at the first separating plane in Boolean mode. "
                "Timed per run: MinkowskiDiff::set + GJK::evaluate for Coal, agjk_distance or "
                "agjk_collide (distance only, no witness points) for agjk; R = %d runs per "
                "problem, agjk's right before Coal's; the whole comparison run in %d "
                "process%s, each problem's times the median over them (see "
                "tools/bench/repeat.h). %d problems x 4 methods x 2 modes, "
                "%d skipped, %.0f s per process.\n\n",
            d->version, r->cfg->tolerance, r->cfg->max_iterations, r->cfg->coal_reps,
            d->processes, d->processes == 1 ? "" : "es", d->count / 8, d->skipped_problems,
            d->seconds);
    fprintf(md, "Each run's time includes one clock read: an empty run timed the same way "
                "took %.1f ns here. It is in both libraries' times, so the ratios of the "
                "shortest queries lie nearer 1 than those of the queries alone would.\n\n",
            r->clock_overhead_ns);
    {
        FILE *outs[2];
        outs[0] = md;
        outs[1] = stdout;
        printf("\nagjk / Coal %s, same method (results in %s/tables.md):\n\n", d->version,
               r->cfg->out_dir);
        ratio_table(outs, 2, r, d, b0, b1, b2);
        {
            int k;
            coal_bench_answers a;
            memset(&a, 0, sizeof a);
            coal_bench_count_answers(d, &a);
            for (k = 0; k < 2; ++k)
                fprintf(outs[k], "Answers of these %d runs against the certified reference: "
                                 "wrong verdicts agjk %d, Coal %d; distances off by more than "
                                 "sqrt(tolerance) agjk %d, Coal %d; no verdict agjk %d, Coal %d "
                                 "(details below).\n\n",
                        a.runs, a.agjk_wrong, a.coal_wrong, a.agjk_off, a.coal_off, a.agjk_nc,
                        a.coal_nc);
        }
    }
    fprintf(md, "### Details: median ns, iterations and support calls (mean), answers\n\n");
    snprintf(path, sizeof path, "%s/coal.csv", r->cfg->out_dir);
    csv = coal_bench_details_open(md, path, "set", "family", 0);
    for (fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c)
            for (mode = 0; mode < 2; ++mode)
                for (m = 0; m < 4; ++m) {
                    coal_bench_group g = coal_bench_group_of(r->set, d, fam, c,
                                                             coal_bench_methods[m], mode, b0, b1,
                                                             b2);
                    if (!g.n) continue;
                    coal_bench_detail_row(md, csv, bench_family_name(fam), c, mode, m, &g, 0);
                }
    fprintf(md, "\nIterations: agjk counts the support call that detects convergence; Coal's "
                "GJK::getNumIterations() does not. Support calls of Coal are counted in one "
                "extra untimed run through a wrapper of its support function. \"wrong\": a "
                "verdict the certified reference refutes; \"off\": a converged distance "
                "farther than sqrt(tolerance) from the reference, which the duality gap rules "
                "out (Coal gives no certified bound); \"no verdict\": agjk's not converged or "
                "contact within tolerance, Coal's Failed.\n\n");
    if (csv) fclose(csv);
    fclose(md);
    free(b0);
    free(b1);
    free(b2);
    return 0;
}
