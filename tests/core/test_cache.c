/* SPDX-License-Identifier: MIT */
/* The warm-start cache (agjk/cache.h) changes speed, never answers:
 *   - along smooth trajectories (ellipsoids, boxes, polytopes; close, touching
 *     and shallowly overlapping poses) every cached answer is certified by the
 *     long double reference, agrees with the cold answer of the same pose
 *     within the two certified bounds, and has the same status unless one of
 *     the two is "contact within tolerance"; with the cache the trajectories
 *     take fewer support calls than cold (the point of it);
 *   - a cache from another pair, a swapped pair, a zeroed, garbage, NaN-filled
 *     or wrongly sized one is ignored: the answer is bit for bit the cold one;
 *   - a cache of the same pair filled at a far-away pose is still certified;
 *   - invalid input empties the cache; every result is NaN-free. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "core_checks.h"
#include "ref_depth.h"

#define STEPS 120
#define MAX_VERTS 40

typedef struct pair {
    ref_shape ra, rb;
    agjk_vec3 va[MAX_VERTS], vb[MAX_VERTS];
    agjk_shape a, b;
    agjk_pose pa, pb;     /* placed by tu_set_distance */
    agjk_vec3 axis_a, axis_b, slide;
    double size;
} pair;

static void make_shape(tu_rng *rng, ref_shape *s, agjk_vec3 *store, int kind) {
    if (kind == 0) tu_random_ellipsoid(rng, s, 1.0);
    else if (kind == 1) tu_random_box(rng, s, 1.0);
    else tu_random_polytope(rng, s, store, 8 + (int)tu_uniform_int(rng, MAX_VERTS - 8), 1.0);
}

/* A pair of `kind` shapes at a small distance, with its trajectory's axes. */
static int make_pair(tu_rng *rng, int kind, pair *p) {
    make_shape(rng, &p->ra, p->va, kind);
    make_shape(rng, &p->rb, p->vb, kind);
    if (ref_make_agjk(&p->ra, &p->a) != AGJK_STATUS_OK) return -1;
    if (ref_make_agjk(&p->rb, &p->b) != AGJK_STATUS_OK) return -1;
    p->pa = tu_random_pose(rng, 1.0);
    p->pb = tu_random_pose(rng, 1.0);
    p->size = tu_bounding_radius(&p->rb);
    if (tu_set_distance(&p->ra, &p->pa, &p->rb, &p->pb, 0.01 * p->size, NULL) != 0) return -1;
    p->axis_a = tu_unit_vector(rng);
    p->axis_b = tu_unit_vector(rng);
    /* From A towards B, roughly: B slides back and forth along it. */
    p->slide = tu_sub(p->pb.translation, p->pa.translation);
    p->slide = tu_scale(p->slide, 1.0 / tu_norm(p->slide));
    return 0;
}

static void axis_rotation(agjk_vec3 u, double t, double r[3][3]) {
    double c = cos(t), s = sin(t), k = 1.0 - c;
    r[0][0] = k * u.x * u.x + c;       r[0][1] = k * u.x * u.y - s * u.z; r[0][2] = k * u.x * u.z + s * u.y;
    r[1][0] = k * u.x * u.y + s * u.z; r[1][1] = k * u.y * u.y + c;       r[1][2] = k * u.y * u.z - s * u.x;
    r[2][0] = k * u.x * u.z - s * u.y; r[2][1] = k * u.y * u.z + s * u.x; r[2][2] = k * u.z * u.z + c;
}

/* Poses of step i: small turns of both shapes, B sliding from 2% of its size
 * apart to 2% overlap (along the initial axis) and back. */
static void step_poses(const pair *p, int i, agjk_pose *pa, agjk_pose *pb) {
    agjk_pose ra = tu_pose_identity(), rb = tu_pose_identity();
    axis_rotation(p->axis_a, 0.002 * i, ra.rotation);
    axis_rotation(p->axis_b, 0.003 * i, rb.rotation);
    *pa = p->pa;
    *pb = p->pb;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            pa->rotation[r][c] = 0.0;
            pb->rotation[r][c] = 0.0;
            for (int k = 0; k < 3; k++) {
                pa->rotation[r][c] += ra.rotation[r][k] * p->pa.rotation[k][c];
                pb->rotation[r][c] += rb.rotation[r][k] * p->pb.rotation[k][c];
            }
        }
    double s = p->size * (0.02 * cos(6.283185307179586 * i / STEPS) - 0.01);
    pb->translation = tu_add(pb->translation, tu_scale(p->slide, s));
}

static int finite_result(const agjk_result *r) {
    return isfinite(r->distance) && isfinite(r->bound) && isfinite(r->gap) &&
           tu_vec_finite(r->witness_a) && tu_vec_finite(r->witness_b) && tu_vec_finite(r->normal);
}

/* The cached answer against the reference and the cold answer. */
static void check_answer(const char *what, const pair *p, const agjk_pose *pa, const agjk_pose *pb,
                         const agjk_result *cold, const agjk_result *warm, int boolean, int fw) {
    ref_result ref;
    TU_ENSURE(finite_result(warm), "%s: NaN or Inf in the result", what);
    /* Plain Frank-Wolfe may reach the iteration cap on polytopes, cold or not,
     * and keeps no simplex to certify an overlap with. Every other method goes
     * on past the tolerance until the sign is decided (solver.c,
     * sign_pending, within a budget of iterations), so that cold and warm
     * queries agree, except within the tolerance's scale of contact (the
     * default 1e-8 on squared lengths: 1e-4), where the budget may run out
     * and "contact within tolerance" is an honest answer: judged, when the
     * statuses differ, by an independent bracket on the signed distance. */
    int contact = warm->status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE ||
                  cold->status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE;
    int undecided = fw && (contact || warm->status == AGJK_STATUS_NOT_CONVERGED ||
                           cold->status == AGJK_STATUS_NOT_CONVERGED);
    if (contact && !undecided && warm->status != cold->status) {
        ref_signed_bracket br;
        ref_signed_distance_bb(&p->ra, pa, &p->rb, pb, 1e-7L * p->size, 20000, &br);
        undecided = br.lower <= 1e-4L && br.upper >= -1e-4L;
    }
    TU_ENSURE(warm->status != AGJK_STATUS_INVALID_INPUT &&
                  (fw || warm->status != AGJK_STATUS_NOT_CONVERGED),
              "%s: status %d", what, warm->status);
    TU_ENSURE(warm->status == cold->status || undecided,
              "%s: status %d with the cache, %d cold", what, warm->status, cold->status);
    if (ref_distance(&p->ra, pa, &p->rb, pb, &ref) != 0) return; /* no verdict to judge by */
    double slack = 1e-12 * p->size;
    if (warm->status == AGJK_STATUS_SEPARATED)
        TU_ENSURE(!ref.intersecting, "%s: separated, the reference says intersecting", what);
    if (warm->status == AGJK_STATUS_INTERSECTING)
        TU_ENSURE(ref.intersecting || ref.lower <= slack,
                  "%s: intersecting, the reference says separated by %Lg", what, ref.lower);
    if (boolean) return;
    /* The certified interval [distance - bound, distance] holds the truth. */
    long double lo = ref.intersecting ? 0.0L : ref.lower, hi = ref.intersecting ? 0.0L : ref.upper;
    TU_ENSURE(warm->distance + slack >= lo && warm->distance - warm->bound - slack <= hi,
              "%s: [%.17g, %.17g] misses the reference [%.17Lg, %.17Lg]", what,
              warm->distance - warm->bound, warm->distance, lo, hi);
    TU_ENSURE(fabs(warm->distance - cold->distance) <= warm->bound + cold->bound + slack,
              "%s: distance %.17g (bound %.3g) cached vs %.17g (bound %.3g) cold", what,
              warm->distance, warm->bound, cold->distance, cold->bound);
}

/* Every method, every kind of shape, distance and Boolean queries. */
START_TEST(trajectories) {
    static const char *const kinds[3] = {"ellipsoids", "boxes", "polytopes"};
    tu_rng rng;
    tu_rng_seed(&rng, 909);
    for (int m = 0; m < CORE_METHOD_COUNT; m++)
        for (int kind = 0; kind < 3; kind++)
            for (int boolean = 0; boolean < 2; boolean++) {
                pair p;
                long cold_calls = 0, warm_calls = 0;
                int tries = 0;
                while (make_pair(&rng, kind, &p) != 0) TU_CHECK(++tries < 100);
                agjk_options o = agjk_default_options();
                o.method = core_methods[m];
                agjk_cache cache;
                agjk_cache_init(&cache);
                for (int i = 0; i < STEPS; i++) {
                    agjk_pose pa, pb;
                    agjk_result cold, warm;
                    char what[160];
                    step_poses(&p, i, &pa, &pb);
                    snprintf(what, sizeof what, "%s %s %s step %d", agjk_method_name(o.method),
                             kinds[kind], boolean ? "collide" : "distance", i);
                    if (boolean) {
                        agjk_collide(&p.a, &pa, &p.b, &pb, &o, &cold);
                        agjk_collide_cached(&p.a, &pa, &p.b, &pb, &o, &cache, &warm);
                    } else {
                        agjk_distance(&p.a, &pa, &p.b, &pb, &o, &cold);
                        agjk_distance_cached(&p.a, &pa, &p.b, &pb, &o, &cache, &warm);
                    }
                    check_answer(what, &p, &pa, &pb, &cold, &warm, boolean,
                                 o.method == AGJK_METHOD_FRANK_WOLFE);
                    TU_ENSURE(cache.struct_size == sizeof cache && cache.count >= 0 &&
                                  cache.count <= 4 &&
                                  (cache.count >= 1 || tu_norm(cache.direction) > 0.0),
                              "%s: cache not refilled (count %d)", what, cache.count);
                    cold_calls += cold.support_calls;
                    warm_calls += warm.support_calls;
                }
                /* Plain Frank-Wolfe keeps only a direction; the others must gain. */
                if (o.method != AGJK_METHOD_FRANK_WOLFE && !boolean)
                    TU_ENSURE(warm_calls < cold_calls, "%s %s: %ld support calls with the cache, "
                              "%ld cold", agjk_method_name(o.method), kinds[kind], warm_calls,
                              cold_calls);
            }
}
END_TEST

/* A cache the query must ignore gives exactly the cold result. */
static void expect_ignored(const char *what, const pair *p, agjk_cache *cache, int boolean) {
    agjk_options o = agjk_default_options();
    agjk_result cold, warm;
    memset(&cold, 0, sizeof cold);
    memset(&warm, 0, sizeof warm);
    if (boolean) {
        agjk_collide(&p->a, &p->pa, &p->b, &p->pb, &o, &cold);
        agjk_collide_cached(&p->a, &p->pa, &p->b, &p->pb, &o, cache, &warm);
    } else {
        agjk_distance(&p->a, &p->pa, &p->b, &p->pb, &o, &cold);
        agjk_distance_cached(&p->a, &p->pa, &p->b, &p->pb, &o, cache, &warm);
    }
    TU_ENSURE(memcmp(&cold, &warm, sizeof cold) == 0,
              "%s: result differs from the cold one (status %d vs %d, %d vs %d support calls)",
              what, warm.status, cold.status, warm.support_calls, cold.support_calls);
    TU_ENSURE(cache->struct_size == sizeof *cache && cache->count >= 0 && cache->count <= 4 &&
                  cache->support_a == p->a.support && cache->data_a == p->a.data,
              "%s: the cache was not refilled for this pair", what);
}

/* Fills `cache` for pair q at its pose, with simplex points: on curved shapes
 * a cache keeps only its direction unless flagged flat (a flag a caller may
 * set: it only chooses the start), so the second query runs flagged. */
static void fill(const pair *q, agjk_cache *cache) {
    agjk_result r;
    agjk_cache_init(cache);
    agjk_distance_cached(&q->a, &q->pa, &q->b, &q->pb, NULL, cache, &r);
    cache->flags |= AGJK_CACHE_FLAT;
    agjk_distance_cached(&q->a, &q->pa, &q->b, &q->pb, NULL, cache, &r);
    TU_CHECK(cache->count >= 1);
}

START_TEST(foreign_and_garbage) {
    tu_rng rng;
    tu_rng_seed(&rng, 4242);
    for (int kind = 0; kind < 3; kind++)
        for (int boolean = 0; boolean < 2; boolean++)
            for (int trial = 0; trial < 20; trial++) {
                pair p, q;
                agjk_cache cache;
                int tries = 0;
                while (make_pair(&rng, kind, &p) != 0) TU_CHECK(++tries < 100);
                while (make_pair(&rng, 2 - kind, &q) != 0) TU_CHECK(++tries < 200);
                /* another pair's cache */
                fill(&q, &cache);
                expect_ignored("foreign pair", &p, &cache, boolean);
                /* the same shapes, swapped */
                {
                    pair s = p;
                    s.a = p.b;
                    s.b = p.a;
                    s.pa = p.pb;
                    s.pb = p.pa;
                    fill(&s, &cache);
                    if (p.a.support != p.b.support || p.a.data != p.b.data)
                        expect_ignored("swapped pair", &p, &cache, boolean);
                }
                /* zeroed */
                memset(&cache, 0, sizeof cache);
                expect_ignored("zeroed", &p, &cache, boolean);
                /* random bytes */
                for (size_t k = 0; k < sizeof cache; k++)
                    ((unsigned char *)&cache)[k] = (unsigned char)tu_uniform_int(&rng, 256);
                expect_ignored("garbage", &p, &cache, boolean);
                /* the right pair, but NaN, Inf, huge values or a bad count */
                static const double bad[] = {NAN, INFINITY, -INFINITY, 1e300};
                for (int b = 0; b < 4; b++)
                    for (int field = 0; field < 4; field++) {
                        fill(&p, &cache);
                        cache.flags = AGJK_CACHE_FLAT; /* the points are read */
                        if (field == 0) cache.point_a[0].y = bad[b];
                        if (field == 1) cache.point_b[cache.count - 1].z = bad[b];
                        if (field == 2) cache.direction.x = bad[b];
                        if (field == 3) cache.direction_prev.z = bad[b];
                        expect_ignored("bad value", &p, &cache, boolean);
                    }
                /* the right pair, a point edited within range (by one ulp, or
                 * moved far off the shapes): the check value catches it */
                for (int e = 0; e < 2; e++) {
                    fill(&p, &cache);
                    cache.flags = AGJK_CACHE_FLAT;
                    agjk_vec3 *pt = &cache.point_b[cache.count - 1];
                    pt->x = e == 0 ? nextafter(pt->x, INFINITY) : pt->x - 3.0 * p.size;
                    expect_ignored("edited point", &p, &cache, boolean);
                }
                static const int32_t counts[] = {-1, 5, INT32_MIN, 1 << 30};
                for (int c = 0; c < 4; c++) {
                    fill(&p, &cache);
                    cache.count = counts[c];
                    expect_ignored("bad count", &p, &cache, boolean);
                }
                fill(&p, &cache);
                cache.struct_size = (uint32_t)sizeof cache - 8;
                expect_ignored("wrong struct_size", &p, &cache, boolean);
            }
}
END_TEST

/* A cache of the same pair from a far-away pose, or holding points moved off
 * the shapes in ways the consistency check sees: still certified answers. */
START_TEST(stale) {
    tu_rng rng;
    int flat_cases = 0;
    tu_rng_seed(&rng, 77);
    for (int kind = 0; kind < 3; kind++)
        for (int trial = 0; trial < 30; trial++) {
            pair p;
            int tries = 0;
            while (make_pair(&rng, kind, &p) != 0) TU_CHECK(++tries < 100);
            agjk_cache cache;
            agjk_result cold, warm;
            /* filled at a random other pose: overlapping, far, very far (1e10
             * sizes: the cached points' recovery in B's frame then rounds by
             * far more than B's thickness), or under a rotation orthonormal
             * only to 5e-7 per entry (accepted: R^T then inverts it only
             * that well) */
            pair far = p;
            int variant = trial % 4;
            far.pb = tu_random_pose(&rng, variant == 1 ? 0.05 : 3.0);
            if (variant == 2) far.pb.translation = tu_scale(far.pb.translation, 1e10 * p.size);
            if (variant == 3)
                for (int r = 0; r < 3; r++)
                    for (int c = 0; c < 3; c++) far.pb.rotation[r][c] *= 1.0 + (r == c ? 5e-7 : -3e-7);
            fill(&far, &cache);
            for (int flat = 0; flat < 2; flat++) {
                agjk_cache c = cache;
                /* the simplex path, or (curved shapes) the direction path */
                c.flags = flat ? c.flags | AGJK_CACHE_FLAT : c.flags & ~AGJK_CACHE_FLAT;
                agjk_distance(&p.a, &p.pa, &p.b, &p.pb, NULL, &cold);
                agjk_distance_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, &c, &warm);
                check_answer("stale", &p, &p.pa, &p.pb, &cold, &warm, 0, 0);
                agjk_collide(&p.a, &p.pa, &p.b, &p.pb, NULL, &cold);
                c = cache;
                c.flags = flat ? c.flags | AGJK_CACHE_FLAT : c.flags & ~AGJK_CACHE_FLAT;
                agjk_collide_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, &c, &warm);
                check_answer("stale collide", &p, &p.pa, &p.pb, &cold, &warm, 1, 0);
            }
            /* Cached points moved off the shapes by hand (they could fake an
             * overlap): the check value no longer matches, the cache is ignored. */
            fill(&p, &cache);
            cache.flags |= AGJK_CACHE_FLAT;
            agjk_vec3 toward = tu_sub(p.pb.translation, p.pa.translation);
            for (int i = 0; i < cache.count; i++) {
                agjk_vec3 local = tu_vec(tu_dot(toward, tu_vec(p.pa.rotation[0][0], p.pa.rotation[1][0], p.pa.rotation[2][0])),
                                         tu_dot(toward, tu_vec(p.pa.rotation[0][1], p.pa.rotation[1][1], p.pa.rotation[2][1])),
                                         tu_dot(toward, tu_vec(p.pa.rotation[0][2], p.pa.rotation[1][2], p.pa.rotation[2][2])));
                cache.point_a[i] = tu_add(cache.point_a[i], tu_scale(local, 3.0));
            }
            expect_ignored("points moved off the shape", &p, &cache, trial % 2);
            /* Shape data changed in place behind the same pointer (which the
             * check value cannot see; agjk_cache_init is documented for it):
             * a box or ellipsoid that shrank leaves cached points outside it,
             * in front of the new surface, where the first support plane cuts
             * them off. The answers stay certified. */
            if (kind == 1) {
                fill(&p, &cache);
                for (int k = 0; k < 3; k++) p.ra.p[k] *= 0.8;
                TU_CHECK(ref_make_agjk(&p.ra, &p.a) == AGJK_STATUS_OK);
                agjk_distance(&p.a, &p.pa, &p.b, &p.pb, NULL, &cold);
                agjk_distance_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, &cache, &warm);
                check_answer("box shrunk in place", &p, &p.pa, &p.pb, &cold, &warm, 0, 0);
                flat_cases += (cache.flags & AGJK_CACHE_FLAT) != 0;
            }
        }
    TU_ENSURE(flat_cases >= 20, "only %d box pairs used the cached simplex", flat_cases);
}
END_TEST

/* Overlapping shapes: an unchanged pose is answered by one support call
 * (the cached tetrahedron still holds the origin). */
START_TEST(enclosed) {
    tu_rng rng;
    tu_rng_seed(&rng, 5);
    for (int kind = 0; kind < 3; kind++)
        for (int trial = 0; trial < 20; trial++) {
            pair p;
            int tries = 0;
            while (make_pair(&rng, kind, &p) != 0) TU_CHECK(++tries < 100);
            tu_pose_translate(&p.pb, tu_scale(p.slide, -0.2 * p.size));
            agjk_cache cache;
            agjk_result r1, r2;
            agjk_cache_init(&cache);
            agjk_distance_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, &cache, &r1);
            if (r1.status != AGJK_STATUS_INTERSECTING) continue;
            TU_CHECK_INT_EQ(cache.count, 4);
            agjk_distance_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, &cache, &r2);
            TU_CHECK_INT_EQ(r2.status, AGJK_STATUS_INTERSECTING);
            TU_CHECK_INT_EQ(r2.support_calls, 1);
        }
}
END_TEST

/* A cached tetrahedron (or face) that stops holding the origin by a hair:
 * B slides out of a shallow overlap in steps down to 1e-9 of the size, each
 * query warm-started from the one before, and every answer is judged. The
 * cache's interior test (cache.c) must hand the cases near its margins to
 * the exact projection, never claim an enclosure that is not there. */
START_TEST(leaving_the_cached_simplex) {
    tu_rng rng;
    tu_rng_seed(&rng, 77);
    int enclosed_then_not = 0;
    for (int kind = 0; kind < 3; kind++)
        for (int trial = 0; trial < 10; trial++) {
            pair p;
            int tries = 0;
            while (make_pair(&rng, kind, &p) != 0) TU_CHECK(++tries < 100);
            agjk_cache cache;
            agjk_cache_init(&cache);
            agjk_pose pb0 = p.pb;
            int was_enclosed = 0;
            for (int i = 0; i < 40; i++) {
                /* Overlap depth from 1e-2 to 1e-9 of the size, then the same apart. */
                double e = 1e-2 * pow(1e-7, (i % 20) / 19.0) * (i < 20 ? -1.0 : 1.0);
                agjk_pose pb = pb0;
                agjk_result cold, warm;
                char what[96];
                if (tu_set_distance(&p.ra, &p.pa, &p.rb, &pb, e * p.size, NULL) != 0) continue;
                agjk_distance(&p.a, &p.pa, &p.b, &pb, NULL, &cold);
                agjk_distance_cached(&p.a, &p.pa, &p.b, &pb, NULL, &cache, &warm);
                snprintf(what, sizeof what, "kind %d trial %d step %d (offset %.3g)", kind,
                         trial, i, e);
                check_answer(what, &p, &p.pa, &pb, &cold, &warm, 0, 0);
                if (warm.status == AGJK_STATUS_INTERSECTING) was_enclosed = 1;
                else if (was_enclosed) ++enclosed_then_not, was_enclosed = 0;
            }
        }
    TU_ENSURE(enclosed_then_not >= 10, "only %d runs left an overlap", enclosed_then_not);
}
END_TEST

static void lying_support(const void *data, const agjk_vec3 *d, agjk_vec3 *out, int *hint) {
    (void)data;
    (void)d;
    (void)hint;
    out->x = out->y = out->z = NAN;
}

START_TEST(invalid_input_empties) {
    tu_rng rng;
    tu_rng_seed(&rng, 6);
    pair p;
    int tries = 0;
    while (make_pair(&rng, 0, &p) != 0) TU_CHECK(++tries < 100);
    agjk_cache cache;
    agjk_result r;
    fill(&p, &cache);
    TU_CHECK_INT_EQ(agjk_distance_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, &cache, NULL),
                    AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(cache.count, 0);
    fill(&p, &cache);
    agjk_shape bad = p.b;
    bad.support = lying_support;
    TU_CHECK_INT_EQ(agjk_collide_cached(&p.a, &p.pa, &bad, &p.pb, NULL, &cache, &r),
                    AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(cache.count, 0);
    TU_CHECK(finite_result(&r));
    /* NULL cache: exactly the uncached query */
    agjk_result a, b;
    agjk_distance(&p.a, &p.pa, &p.b, &p.pb, NULL, &a);
    agjk_distance_cached(&p.a, &p.pa, &p.b, &p.pb, NULL, NULL, &b);
    TU_CHECK(memcmp(&a, &b, sizeof a) == 0);
    /* init */
    memset(&cache, 0xab, sizeof cache);
    agjk_cache_init(&cache);
    TU_CHECK_INT_EQ(cache.struct_size, sizeof cache);
    TU_CHECK_INT_EQ(cache.count, 0);
    memset(&cache, 0xab, sizeof cache);
    agjk_cache_init_sized(&cache, sizeof cache - 1);
    TU_CHECK_INT_EQ(cache.count, (int32_t)0xabababab);
    agjk_cache_init_sized(NULL, sizeof cache);
}
END_TEST

int main(void) {
    Suite *s = suite_create("cache");
    TU_ADD(s, trajectories);
    TU_ADD(s, foreign_and_garbage);
    TU_ADD(s, stale);
    TU_ADD(s, enclosed);
    TU_ADD(s, leaving_the_cached_simplex);
    TU_ADD(s, invalid_input_empties);
    return tu_run_suite(s);
}
