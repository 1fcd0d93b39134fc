/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the query API with shapes, poses and options decoded from
 * bytes (tests/fuzz/fuzz_decode.h). Any invariant violation aborts. Built with
 * clang -fsanitize=fuzzer,address,undefined by `make fuzz`; the inputs in
 * tests/fuzz/regressions/query are replayed by `make check` (replay.c). */
#include "fuzz_decode.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FZ_MAX_VERTS 40

typedef struct fz_shape {
    agjk_shape shape;
    agjk_ellipsoid ellipsoid;
    agjk_box box;
    agjk_capsule capsule;
    agjk_cylinder cylinder;
    agjk_cone cone;
    agjk_polytope polytope;
    agjk_prepared_polytope prepared;
    agjk_vec3 vertices[FZ_MAX_VERTS];
    int32_t offsets[FZ_MAX_VERTS + 1];
    int32_t neighbors[4 * FZ_MAX_VERTS];
    int valid; /* the constructor accepted it */
    int kind;
} fz_shape;

static void decode_shape(fuzz_reader *r, fz_shape *s) {
    uint8_t kind = fz_u8(r) % 9;
    agjk_status st = AGJK_STATUS_INVALID_INPUT;
    double p0 = fz_double(r), p1 = fz_double(r), p2 = fz_double(r);
    memset(s, 0, sizeof *s);
    switch (kind) {
    case 0: st = agjk_shape_point(&s->shape); break;
    case 1: st = agjk_shape_sphere(&s->shape, p0); break;
    case 2:
        s->ellipsoid.radii.x = p0; s->ellipsoid.radii.y = p1; s->ellipsoid.radii.z = p2;
        st = agjk_shape_ellipsoid(&s->shape, &s->ellipsoid);
        break;
    case 3:
        s->box.half_extents.x = p0; s->box.half_extents.y = p1; s->box.half_extents.z = p2;
        st = agjk_shape_box(&s->shape, &s->box);
        break;
    case 4:
        s->capsule.radius = p0; s->capsule.half_height = p1;
        st = agjk_shape_capsule(&s->shape, &s->capsule);
        break;
    case 5:
        s->cylinder.radius = p0; s->cylinder.half_height = p1;
        st = agjk_shape_cylinder(&s->shape, &s->cylinder);
        break;
    case 6:
        s->cone.radius = p0; s->cone.half_height = p1;
        st = agjk_shape_cone(&s->shape, &s->cone);
        break;
    default: {
        /* A point cloud (kind 7), or one with a fuzzed vertex graph (kind 8):
         * the constructor must reject any malformed graph. */
        int n = fz_u8(r) % (FZ_MAX_VERTS + 1);
        for (int i = 0; i < n; i++) {
            s->vertices[i].x = fz_double(r);
            s->vertices[i].y = fz_double(r);
            s->vertices[i].z = fz_double(r);
        }
        s->polytope.vertices = s->vertices;
        s->polytope.vertex_count = n;
        if (kind == 8 && n > 0) {
            int e = 0;
            s->offsets[0] = 0;
            for (int i = 0; i < n; i++) {
                int deg = fz_u8(r) % 5;
                for (int k = 0; k < deg; k++) {
                    /* Index n (out of range) and -1 are meant to occur. */
                    int32_t idx = (int32_t)(fz_u8(r) % (n + 1));
                    if (fz_u8(r) == 255) idx = -1;
                    s->neighbors[e++] = idx;
                }
                s->offsets[i + 1] = e;
            }
            if (fz_u8(r) == 7) s->offsets[0] = 1;
            s->polytope.neighbor_offsets = s->offsets;
            s->polytope.neighbors = s->neighbors;
        }
        /* Odd vertex counts with adjacency prepared (no input byte spent:
         * the regression inputs keep their meaning). */
        if (kind == 8 && n % 2) {
            st = agjk_polytope_prepare(&s->prepared, &s->polytope);
            if (st == AGJK_STATUS_OK) st = agjk_shape_prepared_polytope(&s->shape, &s->prepared);
        } else {
            st = agjk_shape_polytope(&s->shape, &s->polytope);
        }
        break;
    }
    }
    FUZZ_CHECK(st == AGJK_STATUS_OK || st == AGJK_STATUS_INVALID_INPUT, "constructor status %d", st);
    s->kind = kind;
#ifdef FUZZ_DEBUG
    fprintf(stderr, "shape kind %d params %.17g %.17g %.17g status %d vertices %d\n", kind, p0, p1,
            p2, (int)st, (int)s->polytope.vertex_count);
    for (int i = 0; i < s->polytope.vertex_count; i++)
        fprintf(stderr, "  v %.17g %.17g %.17g\n", s->vertices[i].x, s->vertices[i].y,
                s->vertices[i].z);
#endif
    s->valid = st == AGJK_STATUS_OK;
    if (s->valid && (fz_u8(r) & 1)) {
        double m = fz_double(r);
        agjk_status sm = agjk_shape_set_margin(&s->shape, m);
        FUZZ_CHECK(sm == (m >= 0 && m <= FZ_MAXC ? AGJK_STATUS_OK : AGJK_STATUS_INVALID_INPUT),
                   "set_margin(%g) gave %d", m, sm);
    }
}

/* agjk_signed_distance on the same input: status and fields sane, the
 * interval ordered, consistent with agjk_distance's certified verdict, and
 * (overlap) the depth bound real: h_A(n) + h_B(-n) <= -lower, evaluated
 * through the shapes' own supports. */
static void check_signed(const agjk_shape *a, const agjk_pose *pa, const agjk_shape *b,
                         const agjk_pose *pb, const agjk_options *o, int exact) {
    agjk_signed_result r;
    agjk_result d;
    agjk_status ss = agjk_signed_distance(a, pa, b, pb, o, &r);
    agjk_status sd = agjk_distance(a, pa, b, pb, o, &d);
#ifdef FUZZ_DEBUG
    fprintf(stderr, "signed: %s s %.17g [%.17g, %.17g] n %g %g %g it %d/%d\n",
            agjk_status_string(ss), r.signed_distance, r.lower, r.upper, r.normal.x, r.normal.y,
            r.normal.z, r.gjk_iterations, r.epa_iterations);
#endif
    FUZZ_CHECK(ss == r.status && (unsigned)ss <= AGJK_STATUS_INVALID_INPUT, "signed status %d", ss);
    const double v[12] = {r.signed_distance, r.lower, r.upper, r.normal.x, r.normal.y, r.normal.z,
                          r.witness_a.x, r.witness_a.y, r.witness_a.z, r.witness_b.x,
                          r.witness_b.y, r.witness_b.z};
    for (int i = 0; i < 12; i++) FUZZ_CHECK(isfinite(v[i]), "signed field %d not finite", i);
    if (sd == AGJK_STATUS_INVALID_INPUT && d.support_calls == 0)
        FUZZ_CHECK(ss == AGJK_STATUS_INVALID_INPUT, "distance rejects the input, signed accepts");
    if (ss == AGJK_STATUS_INVALID_INPUT) return;
    FUZZ_CHECK(r.lower <= r.signed_distance && r.signed_distance <= r.upper,
               "signed %.17g outside [%.17g, %.17g]", r.signed_distance, r.lower, r.upper);
    FUZZ_CHECK(r.epa_iterations >= 0 && r.gjk_iterations >= 0 && r.support_calls >= 0, "counters");
    if (ss == AGJK_STATUS_SEPARATED) FUZZ_CHECK(r.lower > 0, "SEPARATED with lower %g", r.lower);
    if (ss == AGJK_STATUS_INTERSECTING) FUZZ_CHECK(r.upper < 0, "INTERSECTING with upper %g", r.upper);
    if (!exact || !a || !b) return;
    double scale = fz_scale(a, pa, b, pb);
    /* plus a few subnormal ulps: the world-frame evaluation below rounds
     * absolutely there */
    double slack = 1e-12 * scale + 16 * 4.9406564584124654e-324;
    if (sd == AGJK_STATUS_SEPARATED)
        FUZZ_CHECK(r.upper >= d.distance - d.bound - slack && r.lower <= d.distance + slack,
                   "signed [%.17g, %.17g] vs distance [%.17g, %.17g]", r.lower, r.upper,
                   d.distance - d.bound, d.distance);
    {
        /* For every n, h_D(n) >= -s (s the signed distance); the lower end
         * of the interval comes from a support value: h_D(normal) <= -lower. */
        agjk_vec3 n = r.normal, m = {-r.normal.x, -r.normal.y, -r.normal.z};
        double h = fz_support_value(a, pa, n) + fz_support_value(b, pb, m);
        /* the world-frame normal carries the rotations' skew (fz_check_pair) */
        double tilt = 8.0 * (fz_rotation_skew(pa) + fz_rotation_skew(pb)) * scale;
#ifdef FUZZ_DEBUG
        fprintf(stderr, "signed: h_A(n) + h_B(-n) = %.17g, -lower = %.17g\n", h, -r.lower);
#endif
        FUZZ_CHECK(h <= -r.lower + slack + tilt, "-lower %.17g below h_D(normal) %.17g (scale %g)",
                   -r.lower, h, scale);
    }
    FUZZ_CHECK(!((ss == AGJK_STATUS_SEPARATED && sd == AGJK_STATUS_INTERSECTING) ||
                 (ss == AGJK_STATUS_INTERSECTING && sd == AGJK_STATUS_SEPARATED)),
               "signed says %s, distance says %s", agjk_status_string(ss), agjk_status_string(sd));
}

/* The warm-start cache: filled by a query at another pose of B (a stale
 * cache), its start fields (directions, hints, flags: outside the check
 * value) possibly overwritten with fuzzed values, then used at the real
 * poses. Whatever it holds, the cached answer is as certified as the cold
 * one: same invalid-input verdict, finite fields, no contradicting verdict,
 * overlapping certified intervals, a well-formed cache afterwards. */
static void check_cached(const agjk_shape *a, const agjk_pose *pa, const agjk_shape *b,
                         const agjk_pose *pb, const agjk_options *o, int exact, fuzz_reader *r) {
    agjk_pose p2;
    fz_pose(r, &p2);
    uint8_t mutate = fz_u8(r);
    for (int boolean = 0; boolean < 2; boolean++) {
        agjk_cache c;
        agjk_result cold, fill, warm;
        agjk_cache_init(&c);
        agjk_status sc = boolean ? agjk_collide(a, pa, b, pb, o, &cold)
                                 : agjk_distance(a, pa, b, pb, o, &cold);
        if (boolean) agjk_collide_cached(a, pa, b, &p2, o, &c, &fill);
        else agjk_distance_cached(a, pa, b, &p2, o, &c, &fill);
        if (mutate & 1) c.direction.x = fz_double(r), c.direction.y = fz_double(r), c.direction.z = fz_double(r);
        if (mutate & 2) c.direction_prev.x = fz_double(r), c.direction_prev.z = fz_double(r);
        if (mutate & 4) c.hint_a = (int32_t)fz_u16(r) - 1000, c.hint_b = (int32_t)fz_u16(r) * 7;
        if (mutate & 8) c.flags = fz_u8(r);
        agjk_status sw = boolean ? agjk_collide_cached(a, pa, b, pb, o, &c, &warm)
                                 : agjk_distance_cached(a, pa, b, pb, o, &c, &warm);
#ifdef FUZZ_DEBUG
        fprintf(stderr, "cached %s: %s d %.17g bound %g it %d (cold %s d %.17g bound %g)\n",
                boolean ? "collide" : "distance", agjk_status_string(sw), warm.distance, warm.bound,
                warm.iterations, agjk_status_string(sc), cold.distance, cold.bound);
#endif
        FUZZ_CHECK(sw == warm.status && (unsigned)sw <= AGJK_STATUS_INVALID_INPUT, "cached status %d", sw);
        FUZZ_CHECK(fz_finite_result(&warm), "cached result not finite");
        if (sc == AGJK_STATUS_INVALID_INPUT && cold.support_calls == 0)
            FUZZ_CHECK(sw == AGJK_STATUS_INVALID_INPUT, "cold rejects the input, cached accepts");
        FUZZ_CHECK(c.struct_size == sizeof c && c.count >= 0 && c.count <= 4, "cache left malformed");
        if (!exact || sw == AGJK_STATUS_INVALID_INPUT || sc == AGJK_STATUS_INVALID_INPUT) continue;
        FUZZ_CHECK(!((sw == AGJK_STATUS_SEPARATED && sc == AGJK_STATUS_INTERSECTING) ||
                     (sw == AGJK_STATUS_INTERSECTING && sc == AGJK_STATUS_SEPARATED)),
                   "cached says %s, cold says %s", agjk_status_string(sw), agjk_status_string(sc));
        if (boolean) continue;
        double scale = fz_scale(a, pa, b, pb);
        double slack = 1e-12 * scale + 16 * 4.9406564584124654e-324;
        FUZZ_CHECK(warm.distance + slack >= cold.distance - cold.bound &&
                       cold.distance + slack >= warm.distance - warm.bound,
                   "cached [%.17g, %.17g] and cold [%.17g, %.17g] apart", warm.distance - warm.bound,
                   warm.distance, cold.distance - cold.bound, cold.distance);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fuzz_reader r = {data, size, 0};
    fz_shape a, b;
    agjk_pose pa, pb;
    agjk_options o;
    decode_shape(&r, &a);
    decode_shape(&r, &b);
    fz_pose(&r, &pa);
    fz_pose(&r, &pb);
    fz_options(&r, &o);
    /* A fuzzed vertex graph that passes the constructor's checks may still
     * not be the hull's edge graph: hill climbing is then inexact (documented
     * in shapes.h), so only the crash/NaN/status invariants apply. */
    int exact = a.kind != 8 && b.kind != 8;
#ifdef FUZZ_DEBUG
    for (int k = 0; k < 2; k++) {
        const agjk_pose *p = k ? &pb : &pa;
        fprintf(stderr, "pose %c t %.17g %.17g %.17g\n", 'a' + k, p->translation.x, p->translation.y,
                p->translation.z);
        for (int i = 0; i < 3; i++)
            fprintf(stderr, "  R %.17g %.17g %.17g\n", p->rotation[i][0], p->rotation[i][1],
                    p->rotation[i][2]);
    }
    fprintf(stderr, "options method %d mode %d tol %g maxit %d compute %u init %d (%g %g %g) margins %g %g\n",
            o.method, o.tolerance_mode, o.tolerance, o.max_iterations, o.compute,
            o.use_initial_direction, o.initial_direction.x, o.initial_direction.y,
            o.initial_direction.z, a.shape.margin, b.shape.margin);
#endif
    const agjk_options *opts = fz_u8(&r) == 1 ? NULL : &o; /* NULL: the defaults */
    const agjk_shape *sa = a.valid ? &a.shape : NULL, *sb = b.valid ? &b.shape : NULL;
    fz_check_pair(sa, &pa, sb, &pb, opts, exact);
    check_signed(sa, &pa, sb, &pb, opts, exact);
    /* Only with shapes: the cache records the pair's pointers. */
    if (sa && sb) check_cached(sa, &pa, sb, &pb, opts, exact, &r);
    return 0;
}
