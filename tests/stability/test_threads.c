/* SPDX-License-Identifier: MIT */
/* Thread safety (issue 5, item 5).
 *
 * query.h promises reentrant, thread-safe queries with no global state: shapes
 * and poses may be shared as long as nobody writes them. Several threads run
 * the same queries on the same shared shapes (including a polytope with
 * hill-climbing adjacency, whose warm-start hint lives in the query) and each
 * result must equal, byte for byte, the one computed beforehand by a single
 * thread. Run under ThreadSanitizer by `make check-tsan`. */
#include <check.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "agjk/polytope.h"
#include "stab_util.h"

#define NTHREADS 4
#define NQUERIES 96
#define ROUNDS 8

static agjk_ellipsoid g_ell = {{0.6, 0.3, 0.2}};
static agjk_box g_box = {{0.4, 0.2, 0.3}};
static agjk_capsule g_cap = {0.2, 0.4};
static agjk_cone g_cone = {0.3, 0.4};
/* Octahedron with its vertex graph (each vertex neighbours the four that are
 * not its opposite), so hill climbing is used. */
static const agjk_vec3 g_oct_v[6] = {{0.5, 0, 0}, {-0.5, 0, 0}, {0, 0.5, 0},
                                     {0, -0.5, 0}, {0, 0, 0.5}, {0, 0, -0.5}};
static const int32_t g_oct_off[7] = {0, 4, 8, 12, 16, 20, 24};
static const int32_t g_oct_nb[24] = {2, 3, 4, 5, 2, 3, 4, 5, 0, 1, 4, 5,
                                     0, 1, 4, 5, 0, 1, 2, 3, 0, 1, 2, 3};
static agjk_polytope g_oct = {g_oct_v, 6, g_oct_off, g_oct_nb};

#define NSHAPES 5
static agjk_shape g_shapes[NSHAPES];
static agjk_pose g_poses[NQUERIES][2];
static int g_pair[NQUERIES][2];
static agjk_options g_opts[NQUERIES];
static agjk_result g_expected[NQUERIES][2];

static void setup(void) {
    stab_rng rng = {3001};
    ck_assert_int_eq(agjk_shape_ellipsoid(&g_shapes[0], &g_ell), AGJK_STATUS_OK);
    ck_assert_int_eq(agjk_shape_box(&g_shapes[1], &g_box), AGJK_STATUS_OK);
    ck_assert_int_eq(agjk_shape_capsule(&g_shapes[2], &g_cap), AGJK_STATUS_OK);
    ck_assert_int_eq(agjk_shape_cone(&g_shapes[3], &g_cone), AGJK_STATUS_OK);
    ck_assert_int_eq(agjk_shape_polytope(&g_shapes[4], &g_oct), AGJK_STATUS_OK);
    for (int q = 0; q < NQUERIES; q++) {
        for (int k = 0; k < 2; k++) {
            stab_pose_identity(&g_poses[q][k]);
            stab_pose_random_rotation(&g_poses[q][k], &rng);
            g_poses[q][k].translation.x = stab_range(&rng, -0.8, 0.8);
            g_poses[q][k].translation.y = stab_range(&rng, -0.8, 0.8);
            g_poses[q][k].translation.z = stab_range(&rng, -0.8, 0.8);
            g_pair[q][k] = (int)(stab_next(&rng) % NSHAPES);
        }
        g_opts[q] = agjk_default_options();
        g_opts[q].method = (agjk_method)(q % 5);
        g_opts[q].tolerance_mode = (agjk_tolerance_mode)((q / 5) % 2);
        g_opts[q].hint_a = (int32_t)(q % 6);
        g_opts[q].hint_b = (int32_t)((q * 7) % 6);
    }
}

static void run_one(int q, agjk_result out[2]) {
    const agjk_shape *a = &g_shapes[g_pair[q][0]], *b = &g_shapes[g_pair[q][1]];
    memset(out, 0, 2 * sizeof out[0]);
    agjk_distance(a, &g_poses[q][0], b, &g_poses[q][1], &g_opts[q], &out[0]);
    agjk_collide(a, &g_poses[q][0], b, &g_poses[q][1], &g_opts[q], &out[1]);
}

typedef struct worker {
    int id;
    long mismatches;
} worker;

static void *work(void *arg) {
    worker *w = (worker *)arg;
    for (int round = 0; round < ROUNDS; round++)
        for (int i = 0; i < NQUERIES; i++) {
            /* Each thread walks the queries in its own order. */
            int q = (i * (2 * w->id + 1) + round) % NQUERIES;
            agjk_result r[2];
            run_one(q, r);
            if (memcmp(r, g_expected[q], sizeof r) != 0) w->mismatches++;
        }
    return NULL;
}

START_TEST(test_shared_shapes) {
    pthread_t th[NTHREADS];
    worker w[NTHREADS];
    long total = 0;
    setup();
    for (int q = 0; q < NQUERIES; q++) {
        run_one(q, g_expected[q]);
        ck_assert(g_expected[q][0].status != AGJK_STATUS_INVALID_INPUT);
    }
    for (int t = 0; t < NTHREADS; t++) {
        w[t].id = t;
        w[t].mismatches = 0;
        ck_assert_int_eq(pthread_create(&th[t], NULL, work, &w[t]), 0);
    }
    for (int t = 0; t < NTHREADS; t++) {
        ck_assert_int_eq(pthread_join(th[t], NULL), 0);
        total += w[t].mismatches;
    }
    printf("threads: %d threads x %d rounds x %d query pairs, %ld results differing from the "
           "single-thread run\n", NTHREADS, ROUNDS, NQUERIES, total);
    ck_assert_int_eq(total, 0);
}
END_TEST

int main(void) {
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("shared");
    SRunner *sr;
    int failed;
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_shared_shapes);
    suite_add_tcase(s, tc);
    sr = srunner_create(s);
    alarm(300);
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
