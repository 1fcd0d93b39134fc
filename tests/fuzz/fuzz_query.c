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
        st = agjk_shape_polytope(&s->shape, &s->polytope);
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
    if (fz_u8(&r) == 1) {
        /* NULL options: the defaults. */
        fz_check_pair(a.valid ? &a.shape : NULL, &pa, b.valid ? &b.shape : NULL, &pb, NULL, exact);
    } else {
        fz_check_pair(a.valid ? &a.shape : NULL, &pa, b.valid ? &b.shape : NULL, &pb, &o, exact);
    }
    return 0;
}
