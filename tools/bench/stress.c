/* SPDX-License-Identifier: MIT */
#include "stress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "coal_adapter.h"
#include "coal_bench.h"

enum { STRESS_PROTOCOL = 0, STRESS_FAR = 1, STRESS_TOUCHING = 2 };

typedef struct stress_family {
    const char *name;
    int base;                  /* BENCH_ELLIPSOIDS or BENCH_BOXES */
    double scale;              /* the set's scale */
    int kind;                  /* STRESS_* */
    bench_size_hook size_hook; /* NULL: the protocol's sizes */
} stress_family;

static void scale_axis(agjk_vec3 *v, int axis, double f) {
    if (axis == 0) v->x *= f;
    else if (axis == 1) v->y *= f;
    else v->z *= f;
}

/* Needles (two radii x 1e-3) and pancakes (one radius x 1e-3), half each. */
static void stiff_size(agjk_vec3 *size, bench_rng *rng) {
    int axis = (int)bench_rng_below(rng, 3);
    if (bench_rng_below(rng, 2)) {
        scale_axis(size, (axis + 1) % 3, 1e-3);
        scale_axis(size, (axis + 2) % 3, 1e-3);
    } else {
        scale_axis(size, axis, 1e-3);
    }
}

/* One half extent x 1e-4, or exactly 0 (a plate), half each. */
static void flat_size(agjk_vec3 *size, bench_rng *rng) {
    int axis = (int)bench_rng_below(rng, 3);
    scale_axis(size, axis, bench_rng_below(rng, 2) ? 1e-4 : 0.0);
}

static const stress_family families[] = {
    {"stiff ellipsoids", BENCH_ELLIPSOIDS, 1.0, STRESS_PROTOCOL, stiff_size},
    {"flat boxes", BENCH_BOXES, 1.0, STRESS_PROTOCOL, flat_size},
    {"tiny ellipsoids", BENCH_ELLIPSOIDS, 1e-4, STRESS_PROTOCOL, NULL},
    {"tiny boxes", BENCH_BOXES, 1e-4, STRESS_PROTOCOL, NULL},
    {"huge ellipsoids", BENCH_ELLIPSOIDS, 1e4, STRESS_PROTOCOL, NULL},
    {"huge boxes", BENCH_BOXES, 1e4, STRESS_PROTOCOL, NULL},
    {"far ellipsoids", BENCH_ELLIPSOIDS, 1.0, STRESS_FAR, NULL},
    {"far boxes", BENCH_BOXES, 1.0, STRESS_FAR, NULL},
    {"touching ellipsoids", BENCH_ELLIPSOIDS, 1.0, STRESS_TOUCHING, NULL},
    {"touching boxes", BENCH_BOXES, 1.0, STRESS_TOUCHING, NULL},
};
#define STRESS_COUNT ((int)(sizeof families / sizeof families[0]))

/* Nearly touching: signed distances (times the scale). */
static const double touching_targets[4] = {-1e-6, -1e-9, 1e-9, 1e-6};
static const int touching_categories[4] = {BENCH_OVERLAPPING, BENCH_OVERLAPPING, BENCH_CLOSE,
                                           BENCH_CLOSE};

/* The adaptive method (agjk's default) on one set and category, run once per
 * problem and mode (untimed), judged by the reference. */
typedef struct stress_adaptive {
    double calls;              /* distance mode: support calls, summed */
    int n, wrong, violations, no_verdict;
    /* Boolean mode: its own rule for the first supports (direction.c). */
    double bool_calls;
    int bool_n, bool_wrong, bool_no_verdict;
} stress_adaptive;

struct bench_stress {
    int pairs, poses, reps;
    double tolerance;
    bench_set sets[STRESS_COUNT];
    coal_bench_data *data[STRESS_COUNT];
    stress_adaptive adaptive[STRESS_COUNT][BENCH_CATEGORY_COUNT];
    int full[STRESS_COUNT];    /* the generator ran out of room (a bug) */
    double seconds_generate, seconds_run;
};

static double norm3(agjk_vec3 v) { return sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

/* Far: every pose (its targets alike) moved by one vector of length
 * 1e4 ... 1e6 (log-uniform) in a random direction; the reference is then
 * computed on the moved poses (the move rounds B's translation). */
static void move_far(bench_set *set, bench_rng *rng) {
    agjk_vec3 shift = {0, 0, 0};
    int i;
    for (i = 0; i < set->problem_count; ++i) {
        bench_problem *p = &set->problems[i];
        if (p->target_index == 0) {
            agjk_vec3 u = bench_rng_unit(rng);
            double length = 1e4 * pow(100.0, bench_rng_uniform(rng));
            shift.x = length * u.x;
            shift.y = length * u.y;
            shift.z = length * u.z;
        }
        p->pose_a.translation.x += shift.x;
        p->pose_a.translation.y += shift.y;
        p->pose_a.translation.z += shift.z;
        p->pose_b.translation.x += shift.x;
        p->pose_b.translation.y += shift.y;
        p->pose_b.translation.z += shift.z;
        p->offset = fmax(norm3(p->pose_a.translation), norm3(p->pose_b.translation));
        bench_problem_reference(set, p);
    }
}

/* One run of the adaptive method on problem i of set in `mode`, judged by
 * the reference into *rec; 0, or -1 when it could not run. */
static int judge_adaptive(const bench_set *set, int i, int mode, const bench_solve_options *o,
                          bench_record *rec) {
    memset(rec, 0, sizeof *rec);
    if (bench_solve(set, &set->problems[i], BM_ADAPTIVE, mode, o, &rec->run) != 0) return -1;
    rec->problem = i;
    rec->method = BM_ADAPTIVE;
    rec->mode = mode;
    bench_evaluate(&set->problems[i], rec);
    return 0;
}

/* The adaptive method on every problem of set k, in both modes, with the
 * tolerance the Coal comparison used there (tolerance x scale^2). */
static void run_adaptive(bench_stress *s, int k, const bench_config *cfg) {
    const bench_set *set = &s->sets[k];
    int i;
    for (i = 0; i < set->problem_count; ++i) {
        const bench_problem *p = &set->problems[i];
        stress_adaptive *a = &s->adaptive[k][p->category];
        bench_solve_options o;
        bench_record rec;
        memset(&o, 0, sizeof o);
        o.tolerance = cfg->tolerance * p->scale * p->scale;
        o.max_iterations = cfg->max_iterations;
        if (judge_adaptive(set, i, BENCH_DISTANCE, &o, &rec) == 0) {
            a->calls += rec.run.support_calls;
            a->n++;
            a->wrong += rec.wrong;
            a->violations += rec.violation;
            a->no_verdict += !rec.converged;
        }
        if (judge_adaptive(set, i, BENCH_BOOLEAN, &o, &rec) == 0) {
            a->bool_calls += rec.run.support_calls;
            a->bool_n++;
            a->bool_wrong += rec.wrong;
            a->bool_no_verdict += !rec.converged;
        }
    }
}

bench_stress *bench_stress_run(const bench_config *cfg) {
    bench_stress *s;
    int k;
    if (!coal_adapter_available() || cfg->coal_reps <= 0 || cfg->stress_pairs <= 0) return NULL;
    s = calloc(1, sizeof *s);
    if (!s) abort();
    s->pairs = cfg->stress_pairs;
    s->poses = cfg->stress_poses;
    s->reps = cfg->coal_reps;
    s->tolerance = cfg->tolerance;
    fprintf(stderr, "agjk-bench: agjk vs Coal on a stress set (%d families x %d pairs x %d "
                    "poses, R = %d)\n", STRESS_COUNT, s->pairs, s->poses, s->reps);
    for (k = 0; k < STRESS_COUNT; ++k) {
        const stress_family *f = &families[k];
        bench_set *set = &s->sets[k];
        bench_rng rng;
        int targets = f->kind == STRESS_TOUCHING ? 4 : BENCH_TARGET_COUNT;
        double t0 = bench_now_ns();
        char label[64];
        bench_set_init(set, 2 * s->pairs + 2, s->pairs * s->poses * targets + 1);
        set->scale = f->scale;
        set->size_hook = f->size_hook;
        if (f->kind == STRESS_TOUCHING) {
            set->targets = touching_targets;
            set->target_categories = touching_categories;
            set->target_count = 4;
        }
        /* One stream per family, apart from the protocol's (seed * 4 + 0..3). */
        bench_rng_seed(&rng, cfg->seed * 64 + 32 + (uint64_t)k);
        s->full[k] = bench_generate(set, f->base, s->pairs, s->poses, 0, NULL, &rng,
                                    f->kind != STRESS_FAR, 0) != 0;
        if (f->kind == STRESS_FAR) move_far(set, &rng);
        s->seconds_generate += (bench_now_ns() - t0) * 1e-9;
        t0 = bench_now_ns();
        snprintf(label, sizeof label, "stress, %s", f->name);
        s->data[k] = coal_bench_run_set(cfg, set, label);
        run_adaptive(s, k, cfg);
        s->seconds_run += (bench_now_ns() - t0) * 1e-9;
    }
    return s;
}

/* The processes the times are medians of (repeat.h). */
static int stress_processes(const bench_stress *s) {
    int k;
    for (k = 0; k < STRESS_COUNT; ++k)
        if (s->data[k]) return s->data[k]->processes;
    return 1;
}

int bench_stress_coal_data(bench_stress *s, coal_bench_data **out, int cap) {
    int k, n = 0;
    for (k = 0; s && k < STRESS_COUNT && n < cap; ++k)
        if (s->data[k]) out[n++] = s->data[k];
    return n;
}

void bench_stress_free(bench_stress *s) {
    int k;
    if (!s) return;
    for (k = 0; k < STRESS_COUNT; ++k) {
        coal_bench_free(s->data[k]);
        bench_set_free(&s->sets[k]);
    }
    free(s);
}

/* The compact table: one row per family x category, the 8 median ratios,
 * then the summary over comparable cells, to each of the n streams. */
static void ratio_table(FILE **out, int nout, const bench_stress *s, double *b0, double *b1,
                        double *b2) {
    int k, c, m, mode, o;
    coal_bench_tally t;
    coal_bench_tally_init(&t);
    for (o = 0; o < nout; ++o) coal_bench_ratio_head(out[o], "stress set", NULL, 0);
    for (k = 0; k < STRESS_COUNT; ++k) {
        if (!s->data[k]) continue;
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c) {
            coal_bench_group g[2][4];
            int any = 0;
            for (mode = 0; mode < 2; ++mode)
                for (m = 0; m < 4; ++m) {
                    g[mode][m] = coal_bench_group_of(&s->sets[k], s->data[k], families[k].base, c,
                                                     coal_bench_methods[m], mode, b0, b1, b2);
                    any += g[mode][m].n;
                }
            if (!any) continue;
            for (o = 0; o < nout; ++o) {
                fprintf(out[o], "| %s | %s |", families[k].name, bench_category_name(c));
                for (mode = 0; mode < 2; ++mode)
                    for (m = 0; m < 4; ++m)
                        coal_bench_cell(out[o], g[mode][m].n ? g[mode][m].ratio_median : NAN,
                                        coal_bench_different_work(&g[mode][m]));
                fprintf(out[o], "\n");
            }
            for (mode = 0; mode < 2; ++mode)
                for (m = 0; m < 4; ++m)
                    coal_bench_tally_add(&t, &g[mode][m], families[k].name,
                                         bench_category_name(c), mode, m);
        }
    }
    for (o = 0; o < nout; ++o) {
        fprintf(out[o], "\nagjk time / Coal time for the same method on the same problem, as "
                        "in the table above (median over problems of the per-problem ratio); "
                        "< 1: agjk faster, **bold**: agjk slower, \xe2\x80\xa0: different numbers "
                        "of support calls (means more than 5%% apart).\n\n");
        coal_bench_tally_write(out[o], &t, "On the stress set, of", " on the stress set");
    }
}

/* Support calls per distance query (mean) on the stress set: the four
 * methods the Coal comparison ran (agjk's and Coal's counts from its
 * records) against the adaptive method, as the protocol's table (calls.c). */
static void adaptive_table(FILE *md, const bench_stress *s) {
    int k, c, m, i, rows = 0, worse = 0, worse_gjk = 0, worse_coal = 0;
    int wrong = 0, misses = 0, no_verdict = 0, runs = 0;
    int bool_wrong = 0, bool_no_verdict = 0, bool_runs = 0;
    double bool_calls = 0;
    fprintf(md, "### Stress set: support calls per distance query (mean), the adaptive method\n\n"
                "| stress set | category | GJK | Nesterov | Nesterov-normalized | Polyak | best of "
                "the four | Coal's best | Adaptive |\n|---|---|---|---|---|---|---|---|---|\n");
    for (k = 0; k < STRESS_COUNT; ++k) {
        const coal_bench_data *d = s->data[k];
        if (!d) continue;
        for (c = BENCH_CATEGORY_COUNT - 1; c >= 0; --c) {
            const stress_adaptive *a = &s->adaptive[k][c];
            double agjk[4] = {0, 0, 0, 0}, coal[4] = {0, 0, 0, 0}, best = 0, coal_best = 0, ad;
            int n[4] = {0, 0, 0, 0}, coal_arg = 0;
            if (a->n == 0) continue;
            for (i = 0; i < d->count; ++i) {
                const coal_bench_record *r = &d->recs[i];
                if (r->agjk.mode != BENCH_DISTANCE ||
                    s->sets[k].problems[r->agjk.problem].category != c)
                    continue;
                for (m = 0; m < 4; ++m)
                    if (r->agjk.method == coal_bench_methods[m]) {
                        agjk[m] += r->agjk.run.support_calls;
                        coal[m] += r->coal.run.support_calls;
                        n[m]++;
                    }
            }
            ad = a->calls / a->n;
            fprintf(md, "| %s | %s |", families[k].name, bench_category_name(c));
            for (m = 0; m < 4; ++m) {
                double v = n[m] ? agjk[m] / n[m] : NAN, cv = n[m] ? coal[m] / n[m] : NAN;
                fprintf(md, " %.2f |", v);
                if (m == 0 || v < best) best = v;
                if (m == 0 || cv < coal_best) {
                    coal_best = cv;
                    coal_arg = m;
                }
            }
            fprintf(md, " %.2f | %.2f (%s) | **%.2f** |\n", best, coal_best,
                    coal_bench_method_short[coal_arg], ad);
            ++rows;
            worse += ad > best;
            worse_gjk += n[0] && ad > agjk[0] / n[0];
            worse_coal += ad > coal_best;
            wrong += a->wrong;
            misses += a->violations;
            no_verdict += a->no_verdict;
            runs += a->n;
            bool_wrong += a->bool_wrong;
            bool_no_verdict += a->bool_no_verdict;
            bool_runs += a->bool_n;
            bool_calls += a->bool_calls;
        }
    }
    fprintf(md, "\nAdaptive above the best of the four in %d of %d rows, above GJK in %d, above "
                "Coal's best in %d. Its %d answers (distance mode, the tolerance of the table "
                "above) against the certified reference: %d wrong verdicts, %d certified "
                "intervals missing the reference, %d without a verdict. In Boolean mode, "
                "%d answers: %d wrong verdicts, %d without a verdict (support calls per "
                "query %.2f).\n\n",
            worse, rows, worse_gjk, worse_coal, runs, wrong, misses, no_verdict, bool_runs,
            bool_wrong, bool_no_verdict, bool_runs ? bool_calls / bool_runs : 0.0);
}

static const char *status_name(int status) { return agjk_status_string((agjk_status)status); }

/* Every agjk run the reference refutes, that misses its certified bound or
 * that ends without a verdict (at most `limit` lines; returns how many). */
static int list_agjk_trouble(FILE *f, const bench_stress *s, int limit) {
    int k, i, n = 0;
    for (k = 0; k < STRESS_COUNT; ++k) {
        const coal_bench_data *d = s->data[k];
        if (!d) continue;
        for (i = 0; i < d->count; ++i) {
            const coal_bench_record *r = &d->recs[i];
            const bench_problem *p = &s->sets[k].problems[r->agjk.problem];
            const bench_shape *a = &s->sets[k].shapes[p->a], *b = &s->sets[k].shapes[p->b];
            if (!r->agjk.wrong && !r->agjk.violation && r->agjk.converged) continue;
            if (n++ >= limit) continue;
            fprintf(f, "- %s, pair %d pose %d, signed distance %g, %s %s: agjk %s%s%s, "
                       "distance %.17g bound %.3g after %d iterations; reference %s "
                       "[%.17Lg, %.17Lg]; Coal %s, distance %.17g; sizes (%.17g, %.17g, %.17g) "
                       "and (%.17g, %.17g, %.17g), B at (%.17g, %.17g, %.17g)\n",
                    families[k].name, p->pair, p->pose, p->target,
                    r->agjk.mode ? "Boolean" : "distance", bench_method_name(r->agjk.method),
                    status_name(r->agjk.run.status), r->agjk.wrong ? " (wrong verdict)" : "",
                    r->agjk.violation ? " (certified interval misses the reference)" : "",
                    r->agjk.run.distance, r->agjk.run.bound, r->agjk.run.iterations,
                    p->ref.intersecting ? "intersecting" : "separated", p->ref.lower,
                    p->ref.upper, status_name(r->coal.run.status), r->coal.run.distance,
                    a->size.x, a->size.y, a->size.z, b->size.x, b->size.y, b->size.z,
                    p->pose_b.translation.x, p->pose_b.translation.y, p->pose_b.translation.z);
        }
    }
    return n;
}

int bench_stress_write(const bench_config *cfg, const bench_stress *s) {
    char path[1024];
    FILE *md, *csv, *outs[2];
    double *b0, *b1, *b2;
    int k, c, m, mode, max_count = 0, problems = 0;
    int trouble;
    coal_bench_answers a;
    snprintf(path, sizeof path, "%s/tables.md", cfg->out_dir);
    md = fopen(path, "a");
    if (!md) { perror(path); return -1; }
    fprintf(md, "## agjk vs Coal on a stress set\n\n");
    if (!s) {
        fprintf(md, "Not measured: %s.\n\n",
                !coal_adapter_available() ? "this agjk-bench was built without Coal "
                                            "(tools/fetch-coal.sh)"
                : cfg->coal_reps <= 0     ? "Coal runs disabled (--coal-reps 0)"
                                          : "disabled (--stress-pairs 0)");
        fclose(md);
        return 0;
    }
    for (k = 0; k < STRESS_COUNT; ++k) {
        if (!s->data[k]) continue;
        if (s->data[k]->count > max_count) max_count = s->data[k]->count;
        problems += s->sets[k].problem_count;
    }
    b0 = malloc(sizeof(double) * ((size_t)max_count + 8));
    b1 = malloc(sizeof(double) * ((size_t)max_count + 8));
    b2 = malloc(sizeof(double) * ((size_t)max_count + 8));
    if (!b0 || !b1 || !b2) abort();
    fprintf(md, "The comparison above (Coal %s, same methods, cap of %d iterations, initial "
                "guess, clock; R = %d runs per problem, agjk's right before Coal's; median of "
                "%d processes) on problems "
                "outside the protocol's comfortable range, %d pairs x %d poses per set, each "
                "judged by the certified reference: **stiff ellipsoids**, needles (two radii "
                "x 1e-3) and pancakes (one radius x 1e-3); **flat boxes**, one half extent x "
                "1e-4 or exactly 0 (plates); **tiny** and **huge**, the protocol's ellipsoids "
                "and boxes at scale 1e-4 and 1e4 (sizes, poses and signed distances; tolerance "
                "%g x scale^2, the same relative accuracy); **far**, the protocol's shapes with "
                "both poses moved 1e4 ... 1e6 from the world origin (log-uniform, random "
                "direction); **touching**, the protocol's shapes at signed distances -1e-6, "
                "-1e-9 (overlapping) and 1e-9, 1e-6 (close). The others use the protocol's 12 "
                "signed distances. Tolerance %g (absolute duality gap) unless scaled. "
                "%d problems x 4 methods x 2 modes; generated in %.1f s, timed in %.1f s.\n\n",
            coal_adapter_version(), cfg->max_iterations, s->reps, stress_processes(s), s->pairs,
            s->poses,
            s->tolerance, s->tolerance, problems, s->seconds_generate, s->seconds_run);
    outs[0] = md;
    outs[1] = stdout;
    printf("\nagjk / Coal %s on the stress set (results in %s/tables.md):\n\n",
           coal_adapter_version(), cfg->out_dir);
    ratio_table(outs, 2, s, b0, b1, b2);
    memset(&a, 0, sizeof a);
    for (k = 0; k < STRESS_COUNT; ++k)
        if (s->data[k]) coal_bench_count_answers(s->data[k], &a);
    for (k = 0; k < 2; ++k)
        fprintf(outs[k], "Answers of these %d runs against the certified reference: wrong "
                         "verdicts agjk %d, Coal %d; distances off by more than sqrt(tolerance) "
                         "agjk %d, Coal %d; no verdict agjk %d, Coal %d; agjk's certified "
                         "interval missing the reference %d; agjk's contact within tolerance "
                         "(|x| within the tolerance of 0: no side certified, not counted as "
                         "wrong or as no verdict) %d.\n\n",
                a.runs, a.agjk_wrong, a.coal_wrong, a.agjk_off, a.coal_off, a.agjk_nc, a.coal_nc,
                a.agjk_violations, a.agjk_contact);
    adaptive_table(md, s);
    trouble = a.agjk_wrong + a.agjk_violations + a.agjk_nc;
    if (trouble) {
        fprintf(md, "agjk runs to look at (wrong verdict, certified interval missing the "
                    "reference, or no verdict):\n\n");
        fprintf(stderr, "agjk-bench: stress set: %d agjk runs with a wrong verdict, a missed "
                        "bound or no verdict:\n", trouble);
        list_agjk_trouble(md, s, 20);
        list_agjk_trouble(stderr, s, 5);
        fprintf(md, "\n");
    }
    fprintf(md, "Generation: ");
    for (k = 0; k < STRESS_COUNT; ++k) {
        const bench_set *set = &s->sets[k];
        int i, bad = 0;
        for (i = 0; i < set->problem_count; ++i) bad += !set->problems[i].ref_ok;
        fprintf(md, "%s%s %d problems (%d poses re-drawn, %d pairs skipped, %d references "
                    "not converged and left unjudged, %d stalled within 1e-9, max |d_ref - "
                    "target| / scale %.1e)%s",
                k ? "; " : "", families[k].name, set->problem_count, set->rejected_poses,
                set->skipped_pairs, bad, set->ref_stalled, set->max_target_deviation,
                s->full[k] ? " (generator out of room)" : "");
    }
    fprintf(md, ".\n\n### Stress set details: median ns, support calls (mean), answers\n\n");
    snprintf(path, sizeof path, "%s/stress.csv", cfg->out_dir);
    csv = coal_bench_details_open(md, path, "stress set", "set", 1);
    for (k = 0; k < STRESS_COUNT; ++k) {
        if (!s->data[k]) continue;
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c)
            for (mode = 0; mode < 2; ++mode)
                for (m = 0; m < 4; ++m) {
                    coal_bench_group g = coal_bench_group_of(&s->sets[k], s->data[k],
                                                             families[k].base, c,
                                                             coal_bench_methods[m], mode, b0, b1,
                                                             b2);
                    if (!g.n) continue;
                    coal_bench_detail_row(md, csv, families[k].name, c, mode, m, &g, 1);
                }
    }
    fprintf(md, "\nColumns as in the details above; \"agjk bound misses\": agjk's certified "
                "interval [d - bound, d] misses the reference's (a result the library "
                "guarantees). The rounding slack of these checks is 1e-12 x max(1, scale, "
                "distance of the poses from the origin).\n\n");
    if (csv) fclose(csv);
    fclose(md);
    free(b0);
    free(b1);
    free(b2);
    return 0;
}
