/* SPDX-License-Identifier: MIT */
/* Queries on problems of ordinary size form no subnormal number. On x86 an
 * arithmetic operation with a subnormal operand or result takes a microcode
 * assist of about a hundred cycles, a large share of a query that takes a
 * few hundred: the library keeps every tiny quantity it needs (the caller's
 * granule at huge scales, say) behind integer or exponent arithmetic, and
 * this test holds it to that whatever the compiler does with its branches
 * (clang 14 once turned the granule's conditional into arithmetic on both
 * arms: close box queries took 420 ns instead of 252; gcc's branch hid it).
 *
 * Paper-protocol pairs of every built-in kind (ellipsoids, boxes, rounded
 * boxes, capsules, spheres, polytopes), distant, close and overlapping, every
 * method, distance with and without witness points, Boolean, cached and
 * signed-distance queries. Each query runs with the floating-point status
 * cleared; after it, on x86 the SSE flags DE (a subnormal operand) and UE (an
 * inexact subnormal result) must be clear; elsewhere FE_UNDERFLOW, where the
 * platform has it. */
#include <fenv.h>
#include <stdio.h>
#include <string.h>
#include "core_checks.h"
#include "agjk/cache.h"
#include "agjk/penetration.h"

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
#include <xmmintrin.h>
#define SSE_FLAG_DENORMAL 0x0002u /* DE: an operand was subnormal */
#define SSE_FLAG_UNDERFLOW 0x0010u /* UE: a result was subnormal (and inexact) */
static void flags_clear(void) {
    feclearexcept(FE_ALL_EXCEPT);
    _mm_setcsr(_mm_getcsr() & ~0x3Fu);
}
static unsigned flags_subnormal(void) {
    return _mm_getcsr() & (SSE_FLAG_DENORMAL | SSE_FLAG_UNDERFLOW);
}
#elif defined(FE_UNDERFLOW)
static void flags_clear(void) { feclearexcept(FE_ALL_EXCEPT); }
static unsigned flags_subnormal(void) { return fetestexcept(FE_UNDERFLOW) ? 1u : 0u; }
#else /* no floating-point status to read (soft float): nothing checked */
static void flags_clear(void) {}
static unsigned flags_subnormal(void) { return 0u; }
#endif

#define MAX_VERTS 40
#define PAIRS 12

static const double targets[] = {1.0, 1e-4, 1e-8, -1e-8, -1e-4};
#define N_TARGETS ((int)(sizeof targets / sizeof targets[0]))

static void random_shape(tu_rng *rng, ref_shape *s, agjk_vec3 *store, int kind, double sc) {
    switch (kind) {
    case 0: tu_random_ellipsoid(rng, s, sc); break;
    case 1: tu_random_box(rng, s, sc); break;
    case 2: tu_random_polytope(rng, s, store, 8 + (int)tu_uniform_int(rng, MAX_VERTS - 8), sc); break;
    case 3:
        tu_random_box(rng, s, sc);
        s->margin = 0.2 * tu_paper_radius(rng, sc);
        break;
    case 4: tu_shape_init(s, REF_CAPSULE, tu_paper_radius(rng, sc), tu_paper_radius(rng, sc), 0.0); break;
    default: tu_shape_init(s, REF_SPHERE, tu_paper_radius(rng, sc), 0.0, 0.0); break;
    }
}

/* Fails with the query's description when its flags show a subnormal. */
static void expect_clear(const char *what, int kind, double target, int pair, agjk_method m) {
    unsigned f = flags_subnormal();
    TU_ENSURE(f == 0, "%s formed a subnormal (flags 0x%x): kind %d, target %g, pair %d, %s", what,
              f, kind, target, pair, agjk_method_name(m));
}

START_TEST(ordinary_queries_form_no_subnormal) {
    tu_rng rng;
    tu_rng_seed(&rng, 2026);
    static agjk_vec3 va[MAX_VERTS], vb[MAX_VERTS];
    int queries = 0;
    for (int kind = 0; kind < 6; kind++)
        for (int t = 0; t < N_TARGETS; t++)
            for (int i = 0; i < PAIRS; i++) {
                ref_shape a, b;
                double sc = tu_paper_scale(&rng);
                random_shape(&rng, &a, va, kind, sc);
                random_shape(&rng, &b, vb, (kind + i) % 6, sc);
                agjk_pose pa = tu_random_pose(&rng, 1.0), pb = tu_random_pose(&rng, 1.0);
                TU_CHECK_INT_EQ(tu_set_distance(&a, &pa, &b, &pb, targets[t], NULL), 0);
                agjk_shape sa, sb;
                core_make_shapes(&a, &b, &sa, &sb);
                for (int m = 0; m < CORE_METHOD_COUNT; m++) {
                    agjk_options o = agjk_default_options();
                    o.method = core_methods[m];
                    agjk_result r;
                    flags_clear();
                    agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
                    expect_clear("agjk_distance", kind, targets[t], i, o.method);
                    flags_clear();
                    agjk_collide(&sa, &pa, &sb, &pb, &o, &r);
                    expect_clear("agjk_collide", kind, targets[t], i, o.method);
                    o.compute = AGJK_COMPUTE_WITNESS;
                    flags_clear();
                    agjk_distance(&sa, &pa, &sb, &pb, &o, &r);
                    expect_clear("agjk_distance with witness points", kind, targets[t], i, o.method);
                    /* Warm: the same pair again, then moved slightly. */
                    agjk_cache cache;
                    agjk_cache_init(&cache);
                    agjk_pose moved = pb;
                    moved.translation.x += 1e-3 * sc;
                    flags_clear();
                    agjk_distance_cached(&sa, &pa, &sb, &pb, &o, &cache, &r);
                    agjk_distance_cached(&sa, &pa, &sb, &moved, &o, &cache, &r);
                    agjk_collide_cached(&sa, &pa, &sb, &pb, &o, &cache, &r);
                    expect_clear("cached queries", kind, targets[t], i, o.method);
                    queries += 6;
                }
                agjk_options o = agjk_default_options();
                agjk_signed_result sr;
                flags_clear();
                agjk_signed_distance(&sa, &pa, &sb, &pb, &o, &sr);
                expect_clear("agjk_signed_distance", kind, targets[t], i, o.method);
                queries++;
            }
    printf("subnormals: %d queries, none formed a subnormal\n", queries);
}
END_TEST

int main(void) {
    Suite *s = suite_create("subnormals");
    TU_ADD(s, ordinary_queries_form_no_subnormal);
    return tu_run_suite(s);
}
