/* SPDX-License-Identifier: MIT */
#include "problems.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Signed distances of the paper's benchmark (Sec. IV), in length units. */
const double bench_targets[BENCH_TARGET_COUNT] = {
    -0.1, -0.01, -0.001, -0.0001,  /* overlapping */
    0.0001, 0.001, 0.01, 0.1,      /* close proximity */
    0.5, 1.0, 2.5, 5.0             /* distant */
};

int bench_target_category(int i) { return i < 4 ? BENCH_OVERLAPPING : i < 8 ? BENCH_CLOSE : BENCH_DISTANT; }

const char *bench_family_name(int family) {
    static const char *const names[] = {"ellipsoids", "boxes", "hulls", "meshes"};
    return family >= 0 && family < BENCH_FAMILY_COUNT ? names[family] : "unknown";
}

const char *bench_category_name(int c) {
    static const char *const names[] = {"overlapping", "close", "distant"};
    return c >= 0 && c < BENCH_CATEGORY_COUNT ? names[c] : "unknown";
}

void bench_set_init(bench_set *set, int shape_capacity, int problem_capacity) {
    memset(set, 0, sizeof *set);
    set->shapes = calloc((size_t)shape_capacity, sizeof *set->shapes);
    set->problems = calloc((size_t)problem_capacity, sizeof *set->problems);
    if (!set->shapes || !set->problems) {
        fprintf(stderr, "agjk-bench: out of memory\n");
        exit(2);
    }
    set->shape_capacity = shape_capacity;
    set->scale = 1.0;
    set->problem_capacity = problem_capacity;
}

void bench_set_free(bench_set *set) {
    int i;
    for (i = 0; i < set->shape_count; ++i) {
        free(set->shapes[i].vertices);
        if (set->shapes[i].aux && set->aux_free) set->aux_free(set->shapes[i].aux);
    }
    free(set->shapes);
    free(set->problems);
    memset(set, 0, sizeof *set);
}

void bench_shape_finish(bench_shape *s) {
    agjk_status st = AGJK_STATUS_INVALID_INPUT;
    int i;
    memset(&s->ref, 0, sizeof s->ref);
    s->ref.kind = (ref_kind)s->kind;
    s->radius = 0.0;
    if (s->kind == REF_ELLIPSOID) {
        s->ellipsoid.radii = s->size;
        st = agjk_shape_ellipsoid(&s->shape, &s->ellipsoid);
        s->radius = fmax(s->size.x, fmax(s->size.y, s->size.z));
    } else if (s->kind == REF_BOX) {
        s->box.half_extents = s->size;
        st = agjk_shape_box(&s->shape, &s->box);
        s->radius = sqrt(s->size.x * s->size.x + s->size.y * s->size.y + s->size.z * s->size.z);
    } else {
        s->polytope.vertices = s->vertices;
        s->polytope.vertex_count = s->vertex_count;
        s->polytope.neighbor_offsets = NULL; /* scan support: exact for any point set */
        s->polytope.neighbors = NULL;
        st = agjk_shape_polytope(&s->shape, &s->polytope);
        for (i = 0; i < s->vertex_count; ++i) {
            const agjk_vec3 *v = &s->vertices[i];
            s->radius = fmax(s->radius, sqrt(v->x * v->x + v->y * v->y + v->z * v->z));
        }
        s->ref.vertices = s->vertices;
        s->ref.vertex_count = s->vertex_count;
    }
    s->ref.p[0] = s->size.x;
    s->ref.p[1] = s->size.y;
    s->ref.p[2] = s->size.z;
    if (st == AGJK_STATUS_INVALID_INPUT) {
        fprintf(stderr, "agjk-bench: agjk rejected a generated shape (kind %d)\n", s->kind);
        exit(2);
    }
}

/* Radii ~ N(0.1, 0.025) per axis times a scale in {1, 5, 10} (the paper's
 * ellipsoid generator); redrawn below 0.01 so no axis is degenerate. */
static agjk_vec3 random_size(bench_rng *rng) {
    static const double scales[3] = {1.0, 5.0, 10.0};
    double scale = scales[bench_rng_below(rng, 3)];
    double r[3];
    int i;
    for (i = 0; i < 3; ++i) {
        do r[i] = 0.1 + 0.025 * bench_rng_normal(rng);
        while (r[i] < 0.01);
    }
    {
        agjk_vec3 v;
        v.x = r[0] * scale;
        v.y = r[1] * scale;
        v.z = r[2] * scale;
        return v;
    }
}

static bench_shape *new_shape(bench_set *set) {
    bench_shape *s;
    if (set->shape_count >= set->shape_capacity) return NULL;
    s = &set->shapes[set->shape_count++];
    memset(s, 0, sizeof *s);
    return s;
}

static int make_shape(bench_set *set, int family, int hull_n, const bench_mesh_source *meshes,
                      bench_rng *rng) {
    bench_shape *s = new_shape(set);
    int i;
    if (!s) return -1;
    s->size = random_size(rng);
    if (set->size_hook && (family == BENCH_ELLIPSOIDS || family == BENCH_BOXES))
        set->size_hook(&s->size, rng);
    s->size.x *= set->scale;
    s->size.y *= set->scale;
    s->size.z *= set->scale;
    if (family == BENCH_ELLIPSOIDS) {
        s->kind = REF_ELLIPSOID;
    } else if (family == BENCH_BOXES) {
        s->kind = REF_BOX;
    } else if (family == BENCH_HULLS) {
        /* Every point of an ellipsoid's surface is extreme, so all N points are
         * vertices of their hull: the point set *is* an N-vertex polytope. */
        s->kind = REF_POLYTOPE;
        s->vertex_count = hull_n;
        s->tag = hull_n;
        s->vertices = malloc((size_t)hull_n * sizeof *s->vertices);
        if (!s->vertices) exit(2);
        for (i = 0; i < hull_n; ++i) {
            agjk_vec3 u = bench_rng_unit(rng); /* size already holds the scale */
            s->vertices[i].x = u.x * s->size.x;
            s->vertices[i].y = u.y * s->size.y;
            s->vertices[i].z = u.z * s->size.z;
        }
    } else {
        int m = (int)bench_rng_below(rng, (uint32_t)meshes->count);
        s->kind = REF_POLYTOPE;
        s->tag = m;
        s->vertex_count = meshes->counts[m];
        s->vertices = malloc((size_t)s->vertex_count * sizeof *s->vertices);
        if (!s->vertices) exit(2);
        for (i = 0; i < s->vertex_count; ++i) {
            s->vertices[i].x = meshes->vertices[m][i].x * set->scale;
            s->vertices[i].y = meshes->vertices[m][i].y * set->scale;
            s->vertices[i].z = meshes->vertices[m][i].z * set->scale;
        }
    }
    bench_shape_finish(s);
    if (s->kind == REF_POLYTOPE && set->polytope_hook) set->polytope_hook(s);
    return set->shape_count - 1;
}

static void identity_pose(agjk_pose *p) {
    memset(p, 0, sizeof *p);
    p->rotation[0][0] = p->rotation[1][1] = p->rotation[2][2] = 1.0;
}

/* A precise distance and separation axis for a disjoint pose: plain GJK at a
 * tolerance near the floating-point floor. It only places the shapes; the
 * truth every result is judged against is the reference solver's. */
static int separation(const bench_shape *a, const agjk_pose *pa, const bench_shape *b,
                      const agjk_pose *pb, double length, double *distance, agjk_vec3 *normal) {
    agjk_options o = agjk_default_options();
    agjk_result r;
    double scale = a->radius + b->radius;
    o.method = AGJK_METHOD_GJK;
    o.max_iterations = 1000;
    o.tolerance = 1e-14 * scale * scale;
    agjk_distance(&a->shape, pa, &b->shape, pb, &o, &r);
    if (r.status == AGJK_STATUS_INTERSECTING || r.status == AGJK_STATUS_INVALID_INPUT) return 0;
    if (r.status == AGJK_STATUS_CONTACT_WITHIN_TOLERANCE || r.distance <= 0.0) return 0;
    if (r.bound > 1e-6 * r.distance + 1e-9 * length) return 0; /* not precise enough to place */
    *distance = r.distance;
    *normal = r.normal;
    return 1;
}

void bench_problem_reference(bench_set *set, bench_problem *p) {
    int rc = ref_distance(&set->shapes[p->a].ref, &p->pose_a, &set->shapes[p->b].ref, &p->pose_b,
                          &p->ref);
    /* A non-converged reference whose certified bounds are still within 1e-9
     * of each other (it stalls at the long-double floor on some touching
     * boxes) judges results just as well. */
    long double lo = p->ref.lower, hi = p->ref.upper;
    p->ref_ok = rc == 0 || (!p->ref.intersecting && lo >= 0 && hi >= lo &&
                            hi - lo <= 1e-9L * (hi > 1 ? hi : 1));
    if (rc != 0 && p->ref_ok) set->ref_stalled++;
    if (p->ref_ok && p->target > 0) {
        double dev = fabs((double)p->ref.distance - p->target) / p->scale;
        if (dev > set->max_target_deviation) set->max_target_deviation = dev;
    }
}

int bench_generate(bench_set *set, int family, int pairs, int poses, int hull_n,
                   const bench_mesh_source *meshes, bench_rng *rng, int with_reference,
                   int verbose) {
    int pair, pose, t, target_count = set->targets ? set->target_count : BENCH_TARGET_COUNT;
    for (pair = 0; pair < pairs; ++pair) {
        int ia = make_shape(set, family, hull_n, meshes, rng);
        int ib = make_shape(set, family, hull_n, meshes, rng);
        if (ia < 0 || ib < 0) return -1;
        for (pose = 0; pose < poses; ++pose) {
            agjk_pose pa, pb;
            agjk_vec3 n = {0, 0, 0}, u;
            double d0 = 0.0;
            int tries, placed = 0;
            identity_pose(&pa);
            for (tries = 0; tries < 1000 && !placed; ++tries) {
                bench_rng_rotation(rng, pb.rotation);
                u = bench_rng_unit(rng);
                pb.translation.x = 3.0 * set->scale * u.x;
                pb.translation.y = 3.0 * set->scale * u.y;
                pb.translation.z = 3.0 * set->scale * u.z;
                placed = separation(&set->shapes[ia], &pa, &set->shapes[ib], &pb, set->scale,
                                    &d0, &n);
                if (!placed) set->rejected_poses++;
            }
            if (!placed) {
                set->skipped_pairs++;
                break;
            }
            for (t = 0; t < target_count; ++t) {
                bench_problem *p;
                double target = (set->targets ? set->targets[t] : bench_targets[t]) * set->scale;
                double shift = target - d0;
                if (set->problem_count >= set->problem_capacity) return -1;
                p = &set->problems[set->problem_count++];
                memset(p, 0, sizeof *p);
                p->family = family;
                p->pair = pair;
                p->pose = pose;
                p->target_index = t;
                p->category = set->targets ? set->target_categories[t] : bench_target_category(t);
                p->a = ia;
                p->b = ib;
                p->target = target;
                p->scale = set->scale;
                p->pose_a = pa;
                p->pose_b = pb;
                /* Translating B along n (from A to B) by shift changes the
                 * distance by exactly shift while it stays positive. */
                p->pose_b.translation.x += shift * n.x;
                p->pose_b.translation.y += shift * n.y;
                p->pose_b.translation.z += shift * n.z;
                if (p->target > 0) {
                    p->xstar.x = -p->target * n.x;
                    p->xstar.y = -p->target * n.y;
                    p->xstar.z = -p->target * n.z;
                }
                if (with_reference) bench_problem_reference(set, p);
            }
        }
        if (verbose && (pair + 1) % 10 == 0)
            fprintf(stderr, "\r  %s: %d/%d pairs", bench_family_name(family), pair + 1, pairs);
    }
    if (verbose) fprintf(stderr, "\r  %s: %d/%d pairs, %d problems\n", bench_family_name(family),
                         pairs, pairs, set->problem_count);
    return 0;
}
