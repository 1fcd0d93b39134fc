/* SPDX-License-Identifier: MIT */
/* Distances with a closed form, with every method and two tolerances:
 * sphere-sphere, sphere-box, box-box with aligned axes (any common rotation),
 * capsule-capsule (segment-segment distance computed here), and a point over
 * a cylinder's cap whose final simplex is a sliver. Checked: the
 * certified interval [distance - bound, distance] holds the truth, the status
 * matches, witness points lie on the shapes, |witness_b - witness_a| =
 * distance (for Frank-Wolfe, within the certified interval), the normal is
 * unit and along witness_b - witness_a. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "core_checks.h"

#define N_PAIRS 300
#define EPS 1e-12 /* rounding allowance, shapes of size ~0.1 .. 1 */

/* Closest distance between segments [p0, p1] and [q0, q1]. The squared
 * distance is a convex quadratic in (s, t) on [0,1]^2: its minimum is the
 * stationary point if inside, else on an edge of the square, where it is a
 * convex parabola minimised by the clamped projection. Take the best. */
static double clamp01(double v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }

static double point_segment(agjk_vec3 p, agjk_vec3 a, agjk_vec3 b) {
    agjk_vec3 ab = tu_sub(b, a);
    double l2 = tu_dot(ab, ab);
    double t = l2 > 0 ? clamp01(tu_dot(tu_sub(p, a), ab) / l2) : 0.0;
    return tu_norm(tu_sub(p, tu_add(a, tu_scale(ab, t))));
}

static double segment_segment(agjk_vec3 p0, agjk_vec3 p1, agjk_vec3 q0, agjk_vec3 q1) {
    double best = fmin(fmin(point_segment(p0, q0, q1), point_segment(p1, q0, q1)),
                       fmin(point_segment(q0, p0, p1), point_segment(q1, p0, p1)));
    agjk_vec3 u = tu_sub(p1, p0), v = tu_sub(q1, q0), w = tu_sub(p0, q0);
    double a = tu_dot(u, u), b = tu_dot(u, v), c = tu_dot(v, v), d = tu_dot(u, w), e = tu_dot(v, w);
    double den = a * c - b * b;
    if (den > 1e-14 * a * c) { /* not parallel: the interior stationary point */
        double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
        if (s >= 0 && s <= 1 && t >= 0 && t <= 1)
            best = fmin(best, tu_norm(tu_sub(tu_add(p0, tu_scale(u, s)), tu_add(q0, tu_scale(v, t)))));
    }
    return best;
}

/* Distance from a world point to a shape with a closed form (<= 0 inside). */
static double signed_gap(const ref_shape *s, const agjk_pose *pose, agjk_vec3 w) {
    agjk_vec3 l = tu_sub(w, pose->translation);
    /* local = R^T (w - t) */
    agjk_vec3 loc = tu_vec(pose->rotation[0][0] * l.x + pose->rotation[1][0] * l.y + pose->rotation[2][0] * l.z,
                           pose->rotation[0][1] * l.x + pose->rotation[1][1] * l.y + pose->rotation[2][1] * l.z,
                           pose->rotation[0][2] * l.x + pose->rotation[1][2] * l.y + pose->rotation[2][2] * l.z);
    switch (s->kind) {
    case REF_SPHERE:
        return tu_norm(loc) - s->p[0];
    case REF_BOX: {
        agjk_vec3 q = tu_vec(fmax(-s->p[0], fmin(s->p[0], loc.x)), fmax(-s->p[1], fmin(s->p[1], loc.y)),
                             fmax(-s->p[2], fmin(s->p[2], loc.z)));
        return tu_norm(tu_sub(loc, q));
    }
    case REF_CAPSULE:
        return point_segment(loc, tu_vec(0, 0, -s->p[1]), tu_vec(0, 0, s->p[1])) - s->p[0];
    default:
        return NAN;
    }
}

typedef struct pair_case {
    ref_shape a, b;
    agjk_pose pa, pb;
    double truth; /* signed: < 0 is an overlap (of that depth, or at least that much) */
} pair_case;

static void make_case(int kind, int i, tu_rng *rng, pair_case *c) {
    double sep = (i % 3 == 0) ? -tu_uniform_range(rng, 0.01, 0.05) : tu_log_uniform(rng, -3, 0);
    switch (kind) {
    case 0: { /* sphere-sphere */
        double ra = tu_paper_radius(rng, 1), rb = tu_paper_radius(rng, 1);
        tu_shape_init(&c->a, REF_SPHERE, ra, 0, 0);
        tu_shape_init(&c->b, REF_SPHERE, rb, 0, 0);
        c->pa = tu_random_pose(rng, 1.0);
        c->pb = tu_random_pose(rng, 0.0);
        c->pb.translation = tu_add(c->pa.translation, tu_scale(tu_unit_vector(rng), ra + rb + sep));
        c->truth = tu_norm(tu_sub(c->pb.translation, c->pa.translation)) - ra - rb;
        break;
    }
    case 1: { /* box-sphere: centre outside the box (or inside for overlaps) */
        tu_random_box(rng, &c->a, 1);
        double r = tu_paper_radius(rng, 1);
        tu_shape_init(&c->b, REF_SPHERE, r, 0, 0);
        c->pa = tu_random_pose(rng, 1.0);
        c->pb = tu_random_pose(rng, 0.0);
        agjk_vec3 loc = tu_vec(tu_uniform_range(rng, -1, 1) * c->a.p[0], tu_uniform_range(rng, -1, 1) * c->a.p[1],
                               tu_uniform_range(rng, -1, 1) * c->a.p[2]);
        /* push out through a random face, edge or corner */
        agjk_vec3 dir = tu_vec(0, 0, 0);
        double *cmp[3] = {&dir.x, &dir.y, &dir.z};
        for (int k = 0; k < 3; k++)
            if (k == (i % 3) || tu_uniform(rng) < 0.3) *cmp[k] = tu_uniform(rng) < 0.5 ? -1 : 1;
        agjk_vec3 corner = tu_vec(dir.x != 0 ? dir.x * c->a.p[0] : loc.x, dir.y != 0 ? dir.y * c->a.p[1] : loc.y,
                                  dir.z != 0 ? dir.z * c->a.p[2] : loc.z);
        dir = tu_scale(dir, 1.0 / tu_norm(dir));
        agjk_vec3 centre = sep > 0 ? tu_add(corner, tu_scale(dir, r + sep)) : loc;
        c->pb.translation = tu_pose_apply(&c->pa, centre);
        double g = signed_gap(&c->a, &c->pa, c->pb.translation);
        c->truth = g > 0 ? g - r : -r; /* centre inside the box: overlap of at least r */
        break;
    }
    case 2: { /* box-box, aligned axes, common random rotation */
        tu_random_box(rng, &c->a, 1);
        tu_random_box(rng, &c->b, 1);
        c->pa = tu_random_pose(rng, 1.0);
        c->pb = c->pa;
        agjk_vec3 delta;
        double g[3];
        do {
            delta = tu_scale(tu_unit_vector(rng), tu_uniform_range(rng, 0.05, 0.9));
            g[0] = fabs(delta.x) - c->a.p[0] - c->b.p[0];
            g[1] = fabs(delta.y) - c->a.p[1] - c->b.p[1];
            g[2] = fabs(delta.z) - c->a.p[2] - c->b.p[2];
        } while (fmax(g[0], fmax(g[1], g[2])) > -0.01 && fmax(g[0], fmax(g[1], g[2])) < 1e-3);
        c->pb.translation = tu_pose_apply(&c->pa, delta);
        double s2 = 0, deepest = fmax(g[0], fmax(g[1], g[2]));
        for (int k = 0; k < 3; k++)
            if (g[k] > 0) s2 += g[k] * g[k];
        c->truth = s2 > 0 ? sqrt(s2) : deepest;
        break;
    }
    default: { /* capsule-capsule */
        tu_shape_init(&c->a, REF_CAPSULE, tu_paper_radius(rng, 1), tu_paper_radius(rng, 2), 0);
        tu_shape_init(&c->b, REF_CAPSULE, tu_paper_radius(rng, 1), tu_paper_radius(rng, 2), 0);
        c->pa = tu_random_pose(rng, 0.5);
        c->pb = tu_random_pose(rng, 0.5);
        agjk_vec3 za = tu_vec(0, 0, c->a.p[1]), zb = tu_vec(0, 0, c->b.p[1]);
        double core = segment_segment(tu_pose_apply(&c->pa, tu_scale(za, -1)), tu_pose_apply(&c->pa, za),
                                      tu_pose_apply(&c->pb, tu_scale(zb, -1)), tu_pose_apply(&c->pb, zb));
        c->truth = core - c->a.p[0] - c->b.p[0];
        break;
    }
    }
}

static const char *kind_name[4] = {"sphere-sphere", "box-sphere", "box-box", "capsule-capsule"};

static void run_kind(int kind, agjk_tolerance_mode mode, double tol, uint64_t seed) {
    tu_rng rng;
    tu_rng_seed(&rng, seed);
    int separated = 0, overlapping = 0, status_count[CORE_METHOD_COUNT][5] = {{0}};
    for (int i = 0; i < N_PAIRS; i++) {
        pair_case c;
        make_case(kind, i, &rng, &c);
        agjk_shape sa, sb;
        TU_CHECK_INT_EQ(ref_make_agjk(&c.a, &sa), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(ref_make_agjk(&c.b, &sb), AGJK_STATUS_OK);
        truth_interval t = truth_exact(c.truth, EPS);
        for (int m = 0; m < CORE_METHOD_COUNT; m++) {
            agjk_options o = agjk_default_options();
            o.method = core_methods[m];
            o.tolerance_mode = mode;
            o.tolerance = tol;
            int fw = o.method == AGJK_METHOD_FRANK_WOLFE;
            agjk_result r;
            agjk_distance(&sa, &c.pa, &sb, &c.pb, &o, &r);
            if ((unsigned)r.status < 5) status_count[m][r.status]++;
            char why[256];
            const char *mn = agjk_method_name(o.method);
            TU_ENSURE(check_distance_result(&r, t, EPS, fw, why, sizeof why) == 0,
                      "%s %d %s (truth %.17g, distance %.17g, bound %g, it %d): %s", kind_name[kind], i,
                      mn, c.truth, r.distance, r.bound, (int)r.iterations, why);
            /* The verdict, when the truth is clear of the tolerance. */
            if (t.overlap && !fw)
                TU_ENSURE(r.status == AGJK_STATUS_INTERSECTING, "%s %d %s: overlap %g, status %s",
                          kind_name[kind], i, mn, c.truth, agjk_status_string(r.status));
            if (c.truth > 10 * sqrt(tol) * (mode == AGJK_TOLERANCE_RELATIVE ? c.truth : 1.0) &&
                !(fw && r.status == AGJK_STATUS_NOT_CONVERGED))
                TU_ENSURE(r.status == AGJK_STATUS_SEPARATED, "%s %d %s: distance %g, status %s",
                          kind_name[kind], i, mn, c.truth, agjk_status_string(r.status));
            if (r.status != AGJK_STATUS_SEPARATED) continue;
            /* Witness points on the shapes, the normal along them. */
            double ga = signed_gap(&c.a, &c.pa, r.witness_a), gb = signed_gap(&c.b, &c.pb, r.witness_b);
            TU_ENSURE(ga <= EPS && gb <= EPS, "%s %d %s: witness off the shapes by %g, %g",
                      kind_name[kind], i, mn, ga, gb);
            /* |wb - wa| = distance; for Frank-Wolfe within the certified
             * interval, whose upper end, the distance, allows for the
             * rounding its iterate has gathered over hundreds of steps. */
            agjk_vec3 ab = tu_sub(r.witness_b, r.witness_a);
            double slack = fw ? r.bound : 0.0;
            TU_ENSURE(tu_norm(ab) <= r.distance + EPS && tu_norm(ab) >= r.distance - slack - EPS,
                      "%s %d %s: |wb - wa| = %.17g, distance %.17g, bound %g", kind_name[kind], i,
                      mn, tu_norm(ab), r.distance, r.bound);
            TU_ENSURE(fabs(tu_norm(r.normal) - 1.0) <= 1e-12, "%s %d %s: |normal| = %.17g",
                      kind_name[kind], i, mn, tu_norm(r.normal));
            TU_ENSURE(tu_norm(tu_sub(tu_scale(r.normal, r.distance), ab)) <=
                          EPS + slack + 1e-12 * r.distance,
                      "%s %d %s: normal not along wb - wa", kind_name[kind], i, mn);
        }
        if (t.overlap) overlapping++;
        else separated++;
    }
    printf("%-15s %s %g: sep/int/contact/not-conv per method:", kind_name[kind],
           mode == AGJK_TOLERANCE_RELATIVE ? "rel" : "abs", tol);
    for (int m = 0; m < CORE_METHOD_COUNT; m++)
        printf(" %s %d/%d/%d/%d", agjk_method_name(core_methods[m]), status_count[m][0],
               status_count[m][1], status_count[m][2], status_count[m][3]);
    printf("\n");
    TU_ENSURE(separated > N_PAIRS / 2 && overlapping > N_PAIRS / 10, "case mix %d/%d", separated,
              overlapping);
}

START_TEST(sphere_sphere) {
    run_kind(0, AGJK_TOLERANCE_ABSOLUTE, 1e-8, 31);
    run_kind(0, AGJK_TOLERANCE_RELATIVE, 1e-10, 32);
}
END_TEST

START_TEST(sphere_box) {
    run_kind(1, AGJK_TOLERANCE_ABSOLUTE, 1e-8, 33);
    run_kind(1, AGJK_TOLERANCE_RELATIVE, 1e-10, 34);
}
END_TEST

START_TEST(box_box_aligned) {
    run_kind(2, AGJK_TOLERANCE_ABSOLUTE, 1e-8, 35);
    run_kind(2, AGJK_TOLERANCE_RELATIVE, 1e-10, 36);
}
END_TEST

START_TEST(capsule_capsule) {
    run_kind(3, AGJK_TOLERANCE_ABSOLUTE, 1e-8, 37);
    run_kind(3, AGJK_TOLERANCE_RELATIVE, 1e-10, 38);
}
END_TEST

/* A point 2e-5 over a cylinder's cap, where GJK's final triangle is a sliver
 * (two vertices a few ulps apart, the third far off): its foot is right, its
 * barycentric weights were off by tens of percent, and the witness points
 * combined from them came out 0.116 apart with Nesterov and Polyak. */
START_TEST(cylinder_cap_sliver_witness) {
    agjk_cylinder cyl = {0x1.62cc62f436051p-1, 0x1.f371827adfc7p-6};
    agjk_shape sa, sb;
    TU_CHECK_INT_EQ(agjk_shape_cylinder(&sa, &cyl), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_point(&sb), AGJK_STATUS_OK);
    agjk_pose pa = {{{0x1.ce4c940d70658p-1, 0x1.1ab1ad2eada45p-4, -0x1.b26533ec513eep-2},
                     {0x1.c76dde87eaf6fp-6, 0x1.f37efd86b4e8fp-1, 0x1.be3b278b2ecap-3},
                     {0x1.b72f770e8c774p-2, -0x1.ab1080ef19ee4p-3, 0x1.c206d67ee876dp-1}},
                    {0, 0, 0}};
    agjk_pose pb = tu_pose_identity();
    pb.translation = tu_vec(0x1.0b1eb9be91ffap-7, -0x1.7083f590a344ep-5, -0x1.416e6b17acd4fp-6);
    /* The point in the cylinder's frame, R_A^T t_B (as the query reads the
     * pose), in long double: over the cap, so the distance is |z| - h. */
    long double local[3];
    for (int i = 0; i < 3; i++)
        local[i] = (long double)pa.rotation[0][i] * pb.translation.x +
                   (long double)pa.rotation[1][i] * pb.translation.y +
                   (long double)pa.rotation[2][i] * pb.translation.z;
    ck_assert(local[0] * local[0] + local[1] * local[1] < (long double)cyl.radius * cyl.radius);
    double truth = (double)(fabsl(local[2]) - cyl.half_height);
    truth_interval t = truth_exact(truth, EPS);
    double tolerances[2] = {1e-300, 1e-8};
    for (int k = 0; k < 2; k++)
        for (int m = 0; m < CORE_METHOD_COUNT; m++) {
            agjk_options o = agjk_default_options();
            o.method = core_methods[m];
            o.tolerance = tolerances[k];
            o.compute = AGJK_COMPUTE_WITNESS;
            agjk_result r;
            agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
            const char *mn = agjk_method_name(o.method);
            char why[256];
            TU_ENSURE(check_distance_result(&r, t, EPS, o.method == AGJK_METHOD_FRANK_WOLFE, why,
                                            sizeof why) == 0,
                      "%s %g: %s", mn, o.tolerance, why);
            TU_CHECK_INT_EQ(r.status, AGJK_STATUS_SEPARATED);
            agjk_vec3 ab = tu_sub(r.witness_b, r.witness_a);
            TU_ENSURE(fabs(tu_norm(ab) - r.distance) <= EPS, "%s %g: |wb - wa| = %.17g, distance %.17g",
                      mn, o.tolerance, tu_norm(ab), r.distance);
            TU_ENSURE(tu_norm(tu_sub(r.witness_b, pb.translation)) <= EPS,
                      "%s %g: witness on the point off by %g", mn, o.tolerance,
                      tu_norm(tu_sub(r.witness_b, pb.translation)));
        }
}
END_TEST

START_TEST(segment_distance_itself) {
    /* The test's own segment-segment distance against brute-force sampling. */
    tu_rng rng;
    tu_rng_seed(&rng, 39);
    for (int i = 0; i < 200; i++) {
        agjk_vec3 p0 = tu_unit_vector(&rng), p1 = tu_unit_vector(&rng);
        agjk_vec3 q0 = tu_add(tu_unit_vector(&rng), tu_vec(0.5, 0, 0)), q1 = tu_unit_vector(&rng);
        if (i % 4 == 0) q1 = tu_add(q0, tu_sub(p1, p0)); /* parallel */
        double d = segment_segment(p0, p1, q0, q1), brute = INFINITY;
        for (int a = 0; a <= 200; a++)
            for (int b = 0; b <= 200; b++) {
                agjk_vec3 x = tu_add(p0, tu_scale(tu_sub(p1, p0), a / 200.0));
                agjk_vec3 y = tu_add(q0, tu_scale(tu_sub(q1, q0), b / 200.0));
                brute = fmin(brute, tu_norm(tu_sub(x, y)));
            }
        TU_ENSURE(d <= brute + 1e-15 && d >= brute - 2e-2, "%d: %g vs brute %g", i, d, brute);
    }
}
END_TEST

int main(void) {
    Suite *s = suite_create("analytic");
    TU_ADD(s, segment_distance_itself);
    TU_ADD(s, sphere_sphere);
    TU_ADD(s, sphere_box);
    TU_ADD(s, box_box_aligned);
    TU_ADD(s, capsule_capsule);
    TU_ADD(s, cylinder_cap_sliver_witness);
    return tu_run_suite(s);
}
