/* SPDX-License-Identifier: MIT */
/* Validates the reference solver itself against analytic truth, so that the
 * tests which use it as ground truth rest on something checked:
 *   - sphere-sphere: |c_a - c_b| - r_a - r_b;
 *   - axis-aligned box-box: the norm of the per-axis gaps;
 *   - sphere-box (rotated box): |c - clamp(c)| - r in the box frame;
 *   - the brute-force simplex projection against the optimality condition of
 *     the closest point (<p, w_i - p> >= 0 for every vertex w_i). */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include "check_main.h"
#include "reference.h"
#include "testutil.h"

#define N_CASES 400

static agjk_pose pose_at(agjk_vec3 t) {
    agjk_pose p = tu_pose_identity();
    p.translation = t;
    return p;
}

/* Checks a reference result against the true signed distance `truth`
 * (negative: overlap by a clear amount, in which case intersecting is required). */
static void expect_distance(const ref_result *r, double truth, double size, const char *what,
                            int i) {
    double tol = 1e-14 * size;
    if (truth < -tol) {
        TU_ENSURE(r->intersecting == 1, "%s %d: overlap %g not certified", what, i, truth);
        TU_ENSURE(r->distance == 0.0L, "%s %d: intersecting with distance", what, i);
        return;
    }
    TU_ENSURE(r->intersecting == 0, "%s %d: separated pair (d = %g) called intersecting",
                  what, i, truth);
    TU_ENSURE(r->converged == 1, "%s %d: not converged", what, i);
    TU_ENSURE(fabsl(r->distance - truth) <= tol, "%s %d: distance %.17Lg, truth %.17g", what,
                  i, r->distance, truth);
    TU_ENSURE(r->lower <= truth + tol && r->upper >= truth - tol,
                  "%s %d: bounds [%.17Lg, %.17Lg] miss truth %.17g", what, i, r->lower, r->upper,
                  truth);
    if (truth > tol) {
        /* witnesses: distance apart, along the normal */
        agjk_vec3 d = tu_sub(r->witness_b, r->witness_a);
        TU_ENSURE(fabs(tu_norm(d) - truth) <= 1e-12 * size, "%s %d: witness gap", what, i);
        TU_ENSURE(fabs(tu_norm(r->normal) - 1.0) <= 1e-12, "%s %d: normal not unit", what, i);
        TU_ENSURE(tu_dot(d, r->normal) >= truth - 1e-12 * size, "%s %d: normal direction",
                      what, i);
    }
}

START_TEST(sphere_sphere) {
    tu_rng rng;
    tu_rng_seed(&rng, 1);
    for (int i = 0; i < N_CASES; i++) {
        double ra = tu_paper_radius(&rng, 1.0), rb = tu_paper_radius(&rng, 1.0);
        double gap = (i % 2 ? 1.0 : -1.0) * tu_log_uniform(&rng, -8, 0) * (ra + rb) * 0.5;
        agjk_vec3 u = tu_unit_vector(&rng);
        agjk_vec3 ca = tu_scale(tu_unit_vector(&rng), tu_uniform(&rng));
        agjk_vec3 cb = tu_add(ca, tu_scale(u, ra + rb + gap));
        ref_shape a, b;
        tu_shape_init(&a, REF_SPHERE, ra, 0, 0);
        tu_shape_init(&b, REF_SPHERE, rb, 0, 0);
        agjk_pose pa = pose_at(ca), pb = pose_at(cb);
        ref_result r;
        ref_distance(&a, &pa, &b, &pb, &r);
        double truth = tu_norm(tu_sub(cb, ca)) - ra - rb; /* recomputed: cb was rounded */
        expect_distance(&r, truth, 1.0, "sphere-sphere", i);
    }
}
END_TEST

START_TEST(box_box_axis_aligned) {
    tu_rng rng;
    tu_rng_seed(&rng, 2);
    for (int i = 0; i < N_CASES; i++) {
        ref_shape a, b;
        tu_random_box(&rng, &a, 1.0);
        tu_random_box(&rng, &b, 1.0);
        agjk_vec3 t = tu_scale(tu_unit_vector(&rng), tu_uniform_range(&rng, 0.0, 0.8));
        agjk_pose pa = pose_at(tu_vec(0.25, -0.5, 1.0));
        agjk_pose pb = pose_at(tu_add(pa.translation, t));
        /* gap per axis: |t_i| - (ha_i + hb_i) */
        double g[3] = {fabs(t.x) - a.p[0] - b.p[0], fabs(t.y) - a.p[1] - b.p[1],
                       fabs(t.z) - a.p[2] - b.p[2]};
        double truth = 0.0, deepest = -INFINITY;
        for (int k = 0; k < 3; k++) {
            if (g[k] > 0) truth += g[k] * g[k];
            if (g[k] > deepest) deepest = g[k];
        }
        truth = truth > 0 ? sqrt(truth) : (deepest < 0 ? deepest : 0.0);
        ref_result r;
        ref_distance(&a, &pa, &b, &pb, &r);
        expect_distance(&r, truth, 1.0, "box-box", i);
    }
}
END_TEST

START_TEST(box_box_touching) {
    /* Face contact with distance exactly 0: the reference must not claim
     * a strict overlap, and must report distance ~ 0. */
    ref_shape a, b;
    tu_shape_init(&a, REF_BOX, 0.5, 0.25, 0.125);
    tu_shape_init(&b, REF_BOX, 0.25, 0.5, 0.25);
    agjk_pose pa = pose_at(tu_vec(0, 0, 0)), pb = pose_at(tu_vec(0.75, 0.125, 0.0625));
    ref_result r;
    ref_distance(&a, &pa, &b, &pb, &r);
    TU_CHECK_INT_EQ(r.intersecting, 0);
    TU_CHECK(r.distance <= 1e-15L);
    TU_CHECK(r.lower <= 0.0L);
}
END_TEST

START_TEST(sphere_box_rotated) {
    tu_rng rng;
    tu_rng_seed(&rng, 3);
    for (int i = 0; i < N_CASES; i++) {
        ref_shape s, b;
        double rad = tu_paper_radius(&rng, 1.0);
        tu_shape_init(&s, REF_SPHERE, rad, 0, 0);
        tu_random_box(&rng, &b, 1.0);
        agjk_pose pb = tu_random_pose(&rng, 1.0);
        /* centre in the box frame, then to the world */
        agjk_vec3 local = tu_vec(tu_uniform_range(&rng, -0.6, 0.6), tu_uniform_range(&rng, -0.6, 0.6),
                                 tu_uniform_range(&rng, -0.6, 0.6));
        agjk_pose ps = pose_at(tu_pose_apply(&pb, local));
        agjk_vec3 q = tu_vec(fmax(-b.p[0], fmin(b.p[0], local.x)),
                             fmax(-b.p[1], fmin(b.p[1], local.y)),
                             fmax(-b.p[2], fmin(b.p[2], local.z)));
        double out = tu_norm(tu_sub(local, q));
        if (out == 0.0) continue; /* centre inside the box: deep overlap, checked below */
        double truth = out - rad;
        ref_result r;
        ref_distance(&b, &pb, &s, &ps, &r);
        expect_distance(&r, truth, 1.0, "box-sphere", i);
    }
}
END_TEST

START_TEST(polytope_equals_box) {
    /* The same box as 8 vertices and as a box, rotated: same distance. */
    tu_rng rng;
    tu_rng_seed(&rng, 4);
    for (int i = 0; i < N_CASES / 4; i++) {
        ref_shape box, poly, other;
        agjk_vec3 v[8];
        tu_random_box(&rng, &box, 1.0);
        for (int k = 0; k < 8; k++)
            v[k] = tu_vec(k & 1 ? box.p[0] : -box.p[0], k & 2 ? box.p[1] : -box.p[1],
                          k & 4 ? box.p[2] : -box.p[2]);
        tu_shape_init(&poly, REF_POLYTOPE, 0, 0, 0);
        poly.vertices = v;
        poly.vertex_count = 8;
        tu_random_ellipsoid(&rng, &other, 1.0);
        agjk_pose pa = tu_random_pose(&rng, 0.3), pb = tu_random_pose(&rng, 0.3);
        ref_result r1, r2;
        ref_distance(&box, &pa, &other, &pb, &r1);
        ref_distance(&poly, &pa, &other, &pb, &r2);
        TU_CHECK_INT_EQ(r1.intersecting, r2.intersecting);
        TU_ENSURE(fabsl(r1.distance - r2.distance) <= 1e-14L, "%d: %Lg vs %Lg", i,
                      r1.distance, r2.distance);
    }
}
END_TEST

START_TEST(projection_optimality) {
    /* p = proj(0, conv W) iff <p, w_i - p> >= 0 for every vertex (the
     * variational inequality of the projection onto a convex set). Also
     * weights >= 0, summing to 1, reproducing p. */
    tu_rng rng;
    tu_rng_seed(&rng, 5);
    for (int i = 0; i < 20000; i++) {
        agjk_vec3 w[4];
        int n = 1 + (int)tu_uniform_int(&rng, 4);
        double size = tu_log_uniform(&rng, -3, 3);
        agjk_vec3 c = tu_scale(tu_unit_vector(&rng), size * tu_uniform_range(&rng, 0.0, 2.0));
        for (int k = 0; k < n; k++) w[k] = tu_add(c, tu_scale(tu_unit_vector(&rng), size));
        if (i % 5 == 0 && n >= 3) w[2] = tu_add(tu_scale(w[0], 0.3), tu_scale(w[1], 0.7));
        ref_projection pj;
        TU_CHECK_INT_EQ(ref_project_origin(w, n, &pj), 0);
        long double p[3] = {pj.point[0], pj.point[1], pj.point[2]};
        long double sum = 0, rec[3] = {0, 0, 0};
        for (int k = 0; k < n; k++) {
            TU_CHECK(pj.weights[k] >= 0.0L);
            sum += pj.weights[k];
            rec[0] += pj.weights[k] * w[k].x;
            rec[1] += pj.weights[k] * w[k].y;
            rec[2] += pj.weights[k] * w[k].z;
            long double g = p[0] * (w[k].x - p[0]) + p[1] * (w[k].y - p[1]) + p[2] * (w[k].z - p[2]);
            TU_ENSURE(g >= -1e-15L * size * size, "case %d vertex %d: <p, w - p> = %Lg", i, k, g);
        }
        TU_CHECK(fabsl(sum - 1.0L) <= 1e-15L);
        for (int k = 0; k < 3; k++) TU_CHECK(fabsl(rec[k] - p[k]) <= 1e-15L * size * 4);
    }
    TU_CHECK_INT_EQ(ref_project_origin(NULL, 1, NULL), -1);
}
END_TEST

int main(void) {
    Suite *s = suite_create("reference");
    TU_ADD(s, sphere_sphere);
    TU_ADD(s, box_box_axis_aligned);
    TU_ADD(s, box_box_touching);
    TU_ADD(s, sphere_box_rotated);
    TU_ADD(s, polytope_equals_box);
    TU_ADD(s, projection_optimality);
    return tu_run_suite(s);
}
