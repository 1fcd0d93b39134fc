/* SPDX-License-Identifier: MIT */
/* A mesh file as an agjk shape: load (mesh_load), scale, hull (Qhull), and the
 * polytope support over the hull vertices, with the hill-climbing adjacency
 * for solid hulls. The scale multiplies local coordinates before the pose, in
 * double, so --scale-a 1000 turns a file in metres into millimetres exactly
 * as a caller would.
 *
 * A query on a large point set skips the hull: for 1,000,000 points on a
 * sphere Qhull took 6.5 to 9 s of CPU, a whole query with scan supports 0.03 s
 * (a few ms per support call; a hard query makes tens to hundreds of calls);
 * the answer is the same (the support function of a point set is that of its
 * hull). */
#include "cli.h"

#include <math.h>
#include <string.h>

/* "1e50": the limit as written in agjk/types.h. */
#define LIMIT_TEXT_(x) #x
#define LIMIT_TEXT(x) LIMIT_TEXT_(x)

int cli_shape_load(const char *path, double scale, int flags, cli_shape *s) {
    char err[MESH_ERROR_SIZE];
    memset(s, 0, sizeof *s);
    if (!mesh_load(path, &s->points, err, sizeof err)) {
        cli_error("%s", err);
        return 0;
    }
    for (size_t i = 0; scale != 1.0 && i < s->points.count; i++) {
        agjk_vec3 *p = &s->points.points[i];
        p->x *= scale;
        p->y *= scale;
        p->z *= scale;
        if (!(fabs(p->x) <= AGJK_MAX_COORDINATE && fabs(p->y) <= AGJK_MAX_COORDINATE &&
              fabs(p->z) <= AGJK_MAX_COORDINATE)) {
            cli_error("%s: vertex %zu scaled by %g is out of range (limit %s, the library's "
                      "coordinate range)", path, i, scale, LIMIT_TEXT(AGJK_MAX_COORDINATE));
            mesh_points_free(&s->points);
            return 0;
        }
    }
    for (size_t i = 0; i < s->points.count; i++) {
        const agjk_vec3 *p = &s->points.points[i];
        if (!(fabs(p->x) <= AGJK_MAX_COORDINATE && fabs(p->y) <= AGJK_MAX_COORDINATE &&
              fabs(p->z) <= AGJK_MAX_COORDINATE)) {
            cli_error("%s: vertex %zu is out of range (limit %s, the library's coordinate "
                      "range)", path, i, LIMIT_TEXT(AGJK_MAX_COORDINATE));
            mesh_points_free(&s->points);
            return 0;
        }
    }
    int ok = (!(flags & CLI_SHAPE_HULL) && s->points.count > CLI_QUERY_HULL_MAX_POINTS)
                 ? mesh_hull_points_only(s->points.points, s->points.count, &s->hull, err,
                                         sizeof err)
                 : mesh_hull_build(s->points.points, s->points.count,
                                   (flags & CLI_SHAPE_ADJACENCY) != 0, &s->hull, err, sizeof err);
    if (!ok) {
        cli_error("%s: convex hull: %s", path, err);
        mesh_points_free(&s->points);
        return 0;
    }
    if (agjk_shape_prepared_polytope(&s->shape, &s->hull.prepared) != AGJK_STATUS_OK) {
        /* Finite points in range and our own adjacency: this is a bug, say so. */
        cli_error("%s: the library rejected the hull as a polytope (internal error)", path);
        cli_shape_free(s);
        return 0;
    }
    return 1;
}

#define CLI_STRING(x) #x
#define CLI_EXPAND_STRING(x) CLI_STRING(x)

int cli_hull_hill_climbing(const mesh_hull *h) {
    return h->polytope.neighbor_offsets &&
           h->polytope.vertex_count >= AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES;
}

const char *cli_hull_support_text(const mesh_hull *h) {
    if (!h->polytope.neighbor_offsets)
        return "scan over the points (degenerate hull: the raw point set is used)";
    if (cli_hull_hill_climbing(h)) return "hill climbing over the hull's vertex graph";
    return "scan over the hull vertices (fewer than the library's hill-climbing threshold, "
           CLI_EXPAND_STRING(AGJK_POLYTOPE_HILL_CLIMB_MIN_VERTICES) " vertices)";
}

void cli_shape_free(cli_shape *s) {
    mesh_hull_free(&s->hull);
    mesh_points_free(&s->points);
}
