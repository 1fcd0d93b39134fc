/* SPDX-License-Identifier: MIT */
/* The API contract of include/agjk: version, strings, option defaults, and
 * the documented answer to every kind of bad input (AGJK_STATUS_INVALID_INPUT
 * with a fully written, NaN-free result, never a crash). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "check_main.h"
#include "testutil.h"

static const agjk_method all_methods[6] = {AGJK_METHOD_GJK, AGJK_METHOD_NESTEROV,
                                           AGJK_METHOD_NESTEROV_NORMALIZED, AGJK_METHOD_POLYAK,
                                           AGJK_METHOD_FRANK_WOLFE, AGJK_METHOD_ADAPTIVE};

START_TEST(version) {
    ck_assert_int_eq(agjk_version(), AGJK_VERSION_NUMBER);
    ck_assert_int_eq(AGJK_VERSION_NUMBER,
                     AGJK_VERSION_MAJOR * 10000 + AGJK_VERSION_MINOR * 100 + AGJK_VERSION_PATCH);
    ck_assert_str_eq(agjk_version_string(), AGJK_VERSION_STRING);
    char buf[32];
    snprintf(buf, sizeof buf, "%d.%d.%d", AGJK_VERSION_MAJOR, AGJK_VERSION_MINOR, AGJK_VERSION_PATCH);
    ck_assert_str_eq(buf, AGJK_VERSION_STRING);
}
END_TEST

START_TEST(strings) {
    ck_assert_str_eq(agjk_method_name(AGJK_METHOD_GJK), "gjk");
    ck_assert_str_eq(agjk_method_name(AGJK_METHOD_NESTEROV), "nesterov");
    ck_assert_str_eq(agjk_method_name(AGJK_METHOD_NESTEROV_NORMALIZED), "nesterov-normalized");
    ck_assert_str_eq(agjk_method_name(AGJK_METHOD_POLYAK), "polyak");
    ck_assert_str_eq(agjk_method_name(AGJK_METHOD_FRANK_WOLFE), "fw");
    ck_assert_str_eq(agjk_method_name(AGJK_METHOD_ADAPTIVE), "adaptive");
    ck_assert_str_eq(agjk_method_name((agjk_method)6), "unknown");
    ck_assert_str_eq(agjk_method_name((agjk_method)-1), "unknown");
    ck_assert_str_eq(agjk_status_string(AGJK_STATUS_SEPARATED), "separated");
    const agjk_status known[6] = {AGJK_STATUS_SEPARATED, AGJK_STATUS_INTERSECTING,
                                  AGJK_STATUS_CONTACT_WITHIN_TOLERANCE, AGJK_STATUS_NOT_CONVERGED,
                                  AGJK_STATUS_INVALID_INPUT, AGJK_STATUS_OK};
    for (int i = 0; i < 6; i++) {
        const char *s = agjk_status_string(known[i]);
        ck_assert_ptr_nonnull(s);
        ck_assert_str_ne(s, "unknown status");
        for (int j = 0; j < i; j++) ck_assert_str_ne(s, agjk_status_string(known[j]));
    }
    ck_assert_str_eq(agjk_status_string((agjk_status)42), "unknown status");
    ck_assert_str_eq(agjk_status_string((agjk_status)-1), "unknown status");
}
END_TEST

START_TEST(option_defaults) {
    agjk_options o;
    memset(&o, 0xab, sizeof o);
    agjk_options_init(&o);
    ck_assert_uint_eq(o.struct_size, sizeof o);
    ck_assert_int_eq(o.method, AGJK_METHOD_ADAPTIVE);
    ck_assert_int_eq(o.tolerance_mode, AGJK_TOLERANCE_ABSOLUTE);
    ck_assert(o.tolerance == 1e-8);
    ck_assert_int_eq(o.max_iterations, 1000);
    ck_assert_uint_eq(o.compute, AGJK_COMPUTE_WITNESS);
    ck_assert_int_eq(o.use_initial_direction, 0);
    ck_assert_int_eq(o.hint_a, 0);
    ck_assert_int_eq(o.hint_b, 0);
    agjk_options d = agjk_default_options();
    ck_assert(memcmp(&d, &o, sizeof o) == 0 || (d.method == o.method && d.tolerance == o.tolerance &&
                                                d.max_iterations == o.max_iterations));
    /* too small a struct_size or NULL: nothing written, no crash */
    agjk_options small;
    memset(&small, 0x11, sizeof small);
    agjk_options copy = small;
    agjk_options_init_sized(&small, 4);
    ck_assert(memcmp(&small, &copy, sizeof small) == 0);
    agjk_options_init_sized(NULL, sizeof small);
}
END_TEST

/* Every double of a result finite, reserved zero. */
static void expect_clean(const agjk_result *r, const char *what) {
    const double v[] = {r->distance, r->bound, r->gap, r->witness_a.x, r->witness_a.y,
                        r->witness_a.z, r->witness_b.x, r->witness_b.y, r->witness_b.z,
                        r->normal.x, r->normal.y, r->normal.z};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        TU_ENSURE(isfinite(v[i]), "%s: result field %u not finite", what, (unsigned)i);
    for (int i = 0; i < 8; i++) TU_ENSURE(r->reserved[i] == 0.0, "%s: reserved[%d] written", what, i);
    TU_ENSURE(r->distance >= 0.0 && r->bound >= 0.0, "%s: negative distance/bound", what);
}

typedef struct api_case {
    agjk_shape a, b;
    agjk_pose pa, pb;
    agjk_options opt;
    const agjk_shape *pa_shape, *pb_shape;
    const agjk_pose *ppa, *ppb;
    const agjk_options *popt;
} api_case;

static agjk_ellipsoid ell = {{0.3, 0.2, 0.1}};
static agjk_box box = {{0.2, 0.1, 0.3}};

static void good_case(api_case *c) {
    memset(c, 0, sizeof *c);
    ck_assert_int_eq(agjk_shape_ellipsoid(&c->a, &ell), AGJK_STATUS_OK);
    ck_assert_int_eq(agjk_shape_box(&c->b, &box), AGJK_STATUS_OK);
    c->pa = tu_pose_identity();
    c->pb = tu_pose_identity();
    c->pb.translation = tu_vec(1.0, 0.25, -0.5);
    agjk_options_init(&c->opt);
    c->pa_shape = &c->a;
    c->pb_shape = &c->b;
    c->ppa = &c->pa;
    c->ppb = &c->pb;
    c->popt = &c->opt;
}

/* Runs both queries on the case and expects INVALID_INPUT with a clean result. */
static void expect_invalid(const api_case *c, const char *what) {
    for (int q = 0; q < 2; q++) {
        agjk_result r;
        memset(&r, 0xff, sizeof r); /* all NaN: every field must be overwritten */
        agjk_status st = q == 0 ? agjk_distance(c->pa_shape, c->ppa, c->pb_shape, c->ppb, c->popt, &r)
                                : agjk_collide(c->pa_shape, c->ppa, c->pb_shape, c->ppb, c->popt, &r);
        TU_ENSURE(st == AGJK_STATUS_INVALID_INPUT, "%s (%s): status %d", what,
                  q ? "collide" : "distance", (int)st);
        TU_ENSURE(r.status == AGJK_STATUS_INVALID_INPUT, "%s: result.status %d", what, (int)r.status);
        expect_clean(&r, what);
    }
}

static void expect_valid(const api_case *c, const char *what) {
    agjk_result r;
    memset(&r, 0xff, sizeof r);
    agjk_status st = agjk_distance(c->pa_shape, c->ppa, c->pb_shape, c->ppb, c->popt, &r);
    TU_ENSURE(st == AGJK_STATUS_SEPARATED, "%s: status %d", what, (int)st);
    expect_clean(&r, what);
}

static void nan_support(const void *data, const agjk_vec3 *d, agjk_vec3 *out, int *hint) {
    (void)data; (void)d; (void)hint;
    out->x = NAN; out->y = 0; out->z = 0;
}

static void inf_support(const void *data, const agjk_vec3 *d, agjk_vec3 *out, int *hint) {
    (void)data; (void)hint;
    out->x = d->x > 0 ? INFINITY : -INFINITY; out->y = 0; out->z = 0;
}

START_TEST(bad_input) {
    api_case c;
    good_case(&c);
    expect_valid(&c, "baseline");
    good_case(&c); c.pa_shape = NULL; expect_invalid(&c, "NULL shape a");
    good_case(&c); c.pb_shape = NULL; expect_invalid(&c, "NULL shape b");
    good_case(&c); c.ppa = NULL; expect_invalid(&c, "NULL pose a");
    good_case(&c); c.ppb = NULL; expect_invalid(&c, "NULL pose b");
    good_case(&c); c.popt = NULL; expect_valid(&c, "NULL options mean defaults");
    good_case(&c);
    ck_assert_int_eq(agjk_distance(&c.a, &c.pa, &c.b, &c.pb, NULL, NULL), AGJK_STATUS_INVALID_INPUT);
    ck_assert_int_eq(agjk_collide(&c.a, &c.pa, &c.b, &c.pb, NULL, NULL), AGJK_STATUS_INVALID_INPUT);
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    for (int b = 0; b < 3; b++) {
        good_case(&c); c.pa.translation.y = bad[b]; expect_invalid(&c, "non-finite translation a");
        good_case(&c); c.pb.translation.z = bad[b]; expect_invalid(&c, "non-finite translation b");
        good_case(&c); c.pa.rotation[1][2] = bad[b]; expect_invalid(&c, "non-finite rotation a");
        good_case(&c); c.pb.rotation[0][0] = bad[b]; expect_invalid(&c, "non-finite rotation b");
        good_case(&c); c.a.margin = bad[b]; expect_invalid(&c, "non-finite margin");
        good_case(&c); c.opt.tolerance = bad[b]; expect_invalid(&c, "non-finite tolerance");
        good_case(&c); c.opt.use_initial_direction = 1; c.opt.initial_direction.x = bad[b];
        expect_invalid(&c, "non-finite initial direction");
    }
    /* rotations that are not proper rotations */
    good_case(&c); c.pa.rotation[0][0] = 1.01; expect_invalid(&c, "scaled rotation");
    good_case(&c); c.pb.rotation[0][1] = 0.1; expect_invalid(&c, "sheared rotation");
    good_case(&c); c.pa.rotation[2][2] = -1.0; expect_invalid(&c, "reflection (det -1)");
    good_case(&c); memset(c.pb.rotation, 0, sizeof c.pb.rotation); expect_invalid(&c, "zero matrix");
    good_case(&c); c.pa.rotation[1][1] = 1.0 + 1e-5; expect_invalid(&c, "entry off by 1e-5");
    good_case(&c); c.pa.rotation[1][1] = 1.0 + 1e-9; expect_valid(&c, "entry off by 1e-9 is accepted");
    /* Each pose passes the check of its summed squared deviations alone,
     * the pair does not: the entry-by-entry test decides (valid). Likewise
     * two translations in range whose 1-norms sum beyond it. */
    good_case(&c); c.pa.rotation[0][1] = 7e-7; c.pb.rotation[0][1] = 7e-7;
    expect_valid(&c, "both rotations off by 7e-7 are accepted");
    good_case(&c); c.pa.rotation[0][1] = 7e-7; c.pb.rotation[0][1] = -2e-6;
    expect_invalid(&c, "one rotation off by 2e-6 beside one off by 7e-7");
    good_case(&c); c.pa.translation = tu_vec(0.6 * AGJK_MAX_COORDINATE, 0.0, 0.0);
    c.pb.translation = tu_vec(-0.6 * AGJK_MAX_COORDINATE, 0.0, 0.0);
    expect_valid(&c, "translations summing beyond the range are each accepted");
    /* shapes */
    good_case(&c); c.b.margin = -0.1; expect_invalid(&c, "negative margin");
    good_case(&c); c.a.support = NULL; expect_invalid(&c, "NULL support function");
    good_case(&c); c.b.support = nan_support; expect_invalid(&c, "support returns NaN");
    good_case(&c); c.a.support = inf_support; expect_invalid(&c, "support returns Inf");
    agjk_box nanbox = box;
    nanbox.half_extents.x = NAN; /* changed after construction: support gives NaN */
    good_case(&c); c.b.data = &nanbox; expect_invalid(&c, "box edited to NaN");
    /* options */
    good_case(&c); c.opt.max_iterations = 0; expect_invalid(&c, "max_iterations 0");
    good_case(&c); c.opt.max_iterations = -5; expect_invalid(&c, "max_iterations < 0");
    good_case(&c); c.opt.tolerance = 0.0; expect_invalid(&c, "tolerance 0");
    good_case(&c); c.opt.tolerance = -1e-8; expect_invalid(&c, "tolerance < 0");
    good_case(&c); c.opt.method = (agjk_method)6; expect_invalid(&c, "unknown method 6");
    good_case(&c); c.opt.method = (agjk_method)-1; expect_invalid(&c, "unknown method -1");
    good_case(&c); c.opt.tolerance_mode = (agjk_tolerance_mode)2; expect_invalid(&c, "unknown tolerance mode");
    good_case(&c); c.opt.use_initial_direction = 1; c.opt.initial_direction = tu_vec(0, 0, 0);
    {
        /* a zero warm start is not documented as invalid: must not crash or NaN */
        agjk_result r;
        memset(&r, 0xff, sizeof r);
        agjk_distance(&c.a, &c.pa, &c.b, &c.pb, &c.opt, &r);
        expect_clean(&r, "zero initial direction");
    }
}
END_TEST

START_TEST(zero_vertices) {
    agjk_vec3 v[1] = {{0, 0, 0}};
    agjk_polytope p;
    memset(&p, 0, sizeof p);
    p.vertices = v;
    p.vertex_count = 0;
    agjk_shape s;
    ck_assert_int_eq(agjk_shape_polytope(&s, &p), AGJK_STATUS_INVALID_INPUT);
}
END_TEST

START_TEST(good_results_are_clean) {
    /* Two spheres (radii 1 and 0.5) 3 apart along x: distance 1.5 exactly
     * representable; every method, both queries. */
    agjk_shape a, b;
    ck_assert_int_eq(agjk_shape_sphere(&a, 1.0), AGJK_STATUS_OK);
    ck_assert_int_eq(agjk_shape_sphere(&b, 0.5), AGJK_STATUS_OK);
    agjk_pose pa = tu_pose_identity(), pb = tu_pose_identity();
    pb.translation = tu_vec(3.0, 0.0, 0.0);
    for (int m = 0; m < 6; m++) {
        agjk_options o = agjk_default_options();
        o.method = all_methods[m];
        agjk_result r;
        memset(&r, 0xff, sizeof r);
        ck_assert_int_eq(agjk_distance(&a, &pa, &b, &pb, &o, &r), AGJK_STATUS_SEPARATED);
        expect_clean(&r, agjk_method_name(o.method));
        ck_assert(fabs(r.distance - 1.5) <= 1e-12);
        ck_assert(fabs(r.normal.x - 1.0) <= 1e-12);
        ck_assert(fabs(r.witness_a.x - 1.0) <= 1e-12 && fabs(r.witness_b.x - 2.5) <= 1e-12);
        ck_assert(r.iterations >= 1 && r.support_calls >= 1);
        if (o.method == AGJK_METHOD_GJK || o.method == AGJK_METHOD_FRANK_WOLFE)
            ck_assert_int_eq(r.momentum_stop_iteration, -1);
        /* without witness points requested: zero witnesses, same distance */
        o.compute = AGJK_COMPUTE_DISTANCE;
        agjk_result r2;
        memset(&r2, 0xff, sizeof r2);
        ck_assert_int_eq(agjk_distance(&a, &pa, &b, &pb, &o, &r2), AGJK_STATUS_SEPARATED);
        expect_clean(&r2, "no witness");
        ck_assert(r2.distance == r.distance);
        ck_assert(tu_norm(r2.witness_a) == 0.0 && tu_norm(r2.witness_b) == 0.0);
        /* Boolean query: no distance, no witness, unit separating normal */
        memset(&r2, 0xff, sizeof r2);
        ck_assert_int_eq(agjk_collide(&a, &pa, &b, &pb, &o, &r2), AGJK_STATUS_SEPARATED);
        expect_clean(&r2, "collide");
        ck_assert(r2.distance == 0.0 && r2.bound == 0.0);
        ck_assert(tu_norm(r2.witness_a) == 0.0 && tu_norm(r2.witness_b) == 0.0);
        ck_assert(fabs(tu_norm(r2.normal) - 1.0) <= 1e-12);
        ck_assert(r2.normal.x > 0.0); /* from A towards B */
        /* overlapping: intersecting, distance 0, zero normal */
        pb.translation.x = 1.0;
        memset(&r2, 0xff, sizeof r2);
        ck_assert_int_eq(agjk_distance(&a, &pa, &b, &pb, &o, &r2), AGJK_STATUS_INTERSECTING);
        expect_clean(&r2, "intersecting");
        ck_assert(r2.distance == 0.0);
        ck_assert(tu_norm(r2.normal) == 0.0);
        memset(&r2, 0xff, sizeof r2);
        ck_assert_int_eq(agjk_collide(&a, &pa, &b, &pb, &o, &r2), AGJK_STATUS_INTERSECTING);
        expect_clean(&r2, "collide intersecting");
        pb.translation.x = 3.0;
    }
}
END_TEST

int main(void) {
    Suite *s = suite_create("api");
    TU_ADD(s, version);
    TU_ADD(s, strings);
    TU_ADD(s, option_defaults);
    TU_ADD(s, bad_input);
    TU_ADD(s, zero_vertices);
    TU_ADD(s, good_results_are_clean);
    return tu_run_suite(s);
}
