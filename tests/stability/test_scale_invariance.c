/* SPDX-License-Identifier: MIT */
/* Scale invariance (issue 5, item 2).
 *
 * The same problem scaled as a whole (shape sizes, vertices, translations) by
 * factors from 1e-6 to 1e6, with AGJK_TOLERANCE_RELATIVE: the Boolean answer
 * must not change, the relative distance error must stay within the
 * documented tolerance / 2 (truth: the analytic separation of stab_place,
 * scaled), and for power-of-two factors, where scaling is exact in floating
 * point, the whole computation must be exactly equivariant (same status, same
 * iterations, distance scaled bit for bit): any absolute epsilon hidden in the
 * solver shows up there. libccd flips its Boolean answer on ~9% of box pairs
 * at scale 1e-3 (DESIGN.md); agjk must flip none. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stab_util.h"

#define MAX_VERTS 64

typedef struct problem {
    ref_shape a, b;
    agjk_vec3 va[MAX_VERTS], vb[MAX_VERTS];
    agjk_pose pa, pb;
    double sep;      /* analytic distance at scale 1 (>= 0), or < 0 for overlap */
    int overlap_certified;
} problem;

typedef struct outcome {
    agjk_status collide[5], distance[5];
    double d[5];
    int it[5];
} outcome;

static const double factors[] = {0x1p-20, 1e-6, 1e-3, 0x1p-10, 0.1, 1.0, 3.7, 0x1p10, 1e3, 1e6,
                                 0x1p20, 123456.789, 7.3e-5};
#define NFACT (sizeof factors / sizeof factors[0])

static long g_problems, g_queries, g_bool_flips, g_exact_breaks, g_rel_breaks, g_minor;
static long g_verdict_changes;
static double g_worst_rel, g_worst_rel_change;

/* Scales a copy of `p` by f into `q` (vertex arrays copied into q's storage). */
static void scale_problem(const problem *p, double f, problem *q) {
    *q = *p;
    for (int i = 0; i < 3; i++) {
        q->a.p[i] = p->a.p[i] * f;
        q->b.p[i] = p->b.p[i] * f;
    }
    q->a.margin = p->a.margin * f;
    q->b.margin = p->b.margin * f;
    for (int i = 0; i < p->a.vertex_count; i++) {
        q->va[i].x = p->va[i].x * f; q->va[i].y = p->va[i].y * f; q->va[i].z = p->va[i].z * f;
    }
    for (int i = 0; i < p->b.vertex_count; i++) {
        q->vb[i].x = p->vb[i].x * f; q->vb[i].y = p->vb[i].y * f; q->vb[i].z = p->vb[i].z * f;
    }
    q->a.vertices = q->va;
    q->b.vertices = q->vb;
    q->pa.translation.x *= f; q->pa.translation.y *= f; q->pa.translation.z *= f;
    q->pb.translation.x *= f; q->pb.translation.y *= f; q->pb.translation.z *= f;
}

/* Sanity of every result; a minor defect (negative gap) is counted and
 * fails the test at the end, anything worse fails at once. */
static void sane_or_count(const char *what, agjk_status st, const agjk_result *r) {
    int v = stab_result_sane(what, st, r, 256);
    ck_assert_msg(v < 2, "%s: result not sane (see output)", what);
    if (v == 1) g_minor++;
}

static void solve(problem *q, outcome *o) {
    agjk_shape sa, sb;
    ck_assert_int_eq(stab_make_shape(&q->a, &sa), AGJK_STATUS_OK);
    ck_assert_int_eq(stab_make_shape(&q->b, &sb), AGJK_STATUS_OK);
    for (int m = 0; m < 5; m++) {
        agjk_options opt = agjk_default_options();
        agjk_result r;
        opt.method = (agjk_method)m;
        opt.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
        opt.tolerance = 1e-8;
        opt.max_iterations = 256;
        o->collide[m] = agjk_collide(&sa, &q->pa, &sb, &q->pb, &opt, &r);
        sane_or_count("collide", o->collide[m], &r);
        o->distance[m] = agjk_distance(&sa, &q->pa, &sb, &q->pb, &opt, &r);
        sane_or_count("distance", o->distance[m], &r);
        o->d[m] = r.distance;
        o->it[m] = r.iterations;
        g_queries += 2;
    }
}

/* Is f a power of two (scaling by it is exact)? */
static int pow2(double f) {
    int e;
    return frexp(f, &e) == 0.5;
}

static void check_problem(const char *tag, const problem *p) {
    outcome base, o;
    problem q;
    char name[128];
    scale_problem(p, 1.0, &q);
    solve(&q, &base);
    g_problems++;
    for (size_t k = 0; k < NFACT; k++) {
        double f = factors[k];
        scale_problem(p, f, &q);
        solve(&q, &o);
        snprintf(name, sizeof name, "%s x %g", tag, f);
        for (int m = 0; m < 5; m++) {
            const char *meth = agjk_method_name((agjk_method)m);
            if ((o.collide[m] == AGJK_STATUS_SEPARATED && base.collide[m] == AGJK_STATUS_INTERSECTING) ||
                (o.collide[m] == AGJK_STATUS_INTERSECTING && base.collide[m] == AGJK_STATUS_SEPARATED)) {
                printf("FAIL %s [%s]: Boolean answer %s at scale 1, %s at scale %g\n", name, meth,
                       agjk_status_string(base.collide[m]), agjk_status_string(o.collide[m]), f);
                g_bool_flips++;
            } else if (o.collide[m] != base.collide[m]) {
                /* A certain answer at one scale, an honest "not sure" at another
                 * (the iteration cap met one iteration earlier or later after
                 * rounding): not a lie, but counted and reported. */
                printf("NOTE %s [%s]: Boolean verdict %s at scale 1, %s at scale %g\n", name, meth,
                       agjk_status_string(base.collide[m]), agjk_status_string(o.collide[m]), f);
                g_verdict_changes++;
            }
            if (pow2(f) && (o.distance[m] != base.distance[m] || o.it[m] != base.it[m] ||
                            o.d[m] != base.d[m] * f || o.collide[m] != base.collide[m])) {
                printf("FAIL %s [%s]: not exactly equivariant under a power-of-two scaling: "
                       "%s/%s, %d/%d iterations, distance %.17g vs %.17g\n",
                       name, meth, agjk_status_string(base.distance[m]),
                       agjk_status_string(o.distance[m]), base.it[m], o.it[m], base.d[m] * f, o.d[m]);
                g_exact_breaks++;
            }
            if (p->sep > 0 && o.distance[m] == AGJK_STATUS_SEPARATED) {
                /* Truth: the analytic separation, scaled; slack for the rounding
                 * of the translations (a few ulps of the problem's size). */
                double truth = p->sep * f;
                double slack = 64 * DBL_EPSILON * stab_magnitude(&q.a, &q.pa, &q.b, &q.pb);
                double rel = fabs(o.d[m] - truth) / truth;
                double rel1 = fabs(base.d[m] - p->sep) / p->sep;
                if (rel > g_worst_rel) g_worst_rel = rel;
                if (base.distance[m] == AGJK_STATUS_SEPARATED &&
                    fabs(rel - rel1) > g_worst_rel_change)
                    g_worst_rel_change = fabs(rel - rel1);
                if (fabs(o.d[m] - truth) > 0.5e-8 * truth + 2 * slack) {
                    printf("FAIL %s [%s]: relative error %.3g > tolerance/2 (distance %.17g, "
                           "true %.17g)\n", name, meth, rel, o.d[m], truth);
                    g_rel_breaks++;
                }
            }
            if (p->overlap_certified &&
                (o.collide[m] == AGJK_STATUS_SEPARATED || o.distance[m] == AGJK_STATUS_SEPARATED)) {
                printf("FAIL %s [%s]: certified overlap answered separated\n", name, meth);
                g_bool_flips++;
            }
        }
    }
}

static ref_shape mk(ref_kind kind, double p0, double p1, double p2, double margin) {
    ref_shape s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.p[0] = p0;
    s.p[1] = p1;
    s.p[2] = p2;
    s.margin = margin;
    return s;
}

static void random_points(agjk_vec3 *v, int n, stab_rng *rng, double flat) {
    for (int i = 0; i < n; i++) {
        v[i].x = stab_range(rng, -0.5, 0.5);
        v[i].y = stab_range(rng, -0.5, 0.5);
        v[i].z = stab_range(rng, -0.5, 0.5) * flat;
    }
}

/* Builds problems of every kind and checks each at every scale. */
static void run_family(const char *tag, ref_shape a, ref_shape b, int verts_a, int verts_b,
                       double flat, stab_rng *rng) {
    static const double seps[] = {1e-1, 1e-3, 1e-6, 1e-9, -1e-3, -1e-1};
    for (size_t s = 0; s < sizeof seps / sizeof seps[0]; s++) {
        problem p;
        agjk_vec3 n = stab_unit(rng);
        double nn[3] = {n.x, n.y, n.z};
        char name[96];
        memset(&p, 0, sizeof p);
        p.a = a;
        p.b = b;
        if (verts_a) {
            random_points(p.va, verts_a, rng, flat);
            p.a.vertices = p.va;
            p.a.vertex_count = verts_a;
        }
        if (verts_b) {
            random_points(p.vb, verts_b, rng, flat);
            p.b.vertices = p.vb;
            p.b.vertex_count = verts_b;
        }
        stab_pose_identity(&p.pa);
        stab_pose_identity(&p.pb);
        stab_pose_random_rotation(&p.pa, rng);
        stab_pose_random_rotation(&p.pb, rng);
        p.pa.translation.x = stab_range(rng, -1, 1);
        p.pa.translation.y = stab_range(rng, -1, 1);
        p.pa.translation.z = stab_range(rng, -1, 1);
        p.sep = seps[s];
        if (seps[s] >= 0) {
            stab_place(&p.a, &p.pa, &p.b, &p.pb, nn, seps[s]);
        } else {
            p.overlap_certified = stab_place_overlap(&p.a, &p.pa, &p.b, &p.pb, nn, -seps[s]);
        }
        snprintf(name, sizeof name, "%s sep %g", tag, seps[s]);
        check_problem(name, &p);
    }
}

START_TEST(test_scale_families) {
    stab_rng rng = {2001};
    for (int rep = 0; rep < 3; rep++) {
        run_family("ellipsoids", mk(REF_ELLIPSOID, 1, 0.3, 0.1, 0), mk(REF_ELLIPSOID, 0.5, 0.5, 0.2, 0),
                   0, 0, 1, &rng);
        run_family("stiff ellipsoids", mk(REF_ELLIPSOID, 1, 1e-2, 1e-4, 0),
                   mk(REF_ELLIPSOID, 1e-4, 1, 0.5, 0), 0, 0, 1, &rng);
        run_family("boxes", mk(REF_BOX, 0.5, 0.3, 0.2, 0), mk(REF_BOX, 0.4, 0.4, 0.4, 0), 0, 0, 1, &rng);
        run_family("plate/needle", mk(REF_BOX, 1, 1, 1e-6, 0), mk(REF_BOX, 1e-6, 1e-6, 1, 0), 0, 0, 1,
                   &rng);
        run_family("spheres", mk(REF_SPHERE, 0.5, 0, 0, 0), mk(REF_SPHERE, 0.2, 0, 0, 0), 0, 0, 1, &rng);
        run_family("capsule/cylinder", mk(REF_CAPSULE, 0.2, 0.5, 0, 0), mk(REF_CYLINDER, 0.3, 0.4, 0, 0),
                   0, 0, 1, &rng);
        run_family("cone/rounded box", mk(REF_CONE, 0.4, 0.3, 0, 0), mk(REF_BOX, 0.2, 0.3, 0.1, 0.05), 0, 0,
                   1, &rng);
        run_family("polytopes", mk(REF_POLYTOPE, 0, 0, 0, 0), mk(REF_POLYTOPE, 0, 0, 0, 0), 40, 12, 1,
                   &rng);
        run_family("flat polytopes", mk(REF_POLYTOPE, 0, 0, 0, 0), mk(REF_ELLIPSOID, 0.3, 0.2, 0.1, 0),
                   16, 0, 0, &rng);
    }
    printf("scale invariance: %ld problems x %zu scales (%ld queries): %ld Boolean flips, "
           "%ld certain/uncertain verdict changes, %ld power-of-two equivariance breaks, "
           "%ld relative-error breaks, %ld minor result defects; worst relative error %.3g, "
           "worst change of relative error across scales %.3g\n",
           g_problems, NFACT, g_queries, g_bool_flips, g_verdict_changes, g_exact_breaks,
           g_rel_breaks, g_minor, g_worst_rel, g_worst_rel_change);
    ck_assert_int_eq(g_bool_flips, 0);
    ck_assert_int_eq(g_exact_breaks, 0);
    ck_assert_int_eq(g_rel_breaks, 0);
    ck_assert_int_eq(g_minor, 0);
}
END_TEST

/* Far outside the tested range, 1e-300 ... 1e50 (AGJK_MAX_COORDINATE): the
 * library may refuse (INVALID_INPUT) or lose accuracy (NOT_CONVERGED, large
 * bound), but it must not lie: a certified bracket must hold the truth and a
 * certain Boolean answer must be right. Underflow of squared norms is the
 * danger at the small end (1e-160 squared is below DBL_MIN). */
static long g_extreme_checked, g_extreme_lies, g_extreme_refused;

static void check_extreme(const char *tag, const problem *p) {
    static const double far_factors[] = {1e-300, 1e-250, 1e-200, 1e-160, 1e-150, 1e-120, 1e-100,
                                         1e-60, 1e-20, 1e20, 1e40};
    for (size_t k = 0; k < sizeof far_factors / sizeof far_factors[0]; k++) {
        double f = far_factors[k];
        problem q;
        agjk_shape sa, sb;
        scale_problem(p, f, &q);
        if (stab_make_shape(&q.a, &sa) != AGJK_STATUS_OK ||
            stab_make_shape(&q.b, &sb) != AGJK_STATUS_OK) {
            g_extreme_refused++;
            continue;
        }
        double slack = 64 * DBL_EPSILON * stab_magnitude(&q.a, &q.pa, &q.b, &q.pb);
        for (int m = 0; m < 5; m++) {
            agjk_options opt = agjk_default_options();
            agjk_result r;
            agjk_status sd, sc;
            opt.method = (agjk_method)m;
            opt.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
            opt.max_iterations = 256;
            sd = agjk_distance(&sa, &q.pa, &sb, &q.pb, &opt, &r);
            ck_assert_msg(stab_result_sane("extreme distance", sd, &r, 256) < 2, "%s x %g", tag, f);
            g_extreme_checked++;
            if (sd == AGJK_STATUS_INVALID_INPUT) {
                g_extreme_refused++;
            } else if (p->sep >= 0) {
                double truth = p->sep * f, lo = r.distance - r.bound;
                if (truth < lo - slack || truth > r.distance + slack ||
                    (sd == AGJK_STATUS_INTERSECTING && truth > slack)) {
                    printf("FAIL %s x %g [%s]: %s distance %.17g bound %.3g, true %.17g\n", tag, f,
                           agjk_method_name(opt.method), agjk_status_string(sd), r.distance,
                           r.bound, truth);
                    g_extreme_lies++;
                }
            } else if (p->overlap_certified && sd == AGJK_STATUS_SEPARATED) {
                printf("FAIL %s x %g [%s]: certified overlap answered separated\n", tag, f,
                       agjk_method_name(opt.method));
                g_extreme_lies++;
            }
            sc = agjk_collide(&sa, &q.pa, &sb, &q.pb, &opt, &r);
            ck_assert_msg(stab_result_sane("extreme collide", sc, &r, 256) < 2, "%s x %g", tag, f);
            g_extreme_checked++;
            if ((p->sep > 0 && p->sep * f > slack && sc == AGJK_STATUS_INTERSECTING) ||
                (p->overlap_certified && sc == AGJK_STATUS_SEPARATED)) {
                printf("FAIL %s x %g [%s]: collide says %s, truth separation %g\n", tag, f,
                       agjk_method_name(opt.method), agjk_status_string(sc), p->sep * f);
                g_extreme_lies++;
            }
        }
    }
}

START_TEST(test_extreme_scales_honest) {
    stab_rng rng = {2002};
    static const double seps[] = {0.5, 1e-3, -1e-2};
    ref_shape pairs[4][2];
    pairs[0][0] = mk(REF_ELLIPSOID, 0.5, 0.3, 0.2, 0);
    pairs[0][1] = mk(REF_BOX, 0.4, 0.4, 0.1, 0);
    pairs[1][0] = mk(REF_SPHERE, 0.5, 0, 0, 0);
    pairs[1][1] = mk(REF_CAPSULE, 0.2, 0.4, 0, 0);
    pairs[2][0] = mk(REF_CYLINDER, 0.3, 0.4, 0, 0);
    pairs[2][1] = mk(REF_CONE, 0.4, 0.3, 0, 0);
    pairs[3][0] = mk(REF_ELLIPSOID, 1, 1e-2, 1e-3, 0);
    pairs[3][1] = mk(REF_BOX, 0.3, 0.2, 0.1, 0.05);
    for (int i = 0; i < 4; i++)
        for (size_t s = 0; s < sizeof seps / sizeof seps[0]; s++) {
            problem p;
            agjk_vec3 n = stab_unit(&rng);
            double nn[3] = {n.x, n.y, n.z};
            char name[64];
            memset(&p, 0, sizeof p);
            p.a = pairs[i][0];
            p.b = pairs[i][1];
            stab_pose_identity(&p.pa);
            stab_pose_identity(&p.pb);
            stab_pose_random_rotation(&p.pa, &rng);
            stab_pose_random_rotation(&p.pb, &rng);
            p.pa.translation.x = stab_range(&rng, -1, 1);
            p.sep = seps[s];
            if (seps[s] >= 0)
                stab_place(&p.a, &p.pa, &p.b, &p.pb, nn, seps[s]);
            else
                p.overlap_certified = stab_place_overlap(&p.a, &p.pa, &p.b, &p.pb, nn, -seps[s]);
            snprintf(name, sizeof name, "extreme pair %d sep %g", i, seps[s]);
            check_extreme(name, &p);
        }
    printf("extreme scales 1e-300 ... 1e40: %ld queries, %ld refused (INVALID_INPUT), %ld dishonest\n",
           g_extreme_checked, g_extreme_refused, g_extreme_lies);
    ck_assert_int_eq(g_extreme_lies, 0);
}
END_TEST

int main(void) {
    Suite *s = suite_create("scale invariance");
    TCase *tc = tcase_create("scales");
    SRunner *sr;
    int failed;
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_scale_families);
    tcase_add_test(tc, test_extreme_scales_honest);
    suite_add_tcase(s, tc);
    sr = srunner_create(s);
    alarm(300);
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
