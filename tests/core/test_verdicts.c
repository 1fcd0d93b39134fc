/* SPDX-License-Identifier: MIT */
/* A verdict whenever the certificate allows one, and a truthful reason when it
 * does not:
 * - a point facing a triangulated cube face (GJK's progress there is below the
 *   rounding of ||x||^2 while the gap is already 0) converges;
 * - random polytope pairs at gaps 1e-9 ... 1 of their size, at the most
 *   accurate tolerance (1e-300, raised to the floating-point floor), converge
 *   with a certified interval holding the long-double reference at both ends;
 * - NOT_CONVERGED carries its stop reason (iteration cap, relative accuracy
 *   below double precision), every other status AGJK_STOP_NONE. */
#include <math.h>
#include <stdio.h>
#include "core_checks.h"

static const agjk_method all_methods[] = {AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV,
                                          AGJK_METHOD_NESTEROV_NORMALIZED, AGJK_METHOD_POLYAK,
                                          AGJK_METHOD_FRANK_WOLFE};
#define N_METHODS ((int)(sizeof all_methods / sizeof all_methods[0]))

/* The unit cube's 8 corners (support by scan: the solver meets the face
 * through its triangles' vertices, one at a time). */
static void unit_cube(agjk_vec3 v[8]) {
    int n = 0;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            for (int k = 0; k < 2; k++) v[n++] = tu_vec(i - 0.5, j - 0.5, k - 0.5);
}

START_TEST(point_facing_cube_face) {
    agjk_vec3 cube[8];
    unit_cube(cube);
    agjk_polytope pc = {cube, 8, NULL, NULL};
    agjk_shape sc;
    TU_CHECK_INT_EQ(agjk_shape_polytope(&sc, &pc), AGJK_STATUS_OK);
    tu_rng rng;
    tu_rng_seed(&rng, 10);
    int queries = 0;
    for (int i = 0; i < 200; i++) {
        /* A point in front of the face x = 9.5, off its centre by 1e-9 ... 0.3. */
        double off = i == 0 ? 1e-7 : pow(10.0, -9.0 + 8.5 * tu_uniform(&rng));
        double ang = 6.283185307179586 * tu_uniform(&rng);
        agjk_vec3 p = tu_vec(1.0, i == 0 ? off : off * cos(ang), i == 0 ? 0.0 : off * sin(ang));
        agjk_polytope pp = {&p, 1, NULL, NULL};
        agjk_shape sp;
        TU_CHECK_INT_EQ(agjk_shape_polytope(&sp, &pp), AGJK_STATUS_OK);
        agjk_pose pa = tu_pose_identity(), pb = tu_pose_identity();
        pb.translation = tu_vec(10.0, 0.0, 0.0);
        for (int m = 0; m < N_METHODS; m++)
            for (int t = 0; t < 2; t++) {
                agjk_options o = agjk_default_options();
                o.method = all_methods[m];
                o.tolerance = t ? 1e-8 : 1e-300;
                agjk_result r;
                agjk_status st = agjk_distance(&sp, &pa, &sc, &pb, &o, &r);
                queries++;
                /* Plain FW's line search stops moving ||x|| in double precision
                 * long before GJK's floor (its steps shrink like g^2 / ||x - s||^2,
                 * below the rounding of ||x||^2 = 72 once g ~ 1e-8): it may say
                 * so, with that reason. */
                if (o.method == AGJK_METHOD_FRANK_WOLFE && st == AGJK_STATUS_NOT_CONVERGED) {
                    TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_NO_PROGRESS);
                    TU_ENSURE(r.distance - r.bound > 0, "offset %g: separation not certified", off);
                    continue;
                }
                TU_ENSURE(st == AGJK_STATUS_SEPARATED,
                          "offset %g, %s, tolerance %g: %s after %d iterations (gap %g)", off,
                          agjk_method_name(o.method), o.tolerance, agjk_status_string(st),
                          r.iterations, r.gap);
                TU_ENSURE(r.distance - r.bound <= 8.5 && 8.5 <= r.distance,
                          "offset %g: 8.5 outside [%.17g, %.17g]", off, r.distance - r.bound,
                          r.distance);
                TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_NONE);
            }
    }
    printf("point facing a cube face: %d queries, all separated\n", queries);
}
END_TEST

START_TEST(polytopes_at_the_floor) {
    tu_rng rng;
    tu_rng_seed(&rng, 11);
    static agjk_vec3 va[40], vb[40];
    int queries = 0, not_converged = 0;
    for (int i = 0; i < 150; i++) {
        ref_shape a, b;
        tu_random_polytope(&rng, &a, va, 12 + i % 29, 1.0);
        tu_random_polytope(&rng, &b, vb, 8 + i % 31, 1.0);
        agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
        double gap = pow(10.0, -9.0 + 9.0 * tu_uniform(&rng));
        if (tu_set_distance(&a, &pa, &b, &pb, gap, NULL) != 0) continue;
        ref_result ref;
        if (ref_distance(&a, &pa, &b, &pb, &ref) != 0 || ref.intersecting) continue;
        agjk_shape sa, sb;
        TU_CHECK_INT_EQ(ref_make_agjk(&a, &sa), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(ref_make_agjk(&b, &sb), AGJK_STATUS_OK);
        /* The reference works in world coordinates, in long double. */
        long double slack = 64.0L * LDBL_EPSILON * ref.scale;
        for (int m = 0; m < N_METHODS - 1; m++) { /* plain FW needs thousands of iterations */
            agjk_options o = agjk_default_options();
            o.method = all_methods[m];
            o.tolerance = 1e-300;
            agjk_result r;
            agjk_status st = agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
            queries++;
            if (st == AGJK_STATUS_NOT_CONVERGED) {
                not_converged++;
                printf("not converged: pair %d gap %g %s: reason %d, %d iterations, gap %g\n", i,
                       gap, agjk_method_name(o.method), (int)r.stop_reason, r.iterations, r.gap);
            }
            TU_ENSURE(st == AGJK_STATUS_SEPARATED || st == AGJK_STATUS_NOT_CONVERGED ||
                          (st == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE && gap < 1e-6),
                      "pair %d gap %g %s: %s", i, gap, agjk_method_name(o.method),
                      agjk_status_string(st));
            TU_ENSURE((long double)r.distance - r.bound <= ref.upper + slack &&
                          ref.lower - slack <= (long double)r.distance,
                      "pair %d gap %g %s: [%.17g, %.17g] misses the reference [%.17Lg, %.17Lg]", i,
                      gap, agjk_method_name(o.method), r.distance - r.bound, r.distance, ref.lower,
                      ref.upper);
        }
    }
    printf("random polytopes at the floating-point floor: %d queries, %d not converged\n", queries,
           not_converged);
    TU_ENSURE(queries > 400, "only %d queries ran", queries);
    TU_ENSURE(not_converged * 1000 <= queries, "%d of %d not converged (> 0.1%%)", not_converged,
              queries);
}
END_TEST

START_TEST(stop_reasons) {
    ref_shape a, b;
    tu_shape_init(&a, REF_ELLIPSOID, 0.1, 0.05, 0.08);
    tu_shape_init(&b, REF_ELLIPSOID, 0.07, 0.12, 0.05);
    agjk_shape sa, sb;
    TU_CHECK_INT_EQ(ref_make_agjk(&a, &sa), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(ref_make_agjk(&b, &sb), AGJK_STATUS_OK);
    tu_rng rng;
    tu_rng_seed(&rng, 12);
    agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
    TU_CHECK_INT_EQ(tu_set_distance(&a, &pa, &b, &pb, 1e-3, NULL), 0);
    agjk_result r;
    agjk_options o = agjk_default_options();
    o.method = AGJK_METHOD_GJK;
    /* Converged: no reason. */
    TU_CHECK_INT_EQ(agjk_distance(&sa, &pa, &sb, &pb, &o, &r), AGJK_STATUS_SEPARATED);
    TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_NONE);
    /* The cap. */
    o.max_iterations = 2;
    TU_CHECK_INT_EQ(agjk_distance(&sa, &pa, &sb, &pb, &o, &r), AGJK_STATUS_NOT_CONVERGED);
    TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_ITERATION_CAP);
    TU_CHECK_INT_EQ(r.iterations, 2);
    /* Relative accuracy beyond double precision: 1e-20 of a distance of 1e-3. */
    o.max_iterations = 1000;
    o.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
    o.tolerance = 1e-20;
    TU_CHECK_INT_EQ(agjk_distance(&sa, &pa, &sb, &pb, &o, &r), AGJK_STATUS_NOT_CONVERGED);
    TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_BELOW_PRECISION);
    /* ... which a reachable relative tolerance meets, with the promised accuracy. */
    o.tolerance = 1e-10;
    TU_CHECK_INT_EQ(agjk_distance(&sa, &pa, &sb, &pb, &o, &r), AGJK_STATUS_SEPARATED);
    TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_NONE);
    TU_ENSURE(r.bound <= 0.5e-10 * (r.distance - r.bound), "bound %g for distance %g", r.bound,
              r.distance);
    /* Verdicts of collide carry no reason either. */
    TU_CHECK_INT_EQ(agjk_collide(&sa, &pa, &sb, &pb, NULL, &r), AGJK_STATUS_SEPARATED);
    TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_NONE);
}
END_TEST

int main(void) {
    Suite *s = suite_create("verdicts");
    TU_ADD(s, point_facing_cube_face);
    TU_ADD(s, polytopes_at_the_floor);
    TU_ADD(s, stop_reasons);
    return tu_run_suite(s);
}
