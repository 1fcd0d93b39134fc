/* SPDX-License-Identifier: MIT */
/* The bad-input matrix (issue 5, item 3).
 *
 * Every public function of the include/agjk headers called with NULL, NaN, Inf,
 * negative sizes, zero and huge vertex counts, zero iterations, tolerance <= 0
 * and friends. For each call: the documented status, no crash, no NaN in the
 * result, nothing written outside the output struct (guard bytes on both
 * sides), and the inputs left untouched (compared byte for byte). */
#include <check.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "agjk/polytope.h"
#include "stab_util.h"

/* NaN and Inf built at run time: no reliance on <math.h> macros being
 * constant expressions under -std=c99 -Wpedantic. */
static double g_zero = 0.0;
#define NAN_ (g_zero / g_zero)
#define INF_ (1.0 / g_zero)

static long g_count; /* calls checked */
/* Expected outcomes: VALID accepts any non-error status (constructors:
 * exactly AGJK_STATUS_OK), ANY only checks sanity. */
#define VALID 0
#define INVALID 4
#define ANY (-1)
/* Finite values beyond the documented coordinate range (types.h). */
#ifdef AGJK_MAX_COORDINATE
#define BEYOND INVALID
#define MAXC AGJK_MAX_COORDINATE
#else
#define BEYOND ANY
#define MAXC 1e300
#endif

typedef struct guarded_shape {
    unsigned char pre[STAB_GUARD];
    agjk_shape s;
    unsigned char post[STAB_GUARD];
} guarded_shape;

typedef struct guarded_result {
    unsigned char pre[STAB_GUARD];
    agjk_result r;
    unsigned char post[STAB_GUARD];
} guarded_result;

static void gs_init(guarded_shape *g) {
    stab_guard_fill(g->pre);
    stab_guard_fill(g->post);
    memset(&g->s, 0x5A, sizeof g->s);
}

static void gs_check(const guarded_shape *g, const char *what) {
    ck_assert_msg(stab_guard_ok(g->pre) && stab_guard_ok(g->post),
                  "%s wrote outside the agjk_shape", what);
}

/* ---- shape constructors ---- */

#define EXPECT_SHAPE(call, expected)                                                   \
    do {                                                                               \
        guarded_shape g_;                                                              \
        gs_init(&g_);                                                                  \
        agjk_shape *shape_ = &g_.s;                                                    \
        agjk_status st_ = (call);                                                      \
        (void)shape_;                                                                  \
        gs_check(&g_, #call);                                                          \
        if ((expected) == INVALID) {                                                   \
            guarded_shape u_;                                                          \
            gs_init(&u_);                                                              \
            ck_assert_msg(st_ == AGJK_STATUS_INVALID_INPUT, "%s: got %s, expected invalid", \
                          #call, agjk_status_string(st_));                             \
            /* documented: the shape is left unchanged */                              \
            ck_assert_msg(memcmp(&u_.s, &g_.s, sizeof u_.s) == 0, "%s: shape changed", #call); \
        } else {                                                                       \
            ck_assert_msg(st_ == AGJK_STATUS_OK, "%s: valid input gave %s", #call,      \
                          agjk_status_string(st_));                                    \
        }                                                                              \
        g_count++;                                                                     \
    } while (0)


START_TEST(test_scalar_shapes) {
    double nan = NAN_, inf = INF_;
    EXPECT_SHAPE(agjk_shape_point(NULL), INVALID);
    EXPECT_SHAPE(agjk_shape_point(shape_), VALID);
    EXPECT_SHAPE(agjk_shape_sphere(NULL, 1.0), INVALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, 0.0), VALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, MAXC), VALID);
#ifdef AGJK_MAX_COORDINATE
    EXPECT_SHAPE(agjk_shape_sphere(shape_, 2 * MAXC), INVALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, DBL_MAX), INVALID);
#endif
    EXPECT_SHAPE(agjk_shape_sphere(shape_, -1.0), INVALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, -DBL_MIN), INVALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, nan), INVALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, inf), INVALID);
    EXPECT_SHAPE(agjk_shape_sphere(shape_, -inf), INVALID);
    {
        agjk_capsule c[] = {{-1, 1}, {1, -1}, {nan, 1}, {1, nan}, {inf, 1}, {1, inf}};
        agjk_cylinder y[] = {{-1, 1}, {1, -1}, {nan, 1}, {1, nan}, {inf, 1}, {1, inf}};
        agjk_cone k[] = {{-1, 1}, {1, -1}, {nan, 1}, {1, nan}, {inf, 1}, {1, inf}};
        agjk_capsule cz = {0, 0};
        agjk_cylinder yz = {0, 0};
        agjk_cone kz = {0, 0};
        for (int i = 0; i < 6; i++) {
            EXPECT_SHAPE(agjk_shape_capsule(shape_, &c[i]), INVALID);
            EXPECT_SHAPE(agjk_shape_cylinder(shape_, &y[i]), INVALID);
            EXPECT_SHAPE(agjk_shape_cone(shape_, &k[i]), INVALID);
        }
        EXPECT_SHAPE(agjk_shape_capsule(shape_, NULL), INVALID);
        EXPECT_SHAPE(agjk_shape_cylinder(shape_, NULL), INVALID);
        EXPECT_SHAPE(agjk_shape_cone(shape_, NULL), INVALID);
        EXPECT_SHAPE(agjk_shape_capsule(NULL, &cz), INVALID);
        EXPECT_SHAPE(agjk_shape_cylinder(NULL, &yz), INVALID);
        EXPECT_SHAPE(agjk_shape_cone(NULL, &kz), INVALID);
        /* Zero sizes are documented as allowed (>= 0). */
        EXPECT_SHAPE(agjk_shape_capsule(shape_, &cz), VALID);
        EXPECT_SHAPE(agjk_shape_cylinder(shape_, &yz), VALID);
        EXPECT_SHAPE(agjk_shape_cone(shape_, &kz), VALID);
    }
    {
        agjk_ellipsoid e[] = {{{0, 1, 1}}, {{1, -1, 1}}, {{1, 1, nan}}, {{inf, 1, 1}},
                              {{1, -inf, 1}}, {{-0.0, 1, 1}}};
        agjk_box b[] = {{{-1, 1, 1}}, {{1, nan, 1}}, {{1, 1, inf}}, {{-DBL_MIN, 0, 0}}};
        agjk_box bz = {{0, 0, 0}}, bflat = {{1, 1, 0}};
        agjk_ellipsoid etiny = {{DBL_MIN, 1, MAXC}};
        for (size_t i = 0; i < sizeof e / sizeof e[0]; i++)
            EXPECT_SHAPE(agjk_shape_ellipsoid(shape_, &e[i]), INVALID); /* radii must be > 0 */
        for (size_t i = 0; i < sizeof b / sizeof b[0]; i++)
            EXPECT_SHAPE(agjk_shape_box(shape_, &b[i]), INVALID);
        EXPECT_SHAPE(agjk_shape_ellipsoid(shape_, NULL), INVALID);
        EXPECT_SHAPE(agjk_shape_box(shape_, NULL), INVALID);
        EXPECT_SHAPE(agjk_shape_ellipsoid(NULL, &etiny), INVALID);
        EXPECT_SHAPE(agjk_shape_box(NULL, &bz), INVALID);
        EXPECT_SHAPE(agjk_shape_ellipsoid(shape_, &etiny), VALID);
        EXPECT_SHAPE(agjk_shape_box(shape_, &bz), VALID);
        EXPECT_SHAPE(agjk_shape_box(shape_, &bflat), VALID);
    }
}
END_TEST

START_TEST(test_polytope_and_margin) {
    double nan = NAN_, inf = INF_;
    agjk_vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    agjk_vec3 vnan[2] = {{0, 0, 0}, {0, nan, 0}};
    agjk_vec3 vinf[2] = {{inf, 0, 0}, {0, 0, 0}};
    /* Tetrahedron adjacency: every vertex neighbours the three others. */
    int32_t off[5] = {0, 3, 6, 9, 12};
    int32_t nb[12] = {1, 2, 3, 0, 2, 3, 0, 1, 3, 0, 1, 2};
    int32_t off_bad0[5] = {1, 3, 6, 9, 12};
    int32_t off_dec[5] = {0, 3, 2, 9, 12};
    int32_t nb_out[12] = {1, 2, 3, 0, 2, 3, 0, 1, 4, 0, 1, 2};
    int32_t nb_neg[12] = {1, 2, 3, 0, 2, 3, 0, 1, -1, 0, 1, 2};
    agjk_polytope ok = {v, 4, NULL, NULL}, okadj = {v, 4, off, nb};
    agjk_polytope bad[] = {
        {NULL, 4, NULL, NULL},
        {v, 0, NULL, NULL},
        {v, -1, NULL, NULL},
        {v, INT32_MIN, NULL, NULL},
        {v, AGJK_POLYTOPE_MAX_VERTICES + 1, NULL, NULL}, /* must be refused before reading */
        {v, INT32_MAX, NULL, NULL},
        {vnan, 2, NULL, NULL},
        {vinf, 2, NULL, NULL},
        {v, 4, off, NULL},
        {v, 4, NULL, nb},
        {v, 4, off_bad0, nb},
        {v, 4, off_dec, nb},
        {v, 4, off, nb_out},
        {v, 4, off, nb_neg},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        EXPECT_SHAPE(agjk_shape_polytope(shape_, &bad[i]), INVALID);
    }
    EXPECT_SHAPE(agjk_shape_polytope(shape_, NULL), INVALID);
    EXPECT_SHAPE(agjk_shape_polytope(NULL, &ok), INVALID);
    EXPECT_SHAPE(agjk_shape_polytope(shape_, &ok), VALID);
    EXPECT_SHAPE(agjk_shape_polytope(shape_, &okadj), VALID);
    {
        agjk_polytope one = {v, 1, NULL, NULL};
        EXPECT_SHAPE(agjk_shape_polytope(shape_, &one), VALID);
    }
    /* Margins. */
    {
#ifdef AGJK_MAX_COORDINATE
        const double bad_m[] = {-1.0, -DBL_MIN, nan, inf, -inf, 2 * MAXC};
#else
        const double bad_m[] = {-1.0, -DBL_MIN, nan, inf, -inf};
#endif
        for (size_t i = 0; i < sizeof bad_m / sizeof bad_m[0]; i++) {
            guarded_shape g;
            agjk_status st;
            gs_init(&g);
            ck_assert(agjk_shape_sphere(&g.s, 1.0) != AGJK_STATUS_INVALID_INPUT);
            {
                agjk_shape before = g.s;
                st = agjk_shape_set_margin(&g.s, bad_m[i]);
                gs_check(&g, "agjk_shape_set_margin");
                ck_assert_msg(memcmp(&before, &g.s, sizeof before) == 0,
                              "rejected margin %g changed the shape", bad_m[i]);
            }
            ck_assert_msg(st == AGJK_STATUS_INVALID_INPUT, "margin %g accepted", bad_m[i]);
            g_count++;
        }
        EXPECT_SHAPE(agjk_shape_set_margin(NULL, 1.0), INVALID);
        EXPECT_SHAPE((agjk_shape_point(shape_), agjk_shape_set_margin(shape_, 0.0)), VALID);
        EXPECT_SHAPE((agjk_shape_point(shape_), agjk_shape_set_margin(shape_, MAXC)), VALID);

    }
}
END_TEST

/* ---- queries ---- */

typedef agjk_status (*query_fn)(const agjk_shape *, const agjk_pose *, const agjk_shape *,
                                const agjk_pose *, const agjk_options *, agjk_result *);

static const query_fn queries[2] = {agjk_distance, agjk_collide};
static const char *const query_names[2] = {"agjk_distance", "agjk_collide"};

/* The same checks for agjk_signed_distance (penetration.h): guards, inputs
 * untouched, every field finite, lower <= signed_distance <= upper, a fully
 * zeroed result on invalid input. */
typedef struct guarded_signed {
    unsigned char pre[STAB_GUARD];
    agjk_signed_result r;
    unsigned char post[STAB_GUARD];
} guarded_signed;

static void check_signed(const char *what, const agjk_shape *a, const agjk_pose *pa,
                         const agjk_shape *b, const agjk_pose *pb, const agjk_options *o,
                         int expected) {
    guarded_signed g;
    agjk_shape a0, b0;
    agjk_pose pa0, pb0;
    agjk_options o0;
    char name[192];
    if (a) a0 = *a;
    if (b) b0 = *b;
    if (pa) pa0 = *pa;
    if (pb) pb0 = *pb;
    if (o) o0 = *o;
    stab_guard_fill(g.pre);
    stab_guard_fill(g.post);
    memset(&g.r, 0xFF, sizeof g.r);
    agjk_status st = agjk_signed_distance(a, pa, b, pb, o, &g.r);
    const agjk_signed_result *r = &g.r;
    snprintf(name, sizeof name, "agjk_signed_distance: %s", what);
    ck_assert_msg(stab_guard_ok(g.pre) && stab_guard_ok(g.post), "%s: wrote outside result", name);
    ck_assert_msg(st == r->status, "%s: returned %d, result says %d", name, st, r->status);
    ck_assert_msg(st >= AGJK_STATUS_SEPARATED && st <= AGJK_STATUS_INVALID_INPUT,
                  "%s: status %d", name, st);
    const double v[] = {r->signed_distance, r->lower, r->upper, r->normal.x, r->normal.y,
                        r->normal.z, r->witness_a.x, r->witness_a.y, r->witness_a.z,
                        r->witness_b.x, r->witness_b.y, r->witness_b.z};
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        ck_assert_msg(isfinite(v[i]), "%s: field %u not finite", name, (unsigned)i);
    for (int i = 0; i < 8; i++) ck_assert_msg(r->reserved[i] == 0.0, "%s: reserved written", name);
    ck_assert_msg(r->gjk_iterations >= 0 && r->epa_iterations >= 0 && r->support_calls >= 0,
                  "%s: negative counter", name);
    if (st == AGJK_STATUS_INVALID_INPUT) {
        agjk_signed_result zero;
        memset(&zero, 0, sizeof zero);
        zero.status = AGJK_STATUS_INVALID_INPUT;
        ck_assert_msg(memcmp(&zero, r, sizeof zero) == 0, "%s: invalid input, result not zeroed", name);
    } else {
        ck_assert_msg(r->lower <= r->signed_distance && r->signed_distance <= r->upper,
                      "%s: %.17g outside [%.17g, %.17g]", name, r->signed_distance, r->lower, r->upper);
        double nn = sqrt(r->normal.x * r->normal.x + r->normal.y * r->normal.y +
                         r->normal.z * r->normal.z);
        ck_assert_msg(nn == 0.0 || fabs(nn - 1.0) < 1e-9, "%s: normal of norm %.17g", name, nn);
        if (o && o->max_iterations > 0)
            ck_assert_msg(r->epa_iterations <= o->max_iterations, "%s: EPA above the cap", name);
    }
    ck_assert_msg(!a || memcmp(&a0, a, sizeof a0) == 0, "%s: modified shape a", name);
    ck_assert_msg(!b || memcmp(&b0, b, sizeof b0) == 0, "%s: modified shape b", name);
    ck_assert_msg(!pa || memcmp(&pa0, pa, sizeof pa0) == 0, "%s: modified pose a", name);
    ck_assert_msg(!pb || memcmp(&pb0, pb, sizeof pb0) == 0, "%s: modified pose b", name);
    ck_assert_msg(!o || memcmp(&o0, o, sizeof o0) == 0, "%s: modified options", name);
    if (expected == INVALID)
        ck_assert_msg(st == AGJK_STATUS_INVALID_INPUT, "%s: got %s, expected invalid input", name,
                      agjk_status_string(st));
    else if (expected == VALID)
        ck_assert_msg(st != AGJK_STATUS_INVALID_INPUT, "%s: valid input rejected", name);
    ck_assert_int_eq(agjk_signed_distance(a, pa, b, pb, o, NULL), AGJK_STATUS_INVALID_INPUT);
    g_count += 2;
}

/* Calls both queries, checks guards, input immutability, sanity, and (if
 * expected >= 0) the status. Returns the distance query's status. */
static agjk_status run_queries(const char *what, const agjk_shape *a, const agjk_pose *pa,
                               const agjk_shape *b, const agjk_pose *pb, const agjk_options *o,
                               int expected) {
    agjk_status first = AGJK_STATUS_INVALID_INPUT;
    for (int q = 0; q < 2; q++) {
        guarded_result g;
        agjk_shape a0, b0;
        agjk_pose pa0, pb0;
        agjk_options o0;
        agjk_status st;
        char name[192];
        if (a) a0 = *a;
        if (b) b0 = *b;
        if (pa) pa0 = *pa;
        if (pb) pb0 = *pb;
        if (o) o0 = *o;
        stab_guard_fill(g.pre);
        stab_guard_fill(g.post);
        memset(&g.r, 0xFF, sizeof g.r);
        st = queries[q](a, pa, b, pb, o, &g.r);
        snprintf(name, sizeof name, "%s: %s", query_names[q], what);
        ck_assert_msg(stab_guard_ok(g.pre) && stab_guard_ok(g.post), "%s: wrote outside result",
                      name);
        ck_assert_msg(stab_result_sane(name, st, &g.r, o ? o->max_iterations : 0) == 0,
                      "%s: result not sane (see output)", name);
        ck_assert_msg(!a || memcmp(&a0, a, sizeof a0) == 0, "%s: modified shape a", name);
        ck_assert_msg(!b || memcmp(&b0, b, sizeof b0) == 0, "%s: modified shape b", name);
        ck_assert_msg(!pa || memcmp(&pa0, pa, sizeof pa0) == 0, "%s: modified pose a", name);
        ck_assert_msg(!pb || memcmp(&pb0, pb, sizeof pb0) == 0, "%s: modified pose b", name);
        ck_assert_msg(!o || memcmp(&o0, o, sizeof o0) == 0, "%s: modified options", name);
        if (expected == INVALID)
            ck_assert_msg(st == AGJK_STATUS_INVALID_INPUT, "%s: got %s, expected invalid input",
                          name, agjk_status_string(st));
        else if (expected == VALID)
            ck_assert_msg(st != AGJK_STATUS_INVALID_INPUT, "%s: valid input rejected", name);
        /* NULL result: documented to return INVALID_INPUT and write nothing. */
        ck_assert_int_eq(queries[q](a, pa, b, pb, o, NULL), AGJK_STATUS_INVALID_INPUT);
        g_count += 2;
        if (q == 0) first = st;
    }
    check_signed(what, a, pa, b, pb, o, expected);
    return first;
}

static agjk_shape g_sa, g_sb;
static agjk_ellipsoid g_ell = {{0.5, 0.3, 0.2}};
static agjk_box g_box = {{0.4, 0.4, 0.1}};
static agjk_pose g_pa, g_pb;

static void setup_pair(void) {
    ck_assert(agjk_shape_ellipsoid(&g_sa, &g_ell) != AGJK_STATUS_INVALID_INPUT);
    ck_assert(agjk_shape_box(&g_sb, &g_box) != AGJK_STATUS_INVALID_INPUT);
    stab_pose_identity(&g_pa);
    stab_pose_identity(&g_pb);
    g_pb.translation.x = 1.5;
}

START_TEST(test_query_null_and_options) {
    double nan = NAN_, inf = INF_;
    agjk_options o = agjk_default_options();
    setup_pair();
    run_queries("valid", &g_sa, &g_pa, &g_sb, &g_pb, &o, VALID);
    run_queries("NULL options (defaults)", &g_sa, &g_pa, &g_sb, &g_pb, NULL, VALID);
    run_queries("NULL a", NULL, &g_pa, &g_sb, &g_pb, &o, INVALID);
    run_queries("NULL pose a", &g_sa, NULL, &g_sb, &g_pb, &o, INVALID);
    run_queries("NULL b", &g_sa, &g_pa, NULL, &g_pb, &o, INVALID);
    run_queries("NULL pose b", &g_sa, &g_pa, &g_sb, NULL, &o, INVALID);
    run_queries("all NULL", NULL, NULL, NULL, NULL, NULL, INVALID);
    {
        const double bad_tol[] = {0.0, -0.0, -1.0, -DBL_MIN, nan, inf, -inf};
        for (size_t i = 0; i < sizeof bad_tol / sizeof bad_tol[0]; i++)
            for (int mode = 0; mode < 2; mode++) {
                char what[64];
                o = agjk_default_options();
                o.tolerance = bad_tol[i];
                o.tolerance_mode = (agjk_tolerance_mode)mode;
                snprintf(what, sizeof what, "tolerance %g mode %d", bad_tol[i], mode);
                run_queries(what, &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
            }
        /* Extreme but valid tolerances: must terminate with an honest answer. */
        const double odd_tol[] = {DBL_MIN, 4.9e-324, 1e-300, DBL_MAX, 1e300};
        for (size_t i = 0; i < sizeof odd_tol / sizeof odd_tol[0]; i++)
            for (int mode = 0; mode < 2; mode++) {
                char what[64];
                o = agjk_default_options();
                o.tolerance = odd_tol[i];
                o.tolerance_mode = (agjk_tolerance_mode)mode;
                snprintf(what, sizeof what, "tolerance %g mode %d", odd_tol[i], mode);
                run_queries(what, &g_sa, &g_pa, &g_sb, &g_pb, &o, VALID);
            }
    }
    {
        const int32_t bad_it[] = {0, -1, INT32_MIN};
        for (size_t i = 0; i < 3; i++) {
            char what[64];
            o = agjk_default_options();
            o.max_iterations = bad_it[i];
            snprintf(what, sizeof what, "max_iterations %d", (int)bad_it[i]);
            run_queries(what, &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
        }
        o = agjk_default_options();
        o.max_iterations = 1;
        run_queries("max_iterations 1", &g_sa, &g_pa, &g_sb, &g_pb, &o, VALID);
    }
    {
        const int bad_method[] = {-1, 6, 1000, INT_MIN};
        for (size_t i = 0; i < 4; i++) {
            char what[64];
            o = agjk_default_options();
            o.method = (agjk_method)bad_method[i];
            snprintf(what, sizeof what, "method %d", bad_method[i]);
            run_queries(what, &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
        }
        o = agjk_default_options();
        o.tolerance_mode = (agjk_tolerance_mode)2;
        run_queries("tolerance_mode 2", &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
        o = agjk_default_options();
        o.tolerance_mode = (agjk_tolerance_mode)-1;
        run_queries("tolerance_mode -1", &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
        o = agjk_default_options();
        o.compute = 0xFFFFFFFFu;
        /* Unknown compute bits: distance rejects them; collide ignores compute. */
        run_queries("compute ~0", &g_sa, &g_pa, &g_sb, &g_pb, &o, ANY);
    }
    {
        const uint32_t bad_size[] = {0, 4, (uint32_t)sizeof(agjk_options) - 1};
        for (size_t i = 0; i < 3; i++) {
            char what[64];
            o = agjk_default_options();
            o.struct_size = bad_size[i];
            snprintf(what, sizeof what, "struct_size %u", (unsigned)bad_size[i]);
            run_queries(what, &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
        }
    }
    {
        const agjk_vec3 bad_dir[] = {{nan, 0, 0}, {0, inf, 0}, {0, 0, -inf}};
        const agjk_vec3 odd_dir[] = {{0, 0, 0}, {1e-300, 0, 0}, {1e300, -1e300, 1e300},
                                     {4.9e-324, 0, 0}};
        for (int i = 0; i < 3; i++) {
            o = agjk_default_options();
            o.use_initial_direction = 1;
            o.initial_direction = bad_dir[i];
            run_queries("non-finite initial direction", &g_sa, &g_pa, &g_sb, &g_pb, &o, INVALID);
        }
        for (int i = 0; i < 4; i++) {
            o = agjk_default_options();
            o.use_initial_direction = 1;
            o.initial_direction = odd_dir[i];
            run_queries("zero/tiny/huge initial direction", &g_sa, &g_pa, &g_sb, &g_pb, &o, VALID);
        }
        /* Hints out of range are only hints: must be accepted and clamped. */
        o = agjk_default_options();
        o.hint_a = -5;
        o.hint_b = INT32_MAX;
        run_queries("odd hints", &g_sa, &g_pa, &g_sb, &g_pb, &o, VALID);
    }
}
END_TEST

START_TEST(test_query_poses) {
    double nan = NAN_, inf = INF_;
    agjk_options o = agjk_default_options();
    setup_pair();
    for (int which = 0; which < 2; which++) {
        agjk_pose p = g_pb;
        agjk_pose *pa = which ? &g_pa : &p, *pb = which ? &p : &g_pb;
        p.translation.x = nan;
        run_queries("NaN translation", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        p.translation.z = -inf;
        run_queries("Inf translation", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        p.rotation[1][2] = nan;
        run_queries("NaN rotation", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        p.rotation[0][0] = inf;
        run_queries("Inf rotation", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        for (int i = 0; i < 3; i++) p.rotation[i][i] = 2.0;
        run_queries("scaled rotation", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        p.rotation[2][2] = -1.0; /* a reflection: orthonormal, det -1 */
        run_queries("reflection", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        memset(p.rotation, 0, sizeof p.rotation);
        run_queries("zero rotation", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        p.rotation[0][1] = 1e-3; /* beyond the documented 1e-6 */
        run_queries("skewed rotation 1e-3", &g_sa, pa, &g_sb, pb, &o, INVALID);
        p = g_pb;
        p.rotation[0][1] = 1e-9; /* within 1e-6: accepted */
        run_queries("skewed rotation 1e-9", &g_sa, pa, &g_sb, pb, &o, VALID);
        /* Finite but huge translations: any honest status, no NaN. */
        p = g_pb;
        p.translation.x = 1e300;
        run_queries("translation 1e300", &g_sa, pa, &g_sb, pb, &o, BEYOND);
        p = g_pb;
        p.translation.x = DBL_MAX;
        p.translation.y = -DBL_MAX;
        run_queries("translation DBL_MAX", &g_sa, pa, &g_sb, pb, &o, BEYOND);
        p = g_pb;
        p.translation.x = MAXC; /* at the limit: valid, finite answer */
        run_queries("translation at the coordinate limit", &g_sa, pa, &g_sb, pb, &o, VALID);
        p = g_pb;
        p.translation.y = -MAXC;
        p.translation.z = MAXC;
        run_queries("translation at the limit on two axes", &g_sa, pa, &g_sb, pb, &o, VALID);
        p = g_pb;
        p.translation.x = 1e-320;
        run_queries("denormal translation", &g_sa, pa, &g_sb, pb, &o, VALID);
    }
}
END_TEST

/* ---- user shapes with hostile support callbacks ---- */

typedef struct hostile {
    int mode;          /* what to return */
    int after;         /* good answers before the bad one */
} hostile;

static void hostile_support(const void *data, const agjk_vec3 *d, agjk_vec3 *out, int *hint) {
    const hostile *h = (const hostile *)data;
    double nan = NAN_, inf = INF_;
    double n = sqrt(d->x * d->x + d->y * d->y + d->z * d->z);
    int k = *hint;
    *hint = k + 1; /* the call counter lives in the hint: the callback stays pure */
    out->x = d->x / n;
    out->y = d->y / n;
    out->z = d->z / n;
    if (k < h->after) return;
    switch (h->mode) {
    case 0: out->y = nan; break;
    case 1: out->z = inf; break;
    case 2: out->x = 1e300; out->y = -1e300; break;           /* huge, finite */
    case 3: out->x = DBL_MAX; break;
    case 4: out->x = 4.9e-324; out->y = 0; out->z = 0; break; /* denormal */
    case 5: out->x = -out->x; out->y = -out->y; out->z = -out->z; break; /* not a support */
    case 6: out->x = (k % 2) ? 1 : -1; out->y = 0; out->z = 0; break;    /* inconsistent */
    }
}

START_TEST(test_hostile_support) {
    agjk_options o = agjk_default_options();
    setup_pair();
    for (int mode = 0; mode < 7; mode++)
        for (int after = 0; after < 6; after += 5) {
            hostile h = {mode, after};
            agjk_shape hs = {hostile_support, &h, 0.0};
            char what[64];
            /* A non-finite point makes the query invalid, but only if the
             * query asks for it: with `after` good answers first it may be done. */
            int expected = mode <= 1 && after == 0 ? INVALID : ANY;
            if ((mode == 2 || mode == 3) && after == 0) expected = BEYOND;
            snprintf(what, sizeof what, "hostile support mode %d after %d", mode, after);
            for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
                o.method = (agjk_method)m;
                o.max_iterations = 64;
                run_queries(what, &hs, &g_pa, &g_sb, &g_pb, &o, expected);
                run_queries(what, &g_sa, &g_pa, &hs, &g_pb, &o, expected);
                for (int q = 0; q < 2 && mode <= 1; q++) {
                    /* The hint counts the hostile shape's calls: once the bad
                     * point was handed out, the answer must be INVALID_INPUT. */
                    agjk_result r;
                    agjk_status st = queries[q](&hs, &g_pa, &g_sb, &g_pb, &o, &r);
                    if (r.hint_a > after)
                        ck_assert_msg(st == AGJK_STATUS_INVALID_INPUT,
                                      "%s %s: bad point used (%d calls), got %s", query_names[q],
                                      what, r.hint_a, agjk_status_string(st));
                }
            }
        }
    {
        /* Hand-made shape structs that bypass the constructors. */
        agjk_shape s = g_sa;
        s.support = NULL;
        run_queries("NULL support", &s, &g_pa, &g_sb, &g_pb, &o, INVALID);
        s = g_sa;
        s.margin = NAN_;
        run_queries("NaN margin", &s, &g_pa, &g_sb, &g_pb, &o, INVALID);
        s.margin = -1;
        run_queries("negative margin", &s, &g_pa, &g_sb, &g_pb, &o, INVALID);
        s.margin = INF_;
        run_queries("Inf margin", &s, &g_pa, &g_sb, &g_pb, &o, INVALID);
        s.margin = MAXC;
        run_queries("huge margin", &s, &g_pa, &g_sb, &g_pb, &o, VALID);
        s.margin = 1e300;
        run_queries("margin 1e300", &s, &g_pa, &g_sb, &g_pb, &o, BEYOND);
        s.margin = DBL_MAX;
        run_queries("DBL_MAX margins", &s, &g_pa, &s, &g_pb, &o, ANY);
    }
}
END_TEST

/* Shapes mixing tiny (denormal) and large coordinates: valid input, so a
 * verdict or NOT_CONVERGED with every field finite. A solver that rescales by
 * the magnitude of its first support point overflows when that point is tiny
 * and a later one large (found by fuzzing: distance inf, bound NaN). */
/* agjk_signed_distance on overlapping shapes, where EPA runs: hostile
 * supports arriving during GJK, the blow-up or EPA itself, and extreme
 * options (one iteration, tolerances at both ends, relative mode). */
START_TEST(test_signed_overlapping) {
    agjk_options o = agjk_default_options();
    setup_pair();
    agjk_pose pb = g_pb;
    pb.translation.x = 0.2;
    for (int mode = 0; mode < 7; mode++)
        for (int after = 0; after < 40; after += 3) {
            hostile h = {mode, after};
            agjk_shape hs = {hostile_support, &h, 0.0};
            char what[96];
            snprintf(what, sizeof what, "overlapping, hostile support mode %d after %d", mode, after);
            for (int m = 0; m < 5; m++) {
                o.method = (agjk_method)m;
                o.max_iterations = 64;
                check_signed(what, &hs, &g_pa, &g_sb, &pb, &o, ANY);
                check_signed(what, &g_sa, &g_pa, &hs, &pb, &o, ANY);
                if (mode <= 1) {
                    agjk_signed_result r;
                    agjk_status st = agjk_signed_distance(&hs, &g_pa, &g_sb, &pb, &o, &r);
                    /* a NaN or Inf point handed out must end in INVALID_INPUT
                     * (the result is zeroed then, hints included) */
                    ck_assert_msg(st == AGJK_STATUS_INVALID_INPUT || r.hint_a <= after,
                                  "%s: bad point used (%d calls), got %s", what, r.hint_a,
                                  agjk_status_string(st));
                }
            }
        }
    o = agjk_default_options();
    const int caps[] = {1, 2, 3, 1000};
    const double tols[] = {DBL_MIN, 1e-300, 1e-8, 1.0, 1e300};
    for (int c = 0; c < 4; c++)
        for (int t = 0; t < 5; t++)
            for (int mode = 0; mode < 2; mode++) {
                char what[96];
                o.max_iterations = caps[c];
                o.tolerance = tols[t];
                o.tolerance_mode = (agjk_tolerance_mode)mode;
                snprintf(what, sizeof what, "overlapping, cap %d, tolerance %g, mode %d", caps[c],
                         tols[t], mode);
                check_signed(what, &g_sa, &g_pa, &g_sb, &pb, &o, VALID);
                check_signed(what, &g_sa, &g_pa, &g_sa, &g_pa, &o, VALID); /* identical */
            }
}
END_TEST

START_TEST(test_mixed_magnitudes) {
    const double tiny[] = {4.9e-324, 4.3e-322, 1e-310, 1e-300, 1e-200, 0.0};
    const double big[] = {1.0, 6e10, 1e30, MAXC};
    agjk_options o = agjk_default_options();
    {
        /* The fuzzer's case (tests/fuzz/regressions/query/denormal-first-support-inf). */
        agjk_vec3 v[6] = {{-3.09814453125, -3.09814453125, 0}, {0, 0, 4.3477776834029696e-322},
                          {-3.09814453125, -3.09814453125, -3.09814453125},
                          {-3.09814453125, -10, 0}, {0, 6.0947938070976174e-320, -62353515625},
                          {-62353515625, -62353515625, -62353515625}};
        agjk_polytope p = {v, 6, NULL, NULL};
        agjk_shape pt, poly;
        agjk_pose pose;
        stab_pose_quat(&pose, 0.5, 0.5, 0.5, 0.5); /* rows (0 0 1) (1 0 0) (0 1 0) */
        pose.translation.x = pose.translation.y = pose.translation.z = -62353515625;
        ck_assert_int_eq(agjk_shape_point(&pt), AGJK_STATUS_OK);
        ck_assert_int_eq(agjk_shape_polytope(&poly, &p), AGJK_STATUS_OK);
        for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
            o.method = (agjk_method)m;
            run_queries("fuzzer's point vs denormal/huge polytope", &pt, &pose, &poly, &pose, &o,
                        VALID);
        }
    }
    for (size_t i = 0; i < sizeof tiny / sizeof tiny[0]; i++)
        for (size_t j = 0; j < sizeof big / sizeof big[0]; j++)
            for (int order = 0; order < 2; order++) {
                agjk_vec3 v[4] = {{0, 0, tiny[i]}, {-big[j], -big[j], -big[j]},
                                  {tiny[i], -big[j], 0}, {-big[j], tiny[i], 0}};
                agjk_polytope p = {v, 4, NULL, NULL};
                agjk_shape pt, poly, sph;
                agjk_pose pa, pb;
                char what[96];
                if (order) { agjk_vec3 t = v[0]; v[0] = v[1]; v[1] = t; }
                ck_assert_int_eq(agjk_shape_point(&pt), AGJK_STATUS_OK);
                ck_assert_int_eq(agjk_shape_polytope(&poly, &p), AGJK_STATUS_OK);
                ck_assert_int_eq(agjk_shape_sphere(&sph, tiny[i]), AGJK_STATUS_OK);
                stab_pose_identity(&pa);
                stab_pose_identity(&pb);
                snprintf(what, sizeof what, "tiny %g big %g order %d", tiny[i], big[j], order);
                for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
                    o.method = (agjk_method)m;
                    run_queries(what, &pt, &pa, &poly, &pb, &o, VALID);
                    run_queries(what, &sph, &pa, &poly, &pb, &o, VALID);
                    pb.translation.x = big[j] / 2;
                    run_queries(what, &poly, &pa, &poly, &pb, &o, VALID);
                    pb.translation.x = 0;
                }
            }
}
END_TEST

/* Concentric shapes with denormal or tiny sizes and translations: both
 * contain the common centre, so no query may answer SEPARATED. Found by
 * fuzzing (collide said separated for a flat cone and an ellipsoid with a
 * 3.9e-312 semi-axis sharing their centre). */
/* Large shapes sharing their centre, one shifted by a denormal: they overlap
 * by ~1e5, so SEPARATED is a plain lie (found by fuzzing). */
START_TEST(test_denormal_shift_concentric) {
    {
        /* Large shapes sharing their centre, one shifted by a denormal
         * (regressions/query/denormal-shift-cone-box-false-separated). */
        agjk_cone cone = {196960.44921875, 505859375000};
        agjk_box box = {{94433593750, 0.050585937500000004, 999969.482421875}};
        static const double ra[3][3] = {
            {-0.6022802391698332, -0.32747297662990377, 0.72802469950042137},
            {0.72802469950042137, 0.14879320706658494, 0.6692089497669329},
            {-0.32747297662990377, 0.93307128940290029, 0.14879320706658494}};
        static const double rb[3][3] = {
            {-0.0028991897205428163, 0.0029076195322637055, 0.99999157018827911},
            {0.99999157018827911, -0.0028991897205428163, 0.0029076195322637055},
            {0.0029076195322637055, 0.99999157018827911, -0.0028991897205428163}};
        agjk_shape sc, sb;
        agjk_pose pa, pb;
        agjk_result r;
        ck_assert_int_eq(agjk_shape_cone(&sc, &cone), AGJK_STATUS_OK);
        ck_assert_int_eq(agjk_shape_box(&sb, &box), AGJK_STATUS_OK);
        ck_assert_int_eq(agjk_shape_set_margin(&sb, 9.99756e-08), AGJK_STATUS_OK);
        stab_pose_identity(&pa);
        stab_pose_identity(&pb);
        memcpy(pa.rotation, ra, sizeof ra);
        memcpy(pb.rotation, rb, sizeof rb);
        for (int k = 0; k < 2; k++) {
            pa.translation.z = k ? 5.4323092096489346e-312 : 0.0;
            for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
                agjk_options o = agjk_default_options();
                o.method = (agjk_method)m;
                ck_assert_msg(agjk_collide(&sc, &pa, &sb, &pb, &o, &r) != AGJK_STATUS_SEPARATED,
                              "concentric cone/box shifted by %g, %s: collide says separated",
                              pa.translation.z, agjk_method_name(o.method));
                ck_assert_msg(agjk_distance(&sc, &pa, &sb, &pb, &o, &r) != AGJK_STATUS_SEPARATED,
                              "concentric cone/box shifted by %g, %s: distance says separated",
                              pa.translation.z, agjk_method_name(o.method));
            }
        }
    }
}
END_TEST

START_TEST(test_tiny_concentric) {
    const double tiny[] = {2.7e-93, 1e-200, 3.9e-312, 4.9e-324};
    {
        /* The fuzzer's case (regressions/query/denormal-cone-ellipsoid-false-separated). */
        agjk_cone cone = {212860107.421875, 2.7357906664048309e-93};
        agjk_ellipsoid ell = {{3258056640.625, 9.9539184570312493e-08, 3.8771769168325531e-312}};
        agjk_shape sc, se;
        agjk_pose pa, pb;
        agjk_result r;
        ck_assert_int_eq(agjk_shape_cone(&sc, &cone), AGJK_STATUS_OK);
        ck_assert_int_eq(agjk_shape_ellipsoid(&se, &ell), AGJK_STATUS_OK);
        stab_pose_identity(&pa);
        stab_pose_identity(&pb);
        {
            static const double ra[3][3] = {
                {-0.54271150822125724, -0.78716304453209152, 0.29298218404397292},
                {0.29298218404397292, 0.14949311440064728, 0.94435864404346848},
                {-0.78716304453209152, 0.59835286417778877, 0.14949311440064728}};
            static const double rb[3][3] = {
                {-0.94940329509218557, -0.31383981094091817, 0.01174548154270369},
                {0.017523767890521486, -0.090278005301328568, -0.9957624211214906},
                {0.31357024863181837, -0.9451742986493985, 0.091209891709164603}};
            memcpy(pa.rotation, ra, sizeof ra);
            memcpy(pb.rotation, rb, sizeof rb);
        }
        pa.translation.z = 7.988568138838989e-315;
        for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
            agjk_options o = agjk_default_options();
            o.method = (agjk_method)m;
            ck_assert_msg(agjk_collide(&sc, &pa, &se, &pb, &o, &r) != AGJK_STATUS_SEPARATED,
                          "fuzzer's cone/ellipsoid %s: collide says separated",
                          agjk_method_name(o.method));
            ck_assert_msg(agjk_distance(&sc, &pa, &se, &pb, &o, &r) != AGJK_STATUS_SEPARATED,
                          "fuzzer's cone/ellipsoid %s: distance says separated",
                          agjk_method_name(o.method));
        }
    }
    const double shift[] = {0.0, 8e-315, 5e-312, 1e-300};
    for (size_t i = 0; i < sizeof tiny / sizeof tiny[0]; i++)
        for (size_t k = 0; k < sizeof shift / sizeof shift[0]; k++)
            for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
                agjk_cone cone = {212860107.421875, tiny[i]};
                agjk_ellipsoid ell = {{3258056640.625, 9.95e-08, tiny[i]}};
                agjk_cone seg = {0, tiny[i]};
                agjk_shape sc, se, ss, pt;
                agjk_pose pa, pb;
                agjk_options o = agjk_default_options();
                agjk_result r;
                agjk_status st;
                o.method = (agjk_method)m;
                ck_assert_int_eq(agjk_shape_cone(&sc, &cone), AGJK_STATUS_OK);
                ck_assert_int_eq(agjk_shape_ellipsoid(&se, &ell), AGJK_STATUS_OK);
                ck_assert_int_eq(agjk_shape_cone(&ss, &seg), AGJK_STATUS_OK);
                ck_assert_int_eq(agjk_shape_point(&pt), AGJK_STATUS_OK);
                stab_pose_identity(&pa);
                stab_pose_identity(&pb);
                /* A shift along z stays inside both (within their thickness)
                 * only when it is below the tiny size: otherwise skip it. */
                if (shift[k] > tiny[i]) continue;
                pa.translation.z = shift[k];
                st = agjk_collide(&sc, &pa, &se, &pb, &o, &r);
                ck_assert_msg(st != AGJK_STATUS_SEPARATED,
                              "cone/ellipsoid size %g shift %g %s: collide says separated",
                              tiny[i], shift[k], agjk_method_name(o.method));
                st = agjk_distance(&sc, &pa, &se, &pb, &o, &r);
                ck_assert_msg(st != AGJK_STATUS_SEPARATED,
                              "cone/ellipsoid size %g shift %g %s: distance says separated",
                              tiny[i], shift[k], agjk_method_name(o.method));
                st = agjk_collide(&ss, &pa, &pt, &pa, &o, &r);
                ck_assert_msg(st != AGJK_STATUS_SEPARATED,
                              "segment/point size %g %s: collide says separated", tiny[i],
                              agjk_method_name(o.method));
                g_count += 3;
            }
}
END_TEST

/* A separating plane reported by agjk_collide must separate, also when the
 * translations are denormal (x_0 = c_A - c_B is then a denormal vector).
 * Found by fuzzing: the plane overlapped the shapes by 2.5e10. Checked in
 * long double with the independent supports of stab_util. */
START_TEST(test_denormal_translation_plane) {
    static agjk_vec3 v[1] = {{8.8288253015836587e-280, 41958618.1640625, 4.1616821289062499e-07}};
    ref_shape a, b;
    agjk_shape sa, sb;
    agjk_pose pa = {{{-0.068296821024357968, 0.6773475494246648, -0.73248606916880554},
                     {0.99721914771710063, 0.068296821024357746, -0.029824749191672606},
                     {0.029824749191672606, -0.73248606916880554, -0.68012840170756417}},
                    {0, 0, 1.2598673968951787e-321}};
    agjk_pose pb = {{{0.00077820964507213652, 0.99999939391772186, -0.00077881572735022386},
                     {-0.00077881572735022386, -0.00077820964507213652, -0.99999939391772186},
                     {-0.99999939391772186, 0.00077881572735022386, 0.00077820964507213652}},
                    {0, 5.3474293919676782e-312, 0}};
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.kind = REF_POLYTOPE;
    a.vertices = v;
    a.vertex_count = 1;
    b.kind = REF_ELLIPSOID;
    b.p[0] = 419586181640.625;
    b.p[1] = 41.8670654296875;
    b.p[2] = 445861816.40625;
    ck_assert_int_eq(stab_make_shape(&a, &sa), AGJK_STATUS_OK);
    ck_assert_int_eq(stab_make_shape(&b, &sb), AGJK_STATUS_OK);
    for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; m++) {
        agjk_options o = agjk_default_options();
        agjk_result r;
        o.method = (agjk_method)m;
        if (agjk_collide(&sa, &pa, &sb, &pb, &o, &r) == AGJK_STATUS_SEPARATED) {
            long double n[3] = {r.normal.x, r.normal.y, r.normal.z};
            long double mn[3] = {-n[0], -n[1], -n[2]}, p[3];
            long double gap = -(stab_support_world(&a, &pa, n, p) + stab_support_world(&b, &pb, mn, p));
            /* Rounding of a unit normal moves h by ~eps x 4e11 = 1e-4. */
            ck_assert_msg(gap > -1.0, "%s: the reported plane overlaps the shapes by %Lg",
                          agjk_method_name(o.method), -gap);
        }
        g_count++;
    }
}
END_TEST

/* ---- simplex projection, options init, strings ---- */

START_TEST(test_simplex_projection) {
    double nan = NAN_, inf = INF_;
    agjk_vec3 v[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    struct {
        unsigned char pre[STAB_GUARD];
        agjk_simplex_projection p;
        unsigned char post[STAB_GUARD];
    } g;
    const int bad_count[] = {0, -1, 5, INT_MIN, INT_MAX};
    for (size_t i = 0; i < sizeof bad_count / sizeof bad_count[0]; i++) {
        stab_guard_fill(g.pre);
        stab_guard_fill(g.post);
        ck_assert_int_eq(agjk_simplex_project_origin(v, bad_count[i], &g.p), AGJK_STATUS_INVALID_INPUT);
        ck_assert(stab_guard_ok(g.pre) && stab_guard_ok(g.post));
        g_count++;
    }
    ck_assert_int_eq(agjk_simplex_project_origin(NULL, 3, &g.p), AGJK_STATUS_INVALID_INPUT);
    ck_assert_int_eq(agjk_simplex_project_origin(v, 3, NULL), AGJK_STATUS_INVALID_INPUT);
    for (int c = 1; c <= 4; c++) {
        agjk_vec3 w[4];
        memcpy(w, v, sizeof w);
        w[c - 1].y = (c % 2) ? nan : inf;
        ck_assert_int_eq(agjk_simplex_project_origin(w, c, &g.p), AGJK_STATUS_INVALID_INPUT);
        g_count += 3;
    }
    /* Finite but extreme inputs: documented "always finite for finite input". */
    {
        const double scales[] = {1e-300, 4.9e-324, 1e-160, 1e150, 1e200, 1e300, DBL_MAX};
        stab_rng rng = {77};
        for (size_t s = 0; s < sizeof scales / sizeof scales[0]; s++)
            for (int trial = 0; trial < 200; trial++) {
                agjk_vec3 w[4];
                int c = 1 + trial % 4;
                for (int i = 0; i < 4; i++) {
                    double f = scales[s] > 1e300 ? 1.0 : 2.0;
                    w[i].x = scales[s] * stab_range(&rng, -1, 1) * f / 2;
                    w[i].y = scales[s] * stab_range(&rng, -1, 1) * f / 2;
                    w[i].z = scales[s] * stab_range(&rng, -1, 1) * f / 2;
                    if (trial % 7 == 0 && i > 0) w[i] = w[0];            /* repeated */
                    if (trial % 5 == 0 && i > 1) {                       /* collinear */
                        w[i].x = w[0].x + (w[1].x - w[0].x) * 0.5;
                        w[i].y = w[0].y;
                        w[i].z = w[0].z;
                    }
                }
                stab_guard_fill(g.pre);
                stab_guard_fill(g.post);
                agjk_status st = agjk_simplex_project_origin(w, c, &g.p);
                ck_assert(stab_guard_ok(g.pre) && stab_guard_ok(g.post));
                if (st == AGJK_STATUS_INVALID_INPUT && scales[s] > MAXC) continue; /* documented */
                ck_assert_msg(st == AGJK_STATUS_SEPARATED || st == AGJK_STATUS_INTERSECTING,
                              "scale %g: status %d", scales[s], (int)st);
                ck_assert_msg(isfinite(g.p.point.x) && isfinite(g.p.point.y) &&
                                  isfinite(g.p.point.z),
                              "scale %g count %d: non-finite projection", scales[s], c);
                double sum = 0;
                for (int i = 0; i < 4; i++) {
                    ck_assert_msg(isfinite(g.p.weights[i]) && g.p.weights[i] >= 0,
                                  "scale %g count %d: weight %d = %g", scales[s], c, i,
                                  g.p.weights[i]);
                    if (i >= c) ck_assert(g.p.weights[i] == 0);
                    sum += g.p.weights[i];
                }
                ck_assert_msg(fabs(sum - 1) < 1e-9, "scale %g: weights sum %g", scales[s], sum);
                ck_assert(g.p.support_count >= 1 && g.p.support_count <= c);
                ck_assert((g.p.support_mask & ~((1u << c) - 1)) == 0);
                g_count++;
            }
    }
}
END_TEST

START_TEST(test_options_strings_version) {
    struct {
        unsigned char pre[STAB_GUARD];
        agjk_options o;
        unsigned char post[STAB_GUARD];
    } g;
    unsigned char before[sizeof(agjk_options)];
    /* NULL and too-small sizes: documented to do nothing. */
    agjk_options_init_sized(NULL, sizeof(agjk_options));
    const size_t small[] = {0, 1, 4, 8};
    for (size_t i = 0; i < 4; i++) {
        stab_guard_fill(g.pre);
        stab_guard_fill(g.post);
        memset(&g.o, 0x33, sizeof g.o);
        memcpy(before, &g.o, sizeof before);
        agjk_options_init_sized(&g.o, small[i]);
        ck_assert(stab_guard_ok(g.pre) && stab_guard_ok(g.post));
        ck_assert_msg(memcmp(before, &g.o, sizeof before) == 0, "init with size %zu wrote",
                      small[i]);
        g_count++;
    }
    /* A caller with a bigger (newer) struct: nothing beyond what it declared. */
    {
        struct {
            agjk_options o;
            unsigned char future[32];
            unsigned char post[STAB_GUARD];
        } big;
        stab_guard_fill(big.post);
        agjk_options_init_sized(&big.o, sizeof big.o + sizeof big.future);
        ck_assert(stab_guard_ok(big.post));
        ck_assert(big.o.tolerance > 0 && big.o.max_iterations >= 1);
        g_count++;
    }
    stab_guard_fill(g.pre);
    stab_guard_fill(g.post);
    agjk_options_init(&g.o);
    ck_assert(stab_guard_ok(g.pre) && stab_guard_ok(g.post));
    ck_assert(g.o.struct_size == sizeof(agjk_options));
    /* Strings: never NULL, unknown values named as documented. */
    const int codes[] = {-1, 6, 1000, INT_MIN, INT_MAX};
    for (int s = 0; s <= 5; s++) {
        const char *t = agjk_status_string((agjk_status)s);
        ck_assert(t != NULL && t[0] != '\0' && strcmp(t, "unknown status") != 0);
        if (s == 5) break;
        t = agjk_method_name((agjk_method)s);
        ck_assert(t != NULL && t[0] != '\0' && strcmp(t, "unknown") != 0);
    }
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        const char *t = agjk_status_string((agjk_status)codes[i]);
        ck_assert(t != NULL);
        ck_assert_str_eq(t, "unknown status");
        t = agjk_method_name((agjk_method)codes[i]);
        ck_assert(t != NULL);
        ck_assert_str_eq(t, "unknown");
        g_count += 2;
    }
    ck_assert_int_eq(agjk_version(), AGJK_VERSION_NUMBER);
    ck_assert_str_eq(agjk_version_string(), AGJK_VERSION_STRING);
}
END_TEST

/* ---- polytope adjacency (agjk/polytope.h) ---- */

#define ADJ_GUARD 16
#define ADJ_POISON (-777)

static void fill_i32(int32_t *p, int n, int32_t v) {
    for (int i = 0; i < n; i++) p[i] = v;
}

static int all_i32(const int32_t *p, int n, int32_t v) {
    for (int i = 0; i < n; i++)
        if (p[i] != v) return 0;
    return 1;
}

START_TEST(test_polytope_adjacency) {
    /* Tetrahedron: 4 vertices, 4 triangles. */
    static const agjk_vec3 v[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1, 0.1, 0.1}};
    static const int32_t tri[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    static const int32_t tri_out[12] = {0, 2, 1, 0, 1, 3, 0, 3, 4, 1, 2, 3};
    static const int32_t tri_neg[12] = {0, 2, 1, 0, 1, 3, 0, 3, -1, 1, 2, 3};
    static const int32_t tri_rep[12] = {0, 2, 2, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    int32_t oc = ADJ_POISON, nc = ADJ_POISON;
    /* capacity */
    const int32_t bad_vc[] = {0, -1, INT32_MIN, AGJK_POLYTOPE_MAX_VERTICES + 1, INT32_MAX};
    for (size_t i = 0; i < sizeof bad_vc / sizeof bad_vc[0]; i++) {
        oc = nc = ADJ_POISON;
        ck_assert_int_eq(agjk_polytope_adjacency_capacity(bad_vc[i], 4, &oc, &nc),
                         AGJK_STATUS_INVALID_INPUT);
        ck_assert_msg(oc == ADJ_POISON && nc == ADJ_POISON, "capacity wrote on failure");
        g_count++;
    }
    const int32_t bad_tc[] = {-1, INT32_MIN, INT32_MAX, INT32_MAX / 6 + 1};
    for (size_t i = 0; i < sizeof bad_tc / sizeof bad_tc[0]; i++) {
        oc = nc = ADJ_POISON;
        ck_assert_int_eq(agjk_polytope_adjacency_capacity(4, bad_tc[i], &oc, &nc),
                         AGJK_STATUS_INVALID_INPUT);
        ck_assert(oc == ADJ_POISON && nc == ADJ_POISON);
        g_count++;
    }
    ck_assert_int_eq(agjk_polytope_adjacency_capacity(4, 4, NULL, &nc), AGJK_STATUS_INVALID_INPUT);
    ck_assert_int_eq(agjk_polytope_adjacency_capacity(4, 4, &oc, NULL), AGJK_STATUS_INVALID_INPUT);
    ck_assert_int_eq(agjk_polytope_adjacency_capacity(4, 4, &oc, &nc), AGJK_STATUS_OK);
    ck_assert(oc == 5 && nc >= 12);
    /* build_into: guards around both buffers. */
    {
        int32_t off[ADJ_GUARD + 8 + ADJ_GUARD], nb[ADJ_GUARD + 64 + ADJ_GUARD];
        struct {
            const int32_t *t;
            int32_t vc, tc, cap;
            int ok;
        } cases[] = {
            {tri, 4, 4, 24, 1},      {tri, 4, 4, 12, 0},     {tri, 4, 4, 11, 0},
            {tri, 4, 4, 0, 0},       {tri, 4, 4, -1, 0},     {tri_out, 4, 4, 24, 0},
            {tri_neg, 4, 4, 24, 0},  {tri_rep, 4, 4, 24, 0}, {tri, 5, 4, 24, 0}, /* unused vertex */
            {NULL, 4, 4, 24, 0},     {tri, 4, -1, 24, 0},    {tri, 0, 4, 24, 0},
            {tri, -3, 4, 24, 0},     {tri, 4, 0, 24, 0},
        };
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            agjk_status st;
            fill_i32(off, (int)(sizeof off / sizeof off[0]), ADJ_POISON);
            fill_i32(nb, (int)(sizeof nb / sizeof nb[0]), ADJ_POISON);
            int32_t cap = cases[i].cap > 64 ? 64 : cases[i].cap;
            st = agjk_polytope_adjacency_build_into(cases[i].vc, cases[i].t, cases[i].tc,
                                                    off + ADJ_GUARD, nb + ADJ_GUARD, cap);
            ck_assert_msg(all_i32(off, ADJ_GUARD, ADJ_POISON) &&
                              all_i32(off + ADJ_GUARD + 8,
                                      ADJ_GUARD, ADJ_POISON),
                          "case %zu: wrote outside neighbor_offsets", i);
            ck_assert_msg(all_i32(nb, ADJ_GUARD, ADJ_POISON) &&
                              all_i32(nb + ADJ_GUARD + (cap > 0 ? cap : 0), ADJ_GUARD, ADJ_POISON),
                          "case %zu: wrote outside neighbors", i);
            if (cases[i].ok) {
                ck_assert_msg(st == AGJK_STATUS_OK, "case %zu: %s", i, agjk_status_string(st));
                ck_assert_int_eq(off[ADJ_GUARD + 4], 12);
            } else {
                ck_assert_msg(st == AGJK_STATUS_INVALID_INPUT, "case %zu: %s, expected invalid",
                              i, agjk_status_string(st));
            }
            g_count++;
        }
        ck_assert_int_eq(agjk_polytope_adjacency_build_into(4, tri, 4, NULL, nb, 24),
                         AGJK_STATUS_INVALID_INPUT);
        ck_assert_int_eq(agjk_polytope_adjacency_build_into(4, tri, 4, off, NULL, 24),
                         AGJK_STATUS_INVALID_INPUT);
    }
    /* Allocating variant: failure leaves no adjacency; free is idempotent. */
    {
        agjk_polytope p = {v, 4, NULL, NULL};
        ck_assert_int_eq(agjk_polytope_build_adjacency(NULL, tri, 4), AGJK_STATUS_INVALID_INPUT);
        ck_assert_int_eq(agjk_polytope_build_adjacency(&p, tri_out, 4), AGJK_STATUS_INVALID_INPUT);
        ck_assert(p.neighbor_offsets == NULL && p.neighbors == NULL);
        ck_assert_int_eq(agjk_polytope_build_adjacency(&p, NULL, 4), AGJK_STATUS_INVALID_INPUT);
        ck_assert_int_eq(agjk_polytope_build_adjacency(&p, tri, -4), AGJK_STATUS_INVALID_INPUT);
        ck_assert(p.neighbor_offsets == NULL && p.neighbors == NULL);
        ck_assert_int_eq(agjk_polytope_build_adjacency(&p, tri, 4), AGJK_STATUS_OK);
        ck_assert(p.neighbor_offsets != NULL && p.neighbors != NULL);
        {
            agjk_shape sh;
            ck_assert_int_eq(agjk_shape_polytope(&sh, &p), AGJK_STATUS_OK);
        }
        agjk_polytope_free_adjacency(&p);
        ck_assert(p.neighbor_offsets == NULL && p.neighbors == NULL);
        agjk_polytope_free_adjacency(&p);
        agjk_polytope_free_adjacency(NULL);
        p.vertex_count = 0;
        ck_assert_int_eq(agjk_polytope_build_adjacency(&p, tri, 4), AGJK_STATUS_INVALID_INPUT);
        ck_assert(p.neighbor_offsets == NULL && p.neighbors == NULL);
        g_count += 10;
    }
}
END_TEST

static Suite *bad_input_suite(void) {
    Suite *s = suite_create("bad input");
    TCase *tc = tcase_create("matrix");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_scalar_shapes);
    tcase_add_test(tc, test_polytope_and_margin);
    tcase_add_test(tc, test_query_null_and_options);
    tcase_add_test(tc, test_query_poses);
    tcase_add_test(tc, test_hostile_support);
    tcase_add_test(tc, test_signed_overlapping);
    tcase_add_test(tc, test_mixed_magnitudes);
    tcase_add_test(tc, test_tiny_concentric);
    tcase_add_test(tc, test_denormal_shift_concentric);
    tcase_add_test(tc, test_denormal_translation_plane);
    tcase_add_test(tc, test_simplex_projection);
    tcase_add_test(tc, test_options_strings_version);
    tcase_add_test(tc, test_polytope_adjacency);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) {
    SRunner *sr = srunner_create(bad_input_suite());
    int failed;
    alarm(120);
    /* No fork, so the count adds up; a crash fails the whole program. */
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    printf("bad-input matrix: %ld calls checked\n", g_count);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
