/* SPDX-License-Identifier: MIT */
#include "depth_bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ccd_adapter.h"
#include "ccd_bench.h"
#include "coal_adapter.h"
#include "coal_bench.h"
#include "guard.h"
#include "hull_support.h"
#include "solve.h"
#include "stats.h"
#include "../../tests/common/ref_depth.h"

enum { OK = 0, NOT_FOUND = 1, NAN_ANSWER = 2, NOT_CONVERGED = 3, MISSED = 4 };

typedef struct depth_record {
    double ref_lo, ref_hi;        /* reference bracket on the signed distance */
    int ref_ok;
    double value[DB_COUNT];       /* signed distance answered (-depth) */
    double time_ns[DB_COUNT];
    int result[DB_COUNT];         /* OK, NOT_FOUND, NAN_ANSWER, NOT_CONVERGED, MISSED */
    double lower, upper;          /* agjk's certified interval */
    int epa_iterations;
} depth_record;

typedef struct ctx {
    const bench_set *set;
    const depth_bench_options *o;
    void **coal_shapes;       /* one per shape of the set, NULL without Coal */
} ctx;

static volatile double sink;

static const char *column_name(int c) {
    static const char *const names[DB_COUNT] = {"agjk EPA (certified)",
                                                "agjk EPA, width <= 1e-4 x scale",
                                                "libccd GJK+EPA, default",
                                                "libccd GJK+EPA, tight", "libccd MPR",
                                                "Coal GJK+EPA, default", "Coal GJK+EPA, tight"};
    return names[c];
}

/* libccd's EPA tolerance matched to what agjk certifies at depth p for the
 * absolute tolerance tol: min(sqrt(tol), tol / (2 p)). */
static double matched_epa_tolerance(double tol, double depth) {
    double w = sqrt(tol);
    if (depth > 0 && tol / (2 * depth) < w) w = tol / (2 * depth);
    return w;
}

/* Coal's GJK + EPA: default settings (its narrowphase's: GJK 128 iterations
 * and tolerance 1e-6, EPA 64 iterations and tolerance 1e-6) or tight (EPA
 * stops when its support gains at most tolerance x (1 + |w|), |w| about the
 * depth: the width agjk certifies, divided by 1 + depth; as many iterations
 * as agjk's store has vertices: Coal sizes its stores by the iteration cap
 * and its EPA::reset walks all of them, so a cap of 1000 would time that). */
static int run_coal(const ctx *c, const bench_problem *p, int tight, double width, double depth,
                    double *value, double *time_ns) {
    void *sa = c->coal_shapes[p->a], *sb = c->coal_shapes[p->b];
    coal_depth_desc d;
    coal_depth_answer a;
    memset(&d, 0, sizeof d);
    coal_bench_pose(&p->pose_a, d.rotation_a, d.translation_a);
    coal_bench_pose(&p->pose_b, d.rotation_b, d.translation_b);
    d.gjk_tolerance = 1e-6;
    d.gjk_max_iterations = 128;
    d.epa_tolerance = tight ? width / (1.0 + depth) : 1e-6;
    d.epa_max_iterations = tight ? AGJK_EPA_MAX_VERTICES : 64;
    d.reps = c->o->reps > 0 ? c->o->reps : 1;
    d.now_ns = bench_now_ns;
    d.trimmed_mean = bench_trimmed_mean;
    if (!sa || !sb || coal_adapter_depth(sa, sb, &d, &a) != 0 || !a.found) return NOT_FOUND;
    *value = -a.depth;
    *time_ns = a.time_ns;
    if (!isfinite(a.depth) || !isfinite(a.normal[0]) || !isfinite(a.normal[1]) ||
        !isfinite(a.normal[2]))
        return NAN_ANSWER;
    /* Coal's statuses: AccuracyReached, or an answer it still calls valid
     * (iteration cap) or a failure (out of faces or vertices, degenerate). */
    return a.epa_status == 3 /* EPA::AccuracyReached */ ? OK : NOT_CONVERGED;
}

static void run_case(void *vctx, int index, void *record) {
    const ctx *c = vctx;
    const bench_problem *p = &c->set->problems[index];
    const bench_shape *a = &c->set->shapes[p->a], *b = &c->set->shapes[p->b];
    depth_record *rec = record;
    int reps = c->o->reps > 0 ? c->o->reps : 1;
    double *t = malloc((size_t)reps * sizeof *t);
    if (!t) abort();
    memset(rec, 0, sizeof *rec);
    double size = a->radius + b->radius;
    ref_signed_bracket br;
    rec->ref_ok = ref_signed_distance_bb(&a->ref, &p->pose_a, &b->ref, &p->pose_b,
                                         1e-12L * size, 400000, &br) == 0;
    rec->ref_lo = (double)br.lower;
    rec->ref_hi = (double)br.upper;
    double tol = c->o->tolerance * p->scale * p->scale;
    for (int col = 0; col < DB_COUNT; ++col) {
        double value = 0;
        int result = OK;
        if (col == DB_COAL || col == DB_COAL_T) {
            if (!c->coal_shapes) continue;
            double t_ns = 0;
            result = run_coal(c, p, col == DB_COAL_T, matched_epa_tolerance(tol, -rec->ref_lo),
                              -rec->ref_lo, &value, &t_ns);
            rec->value[col] = value;
            rec->result[col] = result;
            rec->time_ns[col] = t_ns;
            continue;
        } else if (col == DB_AGJK || col == DB_AGJK_1E4) {
            agjk_options opt = agjk_default_options();
            agjk_signed_result r;
            opt.method = ccd_bench_accel_method(p->family);
            opt.max_iterations = c->o->max_iterations;
            opt.tolerance = tol;
            if (col == DB_AGJK_1E4) {
                /* width <= tolerance / 2 x depth = 1e-4 x scale */
                opt.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
                opt.tolerance = fmin(1.0, 2e-4 * p->scale / fmax(-rec->ref_hi, 1e-300));
            }
            for (int k = 0; k < reps; ++k) {
                double t0 = bench_now_ns();
                agjk_signed_distance(&a->shape, &p->pose_a, &b->shape, &p->pose_b, &opt, &r);
                t[k] = bench_now_ns() - t0;
                sink = r.signed_distance;
            }
            value = r.signed_distance;
            if (col == DB_AGJK) {
                rec->lower = r.lower;
                rec->upper = r.upper;
                rec->epa_iterations = r.epa_iterations;
            }
            if (!isfinite(r.signed_distance) || !isfinite(r.lower) || !isfinite(r.upper))
                result = NAN_ANSWER;
            else if (r.status == AGJK_STATUS_NOT_CONVERGED || r.status == AGJK_STATUS_INVALID_INPUT)
                result = NOT_CONVERGED;
            else if (r.lower > rec->ref_hi + 1e-16 * size || r.upper < rec->ref_lo - 1e-16 * size)
                result = MISSED;
        } else {
            bench_ccd_query q;
            bench_ccd_prepare(&q, c->set, p, (unsigned long)c->o->max_iterations);
            if (col == DB_CCD_EPA_T)
                q.ccd.epa_tolerance = matched_epa_tolerance(tol, -rec->ref_lo);
            ccd_real_t depth = 0;
            ccd_vec3_t dir, pos;
            int found = -1;
            for (int k = 0; k < reps; ++k) {
                q.hint_a = q.hint_b = 0;
                double t0 = bench_now_ns();
                found = col == DB_CCD_MPR ? ccdMPRPenetration(&q.a, &q.b, &q.ccd, &depth, &dir, &pos)
                                          : ccdGJKPenetration(&q.a, &q.b, &q.ccd, &depth, &dir, &pos);
                t[k] = bench_now_ns() - t0;
                sink = depth;
            }
            value = -depth;
            if (found != 0) result = NOT_FOUND;
            else if (!isfinite(depth) || !isfinite(dir.v[0]) || !isfinite(dir.v[1]) ||
                     !isfinite(dir.v[2]))
                result = NAN_ANSWER;
        }
        rec->value[col] = value;
        rec->result[col] = result;
        rec->time_ns[col] = bench_trimmed_mean(t, reps);
    }
    free(t);
}

static double median_of(double *v, int n) { return n ? bench_median(v, n) : NAN; }

int depth_bench_run(const bench_set *set, const depth_bench_options *o) {
    int n = 0;
    int *index = malloc((size_t)set->problem_count * sizeof *index + 1);
    if (!index) return -1;
    /* Hulls above 200 vertices are left out: the long double reference scans
     * every vertex in each of its ~1000 directions (20 ms a problem at 2500). */
    for (int i = 0; i < set->problem_count; ++i) {
        const bench_problem *p = &set->problems[i];
        if (p->category != BENCH_OVERLAPPING || !p->ref.intersecting) continue;
        if (p->family == BENCH_HULLS && set->shapes[p->a].vertex_count > 200) continue;
        index[n++] = i;
    }
    /* guard_run numbers cases 0..n-1: a view of the overlapping problems. */
    bench_set view = *set;
    bench_problem *problems = malloc((size_t)n * sizeof *problems + 1);
    depth_record *recs = calloc((size_t)n + 1, sizeof *recs);
    unsigned char *outcome = calloc((size_t)n + 1, 1);
    double *v1 = malloc((size_t)n * sizeof(double) + 8), *v2 = malloc((size_t)n * sizeof(double) + 8);
    if (!problems || !recs || !outcome || !v1 || !v2) return -1;
    for (int i = 0; i < n; ++i) problems[i] = set->problems[index[i]];
    view.problems = problems;
    view.problem_count = n;
    ctx c = {&view, o, NULL};
    int coal = coal_adapter_available();
    if (coal) {
        c.coal_shapes = calloc((size_t)set->shape_count + 1, sizeof *c.coal_shapes);
        if (!c.coal_shapes) return -1;
        for (int i = 0; i < set->shape_count; ++i) c.coal_shapes[i] = coal_bench_shape(&set->shapes[i]);
    }
    fprintf(stderr, "agjk-bench: penetration depth, agjk vs libccd%s on %d overlapping problems "
                    "(R = %d, %g s watchdog per case)\n", coal ? " and Coal" : "", n, o->reps,
            o->timeout_seconds);
    guard_run(n, sizeof *recs, run_case, &c, recs, outcome, o->timeout_seconds);

    char path[1024];
    snprintf(path, sizeof path, "%s/depth.csv", o->out_dir);
    FILE *csv = fopen(path, "w");
    if (csv) {
        fprintf(csv, "family,pair,pose,target,ref_lo,ref_hi,ref_ok,guard");
        for (int col = 0; col < DB_COUNT; ++col)
            fprintf(csv, ",value_%d,time_ns_%d,result_%d", col, col, col);
        fprintf(csv, ",agjk_lower,agjk_upper,epa_iterations\n");
        for (int i = 0; i < n; ++i) {
            const depth_record *r = &recs[i];
            const bench_problem *p = &problems[i];
            fprintf(csv, "%s,%d,%d,%g,%.17g,%.17g,%d,%d", bench_family_name(p->family), p->pair,
                    p->pose, p->target, r->ref_lo, r->ref_hi, r->ref_ok, outcome[i]);
            for (int col = 0; col < DB_COUNT; ++col)
                fprintf(csv, ",%.17g,%.1f,%d", r->value[col], r->time_ns[col], r->result[col]);
            fprintf(csv, ",%.17g,%.17g,%d\n", r->lower, r->upper, r->epa_iterations);
        }
        fclose(csv);
    }
    snprintf(path, sizeof path, "%s/depth.md", o->out_dir);
    FILE *md = fopen(path, "w");
    FILE *outs[2] = {stderr, md};
    int missed = 0;
    for (int k = 0; k < 2; ++k) {
        FILE *f = outs[k];
        if (!f) continue;
        fprintf(f, "\n## Penetration depth: agjk vs libccd and Coal\n\n"
                   "Overlapping problems of the benchmark (signed distances -0.1 ... -1e-4 x scale),\n"
                   "reference: branch and bound over the sphere of directions in long double\n"
                   "(bracket <= 1e-12 x size: smaller errors are at its resolution).\n"
                   "Hulls: N = 33 and 141 only. agjk: tolerance %g x scale^2 (absolute);\n"
                   "agjk 1e-4: asked for libccd's default accuracy, an interval of width\n"
                   "<= 1e-4 x scale; libccd default: epa_tolerance 1e-4; libccd tight:\n"
                   "epa_tolerance = the width agjk certifies at that depth.\n"
                   "Coal %s: GJK + EPA as its narrowphase runs them (EPA after GJK reports\n"
                   "Collision); default: its defaults (EPA tolerance 1e-6, 64 iterations);\n"
                   "tight: EPA tolerance = that width / (1 + depth) (Coal stops when a support\n"
                   "gains <= tolerance x (1 + |w|)), %d iterations. Coal's not converged: EPA\n"
                   "ended without AccuracyReached (iteration cap, out of faces, degenerate).\n"
                   "Error = |answer - reference|; time = mean of the fastest 90%% of %d runs.\n\n",
                o->tolerance, coal_adapter_version(), AGJK_EPA_MAX_VERTICES, o->reps);
        fprintf(f, "| family | method | n | median error | max error | median ns | time / libccd EPA tight (median) | not found | NaN | hung/crashed | not converged | outside certified interval |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    }
    for (int fam = 0; fam < BENCH_FAMILY_COUNT; ++fam)
        for (int col = 0; col < DB_COUNT; ++col) {
            int cnt = 0, nf = 0, nan = 0, hung = 0, nc = 0, miss = 0, ne = 0, nr = 0;
            double emax = 0;
            for (int i = 0; i < n; ++i) {
                const depth_record *r = &recs[i];
                if (problems[i].family != fam) continue;
                ++cnt;
                if (outcome[i] != GUARD_OK) { ++hung; continue; }
                if (r->result[col] == NOT_FOUND) ++nf;
                if (r->result[col] == NAN_ANSWER) ++nan;
                if (r->result[col] == NOT_CONVERGED) ++nc;
                if (r->result[col] == MISSED) ++miss;
                if (r->ref_ok && r->result[col] != NOT_FOUND && r->result[col] != NAN_ANSWER) {
                    double mid = 0.5 * (r->ref_lo + r->ref_hi);
                    double e = fabs(r->value[col] - mid);
                    v1[ne++] = e;
                    if (e > emax) emax = e;
                }
                if (r->time_ns[DB_CCD_EPA_T] > 0) v2[nr++] = r->time_ns[col] / r->time_ns[DB_CCD_EPA_T];
            }
            if (cnt == 0) continue;
            if ((col == DB_COAL || col == DB_COAL_T) && !coal) continue;
            if (col <= DB_AGJK_1E4) missed += miss;
            double emed = median_of(v1, ne), ratio = median_of(v2, nr);
            nr = 0;
            for (int i = 0; i < n; ++i)
                if (problems[i].family == fam && outcome[i] == GUARD_OK) v2[nr++] = recs[i].time_ns[col];
            double tmed = median_of(v2, nr);
            char ncs[16] = "-", misses[16] = "-";
            if (col <= DB_AGJK_1E4) {
                snprintf(ncs, sizeof ncs, "%d", nc);
                snprintf(misses, sizeof misses, "%d", miss);
            } else if (col == DB_COAL || col == DB_COAL_T) {
                snprintf(ncs, sizeof ncs, "%d", nc);
            }
            for (int k = 0; k < 2; ++k) {
                FILE *f = outs[k];
                if (!f) continue;
                fprintf(f, "| %s | %s | %d | %.2e | %.2e | %.0f | %.2f | %d | %d | %d | %s | %s |\n",
                        bench_family_name(fam), column_name(col), cnt, emed, emax, tmed, ratio, nf,
                        nan, hung, ncs, misses);
            }
        }
    if (md) fclose(md);
    if (c.coal_shapes) {
        for (int i = 0; i < set->shape_count; ++i) coal_adapter_shape_free(c.coal_shapes[i]);
        free(c.coal_shapes);
    }
    free(index);
    free(problems);
    free(recs);
    free(outcome);
    free(v1);
    free(v2);
    return missed;
}
