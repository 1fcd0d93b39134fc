/* SPDX-License-Identifier: MIT */
/* libccd comparison suite, correctness part (the timing part is in
 * `make bench`): the benchmark's problems (ellipsoids, boxes, hulls of 33 and
 * 141 points, at the 12 signed distances of Montaut et al. 2022) through
 * agjk_collide (GJK and the accelerated method) and through libccd's
 * ccdGJKIntersect and ccdMPRIntersect, each judged against the certified
 * long-double reference (tests/common/reference.h).
 *
 * A second set repeats the ellipsoids and boxes at scale 1e-3 (sizes, poses
 * and distances), where absolute epsilons inside a solver change its answers;
 * agjk's tolerance is scaled with the problem (tolerance * scale^2).
 *
 * Fails if agjk gives one certified verdict the reference refutes, if an agjk
 * query hangs or crashes, or if the reference itself fails. libccd's errors
 * are counted and shown with examples but do not fail the test: they are
 * libccd's (absolute tolerances, unbounded MPR refinement), not ours. Every
 * case runs in a watchdog child (tools/bench/guard.h), one pass per solver, so
 * a libccd loop that ignores max_iterations cannot hang `make check`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../tools/bench/ccd_adapter.h"
#include "../../tools/bench/ccd_bench.h"
#include "../../tools/bench/guard.h"

#define SEED 20220509u
#define EXAMPLES 4

typedef struct tally {
    int cases, wrong, no_verdict, guard_failures;
    int wrong_by_cat[BENCH_FAMILY_COUNT][BENCH_CATEGORY_COUNT];
    int shown;
} tally;

/* A verdict is wrong when the certified reference refutes it: "intersecting"
 * while the reference's lower bound is positive, or "separated" while the
 * reference certifies an overlap. */
static int refuted(const bench_problem *p, int answer) {
    if (!p->ref_ok || answer < 0) return 0;
    if (answer == 1) return !p->ref.intersecting && p->ref.lower > 1e-12;
    return p->ref.intersecting;
}

static void show(const bench_problem *p, int column, int answer) {
    printf("    e.g. %s (scale %g) pair %d pose %d, signed distance %g: %s says %s; reference %s "
           "(distance in [%.3Lg, %.3Lg]); B at (%.6f, %.6f, %.6f)\n",
           bench_family_name(p->family), p->scale, p->pair, p->pose, p->target,
           ccd_bench_column_name(column), answer ? "intersecting" : "separated",
           p->ref.intersecting ? "intersecting" : "separated", p->ref.lower, p->ref.upper,
           p->pose_b.translation.x, p->pose_b.translation.y, p->pose_b.translation.z);
}

int main(void) {
    bench_set set;
    bench_rng rng;
    ccd_bench_record *recs;
    unsigned char *outcome;
    tally t[CB_COUNT];
    ccd_bench_options o;
    int i, col, pass, fam, c, ref_bad = 0, failed = 0, agjk_undecided_far = 0, first_small;
    int small_wrong[CB_COUNT] = {0}, small_cases = 0;
    static const unsigned passes[3] = {(1u << CB_AGJK_GJK) | (1u << CB_AGJK_ACCEL),
                                       1u << CB_CCD_GJK, 1u << CB_CCD_MPR};

    if (bench_ccd_check() != 0) {
        printf("SKIP: libccd is not a double-precision build\n");
        return 0;
    }
    bench_set_init(&set, 256, 4096);
    bench_rng_seed(&rng, SEED);
    bench_generate(&set, BENCH_ELLIPSOIDS, 12, 4, 0, NULL, &rng, 1, 0);
    bench_generate(&set, BENCH_BOXES, 12, 4, 0, NULL, &rng, 1, 0);
    bench_generate(&set, BENCH_HULLS, 4, 2, 33, NULL, &rng, 1, 0);
    bench_generate(&set, BENCH_HULLS, 4, 2, 141, NULL, &rng, 1, 0);
    /* The same protocol at millimetre scale (sizes, poses and distances times
     * 1e-3): absolute epsilons inside a solver show up here. */
    set.scale = 1e-3;
    first_small = set.problem_count;
    bench_generate(&set, BENCH_ELLIPSOIDS, 8, 3, 0, NULL, &rng, 1, 0);
    bench_generate(&set, BENCH_BOXES, 8, 3, 0, NULL, &rng, 1, 0);
    for (i = 0; i < set.problem_count; ++i) ref_bad += !set.problems[i].ref_ok;
    small_cases = set.problem_count - first_small;
    printf("%d problems (ellipsoids, boxes, hulls N = 33 and 141, and %d ellipsoid/box "
           "problems at scale 1e-3; 12 signed distances); reference failed on %d\n",
           set.problem_count, small_cases, ref_bad);
    if (set.problem_count < 1500 || ref_bad > set.problem_count / 100) {
        printf("FAIL: problem generation or the reference solver\n");
        return 1;
    }

    recs = calloc((size_t)set.problem_count, sizeof *recs);
    outcome = calloc((size_t)set.problem_count, 1);
    if (!recs || !outcome) return 1;
    memset(t, 0, sizeof t);
    o.reps = 0;
    o.max_iterations = 1000;
    o.timeout_seconds = 5.0;
    o.tolerance = 1e-8; /* times scale^2: the same relative accuracy at every scale */
    for (pass = 0; pass < 3; ++pass) {
        ccd_bench_record *part = calloc((size_t)set.problem_count, sizeof *part);
        if (!part) return 1;
        o.columns = passes[pass];
        if (ccd_bench_run(&set, &o, part, outcome) < 0) {
            printf("FAIL: cannot fork the watchdog child\n");
            return 1;
        }
        for (i = 0; i < set.problem_count; ++i)
            for (col = 0; col < CB_COUNT; ++col) {
                const bench_problem *p = &set.problems[i];
                tally *k = &t[col];
                int answer;
                if (!(passes[pass] & (1u << col))) continue;
                k->cases++;
                if (outcome[i] != GUARD_OK) {
                    k->guard_failures++;
                    if (k->shown++ < EXAMPLES)
                        printf("    %s %s on %s pair %d pose %d, signed distance %g\n",
                               ccd_bench_column_name(col),
                               outcome[i] == GUARD_HUNG ? "hung" : "crashed",
                               bench_family_name(p->family), p->pair, p->pose, p->target);
                    continue;
                }
                answer = part[i].answer[col];
                recs[i].answer[col] = answer;
                if (answer < 0) {
                    k->no_verdict++;
                    if (col <= CB_AGJK_ACCEL && (p->target >= 0.1 * p->scale ||
                                                 p->target <= -0.1 * p->scale))
                        agjk_undecided_far++;
                } else if (refuted(p, answer)) {
                    k->wrong++;
                    if (i >= first_small) small_wrong[col]++;
                    else k->wrong_by_cat[p->family][p->category]++;
                    if (k->shown++ < EXAMPLES) show(p, col, answer);
                }
            }
        free(part);
    }

    printf("\n%-18s %6s %6s %10s %14s\n", "solver", "cases", "wrong", "no verdict",
           "hung/crashed");
    for (col = 0; col < CB_COUNT; ++col)
        printf("%-18s %6d %6d %10d %14d\n", ccd_bench_column_name(col), t[col].cases,
               t[col].wrong, t[col].no_verdict, t[col].guard_failures);
    printf("\nwrong verdicts by family and category (agjk GJK / accel. / libccd GJK / MPR):\n");
    printf("  scale 1e-3 (%d problems): %d / %d / %d / %d\n", small_cases, small_wrong[0],
           small_wrong[1], small_wrong[2], small_wrong[3]);
    for (fam = 0; fam < BENCH_HULLS + 1; ++fam)
        for (c = 0; c < BENCH_CATEGORY_COUNT; ++c)
            printf("  %-10s %-11s %d / %d / %d / %d\n", bench_family_name(fam),
                   bench_category_name(c), t[0].wrong_by_cat[fam][c], t[1].wrong_by_cat[fam][c],
                   t[2].wrong_by_cat[fam][c], t[3].wrong_by_cat[fam][c]);
    printf("(agjk's \"no verdict\" is contact within tolerance: |d| below sqrt(1e-8 s^2) = "
           "1e-4 s at scale s.)\n");

    for (col = CB_AGJK_GJK; col <= CB_AGJK_ACCEL; ++col) {
        if (t[col].wrong > 0) {
            printf("FAIL: %s gave %d verdicts the certified reference refutes\n",
                   ccd_bench_column_name(col), t[col].wrong);
            failed = 1;
        }
        if (t[col].guard_failures > 0) {
            printf("FAIL: %s hung or crashed %d times\n", ccd_bench_column_name(col),
                   t[col].guard_failures);
            failed = 1;
        }
    }
    if (agjk_undecided_far > 0) {
        printf("FAIL: agjk gave no verdict on %d problems at |d| >= 0.1\n", agjk_undecided_far);
        failed = 1;
    }
    free(recs);
    free(outcome);
    bench_set_free(&set);
    printf("%s\n", failed ? "FAIL" : "PASS (libccd's disagreements are reported, not failed)");
    return failed;
}
