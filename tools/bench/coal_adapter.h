/* SPDX-License-Identifier: MIT */
/* Coal 3.0.3 (coal-library/coal, the successor of HPP-FCL) seen from C: its
 * shapes, its GJK solver (coal::details::GJK) and its EPA (coal::details::EPA),
 * for the benchmark's agjk/Coal comparisons. Plain C types only, so that the
 * C++ side (coal_adapter.cpp, built only when tools/fetch-coal.sh has fetched
 * Coal) includes no agjk header, and coal_stub.c stands in when Coal is absent. */
#ifndef AGJK_BENCH_COAL_ADAPTER_H
#define AGJK_BENCH_COAL_ADAPTER_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { COAL_SHAPE_ELLIPSOID = 0, COAL_SHAPE_BOX = 1, COAL_SHAPE_CONVEX = 2 };

typedef struct coal_shape_desc {
    int kind;                  /* COAL_SHAPE_* */
    double size[3];            /* ellipsoid radii, or box half extents */
    const double *vertices;    /* convex: vertex_count xyz triples (a hull's vertices) */
    int vertex_count;
    const int32_t *triangles;  /* convex: the hull's triangles, 3 indices each, outward;
                                  Coal builds its vertex graph (hill climbing) from them */
    int triangle_count;
} coal_shape_desc;

/* GJK variants: coal::details::GJK's gjk_variant, and for
 * COAL_NESTEROV / COAL_NESTEROV_NORMALIZED the MinkowskiDiff's
 * normalize_support_direction forced off / on (Coal would otherwise pick it
 * from the shape types: on for two polytopes or boxes). */
enum { COAL_GJK = 0, COAL_NESTEROV = 1, COAL_NESTEROV_NORMALIZED = 2, COAL_POLYAK = 3 };

typedef struct coal_query_desc {
    double rotation_a[9], translation_a[3]; /* row-major, p_world = R p + t */
    double rotation_b[9], translation_b[3];
    int method;                /* COAL_GJK ... COAL_POLYAK */
    int boolean;               /* 1: early exit at the first separating plane
                                  (setDistanceEarlyBreak(0)); 0: distance */
    double tolerance;          /* absolute duality-gap tolerance (length^2) */
    int max_iterations;
    int reps;                  /* timed runs; the time is trimmed_mean(times, reps) */
    double (*now_ns)(void);    /* the benchmark's clock */
    double (*trimmed_mean)(double *t, int n);
} coal_query_desc;

typedef struct coal_answer {
    int verdict;               /* 1 intersecting, 0 separated, -1 no verdict (Failed) */
    int coal_status;           /* coal::details::GJK::Status */
    int iterations;            /* GJK::getNumIterations() */
    int support_calls;         /* counted in one extra, untimed run */
    double distance;           /* GJK::distance when separated, else 0 */
    double time_ns;            /* 0 when reps == 0 */
} coal_answer;

/* 1 when this build has Coal (coal_adapter.cpp), 0 with coal_stub.c. */
int coal_adapter_available(void);
/* "3.0.3", or a sentence saying how to get Coal. */
const char *coal_adapter_version(void);

/* A Coal shape built from desc (NULL on failure or without Coal). */
void *coal_adapter_shape_new(const coal_shape_desc *desc);
void coal_adapter_shape_free(void *shape);

/* Runs Coal's GJK on shapes a and b. Timed region, per run: MinkowskiDiff::set
 * (poses to A's frame, support function selection), the initial guess
 * x0 = c_A - c_B (local origins, in A's frame, as agjk), GJK::evaluate.
 * Returns 0, or -1 (no Coal, or Coal threw). */
int coal_adapter_run(const void *shape_a, const void *shape_b, const coal_query_desc *q,
                     coal_answer *out);

/* A query prepared once (Coal's GJK object, the transforms) and run one time
 * per call of coal_adapter_query_run: exactly the timed region of
 * coal_adapter_run, for instruction counting (tools/bench/callgrind.sh).
 * _run returns the verdict (1, 0, -1) or -2 if Coal threw. */
void *coal_adapter_query_new(const void *shape_a, const void *shape_b, const coal_query_desc *q);
int coal_adapter_query_run(void *query);
void coal_adapter_query_free(void *query);

/* Penetration depth, as Coal's narrowphase (GJKSolver::runGJKAndEPA) computes
 * it: GJK (Coal's default variant and convergence criterion), and when it
 * reports Collision, coal::details::EPA from GJK's simplex, then EPA's witness
 * points and normal. */
typedef struct coal_depth_desc {
    double rotation_a[9], translation_a[3]; /* row-major, p_world = R p + t */
    double rotation_b[9], translation_b[3];
    double gjk_tolerance;      /* GJK's tolerance (Coal's default 1e-6) */
    int gjk_max_iterations;    /* (Coal's default 128) */
    double epa_tolerance;      /* EPA stops when support - face distance <= this */
    int epa_max_iterations;    /* also sizes EPA's vertex and face stores */
    int reps;                  /* timed runs; the time is trimmed_mean(times, reps) */
    double (*now_ns)(void);
    double (*trimmed_mean)(double *t, int n);
} coal_depth_desc;

typedef struct coal_depth_answer {
    int found;                 /* 1: GJK reported Collision and EPA ran */
    int gjk_status;            /* coal::details::GJK::Status */
    int epa_status;            /* coal::details::EPA::Status (-1: did not run) */
    int epa_valid;             /* epa_status & EPA::Valid (accuracy reached or max
                                  iterations hit with a usable answer) */
    int epa_iterations;        /* EPA::getNumIterations() */
    double depth;              /* EPA::depth: Coal's distance is min(0, -depth) */
    double normal[3];          /* from A to B, A's frame */
    double time_ns;            /* 0 when reps == 0 */
} coal_depth_answer;

/* Runs GJK + EPA on shapes a and b. Timed region, per run: MinkowskiDiff::set,
 * GJK::reset and evaluate from x0 = c_A - c_B (as coal_adapter_run), and on
 * Collision EPA::reset (its stores are allocated beforehand, outside the
 * timed region, as a GJKSolver reused between queries has them), evaluate from
 * -x0 (as runGJKAndEPA passes -guess), getWitnessPointsAndNormal.
 * Returns 0, or -1 (no Coal, or Coal threw). */
int coal_adapter_depth(const void *shape_a, const void *shape_b, const coal_depth_desc *q,
                       coal_depth_answer *out);

/* The same query prepared once and run once per _run call (instruction
 * counts); _run returns 1 (EPA ran), 0 (no collision) or -2 (Coal threw). */
void *coal_adapter_depth_query_new(const void *shape_a, const void *shape_b,
                                   const coal_depth_desc *q);
int coal_adapter_depth_query_run(void *query);
void coal_adapter_depth_query_answer(const void *query, coal_depth_answer *out);
void coal_adapter_depth_query_free(void *query);

#ifdef __cplusplus
}
#endif

#endif
