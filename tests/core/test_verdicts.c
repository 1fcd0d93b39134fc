/* SPDX-License-Identifier: MIT */
/* A verdict whenever the certificate allows one, and a truthful reason when it
 * does not:
 * - a point facing a triangulated cube face (GJK's progress there is below the
 *   rounding of ||x||^2 while the gap is already 0) converges;
 * - random polytope pairs at gaps 1e-9 ... 1 of their size, at the most
 *   accurate tolerance (1e-300, raised to the floating-point floor), converge
 *   with a certified interval holding the long-double reference at both ends;
 * - NOT_CONVERGED carries its stop reason (iteration cap, relative accuracy
 *   below double precision), every other status AGJK_STOP_NONE;
 * - "intersecting" only when certified beyond the rounding of the points of
 *   D: a 1e9 ... 1e12 long needle passing a thin box by 1e-8 ... 1, where that
 *   rounding (about 1e-7 ... 1e-3) often swamps the gap, gets no false
 *   overlap (checked against the exact distance in quadruple precision),
 *   while deep overlaps of the same pairs are still certified;
 * - two ellipsoids overlapping by 1.5e-6 of their size, where plain GJK
 *   creeps on triangles past the origin until the sign-seeking budget runs
 *   out (coherent-motion benchmark, fast ellipsoids, pair 6, step 63): the
 *   cold query certifies the overlap, as the warm-started ones do, instead
 *   of answering contact within tolerance;
 * - plain Frank-Wolfe, whose iterate is one computed point carried over
 *   hundreds of steps, certifies neither an overlap nor a distance bound
 *   that its accumulated rounding has moved past the exact distance (a box
 *   and a sphere 3.3e-16 apart, two boxes 71 apart after 200 steps, a cube
 *   and a sphere: exact distances in long double, where each difference of
 *   these doubles is exact). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include "core_checks.h"
#include "quad.h"

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
        core_make_shapes(&a, &b, &sa, &sb);
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
    core_make_shapes(&a, &b, &sa, &sb);
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

/* Exact truth for a needle (a segment) and a box: their squared distance in
 * quadruple precision (tests/common/quad.h: products of doubles are exact,
 * and the rounding of the frame changes is below 1e-30 of the needle's
 * length, far below the gaps tested). Where the compiler has no such type,
 * the test is skipped. */
#ifdef HAVE_QUAD
/* Squared distance from p (box frame) to the box of half extents h. */
static quad box_distance2(const quad p[3], const double h[3]) {
    quad d2 = 0;
    for (int i = 0; i < 3; i++) {
        quad e = (p[i] < 0 ? -p[i] : p[i]) - (quad)h[i];
        if (e > 0) d2 += e * e;
    }
    return d2;
}

/* Squared distance between the segment [v0, v1] (A's frame) and the box
 * (B's frame): both ends in B's frame, then a ternary search on the convex
 * function t -> distance^2(v0 + t (v1 - v0), box). */
static quad needle_box_distance2(const agjk_pose *pa, const agjk_vec3 v[2], const agjk_pose *pb,
                                 const double h[3]) {
    quad e[2][3];
    for (int k = 0; k < 2; k++) {
        const double vv[3] = {v[k].x, v[k].y, v[k].z};
        const double ta[3] = {pa->translation.x, pa->translation.y, pa->translation.z};
        const double tb[3] = {pb->translation.x, pb->translation.y, pb->translation.z};
        quad w[3];
        for (int i = 0; i < 3; i++) {
            w[i] = (quad)ta[i] - (quad)tb[i];
            for (int j = 0; j < 3; j++) w[i] += (quad)pa->rotation[i][j] * (quad)vv[j];
        }
        for (int i = 0; i < 3; i++) {
            e[k][i] = 0;
            for (int j = 0; j < 3; j++) e[k][i] += (quad)pb->rotation[j][i] * w[j];
        }
    }
    quad lo = 0, hi = 1, p1[3], p2[3];
    for (int it = 0; it < 300; it++) {
        quad t1 = lo + (hi - lo) / 3, t2 = hi - (hi - lo) / 3;
        for (int i = 0; i < 3; i++) {
            p1[i] = e[0][i] + (e[1][i] - e[0][i]) * t1;
            p2[i] = e[0][i] + (e[1][i] - e[0][i]) * t2;
        }
        if (box_distance2(p1, h) < box_distance2(p2, h)) hi = t2;
        else lo = t1;
    }
    for (int i = 0; i < 3; i++) p1[i] = e[0][i] + (e[1][i] - e[0][i]) * lo;
    return box_distance2(p1, h);
}
#endif

/* A needle of half length 1e9 ... 1e12 along x and a thin box beside it
 * (gap 1e-8 ... 1 along y or z) or through it, the pair turned and moved as a
 * whole: the relative transform rounds at about 1e-16 of the needle's length,
 * far above most gaps. The answer may be "contact within tolerance", but
 * never a false "intersecting", and its interval holds the exact distance;
 * overlaps much deeper than the rounding are still certified. */
START_TEST(needles_get_no_false_overlap) {
#ifndef HAVE_QUAD
    fprintf(stderr, "needles: no quadruple precision type, skipped\n");
#else
    tu_rng rng;
    tu_rng_seed(&rng, 31);
    int wrong = 0, outside = 0, separated = 0, deep = 0, deep_certified = 0;
    const int pairs = 4000;
    for (int i = 0; i < pairs; i++) {
        double L = tu_log_uniform(&rng, 9, 12);
        agjk_vec3 needle[2] = {tu_vec(-L, 0.0, 0.0), tu_vec(L, 0.0, 0.0)};
        double h[3] = {tu_log_uniform(&rng, -3, 1), tu_log_uniform(&rng, -3, 1),
                       tu_log_uniform(&rng, -6, 0)};
        int along_z = i % 2, overlap = i % 4 == 1;
        double beside = along_z ? h[2] : h[1];
        double gap = overlap ? -tu_uniform_range(&rng, 0.1, 1.9) * beside : tu_log_uniform(&rng, -8, 0);
        agjk_pose pa = tu_pose_identity(), pb = tu_pose_identity();
        pb.translation = tu_vec(tu_uniform_range(&rng, -0.5, 0.5) * L, along_z ? 0.0 : beside + gap,
                                along_z ? beside + gap : 0.0);
        agjk_pose whole = tu_random_pose(&rng, i % 3 ? 1e8 : 0.0);
        pa = tu_pose_compose(&whole, &pa);
        pb = tu_pose_compose(&whole, &pb);
        ref_shape a, b;
        tu_shape_init(&a, REF_POLYTOPE, 0.0, 0.0, 0.0);
        a.vertices = needle;
        a.vertex_count = 2;
        tu_shape_init(&b, REF_BOX, h[0], h[1], h[2]);
        agjk_shape sa, sb;
        core_make_shapes(&a, &b, &sa, &sb);
        quad d2 = needle_box_distance2(&pa, needle, &pb, h);
        int apart = d2 > (quad)1e-40; /* far above the quad rounding, 1e-22 at most */
        separated += apart;
        agjk_options o = agjk_default_options();
        o.tolerance = i % 3 == 2 ? 1e-8 : 1e-300; /* the library's and the CLI's defaults */
        agjk_result rd, rc;
        agjk_status sd = agjk_distance(&sa, &pa, &sb, &pb, &o, &rd);
        agjk_status sc = agjk_collide(&sa, &pa, &sb, &pb, &o, &rc);
        if (apart && (sd == AGJK_STATUS_INTERSECTING || sc == AGJK_STATUS_INTERSECTING)) {
            if (wrong < 5)
                fprintf(stderr, "needle %g, gap %g: distance %s, collide %s\n", L,
                        (double)d2 > 0 ? sqrt((double)d2) : 0.0, agjk_status_string(sd),
                        agjk_status_string(sc));
            ++wrong;
        }
        if (!apart && (sd == AGJK_STATUS_SEPARATED || sc == AGJK_STATUS_SEPARATED)) ++wrong;
        if (sd == AGJK_STATUS_SEPARATED || sd == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE) {
            quad low = (quad)rd.distance - (quad)rd.bound, up = (quad)rd.distance;
            if ((low > 0 && low * low > d2) || d2 > up * up) ++outside;
        }
        /* The origin's depth in D: the needle's distance to the nearer face
         * across it, and to the faces of the other axis across it; certified
         * when more than 100 times the rounding (about 8 eps L). */
        double inside = beside - fabs(beside + gap), other = along_z ? h[1] : h[2];
        double depth = inside < other ? inside : other;
        if (overlap && depth > 100.0 * 8.0 * DBL_EPSILON * L) {
            ++deep;
            deep_certified += sd == AGJK_STATUS_INTERSECTING && sc == AGJK_STATUS_INTERSECTING;
        }
    }
    TU_ENSURE(wrong == 0, "%d wrong verdicts in %d pairs (%d apart)", wrong, pairs, separated);
    TU_ENSURE(outside == 0, "%d distance intervals miss the exact distance", outside);
    /* Deep overlaps stay decided (all 273 with seed 31; a needle where GJK
     * stalls would end as an honest contact within tolerance instead). */
    TU_ENSURE(deep > 100 && deep_certified >= 0.95 * deep, "%d of %d deep overlaps certified",
              deep_certified, deep);
    fprintf(stderr, "needles: %d pairs (%d apart), 0 wrong verdicts, %d of %d deep overlaps certified\n",
            pairs, separated, deep_certified, deep);
#endif
}
END_TEST

/* A point beside a needle- or ribbon-shaped ellipsoid (radii 1e-9 ... 1e-3
 * across, 1 ... 10 wide, 1e10 ... 1e44 long), off its thin side by 1e-3
 * ... 1, both turned: the support points are up to 1e44 long, and the
 * rounding of the relative transform, far above the gap, leaves the sign
 * undecidable in double precision. "Contact within tolerance" then, or
 * "separated" where a plane shows it, but never "intersecting": the
 * overlap certification once took a normal lost to rounding (a point 1e43
 * times nearer the origin than the others vanishing from both differences)
 * for no facet at all (a fuzz input: radii 9.8e-9, 9.9 and 4.5e43, gap
 * 0.12). */
START_TEST(point_beside_ellipsoid_needle) {
    tu_rng rng;
    tu_rng_seed(&rng, 44);
    const agjk_method methods[] = {AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV, AGJK_METHOD_ADAPTIVE};
    int wrong = 0, queries = 0;
    for (int i = 0; i < 600; i++) {
        agjk_ellipsoid e = {{tu_log_uniform(&rng, -9, -3), tu_log_uniform(&rng, 0, 1),
                             tu_log_uniform(&rng, 10, 44)}};
        double gap = tu_log_uniform(&rng, -3, 0);
        agjk_shape a, b;
        TU_CHECK_INT_EQ(agjk_shape_point(&a), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(agjk_shape_ellipsoid(&b, &e), AGJK_STATUS_OK);
        agjk_pose pa = tu_pose_identity(), pb = tu_pose_identity();
        tu_random_rotation(&rng, pa.rotation);
        tu_random_rotation(&rng, pb.rotation);
        pb.translation = tu_vec(tu_uniform_range(&rng, -1, 1), tu_uniform_range(&rng, -1, 1),
                                tu_uniform_range(&rng, -1, 1));
        /* The point at (radius + gap, y, 0) in B's frame, |y| within half
         * the width: outside by at least the gap along B's thin axis. */
        double y = tu_uniform_range(&rng, -0.5, 0.5) * e.radii.y;
        agjk_vec3 local = tu_vec(e.radii.x + gap, y, 0.0);
        for (int r = 0; r < 3; r++)
            (&pa.translation.x)[r] = (&pb.translation.x)[r] + pb.rotation[r][0] * local.x +
                                     pb.rotation[r][1] * local.y;
        for (int m = 0; m < 3; m++) {
            agjk_options o = agjk_default_options();
            o.method = methods[m];
            agjk_result rd, rc;
            agjk_status sd = agjk_distance(&a, &pa, &b, &pb, &o, &rd);
            agjk_status sc = agjk_collide(&a, &pa, &b, &pb, &o, &rc);
            queries += 2;
            if (sd == AGJK_STATUS_INTERSECTING || sc == AGJK_STATUS_INTERSECTING) {
                if (wrong < 5)
                    fprintf(stderr, "radii %g %g %g, gap %g, method %d: distance %s, collide %s\n",
                            e.radii.x, e.radii.y, e.radii.z, gap, m, agjk_status_string(sd),
                            agjk_status_string(sc));
                ++wrong;
            }
        }
    }
    TU_ENSURE(wrong == 0, "%d false overlaps in %d queries", wrong, queries);
}
END_TEST

/* The pose of tools/bench/coherent.c's fast ellipsoid trajectory, pair 6,
 * step 63 (seed 1), bit for bit. The cold adaptive query used to end
 * "contact within tolerance" with [0, 3.3e-7] after 19 support calls while
 * the hinted and cached queries of that step certified the overlap. */
START_TEST(shallow_overlap_decided_cold) {
    ref_shape ra, rb;
    tu_shape_init(&ra, REF_ELLIPSOID, 0x1.499806955c08fp-1, 0x1.f1cf2b8da2472p-2,
                  0x1.1371ed696047fp-1);
    tu_shape_init(&rb, REF_ELLIPSOID, 0x1.310adcacecf78p+0, 0x1.e920c1d1d7205p-1,
                  0x1.e33a7c36dcf01p-1);
    agjk_pose pa = {{{0x1.e9feb3a8767c6p-1, 0x1.28f665b5516b4p-2, -0x1.835e720e06cb8p-9},
                     {-0x1.276a0466a18a2p-2, 0x1.e6dad17a554bdp-1, -0x1.cb80019aace0fp-4},
                     {-0x1.e6fb3eec874d1p-6, 0x1.bb3e5bc7db11dp-4, 0x1.fcc40bbf917c9p-1}},
                    {0x1.337b96c2c9ffap-4, 0x1.337b96c2c9ffap-4, 0x1.337b96c2c9ffap-4}};
    agjk_pose pb = {{{0x1.ae142117a6e43p-1, -0x1.046228b2bec63p-3, -0x1.0e12708b96cc7p-1},
                     {-0x1.82e0310557289p-2, -0x1.ab6d17e4a191cp-1, -0x1.9a0996b1ec82fp-2},
                     {-0x1.8ec9fa0a94ef2p-2, 0x1.12402a9af7489p-1, -0x1.7fa16d860ee9fp-1}},
                    {-0x1.c59929c926f0cp-1, 0x1.1a629ed3886e6p-1, -0x1.0ad674b6f40b1p+0}};
    agjk_shape sa, sb;
    TU_CHECK_INT_EQ(ref_make_agjk(&ra, &sa), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(ref_make_agjk(&rb, &sb), AGJK_STATUS_OK);
    /* The truth: an overlap, certified in long double. */
    ref_result ref;
    TU_CHECK_INT_EQ(ref_distance(&ra, &pa, &rb, &pb, &ref), 0);
    TU_ENSURE(ref.intersecting, "the reference does not certify the overlap");
    /* Cold, default method (the benchmark's distance query, and the
     * default's witness points, and the Boolean query): certified. */
    for (int q = 0; q < 3; q++) {
        agjk_options o = agjk_default_options();
        if (q == 0) o.compute = AGJK_COMPUTE_DISTANCE;
        agjk_result r;
        agjk_status st = q == 2 ? agjk_collide(&sa, &pa, &sb, &pb, &o, &r)
                                : agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
        TU_ENSURE(st == AGJK_STATUS_INTERSECTING && r.status == st,
                  "query %d: status %d (distance %g, bound %g) after %d support calls", q, st,
                  r.distance, r.bound, r.support_calls);
        /* A few supports beyond the plain loop's 19, not a search. */
        TU_ENSURE(r.support_calls <= 26, "query %d: %d support calls", q, r.support_calls);
    }
    /* Every method but plain Frank-Wolfe (which keeps no simplex to certify
     * with) decides it too. */
    for (int m = 0; m < CORE_METHOD_COUNT; m++) {
        if (core_methods[m] == AGJK_METHOD_FRANK_WOLFE) continue;
        agjk_options o = agjk_default_options();
        o.method = core_methods[m];
        agjk_result r;
        TU_CHECK_INT_EQ(agjk_distance(&sa, &pa, &sb, &pb, &o, &r), AGJK_STATUS_INTERSECTING);
    }
}
END_TEST

/* The exact distance must lie in the certified interval [distance - bound,
 * distance] (any status but intersecting, which must not come). */
static void check_holds(const char *what, const agjk_result *r, long double exact) {
    TU_ENSURE(r->status != AGJK_STATUS_INTERSECTING && r->status != AGJK_STATUS_INVALID_INPUT,
              "%s: status %s", what, agjk_status_string(r->status));
    TU_ENSURE((long double)r->distance >= exact &&
                  (long double)r->distance - (long double)r->bound <= exact,
              "%s: exact %.21Lg outside [%.21g, %.21g] (%s, %d iterations)", what, exact,
              r->distance - r->bound, r->distance, agjk_status_string(r->status), r->iterations);
}

START_TEST(frank_wolfe_drift_bounded) {
    agjk_options o = agjk_default_options();
    o.method = AGJK_METHOD_FRANK_WOLFE;
    agjk_pose id = tu_pose_identity(), pb = id;
    agjk_shape sa, sb;
    agjk_result r;
    /* A sphere over a box's +y face, 3.3e-16 apart: Frank-Wolfe once ended
     * "intersecting" through the margin (its drifted iterate ||x|| + noise
     * below the radius), from agjk_distance and agjk_collide alike. */
    agjk_box box = {{0x1.29655d3bfba09p-3, 0x1.8f04f574434e3p-1, 0x1.82e8b2cd60c8p-2}};
    double radius = 0x1.67298cdf3a1f1p+0;
    TU_CHECK_INT_EQ(agjk_shape_box(&sa, &box), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_sphere(&sb, radius), AGJK_STATUS_OK);
    pb.translation = tu_vec(0x1.c9f7ed7d21e7ep-5, 0x1.175603ccade32p+1, -0x1.72b83e17d03f2p-2);
    long double exact = (long double)pb.translation.y - box.half_extents.y - radius;
    ck_assert(exact > 0.0L);
    double tolerances[2] = {1e-8, 1e-300};
    for (int k = 0; k < 2; ++k) {
        o.tolerance = tolerances[k];
        agjk_distance(&sa, &id, &sb, &pb, &o, &r);
        check_holds("box and sphere, distance", &r, exact);
        agjk_collide(&sa, &id, &sb, &pb, &o, &r);
        TU_ENSURE(r.status != AGJK_STATUS_INTERSECTING, "box and sphere, collide: intersecting");
    }
    /* Two boxes 71 apart along y, 200 steps: the upper end, rounding
     * allowance included, came out 2.4e-14 below the exact distance. */
    agjk_box ba = {{0x1.856fd78ed5da8p-3, 0x1.789e039cce9b8p-3, 0x1.daafa04b8650fp-1}};
    agjk_box bb = {{0x1.0cbb8afeef3bbp-1, 0x1.9ecd002142474p-2, 0x1.083d27365af2p-2}};
    TU_CHECK_INT_EQ(agjk_shape_box(&sa, &ba), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_box(&sb, &bb), AGJK_STATUS_OK);
    pb.translation = tu_vec(0x1.264402ea1e175p-1, -0x1.1f58443cf12ap+6, -0x1.7fabb15698ac4p-1);
    o.tolerance = 1e-8;
    o.max_iterations = 200;
    agjk_distance(&sa, &id, &sb, &pb, &o, &r);
    check_holds("two boxes",
                &r, -(long double)pb.translation.y - ba.half_extents.y - bb.half_extents.y);
    /* A cube given as 8 points and a sphere above its +z face. */
    double hx = 0x1.2bb63537b1da3p-7, hy = 0x1.ed5691fc88db4p-6, hz = 0x1.d09144609cb7dp-6;
    agjk_vec3 v[8];
    for (int i = 0; i < 8; i++)
        v[i] = tu_vec((i & 1) ? hx : -hx, (i & 2) ? hy : -hy, (i & 4) ? hz : -hz);
    agjk_polytope cube = {v, 8, NULL, NULL};
    double rad = 0x1.024884ed0a058p-8;
    TU_CHECK_INT_EQ(agjk_shape_polytope(&sa, &cube), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_sphere(&sb, rad), AGJK_STATUS_OK);
    pb.translation = tu_vec(-0x1.2aea77455399bp-8, 0x1.07639b99fe95cp-7, 0x1.74c48f8c5317ap+1);
    o.tolerance = 1e-300;
    o.max_iterations = 1000;
    agjk_distance(&sa, &id, &sb, &pb, &o, &r);
    check_holds("cube and sphere", &r, (long double)pb.translation.z - hz - rad);
}
END_TEST

/* Two segments crossing 8.07e-16 apart (a box of zero width and height, a
 * capsule of zero radius; the pose found by a review's fuzzer): Nesterov
 * with normalized directions ends within rounding of contact on a sliver
 * whose member point lies 3 noise from the origin, farther than x. That
 * widens the interval to [0, 7.7e-15], which still meets any absolute
 * tolerance (its squared width is far below 1e-8, and below the floor that
 * 1e-300 is raised to): the answer is contact within tolerance, as the
 * other methods give, not NOT_CONVERGED with a stop reason of relative mode.
 * Exact distance of the two lines in quadruple precision (the closest points
 * lie inside both segments). */
#ifdef HAVE_QUAD
START_TEST(inexact_member_point_meets_tolerance) {
    agjk_box seg_a = {{0, 0, 0x1.f4fa278e3a321p-1}};
    agjk_capsule seg_b = {0, 0x1.4cb6e581a7cf9p-1};
    agjk_shape sa, sb;
    TU_CHECK_INT_EQ(agjk_shape_box(&sa, &seg_a), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_capsule(&sb, &seg_b), AGJK_STATUS_OK);
    agjk_pose pa = tu_pose_identity();
    agjk_pose pb = {{{-0x1.25d509fd16b7p-2, 0x1.765f7def18b4bp-1, 0x1.3cdde03bf519cp-1},
                     {-0x1.8737378d4005dp-1, -0x1.20f3a3fb53f78p-1, 0x1.4001e5b0cd282p-2},
                     {0x1.27d21fd7e97bcp-1, -0x1.88681b6c474bap-2, 0x1.70f820b7bd4a8p-1}},
                    {-0x1.f9adecdd536bfp-49, -0x1.f3f0e26dffdfp-51, -0x1.4c14f4f335771p-4}};
    /* A: the z axis, |z| <= ha. B: t + s u, u B's local z axis in A's frame
     * (its rotation's third column), |s| <= hb. */
    quad u[3] = {pb.rotation[0][2], pb.rotation[1][2], pb.rotation[2][2]};
    quad t[3] = {pb.translation.x, pb.translation.y, pb.translation.z};
    quad n[3] = {-u[1], u[0], 0}; /* e_z x u */
    quad nn = n[0] * n[0] + n[1] * n[1];
    quad tn = t[0] * n[0] + t[1] * n[1];
    quad exact2 = tn * tn / nn; /* squared distance of the two lines */
    /* Their closest points: s = -<t, u_perp> / |u_perp|^2 (u_perp the part of
     * u across z), z = t_z + s u_z; both within the segments. */
    quad s = -(t[0] * u[0] + t[1] * u[1]) / nn, z = t[2] + s * u[2];
    ck_assert(s > -0x1.4cb6e581a7cf9p-1 && s < 0x1.4cb6e581a7cf9p-1);
    ck_assert(z > -0x1.f4fa278e3a321p-1 && z < 0x1.f4fa278e3a321p-1);
    ck_assert(exact2 > 0x1p-102 && exact2 < 0x1p-100); /* 8.07e-16 apart */
    static const agjk_method methods[] = {
        AGJK_METHOD_GJK,    AGJK_METHOD_NESTEROV,    AGJK_METHOD_NESTEROV_NORMALIZED,
        AGJK_METHOD_POLYAK, AGJK_METHOD_FRANK_WOLFE, AGJK_METHOD_ADAPTIVE};
    double tolerances[2] = {1e-8, 1e-300};
    for (int m = 0; m < 6; m++)
        for (int k = 0; k < 2; k++) {
            agjk_options o = agjk_default_options();
            o.method = methods[m];
            o.tolerance = tolerances[k];
            agjk_result r;
            agjk_status st = agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
            TU_ENSURE(st == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE || st == AGJK_STATUS_SEPARATED,
                      "%s, tolerance %g: %s (stop reason %d), distance %g", agjk_method_name(o.method),
                      o.tolerance, agjk_status_string(st), r.stop_reason, r.distance);
            TU_CHECK_INT_EQ(r.stop_reason, AGJK_STOP_NONE);
            /* The interval holds the exact distance, and its squared upper end
             * is within the tolerance or the floating-point floor, 2 (||x|| +
             * ||x - s||) 4 eps size, below 64 eps here (the problem's size,
             * half lengths plus offset, is below 1.8, and ||x - s|| below 3.4). */
            quad up = r.distance, lo = (quad)r.distance - r.bound;
            TU_ENSURE(up * up >= exact2 && (lo <= 0 || lo * lo <= exact2),
                      "%s: [%g, %g] misses the exact distance", agjk_method_name(o.method),
                      r.distance - r.bound, r.distance);
            TU_ENSURE(r.distance * r.distance <= o.tolerance + 64 * DBL_EPSILON,
                      "%s: distance %g", agjk_method_name(o.method), r.distance);
            /* agjk_collide shares the verdict. */
            st = agjk_collide(&sa, &pa, &sb, &pb, &o, &r);
            TU_ENSURE(st == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE || st == AGJK_STATUS_SEPARATED,
                      "collide, %s, tolerance %g: %s (stop reason %d)", agjk_method_name(o.method),
                      o.tolerance, agjk_status_string(st), r.stop_reason);
        }
}
END_TEST
#endif

int main(void) {
    Suite *s = suite_create("verdicts");
    TU_ADD(s, point_facing_cube_face);
    TU_ADD(s, polytopes_at_the_floor);
    TU_ADD(s, stop_reasons);
    TU_ADD(s, needles_get_no_false_overlap);
    TU_ADD(s, point_beside_ellipsoid_needle);
    TU_ADD(s, shallow_overlap_decided_cold);
    TU_ADD(s, frank_wolfe_drift_bounded);
#ifdef HAVE_QUAD
    TU_ADD(s, inexact_member_point_meets_tolerance);
#endif
    return tu_run_suite(s);
}
