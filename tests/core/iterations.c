/* SPDX-License-Identifier: MIT */
/* Mean iterations of each method on random ellipsoid pairs at fixed signed
 * distances (the paper's protocol, Montaut et al. 2022 Sec. V-A: radii
 * ~ N(0.1, 0.025) x {1, 5, 10}, random relative poses, shape B slid along the
 * closest-point axis; absolute tolerance 1e-8 on the duality gap, at most 1000
 * iterations). The paper reports ~16 (GJK) and ~7 (Nesterov) iterations in
 * close proximity. Built by `make`, not a test (no pass/fail):
 *   out/tests/core/iterations [pairs per distance, default 1000] [seed] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testutil.h"

static const double distances[] = {-0.1, -0.01, -1e-3, -1e-4, 1e-4, 1e-3, 1e-2, 0.1, 0.5, 1.0, 5.0};
#define N_DIST ((int)(sizeof distances / sizeof distances[0]))
#define N_METHODS 5
static const agjk_method methods[N_METHODS] = {AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV,
                                               AGJK_METHOD_NESTEROV_NORMALIZED, AGJK_METHOD_POLYAK,
                                               AGJK_METHOD_ADAPTIVE};

int main(int argc, char **argv) {
    int pairs = argc > 1 ? atoi(argv[1]) : 1000;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 10) : 2022;
    if (pairs < 1) pairs = 1;
    tu_rng rng;
    tu_rng_seed(&rng, seed);
    printf("# %d ellipsoid pairs per distance, seed %llu, absolute tolerance 1e-8, cap 1000\n", pairs,
           (unsigned long long)seed);
    printf("# query     distance   gjk  nesterov  normalized  polyak  adaptive   (mean iterations;"
           " support calls of adaptive)\n");
    double close_sum[2][N_METHODS] = {{0}};
    int close_n = 0;
    for (int q = 0; q < 2; q++) {
        tu_rng_seed(&rng, seed);
        for (int k = 0; k < N_DIST; k++) {
            double it_sum[N_METHODS] = {0}, adaptive_calls = 0;
            for (int i = 0; i < pairs; i++) {
                ref_shape a, b;
                double sc = tu_paper_scale(&rng);
                tu_random_ellipsoid(&rng, &a, sc);
                tu_random_ellipsoid(&rng, &b, sc);
                agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
                if (tu_set_distance(&a, &pa, &b, &pb, distances[k], NULL) != 0) continue;
                agjk_shape sa, sb;
                ref_make_agjk(&a, &sa);
                ref_make_agjk(&b, &sb);
                for (int m = 0; m < N_METHODS; m++) {
                    agjk_options o = agjk_default_options();
                    o.method = methods[m];
                    o.max_iterations = 1000;
                    agjk_result r;
                    if (q == 0) agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
                    else agjk_collide(&sa, &pa, &sb, &pb, &o, &r);
                    it_sum[m] += r.iterations;
                    if (methods[m] == AGJK_METHOD_ADAPTIVE) adaptive_calls += r.support_calls;
                }
            }
            printf("%-9s %9.0e %6.2f %9.2f %11.2f %7.2f %9.2f (%.2f)\n", q == 0 ? "distance" : "collide",
                   distances[k], it_sum[0] / pairs, it_sum[1] / pairs, it_sum[2] / pairs,
                   it_sum[3] / pairs, it_sum[4] / pairs, adaptive_calls / pairs);
            if (distances[k] > 0 && distances[k] <= 0.1) {
                for (int m = 0; m < N_METHODS; m++) close_sum[q][m] += it_sum[m] / pairs;
                if (q == 0) close_n++;
            }
        }
    }
    for (int q = 0; q < 2; q++)
        printf("# close proximity (1e-4 .. 0.1), %s: mean iterations gjk %.2f, nesterov %.2f, "
               "normalized %.2f, polyak %.2f, adaptive %.2f (paper: ~16 and ~7)\n",
               q == 0 ? "distance" : "collide", close_sum[q][0] / close_n, close_sum[q][1] / close_n,
               close_sum[q][2] / close_n, close_sum[q][3] / close_n, close_sum[q][4] / close_n);
    return 0;
}
