/* SPDX-License-Identifier: MIT */
/* Every built-in support function against brute force and against the
 * reference's analytic support (tests/common/ref_support.c):
 *   - h(d) = <d, s(d)> equals the analytic support value;
 *   - <d, s(d)> >= <d, p> for dense samples p of the shape (surface samples,
 *     or the vertex list of a polytope);
 *   - s(d) belongs to the shape;
 * on random, axis-aligned, tiny and huge directions. Constructors reject
 * negative, NaN and infinite sizes and leave the shape untouched. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "agjk/penetration.h"
#include "agjk/polytope.h"
#include "brute_hull.h"
#include "check_main.h"
#include "reference.h"
#include "testutil.h"
#include "../../src/shape_points.h"

#define N_SAMPLES 4000
#define N_DIRS 600

/* Sample points of the core of s (margin excluded), in its local frame. */
static int sample_core(const ref_shape *s, tu_rng *rng, agjk_vec3 *out, int max) {
    int n = 0;
    switch (s->kind) {
    case REF_POINT:
    case REF_SPHERE:
        out[n++] = tu_vec(0, 0, 0);
        break;
    case REF_ELLIPSOID:
        for (; n < max; n++) {
            agjk_vec3 u = tu_unit_vector(rng);
            out[n] = tu_vec(s->p[0] * u.x, s->p[1] * u.y, s->p[2] * u.z);
        }
        break;
    case REF_BOX:
        for (; n < max; n++)
            out[n] = tu_vec(tu_uniform_range(rng, -1, 1) * s->p[0], tu_uniform_range(rng, -1, 1) * s->p[1],
                            tu_uniform_range(rng, -1, 1) * s->p[2]);
        for (int k = 0; k < 8 && k < max; k++) /* and the corners */
            out[k] = tu_vec(k & 1 ? s->p[0] : -s->p[0], k & 2 ? s->p[1] : -s->p[1],
                            k & 4 ? s->p[2] : -s->p[2]);
        break;
    case REF_CAPSULE:
        for (; n < max; n++) out[n] = tu_vec(0, 0, tu_uniform_range(rng, -1, 1) * s->p[1]);
        out[0].z = s->p[1];
        out[1].z = -s->p[1];
        break;
    case REF_CYLINDER:
    case REF_CONE:
        for (; n < max; n++) {
            double phi = tu_uniform_range(rng, 0, 6.283185307179586);
            int top = n % 2;
            double r = s->p[0];
            if (s->kind == REF_CONE && top) r = 0.0; /* apex */
            out[n] = tu_vec(r * cos(phi), r * sin(phi), top ? s->p[1] : -s->p[1]);
        }
        break;
    case REF_POLYTOPE:
        for (; n < s->vertex_count && n < max; n++) out[n] = s->vertices[n];
        break;
    }
    return n;
}

/* Distance of a local point from the core of s (0 inside), exact formulas
 * where they are simple; for ellipsoid and polytope the reference solver. */
static double core_distance(const ref_shape *s, agjk_vec3 p) {
    ref_shape core = *s;
    core.margin = 0.0;
    if (core.kind == REF_SPHERE) core.p[0] = 0.0;
    if (core.kind == REF_CAPSULE) core.p[0] = 0.0;
    agjk_pose id = tu_pose_identity();
    return tu_distance_to_shape(&core, &id, p);
}

static agjk_vec3 random_direction(tu_rng *rng, int i) {
    switch (i % 6) {
    case 0: { /* axis-aligned, exact zeros in the other components */
        double v[3] = {0, 0, 0};
        v[tu_uniform_int(rng, 3)] = tu_uniform(rng) < 0.5 ? -1.0 : 1.0;
        return tu_vec(v[0], v[1], v[2]);
    }
    case 1: /* in a coordinate plane */
        return tu_vec(tu_normal(rng), tu_normal(rng), 0.0);
    case 2: /* tiny magnitude */
        return tu_scale(tu_unit_vector(rng), 1e-300);
    case 3: /* huge magnitude */
        return tu_scale(tu_unit_vector(rng), 1e300);
    default:
        return tu_scale(tu_unit_vector(rng), tu_log_uniform(rng, -5, 5));
    }
}

static void check_shape(ref_shape *s, tu_rng *rng, const char *what) {
    static agjk_vec3 samples[N_SAMPLES];
    agjk_shape shape;
    TU_CHECK_INT_EQ(ref_make_agjk(s, &shape), AGJK_STATUS_OK);
    double expect_margin = s->margin + ((s->kind == REF_SPHERE || s->kind == REF_CAPSULE) ? s->p[0] : 0);
    TU_ENSURE(shape.margin == expect_margin, "%s: margin %g, expected %g", what, shape.margin,
                  expect_margin);
    int ns = sample_core(s, rng, samples, N_SAMPLES);
    double size = tu_bounding_radius(s) + 1e-300;
    for (int i = 0; i < N_DIRS; i++) {
        agjk_vec3 d = random_direction(rng, i);
        agjk_vec3 sup = tu_vec(NAN, NAN, NAN);
        int hint = 0;
        shape.support(shape.data, &d, &sup, &hint);
        TU_ENSURE(tu_vec_finite(sup), "%s dir %d: non-finite support", what, i);
        /* compare with unit direction to keep numbers in range */
        agjk_vec3 u = tu_scale(d, 1.0 / tu_norm(tu_scale(d, 1.0 / fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z))))) /
                                      fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z))));
        double h = tu_dot(u, sup);
        long double dl[3] = {u.x, u.y, u.z}, rs[3];
        ref_shape core = *s;
        core.margin = 0.0;
        if (core.kind == REF_SPHERE || core.kind == REF_CAPSULE) core.p[0] = 0.0;
        ref_support_local(&core, dl, rs);
        double h_ref = (double)(dl[0] * rs[0] + dl[1] * rs[1] + dl[2] * rs[2]);
        TU_ENSURE(fabs(h - h_ref) <= 1e-13 * size, "%s dir %d: h(d) = %.17g, analytic %.17g",
                      what, i, h, h_ref);
        for (int k = 0; k < ns; k++)
            TU_ENSURE(tu_dot(u, samples[k]) <= h + 1e-13 * size,
                          "%s dir %d: sample %d beats the support by %g", what, i, k,
                          tu_dot(u, samples[k]) - h);
        if (i % 10 == 0) {
            double dist = core_distance(s, sup);
            TU_ENSURE(dist <= 1e-13 * size, "%s dir %d: support point %g outside the shape",
                          what, i, dist);
        }
        if (s->kind == REF_POLYTOPE) { /* a scan returns one of the vertices */
            int found = 0;
            for (int k = 0; k < s->vertex_count; k++)
                if (s->vertices[k].x == sup.x && s->vertices[k].y == sup.y && s->vertices[k].z == sup.z)
                    found = 1;
            TU_ENSURE(found, "%s dir %d: support is not a vertex", what, i);
        }
    }
}

START_TEST(builtin_shapes) {
    tu_rng rng;
    tu_rng_seed(&rng, 21);
    static agjk_vec3 verts[300];
    for (int rep = 0; rep < 6; rep++) {
        double sc = rep < 3 ? tu_paper_scale(&rng) : tu_log_uniform(&rng, -4, 4);
        ref_shape s;
        tu_shape_init(&s, REF_POINT, 0, 0, 0);
        check_shape(&s, &rng, "point");
        tu_shape_init(&s, REF_SPHERE, tu_paper_radius(&rng, sc), 0, 0);
        check_shape(&s, &rng, "sphere");
        tu_random_ellipsoid(&rng, &s, sc);
        check_shape(&s, &rng, "ellipsoid");
        tu_shape_init(&s, REF_ELLIPSOID, sc, 1e-3 * sc, 1e3 * sc); /* stiff */
        check_shape(&s, &rng, "stiff ellipsoid");
        tu_random_box(&rng, &s, sc);
        check_shape(&s, &rng, "box");
        tu_shape_init(&s, REF_BOX, sc, 0.0, 0.5 * sc); /* plate */
        check_shape(&s, &rng, "plate");
        tu_shape_init(&s, REF_CAPSULE, tu_paper_radius(&rng, sc), tu_paper_radius(&rng, sc), 0);
        check_shape(&s, &rng, "capsule");
        tu_shape_init(&s, REF_CYLINDER, tu_paper_radius(&rng, sc), tu_paper_radius(&rng, sc), 0);
        check_shape(&s, &rng, "cylinder");
        tu_shape_init(&s, REF_CONE, tu_paper_radius(&rng, sc), tu_paper_radius(&rng, sc), 0);
        check_shape(&s, &rng, "cone");
        tu_shape_init(&s, REF_CONE, tu_paper_radius(&rng, sc), 0.0, 0); /* flat disc */
        check_shape(&s, &rng, "flat cone");
        int nv = 4 + (int)tu_uniform_int(&rng, 200);
        tu_random_polytope(&rng, &s, verts, nv, sc);
        /* interior points and duplicates are allowed */
        verts[nv] = tu_vec(0, 0, 0);
        verts[nv + 1] = verts[0];
        s.vertex_count = nv + 2;
        check_shape(&s, &rng, "polytope");
        tu_random_box(&rng, &s, sc);
        s.margin = 0.3 * sc;
        check_shape(&s, &rng, "rounded box");
    }
}
END_TEST

/* Calls `make` on a bad argument and checks it is rejected and leaves the
 * shape exactly as it was. */
#define EXPECT_REJECT(call)                                                              \
    do {                                                                                 \
        agjk_shape sh_;                                                                  \
        memset(&sh_, 0x5a, sizeof sh_);                                                  \
        agjk_shape before_ = sh_;                                                        \
        agjk_shape *shape = &sh_;                                                        \
        TU_ENSURE((call) == AGJK_STATUS_INVALID_INPUT, "accepted: %s", #call);       \
        TU_ENSURE(memcmp(&sh_, &before_, sizeof sh_) == 0, "shape changed: %s", #call); \
    } while (0)

START_TEST(constructors_reject_bad_sizes) {
    const double bad[4] = {-1.0, -1e-300, NAN, INFINITY};
    for (int b = 0; b < 4; b++) {
        double v = bad[b];
        agjk_ellipsoid e = {{1, 1, 1}};
        agjk_box bx = {{1, 1, 1}};
        agjk_capsule c = {1, 1};
        agjk_cylinder cy = {1, 1};
        agjk_cone co = {1, 1};
        EXPECT_REJECT(agjk_shape_sphere(shape, v));
        e.radii.x = v; EXPECT_REJECT(agjk_shape_ellipsoid(shape, &e)); e.radii.x = 1;
        e.radii.z = v; EXPECT_REJECT(agjk_shape_ellipsoid(shape, &e)); e.radii.z = 1;
        bx.half_extents.y = v; EXPECT_REJECT(agjk_shape_box(shape, &bx)); bx.half_extents.y = 1;
        c.radius = v; EXPECT_REJECT(agjk_shape_capsule(shape, &c)); c.radius = 1;
        c.half_height = v; EXPECT_REJECT(agjk_shape_capsule(shape, &c));
        cy.radius = v; EXPECT_REJECT(agjk_shape_cylinder(shape, &cy)); cy.radius = 1;
        cy.half_height = v; EXPECT_REJECT(agjk_shape_cylinder(shape, &cy));
        co.radius = v; EXPECT_REJECT(agjk_shape_cone(shape, &co)); co.radius = 1;
        co.half_height = v; EXPECT_REJECT(agjk_shape_cone(shape, &co));
        agjk_shape ok;
        TU_CHECK_INT_EQ(agjk_shape_box(&ok, &bx), AGJK_STATUS_OK);
        agjk_shape keep = ok;
        TU_CHECK_INT_EQ(agjk_shape_set_margin(&ok, v), AGJK_STATUS_INVALID_INPUT);
        TU_CHECK(memcmp(&ok, &keep, sizeof ok) == 0);
    }
    /* An ellipsoid needs radii > 0 (documented), unlike the box. */
    agjk_ellipsoid flat = {{1, 0, 1}};
    EXPECT_REJECT(agjk_shape_ellipsoid(shape, &flat));
    /* NULL pointers */
    agjk_box bx = {{1, 1, 1}};
    TU_CHECK_INT_EQ(agjk_shape_box(NULL, &bx), AGJK_STATUS_INVALID_INPUT);
    EXPECT_REJECT(agjk_shape_box(shape, NULL));
    EXPECT_REJECT(agjk_shape_ellipsoid(shape, NULL));
    EXPECT_REJECT(agjk_shape_capsule(shape, NULL));
    EXPECT_REJECT(agjk_shape_cylinder(shape, NULL));
    EXPECT_REJECT(agjk_shape_cone(shape, NULL));
    EXPECT_REJECT(agjk_shape_polytope(shape, NULL));
    TU_CHECK_INT_EQ(agjk_shape_point(NULL), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_shape_sphere(NULL, 1.0), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_shape_set_margin(NULL, 1.0), AGJK_STATUS_INVALID_INPUT);
    /* zero sizes are fine */
    agjk_shape sh;
    TU_CHECK_INT_EQ(agjk_shape_sphere(&sh, 0.0), AGJK_STATUS_OK);
    agjk_box zero = {{0, 0, 0}};
    TU_CHECK_INT_EQ(agjk_shape_box(&sh, &zero), AGJK_STATUS_OK);
}
END_TEST

START_TEST(polytope_rejects_bad_vertices) {
    agjk_vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    agjk_polytope p;
    memset(&p, 0, sizeof p);
    p.vertices = v;
    p.vertex_count = 0;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    p.vertex_count = -3;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    p.vertex_count = 4;
    p.vertices = NULL;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    p.vertices = v;
    v[2].y = NAN;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    v[2].y = -INFINITY;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    v[2].y = 1.0;
    p.vertex_count = AGJK_POLYTOPE_MAX_VERTICES + 1;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    p.vertex_count = 4;
    /* malformed adjacency: offsets not starting at 0 / out-of-range neighbour */
    int32_t off[5] = {1, 2, 3, 4, 5};
    int32_t nb[5] = {1, 2, 3, 0, 9};
    p.neighbor_offsets = off;
    p.neighbors = nb;
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    int32_t off2[5] = {0, 1, 2, 3, 4};
    p.neighbor_offsets = off2;
    nb[3] = 9; /* neighbour index beyond the vertex count */
    EXPECT_REJECT(agjk_shape_polytope(shape, &p));
    p.neighbor_offsets = NULL;
    p.neighbors = NULL;
    agjk_shape sh;
    TU_CHECK_INT_EQ(agjk_shape_polytope(&sh, &p), AGJK_STATUS_OK);
}
END_TEST

/* The shape of `poly`: plain (agjk_shape_polytope) or prepared into *prep,
 * which must then outlive the shape. */
static void polytope_shape(agjk_shape *shape, const agjk_polytope *poly,
                           agjk_prepared_polytope *prep, int prepared) {
    if (prepared) {
        TU_CHECK_INT_EQ(agjk_polytope_prepare(prep, poly), AGJK_STATUS_OK);
        TU_CHECK_INT_EQ(agjk_shape_prepared_polytope(shape, prep), AGJK_STATUS_OK);
    } else {
        TU_CHECK_INT_EQ(agjk_shape_polytope(shape, poly), AGJK_STATUS_OK);
    }
}

/* agjk_polytope_prepare checks the polytope as agjk_shape_polytope does
 * and leaves the struct unchanged on failure. agjk_shape_prepared_polytope
 * rejects an unprepared struct, and a bound the vertices exceed (they moved
 * after preparing: the climb's certification would rest on a false bound),
 * is NaN or lies beyond the coordinate range. */
START_TEST(prepared_polytope_rejects_bad_input) {
    agjk_vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -2}};
    agjk_polytope p = {v, 4, NULL, NULL};
    agjk_prepared_polytope pp, before;
    memset(&pp, 0x5a, sizeof pp);
    before = pp;
    TU_CHECK_INT_EQ(agjk_polytope_prepare(NULL, &p), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_polytope_prepare(&pp, NULL), AGJK_STATUS_INVALID_INPUT);
    TU_CHECK_INT_EQ(agjk_polytope_prepare_sized(&pp, sizeof pp - 1, &p),
                    AGJK_STATUS_INVALID_INPUT);
    v[1].x = NAN;
    TU_CHECK_INT_EQ(agjk_polytope_prepare(&pp, &p), AGJK_STATUS_INVALID_INPUT);
    v[1].x = 1.0;
    int32_t off[5] = {0, 1, 2, 3, 4}, nb[4] = {1, 2, 3, 9};
    p.neighbor_offsets = off;
    p.neighbors = nb;
    TU_CHECK_INT_EQ(agjk_polytope_prepare(&pp, &p), AGJK_STATUS_INVALID_INPUT);
    TU_ENSURE(memcmp(&pp, &before, sizeof pp) == 0, "a failed prepare changed the struct");
    p.neighbor_offsets = NULL;
    p.neighbors = NULL;

    TU_CHECK_INT_EQ(agjk_polytope_prepare(&pp, &p), AGJK_STATUS_OK);
    TU_CHECK_INT_EQ((int)pp.struct_size, (int)sizeof pp);
    TU_CHECK(pp.coordinate_bound == 2.0);
    TU_CHECK(pp.polytope.vertices == v && pp.polytope.vertex_count == 4);
    agjk_shape sh;
    TU_CHECK_INT_EQ(agjk_shape_prepared_polytope(&sh, &pp), AGJK_STATUS_OK);
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, NULL));
    TU_CHECK_INT_EQ(agjk_shape_prepared_polytope(NULL, &pp), AGJK_STATUS_INVALID_INPUT);
    agjk_prepared_polytope bad = pp;
    bad.struct_size = 0; /* never prepared (a zeroed struct) */
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &bad));
    bad = pp;
    bad.coordinate_bound = NAN;
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &bad));
    bad.coordinate_bound = INFINITY;
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &bad));
    bad.coordinate_bound = 1.5;
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &bad));
    /* The start vertices: the supports along the axes and the diagonals
     * (first of equals, as a scan); any index outside the vertices is
     * rejected. */
    TU_CHECK(pp.starts[0] == 1 && pp.starts[1] == 0 && pp.starts[2] == 2 && pp.starts[5] == 3 &&
             pp.starts[6] == 1 && pp.starts[6 + 4] == 3);
    bad = pp;
    bad.starts[7] = 4;
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &bad));
    bad.starts[7] = -1;
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &bad));
    bad = pp;
    v[2].y = -2.5; /* moved after preparing */
    EXPECT_REJECT(agjk_shape_prepared_polytope(shape, &pp));
    v[2].y = 1.0;
    /* a looser bound than the tightest is still a bound */
    bad.coordinate_bound = 3.0;
    TU_CHECK_INT_EQ(agjk_shape_prepared_polytope(&sh, &bad), AGJK_STATUS_OK);
}
END_TEST

START_TEST(polytope_hill_climbing) {
    /* Hill climbing over the hull's edge graph (adjacency built from the
     * brute-force hull) must find the same support value as a scan, from
     * any hint, including out-of-range hints, and along a coherent sequence
     * of directions that carries the hint. */
    tu_rng rng;
    tu_rng_seed(&rng, 22);
    static agjk_vec3 verts[72];
    static int32_t tris[3 * 2 * 72];
    for (int rep = 0; rep < 20; rep++) {
        ref_shape s;
        int n = 32 + (int)tu_uniform_int(&rng, 40);
        tu_random_polytope(&rng, &s, verts, n, tu_paper_scale(&rng));
        int nt = brute_hull(verts, n, tris, 2 * 72);
        TU_ENSURE(nt == 2 * n - 4, "hull of %d points on an ellipsoid: %d triangles", n, nt);
        agjk_polytope poly;
        memset(&poly, 0, sizeof poly);
        poly.vertices = verts;
        poly.vertex_count = n;
        TU_CHECK_INT_EQ(agjk_polytope_build_adjacency(&poly, tris, nt), AGJK_STATUS_OK);
        double size = tu_bounding_radius(&s);
        for (int prepared = 0; prepared < 2; ++prepared) {
            agjk_shape shape;
            agjk_prepared_polytope prep;
            polytope_shape(&shape, &poly, &prep, prepared);
            agjk_vec3 d = tu_unit_vector(&rng), axis = tu_unit_vector(&rng);
            int carried = 0;
            for (int i = 0; i < 1000; i++) {
                int hint;
                if (i % 2) {
                    /* coherent: rotate d a little about a fixed axis, keep the hint */
                    d = tu_add(d, tu_scale(tu_cross(axis, d), 0.05));
                    d = tu_scale(d, 1.0 / tu_norm(d));
                    hint = carried;
                } else {
                    d = tu_unit_vector(&rng);
                    hint = (i % 10 == 0) ? (i % 20 == 0 ? -7 : n + 5) : (int)tu_uniform_int(&rng, (uint32_t)n);
                }
                agjk_vec3 sup;
                shape.support(shape.data, &d, &sup, &hint);
                long double dl[3] = {d.x, d.y, d.z}, rs[3];
                ref_support_local(&s, dl, rs);
                double h_ref = (double)(dl[0] * rs[0] + dl[1] * rs[1] + dl[2] * rs[2]);
                TU_ENSURE(fabs(tu_dot(d, sup) - h_ref) <= 1e-14 * size,
                          "polytope %d (n=%d, prepared %d) dir %d: hill climbing h = %.17g, scan %.17g",
                          rep, n, prepared, i, tu_dot(d, sup), h_ref);
                TU_ENSURE(hint >= 0 && hint < n, "polytope %d dir %d: hint %d out of range", rep, i, hint);
                carried = hint;
            }
        }
        agjk_polytope_free_adjacency(&poly);
    }
}
END_TEST

START_TEST(polytope_hill_climbing_threshold) {
    /* Hill climbing is used from AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES
     * vertices on, as documented (and as `agjk info` reports). An adjacency
     * with no edges tells the two apart: a climb stays at the hint, a scan
     * finds the maximum. */
    enum { N = AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES };
    agjk_vec3 v[N];
    int32_t offsets[N + 1] = {0};
    int32_t no_edges[1] = {0};
    for (int i = 0; i < N; i++) v[i] = tu_vec((double)i, (double)(i * i % 7), (double)(i % 3));
    for (int count = N - 1; count <= N; count++) {
        agjk_polytope poly = {v, count, offsets, no_edges};
        agjk_shape shape;
        TU_CHECK_INT_EQ(agjk_shape_polytope(&shape, &poly), AGJK_STATUS_OK);
        agjk_vec3 d = tu_vec(1, 0, 0), sup;
        int hint = 0;
        shape.support(shape.data, &d, &sup, &hint);
        if (count < N)
            TU_ENSURE(sup.x == count - 1, "%d vertices: support x = %g, scan gives %d", count, sup.x,
                      count - 1);
        else
            TU_ENSURE(sup.x == 0.0, "%d vertices: support x = %g, a climb stays at vertex 0", count,
                      sup.x);
    }
}
END_TEST

START_TEST(brute_hull_itself) {
    /* The test's hull: a cube's 8 corners give 12 triangles, an octahedron 8. */
    agjk_vec3 cube[8];
    int32_t tris[3 * 64];
    for (int k = 0; k < 8; k++) cube[k] = tu_vec(k & 1 ? 1 : -1, k & 2 ? 1.1 : -1.1, k & 4 ? 0.9 : -0.9);
    /* a cube's faces are planar quads: 4 coplanar points, not general position */
    TU_CHECK_INT_EQ(brute_hull(cube, 8, tris, 64), -1);
    agjk_vec3 octa[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    TU_CHECK_INT_EQ(brute_hull(octa, 6, tris, 64), 8);
    agjk_vec3 tet[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1, 0.1, 0.1}};
    TU_CHECK_INT_EQ(brute_hull(tet, 5, tris, 64), 4); /* the interior point is on no face */
    for (int t = 0; t < 4; t++)
        for (int c = 0; c < 3; c++) TU_CHECK(tris[3 * t + c] != 4);
}
END_TEST

/* A caller's callback that forwards to a built-in shape's own: the solver
 * cannot tell it is built in, so it calls through the pointer. */
static void forwarding_support(const void *data, const agjk_vec3 *direction, agjk_vec3 *out,
                               int *hint) {
    const agjk_shape *inner = (const agjk_shape *)data;
    inner->support(inner->data, direction, out, hint);
}

/* Equal bit for bit, but for the distance's rounding allowance when an
 * ellipsoid takes part: recognised as built in, its radii bound the
 * magnitude of its support points from the second support on (src/
 * minkowski.c), where behind a caller's callback only the points seen so far
 * do. The distance (the upper end of the certified interval) and its bound
 * may then differ by a few ulps of the problem's size, `slack`; everything
 * else, iterations and verdict included, must not. */
static int same_result(agjk_result r1, agjk_result r2, double slack) {
    if (!(fabs(r1.distance - r2.distance) <= slack && fabs(r1.bound - r2.bound) <= slack)) return 0;
    r2.distance = r1.distance;
    r2.bound = r1.bound;
    return memcmp(&r1, &r2, sizeof r1) == 0;
}
/* B a built-in ellipsoid: the solver's loop forms its points in A's frame
 * its own way (src/minkowski.h), other bits than the callback's point
 * rotated and translated. Two roundings of the same run, then, which may
 * certify their answers an iteration apart (the last bits decide where a
 * stopping test is first met): the same verdict, and certified intervals
 * [distance - bound, distance] that overlap, up to the allowance. */
static int close_result(agjk_result r1, agjk_result r2, double slack) {
    double low1 = fmax(0.0, r1.distance - r1.bound), low2 = fmax(0.0, r2.distance - r2.bound);
    return r1.status == r2.status && fmax(low1, low2) <= fmin(r1.distance, r2.distance) + slack;
}
static int same_signed_result(agjk_signed_result s1, agjk_signed_result s2, double slack) {
    if (!(fabs(s1.lower - s2.lower) <= slack && fabs(s1.upper - s2.upper) <= slack)) return 0;
    s2.lower = s1.lower;
    s2.upper = s1.upper;
    return memcmp(&s1, &s2, sizeof s1) == 0;
}

/* The same for a signed distance: the same verdict, and certified
 * intervals [lower, upper] that overlap. */
static int close_signed_result(agjk_signed_result s1, agjk_signed_result s2, double slack) {
    return s1.status == s2.status && fmax(s1.lower, s2.lower) <= fmin(s1.upper, s2.upper) + slack;
}

/* The simplest built-in shapes have their support computed in place of the
 * call (src/minkowski.h): every query must give what the same shapes give
 * through a caller's callback (bit for bit, up to the rounding allowance of
 * same_result; within the rounding of close_result when B is an ellipsoid),
 * on random sizes (the ellipsoid's in-place formula covers only ordinary
 * ones: tiny and huge sizes take its callback's rescaling path), poses,
 * methods and modes. With B behind its callback and A built in, bit for bit
 * again. */
START_TEST(direct_support_matches_callback) {
    tu_rng rng;
    tu_rng_seed(&rng, 77);
    agjk_box box[2];
    agjk_ellipsoid ell[2];
    agjk_capsule cap[2];
    agjk_cylinder cyl[2];
    const agjk_method methods[] = {AGJK_METHOD_GJK, AGJK_METHOD_ADAPTIVE, AGJK_METHOD_NESTEROV};
    int queries = 0, fused = 0, same_run = 0;
    for (int rep = 0; rep < 300; rep++) {
        double sc = rep % 10 == 9 ? tu_log_uniform(&rng, -250, 40) : tu_log_uniform(&rng, -2, 2);
        agjk_shape shape[2], wrapped[2];
        int ellipsoids = 0, ellipsoid_b = 0;
        double size = 0.0;
        for (int k = 0; k < 2; k++) {
            int kind = (int)tu_uniform_int(&rng, 6);
            ellipsoids += kind == 1;
            ellipsoid_b = k == 1 && kind == 1;
            double r0 = sc * tu_uniform_range(&rng, 0.1, 1), r1 = sc * tu_uniform_range(&rng, 0.1, 1),
                   r2 = sc * tu_uniform_range(&rng, 0.1, 1);
            box[k].half_extents = tu_vec(r0, r1, r2);
            ell[k].radii = tu_vec(r0, r1, r2);
            cap[k].radius = r0;
            cap[k].half_height = r1;
            cyl[k].radius = r0;
            cyl[k].half_height = r1;
            size += fmax(r0, fmax(r1, r2));
            agjk_status st = kind == 0   ? agjk_shape_box(&shape[k], &box[k])
                             : kind == 1 ? agjk_shape_ellipsoid(&shape[k], &ell[k])
                             : kind == 2 ? agjk_shape_sphere(&shape[k], r0)
                             : kind == 3 ? agjk_shape_point(&shape[k])
                             : kind == 4 ? agjk_shape_capsule(&shape[k], &cap[k])
                                         : agjk_shape_cylinder(&shape[k], &cyl[k]);
            TU_CHECK_INT_EQ(st, AGJK_STATUS_OK);
            wrapped[k].support = forwarding_support;
            wrapped[k].data = &shape[k];
            wrapped[k].margin = shape[k].margin;
        }
        agjk_pose pa = tu_pose_identity(), pb = tu_random_pose(&rng, 1.0);
        tu_random_rotation(&rng, pa.rotation);
        pb.translation = tu_scale(pb.translation, 1.5 * sc);
        size += fmax(fabs(pb.translation.x), fmax(fabs(pb.translation.y), fabs(pb.translation.z)));
        double slack = ellipsoids ? 64.0 * DBL_EPSILON * size : 0.0;
        for (int m = 0; m < 3; m++) {
            agjk_options o = agjk_default_options();
            o.method = methods[m];
            agjk_result r1, r2, r3;
            for (int mode = 0; mode < 2; mode++) {
                agjk_status (*query)(const agjk_shape *, const agjk_pose *, const agjk_shape *,
                                     const agjk_pose *, const agjk_options *, agjk_result *) =
                    mode ? agjk_collide : agjk_distance;
                query(&shape[0], &pa, &shape[1], &pb, &o, &r1);
                query(&wrapped[0], &pa, &wrapped[1], &pb, &o, &r2);
                query(&shape[0], &pa, &wrapped[1], &pb, &o, &r3);
                TU_ENSURE((ellipsoid_b ? close_result(r1, r2, slack)
                                       : same_result(r1, r2, slack)) &&
                              same_result(r3, r2, slack),
                          "rep %d method %d mode %d: direct and callback answers differ", rep, m,
                          mode);
                fused += ellipsoid_b && r1.status == AGJK_STATUS_SEPARATED;
                same_run += ellipsoid_b && r1.status == AGJK_STATUS_SEPARATED &&
                            r1.iterations == r2.iterations;
                queries += 3;
            }
            agjk_signed_result s1, s2;
            agjk_signed_distance(&shape[0], &pa, &shape[1], &pb, &o, &s1);
            agjk_signed_distance(&wrapped[0], &pa, &wrapped[1], &pb, &o, &s2);
            TU_ENSURE(ellipsoid_b ? close_signed_result(s1, s2, slack)
                                  : same_signed_result(s1, s2, slack),
                      "rep %d method %d: direct and callback signed distances differ", rep, m);
        }
    }
    TU_CHECK(queries == 300 * 3 * 6);
    /* Separated pairs with B an ellipsoid occurred, and nearly all of them
     * took as many iterations as through the callback. */
    TU_CHECK(fused > 0 && same_run >= fused - fused / 10);
}
END_TEST

/* Ellipsoids of ordinary size with one radius far below the others (a
 * plate 1e-200 thick: the problem keeps the scale of 1): the support path
 * skips the range test of ||D d||^2 only for radii that keep it in range
 * (src/minkowski.c, point_bounds), since along the thin axis, exactly as
 * axis-aligned poses give it, ||D d||^2 underflows to 0 and the point
 * would come out NaN. The answer is the plate's analytic distance. */
START_TEST(ellipsoid_plates_keep_the_range_test) {
    const double thin[] = {1e-200, 1e-160, 1e-120};
    const agjk_method methods[] = {AGJK_METHOD_GJK, AGJK_METHOD_ADAPTIVE, AGJK_METHOD_NESTEROV,
                                   AGJK_METHOD_POLYAK};
    int queries = 0;
    for (int t = 0; t < 3; t++)
        for (int axis = 0; axis < 3; axis++)
            for (int swap = 0; swap < 2; swap++) {
                agjk_ellipsoid plate, ball;
                double r[3] = {0.8, 0.6, 0.7};
                r[axis] = thin[t];
                plate.radii = tu_vec(r[0], r[1], r[2]);
                ball.radii = tu_vec(0.3, 0.25, 0.2);
                agjk_shape sp, sb;
                TU_CHECK_INT_EQ(agjk_shape_ellipsoid(&sp, &plate), AGJK_STATUS_OK);
                TU_CHECK_INT_EQ(agjk_shape_ellipsoid(&sb, &ball), AGJK_STATUS_OK);
                /* The ball beside the plate along its thin axis, 0.05 away. */
                double ball_r[3] = {0.3, 0.25, 0.2}, off[3] = {0.0, 0.0, 0.0};
                off[axis] = thin[t] + ball_r[axis] + 0.05;
                agjk_pose pp = tu_pose_identity(), pb = tu_pose_identity();
                pb.translation = tu_vec(off[0], off[1], off[2]);
                for (int m = 0; m < 4; m++) {
                    agjk_options o = agjk_default_options();
                    o.method = methods[m];
                    agjk_result res;
                    agjk_status st = swap ? agjk_distance(&sb, &pb, &sp, &pp, &o, &res)
                                          : agjk_distance(&sp, &pp, &sb, &pb, &o, &res);
                    TU_ENSURE(st == AGJK_STATUS_SEPARATED && fabs(res.distance - 0.05) <= 1e-7 &&
                                  res.distance - res.bound <= 0.05 + 1e-12,
                              "plate %g axis %d swap %d method %d: status %d distance %.17g "
                              "bound %g",
                              thin[t], axis, swap, m, (int)st, res.distance, res.bound);
                    st = swap ? agjk_collide(&sb, &pb, &sp, &pp, &o, &res)
                              : agjk_collide(&sp, &pp, &sb, &pb, &o, &res);
                    TU_ENSURE(st == AGJK_STATUS_SEPARATED,
                              "plate %g axis %d swap %d method %d: Boolean status %d", thin[t],
                              axis, swap, m, (int)st);
                    queries += 2;
                }
            }
    TU_CHECK(queries == 3 * 3 * 2 * 4 * 2);
}
END_TEST

/* An ellipsoid's support point D^2 d / ||D d||, from the callback, against
 * long double: its support value <d, s> within 9 units of roundoff u of
 * ||D d||, and the point on the surface (sum (s_i / r_i)^2 = 1) within
 * 18 u. The bounds, to first order: ||D d||^2 is computed to 5 u, the
 * square root and the reciprocal of the square (src/shape_points.h) give
 * 1 / ||D d|| to 2.5 u plus three roundings, D^2 d takes 2 u and the
 * product one more: 8.5 u on every (non-negative) term d_i s_i; the
 * surface's sum of squares doubles the point's 8.5 u. These are the
 * errors the solver's rounding allowance covers. Radii spanning six
 * orders, directions of any size the callback computes without rescaling,
 * axis-aligned ones included. */
START_TEST(ellipsoid_support_within_roundoff) {
    const long double u = DBL_EPSILON / 2.0;
    tu_rng rng;
    tu_rng_seed(&rng, 88);
    long double worst_value = 0.0L, worst_surface = 0.0L;
    for (int i = 0; i < 200000; i++) {
        agjk_ellipsoid e;
        e.radii = tu_vec(tu_log_uniform(&rng, -3, 3), tu_log_uniform(&rng, -3, 3),
                         tu_log_uniform(&rng, -3, 3));
        agjk_shape shape;
        TU_CHECK_INT_EQ(agjk_shape_ellipsoid(&shape, &e), AGJK_STATUS_OK);
        agjk_vec3 d = tu_scale(tu_unit_vector(&rng), tu_log_uniform(&rng, -5, 5));
        if (i % 7 == 0) d.x = 0.0;
        if (i % 11 == 0) d.y = 0.0;
        if (i % 77 == 0) d.z = 1.0;
        agjk_vec3 sp = tu_vec(NAN, NAN, NAN);
        int hint = 0;
        shape.support(shape.data, &d, &sp, &hint);
        long double r[3] = {e.radii.x, e.radii.y, e.radii.z}, dv[3] = {d.x, d.y, d.z};
        long double s3[3] = {sp.x, sp.y, sp.z}, n2 = 0.0L, value = 0.0L, surface = 0.0L;
        for (int k = 0; k < 3; k++) {
            n2 += (r[k] * dv[k]) * (r[k] * dv[k]);
            value += dv[k] * s3[k];
            surface += (s3[k] / r[k]) * (s3[k] / r[k]);
        }
        long double h = sqrtl(n2);
        long double ev = fabsl(value - h) / (h * u), es = fabsl(surface - 1.0L) / u;
        if (ev > worst_value) worst_value = ev;
        if (es > worst_surface) worst_surface = es;
        TU_ENSURE(ev <= 9.0L && es <= 18.0L,
                  "radii (%.17g %.17g %.17g) d (%.17g %.17g %.17g): support value off by "
                  "%.2Lf u, surface by %.2Lf u",
                  e.radii.x, e.radii.y, e.radii.z, d.x, d.y, d.z, ev, es);
    }
    /* (Not a trivial pass: the errors are of the order of the bounds.) */
    TU_ENSURE(worst_value > 1.0L && worst_surface > 1.0L,
              "worst support value error %.2Lf u, surface %.2Lf u", worst_value, worst_surface);
}
END_TEST

/* A random polytope on an ellipsoid, with its hull's adjacency when
 * `adjacency` (else scanned); n points. */
static void pair_polytope(tu_rng *rng, agjk_polytope *poly, agjk_vec3 *verts, int32_t *tris,
                          int n, int adjacency) {
    ref_shape s;
    tu_random_polytope(rng, &s, verts, n, tu_paper_scale(rng));
    memset(poly, 0, sizeof *poly);
    poly->vertices = verts;
    poly->vertex_count = n;
    if (adjacency) {
        int nt = brute_hull(verts, n, tris, 2 * 80);
        TU_ENSURE(nt == 2 * n - 4, "hull of %d points on an ellipsoid: %d triangles", n, nt);
        TU_CHECK_INT_EQ(agjk_polytope_build_adjacency(poly, tris, nt), AGJK_STATUS_OK);
    }
}

/* The two polytopes' supports taken in turns (agjk__polytope_pair_support,
 * the Minkowski support's path for a pair of polytopes, and its prepared
 * twin for a pair of prepared ones) are each the
 * support one climb or scan gives, point and hint, from any hints
 * (out-of-range ones too) and either way of finding them. And queries on
 * such pairs answer bit for bit as with A behind a callback, where each
 * shape is asked on its own. */
typedef void (*pair_support_fn)(const void *, const agjk_vec3 *, agjk_vec3 *, int *,
                                const void *, const agjk_vec3 *, agjk_vec3 *, int *);

/* The prepared pair support as a later support of a query calls it, and
 * as the first one does (its climbs may start elsewhere than at the hints). */
static void prepared_pair(const void *da, const agjk_vec3 *a, agjk_vec3 *oa, int *ha,
                          const void *db, const agjk_vec3 *b, agjk_vec3 *ob, int *hb) {
    agjk__prepared_polytope_pair_support(da, a, oa, ha, db, b, ob, hb, 0);
}
static void prepared_pair_first(const void *da, const agjk_vec3 *a, agjk_vec3 *oa, int *ha,
                                const void *db, const agjk_vec3 *b, agjk_vec3 *ob, int *hb) {
    agjk__prepared_polytope_pair_support(da, a, oa, ha, db, b, ob, hb, 1);
}

/* polytope_pair_support_matches_single for one pair of shapes (plain or
 * prepared polytopes) and the pair function of their kind; returns the
 * number of queries compared. `first`: the pair function as a query's first
 * support calls it, whose climbs may start elsewhere than at the hints; its
 * support values must then match the single ones within rounding, and the
 * queries' certified answers must agree (a tie may resolve to the other
 * vertex, so not bit for bit). */
static int check_pair(tu_rng *rng, const agjk_shape *sa, const agjk_shape *sb, pair_support_fn pair,
                      pair_support_fn first, int na, int nb, int rep) {
    for (int i = 0; i < 200; i++) {
        agjk_vec3 da = tu_unit_vector(rng), db = tu_scale(tu_unit_vector(rng), 3.0);
        int ha = i % 17 == 0 ? -3 : (int)tu_uniform_int(rng, (uint32_t)na + 2);
        int hb = i % 13 == 0 ? nb + 9 : (int)tu_uniform_int(rng, (uint32_t)nb);
        int ha1 = ha, hb1 = hb, ha2 = ha, hb2 = hb;
        agjk_vec3 oa1, ob1, oa2, ob2;
        sa->support(sa->data, &da, &oa1, &ha1);
        sb->support(sb->data, &db, &ob1, &hb1);
        pair(sa->data, &da, &oa2, &ha2, sb->data, &db, &ob2, &hb2);
        TU_ENSURE(memcmp(&oa1, &oa2, sizeof oa1) == 0 && memcmp(&ob1, &ob2, sizeof ob1) == 0 &&
                      ha1 == ha2 && hb1 == hb2,
                  "pair %d (n = %d, %d) direction %d: in turns (%d, %d), alone (%d, %d)", rep, na,
                  nb, i, ha2, hb2, ha1, hb1);
        if (!first) continue;
        /* (hints 0 half of the time: a cold query's first support, which
         * may start from a prepared polytope's start vertices) */
        int ha3 = i % 2 ? 0 : ha, hb3 = i % 2 ? 0 : hb;
        agjk_vec3 oa3, ob3;
        first(sa->data, &da, &oa3, &ha3, sb->data, &db, &ob3, &hb3);
        double ea = fabs(tu_dot(da, oa3) - tu_dot(da, oa1)), eb = fabs(tu_dot(db, ob3) - tu_dot(db, ob1));
        TU_ENSURE(ea <= 1e-14 * (1.0 + fabs(tu_dot(da, oa1))) &&
                      eb <= 3e-14 * (1.0 + fabs(tu_dot(db, ob1))),
                  "pair %d direction %d: first support off by %g, %g", rep, i, ea, eb);
    }
    agjk_shape wrapped = {forwarding_support, sa, 0.0};
    int queries = 0;
    for (int q = 0; q < 20; q++) {
        agjk_pose posa = tu_random_pose(rng, 1.0), posb = tu_random_pose(rng, 1.0);
        agjk_options o = agjk_default_options();
        o.method = q % 3 == 0   ? AGJK_METHOD_GJK
                   : q % 3 == 1 ? AGJK_METHOD_NESTEROV
                                : AGJK_METHOD_ADAPTIVE;
        o.compute = AGJK_COMPUTE_WITNESS;
        agjk_result r1, r2;
        if (q % 2) {
            agjk_collide(&wrapped, &posa, sb, &posb, &o, &r1);
            agjk_collide(sa, &posa, sb, &posb, &o, &r2);
        } else {
            agjk_distance(&wrapped, &posa, sb, &posb, &o, &r1);
            agjk_distance(sa, &posa, sb, &posb, &o, &r2);
        }
        if (!first)
            TU_ENSURE(memcmp(&r1, &r2, sizeof r1) == 0,
                      "pair %d query %d: status %d / %d, distance %.17g / %.17g", rep, q,
                      (int)r1.status, (int)r2.status, r1.distance, r2.distance);
        else
            TU_ENSURE(r1.status == r2.status &&
                          (q % 2 || (r1.distance - r1.bound <= r2.distance &&
                                     r2.distance - r2.bound <= r1.distance)),
                      "pair %d query %d: status %d / %d, [%.17g, %.17g] / [%.17g, %.17g]", rep,
                      q, (int)r1.status, (int)r2.status, r1.distance - r1.bound, r1.distance,
                      r2.distance - r2.bound, r2.distance);
        ++queries;
    }
    return queries;
}

START_TEST(polytope_pair_support_matches_single) {
    tu_rng rng;
    tu_rng_seed(&rng, 31);
    static agjk_vec3 va[80], vb[80];
    static int32_t ta[3 * 2 * 80], tb[3 * 2 * 80];
    int pairs = 0, climbed = 0;
    for (int rep = 0; rep < 40; rep++) {
        agjk_polytope pa, pb;
        /* Mostly climbing sizes; every fifth pair has a polytope scanned
         * for its size, and every fourth one without adjacency. */
        int na = rep % 5 == 4 ? 8 + (int)tu_uniform_int(&rng, 24) : 32 + (int)tu_uniform_int(&rng, 48);
        int nb = 32 + (int)tu_uniform_int(&rng, 48);
        pair_polytope(&rng, &pa, va, ta, na, rep % 4 != 3);
        pair_polytope(&rng, &pb, vb, tb, nb, rep % 4 != 2);
        climbed += pa.neighbor_offsets && pb.neighbor_offsets &&
                   na >= AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES &&
                   nb >= AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES;
        agjk_shape sa, sb;
        agjk_prepared_polytope ppa, ppb;
        polytope_shape(&sa, &pa, NULL, 0);
        polytope_shape(&sb, &pb, NULL, 0);
        pairs += check_pair(&rng, &sa, &sb, agjk__polytope_pair_support, NULL, na, nb, rep);
        polytope_shape(&sa, &pa, &ppa, 1);
        polytope_shape(&sb, &pb, &ppb, 1);
        pairs += check_pair(&rng, &sa, &sb, prepared_pair, prepared_pair_first, na, nb, rep);
        if (pa.neighbor_offsets) agjk_polytope_free_adjacency(&pa);
        if (pb.neighbor_offsets) agjk_polytope_free_adjacency(&pb);
    }
    TU_ENSURE(climbed >= 15, "only %d pairs where both climb", climbed);
    TU_ENSURE(pairs == 1600, "%d queries", pairs);
}
END_TEST

/* <d, s> in long double (each product of two doubles to 64 bits), and its
 * maximum over v[0..n-1]. */
static long double long_dot(agjk_vec3 d, agjk_vec3 s) {
    return (long double)d.x * s.x + (long double)d.y * s.y + (long double)d.z * s.z;
}
static long double long_max(const agjk_vec3 *v, int n, agjk_vec3 d) {
    long double best = -INFINITY;
    for (int i = 0; i < n; ++i) best = fmaxl(best, long_dot(d, v[i]));
    return best;
}

/* A prism over a strictly convex polygon near x = offset whose vertex v =
 * (offset + 1, 0) has a very short edge to a = (offset + 1, edge), and
 * beyond a, w = (offset + 1 - 1e-6, 1) (then a half circle back). Along d =
 * (1, t, 0) with t > 0 the short edge gains t * edge, below the rounding of
 * <d, v> near x = 1001, while w lies higher than v by about t - 1e-6. The
 * caps are fans from a vertex far from v, so that v, a and w have few
 * neighbours and the climb from v must cross the short edge. `lean` moves a
 * back along x (the short edge leans), and w lies `back` behind v (1e-6 in
 * the plain prism). Returns the vertex count; *nt the triangle count. */
#define PRISM_SIDE 20
static int leaning_prism(double offset, double edge, double lean, double back, agjk_vec3 *v,
                         int32_t *tris, int *nt) {
    double px[PRISM_SIDE], py[PRISM_SIDE];
    int n = 0;
    px[n] = offset + 1.0, py[n++] = 0.0;
    px[n] = offset + 1.0 - lean, py[n++] = edge;
    px[n] = offset + 1.0 - back, py[n++] = 1.0;
    for (int k = 0; k < PRISM_SIDE - 3; ++k) {
        double t = 1.5707963267948966 + 3.141592653589793 * k / (PRISM_SIDE - 4);
        px[n] = offset - 1.0 + 1.5 * cos(t), py[n++] = 1.5 * sin(t);
    }
    for (int i = 0; i < n; ++i) {
        v[i] = (agjk_vec3){px[i], py[i], 1.0};
        v[n + i] = (agjk_vec3){px[i], py[i], -1.0};
    }
    int t = 0, apex = n / 2 + 1;
    for (int i = 0; i < n; ++i) {
        int j = (i + 1) % n;
        int32_t side[2][3] = {{i, j, n + j}, {i, n + j, n + i}};
        for (int m = 0; m < 2; ++m, ++t) memcpy(&tris[3 * t], side[m], sizeof side[m]);
        if (i != apex && j != apex) {
            int32_t cap[2][3] = {{apex, i, j}, {n + apex, n + j, n + i}};
            for (int m = 0; m < 2; ++m, ++t) memcpy(&tris[3 * t], cap[m], sizeof cap[m]);
        }
    }
    *nt = t;
    return 2 * n;
}

static int short_edge_prism(double offset, double edge, agjk_vec3 *v, int32_t *tris, int *nt) {
    return leaning_prism(offset, edge, 0.0, 1e-6, v, tris, nt);
}

/* The exact distance (long double) from q to the prism's side polygon, the
 * first `sides` vertices of v (q within the prism's height). */
static long double polygon_distance(const agjk_vec3 *v, int sides, agjk_vec3 q) {
    long double best = INFINITY;
    for (int i = 0; i < sides; ++i) {
        int j = (i + 1) % sides;
        long double ax = v[i].x, ay = v[i].y, ex = (long double)v[j].x - ax,
                    ey = (long double)v[j].y - ay;
        long double qx = (long double)q.x - ax, qy = (long double)q.y - ay;
        long double u = (qx * ex + qy * ey) / (ex * ex + ey * ey);
        u = u < 0 ? 0 : (u > 1 ? 1 : u);
        best = fminl(best, hypotl(qx - u * ex, qy - u * ey));
    }
    return best;
}

START_TEST(polytope_climb_short_edges) {
    /* The climb's support value against the exact maximum over the
     * vertices (long double: each product of two doubles to 64 bits), from
     * every hint, with edges of 1e-9, 1e-12 and one ulp of the coordinates,
     * at offsets 0, 1e3 and 1e6: never below it by more than a scan can be
     * (a few ulps of |d|_1 max |v|). Then distance queries against a point
     * beyond w: the certified interval holds the exact distance, and a
     * point just inside the prism, past the short edge, is never called
     * separated. */
    static agjk_vec3 v[2 * PRISM_SIDE];
    static int32_t tris[3 * 4 * PRISM_SIDE];
    const double offsets[3] = {0.0, 1e3, 1e6};
    int checked = 0;
    for (int oi = 0; oi < 3; ++oi) {
        double offset = offsets[oi];
        double edges[3] = {1e-9, 1e-12, nextafter(offset + 1.0, INFINITY) - (offset + 1.0)};
        for (int ei = 0; ei < 3; ++ei) {
            int nt, n = short_edge_prism(offset, edges[ei], v, tris, &nt);
            agjk_polytope poly = {v, n, NULL, NULL};
            TU_CHECK_INT_EQ(agjk_polytope_build_adjacency(&poly, tris, nt), AGJK_STATUS_OK);
            for (int prepared = 0; prepared < 2; ++prepared) {
                agjk_shape shape;
                agjk_prepared_polytope prep;
                polytope_shape(&shape, &poly, &prep, prepared);
                double vmax = 0.0;
                for (int i = 0; i < n; ++i) vmax = fmax(vmax, fmax(fabs(v[i].x), fabs(v[i].y)));
                for (int di = 0; di < 60; ++di) {
                    /* t from 1e-2 down to 1e-8: w above v by t - 1e-6, or below */
                    double t = pow(10.0, -2.0 - 6.0 * di / 59.0);
                    agjk_vec3 d = {1.0, t, di % 2 ? 0.0 : 1e-3 * t};
                    long double best = long_max(v, n, d);
                    for (int hint = 0; hint < n; ++hint) {
                        int h = hint;
                        agjk_vec3 s;
                        shape.support(shape.data, &d, &s, &h);
                        long double got = long_dot(d, s);
                        double allowed = 8.0 * DBL_EPSILON * (1.0 + t + 1e-3 * t) * vmax;
                        TU_ENSURE(got >= best - allowed,
                                  "offset %g edge %g t %g from hint %d: vertex %d, %.21Lg below the "
                                  "maximum %.21Lg",
                                  offset, edges[ei], t, hint, h, best - got, best);
                        ++checked;
                    }
                }
                /* Queries: B a point at q. The exact distance to the prism's
                 * side (|z| <= 1) is the distance to the polygon. */
                agjk_shape point;
                agjk_shape_point(&point);
                agjk_pose ia = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}}, pb = ia;
                pb.translation = (agjk_vec3){offset + 1.0 + 1e5, 6.0, 0.0};
                long double exact = polygon_distance(v, n / 2, pb.translation);
                /* just inside, past the short edge: halfway between a and w */
                agjk_pose inside = ia;
                inside.translation = (agjk_vec3){offset + 1.0 - 0.6e-6, 0.4, 0.0};
                for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; ++m) {
                    agjk_options o = agjk_default_options();
                    o.method = (agjk_method)m;
                    agjk_result r;
                    TU_CHECK_INT_EQ(agjk_distance(&shape, &ia, &point, &pb, &o, &r), r.status);
                    TU_ENSURE(r.status != AGJK_STATUS_INVALID_INPUT &&
                                  (long double)r.distance - r.bound <= exact &&
                                  exact <= (long double)r.distance,
                              "offset %g edge %g %s: [%.17g, %.17g] misses %.17Lg", offset,
                              edges[ei], agjk_method_name(o.method), r.distance - r.bound,
                              r.distance, exact);
                    agjk_collide(&shape, &ia, &point, &inside, &o, &r);
                    TU_ENSURE(r.status != AGJK_STATUS_SEPARATED,
                              "offset %g edge %g %s: a point inside called separated", offset,
                              edges[ei], agjk_method_name(o.method));
                }
            }
            agjk_polytope_free_adjacency(&poly);
        }
    }
    TU_ENSURE(checked == 2 * 9 * 60 * 2 * PRISM_SIDE, "%d support checks", checked);
}
END_TEST

START_TEST(polytope_climb_hidden_fall) {
    /* The short edge (1e-9) of the prism at x = 1001 leaning back by 2 ulps
     * of x: along d = (dx, t, 1e-3), with t chosen so that a lies higher
     * than v by 0.3 ulp of x (times dx), the computed <d, a> is strictly
     * lower than <d, v> for some dx (the first of 64 tried for which
     * rounding does that; the comparisons below are the climb's own, and the
     * true gain is checked in long double). w lies behind a, higher than v
     * by about 1.7e-5. A climb that takes "no neighbour computes higher" for
     * a maximum, or allows too little for rounding, stops at v. */
    static agjk_vec3 v[2 * PRISM_SIDE];
    static int32_t tris[3 * 4 * PRISM_SIDE];
    const double x = 1001.0, edge = 1e-9, ulp = nextafter(x, INFINITY) - x;
    int tried = 0, found = 0;
    for (int j = 0; j < 64 && !found; ++j, ++tried) {
        double dx = 1.0 + (j + 0.5) / 67.0, t = (2.0 * dx + 0.3) * ulp / edge, ax = x - 2.0 * ulp;
        agjk_vec3 d = {dx, t, 1e-3};
        double dot_v = d.x * x + d.y * 0.0 + d.z * 1.0;
        double dot_a = d.x * ax + d.y * edge + d.z * 1.0;
        long double gain = (long double)d.x * (ax - x) + (long double)d.y * edge;
        if (!(dot_a < dot_v && gain > 0)) continue;
        found = 1;
        double back = (2.0 + 0.15 / dx) * ulp / edge;
        int nt, n = leaning_prism(x - 1.0, edge, 2.0 * ulp, back, v, tris, &nt);
        long double best = long_max(v, n, d);
        long double at_v = (long double)d.x * x + d.z;
        TU_ENSURE(best - at_v > 1e-5, "the prism's maximum lies %.3Lg above v", best - at_v);
        agjk_polytope poly = {v, n, NULL, NULL};
        TU_CHECK_INT_EQ(agjk_polytope_build_adjacency(&poly, tris, nt), AGJK_STATUS_OK);
        for (int prepared = 0; prepared < 2; ++prepared) {
            agjk_shape shape;
            agjk_prepared_polytope prep;
            polytope_shape(&shape, &poly, &prep, prepared);
            for (int hint = 0; hint < n; ++hint) {
                int h = hint;
                agjk_vec3 s;
                shape.support(shape.data, &d, &s, &h);
                long double got = long_dot(d, s);
                TU_ENSURE(got >= best - 8.0 * DBL_EPSILON * 4.0 * x,
                          "dx %g, prepared %d, from hint %d: vertex %d, %.3Lg below the maximum",
                          dx, prepared, hint, h, best - got);
            }
        }
        agjk_polytope_free_adjacency(&poly);
    }
    TU_ENSURE(found, "no dx of %d makes the neighbour compute lower", tried);
}
END_TEST

START_TEST(polytope_climb_short_edges_swept) {
    /* Distance queries from the short-edge prism to points along the
     * directions where its short edge hides a rise (B at (offset + 1 + D,
     * D t, 0.3)), from the hints the queries carry: the certified interval
     * must hold the exact distance (long double, point to polygon) for
     * every method. The climb before the fix missed it in 876 of these
     * 2400 queries at x = 1000. */
    static agjk_vec3 v[2 * PRISM_SIDE];
    static int32_t tris[3 * 4 * PRISM_SIDE];
    const double offsets[2] = {1e3, 0.0}, edges[2] = {1e-9, 1e-12};
    int checked = 0;
    for (int oi = 0; oi < 2; ++oi) {
        int nt, n = short_edge_prism(offsets[oi], edges[oi], v, tris, &nt), sides = n / 2;
        agjk_polytope poly = {v, n, NULL, NULL};
        TU_CHECK_INT_EQ(agjk_polytope_build_adjacency(&poly, tris, nt), AGJK_STATUS_OK);
        for (int prepared = 0; prepared < 2; ++prepared) {
            agjk_shape shape, point;
            agjk_prepared_polytope prep;
            polytope_shape(&shape, &poly, &prep, prepared);
            agjk_shape_point(&point);
            agjk_pose ia = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 0, 0}};
            for (int k = 0; k < 400; ++k) {
                double gap = pow(10.0, -3.0 + 6.0 * (k % 20) / 19.0);
                double t = 1e-5 * pow(10.0, 2.0 * (k / 20) / 19.0);
                agjk_pose pb = ia;
                pb.translation = (agjk_vec3){offsets[oi] + 1.0 + gap, gap * t, 0.3};
                long double exact = polygon_distance(v, sides, pb.translation);
                for (int m = 0; m <= AGJK_METHOD_ADAPTIVE; ++m) {
                    agjk_options o = agjk_default_options();
                    o.method = (agjk_method)m;
                    agjk_result r;
                    agjk_distance(&shape, &ia, &point, &pb, &o, &r);
                    TU_ENSURE(r.status != AGJK_STATUS_INVALID_INPUT &&
                                  (long double)r.distance - r.bound <= exact &&
                                  exact <= (long double)r.distance,
                              "offset %g gap %g t %g %s: [%.17g, %.17g] misses %.17Lg",
                              offsets[oi], gap, t, agjk_method_name(o.method),
                              r.distance - r.bound, r.distance, exact);
                    ++checked;
                }
            }
        }
        agjk_polytope_free_adjacency(&poly);
    }
    TU_ENSURE(checked == 2 * 2 * 400 * 6, "%d queries", checked);
}
END_TEST

int main(void) {
    Suite *s = suite_create("shapes");
    TU_ADD(s, builtin_shapes);
    TU_ADD(s, direct_support_matches_callback);
    TU_ADD(s, ellipsoid_plates_keep_the_range_test);
    TU_ADD(s, ellipsoid_support_within_roundoff);
    TU_ADD(s, constructors_reject_bad_sizes);
    TU_ADD(s, polytope_rejects_bad_vertices);
    TU_ADD(s, prepared_polytope_rejects_bad_input);
    TU_ADD(s, brute_hull_itself);
    TU_ADD(s, polytope_hill_climbing);
    TU_ADD(s, polytope_hill_climbing_threshold);
    TU_ADD(s, polytope_pair_support_matches_single);
    TU_ADD(s, polytope_climb_short_edges);
    TU_ADD(s, polytope_climb_hidden_fall);
    TU_ADD(s, polytope_climb_short_edges_swept);
    return tu_run_suite(s);
}
