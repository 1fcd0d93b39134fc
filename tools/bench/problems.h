/* SPDX-License-Identifier: MIT */
/* Benchmark problems: shape pairs at controlled signed distances.
 *
 * The protocol of Montaut et al. (RSS 2022, Sec. IV, and the authors' public
 * benchmark code): shape 1 at the identity, shape 2 with a uniform random
 * rotation and translation 3u (u a uniform unit vector); a pose is kept only if
 * the shapes are disjoint; then shape 2 is slid along the separation vector so
 * that the signed distance takes each of BENCH_TARGET_COUNT fixed values. For a
 * negative value -p the shapes overlap by p along that axis (the paper's
 * "signed distance"; the true penetration depth is at most p). */
#ifndef AGJK_BENCH_PROBLEMS_H
#define AGJK_BENCH_PROBLEMS_H

#include "agjk/agjk.h"
#include "rng.h"
#include "../../tests/common/reference.h"

typedef enum bench_family {
    BENCH_ELLIPSOIDS = 0, /* radii ~ N(0.1, 0.025) per axis, times a scale in {1, 5, 10} */
    BENCH_BOXES = 1,      /* half extents drawn like the ellipsoid radii */
    BENCH_HULLS = 2,      /* N random points on such an ellipsoid (all are hull vertices) */
    BENCH_MESHES = 3,     /* real meshes read from a directory (vertices' hull) */
    BENCH_FAMILY_COUNT = 4
} bench_family;

enum { BENCH_OVERLAPPING = 0, BENCH_CLOSE = 1, BENCH_DISTANT = 2, BENCH_CATEGORY_COUNT = 3 };
#define BENCH_TARGET_COUNT 12
extern const double bench_targets[BENCH_TARGET_COUNT];
int bench_target_category(int target_index);
const char *bench_family_name(int family);
const char *bench_category_name(int category);

/* A shape known to both the reference solver and agjk. Never copied after
 * bench_shape_finish(): its agjk_shape points into the struct itself. */
typedef struct bench_shape {
    int kind;                 /* REF_ELLIPSOID, REF_BOX or REF_POLYTOPE */
    agjk_vec3 size;           /* radii or half extents */
    agjk_vec3 *vertices;      /* owned (polytopes) */
    int vertex_count;
    int tag;                  /* hull size N, or mesh file index */
    double radius;            /* bounding radius about the local origin */
    agjk_ellipsoid ellipsoid;
    agjk_box box;
    agjk_polytope polytope;
    agjk_shape shape;
    ref_shape ref;
    void *aux;                /* owned by the set's polytope hook (a hull), or NULL */
} bench_shape;

struct bench_set;
/* Optional hook run on every new polytope shape: may replace s->polytope (e.g.
 * by a hull with hill-climbing adjacency) and rebuild s->shape, and keep what
 * it allocated in s->aux. The reference keeps the original vertices. */
typedef void (*bench_polytope_hook)(bench_shape *s);
typedef void (*bench_aux_free)(void *aux);
/* Optional hook run on every new ellipsoid or box size (before the set's
 * scale multiplies it): may reshape it, e.g. flatten an axis. */
typedef void (*bench_size_hook)(agjk_vec3 *size, bench_rng *rng);

typedef struct bench_problem {
    int family, pair, pose, target_index, category;
    int a, b;                 /* indices of the shapes */
    double target;            /* signed distance set by the protocol (times scale) */
    double scale;             /* the set's scale when generated */
    double offset;            /* distance of both shapes from the world origin when they
                                 were moved there after generation (0: not moved) */
    agjk_pose pose_a, pose_b;
    agjk_vec3 xstar;          /* x* = p_A - p_B, -target * n when target > 0, else 0 */
    ref_result ref;           /* high-precision certified reference */
    int ref_ok;               /* ref_distance converged, or its certified bounds are
                                 within 1e-9 of each other */
} bench_problem;

typedef struct bench_set {
    bench_shape *shapes;
    int shape_count, shape_capacity;
    bench_problem *problems;
    int problem_count, problem_capacity;
    int rejected_poses;       /* sampled poses that collided (re-drawn) */
    int skipped_pairs;        /* pairs for which no disjoint pose was found */
    int ref_stalled;          /* references not converged but with tight bounds (kept) */
    double max_target_deviation; /* max |d_ref - target| / scale over target > 0 */
    bench_polytope_hook polytope_hook; /* NULL: scan support over the vertices */
    bench_aux_free aux_free;
    double scale;             /* length scale of the next generated problems (default 1):
                                 sizes, translations and signed distances are multiplied */
    bench_size_hook size_hook; /* NULL: the protocol's sizes */
    const double *targets;    /* NULL: bench_targets; else target_count signed distances
                                 (times scale), of categories target_categories */
    const int *target_categories;
    int target_count;
} bench_set;

typedef struct bench_mesh_source {
    agjk_vec3 **vertices;     /* one array per mesh, centred */
    int *counts;
    int count;
} bench_mesh_source;

void bench_set_init(bench_set *set, int shape_capacity, int problem_capacity);
void bench_set_free(bench_set *set);

/* Appends `pairs` pairs x `poses` poses x BENCH_TARGET_COUNT (or the set's
 * target_count) problems of
 * `family`. hull_n: vertex count for BENCH_HULLS; meshes: for BENCH_MESHES.
 * with_reference: also run the reference solver on every problem.
 * Returns 0, or -1 when the set is full. */
int bench_generate(bench_set *set, int family, int pairs, int poses, int hull_n,
                   const bench_mesh_source *meshes, bench_rng *rng, int with_reference,
                   int verbose);

/* Runs the reference solver on p (after its poses changed) and sets p->ref_ok. */
void bench_problem_reference(bench_set *set, bench_problem *p);

/* Fills the agjk and reference views of a shape whose kind/size/vertices are set. */
void bench_shape_finish(bench_shape *s);

#endif
