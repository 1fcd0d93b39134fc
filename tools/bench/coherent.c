/* SPDX-License-Identifier: MIT */
/* Coherent-motion benchmark (see coherent.h).
 *
 * Trajectory of a pair, step i of T, at speed v (1: slow, 5: fast): A turns
 * about a random axis through its origin by 0.001 v rad per step; B turns
 * about its own random axis by 0.002 v rad per step and slides along the
 * initial separation axis n so that, before the rotations, the distance is
 * r (0.01 + 0.04 sin(2 pi v i / T)) (r: B's bounding radius): the pair goes
 * from close proximity through a shallow overlap of up to 3% of r and back,
 * v times; both also drift by 0.001 r per step in world space. At T = 200 and
 * v = 1 a point of B's surface moves by at most about 0.3% of r per step.
 * Every step is queried (agjk_distance, default method) three ways:
 *   cold   default options;
 *   hint   the previous result's hints and -normal as initial direction
 *          (agjk_options::use_initial_direction, hint_a, hint_b);
 *   cache  agjk_distance_cached with one agjk_cache per pair.
 * Support calls are those of one pass; times are the median over `reps`
 * passes of (pass time / T), then the median over pairs. */
#include "coherent.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "solve.h"

enum { CO_COLD = 0, CO_HINT, CO_CACHE, CO_MODES };
enum { CO_ROWS = 6 }; /* ellipsoids, boxes, meshes at speeds 1 and 5 */
static const char *const co_mode_names[CO_MODES] = {"cold", "hint + direction", "cache"};
/* bench_coherent_times' columns: one per row and mode. */
typedef char co_columns_fit[CO_ROWS * CO_MODES == BENCH_COHERENT_COLUMNS ? 1 : -1];

/* Rotation by `angle` about the unit `axis` (Rodrigues), row-major. */
static void axis_rotation(agjk_vec3 axis, double angle, double r[3][3]) {
    double c = cos(angle), s = sin(angle), t = 1.0 - c;
    double x = axis.x, y = axis.y, z = axis.z;
    r[0][0] = t * x * x + c;     r[0][1] = t * x * y - s * z; r[0][2] = t * x * z + s * y;
    r[1][0] = t * x * y + s * z; r[1][1] = t * y * y + c;     r[1][2] = t * y * z - s * x;
    r[2][0] = t * x * z - s * y; r[2][1] = t * y * z + s * x; r[2][2] = t * z * z + c;
}

/* out = a b; out may be b. */
static void mat_mul(double a[3][3], double b[3][3], double out[3][3]) {
    double t[3][3];
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j)
            t[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    memcpy(out, t, sizeof t);
}

typedef struct co_path {
    agjk_pose a0, b0;   /* poses at step 0 before the slide */
    agjk_vec3 n;        /* separation axis, A towards B */
    agjk_vec3 axis_a, axis_b;
    double d0;          /* distance of the base poses */
    double r;           /* B's bounding radius */
    double speed;
    int steps;
} co_path;

static void path_pose(const co_path *p, int i, agjk_pose *pa, agjk_pose *pb) {
    double ra[3][3], rb[3][3];
    double phase = 2.0 * 3.14159265358979323846 * p->speed * i / p->steps;
    double slide = p->r * (0.01 + 0.04 * sin(phase)) - p->d0;
    agjk_vec3 drift;
    drift.x = drift.y = drift.z = 0.001 * p->r * i;
    axis_rotation(p->axis_a, 0.001 * p->speed * i, ra);
    axis_rotation(p->axis_b, 0.002 * p->speed * i, rb);
    *pa = p->a0;
    mat_mul(ra, pa->rotation, pa->rotation);
    pa->translation.x += drift.x;
    pa->translation.y += drift.y;
    pa->translation.z += drift.z;
    *pb = p->b0;
    mat_mul(rb, pb->rotation, pb->rotation);
    pb->translation.x += slide * p->n.x + drift.x;
    pb->translation.y += slide * p->n.y + drift.y;
    pb->translation.z += slide * p->n.z + drift.z;
}

/* One pass over the trajectory in `mode`; results into res[0..steps-1]. */
static void run_pass(const bench_shape *a, const bench_shape *b, const co_path *p, int mode,
                     const agjk_pose *pa, const agjk_pose *pb, agjk_result *res) {
    agjk_cache cache;
    agjk_options o = agjk_default_options();
    int i;
    o.compute = AGJK_COMPUTE_DISTANCE; /* as the paper's tables */
    agjk_cache_init(&cache);
    for (i = 0; i < p->steps; ++i) {
        if (mode == CO_CACHE) {
            agjk_distance_cached(&a->shape, &pa[i], &b->shape, &pb[i], &o, &cache, &res[i]);
            continue;
        }
        if (mode == CO_HINT && i > 0) {
            o.use_initial_direction = 1;
            o.initial_direction.x = -res[i - 1].normal.x;
            o.initial_direction.y = -res[i - 1].normal.y;
            o.initial_direction.z = -res[i - 1].normal.z;
            o.use_initial_direction = res[i - 1].status != AGJK_STATUS_INTERSECTING;
            o.hint_a = res[i - 1].hint_a;
            o.hint_b = res[i - 1].hint_b;
        }
        agjk_distance(&a->shape, &pa[i], &b->shape, &pb[i], &o, &res[i]);
    }
}

static int cmp_int(const void *x, const void *y) {
    int a = *(const int *)x, b = *(const int *)y;
    return (a > b) - (a < b);
}

typedef struct co_stats {
    long queries, calls;
    int *calls_all;        /* every query's support calls, for the median */
    double *ns;            /* per pair: median ns per query */
    int pairs;
    int status_diff;       /* status differs from cold */
    int contradictions;    /* separated vs intersecting, or distances apart */
} co_stats;

static const int families[CO_ROWS] = {BENCH_ELLIPSOIDS, BENCH_ELLIPSOIDS, BENCH_BOXES,
                                      BENCH_BOXES, BENCH_MESHES, BENCH_MESHES};
static const double speeds[CO_ROWS] = {1, 5, 1, 5, 1, 5};

struct bench_coherent {
    co_stats st[CO_ROWS][CO_MODES];
    int pairs, steps, reps;
    int bad;        /* contradictions, all rows */
    int processes;  /* the per-pair times are medians over this many (repeat.h) */
};

bench_coherent *bench_coherent_run(const bench_config *cfg, const bench_set *set, int pairs,
                                   int steps, int reps) {
    bench_coherent *c = calloc(1, sizeof *c);
    co_stats (*st)[CO_MODES];
    agjk_pose *pa = malloc((size_t)steps * sizeof *pa), *pb = malloc((size_t)steps * sizeof *pb);
    agjk_result *res[CO_MODES];
    double *pass_ns = malloc((size_t)(reps > 0 ? reps : 1) * sizeof *pass_ns);
    bench_rng rng;
    int f, m;
    if (!c || !pa || !pb || !pass_ns) abort();
    st = c->st;
    c->pairs = pairs;
    c->steps = steps;
    c->reps = reps;
    c->processes = 1;
    for (m = 0; m < CO_MODES; ++m) {
        res[m] = malloc((size_t)steps * sizeof *res[m]);
        if (!res[m]) abort();
    }
    bench_rng_seed(&rng, cfg->seed * 4 + 77);
    for (f = 0; f < CO_ROWS; ++f) {
        int i, done = 0;
        for (m = 0; m < CO_MODES; ++m) {
            st[f][m].calls_all = malloc((size_t)pairs * steps * sizeof(int) + 8);
            st[f][m].ns = malloc((size_t)pairs * sizeof(double) + 8);
            if (!st[f][m].calls_all || !st[f][m].ns) abort();
        }
        for (i = 0; i < set->problem_count && done < pairs; ++i) {
            const bench_problem *q = &set->problems[i];
            const bench_shape *a, *b;
            co_path p;
            int k, r;
            if (q->family != families[f] || q->pose != 0 || q->target_index != 5) continue;
            a = &set->shapes[q->a];
            b = &set->shapes[q->b];
            p.a0 = q->pose_a;
            p.b0 = q->pose_b;
            p.d0 = q->target;
            p.n.x = -q->xstar.x / q->target;
            p.n.y = -q->xstar.y / q->target;
            p.n.z = -q->xstar.z / q->target;
            p.axis_a = bench_rng_unit(&rng);
            p.axis_b = bench_rng_unit(&rng);
            p.r = b->radius;
            p.speed = speeds[f];
            p.steps = steps;
            for (k = 0; k < steps; ++k) path_pose(&p, k, &pa[k], &pb[k]);
            for (m = 0; m < CO_MODES; ++m) {
                co_stats *s = &st[f][m];
                run_pass(a, b, &p, m, pa, pb, res[m]);
                for (r = 0; r < reps; ++r) {
                    double t0 = bench_now_ns();
                    run_pass(a, b, &p, m, pa, pb, res[m]);
                    pass_ns[r] = (bench_now_ns() - t0) / steps;
                }
                s->ns[s->pairs++] = bench_median(pass_ns, reps);
                for (k = 0; k < steps; ++k) {
                    const agjk_result *x = &res[m][k], *cold = &res[CO_COLD][k];
                    s->calls_all[s->queries++] = x->support_calls;
                    s->calls += x->support_calls;
                    if (m == CO_COLD) continue;
                    if (x->status != cold->status) s->status_diff++;
                    if ((x->status == AGJK_STATUS_SEPARATED && cold->status == AGJK_STATUS_INTERSECTING) ||
                        (x->status == AGJK_STATUS_INTERSECTING && cold->status == AGJK_STATUS_SEPARATED) ||
                        fabs(x->distance - cold->distance) > x->bound + cold->bound + 1e-12 * p.r) {
                        s->contradictions++;
                        ++c->bad;
                    }
                }
            }
            ++done;
        }
    }
    for (m = 0; m < CO_MODES; ++m) free(res[m]);
    free(pa);
    free(pb);
    free(pass_ns);
    (void)cfg;
    return c;
}

int bench_coherent_times(bench_coherent *c, bench_times *out) {
    int f, m, n = 0;
    for (f = 0; f < CO_ROWS; ++f)
        for (m = 0; m < CO_MODES; ++m) {
            co_stats *s = &c->st[f][m];
            if (s->pairs == 0) continue;
            out[n].first = s->ns;
            out[n].count = s->pairs;
            out[n].stride = sizeof s->ns[0];
            ++n;
        }
    return n;
}

void bench_coherent_set_processes(bench_coherent *c, int processes) { c->processes = processes; }

int bench_coherent_write(const bench_config *cfg, bench_coherent *c) {
    co_stats (*st)[CO_MODES] = c->st;
    int f, m, pairs = c->pairs, steps = c->steps, reps = c->reps;
    FILE *md, *csv;
    char path[1024];
    snprintf(path, sizeof path, "%s/tables.md", cfg->out_dir);
    md = fopen(path, "a");
    snprintf(path, sizeof path, "%s/coherent.csv", cfg->out_dir);
    csv = fopen(path, "w");
    if (csv)
        fprintf(csv, "family,speed,mode,pairs,queries,support_calls_mean,support_calls_median,"
                     "ns_per_query_median,calls_ratio_vs_cold,time_ratio_vs_cold,"
                     "status_differs_from_cold,contradictions\n");
    {
        FILE *outs[2];
        int o;
        outs[0] = md;
        outs[1] = stderr;
        for (o = 0; o < 2; ++o) {
            FILE *out = outs[o];
            if (!out) continue;
            fprintf(out, "\n## Coherent motion: the same pair along a smooth trajectory "
                         "(agjk_distance, default method)\n\n"
                         "%d pairs per family, %d steps per trajectory. Slow: A and B turn "
                         "by 0.001 and 0.002 rad per step while B slides from 5%% of its "
                         "radius apart to 3%% overlap and back once; fast: 5 times that "
                         "(tools/bench/coherent.c). ns per query: median over pairs of the "
                         "median of %d passes (each pair's time the median over %d "
                         "process%s, see tools/bench/repeat.h). "
                         "Status differs / contradictions: against the cold query of the "
                         "same step (contradiction: separated vs intersecting, or distances "
                         "further apart than the two certified bounds).\n\n"
                         "| set | motion | mode | queries | support calls mean | median | "
                         "ns/query (median) | calls vs cold | time vs cold | status differs | "
                         "contradictions |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
                    pairs, steps, reps, c->processes, c->processes == 1 ? "" : "es");
            for (f = 0; f < CO_ROWS; ++f) {
                double cold_calls = 0, cold_ns = 0;
                for (m = 0; m < CO_MODES; ++m) {
                    co_stats *s = &st[f][m];
                    double mean, med_calls, ns;
                    if (s->queries == 0) continue;
                    mean = (double)s->calls / s->queries;
                    if (o == 0) qsort(s->calls_all, (size_t)s->queries, sizeof(int), cmp_int);
                    med_calls = s->calls_all[s->queries / 2];
                    if (o == 0) s->ns[s->pairs] = bench_median(s->ns, s->pairs);
                    ns = s->ns[s->pairs];
                    if (m == CO_COLD) { cold_calls = mean; cold_ns = ns; }
                    fprintf(out, "| %s | %s | %s | %ld | %.2f | %.0f | %.0f | %.2fx | %.2fx | %d | %d |\n",
                            bench_family_name(families[f]), speeds[f] > 1 ? "fast" : "slow",
                            co_mode_names[m], s->queries, mean,
                            med_calls, ns, cold_calls / mean, cold_ns / ns, s->status_diff,
                            s->contradictions);
                    if (o == 0 && csv)
                        fprintf(csv, "%s,%g,%s,%d,%ld,%.4f,%.0f,%.1f,%.4f,%.4f,%d,%d\n",
                                bench_family_name(families[f]), speeds[f], co_mode_names[m], s->pairs,
                                s->queries, mean, med_calls, ns, cold_calls / mean,
                                cold_ns / ns, s->status_diff, s->contradictions);
                }
            }
        }
    }
    if (md) fclose(md);
    if (csv) fclose(csv);
    return c->bad;
}

void bench_coherent_free(bench_coherent *c) {
    int f, m;
    if (!c) return;
    for (f = 0; f < CO_ROWS; ++f)
        for (m = 0; m < CO_MODES; ++m) {
            free(c->st[f][m].calls_all);
            free(c->st[f][m].ns);
        }
    free(c);
}
