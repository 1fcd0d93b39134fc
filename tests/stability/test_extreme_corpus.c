/* SPDX-License-Identifier: MIT */
/* The stiff and extreme corpus (issue 5, item 1).
 *
 * Every case is a pair of shapes in poses whose truth is known independently:
 * either analytically (stab_place puts B's support point at a* + sep * n with
 * parallel support planes, so the distance is exactly sep), or by a certified
 * overlap (a point of B strictly inside A), or by the long double reference of
 * tests/common (certified by its own duality gap). Each case runs
 * agjk_distance and agjk_collide with every method and checks: documented
 * status semantics, honest verdicts, no NaN, no writes outside the result,
 * the certified bracket [distance - bound, distance] meets the truth, and the
 * returned normal's plane (evaluated independently in long double) shows the
 * claimed separation. The program prints the corpus size and the worst
 * relative error. Check runs in no-fork mode so the statistics add up; an
 * alarm turns a hang into a failure. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stab_util.h"

static stab_stats g_stats;

#define STAB_PI 3.14159265358979323846

/* Each test asserts that it added no failure to the corpus statistics. */
#define BEGIN_CASES long failures_before = g_stats.failures
#define END_CASES ck_assert_int_eq(g_stats.failures - failures_before, 0)

/* Separations in units of the shapes' size: from far to touching to overlapping. */
static const double seps[] = {1e-1, 1e-3, 1e-6, 1e-9, 1e-12, 0, -1e-12, -1e-9, -1e-6, -1e-3, -1e-1};
#define NSEPS (sizeof seps / sizeof seps[0])

static ref_shape mk(ref_kind kind, double p0, double p1, double p2) {
    ref_shape s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.p[0] = p0;
    s.p[1] = p1;
    s.p[2] = p2;
    return s;
}

static ref_shape mk_poly(const agjk_vec3 *v, int n) {
    ref_shape s = mk(REF_POLYTOPE, 0, 0, 0);
    s.vertices = v;
    s.vertex_count = n;
    return s;
}

/* Places B against A along n at signed separation sep * size and checks the
 * pair in both tolerance modes. Overlaps are certified when a point of B is
 * inside A; otherwise the reference decides. */
static void check_signed(const char *name, ref_shape *a, const agjk_pose *pa, ref_shape *b,
                         const agjk_pose *pb, double sep, double size, double known);

static void run_placed(const char *tag, ref_shape *a, const agjk_pose *pa, ref_shape *b,
                       const agjk_pose *pb0, const double n[3], double sep, double size,
                       int which) {
    agjk_pose pb = *pb0;
    double known;
    char name[128];
    if (sep >= 0) {
        stab_place(a, pa, b, &pb, n, sep * size);
        known = sep * size;
    } else {
        known = stab_place_overlap(a, pa, b, &pb, n, -sep * size) ? STAB_OVERLAP : STAB_UNKNOWN;
    }
    snprintf(name, sizeof name, "%s sep %g", tag, sep);
    /* Relative mode: the accuracy users of near-contact want. */
    stab_check_case(name, a, pa, b, &pb, which, AGJK_TOLERANCE_RELATIVE, 1e-8, 256, known,
                    &g_stats);
    /* Absolute mode at the paper's 1e-8, scaled to the problem's size^2. */
    snprintf(name, sizeof name, "%s sep %g abs", tag, sep);
    stab_check_case(name, a, pa, b, &pb, which, AGJK_TOLERANCE_ABSOLUTE, 1e-8 * size * size, 128,
                    known, &g_stats);
    snprintf(name, sizeof name, "%s sep %g", tag, sep);
    check_signed(name, a, pa, b, &pb, sep, size, known);
}

/* agjk_signed_distance on the same placed pair (penetration.h): every field
 * finite, lower <= signed_distance <= upper, and the interval consistent with
 * what the placement proves: exactly sep * size when separated; when B was
 * pushed `depth` into A along n, the true signed distance lies in
 * [-depth, 0] (translating B back by depth separates them), and below 0 when
 * the overlap is certified. Counted in the corpus statistics. */
static long g_signed_queries, g_signed_not_converged;

static void check_signed(const char *name, ref_shape *a, const agjk_pose *pa, ref_shape *b,
                         const agjk_pose *pb, double sep, double size, double known) {
    agjk_shape sa, sb;
    if (ref_make_agjk(a, &sa) != AGJK_STATUS_OK || ref_make_agjk(b, &sb) != AGJK_STATUS_OK) return;
    double slack = 64 * 2.220446049250313e-16 * stab_magnitude(a, pa, b, pb);
    for (int mode = 0; mode < 2; mode++) {
        agjk_options o = agjk_default_options();
        o.tolerance_mode = (agjk_tolerance_mode)mode;
        o.tolerance = mode ? 1e-6 : 1e-8 * size * size;
        o.max_iterations = 256;
        agjk_signed_result r;
        agjk_status st = agjk_signed_distance(&sa, pa, &sb, pb, &o, &r);
        ++g_stats.queries;
        ++g_signed_queries;
        g_signed_not_converged += st == AGJK_STATUS_NOT_CONVERGED;
        if (st == AGJK_STATUS_NOT_CONVERGED && getenv("STAB_VERBOSE"))
            printf("signed %s (%s): not converged, [%.3g, %.3g], %d/%d iterations\n", name,
                   mode ? "relative" : "absolute", r.lower, r.upper, r.gjk_iterations,
                   r.epa_iterations);
        const double v[] = {r.signed_distance, r.lower, r.upper, r.normal.x, r.normal.y,
                            r.normal.z, r.witness_a.x, r.witness_a.y, r.witness_a.z,
                            r.witness_b.x, r.witness_b.y, r.witness_b.z};
        int bad = st == AGJK_STATUS_INVALID_INPUT;
        for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) bad |= !isfinite(v[i]);
        bad |= !(r.lower <= r.signed_distance && r.signed_distance <= r.upper);
        double lo = known, hi = known;
        if (sep < 0) {
            /* The support planes overlap by -sep * size: s >= sep * size
             * (translating B back along n separates the planes). Whether the
             * shapes overlap (stiff shapes may not) the reference says. */
            ref_result ref;
            lo = sep * size;
            hi = 0.0;
            if (known != STAB_OVERLAP && ref_distance(a, pa, b, pb, &ref) >= 0 && !ref.intersecting) {
                /* certified apart, or touching to the reference's accuracy
                 * (lower 0: the depth is then not bounded by it) */
                if (ref.lower > 0) lo = (double)ref.lower;
                hi = (double)ref.upper;
            }
        } else if (known < 0) {
            lo = -INFINITY; /* not analytic */
            hi = INFINITY;
        }
        bad |= r.upper < lo - slack || r.lower > hi + slack;
        if (known == STAB_OVERLAP) bad |= st == AGJK_STATUS_SEPARATED || r.lower > slack;
        if (st == AGJK_STATUS_SEPARATED) bad |= !(r.lower > 0);
        if (st == AGJK_STATUS_INTERSECTING) bad |= !(r.upper < 0);
        if (bad) {
            ++g_stats.failures;
            printf("signed %s (%s): %s %.17g in [%.17g, %.17g], truth in [%.17g, %.17g] "
                   "(slack %.3g)\n", name, mode ? "relative" : "absolute",
                   agjk_status_string(st), r.signed_distance, r.lower, r.upper, lo, hi, slack);
        }
    }
}

static void random_pose(agjk_pose *p, stab_rng *rng, double spread) {
    stab_pose_identity(p);
    stab_pose_random_rotation(p, rng);
    p->translation.x = stab_range(rng, -spread, spread);
    p->translation.y = stab_range(rng, -spread, spread);
    p->translation.z = stab_range(rng, -spread, spread);
}

static void run_sweep(const char *tag, ref_shape *a, ref_shape *b, stab_rng *rng, double size,
                      double spread, int which) {
    agjk_pose pa, pb;
    agjk_vec3 n = stab_unit(rng);
    double nn[3] = {n.x, n.y, n.z};
    random_pose(&pa, rng, spread);
    random_pose(&pb, rng, spread);
    for (size_t i = 0; i < NSEPS; i++) run_placed(tag, a, &pa, b, &pb, nn, seps[i], size, which);
}

/* Ellipsoids with axis ratios 1 ... 1e4 (distance and Boolean). */
START_TEST(test_ellipsoids_stiff) {
    BEGIN_CASES;
    static const double ratios[] = {1, 10, 100, 1e3, 1e4};
    stab_rng rng = {1001};
    for (size_t r = 0; r < sizeof ratios / sizeof ratios[0]; r++) {
        for (int k = 0; k < 3; k++) {
            double q = ratios[r];
            double mid = pow(q, stab_uniform(&rng));
            ref_shape a = mk(REF_ELLIPSOID, 1, 1 / mid, 1 / q);
            ref_shape b = mk(REF_ELLIPSOID, 1 / q, 1, 1 / sqrt(q));
            char tag[64];
            snprintf(tag, sizeof tag, "ellipsoids ratio %g #%d", q, k);
            run_sweep(tag, &a, &b, &rng, 1.0, 2.0, STAB_BOTH);
        }
    }
    END_CASES;
}
END_TEST

/* Axis ratios 1e5 and 1e6: Boolean queries (issue 5 asks for them there). */
START_TEST(test_ellipsoids_boolean_1e6) {
    BEGIN_CASES;
    static const double ratios[] = {1e5, 1e6};
    stab_rng rng = {1002};
    for (size_t r = 0; r < 2; r++) {
        for (int k = 0; k < 3; k++) {
            double q = ratios[r];
            ref_shape a = mk(REF_ELLIPSOID, 1, 1 / sqrt(q), 1 / q);
            ref_shape b = mk(REF_ELLIPSOID, 1 / q, 1, 1);
            char tag[64];
            snprintf(tag, sizeof tag, "ellipsoids ratio %g #%d", q, k);
            run_sweep(tag, &a, &b, &rng, 1.0, 2.0, STAB_COLLIDE);
        }
    }
    END_CASES;
}
END_TEST

/* Plates and needles: boxes of aspect 1e6. */
START_TEST(test_plates_needles) {
    BEGIN_CASES;
    stab_rng rng = {1003};
    ref_shape plate = mk(REF_BOX, 1, 1, 1e-6), needle = mk(REF_BOX, 1e-6, 1e-6, 1);
    ref_shape plate2 = mk(REF_BOX, 1, 0.5, 1e-6), needle2 = mk(REF_BOX, 1, 1e-6, 1e-6);
    ref_shape cube = mk(REF_BOX, 0.5, 0.5, 0.5);
    for (int k = 0; k < 2; k++) {
        run_sweep("plate/plate", &plate, &plate2, &rng, 1, 1, STAB_BOTH);
        run_sweep("needle/needle", &needle, &needle2, &rng, 1, 1, STAB_BOTH);
        run_sweep("needle/plate", &needle, &plate, &rng, 1, 1, STAB_BOTH);
        run_sweep("plate/cube", &plate, &cube, &rng, 1, 1, STAB_BOTH);
    }
    /* Parallel plates face to face, laterally offset: a 2-D contact set. */
    {
        agjk_pose pa, pb;
        double z[3] = {0, 0, 1};
        stab_pose_identity(&pa);
        stab_pose_identity(&pb);
        pb.translation.x = 0.3;
        pb.translation.y = -0.2;
        for (size_t i = 0; i < NSEPS; i++)
            run_placed("plates face to face", &plate, &pa, &plate2, &pb, z, seps[i], 1, STAB_BOTH);
        /* Needles crossing at right angles, edge on edge. */
        pb.translation.x = 0.1;
        for (size_t i = 0; i < NSEPS; i++)
            run_placed("needles crossing", &needle, &pa, &needle2, &pb, (double[3]){0, 1, 0}, seps[i],
                       1, STAB_BOTH);
    }
    END_CASES;
}
END_TEST

/* Box on box: parallel faces, edge on edge, vertex on face. */
START_TEST(test_boxes_contact) {
    BEGIN_CASES;
    ref_shape a = mk(REF_BOX, 1, 0.7, 0.4), b = mk(REF_BOX, 0.6, 0.9, 0.3);
    agjk_pose pa, pb;
    const double s2 = sqrt(0.5);
    stab_pose_identity(&pa);
    stab_pose_identity(&pb);
    pb.translation.x = 0.25;
    pb.translation.y = 0.1;
    for (size_t i = 0; i < NSEPS; i++)
        run_placed("box face on face", &a, &pa, &b, &pb, (double[3]){0, 0, 1}, seps[i], 1, STAB_BOTH);
    /* Edge on edge: A turned 45 degrees about x, B about y; contact along z. */
    stab_pose_quat(&pa, cos(STAB_PI / 8), sin(STAB_PI / 8), 0, 0);
    stab_pose_quat(&pb, cos(STAB_PI / 8), 0, sin(STAB_PI / 8), 0);
    for (size_t i = 0; i < NSEPS; i++)
        run_placed("box edge on edge", &a, &pa, &b, &pb, (double[3]){0, 0, 1}, seps[i], 1, STAB_BOTH);
    /* Vertex of B on a face of A. */
    stab_pose_identity(&pa);
    stab_pose_quat(&pb, 0.88807383, 0.32505758, 0.32505758, 0);
    for (size_t i = 0; i < NSEPS; i++)
        run_placed("box vertex on face", &a, &pa, &b, &pb, (double[3]){0, 0, 1}, seps[i], 1, STAB_BOTH);
    /* Face on face with B rotated about the normal (an octagonal contact). */
    stab_pose_quat(&pb, cos(STAB_PI / 8), 0, 0, sin(STAB_PI / 8));
    for (size_t i = 0; i < NSEPS; i++)
        run_placed("box face on turned face", &a, &pa, &b, &pb, (double[3]){s2, s2, 0}, seps[i], 1,
                   STAB_BOTH);
    END_CASES;
}
END_TEST

/* Far from the origin: translations 1e6, separations 1e-3. */
START_TEST(test_far_from_origin) {
    BEGIN_CASES;
    stab_rng rng = {1005};
    ref_shape e = mk(REF_ELLIPSOID, 1, 0.5, 0.25), bx = mk(REF_BOX, 0.5, 0.5, 0.5);
    ref_shape cap = mk(REF_CAPSULE, 0.3, 0.8, 0), cyl = mk(REF_CYLINDER, 0.4, 0.6, 0);
    ref_shape *shapes[4] = {&e, &bx, &cap, &cyl};
    static const double far_seps[] = {1e-3, 1e-2, 1e-1, -1e-3};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 2; k++) {
                agjk_pose pa, pb;
                agjk_vec3 n = stab_unit(&rng), t = stab_unit(&rng);
                double nn[3] = {n.x, n.y, n.z}, far = k ? 1e6 : -1e6;
                random_pose(&pa, &rng, 1);
                random_pose(&pb, &rng, 1);
                pa.translation.x += far * t.x; pa.translation.y += far * t.y; pa.translation.z += far * t.z;
                pb.translation = pa.translation;
                for (int s = 0; s < 4; s++)
                    run_placed("far from origin", shapes[i], &pa, shapes[j], &pb, nn, far_seps[s], 1,
                               STAB_BOTH);
            }
    END_CASES;
}
END_TEST

/* Degenerate polytopes: a point, a segment, a flat polygon, duplicated
 * vertices, a nearly coplanar cloud, a collinear cloud. */
static agjk_vec3 g_point[1] = {{0.1, -0.2, 0.3}};
static agjk_vec3 g_segment[2] = {{-1, 0.2, 0}, {1, -0.1, 0.05}};
static agjk_vec3 g_flat[8];
static agjk_vec3 g_dup[8 * 25];
static agjk_vec3 g_nearflat[60];
static agjk_vec3 g_collinear[30];

static void build_degenerate(void) {
    stab_rng rng = {1006};
    for (int i = 0; i < 8; i++) {
        double a = 2 * STAB_PI * i / 8 + 0.1;
        /* In the plane x + 2y + 3z = 0.5 */
        agjk_vec3 u = {2 / sqrt(5.0), -1 / sqrt(5.0), 0}, w = {3 / sqrt(70.0), 6 / sqrt(70.0), -5 / sqrt(70.0)};
        double c = 0.5 / 14;
        g_flat[i].x = c * 1 + cos(a) * u.x + sin(a) * w.x;
        g_flat[i].y = c * 2 + cos(a) * u.y + sin(a) * w.y;
        g_flat[i].z = c * 3 + cos(a) * u.z + sin(a) * w.z;
    }
    for (int i = 0; i < 8 * 25; i++) {
        int v = i % 8;
        g_dup[i].x = (v & 1) ? 0.5 : -0.5;
        g_dup[i].y = (v & 2) ? 0.3 : -0.3;
        g_dup[i].z = (v & 4) ? 0.2 : -0.2;
    }
    for (int i = 0; i < 60; i++) {
        g_nearflat[i].x = stab_range(&rng, -1, 1);
        g_nearflat[i].y = stab_range(&rng, -1, 1);
        g_nearflat[i].z = stab_range(&rng, -1e-12, 1e-12);
    }
    for (int i = 0; i < 30; i++) {
        double t = stab_range(&rng, -1, 1);
        g_collinear[i].x = 0.3 * t;
        g_collinear[i].y = -0.5 * t;
        g_collinear[i].z = 0.8 * t;
    }
}

START_TEST(test_degenerate_polytopes) {
    BEGIN_CASES;
    stab_rng rng = {1007};
    ref_shape polys[6];
    const char *names[6] = {"point", "segment", "flat polygon", "duplicated", "nearly coplanar",
                            "collinear"};
    ref_shape box = mk(REF_BOX, 0.5, 0.4, 0.3), ell = mk(REF_ELLIPSOID, 0.6, 0.3, 0.5);
    build_degenerate();
    polys[0] = mk_poly(g_point, 1);
    polys[1] = mk_poly(g_segment, 2);
    polys[2] = mk_poly(g_flat, 8);
    polys[3] = mk_poly(g_dup, 8 * 25);
    polys[4] = mk_poly(g_nearflat, 60);
    polys[5] = mk_poly(g_collinear, 30);
    for (int i = 0; i < 6; i++) {
        char tag[96];
        snprintf(tag, sizeof tag, "%s / box", names[i]);
        run_sweep(tag, &polys[i], &box, &rng, 1, 1, STAB_BOTH);
        snprintf(tag, sizeof tag, "ellipsoid / %s", names[i]);
        run_sweep(tag, &ell, &polys[i], &rng, 1, 1, STAB_BOTH);
        for (int j = i; j < 6; j++) {
            snprintf(tag, sizeof tag, "%s / %s", names[i], names[j]);
            run_sweep(tag, &polys[i], &polys[j], &rng, 1, 1, STAB_BOTH);
        }
    }
    END_CASES;
}
END_TEST

/* Every built-in kind against every other, random poses (the generic shapes,
 * including cylinders and cones whose supports are not strictly convex). */
START_TEST(test_all_kinds) {
    BEGIN_CASES;
    stab_rng rng = {1008};
    ref_shape kinds[8];
    kinds[0] = mk(REF_POINT, 0, 0, 0);
    kinds[1] = mk(REF_SPHERE, 0.5, 0, 0);
    kinds[2] = mk(REF_ELLIPSOID, 0.7, 0.2, 0.4);
    kinds[3] = mk(REF_BOX, 0.3, 0.6, 0.2);
    kinds[4] = mk(REF_CAPSULE, 0.2, 0.5, 0);
    kinds[5] = mk(REF_CYLINDER, 0.4, 0.3, 0);
    kinds[6] = mk(REF_CONE, 0.5, 0.4, 0);
    kinds[7] = mk(REF_BOX, 0.3, 0.3, 0.3);
    kinds[7].margin = 0.1; /* a rounded box */
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            char tag[64];
            snprintf(tag, sizeof tag, "kinds %d/%d", i, j);
            run_sweep(tag, &kinds[i], &kinds[j], &rng, 1, 1, STAB_BOTH);
        }
    END_CASES;
}
END_TEST

/* Identical shapes at identical poses, concentric shapes (x_0 = c_A - c_B = 0),
 * and deep penetration. */
START_TEST(test_overlap_extremes) {
    BEGIN_CASES;
    stab_rng rng = {1009};
    ref_shape kinds[7];
    build_degenerate();
    kinds[0] = mk(REF_SPHERE, 0.5, 0, 0);
    kinds[1] = mk(REF_ELLIPSOID, 1, 1e-3, 0.1);
    kinds[2] = mk(REF_BOX, 0.3, 0.6, 1e-6);
    kinds[3] = mk(REF_CAPSULE, 0.2, 0.5, 0);
    kinds[4] = mk(REF_CYLINDER, 0.4, 0.3, 0);
    kinds[5] = mk(REF_CONE, 0.5, 0.4, 0);
    kinds[6] = mk_poly(g_dup, 8 * 25);
    for (int i = 0; i < 7; i++)
        for (int j = 0; j < 7; j++) {
            for (int far = 0; far < 2; far++) {
                agjk_pose pa, pb;
                char tag[64];
                random_pose(&pa, &rng, far ? 1e6 : 1);
                pb = pa;
                snprintf(tag, sizeof tag, "%s %d/%d%s", i == j ? "identical" : "concentric", i, j,
                         far ? " far" : "");
                if (i != j) stab_pose_random_rotation(&pb, &rng);
                /* Same centre: the common centre is a common point. */
                stab_check_case(tag, &kinds[i], &pa, &kinds[j], &pb, STAB_BOTH,
                                AGJK_TOLERANCE_RELATIVE, 1e-8, 256, STAB_OVERLAP, &g_stats);
                stab_check_case(tag, &kinds[i], &pa, &kinds[j], &pb, STAB_BOTH,
                                AGJK_TOLERANCE_ABSOLUTE, 1e-8, 128, STAB_OVERLAP, &g_stats);
                /* Deep penetration: centre of B displaced inside A. */
                snprintf(tag, sizeof tag, "deep %d/%d%s", i, j, far ? " far" : "");
                pb.translation.x += 0.05;
                pb.translation.y -= 0.02;
                stab_check_case(tag, &kinds[i], &pa, &kinds[j], &pb, STAB_BOTH,
                                AGJK_TOLERANCE_RELATIVE, 1e-8, 256, STAB_UNKNOWN, &g_stats);
            }
        }
    {
        /* Two points at the same place: distance exactly 0, no interior. */
        ref_shape p = mk(REF_POINT, 0, 0, 0);
        agjk_pose pa;
        random_pose(&pa, &rng, 3);
        stab_check_case("point on point", &p, &pa, &p, &pa, STAB_BOTH, AGJK_TOLERANCE_RELATIVE,
                        1e-8, 256, 0.0, &g_stats);
        stab_check_case("point on point abs", &p, &pa, &p, &pa, STAB_BOTH, AGJK_TOLERANCE_ABSOLUTE,
                        1e-8, 256, 0.0, &g_stats);
    }
    END_CASES;
}
END_TEST

static Suite *corpus_suite(void) {
    Suite *s = suite_create("extreme corpus");
    TCase *tc = tcase_create("corpus");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_ellipsoids_stiff);
    tcase_add_test(tc, test_ellipsoids_boolean_1e6);
    tcase_add_test(tc, test_plates_needles);
    tcase_add_test(tc, test_boxes_contact);
    tcase_add_test(tc, test_far_from_origin);
    tcase_add_test(tc, test_degenerate_polytopes);
    tcase_add_test(tc, test_all_kinds);
    tcase_add_test(tc, test_overlap_extremes);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) {
    SRunner *sr = srunner_create(corpus_suite());
    int failed;
    /* A hang is a failure: SIGALRM kills the program with a non-zero status. */
    alarm(300);
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    stab_stats_print("extreme corpus", &g_stats);
    printf("extreme corpus: %ld signed-distance queries (in the counts above), %ld not converged\n",
           g_signed_queries, g_signed_not_converged);
    if (g_stats.failures > 0) failed++;
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
