/* SPDX-License-Identifier: MIT */
/* Warm start for coherent queries (include/agjk/cache.h), in the spirit of
 * Box2D's simplex cache (Catto, b2ShapeCast/b2Distance): the previous final
 * simplex is kept as points of A and of B in their local frames, which do not
 * depend on the poses, and moved with the new poses to start the next query.
 *
 * Safety: a cache is used only for the pair that filled it and only when every
 * value in it is finite and in range; during the query each support plane is
 * checked against the cached points (agjk__warm_consistent), and a point cut
 * off by one drops them all: the query goes on from that support (solver.c). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "agjk/cache.h"
#include "cache.h"
#include "query_setup.h"
#include "simplex.h"

void agjk_cache_init_sized(agjk_cache *cache, size_t struct_size) {
    if (!cache || struct_size < sizeof(agjk_cache)) return;
    memset(cache, 0, sizeof *cache);
    cache->struct_size = (uint32_t)sizeof *cache;
}

/* Curved shapes: the first direction is the last iterate's, extrapolated
 * linearly from the query before (smooth motion turns the contact normal
 * steadily), with a length of `weight` times the last distance: the momentum
 * of the default method (Nesterov from the start for a given x_0,
 * direction.c) then keeps the directions near it for a few iterations,
 * probing around it, instead of zig-zagging as plain GJK steps do. The
 * slower the normal turns (|n_1 - n_0| between the last two queries), the
 * better the extrapolation and the more it is trusted: weight =
 * CACHE_TURN_TRUST / |n_1 - n_0| within [10, 1000], CACHE_DIRECTION_WEIGHT
 * without a query before. Measured on the coherent-motion benchmark
 * (ellipsoids, support calls per query, slow / fast motion): a fixed weight
 * of 30: 3.5 / 3.0, 100: 1.9 / 3.1, 200: 1.5 / 3.6, 1000: 2.1 / 4.5; from
 * the turn with 0.02: 3.9 / 3.5, 0.05: 2.5 / 3.1, 0.1: 1.9 / 2.9, 0.5: 1.7 /
 * 3.5 (with the Polyak phase first, as before: a fixed 100 gave 3.0 / 2.8,
 * 0.1 from the turn 2.8 / 3.5). */
#define CACHE_DIRECTION_WEIGHT 100.0
#define CACHE_TURN_TRUST 0.1

/* A check value of the cached simplex (its count and its points: what the
 * answer's certificates rest on), so that garbage or hand-edited memory is
 * not mistaken for a simplex of the pair (not a defence against a deliberate
 * forger, who could as well corrupt the shapes). The directions, hints and
 * flags only choose where the query starts: any finite value of them gives
 * the same certified answer, so they are checked for range only, and a warm
 * query that ends on the simplex it started from (the usual end on flat
 * shapes) keeps the check value as it is. FNV-1a steps over 64-bit words in
 * three independent lanes, one per coordinate, so that the multiplications
 * overlap (one chain of them was a tenth of a warm query's time on boxes).
 * Every step is a bijection of its lane, so an edit of any one word always
 * changes the value. The pair's pointers are left out: they are compared
 * with the query's own. The words go in a fixed order (count, then the count
 * points of A and B), mixed in by load and save within the loops that read
 * or write the points anyway. */
#define CHECK_PRIME 0x100000001b3u

static uint64_t bits(double v) {
    uint64_t w;
    memcpy(&w, &v, sizeof w);
    return w;
}

/* The three lanes, a value (kept in registers through the loops). */
typedef struct check_lanes {
    uint64_t x, y, z;
} check_lanes;

static inline check_lanes mix_vec(check_lanes h, agjk_vec3 v) {
    h.x = (h.x ^ bits(v.x)) * CHECK_PRIME;
    h.y = (h.y ^ bits(v.y)) * CHECK_PRIME;
    h.z = (h.z ^ bits(v.z)) * CHECK_PRIME;
    return h;
}

/* The words of the count and of the points' error bound. */
static inline check_lanes check_begin(const agjk_cache *c) {
    check_lanes h;
    h.x = (0xcbf29ce484222325u ^ (uint32_t)c->count) * CHECK_PRIME;
    h.y = (0x84222325cbf29ce4u ^ bits(c->point_error)) * CHECK_PRIME;
    h.z = 0x2325cbf29ce48422u;
    return h;
}

/* The three lanes folded into one value. */
static inline uint64_t check_end(check_lanes h) {
    return (h.x ^ (h.y * CHECK_PRIME)) * CHECK_PRIME ^ h.z;
}

/* Whether the cache was filled for the pair (a, b), with a count in 0..4
 * (its content is checked against the check value while it is read). */
static int cache_of_pair(const agjk_cache *c, const agjk_shape *a, const agjk_shape *b) {
    return c->struct_size == sizeof *c && c->count >= 0 && c->count <= 4 &&
           c->support_a == a->support && c->data_a == a->data && c->support_b == b->support &&
           c->data_b == b->data;
}

/* Finite and within AGJK_MAX_COORDINATE, for a sum of absolute coordinates
 * (NaN and Inf propagate into it; a sum out of range only means a cold
 * start). */
static int sum_in_range(double sum) { return sum <= AGJK_MAX_COORDINATE; }

/* The cached simplex is the last query's final one, every vertex with a
 * positive weight; after a small motion the origin usually still projects
 * into its interior (or, 4 points, lies inside it). Then the answer follows
 * from one small linear system, checked with margins far above its rounding
 * (relative weights above 1e-6 with a determinant above 1e-6 of its scale,
 * where the rounding of a weight is below 1e-9); otherwise, and for 1 point,
 * agjk__simplex_project_gjk decides. Returns its mask, or 0 (undecided). */
#define INSIDE_MARGIN 1e-6
static unsigned project_interior(const agjk_vec3 *w, int n, double lambda[4], agjk_vec3 *x) {
    if (n == 2) {
        agjk_vec3 e = v3_sub(w[1], w[0]);
        double ee = v3_norm2(e), t = -v3_dot(w[0], e);
        if (!(t > INSIDE_MARGIN * ee && ee - t > INSIDE_MARGIN * ee)) return 0;
        lambda[1] = t / ee;
        lambda[0] = 1.0 - lambda[1];
        *x = v3_lerp2(w[0], lambda[0], w[1], lambda[1]);
        return 0x3u;
    }
    if (n == 3) {
        agjk_vec3 e1 = v3_sub(w[1], w[0]), e2 = v3_sub(w[2], w[0]);
        double a11 = v3_norm2(e1), a12 = v3_dot(e1, e2), a22 = v3_norm2(e2);
        double b1 = -v3_dot(w[0], e1), b2 = -v3_dot(w[0], e2);
        double det = a11 * a22 - a12 * a12;
        if (!(det > INSIDE_MARGIN * a11 * a22)) return 0;
        double l1 = b1 * a22 - b2 * a12, l2 = a11 * b2 - a12 * b1, m = INSIDE_MARGIN * det;
        if (!(l1 > m && l2 > m && det - l1 - l2 > m)) return 0;
        double inv = 1.0 / det;
        lambda[1] = l1 * inv;
        lambda[2] = l2 * inv;
        lambda[0] = 1.0 - lambda[1] - lambda[2];
        /* The foot itself from the plane's normal n: n <n, w_0> / |n|^2, as
         * the GJK projection's face case forms it (accurate when the foot is
         * much nearer the origin than the points), and without waiting for
         * the weights: the warm query's first steps all wait for x. */
        agjk_vec3 nrm = v3_cross(e1, e2);
        *x = v3_scale(nrm, v3_dot(nrm, w[0]) / v3_norm2(nrm));
        return 0x7u;
    }
    if (n == 4) {
        /* Weights of the origin: ratios of signed volumes. */
        agjk_vec3 e1 = v3_sub(w[1], w[0]), e2 = v3_sub(w[2], w[0]), e3 = v3_sub(w[3], w[0]);
        agjk_vec3 c23 = v3_cross(e2, e3);
        double vol = v3_dot(e1, c23);
        double scale = v3_norm(e1) * v3_norm(e2) * v3_norm(e3);
        if (vol < 0.0) vol = -vol, scale = -scale; /* orientation: positive weights */
        if (!(vol > INSIDE_MARGIN * (scale < 0.0 ? -scale : scale))) return 0;
        double sg = scale < 0.0 ? -1.0 : 1.0;
        agjk_vec3 o = v3_neg(w[0]);
        double l1 = sg * v3_dot(o, c23);
        double l2 = sg * v3_dot(e1, v3_cross(o, e3));
        double l3 = sg * v3_dot(e1, v3_cross(e2, o));
        double m = INSIDE_MARGIN * vol;
        if (!(l1 > m && l2 > m && l3 > m && vol - l1 - l2 - l3 > m)) return 0;
        lambda[1] = l1 / vol;
        lambda[2] = l2 / vol;
        lambda[3] = l3 / vol;
        lambda[0] = 1.0 - lambda[1] - lambda[2] - lambda[3];
        *x = v3(0.0, 0.0, 0.0);
        return 0xFu;
    }
    return 0;
}

/* a's length, and its unit vector in *unit (a non-zero and in range): one
 * square root and one division but for tiny vectors, whose squares would
 * lose bits (those go through unit max-norm). */
static double length_and_unit(agjk_vec3 a, agjk_vec3 *unit) {
    double n2 = v3_norm2(a);
    if (n2 >= 0x1p-900) {
        double n = sqrt(n2);
        *unit = v3_scale(a, 1.0 / n);
        return n;
    }
    double m = v3_maxabs(a);
    agjk_vec3 b = v3_div(a, m);
    double n = v3_norm(b);
    *unit = v3_scale(b, 1.0 / n);
    return m * n;
}

/* The start from the cache's direction alone (curved shapes, or a simplex
 * that cannot serve): x_0 = weight ||n_1|| p, p the unit vector along
 * 2 n_1 - n_0 (the last two directions, unit, extrapolated linearly), or n_1
 * itself after a jump rather than a steady turn (<p, n_1> <= 1/2), with the
 * weight of CACHE_DIRECTION_WEIGHT's comment. With t = |n_1 - n_0| and
 * q = 2 n_1 - n_0,
 * weight / |q| = CACHE_TURN_TRUST / sqrt(t^2 |q|^2): three square roots and
 * three divisions in all, two of each side by side. */
static int load_direction(const agjk_cache *cache, agjk__solve_input *in, int has_direction) {
    if (!has_direction) return 1;
    agjk_vec3 n1, n0, d1 = cache->direction, d0 = cache->direction_prev;
    double length = length_and_unit(d1, &n1);
    agjk_vec3 x0 = v3_scale(n1, CACHE_DIRECTION_WEIGHT * length);
    /* The first support is taken along d_1, or along |d_0| (2 n_1 - n_0)
     * |d_1| = 2 |d_0| d_1 - |d_1| d_0 (the norms of the directions as
     * length_and_unit takes them, no division): it need not wait for the
     * unit vectors and the weight (on moving ellipsoids, 5% of a warm
     * query's time). */
    agjk_vec3 along = d1;
    if (v3_maxabs(d0) > 0.0) {
        double length0 = length_and_unit(d0, &n0);
        double t2 = v3_norm2(v3_sub(n1, n0));
        agjk_vec3 q = v3_sub(v3_scale(n1, 2.0), n0); /* |q| >= 1 */
        double qq = v3_norm2(q), qn = v3_dot(q, n1);
        /* weight = CACHE_TURN_TRUST / t within [10, 1000] */
        int slow = t2 * 1e6 <= CACHE_TURN_TRUST * CACHE_TURN_TRUST,
            fast = t2 * 1e2 >= CACHE_TURN_TRUST * CACHE_TURN_TRUST;
        if (qn > 0.0 && 4.0 * qn * qn > qq) {
            double f = slow ? 1000.0 / sqrt(qq)
                       : fast ? 10.0 / sqrt(qq)
                              : CACHE_TURN_TRUST / sqrt(t2 * qq);
            x0 = v3_scale(q, f * length);
            along = v3_sub(v3_scale(d1, 2.0 * length0), v3_scale(d0, length));
        } else {
            double weight = slow ? 1000.0 : fast ? 10.0 : CACHE_TURN_TRUST / sqrt(t2);
            x0 = v3_scale(n1, weight * length);
        }
    }
    if (v3_maxabs(x0) > 0.0) {
        in->x0 = x0;
        in->x0_given = 1;
        in->x0_unit = 0.0;
        /* (Far out of range, the product of two norms: x_0 itself then.) */
        double m = v3_maxabs(along);
        in->along = along;
        in->x0_along = m >= 0x1p-900 && m <= 0x1p900;
    }
    return 1;
}

int agjk__cache_load(const agjk_cache *cache, const agjk_shape *a, const agjk_shape *b,
                     agjk__minkowski *md, agjk__solve_input *in) {
    in->warm_count = 0;
    if (!cache || !cache_of_pair(cache, a, b)) return 0;
    int n = cache->count;
    /* Which start the cache gives, decided from its raw content (nothing is
     * used before the check value has matched). */
    int has_direction = v3_maxabs(cache->direction) > 0.0;
    int simplex = n > 0 && in->method != AGJK_METHOD_FRANK_WOLFE &&
                  ((cache->flags & AGJK_CACHE_FLAT) || n == 4 || !has_direction);
    /* One pass over the points: their check words, their size, and for the
     * simplex start their place under md's poses (A's frame is A's local
     * frame; B's points move with the relative pose). */
    check_lanes h = check_begin(cache);
    double size = 0.0, magnitude = 0.0;
    agjk_vec3 w[4];
    for (int i = 0; i < n; ++i) {
        agjk_vec3 pa = cache->point_a[i], pb = cache->point_b[i];
        h = mix_vec(mix_vec(h, pa), pb);
        if (!simplex) continue;
        size += v3_norm1(pa) + v3_norm1(pb);
        double m = v3_maxabs(pa) + v3_maxabs(pb);
        if (m > magnitude) magnitude = m;
        agjk__vertex *v = &in->warm[i];
        v->a = pa;
        v->b = v3_add(m3_mul(&md->rotation[0][0], pb), md->translation);
        v->w = w[i] = v3_sub(pa, v->b);
    }
    if (cache->check != check_end(h) ||
        !sum_in_range(v3_norm1(cache->direction) + v3_norm1(cache->direction_prev)) ||
        !(cache->point_error >= 0.0 && cache->point_error <= AGJK_MAX_COORDINATE))
        return 0;
    md->hint_a = cache->hint_a;
    md->hint_b = cache->hint_b;
    if (n == 0 && !has_direction) return 0;
    /* A direction only (Frank-Wolfe's active set is its iterate alone). */
    if (!simplex) return load_direction(cache, in, has_direction);
    if (!sum_in_range(size)) return 0;
    /* The cached points of B lie within point_error of B (save): the rounding
     * allowances of this query, multiples of md->noise, must cover that
     * (md->scale is still 1 here: caller's units are solver units). Up to
     * about 16 times the rounding of fresh points (4 eps times the problem's
     * size, here over-estimated by the points' summed 1-norms) that costs
     * nothing that matters; a cache filled far from the origin, or under a
     * rotation far less orthonormal than double precision, carries more, and
     * would make this query less precise than a cold one: then only its
     * direction serves. */
    if (cache->point_error > 64.0 * DBL_EPSILON * (md->translation_size + size)) {
        return load_direction(cache, in, has_direction);
    }
    md->noise_floor = cache->point_error;
    /* The cached points are points of this query: their size counts in its
     * rounding scale (and in the scale of its units, agjk__minkowski_set_scale)
     * as that of any support point (the measure of agjk__minkowski_support). */
    agjk__minkowski_grow(md, magnitude > md->magnitude ? magnitude : md->magnitude);
    agjk_vec3 x;
    unsigned mask = project_interior(w, n, in->warm_lambda, &x);
    if (!mask) mask = agjk__simplex_project_gjk(w, n, in->warm_lambda, &x);
    in->warm_mask = mask;
    in->warm_x = x;
    /* The first support goes in direction x, the projection; when the points
     * enclose the origin (x = 0), in the last direction instead. */
    if (mask == 0xFu || v3_maxabs(x) == 0.0) x = cache->direction;
    if (v3_maxabs(x) == 0.0) x = v3(1.0, 0.0, 0.0);
    in->x0 = x;
    in->x0_unit = 0.0;
    in->warm_count = n;
    return 1;
}

/* How far R^T R is from the identity (R: B's frame -> A's frame, the
 * product of the two poses' rotations, each orthonormal only to within a
 * few 1e-6): the largest |(R^T R - I)_ij|. R^T then inverts R only to within it. */
static double rotation_skew(const double *r) {
    agjk_vec3 c0 = v3(r[0], r[3], r[6]), c1 = v3(r[1], r[4], r[7]), c2 = v3(r[2], r[5], r[8]);
    double e[6] = {v3_norm2(c0) - 1.0, v3_norm2(c1) - 1.0, v3_norm2(c2) - 1.0,
                   v3_dot(c0, c1),     v3_dot(c0, c2),     v3_dot(c1, c2)};
    double m = 0.0;
    for (int i = 0; i < 6; ++i) m = fabs(e[i]) > m ? fabs(e[i]) : m;
    return m;
}

/* A bound on how far pb = R^T (b - t), computed, lies from the local point
 * p of B with b = R p + t computed (solver units): (R^T R - I) p, at most
 * skew |p|_1 (p within a hair of pb), plus the rounding of the forward
 * transform, of b - t and of the product with R^T, each a few eps of
 * |p|_1, |b|_1 and |t|_1. Twice the first-order terms, for margin: far
 * from the origin (|t| much larger than B) this is what a cache filled
 * there carries to every later pose. */
static double point_error_of(agjk_vec3 pb, agjk_vec3 b, agjk_vec3 t, double skew) {
    double p1 = v3_norm1(pb), t1 = v3_norm1(t);
    return 2.0 * skew * p1 + 16.0 * DBL_EPSILON * (p1 + v3_norm1(b) + 2.0 * t1);
}

/* Rounding of a scaling by a power of two whose result is subnormal. */
#define SUBNORMAL_ROUNDING 0x1p-1070

/* Whether vertex v is, bit for bit, the warm-start vertex u that load placed
 * from the cache's own local points. */
static int same_vertex(const agjk__vertex *v, const agjk__vertex *u) {
    return v->a.x == u->a.x && v->a.y == u->a.y && v->a.z == u->a.z && v->b.x == u->b.x &&
           v->b.y == u->b.y && v->b.z == u->b.z;
}

void agjk__cache_save(agjk_cache *cache, const agjk_shape *a, const agjk_shape *b,
                      const agjk__minkowski *md, const agjk__solve_input *in,
                      const agjk__solve_output *out) {
    /* The last direction becomes the one before, if the cache was this pair's. */
    agjk_vec3 before = v3(0.0, 0.0, 0.0);
    uint32_t flags_before = 0;
    if (cache_of_pair(cache, a, b) && v3_in_range(cache->direction)) {
        before = cache->direction;
        flags_before = cache->flags;
    }
    /* To the caller's units by inv, a power of two (exact), 1 for problems of
     * ordinary size (the warm start's case). */
    double inv = md->scale == 1.0 ? 1.0 : 1.0 / md->scale;
    agjk_vec3 x = v3_scale(out->x, inv);
    cache->struct_size = (uint32_t)sizeof *cache;
    cache->count = 0;
    for (int i = 0; i < 3; ++i) cache->reserved[i] = 0.0;
    if (!v3_in_range(x)) return;
    cache->direction_prev = before;
    cache->flags = out->flat || (flags_before & AGJK_CACHE_FLAT) ? AGJK_CACHE_FLAT : 0u;
    cache->support_a = a->support;
    cache->support_b = b->support;
    cache->data_a = a->data;
    cache->data_b = b->data;
    cache->hint_a = md->hint_a;
    cache->hint_b = md->hint_b;
    cache->direction = x;
    /* The normal of the plane that certified x (or separated the shapes), when
     * it is not x's own, is the better estimate of x*'s direction (solver.c),
     * with the length ||x||: one square root of a ratio of squares, both in
     * solver units (in range, squares finite), then to the caller's units. A
     * Boolean query that stopped on its first support has no point of D yet
     * (x is x_0): it keeps the previous length. */
    double dn2 = v3_norm2(out->direction);
    if (dn2 > 0.0) {
        double f = out->simplex_count == 0 && v3_maxabs(before) > 0.0
                       ? v3_norm(before) / sqrt(dn2)
                       : sqrt(v3_norm2(out->x) / dn2) * inv;
        cache->direction = v3_scale(out->direction, f);
    }
    int n = out->simplex_count < 0 ? 0 : out->simplex_count > 4 ? 4 : out->simplex_count;
    /* Curved shapes (no vertex met twice): unless it encloses the origin, the
     * next query starts from the direction alone (agjk__cache_load), so the
     * simplex is not kept and its points are not recovered (fast motion on
     * ellipsoids: 293 -> 277 ns per warm query). */
    if (!(cache->flags & AGJK_CACHE_FLAT) && n < 4 && v3_maxabs(cache->direction) > 0.0) n = 0;
    /* Back to B's local frame: R^T (b - t) (rounding of a few ulps, within the
     * tolerance warm_consistent allows, solver.c); but a vertex the solver
     * kept from the warm start in its place (the usual end of a coherent
     * query on flat shapes) came from the local points at that place in the
     * cache, which stay (exact, and no rotation). When all of them stayed,
     * with the count, so does the check value load verified. */
    cache->count = n;
    if (n > 0 && out->warm_kept) return; /* (inv is 1 then: x_0 was used as given) */
    int kept = inv == 1.0 ? in->warm_count : 0;
    unsigned same = 0;
    for (int i = 0; i < n && i < kept; ++i)
        if (same_vertex(&out->simplex[i], &in->warm[i])) same |= 1u << i;
    if (kept > 0 && n == kept && same == (1u << n) - 1u) return;
    /* Points kept keep their bound; the others get the bound of their
     * recovery (point_error_of). */
    double error = same ? cache->point_error : 0.0;
    double skew = same == (1u << n) - 1u ? 0.0 : rotation_skew(&md->rotation[0][0]);
    for (int i = 0; i < n; ++i) {
        if (same & (1u << i)) continue;
        agjk_vec3 pa = out->simplex[i].a;
        agjk_vec3 pb = m3_tmul(&md->rotation[0][0], v3_sub(out->simplex[i].b, md->translation));
        double e = point_error_of(pb, out->simplex[i].b, md->translation, skew) * inv;
        if (inv != 1.0) {
            pa = v3_scale(pa, inv);
            pb = v3_scale(pb, inv);
            e += SUBNORMAL_ROUNDING; /* the scaling back rounds among subnormals */
        }
        cache->point_a[i] = pa;
        cache->point_b[i] = pb;
        if (e > error) error = e;
    }
    cache->point_error = error;
    check_lanes h = check_begin(cache);
    for (int i = 0; i < n; ++i) h = mix_vec(mix_vec(h, cache->point_a[i]), cache->point_b[i]);
    cache->check = check_end(h);
}

/* The warm-started queries of agjk/cache.h: the common query (query.c) with
 * this file's load and save, so that a program that never calls them links
 * no cache code. */
static void cache_reset(agjk_cache *cache) { agjk_cache_init(cache); }

static const agjk__warm_hooks cache_hooks = {agjk__cache_load, agjk__cache_save, cache_reset};

/* Either cached query; an invalid input leaves the cache cleared, as a
 * stale cache must not outlive a query that could not use it. */
static agjk_status cached_query(const agjk_shape *a, const agjk_pose *pose_a,
                                const agjk_shape *b, const agjk_pose *pose_b,
                                const agjk_options *options, agjk_cache *cache,
                                agjk_result *result, int boolean_mode) {
    agjk_status status = agjk__query_run(a, pose_a, b, pose_b, options, result, boolean_mode,
                                         cache, &cache_hooks);
    if (status == AGJK_STATUS_INVALID_INPUT && cache) agjk_cache_init(cache);
    return status;
}

agjk_status agjk_distance_cached(const agjk_shape *a, const agjk_pose *pose_a,
                                 const agjk_shape *b, const agjk_pose *pose_b,
                                 const agjk_options *options, agjk_cache *cache,
                                 agjk_result *result) {
    return cached_query(a, pose_a, b, pose_b, options, cache, result, 0);
}

agjk_status agjk_collide_cached(const agjk_shape *a, const agjk_pose *pose_a,
                                const agjk_shape *b, const agjk_pose *pose_b,
                                const agjk_options *options, agjk_cache *cache,
                                agjk_result *result) {
    return cached_query(a, pose_a, b, pose_b, options, cache, result, 1);
}
