/* SPDX-License-Identifier: MIT */
/* agjk_signed_distance (EPA penetration depth) against independent truth:
 *   - analytic depths: spheres, sphere in a box, boxes on and off axis,
 *     capsules side by side and crossing (flat core difference), touching,
 *     concentric and coplanar flat shapes;
 *   - the exact separating-axis depth of polytope pairs (boxes and random
 *     hulls), thousands of pairs at depths 1e-1 ... 1e-8 of their size;
 *   - a branch-and-bound bracket over the sphere of directions for ellipsoid
 *     pairs (tests/common/ref_depth.h), itself checked against the
 *     separating-axis depth;
 *   - properties: symmetry (normal flipped), rigid invariance, scale covariance.
 *   - the margins' own rounding: spheres and thin capsules, whose cores are
 *     points and tiny segments, checked with no slack against exact values;
 * The certified interval must contain the truth on every pair, its width must
 * meet the tolerance asked when the status says converged, and no field may
 * be NaN. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_main.h"
#include "ref_depth.h"
#include "testutil.h"
#include "quad.h"
#include "../../src/epa.h"
#include "../../src/query_setup.h"

static agjk_pose ident(void) { return tu_pose_identity(); }

static agjk_pose at(double x, double y, double z) {
    agjk_pose p = tu_pose_identity();
    p.translation = tu_vec(x, y, z);
    return p;
}

static int finite_result(const agjk_signed_result *r) {
    const double v[] = {r->signed_distance, r->lower, r->upper, r->normal.x, r->normal.y,
                        r->normal.z, r->witness_a.x, r->witness_a.y, r->witness_a.z,
                        r->witness_b.x, r->witness_b.y, r->witness_b.z};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; ++i)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* The width the documented tolerance asks for at signed distance s (with the
 * floor of 1024 ulps of the size in absolute mode). */
static double asked_width(const agjk_options *o, double lo, double hi, double size) {
    double big = fmax(fabs(lo), fabs(hi));
    if (o->tolerance_mode == AGJK_TOLERANCE_RELATIVE) {
        double small = (lo > 0 || hi < 0) ? fmin(fabs(lo), fabs(hi)) : 0.0;
        return 0.5 * o->tolerance * small;
    }
    double w = sqrt(o->tolerance);
    if (big > 0 && o->tolerance / (2 * big) < w) w = o->tolerance / (2 * big);
    return fmax(w, 2048 * DBL_EPSILON * size);
}

/* Checks r against a truth known to lie in [t_lo, t_hi]; slack absorbs the
 * reference's own rounding. */
static void check_against(const agjk_signed_result *r, double t_lo, double t_hi, double slack,
                          const agjk_options *o, double size, const char *what) {
    TU_ENSURE(finite_result(r), "%s: non-finite field", what);
    TU_ENSURE(r->status != AGJK_STATUS_INVALID_INPUT, "%s: invalid input", what);
    TU_ENSURE(r->lower <= r->upper, "%s: lower %.17g > upper %.17g", what, r->lower, r->upper);
    TU_ENSURE(r->lower <= r->signed_distance && r->signed_distance <= r->upper,
              "%s: estimate %.17g outside [%.17g, %.17g]", what, r->signed_distance, r->lower,
              r->upper);
    TU_ENSURE(r->lower <= t_hi + slack && t_lo - slack <= r->upper,
              "%s: interval [%.17g, %.17g] misses the truth [%.17g, %.17g] (%s)", what, r->lower,
              r->upper, t_lo, t_hi, agjk_status_string(r->status));
    if (r->status != AGJK_STATUS_NOT_CONVERGED) {
        double w = asked_width(o, r->lower, r->upper, size);
        TU_ENSURE(r->upper - r->lower <= w * (1 + 1e-9), "%s: width %.3g above the %.3g asked",
                  what, r->upper - r->lower, w);
        if (r->status == AGJK_STATUS_SEPARATED) TU_CHECK(r->lower > 0);
        if (r->status == AGJK_STATUS_INTERSECTING) TU_CHECK(r->upper < 0);
    }
    double nn = tu_norm(r->normal);
    TU_ENSURE(fabs(nn - 1.0) < 1e-9, "%s: normal of norm %.17g", what, nn);
}

static agjk_signed_result signed_query(const agjk_shape *a, const agjk_pose *pa,
                                       const agjk_shape *b, const agjk_pose *pb,
                                       const agjk_options *o) {
    agjk_signed_result r;
    agjk_status st = agjk_signed_distance(a, pa, b, pb, o, &r);
    TU_CHECK_INT_EQ(st, r.status);
    return r;
}

START_TEST(analytic) {
    agjk_options o = agjk_default_options();
    o.tolerance = 1e-20; /* the floor */
    agjk_shape a, b;
    agjk_pose ia = ident();
    char what[96];
    /* Spheres: depth r1 + r2 - d. */
    for (int i = 0; i < 20; ++i) {
        double d = 1.4 * i / 20.0;
        agjk_shape_sphere(&a, 1.0);
        agjk_shape_sphere(&b, 0.5);
        agjk_pose pb = at(d * 0.6, -d * 0.8, 0);
        agjk_signed_result r = signed_query(&a, &ia, &b, &pb, &o);
        snprintf(what, sizeof what, "spheres d=%g", d);
        check_against(&r, d - 1.5, d - 1.5, 1e-15, &o, 2, what);
        if (d > 0) {
            TU_CHECK(fabs(r.normal.x - 0.6) < 1e-12 && fabs(r.normal.y + 0.8) < 1e-12);
            /* deepest points: on A along n, on B along -n */
            TU_CHECK(fabs(r.witness_a.x - 0.6) < 1e-12 && fabs(r.witness_a.y + 0.8) < 1e-12);
        }
        TU_CHECK_INT_EQ(r.status, AGJK_STATUS_INTERSECTING);
    }
    /* A sphere inside a box: depth r + distance from the centre to the nearest face. */
    agjk_box box = {{0.5, 0.3, 0.2}};
    agjk_shape_box(&a, &box);
    agjk_shape_sphere(&b, 0.1);
    const agjk_vec3 centres[] = {{0.1, 0.05, 0.0}, {0.45, 0.0, 0.0}, {0.0, 0.25, 0.1},
                                 {-0.3, -0.1, -0.15}, {0.55, 0.0, 0.0}};
    for (int i = 0; i < 5; ++i) {
        agjk_vec3 c = centres[i];
        double dface = fmin(0.5 - fabs(c.x), fmin(0.3 - fabs(c.y), 0.2 - fabs(c.z)));
        agjk_pose pb = at(c.x, c.y, c.z);
        agjk_signed_result r = signed_query(&a, &ia, &b, &pb, &o);
        snprintf(what, sizeof what, "sphere in box %d", i);
        check_against(&r, -(0.1 + dface), -(0.1 + dface), 1e-15, &o, 1, what);
    }
    /* Aligned boxes: the smallest overlap along an axis. */
    agjk_box bb = {{0.4, 0.25, 0.3}};
    agjk_shape_box(&b, &bb);
    const agjk_vec3 offsets[] = {{0.85, 0.1, 0.0}, {0.2, 0.5, 0.1}, {0.1, 0.1, 0.45},
                                 {0.0, 0.0, 0.0}, {0.9 - 1e-6, 0.0, 0.0}, {0.9 - 1e-9, 0.2, 0.1}};
    for (int i = 0; i < 6; ++i) {
        agjk_vec3 t = offsets[i];
        double ox = 0.9 - fabs(t.x), oy = 0.55 - fabs(t.y), oz = 0.5 - fabs(t.z);
        double depth = fmin(ox, fmin(oy, oz));
        agjk_pose pb = at(t.x, t.y, t.z);
        agjk_signed_result r = signed_query(&a, &ia, &b, &pb, &o);
        snprintf(what, sizeof what, "aligned boxes %d", i);
        check_against(&r, -depth, -depth, 1e-15, &o, 2, what);
    }
    /* Capsules side by side (parallel axes d apart) and crossing (the core
     * segments intersect: D of the cores is a flat parallelogram, depth of the
     * cores 0, total depth r1 + r2). */
    agjk_capsule c1 = {0.2, 0.5}, c2 = {0.15, 0.4};
    agjk_shape_capsule(&a, &c1);
    agjk_shape_capsule(&b, &c2);
    for (int i = 0; i < 6; ++i) {
        double d = 0.05 * i;
        agjk_pose pb = at(d, 0.0, 0.1);
        agjk_signed_result r = signed_query(&a, &ia, &b, &pb, &o);
        snprintf(what, sizeof what, "parallel capsules d=%g", d);
        if (i > 0) check_against(&r, d - 0.35, d - 0.35, 1e-15, &o, 2, what);
        /* crossing: B's axis along x (rotate z -> x), through A's axis */
        agjk_pose px = at(0.0, d, 0.0);
        double rot[3][3] = {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}};
        memcpy(px.rotation, rot, sizeof rot);
        r = signed_query(&a, &ia, &b, &px, &o);
        snprintf(what, sizeof what, "crossing capsules d=%g", d);
        check_against(&r, d - 0.35, d - 0.35, 1e-15, &o, 2, what);
        if (i == 0) TU_CHECK_INT_EQ(r.status, AGJK_STATUS_INTERSECTING);
    }
    /* Touching boxes, concentric boxes, coplanar squares (flat D, depth 0). */
    agjk_box cube = {{0.5, 0.5, 0.5}}, square = {{0.5, 0.5, 0.0}};
    agjk_shape_box(&a, &cube);
    agjk_shape_box(&b, &cube);
    agjk_pose pt = at(1.0, 0.3, 0.0), pc = at(0, 0, 0);
    agjk_signed_result r = signed_query(&a, &ia, &b, &pt, &o);
    check_against(&r, 0, 0, 1e-15, &o, 2, "touching cubes");
    TU_CHECK_INT_EQ(r.status, AGJK_STATUS_CONTACT_WITHIN_TOLERANCE);
    r = signed_query(&a, &ia, &b, &pc, &o);
    check_against(&r, -1, -1, 1e-15, &o, 2, "concentric cubes");
    agjk_shape_box(&a, &square);
    agjk_shape_box(&b, &square);
    agjk_pose ps = at(0.3, 0.2, 0.0);
    r = signed_query(&a, &ia, &b, &ps, &o);
    check_against(&r, 0, 0, 1e-15, &o, 2, "coplanar squares");
    TU_CHECK_INT_EQ(r.status, AGJK_STATUS_CONTACT_WITHIN_TOLERANCE);
    /* Separated: the same distance as agjk_distance. */
    agjk_shape_box(&a, &cube);
    agjk_shape_sphere(&b, 0.25);
    agjk_pose pf = at(1.5, 0.1, 0.0);
    agjk_options d8 = agjk_default_options();
    r = signed_query(&a, &ia, &b, &pf, &d8);
    agjk_result dr;
    agjk_distance(&a, &ia, &b, &pf, &d8, &dr);
    TU_CHECK_INT_EQ(r.status, AGJK_STATUS_SEPARATED);
    TU_CHECK(fabs(r.signed_distance - dr.distance) <= 1e-12);
    check_against(&r, 0.75, 0.75, 1e-15, &d8, 2, "separated box-sphere");
}
END_TEST

/* World-frame vertices of a posed box or polytope reference shape. */
static int world_vertices(const ref_shape *s, const agjk_pose *p, agjk_vec3 *out) {
    if (s->kind == REF_BOX) {
        for (int i = 0; i < 8; ++i) {
            agjk_vec3 v = tu_vec(i & 1 ? s->p[0] : -s->p[0], i & 2 ? s->p[1] : -s->p[1],
                                 i & 4 ? s->p[2] : -s->p[2]);
            out[i] = tu_pose_apply(p, v);
        }
        return 8;
    }
    for (int i = 0; i < s->vertex_count; ++i) out[i] = tu_pose_apply(p, s->vertices[i]);
    return s->vertex_count;
}

#define N_POLY_PAIRS 2000

/* Exact separating-axis depth of boxes and random hulls at depths 1e-1 ...
 * 1e-8 of their size, absolute (default and the floor) and relative modes. */
START_TEST(polytopes_vs_sat) {
    tu_rng rng;
    tu_rng_seed(&rng, 1101);
    int not_converged = 0, queries = 0, skipped = 0;
    double worst_rel_width = 0;
    for (int i = 0; i < N_POLY_PAIRS; ++i) {
        ref_shape sa, sb;
        agjk_vec3 va_local[14], vb_local[14], va[14], vb[14];
        double scale = tu_paper_scale(&rng);
        if (i % 2 == 0) {
            tu_random_box(&rng, &sa, scale);
            tu_random_box(&rng, &sb, scale);
        } else {
            tu_random_polytope(&rng, &sa, va_local, 6 + (int)tu_uniform_int(&rng, 9), scale);
            tu_random_polytope(&rng, &sb, vb_local, 6 + (int)tu_uniform_int(&rng, 9), scale);
        }
        agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
        double size = tu_bounding_radius(&sa) + tu_bounding_radius(&sb);
        double target = -size * tu_log_uniform(&rng, -8, -1);
        TU_CHECK_INT_EQ(tu_set_distance(&sa, &pa, &sb, &pb, target, NULL), 0);
        int na = world_vertices(&sa, &pa, va), nb = world_vertices(&sb, &pb, vb);
        long double ref = ref_sat_signed_distance(va, na, vb, nb);
        if (!(ref < 0)) {
            /* Sliding along the normal did not make this pair overlap (rare):
             * check against the distance reference instead. */
            ref_result rr;
            TU_CHECK(ref_distance(&sa, &pa, &sb, &pb, &rr) == 0);
            agjk_shape a0, b0;
            ref_make_agjk(&sa, &a0);
            ref_make_agjk(&sb, &b0);
            agjk_options o = agjk_default_options();
            agjk_signed_result r = signed_query(&a0, &pa, &b0, &pb, &o);
            check_against(&r, rr.intersecting ? 0.0 : (double)rr.lower, (double)rr.upper,
                          1e-16 * size, &o, size, "polytope pair not overlapping");
            ++skipped;
            continue;
        }
        agjk_shape a, b;
        TU_CHECK_INT_EQ(ref_make_agjk(&sa, &a), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(ref_make_agjk(&sb, &b), AGJK_STATUS_OK);
        agjk_options opts[3];
        opts[0] = agjk_default_options();
        opts[1] = agjk_default_options();
        opts[1].tolerance = 1e-30;
        opts[2] = agjk_default_options();
        opts[2].tolerance_mode = AGJK_TOLERANCE_RELATIVE;
        opts[2].tolerance = 1e-6;
        opts[i % 2].method = AGJK_METHOD_NESTEROV_NORMALIZED;
        for (int k = 0; k < 3; ++k) {
            char what[64];
            snprintf(what, sizeof what, "polytope pair %d options %d", i, k);
            agjk_signed_result r = signed_query(&a, &pa, &b, &pb, &opts[k]);
            ++queries;
            check_against(&r, (double)ref, (double)ref, 1e-16 * size, &opts[k], size, what);
            /* A relative tolerance below the floating-point floor is
             * honestly not converged: counted only where it can be met. */
            if (asked_width(&opts[k], r.lower, r.upper, size) < 1e-12 * size) continue;
            not_converged += r.status == AGJK_STATUS_NOT_CONVERGED;
            if (r.status == AGJK_STATUS_NOT_CONVERGED && getenv("PEN_VERBOSE"))
                printf("%s: not converged, width %.3g x size, depth %.3g x size, it %d/%d\n", what,
                       (r.upper - r.lower) / size, r.signed_distance / size, r.gjk_iterations,
                       r.epa_iterations);
            if (r.status != AGJK_STATUS_NOT_CONVERGED)
                worst_rel_width = fmax(worst_rel_width, (r.upper - r.lower) / size);
        }
    }
    printf("polytopes vs SAT: %d queries, %d not converged, widest converged interval %.3g x size; "
           "%d pairs not overlapping after the slide (checked against the distance)\n",
           queries, not_converged, worst_rel_width, skipped);
    TU_CHECK(skipped <= N_POLY_PAIRS / 50);
    TU_ENSURE(not_converged <= queries / 100, "%d of %d not converged", not_converged, queries);
}
END_TEST

/* The branch-and-bound reference agrees with the exact separating-axis depth
 * (checks the ellipsoid reference on shapes where the truth is known). */
START_TEST(reference_bb_vs_sat) {
    tu_rng rng;
    tu_rng_seed(&rng, 1102);
    for (int i = 0; i < 40; ++i) {
        ref_shape sa, sb;
        agjk_vec3 va[8], vb[8];
        tu_random_box(&rng, &sa, 1.0);
        tu_random_box(&rng, &sb, 1.0);
        agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
        double size = tu_bounding_radius(&sa) + tu_bounding_radius(&sb);
        TU_CHECK_INT_EQ(tu_set_distance(&sa, &pa, &sb, &pb, -size * tu_log_uniform(&rng, -6, -1), NULL), 0);
        world_vertices(&sa, &pa, va);
        world_vertices(&sb, &pb, vb);
        long double sat = ref_sat_signed_distance(va, 8, vb, 8);
        ref_signed_bracket br;
        ref_signed_distance_bb(&sa, &pa, &sb, &pb, 1e-12L * size, 400000, &br);
        /* Slack: the separating-axis depth is computed from world vertices
         * rounded to double (world_vertices), so it is off by a few double
         * ulps of the size (seen: 6e-17 at size 0.6 with clang, whose code
         * rounds differently from gcc's). */
        TU_ENSURE(br.lower <= sat + 8.0L * DBL_EPSILON * size &&
                      sat - 8.0L * DBL_EPSILON * size <= br.upper,
                  "pair %d: bracket [%.20Lg, %.20Lg] misses SAT %.20Lg", i, br.lower, br.upper, sat);
    }
}
END_TEST

#define N_ELLIPSOID_PAIRS 1000

/* Ellipsoids (the paper's law, also 1:10 flat ones) against the
 * branch-and-bound bracket, depths 1e-1 ... 1e-8 of the size. */
START_TEST(ellipsoids_vs_bb) {
    tu_rng rng;
    tu_rng_seed(&rng, 1103);
    int not_converged = 0, unresolved = 0;
    long total_epa = 0;
    for (int i = 0; i < N_ELLIPSOID_PAIRS; ++i) {
        ref_shape sa, sb;
        double scale = tu_paper_scale(&rng);
        tu_random_ellipsoid(&rng, &sa, scale);
        tu_random_ellipsoid(&rng, &sb, scale);
        if (i % 4 == 3) sb.p[2] *= 0.1;
        if (i % 5 == 4) sa.margin = 0.2 * sa.p[0];
        agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
        double size = tu_bounding_radius(&sa) + tu_bounding_radius(&sb);
        double target = -size * tu_log_uniform(&rng, -8, -1);
        TU_CHECK_INT_EQ(tu_set_distance(&sa, &pa, &sb, &pb, target, NULL), 0);
        ref_signed_bracket br;
        unresolved += ref_signed_distance_bb(&sa, &pa, &sb, &pb, 1e-13L * size, 200000, &br);
        agjk_shape a, b;
        TU_CHECK_INT_EQ(ref_make_agjk(&sa, &a), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(ref_make_agjk(&sb, &b), AGJK_STATUS_OK);
        agjk_options o = agjk_default_options();
        if (i % 3 == 1) {
            o.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
            o.tolerance = i % 2 ? 1e-4 : 1e-8;
        } else if (i % 3 == 2) {
            o.tolerance = 1e-16;
        }
        char what[64];
        snprintf(what, sizeof what, "ellipsoid pair %d", i);
        agjk_signed_result r = signed_query(&a, &pa, &b, &pb, &o);
        check_against(&r, (double)br.lower, (double)br.upper, 1e-16 * size, &o, size, what);
        /* counted only where the tolerance is above the floating-point floor */
        if (asked_width(&o, r.lower, r.upper, size) >= 1e-12 * size)
            not_converged += r.status == AGJK_STATUS_NOT_CONVERGED;
        if (r.status == AGJK_STATUS_NOT_CONVERGED && getenv("PEN_VERBOSE"))
            printf("%s: not converged, width %.3g x size, asked %.3g, depth %.3g x size, it %d/%d\n",
                   what, (r.upper - r.lower) / size, asked_width(&o, r.lower, r.upper, size) / size,
                   r.signed_distance / size, r.gjk_iterations, r.epa_iterations);
        total_epa += r.epa_iterations;
    }
    printf("ellipsoids vs branch and bound: %d pairs, %d not converged, %.1f EPA iterations on "
           "average, %d references wider than 1e-13 x size\n",
           N_ELLIPSOID_PAIRS, not_converged, (double)total_epa / N_ELLIPSOID_PAIRS, unresolved);
    TU_ENSURE(not_converged <= N_ELLIPSOID_PAIRS / 50, "%d not converged", not_converged);
}
END_TEST

static int overlap(double lo1, double hi1, double lo2, double hi2, double slack) {
    return lo1 <= hi2 + slack && lo2 <= hi1 + slack;
}

/* Symmetry (normal flipped), invariance under a common rigid motion, and
 * covariance under scaling: the certified intervals must intersect. */
START_TEST(properties) {
    tu_rng rng;
    tu_rng_seed(&rng, 1104);
    for (int i = 0; i < 300; ++i) {
        ref_shape sa, sb;
        agjk_vec3 va[12], vb[12];
        double scale = tu_paper_scale(&rng);
        switch (i % 3) {
        case 0:
            tu_random_ellipsoid(&rng, &sa, scale);
            tu_random_box(&rng, &sb, scale);
            break;
        case 1:
            tu_random_polytope(&rng, &sa, va, 12, scale);
            tu_random_polytope(&rng, &sb, vb, 10, scale);
            break;
        default:
            tu_random_box(&rng, &sa, scale);
            tu_shape_init(&sb, REF_CAPSULE, tu_paper_radius(&rng, scale), tu_paper_radius(&rng, scale), 0);
            break;
        }
        agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
        double size = tu_bounding_radius(&sa) + tu_bounding_radius(&sb);
        TU_CHECK_INT_EQ(tu_set_distance(&sa, &pa, &sb, &pb, -size * tu_log_uniform(&rng, -6, -1), NULL), 0);
        agjk_shape a, b;
        ref_make_agjk(&sa, &a);
        ref_make_agjk(&sb, &b);
        agjk_options o = agjk_default_options();
        agjk_signed_result r = signed_query(&a, &pa, &b, &pb, &o);
        TU_CHECK(finite_result(&r));
        double slack = 1e-15 * size;
        /* symmetry */
        agjk_signed_result s = signed_query(&b, &pb, &a, &pa, &o);
        TU_ENSURE(overlap(r.lower, r.upper, s.lower, s.upper, slack),
                  "pair %d: [%.17g, %.17g] vs swapped [%.17g, %.17g]", i, r.lower, r.upper, s.lower, s.upper);
        /* (Only when both depths are sharp: a loose interval, allowed by the
         * tolerance, leaves the normal loose too.) */
        if (r.status == AGJK_STATUS_INTERSECTING && s.status == AGJK_STATUS_INTERSECTING &&
            r.upper - r.lower < 1e-6 * size && s.upper - s.lower < 1e-6 * size)
            TU_ENSURE(tu_dot(r.normal, s.normal) < -0.99, "pair %d: normals not opposite", i);
        /* rigid motion */
        agjk_pose m = tu_random_pose(&rng, 3.0);
        agjk_pose ma = tu_pose_compose(&m, &pa), mb = tu_pose_compose(&m, &pb);
        agjk_signed_result t = signed_query(&a, &ma, &b, &mb, &o);
        TU_ENSURE(overlap(r.lower, r.upper, t.lower, t.upper, 4 * slack), "pair %d: rigid motion", i);
        if (r.status == AGJK_STATUS_INTERSECTING && t.status == AGJK_STATUS_INTERSECTING &&
            r.upper - r.lower < 1e-6 * size)
            TU_ENSURE(tu_dot(tu_pose_rotate(&m, r.normal), t.normal) > 0.99, "pair %d: normal", i);
        /* scale: shapes and poses times f, the signed distance times f */
        const double factors[] = {1e-3, 1024.0, 1e3};
        double f = factors[i % 3];
        ref_shape fa = sa, fb = sb;
        agjk_vec3 fva[12], fvb[12];
        for (int k = 0; k < 3; ++k) {
            fa.p[k] *= f;
            fb.p[k] *= f;
        }
        fa.margin *= f;
        fb.margin *= f;
        if (sa.kind == REF_POLYTOPE) {
            for (int k = 0; k < sa.vertex_count; ++k) fva[k] = tu_scale(sa.vertices[k], f);
            for (int k = 0; k < sb.vertex_count; ++k) fvb[k] = tu_scale(sb.vertices[k], f);
            fa.vertices = fva;
            fb.vertices = fvb;
        }
        agjk_shape ga, gb;
        ref_make_agjk(&fa, &ga);
        ref_make_agjk(&fb, &gb);
        agjk_pose qa = tu_pose_scaled(&pa, f), qb = tu_pose_scaled(&pb, f);
        agjk_options of = o;
        of.tolerance = o.tolerance * f * f; /* length units squared */
        agjk_signed_result u = signed_query(&ga, &qa, &gb, &qb, &of);
        TU_ENSURE(overlap(r.lower * f, r.upper * f, u.lower, u.upper, 4 * slack * f),
                  "pair %d: scale %g: [%.17g, %.17g] vs [%.17g, %.17g]", i, f, r.lower * f,
                  r.upper * f, u.lower, u.upper);
        TU_ENSURE(u.status == r.status || u.status == AGJK_STATUS_NOT_CONVERGED ||
                      r.status == AGJK_STATUS_NOT_CONVERGED,
                  "pair %d: status %d vs %d at scale %g", i, r.status, u.status, f);
    }
}
END_TEST

/* Witness points: on the shapes (within the interval's width), and
 * witness_a - witness_b = depth * normal when overlapping. */
START_TEST(witness_points) {
    tu_rng rng;
    tu_rng_seed(&rng, 1105);
    for (int i = 0; i < 200; ++i) {
        ref_shape sa, sb;
        double scale = tu_paper_scale(&rng);
        tu_random_ellipsoid(&rng, &sa, scale);
        tu_random_box(&rng, &sb, scale);
        agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
        double size = tu_bounding_radius(&sa) + tu_bounding_radius(&sb);
        TU_CHECK_INT_EQ(tu_set_distance(&sa, &pa, &sb, &pb, -size * tu_log_uniform(&rng, -4, -1), NULL), 0);
        agjk_shape a, b;
        ref_make_agjk(&sa, &a);
        ref_make_agjk(&sb, &b);
        agjk_options o = agjk_default_options();
        o.tolerance = 1e-16;
        agjk_signed_result r = signed_query(&a, &pa, &b, &pb, &o);
        /* Without witness points asked: the same answer, bit for bit, and
         * zero witnesses (neither GJK nor EPA computes them then). */
        agjk_options bare = o;
        bare.compute = AGJK_COMPUTE_DISTANCE;
        agjk_signed_result rb = signed_query(&a, &pa, &b, &pb, &bare);
        TU_ENSURE(rb.status == r.status && rb.signed_distance == r.signed_distance &&
                      rb.lower == r.lower && rb.upper == r.upper &&
                      rb.normal.x == r.normal.x && rb.normal.y == r.normal.y &&
                      rb.normal.z == r.normal.z && rb.epa_iterations == r.epa_iterations,
                  "pair %d: another answer without witness points", i);
        TU_ENSURE(tu_norm(rb.witness_a) == 0.0 && tu_norm(rb.witness_b) == 0.0,
                  "pair %d: witness points not asked for", i);
        if (r.status != AGJK_STATUS_INTERSECTING) continue;
        double tol = 1e-6 * size;
        agjk_vec3 diff = tu_sub(r.witness_a, r.witness_b);
        agjk_vec3 want = tu_scale(r.normal, -r.signed_distance);
        TU_ENSURE(tu_norm(tu_sub(diff, want)) <= tol, "pair %d: witness gap off by %.3g", i,
                  tu_norm(tu_sub(diff, want)));
        TU_ENSURE(tu_distance_to_shape(&sa, &pa, r.witness_a) <= tol, "pair %d: witness_a off A", i);
        TU_ENSURE(tu_distance_to_shape(&sb, &pb, r.witness_b) <= tol, "pair %d: witness_b off B", i);
    }
}
END_TEST

/* The margins (radii) are added to the cores' answer analytically; their
 * sum and its subtraction round, by half an ulp each, beyond what the
 * cores' allowance (a few ulps of the cores' size) covers when the cores are
 * points or tiny segments: spheres of radii 0.1 and 0.2 with centres 1e-3
 * apart once got the interval [-0.29900000000000004, -0.29900000000000004],
 * beside the exact -0.29900000000000002. Exact values in long double, where
 * these sums and differences of doubles (exponents within 9 of each other)
 * are exact; the interval must hold them with no slack at all. */
static void check_exact(const agjk_shape *a, const agjk_pose *pa, const agjk_shape *b,
                        const agjk_pose *pb, long double exact, const char *what, int i) {
    agjk_options o = agjk_default_options();
    agjk_signed_result r = signed_query(a, pa, b, pb, &o);
    TU_ENSURE((long double)r.lower <= exact && exact <= (long double)r.upper,
              "%s %d: exact %.21Lg outside [%.21g, %.21g] (%s)", what, i, exact, r.lower, r.upper,
              agjk_status_string(r.status));
}

START_TEST(margin_rounding) {
    ck_assert(LDBL_MANT_DIG >= 64); /* (x86's long double: the values below are exact) */
    agjk_shape a, b;
    agjk_pose pa = ident(), pb = at(0.001, 0, 0);
    TU_CHECK_INT_EQ(agjk_shape_sphere(&a, 0.1), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_sphere(&b, 0.2), AGJK_STATUS_OK);
    check_exact(&a, &pa, &b, &pb, (long double)0.001 - (long double)0.1 - (long double)0.2,
                "spheres 0.1 and 0.2", 0);
    /* Capsules with cores 2e-9 long, crossing at right angles at one point:
     * the depth is the radii's sum. */
    agjk_capsule ca = {0.1, 1e-9}, cb = {0.2, 1e-9};
    TU_CHECK_INT_EQ(agjk_shape_capsule(&a, &ca), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_capsule(&b, &cb), AGJK_STATUS_OK);
    agjk_pose turned = {{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}, {0, 0, 0}}; /* B along world x */
    check_exact(&a, &pa, &b, &turned, -((long double)0.1 + (long double)0.2), "crossing capsules",
                0);
    /* Random spheres, centres apart along x (the cores' distance exact):
     * radii in [1/16, 1/2), offsets in [1/512, 1). */
    tu_rng rng;
    tu_rng_seed(&rng, 1201);
    for (int i = 0; i < 20000; ++i) {
        double ra = tu_uniform_range(&rng, 0.0625, 0.5), rb = tu_uniform_range(&rng, 0.0625, 0.5);
        double dx = tu_uniform_range(&rng, 1.0 / 512.0, 1.0);
        TU_CHECK_INT_EQ(agjk_shape_sphere(&a, ra), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(agjk_shape_sphere(&b, rb), AGJK_STATUS_OK);
        pb = at(dx, 0, 0);
        check_exact(&a, &pa, &b, &pb, (long double)dx - ra - rb, "random spheres", i);
    }
}
END_TEST

/* Honest statuses: a full polytope store and the iteration cap end
 * NOT_CONVERGED with an interval that still holds the truth; degenerate
 * starts (GJK ending on a point or a segment: cubes touching corner to corner
 * or edge to edge; D a single point or a segment) give the right depth. */
START_TEST(degenerate_and_capped) {
    agjk_shape a, b;
    agjk_pose ia = ident();
    char what[96];
    /* Deep overlap of two spheres as ellipsoid cores (no margin): round D,
     * the polytope must follow it everywhere; a tolerance at the floor fills
     * the store. Truth: r1 + r2 - d. */
    agjk_ellipsoid e1 = {{0.5, 0.5, 0.5}}, e2 = {{0.4, 0.4, 0.4}};
    agjk_shape_ellipsoid(&a, &e1);
    agjk_shape_ellipsoid(&b, &e2);
    agjk_pose pb = at(0.1, 0.05, -0.02);
    double truth = tu_norm(pb.translation) - 0.9;
    agjk_options o = agjk_default_options();
    o.tolerance = 1e-30;
    agjk_signed_result r = signed_query(&a, &ia, &b, &pb, &o);
    check_against(&r, truth, truth, 1e-15, &o, 1, "store full");
    TU_CHECK_INT_EQ(r.status, AGJK_STATUS_NOT_CONVERGED);
    TU_CHECK(r.epa_iterations <= AGJK_EPA_MAX_VERTICES);
    for (int cap = 1; cap <= 8; cap *= 2) {
        o = agjk_default_options();
        o.max_iterations = cap;
        r = signed_query(&a, &ia, &b, &pb, &o);
        snprintf(what, sizeof what, "cap %d", cap);
        check_against(&r, truth, truth, 1e-15, &o, 1, what);
        TU_CHECK(r.epa_iterations <= cap && r.gjk_iterations <= cap);
        TU_CHECK_INT_EQ(r.status, AGJK_STATUS_NOT_CONVERGED);
    }
    /* Cubes touching corner to corner, edge to edge (turned 45 degrees about
     * z), and overlapping by 1e-9 that way: depth 0 or 1e-9. */
    agjk_box cube = {{0.5, 0.5, 0.5}};
    agjk_shape_box(&a, &cube);
    agjk_shape_box(&b, &cube);
    o = agjk_default_options();
    o.tolerance = 1e-30;
    const double gaps[] = {0.0, -1e-9, -1e-6};
    for (int k = 0; k < 3; ++k) {
        double g = gaps[k];
        agjk_pose corner = at(1 + g, 1 + g, 1 + g);
        r = signed_query(&a, &ia, &b, &corner, &o);
        snprintf(what, sizeof what, "cubes corner to corner %g", g);
        check_against(&r, g, g, 1e-15, &o, 3, what);
        agjk_pose edge = at(1 + g, 1 + g, 0.3);
        r = signed_query(&a, &ia, &b, &edge, &o);
        snprintf(what, sizeof what, "cubes edge to edge %g", g);
        check_against(&r, g, g, 1e-15, &o, 3, what);
        /* B turned 45 degrees about z: its vertical edge against A's face */
        double c = sqrt(0.5);
        agjk_pose turned = at(0.5 + c + g, 0.1, 0.0);
        double rz[3][3] = {{c, -c, 0}, {c, c, 0}, {0, 0, 1}};
        memcpy(turned.rotation, rz, sizeof rz);
        r = signed_query(&a, &ia, &b, &turned, &o);
        snprintf(what, sizeof what, "turned cube edge on face %g", g);
        check_against(&r, g, g, 1e-15, &o, 3, what);
    }
    /* D a single point (two points), a segment (point and segment), a flat
     * square (point and square): depth 0 when the origin is in D. */
    agjk_vec3 seg[2] = {{-1, 0, 0}, {1, 0, 0}};
    agjk_polytope segp = {seg, 2, NULL, NULL};
    agjk_box square = {{0.5, 0.5, 0.0}};
    agjk_shape_point(&a);
    agjk_shape_point(&b);
    r = signed_query(&a, &ia, &b, &ia, &o);
    check_against(&r, 0, 0, 1e-15, &o, 1, "point on point");
    agjk_shape_polytope(&b, &segp);
    agjk_pose ps = at(0.3, 0, 0);
    r = signed_query(&a, &ia, &b, &ps, &o);
    check_against(&r, 0, 0, 1e-15, &o, 1, "point on segment");
    agjk_shape_box(&b, &square);
    agjk_pose pq = at(0.2, -0.1, 0);
    r = signed_query(&a, &ia, &b, &pq, &o);
    check_against(&r, 0, 0, 1e-15, &o, 1, "point in square");
    /* with margins: a sphere touching a flat square from above, and resting
     * 0.1 deep in it */
    agjk_shape_sphere(&a, 0.25);
    agjk_pose up = at(0.2, -0.1, 0.15);
    r = signed_query(&b, &ia, &a, &up, &o);
    check_against(&r, -0.1, -0.1, 1e-15, &o, 1, "sphere into square");
    TU_CHECK(fabs(r.normal.z - 1.0) < 1e-12);
}
END_TEST

/* EPA started on four points (GJK's usual end) that do not span a proper
 * tetrahedron: the common start's tests reject them (a repeated point, a
 * point on the line of two others, four points on a face of D) and the
 * general blow-up takes over; and one proper tetrahedron. D is the box
 * A - B of two axis-aligned boxes, its depth known exactly: 0.2. */
START_TEST(four_point_starts) {
    agjk_box ba = {{0.5, 0.4, 0.3}}, bb = {{0.3, 0.3, 0.3}};
    agjk_shape a, b;
    agjk_shape_box(&a, &ba);
    agjk_shape_box(&b, &bb);
    agjk_pose pa = ident(), pb = at(0.6, 0.1, 0.05);
    const double truth = 0.2;
    for (int kind = 0; kind < 4; ++kind) {
        agjk__minkowski md;
        agjk__solve_input setup;
        TU_CHECK(agjk__query_prepare(&a, &pa, &b, &pb, NULL, 0, &md, &setup));
        /* Vertices of D: the support in direction -(sx, sy, sz) is the
         * corner on that side. */
        agjk__vertex corner[8];
        for (int i = 0; i < 8; ++i)
            agjk__minkowski_support(&md, v3(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0,
                                            i & 4 ? 1.0 : -1.0),
                                    0.0, &corner[i], AGJK__SUPPORT_CALL, NULL, 0.0, 0.0, NULL);
        agjk__vertex sx[4];
        if (kind == 0) { /* the face of D at the largest x: coplanar */
            sx[0] = corner[0];
            sx[1] = corner[2];
            sx[2] = corner[4];
            sx[3] = corner[6];
        } else if (kind == 1) { /* a repeated point */
            sx[0] = corner[0];
            sx[1] = corner[0];
            sx[2] = corner[3];
            sx[3] = corner[5];
        } else if (kind == 2) { /* the midpoint of an edge of D, a point of D too */
            sx[0] = corner[0];
            sx[1] = corner[7];
            sx[2].w = v3_scale(v3_add(corner[0].w, corner[7].w), 0.5);
            sx[2].a = v3_scale(v3_add(corner[0].a, corner[7].a), 0.5);
            sx[2].b = v3_scale(v3_add(corner[0].b, corner[7].b), 0.5);
            sx[3] = corner[3];
        } else { /* alternate corners: a tetrahedron around the origin */
            sx[0] = corner[0];
            sx[1] = corner[3];
            sx[2] = corner[5];
            sx[3] = corner[6];
        }
        agjk__epa_input in;
        in.simplex = sx;
        in.count = 4;
        in.relative = 0;
        in.tolerance = 1e-20;
        in.margin = 0.0;
        in.core_distance_upper = md.noise;
        in.max_iterations = 100;
        in.want_witness = 1;
        agjk__epa_output out;
        agjk__epa(&md, &in, &out);
        TU_ENSURE(out.outcome == AGJK__EPA_CONVERGED && out.converged,
                  "start %d: outcome %d", kind, (int)out.outcome);
        TU_ENSURE(out.lower <= truth && truth <= out.upper && out.upper - out.lower < 1e-12,
                  "start %d: [%.17g, %.17g] misses %.17g", kind, out.lower, out.upper, truth);
        TU_ENSURE(out.has_witness && fabs(out.normal.x - 1.0) < 1e-12,
                  "start %d: normal %g %g %g", kind, out.normal.x, out.normal.y, out.normal.z);
        TU_ENSURE(kind == 3 || out.support_calls >= 2,
                  "start %d: no blow-up (%d support calls)", kind, out.support_calls);
    }
}
END_TEST

/* EPA's nearest-face search (src/epa.h) visits only the faces below a bound
 * and must still find the least key of all: driven through random face
 * births, replacements, frees and bounds (above, among and below the keys:
 * the last forces the full rescan a truthful support callback almost never
 * reaches), against a brute-force minimum. */
START_TEST(nearest_face_search) {
    enum { SLOTS = AGJK__EPA_MAX_FACES };
    static agjk__epa_scan sc;
    double key[SLOTS];
    tu_rng rng;
    tu_rng_seed(&rng, 11);
    int nslots = 0, rescans = 0, queries = 0;
    double bound = INFINITY;
    agjk__epa_scan_init(&sc);
    for (int step = 0; step < 40000; ++step) {
        uint32_t op = tu_uniform_int(&rng, 10);
        if (op < 3 && nslots < SLOTS) { /* a fresh slot */
            key[nslots] = tu_uniform(&rng);
            agjk__epa_scan_fresh(&sc, nslots);
            agjk__epa_scan_offer(&sc, nslots, key[nslots], bound);
            ++nslots;
        } else if (op < 6 && nslots > 0) { /* a slot reused, or freed */
            int i = (int)tu_uniform_int(&rng, (uint32_t)nslots);
            key[i] = tu_uniform_int(&rng, 4) == 0 ? INFINITY : tu_uniform(&rng);
            if (key[i] < INFINITY) agjk__epa_scan_offer(&sc, i, key[i], bound);
        } else if (op < 8) { /* the bound moves: mostly down, sometimes below every key */
            uint32_t how = tu_uniform_int(&rng, 4);
            bound = how == 0 ? INFINITY : how == 1 ? -1.0 : tu_uniform(&rng);
        } else {
            double least = INFINITY, low;
            for (int i = 0; i < nslots; ++i)
                if (key[i] < least) least = key[i];
            int listed = sc.count;
            int best = agjk__epa_scan_nearest(&sc, key, nslots, bound, &low);
            ++queries;
            rescans += sc.count > listed; /* only a rescan lists more than it had */
            if (least < INFINITY) {
                TU_CHECK(best >= 0 && best < nslots);
                TU_CHECK(low == least && key[best] == least);
            } else {
                TU_CHECK(best == -1 && low == INFINITY);
            }
            /* A listed slot is listed once. */
            int seen[SLOTS] = {0};
            for (int i = 0; i < sc.count; ++i) TU_CHECK(seen[sc.slot[i]]++ == 0);
        }
    }
    printf("nearest-face search: %d queries against brute force, %d full rescans\n", queries,
           rescans);
    TU_CHECK(rescans > 100 && rescans < queries);
}
END_TEST

/* Exact truths below in quadruple precision (tests/common/quad.h). */
#ifdef HAVE_QUAD
/* Distance from (rho, z), rho >= 0, to the segment [p, q] of the plane. */
static quad seg2_distance(quad rho, quad z, quad p0, quad p1, quad q0, quad q1) {
    quad e0 = q0 - p0, e1 = q1 - p1, t = ((rho - p0) * e0 + (z - p1) * e1) / (e0 * e0 + e1 * e1);
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    quad d0 = rho - (p0 + t * e0), d1 = z - (p1 + t * e1);
    return qsqrt(d0 * d0 + d1 * d1);
}

/* A verdict only when the final interval, every rounding allowance added,
 * has the width penetration.h promises; NOT_CONVERGED otherwise. Taking
 * agjk_distance's "converged" as its own (no margins) gave SEPARATED with
 * intervals 2e8 times
 * the relative width asked (a point 6.9e-16 from a disc, a point 3.3e-8 from
 * a segment: agjk_distance itself says NOT_CONVERGED there), and in absolute
 * mode 86 000 ulps of the problem's size wide at the floating-point floor (a
 * point 0.034 from a cone of radius 12 836); judging the width before the
 * margins' rounding is added gave INTERSECTING for spheres (case 4). Each
 * interval must also hold the exact distance, computed in quadruple
 * precision. */
START_TEST(verdict_only_when_width_met) {
    static const agjk_method methods[] = {
        AGJK_METHOD_GJK,    AGJK_METHOD_NESTEROV,    AGJK_METHOD_NESTEROV_NORMALIZED,
        AGJK_METHOD_POLYAK, AGJK_METHOD_FRANK_WOLFE, AGJK_METHOD_ADAPTIVE};
    agjk_shape pt;
    TU_CHECK_INT_EQ(agjk_shape_point(&pt), AGJK_STATUS_OK);
    agjk_pose I = ident();
    /* 1: a point 6.9e-16 below a disc (a cone of zero height) of radius
     * 1.9e-3: its offset from the axis (6.6e-16) is inside the disc, so the
     * distance is |z|, exactly. */
    agjk_cone disc = {0x1.e75a42f598acp-10, 0};
    agjk_shape sdisc;
    TU_CHECK_INT_EQ(agjk_shape_cone(&sdisc, &disc), AGJK_STATUS_OK);
    agjk_pose p1 = {{{0x1.73fa017918d0cp-2, -0x1.cf91e0c96e3aap-1, -0x1.c1fbf562ede3cp-3},
                     {-0x1.a326fce38438cp-4, 0x1.90a5c7be34894p-3, -0x1.f35db5f763845p-1},
                     {0x1.da236e03fbe2dp-1, 0x1.81d25ce0c15fep-2, -0x1.61b5afa98704p-6}},
                    {-0x1.76b2057722971p-53, -0x1.7321d81008e03p-51, -0x1.8f05b0ee7e1a8p-51}};
    double d1 = fabs(p1.translation.z);
    ck_assert(hypot(p1.translation.x, p1.translation.y) < disc.radius);
    /* 2: a point 3.3e-8 from a segment (a box 0 x 0 x h). */
    agjk_box segbox = {{0, 0, 0x1.19f49e409dcp+0}};
    agjk_shape sseg;
    TU_CHECK_INT_EQ(agjk_shape_box(&sseg, &segbox), AGJK_STATUS_OK);
    agjk_pose p2 = {{{-0x1.4d249fb2f6818p-2, 0x1.e0e324d106c5ep-1, 0x1.c0aad13169cf8p-4},
                     {0x1.27cc4cad6e1ep-1, 0x1.2813569e457bp-2, -0x1.86cf520502a8p-1},
                     {-0x1.7f46f91c9bbaep-1, -0x1.7af8dd3fb1dc8p-3, -0x1.45fc329e97d2cp-1}},
                    {0x1.b3e7f2680b8a5p-1, 0x1.4edea326ce552p-1, 0x1.f77daed14da5p-3}};
    agjk_pose q2 = {{{-0x1.436a2dd54171p-3, 0x1.3a96b52890161p-1, 0x1.8bc74c78bcae4p-1},
                     {-0x1.4907e93dee78fp-3, -0x1.93a7143198d14p-1, 0x1.300b083a713ffp-1},
                     {0x1.f2d6c8a9d6fe6p-1, -0x1.f24d57c02478p-6, 0x1.c92450be759ep-3}},
                    {0, 0, 0}};
    quad l2[3], d2sq = 0;
    for (int i = 0; i < 3; i++) {
        const double t[3] = {p2.translation.x, p2.translation.y, p2.translation.z};
        l2[i] = 0;
        for (int j = 0; j < 3; j++) l2[i] += (quad)q2.rotation[j][i] * t[j];
    }
    quad over = (l2[2] < 0 ? -l2[2] : l2[2]) - (quad)segbox.half_extents.z;
    d2sq = l2[0] * l2[0] + l2[1] * l2[1] + (over > 0 ? over * over : 0);
    double d2 = (double)qsqrt(d2sq);
    /* 3: a point 0.034 from a cone of radius 12 836, half height 3959: in
     * the cone's axial plane, the distance to the triangle apex (0, h), rim
     * (r, -h), axis foot (0, -h). */
    agjk_cone big = {0x1.91215959ba0a2p+13, 0x1.ef09cbf81f49fp+11};
    agjk_shape scone;
    TU_CHECK_INT_EQ(agjk_shape_cone(&scone, &big), AGJK_STATUS_OK);
    agjk_pose pa = {{{-0x1.f36a4cf96bf2p-5, -0x1.dcad517a90cf1p-1, -0x1.7080ef175656dp-2},
                     {0x1.acd4fe65c9b2cp-3, 0x1.5cc2956ee5f5p-2, -0x1.d54cada54e0acp-1},
                     {0x1.f3ad1241c7366p-1, -0x1.0cc374d781596p-3, 0x1.64b92d0d87848p-3}},
                    {0, 0, 0}};
    agjk_pose pb = I;
    pb.translation = tu_vec(-0x1.87464941dacb1p+8, 0x1.4ff99c07326a8p+10, 0x1.877a9940ae5b4p+12);
    quad l3[3];
    for (int i = 0; i < 3; i++) {
        const double t[3] = {pb.translation.x, pb.translation.y, pb.translation.z};
        l3[i] = 0;
        for (int j = 0; j < 3; j++) l3[i] += (quad)pa.rotation[j][i] * t[j];
    }
    quad rho = qsqrt(l3[0] * l3[0] + l3[1] * l3[1]), r = big.radius, h = big.half_height;
    ck_assert(!(l3[2] <= h && l3[2] >= -h && rho <= r * (h - l3[2]) / (2 * h))); /* outside */
    quad e1 = seg2_distance(rho, l3[2], 0, h, r, -h), e2 = seg2_distance(rho, l3[2], 0, -h, r, -h);
    double d3 = (double)(e1 < e2 ? e1 : e2);
    /* The problem's size, bounded above: the cone's points lie within
     * sqrt(r^2 + h^2) of its origin, the point at the offset. */
    double size3 = hypot(big.radius, big.half_height) + tu_norm(pb.translation);

    /* 4: margins. Spheres of radii 0.1 and 0.2, centres 1e-3 apart: the
     * cores' interval is a few ulps of 1e-3 wide, but the margins' rounding,
     * added afterwards, makes the final one about 5.5e-16 wide, more than a
     * relative 1e-15 asks (1.5e-16): the width was judged before it was
     * added, and the answer was INTERSECTING. */
    agjk_shape s01, s02;
    TU_CHECK_INT_EQ(agjk_shape_sphere(&s01, 0.1), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ(agjk_shape_sphere(&s02, 0.2), AGJK_STATUS_OK);
    agjk_pose c4 = I;
    c4.translation.x = 1e-3;
    double d4 = (double)((quad)1e-3 - (quad)0.1 - (quad)0.2);

    for (int m = 0; m < 6; m++) {
        agjk_options o = agjk_default_options();
        o.method = methods[m];
        char what[96];
        o.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
        o.tolerance = 1e-15;
        agjk_signed_result rs = signed_query(&s01, &I, &s02, &c4, &o);
        snprintf(what, sizeof what, "spheres, relative 1e-15, %s", agjk_method_name(o.method));
        check_against(&rs, d4, d4, 1e-30, &o, 1.0, what);
        o.tolerance_mode = AGJK_TOLERANCE_RELATIVE;
        o.tolerance = 1e-10;
        agjk_signed_result res = signed_query(&pt, &p1, &sdisc, &I, &o);
        snprintf(what, sizeof what, "point and disc, relative 1e-10, %s", agjk_method_name(o.method));
        check_against(&res, d1, d1, 0.0, &o, 1.0, what);
        o.tolerance = 0x1.203af9ee75616p-50;
        res = signed_query(&pt, &p2, &sseg, &q2, &o);
        snprintf(what, sizeof what, "point and segment, relative 1e-15, %s",
                 agjk_method_name(o.method));
        check_against(&res, d2, d2, 1e-22, &o, 1.0, what);
        o.tolerance_mode = AGJK_TOLERANCE_ABSOLUTE;
        for (int k = 0; k < 2; k++) {
            o.tolerance = k ? 1e-8 : 1e-300;
            res = signed_query(&scone, &pa, &pt, &pb, &o);
            snprintf(what, sizeof what, "point and cone, absolute %g, %s", o.tolerance,
                     agjk_method_name(o.method));
            check_against(&res, d3, d3, 1e-20, &o, size3, what);
        }
    }
}
END_TEST
#endif

int main(void) {
    Suite *s = suite_create("penetration");
    TU_ADD(s, nearest_face_search);
    TU_ADD(s, analytic);
    TU_ADD(s, polytopes_vs_sat);
    TU_ADD(s, reference_bb_vs_sat);
    TU_ADD(s, ellipsoids_vs_bb);
    TU_ADD(s, properties);
    TU_ADD(s, witness_points);
    TU_ADD(s, four_point_starts);
    TU_ADD(s, degenerate_and_capped);
    TU_ADD(s, margin_rounding);
#ifdef HAVE_QUAD
    TU_ADD(s, verdict_only_when_width_met);
#endif
    return tu_run_suite(s);
}
