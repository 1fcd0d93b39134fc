/* SPDX-License-Identifier: MIT */
/* agjk-bench: reproduces the experiments of Montaut et al., "Collision
 * Detection Accelerated: An Optimization Perspective" (RSS 2022), adds a
 * work-precision diagram and a Boolean-query comparison with libccd.
 * Run with --help for the options; `make bench` runs the default size. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"
#include "ccd_adapter.h"
#include "coal_bench.h"
#include "depth_bench.h"
#include "coherent.h"
#include "guard.h"
#include "hull_support.h"
#include "mesh_io.h"
#include "nesmino.h"
#include "stress.h"

const double wp_tolerances[WP_TOL_COUNT] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7,
                                            1e-8, 1e-9, 1e-10, 1e-11, 1e-12};

static void usage(FILE *f) {
    fprintf(f,
        "usage: agjk-bench [options]\n"
        "  --seed S          PRNG seed (default 1)\n"
        "  --pairs N         ellipsoid pairs (default 100; boxes N/2, hulls N/10 per size,\n"
        "                    meshes N/2)\n"
        "  --poses M         poses per pair (default 10; hulls and meshes M/2)\n"
        "  --reps R          timing repetitions, mean of the fastest 90%% (default 100)\n"
        "  --slow-reps R     repetitions for FW and NESMINO (default 5)\n"
        "  --slow-pairs K    FW/NESMINO run on the first pose of the first K pairs (default 50)\n"
        "  --slow-max-iter I iteration cap of FW and NESMINO (default 100000)\n"
        "  --max-iter I      iteration cap of GJK and the accelerated methods (default 1000)\n"
        "  --wp-pairs K      pairs in the work-precision run (default 20; 0 disables)\n"
        "  --wp-reps R       repetitions in the work-precision run (default 10)\n"
        "  --ccd-reps R      repetitions in the libccd timing (default 50; 0 disables it)\n"
        "  --coal-reps R     repetitions in the agjk/Coal timing (default 100; 0 disables it;\n"
        "                    needs a build with Coal: tools/fetch-coal.sh)\n"
        "  --stress-pairs K  pairs per family of the agjk/Coal stress set: stiff, flat, tiny,\n"
        "                    huge, far and nearly touching shapes (default 20; 0 disables it;\n"
        "                    runs with the Coal comparison, R = --coal-reps)\n"
        "  --stress-poses M  poses per pair of the stress set (default 5)\n"
        "  --processes K     run the timed comparisons (agjk/libccd, agjk/Coal on the\n"
        "                    protocol and the stress set) in K processes, each problem's\n"
        "                    times the median over them (default 3; 1 with --quick): one\n"
        "                    process can start slow for a library\n"
        "  --child FILE      (internal) one of those processes: run only the comparisons\n"
        "                    and save their times to FILE\n"
        "  --depth-reps R    repetitions in the penetration-depth comparison with libccd\n"
        "                    (default 20; 0 disables it)\n"
        "  --coherent-pairs K  pairs per family moved along smooth trajectories, queried\n"
        "                    cold, with hint + direction, and with agjk_cache (default 20;\n"
        "                    0 disables); --coherent-steps T (200), --coherent-reps R (10)\n"
        "  --tolerance T     duality-gap tolerance of the tables (default 1e-8)\n"
        "  --relative        read tolerances as relative (AGJK_TOLERANCE_RELATIVE: g <= T ||x||^2)\n"
        "                    for agjk's methods; default absolute, as in the paper\n"
        "  --nesmino-mu MU   NESMINO smoothing parameter (default 0: infinite, see nesmino.h)\n"
        "  --scan-support    polytopes without adjacency: every support call scans all\n"
        "                    vertices (default: Qhull hull + hill climbing, as HPP-FCL)\n"
        "  --mesh-dir DIR    also benchmark the meshes (OBJ/OFF) found in DIR\n"
        "  --max-meshes K    read at most K meshes (default 1000)\n"
        "  --mesh-scale S    multiply mesh coordinates by S (default 0.1: the pybullet\n"
        "                    random_urdfs objects then measure 0.2-0.8, like the paper's\n"
        "                    shapes; their URDFs use 0.015)\n"
        "  --out DIR         output directory (default results)\n"
        "  --raw FILE        also write every run to FILE (CSV)\n"
        "  --quick           a small run for development and CI (~10 s)\n");
}

static int parse(int argc, char **argv, bench_config *c) {
    int i;
    memset(c, 0, sizeof *c);
    c->seed = 1;
    c->pairs = 100;
    c->poses = 10;
    c->reps = 100;
    c->slow_reps = 5;
    c->slow_pairs = 50;
    c->slow_max_iterations = 100000;
    c->max_iterations = 1000;
    c->wp_pairs = 20;
    c->wp_reps = 10;
    c->ccd_reps = 50;
    c->coal_reps = 100;
    c->processes = 3;
    c->stress_pairs = 20;
    c->stress_poses = 5;
    c->depth_reps = 20;
    c->coherent_pairs = 20;
    c->coherent_steps = 200;
    c->coherent_reps = 10;
    c->max_meshes = 1000;
    c->tolerance = 1e-8;
    c->mesh_scale = 0.1;
    c->out_dir = "results";
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
#define INT_OPT(name, field) \
        if (strcmp(a, name) == 0 && v) { c->field = atoi(v); ++i; continue; }
        INT_OPT("--pairs", pairs)
        INT_OPT("--poses", poses)
        INT_OPT("--reps", reps)
        INT_OPT("--slow-reps", slow_reps)
        INT_OPT("--slow-pairs", slow_pairs)
        INT_OPT("--slow-max-iter", slow_max_iterations)
        INT_OPT("--max-iter", max_iterations)
        INT_OPT("--wp-pairs", wp_pairs)
        INT_OPT("--wp-reps", wp_reps)
        INT_OPT("--ccd-reps", ccd_reps)
        INT_OPT("--coal-reps", coal_reps)
        INT_OPT("--processes", processes)
        INT_OPT("--stress-pairs", stress_pairs)
        INT_OPT("--stress-poses", stress_poses)
        INT_OPT("--depth-reps", depth_reps)
        INT_OPT("--max-meshes", max_meshes)
        INT_OPT("--coherent-pairs", coherent_pairs)
        INT_OPT("--coherent-steps", coherent_steps)
        INT_OPT("--coherent-reps", coherent_reps)
#undef INT_OPT
        if (strcmp(a, "--relative") == 0) { c->relative = 1; continue; }
        if (strcmp(a, "--scan-support") == 0) { c->scan_support = 1; continue; }
        if (strcmp(a, "--tolerance") == 0 && v) { c->tolerance = atof(v); ++i; continue; }
        if (strcmp(a, "--nesmino-mu") == 0 && v) { c->nesmino_mu = atof(v); ++i; continue; }
        if (strcmp(a, "--mesh-scale") == 0 && v) { c->mesh_scale = atof(v); ++i; continue; }
        if (strcmp(a, "--seed") == 0 && v) { c->seed = strtoull(v, NULL, 0); ++i; continue; }
        if (strcmp(a, "--mesh-dir") == 0 && v) { c->mesh_dir = v; ++i; continue; }
        if (strcmp(a, "--out") == 0 && v) { c->out_dir = v; ++i; continue; }
        if (strcmp(a, "--raw") == 0 && v) { c->raw_path = v; ++i; continue; }
        if (strcmp(a, "--child") == 0 && v) { c->child = v; ++i; continue; }
        if (strcmp(a, "--quick") == 0) {
            c->quick = 1;
            c->pairs = 10;
            c->poses = 3;
            c->reps = 10;
            c->slow_reps = 2;
            c->slow_pairs = 5;
            c->slow_max_iterations = 20000;
            c->wp_pairs = 4;
            c->wp_reps = 3;
            c->ccd_reps = 5;
            c->coal_reps = 10;
            c->processes = 1;
            c->stress_pairs = 2;
            c->stress_poses = 2;
            c->depth_reps = 3;
            c->max_meshes = 100;
            c->coherent_pairs = 4;
            c->coherent_steps = 100;
            c->coherent_reps = 3;
            continue;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { usage(stdout); exit(0); }
        fprintf(stderr, "agjk-bench: unknown or incomplete option '%s'\n", a);
        usage(stderr);
        return -1;
    }
    if (c->pairs < 1 || c->poses < 1 || c->reps < 1 || c->slow_reps < 1 ||
        c->max_iterations < 1 || c->slow_max_iterations < 1 || c->max_meshes < 1 ||
        c->stress_poses < 1 || c->processes < 1) {
        fprintf(stderr, "agjk-bench: sizes must be >= 1\n");
        return -1;
    }
    c->box_pairs = c->pairs / 2 > 0 ? c->pairs / 2 : 1;
    c->hull_pairs = c->pairs / 10 > 2 ? c->pairs / 10 : 2;
    c->hull_poses = c->poses / 2 > 0 ? c->poses / 2 : 1;
    c->mesh_pairs = c->box_pairs;
    c->mesh_poses = c->hull_poses;
    return 0;
}

static const int hull_sizes[4] = {33, 141, 626, 2500};

/* Whether FW and NESMINO (slow: thousands of iterations on boxes) run on p. */
static int slow_subset(const bench_config *c, const bench_problem *p) {
    return p->pose == 0 && p->pair < c->slow_pairs;
}

static void progress(const char *phase, int done, int total, double t0) {
    static double last = 0;
    double now = bench_now_ns();
    if (done < total && now - last < 1e9) return;
    last = now;
    fprintf(stderr, "\r  %s: %d/%d (%.0f s)%s", phase, done, total, (now - t0) * 1e-9,
            done >= total ? "\n" : "");
    fflush(stderr);
}

/* Main measurement: every problem through every method that applies. */
static int run_main(const bench_config *c, const bench_set *set, bench_record *recs) {
    int i, n = 0;
    double t0 = bench_now_ns();
    for (i = 0; i < set->problem_count; ++i) {
        const bench_problem *p = &set->problems[i];
        int m, mode;
        for (m = 0; m < BM_COUNT; ++m) {
            int slow = m == BM_FW || m == BM_NESMINO;
            bench_solve_options o;
            if (slow && !slow_subset(c, p)) continue;
            /* FW and NESMINO belong to the paper's ellipsoid and cube table only. */
            if (slow && p->family != BENCH_ELLIPSOIDS && p->family != BENCH_BOXES) continue;
            o.tolerance = c->tolerance;
            o.relative = c->relative;
            o.max_iterations = slow ? c->slow_max_iterations : c->max_iterations;
            o.reps = slow ? c->slow_reps : c->reps;
            o.nesmino_gap_stop = 0; /* the paper's rule: ||x_k - x*|| <= sqrt(eps) */
            o.nesmino_mu = c->nesmino_mu;
            for (mode = 0; mode < 2; ++mode) {
                bench_record *r = &recs[n];
                memset(r, 0, sizeof *r);
                if (bench_solve(set, p, m, (bench_mode)mode, &o, &r->run) != 0) continue;
                r->problem = i;
                r->method = (signed char)m;
                r->mode = (signed char)mode;
                bench_evaluate(p, r);
                ++n;
            }
        }
        progress("timing", i + 1, set->problem_count, t0);
    }
    return n;
}

/* Work precision: the first pose of the first wp_pairs pairs of ellipsoids and
 * boxes, every tolerance, every method; NESMINO stops on its own duality gap
 * here so that all methods share one stopping rule. */
static void run_work_precision(const bench_config *c, const bench_set *set, bench_report *rep) {
    int fam, m, t, i, total = 0, done = 0;
    double t0 = bench_now_ns();
    double *err = malloc((size_t)set->problem_count * sizeof *err);
    double *ns = malloc((size_t)set->problem_count * sizeof *ns);
    if (!err || !ns) abort();
    for (i = 0; i < set->problem_count; ++i)
        if (set->problems[i].family <= BENCH_BOXES && set->problems[i].pose == 0 &&
            set->problems[i].pair < c->wp_pairs && set->problems[i].ref_ok)
            ++total;
    total *= BM_COUNT * WP_TOL_COUNT;
    for (fam = 0; fam < 2; ++fam)
        for (m = 0; m < BM_COUNT; ++m)
            for (t = 0; t < WP_TOL_COUNT; ++t) {
                wp_point *w = &rep->wp[fam][m][t];
                double it = 0;
                memset(w, 0, sizeof *w);
                for (i = 0; i < set->problem_count; ++i) {
                    const bench_problem *p = &set->problems[i];
                    bench_solve_options o;
                    bench_record r;
                    if (p->family != fam || p->pose != 0 || p->pair >= c->wp_pairs || !p->ref_ok)
                        continue;
                    o.tolerance = wp_tolerances[t];
                    o.relative = c->relative;
                    o.max_iterations = (m == BM_FW || m == BM_NESMINO) ? c->slow_max_iterations
                                                                       : c->max_iterations;
                    o.reps = (m == BM_FW || m == BM_NESMINO) && c->slow_reps < c->wp_reps
                                 ? c->slow_reps : c->wp_reps;
                    o.nesmino_gap_stop = 1;
                    o.nesmino_mu = c->nesmino_mu;
                    memset(&r, 0, sizeof r);
                    r.mode = BENCH_DISTANCE;
                    r.method = (signed char)m;
                    if (bench_solve(set, p, m, BENCH_DISTANCE, &o, &r.run) != 0) continue;
                    bench_evaluate(p, &r);
                    err[w->n] = r.error;
                    ns[w->n] = r.run.time_ns;
                    it += r.run.iterations;
                    w->not_converged += !r.converged;
                    w->n++;
                    rep->wp_problems[fam] = w->n;
                    progress("work-precision", ++done, total, t0);
                }
                w->it_mean = w->n ? it / w->n : 0;
                w->err_median = bench_median(err, w->n);
                w->ns_median = bench_median(ns, w->n);
            }
    if (done < total) progress("work-precision", total, total, t0);
    free(err);
    free(ns);
}

static void write_raw(const char *path, const bench_set *set, const bench_record *recs, int n) {
    FILE *f = fopen(path, "w");
    int i;
    if (!f) { perror(path); return; }
    fprintf(f, "family,pair,pose,target,method,mode,status,iterations,support_calls,time_ns,"
               "distance,bound,d_ref,ref_ok,error,violation,wrong\n");
    for (i = 0; i < n; ++i) {
        const bench_record *r = &recs[i];
        const bench_problem *p = &set->problems[r->problem];
        fprintf(f, "%s,%d,%d,%g,%s,%s,%s,%d,%d,%.1f,%.17g,%.3g,%.17Lg,%d,%.3g,%d,%d\n",
                bench_family_name(p->family), p->pair, p->pose, p->target,
                bench_method_name(r->method), r->mode ? "boolean" : "distance",
                agjk_status_string((agjk_status)r->run.status), r->run.iterations,
                r->run.support_calls, r->run.time_ns, r->run.distance, r->run.bound,
                p->ref.intersecting ? 0.0L : p->ref.distance, p->ref_ok, r->error, r->violation,
                r->wrong);
    }
    fclose(f);
}

/* The Boolean comparison with libccd, when asked for (cfg->ccd_reps > 0) and
 * libccd answers: *recs and *outcome allocated and filled (NULL otherwise),
 * its wall time in *seconds. Returns -1 when out of memory. */
static int run_ccd(const bench_config *cfg, const bench_set *set, ccd_bench_record **recs,
                   unsigned char **outcome, double *seconds) {
    ccd_bench_options co;
    double t0;
    int bad;
    *recs = NULL;
    *outcome = NULL;
    if (cfg->ccd_reps <= 0 || bench_ccd_check() != 0) return 0;
    *recs = calloc((size_t)set->problem_count + 1, sizeof **recs);
    *outcome = calloc((size_t)set->problem_count + 1, 1);
    if (!*recs || !*outcome) return -1;
    co.reps = cfg->ccd_reps;
    co.max_iterations = cfg->max_iterations;
    co.timeout_seconds = 10.0;
    co.columns = 0;
    co.tolerance = cfg->tolerance;
    fprintf(stderr, "agjk-bench: Boolean queries, agjk vs libccd (R = %d, each case "
                    "guarded by a 10 s watchdog)\n", cfg->ccd_reps);
    t0 = bench_now_ns();
    bad = ccd_bench_run(set, &co, *recs, *outcome);
    *seconds = (bench_now_ns() - t0) * 1e-9;
    fprintf(stderr, "  %d cases, %d hung or crashed, %.1f s\n", set->problem_count, bad, *seconds);
    return 0;
}

/* The coherent-motion benchmark when asked for (NULL otherwise). */
static bench_coherent *run_coherent(const bench_config *cfg, const bench_set *set) {
    if (cfg->coherent_pairs <= 0 || cfg->coherent_steps <= 0 || cfg->coherent_reps <= 0)
        return NULL;
    fprintf(stderr, "agjk-bench: coherent motion (%d pairs x %d steps, R = %d)\n",
            cfg->coherent_pairs, cfg->coherent_steps, cfg->coherent_reps);
    return bench_coherent_run(cfg, set, cfg->coherent_pairs, cfg->coherent_steps,
                              cfg->coherent_reps);
}

/* The stress set's Coal comparisons: at most this many families. */
#define STRESS_FAMILIES_MAX 16

/* The Coal comparisons that ran: the protocol's (coal, NULL: none), then the
 * stress set's families. Returns their number, at most 1 + STRESS_FAMILIES_MAX. */
static int coal_data_of(coal_bench_data *coal, bench_stress *stress, coal_bench_data **d) {
    int m = 0;
    if (coal) d[m++] = coal;
    return m + bench_stress_coal_data(stress, d + m, STRESS_FAMILIES_MAX);
}

/* libccd's four columns, agjk's and Coal's of each Coal comparison, the
 * coherent-motion rows: at most this many. */
#define COMPARISON_COLUMNS_MAX \
    (CB_COUNT + 2 * (1 + STRESS_FAMILIES_MAX) + BENCH_COHERENT_COLUMNS)

/* The columns of times of the comparisons that ran (ccd, coal, stress,
 * coherent NULL: not run), in a fixed order that the parent and its children
 * share (bench_repeat). Returns their number. */
static int comparison_times(bench_times *t, ccd_bench_record *ccd, int ccd_count,
                            coal_bench_data *coal, bench_stress *stress,
                            bench_coherent *coherent) {
    coal_bench_data *d[1 + STRESS_FAMILIES_MAX];
    int n = 0, m = coal_data_of(coal, stress, d), k;
    if (ccd && ccd_count > 0)
        for (k = 0; k < CB_COUNT; ++k, ++n) {
            t[n].first = &ccd[0].time_ns[k];
            t[n].count = ccd_count;
            t[n].stride = sizeof ccd[0];
        }
    for (k = 0; k < m; ++k) n += coal_bench_times(d[k], t + n);
    if (coherent) n += bench_coherent_times(coherent, t + n);
    return n;
}

int main(int argc, char **argv) {
    bench_config cfg;
    bench_set set;
    bench_rng rng;
    bench_mesh_source meshes;
    bench_report rep;
    bench_record *recs;
    ccd_bench_record *ccd_recs = NULL;
    unsigned char *ccd_outcome = NULL;
    coal_bench_data *coal;
    bench_stress *stress;
    bench_coherent *coherent;
    int h, cap_problems, cap_shapes, depth_missed = 0, coherent_bad = 0;
    double t0, t_all = bench_now_ns();
    static char command[1024];
    char mesh_note[256] = "";

    if (parse(argc, argv, &cfg) != 0) return 2;
    /* The output folder (one level), before any phase writes into it. */
    if (mkdir(cfg.out_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "agjk-bench: cannot create %s: %s\n", cfg.out_dir, strerror(errno));
        return 2;
    }
    {
        size_t len = 0;
        int i;
        for (i = 0; i < argc && len + 2 < sizeof command; ++i)
            len += (size_t)snprintf(command + len, sizeof command - len, "%s%s", i ? " " : "",
                                    argv[i]);
        cfg.command_line = command;
    }
    memset(&meshes, 0, sizeof meshes);
    memset(&rep, 0, sizeof rep);
    if (cfg.mesh_dir) {
        int got = bench_read_mesh_dir(cfg.mesh_dir, &meshes, cfg.max_meshes, cfg.mesh_scale);
        if (got < 0) {
            fprintf(stderr, "agjk-bench: cannot open mesh directory %s\n", cfg.mesh_dir);
            return 2;
        }
        fprintf(stderr, "agjk-bench: %d meshes read from %s\n", got, cfg.mesh_dir);
        snprintf(mesh_note, sizeof mesh_note, "%d meshes from %s, scaled by %g", got,
                 cfg.mesh_dir, cfg.mesh_scale);
    }
    cap_shapes = 2 * (cfg.pairs + cfg.box_pairs + 4 * cfg.hull_pairs + cfg.mesh_pairs) + 8;
    cap_problems = BENCH_TARGET_COUNT * (cfg.pairs * cfg.poses + cfg.box_pairs * cfg.poses +
                                         4 * cfg.hull_pairs * cfg.hull_poses +
                                         cfg.mesh_pairs * cfg.mesh_poses);
    bench_set_init(&set, cap_shapes, cap_problems);
    if (!cfg.scan_support) {
        set.polytope_hook = bench_hull_hook;
        set.aux_free = bench_hull_free;
    }

    fprintf(stderr, "agjk-bench %s: seed %llu; generating problems and reference distances\n",
            agjk_version_string(), (unsigned long long)cfg.seed);
    t0 = bench_now_ns();
    /* One stream per family, so that changing one family's size keeps the others. */
    bench_rng_seed(&rng, cfg.seed * 4 + 0);
    bench_generate(&set, BENCH_ELLIPSOIDS, cfg.pairs, cfg.poses, 0, NULL, &rng, 1, 1);
    bench_rng_seed(&rng, cfg.seed * 4 + 1);
    bench_generate(&set, BENCH_BOXES, cfg.box_pairs, cfg.poses, 0, NULL, &rng, 1, 1);
    bench_rng_seed(&rng, cfg.seed * 4 + 2);
    for (h = 0; h < 4; ++h)
        bench_generate(&set, BENCH_HULLS, cfg.hull_pairs, cfg.hull_poses, hull_sizes[h], NULL,
                       &rng, 1, 1);
    if (meshes.count > 0) {
        bench_rng_seed(&rng, cfg.seed * 4 + 3);
        bench_generate(&set, BENCH_MESHES, cfg.mesh_pairs, cfg.mesh_poses, 0, &meshes, &rng, 1,
                       1);
    }
    rep.seconds[0] = (bench_now_ns() - t0) * 1e-9;
    {
        int i, bad = 0;
        for (i = 0; i < set.problem_count; ++i) {
            const bench_problem *p = &set.problems[i];
            if (p->ref_ok) continue;
            if (bad++ < 5)
                fprintf(stderr, "  reference not converged: %s pair %d pose %d, signed distance "
                                "%g (vertices %d and %d); excluded from the error checks\n",
                        bench_family_name(p->family), p->pair, p->pose, p->target,
                        set.shapes[p->a].vertex_count, set.shapes[p->b].vertex_count);
        }
        fprintf(stderr, "  %d problems (%d poses re-drawn, %d pairs skipped, %d references "
                        "not converged, %d more stalled with bounds within 1e-9, kept), "
                        "max |d_ref - target| = %.2e, %.1f s\n",
                set.problem_count, set.rejected_poses, set.skipped_pairs, bad, set.ref_stalled,
                set.max_target_deviation, rep.seconds[0]);
    }

    if (cfg.child) {
        /* One of the processes of bench_repeat: the timed comparisons only,
         * in the parent's order, their times saved for it. */
        bench_times t[COMPARISON_COLUMNS_MAX];
        int n, rc;
        double seconds;
        if (run_ccd(&cfg, &set, &ccd_recs, &ccd_outcome, &seconds) != 0) return 2;
        coal = coal_bench_run(&cfg, &set);
        stress = bench_stress_run(&cfg);
        coherent = run_coherent(&cfg, &set);
        n = comparison_times(t, ccd_recs, ccd_recs ? set.problem_count : 0, coal, stress,
                             coherent);
        rc = bench_times_save(cfg.child, t, n) == 0 ? 0 : 2;
        bench_coherent_free(coherent);
        free(ccd_recs);
        free(ccd_outcome);
        coal_bench_free(coal);
        bench_stress_free(stress);
        bench_set_free(&set);
        bench_free_meshes(&meshes);
        return rc;
    }

    recs = calloc((size_t)set.problem_count * BM_COUNT * 2 + 1, sizeof *recs);
    if (!recs) return 2;
    fprintf(stderr, "agjk-bench: distance and Boolean queries, R = %d (FW, NESMINO: R = %d)\n",
            cfg.reps, cfg.slow_reps);
    t0 = bench_now_ns();
    rep.rec_count = run_main(&cfg, &set, recs);
    rep.seconds[1] = (bench_now_ns() - t0) * 1e-9;

    if (cfg.wp_pairs > 0) {
        fprintf(stderr, "agjk-bench: work-precision, tolerances 1e-2 ... 1e-12\n");
        t0 = bench_now_ns();
        run_work_precision(&cfg, &set, &rep);
        rep.seconds[2] = (bench_now_ns() - t0) * 1e-9;
    }

    if (run_ccd(&cfg, &set, &ccd_recs, &ccd_outcome, &rep.seconds[3]) != 0) return 2;
    if (ccd_recs) {
        rep.ccd = ccd_recs;
        rep.ccd_outcome = ccd_outcome;
        rep.ccd_count = set.problem_count;
        rep.ccd_processes = 1;
    }

    coal = coal_bench_run(&cfg, &set);
    stress = bench_stress_run(&cfg);
    coherent = run_coherent(&cfg, &set);
    if (cfg.processes > 1) {
        bench_times t[COMPARISON_COLUMNS_MAX];
        int n = comparison_times(t, ccd_recs, ccd_recs ? set.problem_count : 0, coal, stress,
                                 coherent);
        if (n > 0) {
            coal_bench_data *d[1 + STRESS_FAMILIES_MAX];
            int k, m = coal_data_of(coal, stress, d),
                   used = bench_repeat(t, n, argc, argv, cfg.out_dir, cfg.processes);
            for (k = 0; k < m; ++k) d[k]->processes = used;
            if (ccd_recs) rep.ccd_processes = used;
            if (coherent) bench_coherent_set_processes(coherent, used);
        }
    }
    if (cfg.depth_reps > 0 && bench_ccd_check() == 0) {
        depth_bench_options dopt = {cfg.depth_reps, cfg.max_iterations, cfg.tolerance, 10.0,
                                    cfg.out_dir};
        depth_missed = depth_bench_run(&set, &dopt); /* intervals missing the reference */
    }

    {
        /* What an empty timed region costs: included in every time reported. */
        double t[1000];
        int i;
        for (i = 0; i < 1000; ++i) {
            double a = bench_now_ns();
            t[i] = bench_now_ns() - a;
        }
        rep.clock_overhead_ns = bench_trimmed_mean(t, 1000);
    }
    rep.cfg = &cfg;
    rep.set = &set;
    rep.recs = recs;
    rep.mesh_note = mesh_note;
    rep.seconds[4] = (bench_now_ns() - t_all) * 1e-9;
    if (bench_write_reports(&rep) != 0) return 2;
    if (coal_bench_write(&rep, coal) != 0) return 2;
    if (bench_stress_write(&cfg, stress) != 0) return 2;
    bench_stress_free(stress);
    {
        /* The adaptive method against the paper's four and Coal (calls.c). */
        char path[1024];
        FILE *md;
        snprintf(path, sizeof path, "%s/tables.md", cfg.out_dir);
        md = fopen(path, "a");
        if (md) {
            bench_table_support_calls(md, &rep, coal);
            fclose(md);
        }
        bench_table_support_calls(stderr, &rep, coal);
    }
    coal_bench_free(coal);
    if (coherent) {
        coherent_bad = bench_coherent_write(&cfg, coherent);
        bench_coherent_free(coherent);
    }
    if (cfg.raw_path) write_raw(cfg.raw_path, &set, recs, rep.rec_count);
    {
        /* Exit status: non-zero if any result lies outside its certified bound. */
        int i, viol = 0, wrong = 0;
        for (i = 0; i < rep.rec_count; ++i) {
            viol += recs[i].violation;
            wrong += recs[i].wrong;
        }
        fprintf(stderr, "agjk-bench: done in %.0f s; %d results outside their certified bound, "
                        "%d wrong verdicts; tables in %s/tables.md\n",
                (bench_now_ns() - t_all) * 1e-9, viol, wrong, cfg.out_dir);
        free(recs);
        free(ccd_recs);
        free(ccd_outcome);
        bench_free_meshes(&meshes);
        bench_set_free(&set);
        return viol || wrong || depth_missed || coherent_bad ? 1 : 0;
    }
}
