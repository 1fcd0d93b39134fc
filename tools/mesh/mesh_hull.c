/* SPDX-License-Identifier: MIT */
/* Convex hull of a point set with Qhull's reentrant library (libqhull_r).
 *
 * Options: "Qt" triangulates the output (we need triangles for the vertex
 * graph; triangulating a merged non-triangular facet adds diagonals, harmless
 * for hill climbing). Qhull's default facet merging (C-0) absorbs duplicates
 * and nearly coplanar points, so every hull vertex it reports is extreme to
 * within rounding.
 *
 * Degenerate inputs (all points on one plane or line, or one point) have no
 * 3-D hull. We detect them before calling Qhull, from the affine dimension
 * of the set, and keep the distinct points as the shape: the support
 * function of a point set (a scan) is the support function of its hull, so
 * queries stay exact; only hill climbing is unavailable. */
#include "mesh.h"

#include <libqhull_r/qhull_ra.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static void set_error(char *err, size_t err_size, const char *fmt, ...) {
    va_list ap;
    if (!err || err_size == 0) return;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
}

static agjk_vec3 sub(agjk_vec3 a, agjk_vec3 b) {
    agjk_vec3 r = {a.x - b.x, a.y - b.y, a.z - b.z};
    return r;
}
static double dot(agjk_vec3 a, agjk_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static agjk_vec3 cross(agjk_vec3 a, agjk_vec3 b) {
    agjk_vec3 r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
    return r;
}

static agjk_vec3 scaled(agjk_vec3 a, double s) {
    agjk_vec3 r = {a.x * s, a.y * s, a.z * s};
    return r;
}

/* For a box whose largest coordinate lies outside [2^-400, 2^400], the
 * power of two that brings it to [1, 2): squares and products of the scaled
 * points neither underflow nor overflow (a cloud 1e-200 across once
 * measured as a single point), and the scaling is exact. 1 otherwise (the
 * meshes of ordinary size see Qhull's input as it was), and for a box at the
 * origin. */
static double unit_scale(agjk_vec3 lo, agjk_vec3 hi) {
    double m = fmax(fmax(fmax(fabs(lo.x), fabs(hi.x)), fmax(fabs(lo.y), fabs(hi.y))),
                    fmax(fabs(lo.z), fabs(hi.z)));
    int e;
    if (!(m > 0.0) || !isfinite(m) || (m >= 0x1p-400 && m <= 0x1p400)) return 1.0;
    frexp(m, &e); /* m = f 2^e, f in [0.5, 1) */
    return ldexp(1.0, 1 - e);
}

/* Index of the point maximising f(point scaled by s); ties keep the first. */
static size_t farthest(const agjk_vec3 *p, size_t n, double s,
                       double (*f)(agjk_vec3, const agjk_vec3 *), const agjk_vec3 *ctx,
                       double *best_value) {
    size_t best = 0;
    *best_value = -1.0;
    for (size_t i = 0; i < n; i++) {
        double v = f(scaled(p[i], s), ctx);
        if (v > *best_value) {
            *best_value = v;
            best = i;
        }
    }
    return best;
}

/* ctx[0] = origin point; ctx[1] = line direction (unit); ctx[2] = plane normal (unit). */
static double dist_point(agjk_vec3 q, const agjk_vec3 *ctx) {
    agjk_vec3 d = sub(q, ctx[0]);
    return dot(d, d);
}
static double dist_line(agjk_vec3 q, const agjk_vec3 *ctx) {
    agjk_vec3 c = cross(sub(q, ctx[0]), ctx[1]);
    return dot(c, c);
}
static double dist_plane(agjk_vec3 q, const agjk_vec3 *ctx) {
    return fabs(dot(sub(q, ctx[0]), ctx[2]));
}

static agjk_vec3 unit(agjk_vec3 v) {
    double n = sqrt(dot(v, v));
    agjk_vec3 r = {v.x / n, v.y / n, v.z / n};
    return r;
}

/* Affine dimension of the set, with a tolerance relative to its extent
 * (1e-12: far above double rounding of the coordinates, far below any
 * thickness a real part has), measured on the points scaled by s
 * (unit_scale). */
static int affine_dimension(const agjk_vec3 *p, size_t n, double s) {
    agjk_vec3 ctx[3];
    double d0, d1, d2;
    agjk_vec3 p0 = scaled(p[0], s);
    ctx[0] = p0;
    size_t a = farthest(p, n, s, dist_point, ctx, &d0);
    double extent = sqrt(d0);
    double tol = 1e-12 * extent;
    if (extent == 0.0) return 0;
    ctx[1] = unit(sub(scaled(p[a], s), p0));
    size_t b = farthest(p, n, s, dist_line, ctx, &d1);
    if (sqrt(d1) <= tol) return 1;
    ctx[2] = unit(cross(ctx[1], sub(scaled(p[b], s), p0)));
    farthest(p, n, s, dist_plane, ctx, &d2);
    return d2 <= tol ? 2 : 3;
}

static int vec_cmp(const void *pa, const void *pb) {
    const agjk_vec3 *a = pa, *b = pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->z != b->z) return a->z < b->z ? -1 : 1;
    return 0;
}

/* Degenerate set: keep the distinct points, sorted. */
static int keep_points(const agjk_vec3 *points, size_t count, mesh_hull *hull) {
    agjk_vec3 *v = malloc(count * sizeof *v);
    if (!v) return 0;
    memcpy(v, points, count * sizeof *v);
    qsort(v, count, sizeof *v, vec_cmp);
    size_t n = 0;
    for (size_t i = 0; i < count; i++)
        if (n == 0 || vec_cmp(&v[n - 1], &v[i]) != 0) v[n++] = v[i];
    hull->vertices = v;
    hull->vertex_count = (int32_t)n;
    return 1;
}

/* Copies Qhull's vertices (renumbered 0..n-1, taken from `points`, which
 * Qhull saw scaled) and triangles, each oriented so that its normal agrees
 * with the facet's outward normal. The orientation is judged on Qhull's
 * scaled copies: on a cloud 1e-200 across the normals of the points
 * themselves underflow to zero, which left half the triangles inward. */
static int extract_hull(qhT *qh, const agjk_vec3 *points, mesh_hull *hull) {
    vertexT *vertex, **vertexp;
    facetT *facet;
    int32_t *map = malloc((size_t)qh->num_points * sizeof *map);
    hull->vertices = malloc((size_t)qh->num_vertices * sizeof *hull->vertices);
    hull->triangles = malloc((size_t)qh->num_facets * 3 * sizeof *hull->triangles);
    if (!map || !hull->vertices || !hull->triangles) {
        free(map);
        return 0;
    }
    int32_t nv = 0, nt = 0;
    FORALLvertices {
        int id = qh_pointid(qh, vertex->point);
        map[id] = nv;
        hull->vertices[nv++] = points[id];
    }
    FORALLfacets {
        int32_t tri[3], k = 0;
        if (qh_setsize(qh, facet->vertices) != 3) continue; /* Qt: all are triangles */
        agjk_vec3 q[3];
        FOREACHvertex_(facet->vertices) {
            q[k].x = vertex->point[0];
            q[k].y = vertex->point[1];
            q[k].z = vertex->point[2];
            tri[k++] = map[qh_pointid(qh, vertex->point)];
        }
        agjk_vec3 n = cross(sub(q[1], q[0]), sub(q[2], q[0]));
        agjk_vec3 outward = {facet->normal[0], facet->normal[1], facet->normal[2]};
        if (dot(n, outward) < 0) {
            int32_t t = tri[1];
            tri[1] = tri[2];
            tri[2] = t;
        }
        memcpy(hull->triangles + 3 * (size_t)nt++, tri, sizeof tri);
    }
    free(map);
    hull->vertex_count = nv;
    hull->triangle_count = nt;
    return 1;
}

/* Qhull's exit codes that say the set is too thin for a solid hull (flat to
 * its precision), as against running out of memory or failing inside. */
static int qhull_found_it_thin(int exitcode) {
    return exitcode == qh_ERRsingular || exitcode == qh_ERRprec || exitcode == qh_ERRtopology ||
           exitcode == qh_ERRwide;
}

/* Runs Qhull; Qhull's messages go to a memory stream we discard unless it
 * fails. On failure *thin tells whether the set was too thin (else: out of
 * memory, or Qhull's own error). */
static int run_qhull(const agjk_vec3 *points, size_t count, double s, mesh_hull *hull, int *thin,
                     char *err, size_t err_size) {
    *thin = 0;
    coordT *coords = malloc(count * 3 * sizeof *coords);
    if (!coords) {
        set_error(err, err_size, "out of memory");
        return 0;
    }
    for (size_t i = 0; i < count; i++) {
        coords[3 * i] = points[i].x * s;
        coords[3 * i + 1] = points[i].y * s;
        coords[3 * i + 2] = points[i].z * s;
    }
    char *log = NULL;
    size_t log_size = 0;
    FILE *errfile = open_memstream(&log, &log_size);
    qhT qh_storage, *qh = &qh_storage;
    char options[] = "qhull Qt";
    QHULL_LIB_CHECK
    qh_zero(qh, errfile);
    int exitcode = qh_new_qhull(qh, 3, (int)count, coords, False, options, NULL, errfile);
    int ok = exitcode == 0 && extract_hull(qh, points, hull);
    if (errfile) fclose(errfile);
    *thin = qhull_found_it_thin(exitcode);
    if (!ok && exitcode == 0) {
        set_error(err, err_size, "out of memory");
    } else if (!ok) {
        const char *why = (log && *log) ? log : "unknown error";
        size_t len = strcspn(why, "\n");
        set_error(err, err_size, "Qhull failed (exit code %d): %.*s", exitcode, (int)len, why);
    }
    free(log);
    int curlong, totlong;
    qh_freeqhull(qh, !qh_ALL);
    qh_memfreeshort(qh, &curlong, &totlong);
    free(coords);
    return ok;
}

static void bounding_box(const agjk_vec3 *points, size_t count, mesh_hull *hull) {
    hull->bbox_min = hull->bbox_max = points[0];
    for (size_t i = 1; i < count; i++) {
        const agjk_vec3 *p = &points[i];
        hull->bbox_min.x = fmin(hull->bbox_min.x, p->x);
        hull->bbox_min.y = fmin(hull->bbox_min.y, p->y);
        hull->bbox_min.z = fmin(hull->bbox_min.z, p->z);
        hull->bbox_max.x = fmax(hull->bbox_max.x, p->x);
        hull->bbox_max.y = fmax(hull->bbox_max.y, p->y);
        hull->bbox_max.z = fmax(hull->bbox_max.z, p->z);
    }
}

/* hull->prepared from hull->polytope. The library checks what it accepts:
 * finite points within AGJK_MAX_COORDINATE (mesh loading already rejects
 * others) and a well-formed adjacency (built by the library itself). */
static int prepare(mesh_hull *hull, char *err, size_t err_size) {
    if (agjk_polytope_prepare(&hull->prepared, &hull->polytope) == AGJK_STATUS_OK) return 1;
    set_error(err, err_size, "the library rejected the hull as a polytope");
    return 0;
}

int mesh_hull_points_only(const agjk_vec3 *points, size_t count, mesh_hull *hull, char *err,
                          size_t err_size) {
    memset(hull, 0, sizeof *hull);
    if (count < 1 || count > (size_t)AGJK_POLYTOPE_MAX_VERTICES) {
        set_error(err, err_size, "point count %zu out of range 1..%d", count,
                  AGJK_POLYTOPE_MAX_VERTICES);
        return 0;
    }
    bounding_box(points, count, hull);
    hull->dimension = affine_dimension(points, count, unit_scale(hull->bbox_min, hull->bbox_max));
    hull->vertices = malloc(count * sizeof *hull->vertices);
    if (!hull->vertices) {
        set_error(err, err_size, "out of memory");
        return 0;
    }
    memcpy(hull->vertices, points, count * sizeof *hull->vertices);
    hull->vertex_count = (int32_t)count;
    hull->points_only = 1;
    hull->polytope.vertices = hull->vertices;
    hull->polytope.vertex_count = hull->vertex_count;
    if (prepare(hull, err, err_size)) return 1;
    mesh_hull_free(hull);
    return 0;
}

int mesh_hull_build(const agjk_vec3 *points, size_t count, int with_adjacency, mesh_hull *hull,
                    char *err, size_t err_size) {
    memset(hull, 0, sizeof *hull);
    if (count < 1 || count > (size_t)AGJK_POLYTOPE_MAX_VERTICES) {
        set_error(err, err_size, "point count %zu out of range 1..%d", count,
                  AGJK_POLYTOPE_MAX_VERTICES);
        return 0;
    }
    bounding_box(points, count, hull);
    double s = unit_scale(hull->bbox_min, hull->bbox_max);
    hull->dimension = affine_dimension(points, count, s);
    int thin = 0;
    int ok = hull->dimension == 3 && run_qhull(points, count, s, hull, &thin, err, err_size);
    if (!ok && hull->dimension == 3 && !thin) {
        /* Out of memory (a --memory-limit, say) or Qhull's own failure: an
         * error, not a flat hull (which `info` and `hull` once reported, with
         * exit status 0 and a hull of no faces). */
        mesh_hull_free(hull);
        return 0;
    }
    if (!ok && hull->dimension == 3) {
        /* Thinner than Qhull accepts though thicker than our test: keep the points. */
        free(hull->vertices);
        free(hull->triangles);
        hull->vertices = NULL;
        hull->triangles = NULL;
        hull->vertex_count = hull->triangle_count = 0;
        hull->qhull_failed = 1;
    }
    if (!ok) ok = keep_points(points, count, hull);
    if (!ok) set_error(err, err_size, "out of memory");
    if (ok) {
        hull->polytope.vertices = hull->vertices;
        hull->polytope.vertex_count = hull->vertex_count;
    }
    if (ok && with_adjacency && hull->triangle_count > 0 &&
        agjk_polytope_build_adjacency(&hull->polytope, hull->triangles, hull->triangle_count) !=
            AGJK_STATUS_OK) {
        set_error(err, err_size, "cannot build the hull's vertex adjacency");
        ok = 0;
    }
    if (ok) ok = prepare(hull, err, err_size);
    if (!ok) mesh_hull_free(hull);
    return ok;
}

void mesh_hull_free(mesh_hull *hull) {
    if (!hull) return;
    agjk_polytope_free_adjacency(&hull->polytope);
    free(hull->vertices);
    free(hull->triangles);
    memset(hull, 0, sizeof *hull);
}

const char *mesh_hull_kind(const mesh_hull *hull) {
    if (hull->points_only) return "not computed (support by scan over all the points)";
    if (hull->qhull_failed) return "nearly flat (Qhull found no solid hull)";
    switch (hull->dimension) {
    case 3: return "solid";
    case 2: return "flat (coplanar)";
    case 1: return "collinear";
    default: return "single point";
    }
}

int mesh_hull_write_off(const mesh_hull *hull, FILE *out) {
    /* %.17g round-trips every double exactly. */
    if (fprintf(out, "OFF\n# convex hull (%s) written by agjk\n%d %d 0\n", mesh_hull_kind(hull),
                (int)hull->vertex_count, (int)hull->triangle_count) < 0)
        return 0;
    for (int32_t i = 0; i < hull->vertex_count; i++) {
        const agjk_vec3 *v = &hull->vertices[i];
        if (fprintf(out, "%.17g %.17g %.17g\n", v->x, v->y, v->z) < 0) return 0;
    }
    for (int32_t t = 0; t < hull->triangle_count; t++) {
        const int32_t *tri = hull->triangles + 3 * (size_t)t;
        if (fprintf(out, "3 %d %d %d\n", (int)tri[0], (int)tri[1], (int)tri[2]) < 0) return 0;
    }
    return fflush(out) == 0 && !ferror(out);
}
